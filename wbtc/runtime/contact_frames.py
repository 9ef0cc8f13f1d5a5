"""Webots' asymmetric friction at run time: each such contact's tangent frame and two coefficients.

MuJoCo chooses a contact's tangent directions itself; Webots (ODE's dContactFDir1 + dContactMu2)
points the first one along a direction of the colliding geometries. So every substep is MuJoCo's
mj_step split in two: after mj_step1 (collision, constraints) the contacts between geoms of an
asymmetric ContactProperties get Webots' first friction direction t1 and μ(t1), μ(t2)
(`wbtc.compile.contact.surface_mu`), then the constraints are built again from them and mj_step2
finishes the step. For the Euler integrator the split step is MuJoCo's own step, bit for bit.

Webots' rules (WbSimulationCluster::fillSurfaceParameters and the geometries' computeFrictionDirection):
ODE's contact normal points towards its first geom o1; the solid of `material1` is S1 (when both
solids have the same material, as "default" with "default", S1 is o2). A Plane gives its x axis; a
Box or a Cylinder its x axis when the normal is closest to its z axis, else its z axis; any other
geometry none, and then both directions get the first μ. Each direction turns about the normal by
minus its `frictionRotation` angle; t1 is S1's. ODE's argument order is not MuJoCo's: a Plane is
ODE's o2 (its infinite box is collided last), else MuJoCo's first geom is taken as o1.

Not honoured yet: geometries inside a Transform with a scale (the direction is taken unscaled);
ODE's box-shaped friction bounds (MuJoCo's cone is elliptic: a contact sliding along both
directions at once gets less friction along each than ODE gives); a world whose robots have moving
Track belts (wbtc.runtime.tracks has its own split step, which keeps MuJoCo's frames).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wbtc.compile.contact import ContactLaw, surface_mu

_PLANE, _BOX, _CYLINDER = (int(t) for t in (mujoco.mjtGeom.mjGEOM_PLANE, mujoco.mjtGeom.mjGEOM_BOX,
                                              mujoco.mjtGeom.mjGEOM_CYLINDER))


class ContactFrames:
    """The asymmetric-friction contacts of one model (see the module docstring)."""

    def __init__(self, model: mujoco.MjModel, asymmetric: tuple[list[ContactLaw], dict[str, str]]) -> None:
        laws, materials = asymmetric
        self.model = model
        self.laws = laws
        self.material: dict[int, str] = {}
        for name, material in materials.items():
            try:
                self.material[model.geom(name).id] = material
            except KeyError:
                continue

    def step(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """One mj_step of `model` (this one's) with Webots' friction directions on the asymmetric contacts."""
        mujoco.mj_step1(model, data)
        self.orient(model, data)
        mujoco.mj_step2(model, data)

    def orient(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Between `mj_step1` and `mj_step2`: turn the asymmetric contacts and rebuild the constraints."""
        if self._orient(data):
            rebuild_constraints(model, data)

    def _orient(self, data: mujoco.MjData) -> bool:
        """Set the frames and sliding coefficients of this step's asymmetric contacts; whether any were."""
        changed = False
        contacts = data.contact
        for i in range(data.ncon):
            g0, g1 = int(contacts.geom[i, 0]), int(contacts.geom[i, 1])
            if g0 not in self.material or g1 not in self.material:
                continue
            # ODE's o1, o2 and its normal (towards o1); MuJoCo's normal points from geom 0 to geom 1.
            normal = np.array(contacts.frame[i, :3])
            if int(self.model.geom_type[g0]) == _PLANE:
                o1, o2, ode_normal = g1, g0, normal
            else:
                o1, o2, ode_normal = g0, g1, -normal
            found = self._law(self.material[o1], self.material[o2])
            if found is None:
                continue
            law, inversed = found
            s1, s2 = (o2, o1) if inversed else (o1, o2)
            d1, d2 = self._direction(data, s1, ode_normal), self._direction(data, s2, ode_normal)
            if d1 is None or d2 is None:
                contacts.friction[i, :2] = surface_mu(law, None)
                changed = True
                continue
            d1 = _turn(d1, ode_normal, -law.rotation[0])
            d2 = _turn(d2, ode_normal, -law.rotation[1])
            angle = math.acos(float(np.clip(np.dot(d1, d2), -1.0, 1.0)))
            tangent = d1 - np.dot(d1, normal) * normal
            length = float(np.linalg.norm(tangent))
            if length < 1e-9:
                continue
            tangent /= length
            contacts.frame[i, 3:6] = tangent
            contacts.frame[i, 6:9] = np.cross(normal, tangent)
            contacts.friction[i, :2] = surface_mu(law, angle)
            changed = True
        return changed

    def _law(self, material1: str, material2: str) -> tuple[ContactLaw, bool] | None:
        """The first law for these materials (Webots' search order) and whether it is inversed."""
        for law in self.laws:
            first, second = law.materials
            if (first, second) in ((material1, material2), (material2, material1)):
                # Webots: inversed when material2 is o1's material (always so for equal materials).
                return law, second == material1
        return None

    def _direction(self, data: mujoco.MjData, geom: int, normal: np.ndarray) -> np.ndarray | None:
        """The geom's Webots friction direction in world axes, or None if its geometry has none."""
        kind = int(self.model.geom_type[geom])
        axes = data.geom_xmat[geom].reshape(3, 3)  # columns: the geom's axes in world coordinates
        if kind == _PLANE:
            return axes[:, 0].copy()
        if kind in (_BOX, _CYLINDER):
            local = np.abs(axes.T @ normal)
            return axes[:, 0].copy() if local[2] > local[0] and local[2] > local[1] else axes[:, 2].copy()
        return None


def rebuild_constraints(model: mujoco.MjModel, data: mujoco.MjData) -> None:
    """Make the constraints of `data`'s contacts again, after `mj_step1`, as it makes them.

    mj_fwdPosition's constraint stages, then mj_fwdVelocity's row velocities and references: for
    contacts whose frames, coefficients or number a rule changed between `mj_step1` and `mj_step2`.
    """
    mujoco.mj_makeConstraint(model, data)
    mujoco.mj_island(model, data)
    mujoco.mj_projectConstraint(model, data)
    mujoco.mj_mulJacVec(model, data, data.efc_vel, data.qvel)
    mujoco.mj_referenceConstraint(model, data)


def _turn(vector: np.ndarray, axis: np.ndarray, angle: float) -> np.ndarray:
    """`vector` turned by `angle` about the unit `axis` (right-handed; Rodrigues' formula)."""
    if angle == 0.0:
        return vector
    c, s = math.cos(angle), math.sin(angle)
    return vector * c + np.cross(axis, vector) * s + axis * np.dot(axis, vector) * (1.0 - c)
