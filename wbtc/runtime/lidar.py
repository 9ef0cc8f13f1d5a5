"""Lidar: range images and point clouds from batched MuJoCo ray casts (Webots' Lidar node).

Frame: rays start at the device origin; the lidar looks along its +x axis with +z up and +y to
the left (R2022a+; the compiler turns older, -z-looking lidars into that frame).

Layout, as Webots lays out its depth camera: layer i of n (rows from the top) is at elevation
φᵢ = vfov/2 − i·vfov/(n − 1) + tiltAngle (a single layer: tiltAngle). A fixed lidar's column j of
w = horizontalResolution is at azimuth θⱼ = fov/2 − (j + ½)·fov/w, left to right (pixel centres).
A rotating lidar's column j is at θⱼ = π − 2πj/w in the lidar's frame (column w/2 looks ahead);
while enabled its head turns clockwise at `defaultFrequency` (or `setFrequency`), it samples every
basic time step whatever period is asked (as Webots does) and each sample refreshes the columns
the head swept during the step; the others keep their last value (0 before the first sweep).

Ranges: `projection "cylindrical"` (the default) gives the distance along the ray;
`projection "planar"` casts through the pixel centres of a flat depth image (rows picked as
Webots picks them) and gives the distance to the image plane. A range below `minRange` reads inf
but still hides what is behind; nothing before `maxRange` reads inf. Surfaces closer than `near`
are clipped (the ray goes on, measured along the ray) and back faces are invisible (a ray that
starts inside a shape does not see it), as in OpenGL. The lidar sees visual shapes, not bounding
objects, its own robot's included. `noise` adds a Gaussian of σ = noise · maxRange to finite
ranges, then `resolution` rounds them. The point cloud is r·(cos θ cos φ, sin θ cos φ, sin φ) in
the lidar's frame with the layer index and the time of each column: a fixed lidar stamps column j
at t − j·period/w (Webots' convention), a rotating one at the moment the head passed it.

Not honoured yet: `rotatingHead` (the head solid does not turn), the row/column rounding of
Webots' depth camera in cylindrical mode, geoms with alpha 0 (MuJoCo's rays skip them; Webots'
lidar sees transparent shapes), `spherical` (deprecated), the Webots planar point cloud for
tilted lidars (points use the nominal layer angles, as in Webots).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.context import VISUAL_GROUP
from wbtc.compile.table import DeviceEntry
from wbtc.runtime.sensors import Sensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

#: How many times a ray is continued past clipped surfaces and back faces before giving up.
_MAX_CONTINUES = 16
_EPS = 1e-6
#: A geom group the lidar's rays do not see: a shape a ray goes through is put there for one batch.
_HIDDEN_GROUP = 5


class Lidar(Sensor):
    """A Lidar: range image layer by layer, optional point cloud (see the module docstring)."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        f = entry.fields
        self.width = max(int(f.get("horizontalResolution", 512)), 1)
        self.layers = max(int(f.get("numberOfLayers", 4)), 1)
        self.fov = float(f.get("fieldOfView", 1.5708))
        self.vfov = float(f.get("verticalFieldOfView", 0.2))
        self.tilt = float(f.get("tiltAngle", 0.0))
        self.near = float(f.get("near", 0.01))
        self.min_range = float(f.get("minRange", 0.01))
        self.max_range = float(f.get("maxRange", 1.0))
        self.noise = float(f.get("noise", 0.0))
        self.resolution = float(f.get("resolution", -1.0))
        self.frequency = float(f.get("defaultFrequency", 10.0))
        self.rotating = str(f.get("type", "fixed")).lower().startswith("r")
        self.planar = str(f.get("projection", "cylindrical")) == "planar" and not self.rotating
        self.point_cloud = False
        self.step_ms = sim.step_ms
        self.angle = 0.0  # the rotating head's azimuth in the lidar frame (it turns clockwise: decreasing)
        self.last_ms = 0.0
        self.groups = np.zeros(6, dtype=np.uint8)
        self.groups[VISUAL_GROUP] = 1
        self._inside: tuple[mujoco.MjModel | None, list[int]] = (None, [])  # see _cast
        self.rays, self.depth_axis, self.angles = self._layout()
        count = self.layers * self.width
        self.ranges = np.zeros(count) if self.rotating else np.full(count, math.inf)
        self.times = np.zeros(count)

    def _layout(self) -> tuple[np.ndarray, np.ndarray | None, np.ndarray]:
        """The rays in the lidar frame, the planar depth axis and every ray's nominal angles.

        Returns:
            Unit ray directions (layers·width, 3), layer after layer; the depth axis of a planar
            lidar (None: ranges are along the ray); (θ, φ) of every ray, for the point cloud.
        """
        n, w = self.layers, self.width
        phi = (self.vfov / 2 - np.arange(n) * self.vfov / (n - 1) if n > 1 else np.zeros(1)) + self.tilt
        if self.rotating:
            theta = math.pi - 2 * math.pi * np.arange(w) / w
        else:
            theta = self.fov / 2 - (np.arange(w) + 0.5) * self.fov / w
        tt, pp = np.meshgrid(theta, phi)  # (n, w): rows are layers
        angular = np.stack([np.cos(tt) * np.cos(pp), np.sin(tt) * np.cos(pp), np.sin(pp)], axis=-1).reshape(-1, 3)
        angles = np.stack([tt.ravel(), pp.ravel()], axis=1)
        if not self.planar:
            return angular, None, angles
        # A planar depth camera of w columns and h rows with square pixels; layer i reads row int(i·skip).
        h = 1 if n == 1 else math.ceil((self.vfov + self.fov / w) * (w / self.fov))
        skip = (h - 1) / (n - 1) if (h != n and n != 1) else 1.0
        half = math.tan(self.fov / 2)
        rows = np.array([int(i * skip) for i in range(n)])
        y = half * (1 - (2 * np.arange(w) + 1) / w)
        z = half * (h - 2 * rows - 1) / w
        yy, zz = np.meshgrid(y, z)
        d = np.stack([np.ones_like(yy), yy, zz], axis=-1).reshape(-1, 3)
        c, s = math.cos(self.tilt), math.sin(self.tilt)
        d = d @ np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])  # pitch up by tiltAngle
        return d / np.linalg.norm(d, axis=1, keepdims=True), np.array([c, 0.0, s]), angles

    def enable(self, period: int, now_ms: float) -> None:
        """Sample every `period` ms; a rotating lidar samples every basic time step."""
        if self.rotating and period > 0:
            period = max(int(round(self.step_ms)), 1)
        super().enable(period, now_ms)
        self.last_ms = now_ms

    def command(self, op: str, args: tuple) -> None:
        """Point cloud on/off and the rotating head's frequency."""
        if op == "enablePointCloud":
            self.point_cloud = True
        elif op == "disablePointCloud":
            self.point_cloud = False
        elif op == "setFrequency":
            self.frequency = float(args[0])

    def sample(self, sim: Simulation) -> dict[str, Any]:
        """The range image (and point cloud) as the wire sends it."""
        now_ms = sim.time_ms
        if self.rotating:
            columns, fraction = self._swept(now_ms)
            index = (np.arange(self.layers)[:, None] * self.width + columns[None, :]).ravel()
            stamps = np.tile((self.last_ms + fraction * (now_ms - self.last_ms)) / 1000.0, self.layers)
        else:
            index = np.arange(self.layers * self.width)
            stamps = np.tile(now_ms / 1000.0 - np.arange(self.width) * self.period / 1000.0 / self.width,
                             self.layers)
        self.last_ms = now_ms
        if len(index):
            self.ranges[index] = self._measure(sim, index)
            self.times[index] = stamps
        value: dict[str, Any] = {"ranges": self.ranges.tolist()}
        if self.point_cloud:
            value["points"] = self._points()
        return value

    def _swept(self, now_ms: float) -> tuple[np.ndarray, np.ndarray]:
        """The columns the head swept since the last sample, and when (fraction of the interval)."""
        turn = 2 * math.pi * self.frequency * (now_ms - self.last_ms) / 1000.0
        start = self.angle
        self.angle = math.remainder(self.angle - turn, 2 * math.pi)
        theta = math.pi - 2 * math.pi * np.arange(self.width) / self.width
        behind = np.mod(start - theta, 2 * math.pi)  # how far clockwise of the head each column is
        if turn >= 2 * math.pi:
            return np.arange(self.width), np.clip(behind / max(turn, 1e-12), 0.0, 1.0)
        swept = np.flatnonzero(behind < turn)
        return swept, behind[swept] / turn if turn > 0 else np.zeros(len(swept))

    def _measure(self, sim: Simulation, index: np.ndarray) -> np.ndarray:
        """Ranges of the rays `index`: cast, minRange/maxRange, noise, resolution."""
        pos, mat = self.frame(sim)
        local = self.rays[index]
        # Planar: the range is the depth along the camera axis, so a ray may travel farther than maxRange.
        cosine = local @ self.depth_axis if self.depth_axis is not None else np.ones(len(index))
        limit = self.max_range / np.maximum(cosine, 1e-6)
        dist = self._cast(sim, pos, local @ mat.T, limit)
        ranges = dist * cosine
        ranges[(ranges < self.min_range) | (ranges >= self.max_range)] = math.inf
        if self.noise > 0 and sim.noise_rng is not None:
            finite = np.isfinite(ranges)
            ranges[finite] += sim.noise_rng.normal(0.0, self.noise * self.max_range, int(finite.sum()))
        if self.resolution > 0:
            finite = np.isfinite(ranges)  # np.round rounds halves to even, as Python's round (lookup.quantize)
            ranges[finite] = np.round(ranges[finite] / self.resolution) * self.resolution
        return ranges

    def _cast(self, sim: Simulation, origin: np.ndarray, dirs: np.ndarray, limit: np.ndarray) -> np.ndarray:
        """Distance along each unit ray to the first visible front face beyond `near` (inf: none within `limit`).

        A hit the lidar cannot see is a back face (the ray starts inside a shape, or meets a plane from
        behind) or a surface clipped by `near`: the ray goes on through that shape. Such rays are cast
        again in batches, one per set of shapes they went through, with those shapes hidden. A primitive
        is convex, so a ray never re-enters it and hiding it is exact; a mesh may be concave, so its rays
        go on one by one instead. A primitive that holds the origin (a lidar's own housing) hides every
        ray: once met from behind it is hidden from the start, for as long as it still holds the origin.
        """
        model, data = sim.model, sim.data
        count = len(dirs)
        start = np.array(origin, dtype=float)
        cutoff = float(limit.max()) + 1.0
        if self._inside[0] is not model:
            self._inside = (model, [])
        inside = [g for g in self._inside[1] if _holds(model, data, g, start)]
        self._inside = (model, inside)
        geom, dist, facing = self._hidden_cast(model, data, start, dirs, cutoff, inside)
        types = model.geom_type
        key = np.zeros(count, dtype=np.int64)  # which set of shapes each ray went through (0: none)
        sets: dict[tuple[int, int], int] = {}
        members: list[list[int]] = [list(inside)]
        final = np.zeros(count, dtype=bool)  # rays continued one by one: their distance is the answer
        for _ in range(_MAX_CONTINUES):
            unseen = np.flatnonzero(~final & (geom >= 0) & ((facing > 0) | (dist < self.near)))
            if not len(unseen):
                break
            mesh = types[geom[unseen]] == mujoco.mjtGeom.mjGEOM_MESH
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
        saved = model.geom_group[hidden].copy()
        model.geom_group[hidden] = _HIDDEN_GROUP
        try:
            return self._multi_ray(model, data, start, dirs, cutoff)
        finally:
            model.geom_group[hidden] = saved

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

    def _points(self) -> list[tuple[float, float, float, int, float]]:
        """The point cloud in the lidar's frame: (x, y, z, layer, time) per column, layer after layer."""
        theta, phi = self.angles[:, 0], self.angles[:, 1]
        r = self.ranges
        with np.errstate(invalid="ignore"):
            xyz = np.stack([r * np.cos(theta) * np.cos(phi), r * np.sin(theta) * np.cos(phi), r * np.sin(phi)], axis=1)
        layers = np.repeat(np.arange(self.layers), self.width)
        return [(float(x), float(y), float(z), int(layer), float(t))
                for (x, y, z), layer, t in zip(xyz.tolist(), layers.tolist(), self.times.tolist(), strict=True)]


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
