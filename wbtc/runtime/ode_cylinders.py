"""Webots' cylinder-on-plane contact points under `--ode-contacts` (its own dCollideCylinderPlane).

Webots' ODE (src/ode/ode/src/collision_cylinder_plane.cpp, Cyberbotics' collider, not stock ODE's)
touches a Cylinder boundingObject to a Plane at other points than MuJoCo's collider. With a the
cylinder's axis, n the plane's normal and sin² = |a × n|²:

- each cap (the +a one first) may give points at its centre plus D, plus X, minus D and minus X,
  each one that lies below the plane: D the rim direction that goes deepest, X the one across
  it (along a × n), both of the radius;
- "parallel" (sin² < 0.001, within about 0.032 rad of standing on a cap): D and X are the geom's own
  y and x axes, so a standing cylinder rests on the four ends of two perpendicular diameters (a cross);
- "slightly inclined" (sin² < 0.1, within about 0.32 rad): the four points as above; more inclined
  (a wheel on its side): the deepest point of each cap alone.

MuJoCo gives a standing cylinder three points (a triangle on the rim) and adds two triangle points
while a cylinder is within about 60 degrees of standing. So here a standing cylinder rests on
Webots' four springs of soft contact: the 20 kg base of Webots' `motor2` test tilts 0.0192 rad under
its motor's reaction, as ODE's base does (0.0275 on MuJoCo's triangle), and a robot on four cylinder
legs counts Webots' 20 contact points (16 on triangles). A wheel lying on its side touches at the
deepest point of each rim with either collider, and is left as MuJoCo made it.

After `mj_step1`, `hook_for`'s hook writes each cylinder-plane pair's points in place of MuJoCo's
contacts for it (ODE's contact position: the point on the cylinder; MuJoCo's frame and parameters,
copied from the pair's first contact) and builds the constraints again. `rewrite` does the same after
a bare `mj_collision` (wbtc.runtime.end_contacts: the contacts a supervisor reads).

Not honoured: Webots' points of a cylinder against anything else than a plane (boxes, spheres and
meshes keep MuJoCo's collider); the cross's orientation about the axis is MuJoCo's geom x and y axes
(Webots': the ODE geom's, which may be turned about the axis: its points come in another order).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable

import mujoco
import numpy as np

from wbtc.runtime.contact_frames import rebuild_constraints

Hook = Callable[[mujoco.MjModel, mujoco.MjData], None]

#: Webots' collider: axis and normal "parallel" below this sin², "slightly inclined" below INCLINED_SINE2.
PARALLEL_SINE2, INCLINED_SINE2 = 0.001, 0.1
#: Cylinders this far from standing (sin² above it: within 6 degrees of lying) touch at the deepest point
#: of each cap with both colliders: their contacts are left as MuJoCo made them.
LYING_SINE2 = 0.99
_LYING_COSINE = math.sqrt(1.0 - LYING_SINE2)
#: Every field of a contact (a rebuilt list copies them from its source contacts).
_FIELDS = ("pos", "frame", "dist", "geom", "geom1", "geom2", "friction", "solref", "solreffriction", "solimp", "mu",
           "H", "dim", "includemargin", "elem", "vert", "flex", "adhesion", "surfacevel", "exclude", "efc_address")
_PLANE, _CYLINDER = int(mujoco.mjtGeom.mjGEOM_PLANE), int(mujoco.mjtGeom.mjGEOM_CYLINDER)


def applies(model: mujoco.MjModel) -> bool:
    """Whether `model` has a cylinder and a plane (which may touch)."""
    types = model.geom_type
    return bool((types == _PLANE).any() and (types == _CYLINDER).any())


def hook_for(model: mujoco.MjModel) -> Hook | None:
    """The substep hook giving cylinder-plane pairs Webots' points, or None when `model` has no such pair."""
    if not applies(model):
        return None

    def hook(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        if data.ncon and rewrite(model, data):
            rebuild_constraints(model, data)

    return hook


def ode_points(plane_pos: np.ndarray, normal: np.ndarray, centre: np.ndarray, frame: np.ndarray,
               radius: float, half: float) -> list[np.ndarray]:
    """Webots' contact points of a cylinder on a plane, each below it.

    Args:
        plane_pos: a point of the plane.
        normal: the plane's unit normal.
        centre: the cylinder's centre.
        frame: the cylinder's axes as columns (x, y, then its axis).
        radius: the cylinder's radius.
        half: half its height.

    Returns:
        The points on the cylinder, the +axis cap's first, in Webots' order.
    """
    axis = frame[:, 2]
    across = np.cross(axis, normal)
    sine2 = float(across @ across)
    if sine2 < PARALLEL_SINE2:
        across, deepest = radius * frame[:, 0], radius * frame[:, 1]
    else:
        across *= radius / np.sqrt(sine2)
        deepest = axis * float(normal @ axis) - normal  # the radius against the normal
        deepest *= radius / np.linalg.norm(deepest)
    offsets = (deepest, across, -deepest, -across) if sine2 < INCLINED_SINE2 else (deepest,)
    level = float(normal @ plane_pos)
    points = []
    for cap in (centre + half * axis, centre - half * axis):
        points.extend(point for point in (cap + offset for offset in offsets) if level - float(normal @ point) > 0.0)
    return points


def rewrite(model: mujoco.MjModel, data: mujoco.MjData) -> bool:
    """Replace each cylinder-plane pair's contacts by Webots' points (after `mj_collision`); whether any changed.

    A pair's points take the place of MuJoCo's contacts for it, in the contact list's order.
    """
    ncon = data.ncon
    geoms = data.contact.geom[:ncon]
    types = model.geom_type[geoms]
    pairs = (types[:, 0] == _PLANE) & (types[:, 1] == _CYLINDER)
    if not pairs.any():
        return False
    # The usual case, checked first as it is cheap: every touching cylinder lies on its side (the e-puck's
    # and the Thymio's wheels), where MuJoCo's points are Webots'.
    xmat = data.geom_xmat
    cosines = np.einsum("ij,ij->i", xmat[geoms[pairs, 0]][:, 2::3], xmat[geoms[pairs, 1]][:, 2::3])
    if (np.abs(cosines) <= _LYING_COSINE).all():
        return False
    entries: list[tuple[int, np.ndarray | None, float]] = []  # (source contact, new position, new dist)
    done: set[tuple[int, int]] = set()
    for index in range(ncon):
        if not pairs[index]:
            entries.append((index, None, 0.0))
            continue
        plane, cylinder = int(geoms[index, 0]), int(geoms[index, 1])
        if (plane, cylinder) in done:
            continue
        done.add((plane, cylinder))
        normal = data.geom_xmat[plane].reshape(3, 3)[:, 2]
        radius, half = model.geom_size[cylinder, :2]
        for point in ode_points(data.geom_xpos[plane], normal, data.geom_xpos[cylinder],
                                data.geom_xmat[cylinder].reshape(3, 3), float(radius), float(half)):
            # ODE's contact position is the cylinder's point; the distance, the plane's to it (negative).
            entries.append((index, point, float(normal @ (point - data.geom_xpos[plane]))))
    _rebuild(data, entries)
    return True


def _rebuild(data: mujoco.MjData, entries: list[tuple[int, np.ndarray | None, float]]) -> None:
    """Write the contact list anew: each entry a copy of a source contact, with its new position and dist."""
    contact = data.contact
    saved = {name: np.copy(getattr(contact, name)) for name in _FIELDS}
    sources = np.array([entry[0] for entry in entries], dtype=int)
    # The contacts are the arena's first bytes, and the constraint rows follow (mj_makeConstraint makes
    # them again for the new list), so the list may grow over them; the arena's mark covers it.
    data.ncon = len(entries)
    data.parena = max(int(data.parena), len(entries) * _contact_size())
    contact = data.contact
    for name, values in saved.items():
        getattr(contact, name)[:] = values[sources]
    for slot, (_, position, dist) in enumerate(entries):
        if position is not None:
            contact.pos[slot] = position
            contact.dist[slot] = dist


@functools.lru_cache(maxsize=1)
def _contact_size() -> int:
    """sizeof(mjContact): the arena bytes a contact takes (measured on a one-contact model)."""
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><geom type="plane" size="1 1 1"/><body pos="0 0 0.09"><freejoint/>'
        '<geom type="sphere" size="0.1"/></body></worldbody></mujoco>')
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    mujoco.mj_collision(model, data)
    return int(data.parena) // max(int(data.ncon), 1)
