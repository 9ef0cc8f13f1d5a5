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

import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.own_shapes import OwnShapes
from wbtc.runtime.sensors import Sensor
from wbtc.runtime.visible_rays import VisibleRays

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

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
        self.rays, self.depth_axis, self.angles = self._layout()
        self.caster = OwnShapes(VisibleRays(self.near), self.site, self.rays)
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
        dist = self.caster.cast(sim, pos, mat, index, limit)
        ranges = dist * cosine
        ranges[(ranges < self.min_range) | (ranges >= self.max_range)] = math.inf
        if self.noise > 0 and sim.noise_rng is not None:
            finite = np.isfinite(ranges)
            ranges[finite] += sim.noise_rng.normal(0.0, self.noise * self.max_range, int(finite.sum()))
        if self.resolution > 0:
            finite = np.isfinite(ranges)  # np.round rounds halves to even, as Python's round (lookup.quantize)
            ranges[finite] = np.round(ranges[finite] / self.resolution) * self.resolution
        return ranges

    def _points(self) -> list[tuple[float, float, float, int, float]]:
        """The point cloud in the lidar's frame: (x, y, z, layer, time) per column, layer after layer."""
        theta, phi = self.angles[:, 0], self.angles[:, 1]
        r = self.ranges
        with np.errstate(invalid="ignore"):
            xyz = np.stack([r * np.cos(theta) * np.cos(phi), r * np.sin(theta) * np.cos(phi), r * np.sin(phi)], axis=1)
        layers = np.repeat(np.arange(self.layers), self.width)
        return [(float(x), float(y), float(z), int(layer), float(t))
                for (x, y, z), layer, t in zip(xyz.tolist(), layers.tolist(), self.times.tolist(), strict=True)]
