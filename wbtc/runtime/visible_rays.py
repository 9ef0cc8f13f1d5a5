"""Batched visibility rays, as a depth camera sees: MuJoCo's mj_multiRay against visual shapes, front faces only.

Used by the Lidar and by RangeFinders whose projection is not planar. A hit that a rendered image
would not show is a back face (the ray starts inside a shape, or meets a plane from behind) or a
surface closer than `near`: the ray goes on through that shape. Such rays are cast again in
batches, one per set of shapes they went through, with those shapes hidden. A primitive is convex,
so a ray never re-enters it and hiding it is exact; a mesh may be concave, so its rays go on one by
one instead. A primitive that holds the origin (a lidar's own housing) hides every ray: once met
from behind it is hidden from the start, for as long as it still holds the origin.

Not honoured yet: geoms with alpha 0 (MuJoCo's rays skip them; Webots' depth cameras see them).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.context import VISUAL_GROUP

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

#: How many times a ray is continued past clipped surfaces and back faces before giving up.
_MAX_CONTINUES = 16
_EPS = 1e-6
#: A geom group the rays do not see: a shape a ray goes through is put there for one batch.
_HIDDEN_GROUP = 5


class VisibleRays:
    """Casts bundles of rays from one origin at the visual shapes (see the module docstring)."""

    def __init__(self, near: float) -> None:
        self.near = near
        self.groups = np.zeros(6, dtype=np.uint8)
        self.groups[VISUAL_GROUP] = 1
        self._inside: tuple[mujoco.MjModel | None, list[int]] = (None, [])  # shapes holding the origin

    def cast(self, sim: Simulation, origin: np.ndarray, dirs: np.ndarray, limit: np.ndarray,
             hidden: Sequence[int] = ()) -> np.ndarray:
        """Distance along each unit ray to the first visible front face beyond `near` (inf: none within `limit`).

        A hit the lidar cannot see is a back face (the ray starts inside a shape, or meets a plane from
        behind) or a surface clipped by `near`: the ray goes on through that shape. Such rays are cast
        again in batches, one per set of shapes they went through, with those shapes hidden. A primitive
        is convex, so a ray never re-enters it and hiding it is exact; a mesh may be concave, so its rays
        go on one by one instead. A primitive that holds the origin (a lidar's own housing) hides every
        ray: once met from behind it is hidden from the start, for as long as it still holds the origin.
        The shapes `hidden` are not seen at all (`own_shapes` casts at a device's own shapes apart).
        """
        model, data = sim.model, sim.data
        count = len(dirs)
        start = np.array(origin, dtype=float)
        cutoff = float(limit.max()) + 1.0
        if self._inside[0] is not model:
            self._inside = (model, [])
        inside = [g for g in self._inside[1] if _holds(model, data, g, start)]
        self._inside = (model, inside)
        unseen_from_start = sorted(set(inside).union(hidden))
        geom, dist, facing = self._hidden_cast(model, data, start, dirs, cutoff, unseen_from_start)
        types = model.geom_type
        key = np.zeros(count, dtype=np.int64)  # which set of shapes each ray went through (0: none)
        sets: dict[tuple[int, int], int] = {}
        members: list[list[int]] = [unseen_from_start]
        final = np.zeros(count, dtype=bool)  # rays continued one by one: their distance is the answer
        for _ in range(_MAX_CONTINUES):
            unseen = np.flatnonzero(~final & (geom >= 0) & ((facing > 0) | (dist < self.near)))
            if not len(unseen):
                break
            mesh = types[geom[unseen]] == mujoco.mjtGeom.mjGEOM_MESH
            with _hiding(model, unseen_from_start):
                for k in unseen[mesh].tolist():
                    dist[k] = self._continue(sim, start, dirs[k], float(dist[k]), float(limit[k]))
                    final[k] = True
            unseen = unseen[~mesh]
            pairs, which = np.unique(key[unseen] * model.ngeom + geom[unseen], return_inverse=True)
            for index, pair in enumerate(pairs.tolist()):
                previous, shape = divmod(pair, model.ngeom)
                rays = unseen[which == index]
                if facing[rays[0]] > 0 and shape not in inside:
                    # A convex shape met from behind first holds the origin (a plane: the origin is behind
                    # it): hide it from the start at the next scans, while it still does.
                    inside.append(shape)
                number = sets.setdefault((previous, shape), len(members))
                if number == len(members):
                    members.append(members[previous] + [shape])
                key[rays] = number
                geom[rays], dist[rays], facing[rays] = self._hidden_cast(model, data, start, dirs[rays], cutoff,
                                                                         members[number])
        else:
            dist[~final & (geom >= 0) & ((facing > 0) | (dist < self.near))] = math.inf
        dist[~final & (geom < 0)] = math.inf
        dist[dist > limit] = math.inf
        return dist

    def _hidden_cast(self, model: mujoco.MjModel, data: mujoco.MjData, start: np.ndarray, dirs: np.ndarray,
                     cutoff: float, hidden: list[int]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """`_multi_ray` with the geoms `hidden` put out of the rays' sight for the cast."""
        if not hidden:
            return self._multi_ray(model, data, start, dirs, cutoff)
        with _hiding(model, hidden):
            return self._multi_ray(model, data, start, dirs, cutoff)

    def _multi_ray(self, model: mujoco.MjModel, data: mujoco.MjData, start: np.ndarray, dirs: np.ndarray,
                   cutoff: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One mj_multiRay batch from `start`: the geom hit by each ray (-1), its distance, normal · direction."""
        n = len(dirs)
        geom, dist, normal = np.empty(n, dtype=np.int32), np.empty(n), np.empty(3 * n)
        mujoco.mj_multiRay(model, data, start, np.ascontiguousarray(dirs).ravel(), self.groups, 1, -1, geom, dist,
                           normal, n, cutoff)
        return geom, dist, np.einsum("ij,ij->i", normal.reshape(n, 3), dirs)

    def _continue(self, sim: Simulation, origin: np.ndarray, direction: np.ndarray, travelled: float,
                  limit: float) -> float:
        """Follow one ray past hits the lidar cannot see; the distance of the first one it can."""
        geom = np.zeros(1, dtype=np.int32)
        normal = np.zeros(3)
        for _ in range(_MAX_CONTINUES):
            travelled += _EPS
            if travelled > limit:
                return math.inf
            point = origin + direction * travelled
            step = mujoco.mj_ray(sim.model, sim.data, point, direction, self.groups, 1, -1, geom, normal)
            if step < 0:
                return math.inf
            travelled += step
            if float(normal @ direction) <= 0 and travelled >= self.near:
                return travelled
        return math.inf


@contextmanager
def _hiding(model: mujoco.MjModel, geoms: list[int]) -> Iterator[None]:
    """Put `geoms` out of the rays' sight (in a group they do not see) while the block runs."""
    if not geoms:
        yield
        return
    saved = model.geom_group[geoms].copy()
    model.geom_group[geoms] = _HIDDEN_GROUP
    try:
        yield
    finally:
        model.geom_group[geoms] = saved


def _holds(model: mujoco.MjModel, data: mujoco.MjData, geom: int, point: np.ndarray) -> bool:
    """Whether the primitive `geom` holds `point` (a plane: `point` is behind it)."""
    local = data.geom_xmat[geom].reshape(3, 3).T @ (point - data.geom_xpos[geom])
    x, y, z = (float(v) for v in local)
    size = model.geom_size[geom]
    kind = int(model.geom_type[geom])
    if kind == mujoco.mjtGeom.mjGEOM_PLANE:
        return z < 0.0
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return x * x + y * y + z * z < size[0] ** 2
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:  # size: radius, half length along z
        axial = max(abs(z) - size[1], 0.0)
        return x * x + y * y + axial * axial < size[0] ** 2
    if kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        return (x / size[0]) ** 2 + (y / size[1]) ** 2 + (z / size[2]) ** 2 < 1.0
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:  # size: radius, half height
        return x * x + y * y < size[0] ** 2 and abs(z) < size[1]
    if kind == mujoco.mjtGeom.mjGEOM_BOX:  # size: half extents
        return abs(x) < size[0] and abs(y) < size[1] and abs(z) < size[2]
    return False
