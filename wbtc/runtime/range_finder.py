"""Webots' RangeFinder: a depth image rendered by the device's MuJoCo camera.

Each sample renders the device camera with its frustum from `near` to `maxRange` and reads the depth
buffer back as metres to the image plane (Webots' range image is planar depth, not the distance along
the ray), rows from the top. A depth below `minRange`, or where nothing is drawn before `maxRange`,
reads inf. `noise` adds a Gaussian of σ = noise × maxRange to every pixel; `resolution` rounds depths
to its multiples.

Not honoured yet: `spherical` projections, `motionBlur`, `lens` distortion.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.sensors import Sensor

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

    def sample(self, sim: Simulation) -> dict[str, Any]:
        """Render the depth image (rows from the top, as Webots' range image)."""
        depth = sim.renderer(self.width, self.height).depth(sim.data, self.camera, self.near, self.max_range)
        ranges = depth[::-1].copy()
        finite = np.isfinite(ranges)
        if self.noise > 0 and sim.noise_rng is not None:
            ranges[finite] += sim.noise_rng.normal(0.0, self.noise * self.max_range, int(finite.sum()))
        if self.resolution > 0:
            ranges[finite] = np.round(ranges[finite] / self.resolution) * self.resolution
        ranges[(ranges < self.min_range) | (ranges > self.max_range)] = np.inf
        return {"ranges": ranges.astype(np.float32).ravel().tolist()}
