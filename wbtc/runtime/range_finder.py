"""Webots' RangeFinder: a depth image rendered by the device's MuJoCo camera, or cast ray by ray.

`projection "planar"` (the default): each sample renders the device camera with its frustum from
`near` to `maxRange` and reads the depth buffer back as metres to the image plane (planar depth,
not the distance along the ray), rows from the top. What the depth pass sees is what Webots' range
finder sees: every visual shape, semi-transparent ones included (the range_finder test reads a
transparency 0.5 plane 2 m ahead as 2.0), and no sky. MuJoCo's renderer would otherwise write its
skybox (a sphere whose radius follows the model's far plane: 2.1 m in that test's world) into the
depth buffer and draw blended geoms without writing depth, so `Offscreen.depth` turns both off.

`"cylindrical"` and `"spherical"`: pixel (i, j) looks at azimuth θⱼ = fov/2 − (j + ½)·fov/w and
elevation φᵢ = vfov/2 − (i + ½)·vfov/h, with the vertical field of view vfov = fov·h/w (square
angular pixels), and reads the distance along that ray, cast as a depth camera sees (`visible_rays`:
visual shapes, front faces, beyond `near`); so a field of view up to 2π works.

A range below `minRange`, or where nothing is seen before `maxRange`, reads inf. `noise` adds a
Gaussian of σ = noise × maxRange to every pixel; `resolution` rounds ranges to its multiples.

Not honoured yet: `motionBlur`, `lens` distortion; Webots renders a non-planar projection through a
cube map, whose pixel rounding is not reproduced.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.own_shapes import OwnShapes
from wbtc.runtime.sensors import Sensor
from wbtc.runtime.visible_rays import VisibleRays

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class RangeFinder(Sensor):
    """One RangeFinder device; its value is {"ranges": [width × height floats]}."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        f = entry.fields
        self.width = int(f.get("width", 64))
        self.height = int(f.get("height", 64))
        self.near = float(f.get("near", 0.01))
        self.min_range = float(f.get("minRange", 0.01))
        self.max_range = float(f.get("maxRange", 1.0))
        self.noise = float(f.get("noise", 0.0))
        self.resolution = float(f.get("resolution", -1.0))
        self.camera = sim.model.camera(entry.camera).id
        fov = float(f.get("fieldOfView", 0.7854))
        # Before R2023a a `spherical TRUE` RangeFinder was what `projection "spherical"` is now.
        planar = str(f.get("projection", "planar")) == "planar" and not f.get("spherical")
        self.rays = None if planar else _angular_rays(fov, self.width, self.height)
        self.caster = None if self.rays is None else OwnShapes(VisibleRays(self.near), self.site, self.rays)

    def sample(self, sim: Simulation) -> dict[str, Any]:
        """The range image (rows from the top, as Webots' range image)."""
        if self.rays is None:
            renderer = sim.renderer(self.width, self.height, precise=True)  # shared with a camera of its size
            depth = renderer.depth(sim.data, self.camera, self.near, self.max_range)
            ranges = depth[::-1].copy()
        else:
            pos, mat = self.frame(sim)
            limit = np.full(len(self.rays), self.max_range)
            every = np.arange(len(self.rays))
            ranges = self.caster.cast(sim, pos, mat, every, limit).reshape(self.height, self.width)
        finite = np.isfinite(ranges)
        if self.noise > 0 and sim.noise_rng is not None:
            ranges[finite] += sim.noise_rng.normal(0.0, self.noise * self.max_range, int(finite.sum()))
        if self.resolution > 0:
            ranges[finite] = np.round(ranges[finite] / self.resolution) * self.resolution
        ranges[(ranges < self.min_range) | (ranges > self.max_range)] = np.inf
        return {"ranges": ranges.astype(np.float32).ravel().tolist()}


def _angular_rays(fov: float, width: int, height: int) -> np.ndarray:
    """Unit rays of a cylindrical/spherical range image in the device frame (+x ahead, +y left, +z up), row-major."""
    vfov = fov * height / max(width, 1)
    theta = fov / 2 - (np.arange(width) + 0.5) * fov / width
    phi = vfov / 2 - (np.arange(height) + 0.5) * vfov / height
    tt, pp = np.meshgrid(theta, phi)
    return np.stack([np.cos(tt) * np.cos(pp), np.sin(tt) * np.cos(pp), np.sin(pp)], axis=-1).reshape(-1, 3)
