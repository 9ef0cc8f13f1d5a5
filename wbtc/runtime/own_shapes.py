"""A ray-casting device's own shapes, seen once and reused while they stay put (Lidar, RangeFinder).

A lidar on a robot sees its own robot's visual shapes as Webots' depth camera does: the housing it
sits in (met from inside: invisible), a plate under it within `near` (clipped: the ray goes on).
Those shapes move with the device, so along each of its rays the distance to them is the same at
every scan, and casting at them again every scan is most of a scan's cost (a second batch for the
rays they clip, and the Python that sorts those rays out). `OwnShapes` casts every ray at them once,
then each scan casts only at the rest of the world with them hidden and takes the nearer of the
two per ray. This is exact, but for the 1e-5 m or rad the own shapes may move unnoticed (`_STILL`):
whether a surface point is seen (a front face beyond `near`) does not
depend on the other shapes, so the first one seen along a ray is the nearer of the first one among
the device's own shapes and the first one among the others.

"Own shapes": the visual geoms of the MuJoCo weld group of the device's body (`body_weldid`: no
joint between them and the device) and of the bodies below the device's body (a lidar's turret on
its hinge, which stays put until its motor turns it), unless the device is welded to the world
itself (a robot without Physics moves its bodies in place, so nothing is known to move with it).
Their poses relative to the device are compared at every scan (a turret turns, a supervisor moves a
part without a joint): a scan after which they moved casts at everything, as without this module,
and their distances are cast again at the first scan they are still.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.compile.context import VISUAL_GROUP
from wbtc.runtime.visible_rays import VisibleRays

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

#: How far the own shapes are looked for along a ray (m): they are on the device's own robot.
_OWN_REACH = 1000.0
#: Relative poses (m, and rotation matrix entries) that differ by less are the same: a rigid part's pose
#: relative to the device drifts by up to 1e-8 with the rounding of a moving robot's transforms, and a
#: servo-held turret jitters by up to 2e-6 (the TurtleBot3's LDS-01 turning); the ranges to own shapes
#: are then kept, at most that far from a fresh cast, far below any lidar's resolution.
_STILL = 1e-5


class OwnShapes:
    """Casts a device's fixed bundle of rays, its own shapes apart (see the module docstring)."""

    def __init__(self, caster: VisibleRays, site: int, rays: np.ndarray) -> None:
        """A device's caster, with its own shapes set apart.

        Args:
            caster: the device's visibility caster (its `near`).
            site: the device's site; its body decides which shapes are the device's own.
            rays: every ray of the device in its own frame (unit vectors, one per row).
        """
        self.caster = caster
        self.site = site
        self.rays = rays
        self._model: mujoco.MjModel | None = None
        self._own: list[int] = []
        self._others: list[int] = []
        self._poses: np.ndarray | None = None
        self._dist: np.ndarray | None = None  # per ray; None: to cast again once the own shapes are still

    def cast(self, sim: Simulation, pos: np.ndarray, mat: np.ndarray, index: np.ndarray,
             limit: np.ndarray) -> np.ndarray:
        """Distance along the rays `index` to the first visible surface (inf: none within `limit`).

        Args:
            sim: the simulation (its model and data as of now).
            pos: the device's origin in the world.
            mat: the device's rotation (columns: its axes in the world).
            index: which of the device's rays to cast.
            limit: the farthest distance of each of those rays.
        """
        if self._model is not sim.model:
            self._start(sim.model)
        dirs = self.rays[index] @ mat.T
        if not self._own:
            return self.caster.cast(sim, pos, dirs, limit)
        poses = self._relative_poses(sim, pos, mat)
        if self._poses is None or np.abs(poses - self._poses).max() > _STILL:
            self._poses, self._dist = poses, None  # moving (or new): everything is cast this time
            return self.caster.cast(sim, pos, dirs, limit)
        if self._dist is None:
            everywhere = np.full(len(self.rays), _OWN_REACH)
            self._dist = self.caster.cast(sim, pos, self.rays @ mat.T, everywhere, hidden=self._others)
        dist = np.minimum(self.caster.cast(sim, pos, dirs, limit, hidden=self._own), self._dist[index])
        dist[dist > limit] = np.inf
        return dist

    def _start(self, model: mujoco.MjModel) -> None:
        """Find the own shapes of a new model (a supervisor's recompile makes one)."""
        self._model, self._poses, self._dist = model, None, None
        body = int(model.site_bodyid[self.site])
        group = model.body_weldid[body]
        visual = np.flatnonzero(model.geom_group == VISUAL_GROUP)
        if group == 0:  # welded to the world: nothing is known to move with the device
            self._own, self._others = [], []
            return
        below = np.zeros(model.nbody, dtype=bool)
        below[body] = True
        for b in range(body + 1, model.nbody):  # MuJoCo numbers every body after its parent: one pass
            below[b] = below[model.body_parentid[b]]
        own = ((model.body_weldid == group) | below)[model.geom_bodyid[visual]]
        self._own = visual[own].tolist()
        self._others = visual[~own].tolist()

    def _relative_poses(self, sim: Simulation, pos: np.ndarray, mat: np.ndarray) -> np.ndarray:
        """Each own shape's position and rotation in the device's frame, flattened."""
        data = sim.data
        own = self._own
        where = (data.geom_xpos[own] - pos) @ mat  # world offsets into the device frame (mat's columns)
        turn = np.einsum("ji,kjl->kil", mat, data.geom_xmat[own].reshape(-1, 3, 3))  # matᵀ · R_geom
        return np.concatenate([where.ravel(), turn.ravel()])
