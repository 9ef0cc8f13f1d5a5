"""What a DistanceSensor's rays see at one sample: the distance its lookup table reads, and a laser's spot.

Webots' WbDistanceSensor rules (the rays themselves, their layout and what they hit: see `rays`):

- generic: the weighted mean of the rays' distances (a ray that hits nothing counts the range);
- infra-red: the same mean divided by the weighted mean reflection, 0.2 + 0.8 · red of the surface
  where each ray lands (`surface`), 1 for a ray that hits nothing: dark surfaces look farther;
- sonar: the nearest echo, a ray echoing only when it meets the surface within π/8 of its normal;
- laser: its one ray's distance, and a red spot where it lands (`laser_spot`).

An e-puck samples up to eight of these every step, so the work per ray is kept to the ray casts
and the arithmetic of a plain loop over the rays, in the same order: the values are that loop's to
the bit. The sensor's position and orientation are live views into MjData, made once per MjData.
Each ray is cast on its own (`mj_ray`): `mj_multiRay` casts from one origin only and costs about
15 µs a call before its first ray, against about 2.6 µs for one `mj_ray` (MuJoCo 4.0, e-puck world).

Not honoured yet: what `rays` lists (Webots' ray layout beyond 10 rays, `redColorSensitivity`).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import mujoco

    from wbtc.runtime.sensors import DistanceSensor
    from wbtc.runtime.simulation import Simulation

_SONAR_COS = math.cos(math.pi / 8)
_NO_BODIES: frozenset[int] = frozenset()


class SiteViews:
    """A site's position and rotation matrix as live views into one MjData (remade for another one)."""

    def __init__(self, site: int) -> None:
        self.site = site
        self.data: mujoco.MjData | None = None
        self.pos = np.zeros(3)
        self.mat = np.eye(3)

    def frame(self, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray]:
        """World position and rotation matrix of the site in `data` (views: they follow the state)."""
        if self.data is not data:
            self.data = data
            self.pos = data.site_xpos[self.site]
            self.mat = data.site_xmat[self.site].reshape(3, 3)
        return self.pos, self.mat


def ray_distance(sensor: DistanceSensor, sim: Simulation) -> float:
    """The distance the sensor's lookup table reads now (before noise and resolution).

    Sets `sensor.spot` for a laser (None when it hits nothing or draws no spot).
    """
    pos, mat = sensor.views.frame(sim.data)
    caster = sim.rays
    normal = caster.normal  # the caster's buffer: it holds the normal of the last hit
    kind, max_range = sensor.kind, sensor.range
    infra_red, sonar, laser = kind == "infra-red", kind == "sonar", kind == "laser"
    num = den = 0.0
    nearest = math.inf
    for direction, weight in sensor.rays:
        world_dir = mat.dot(direction)  # the same BLAS product as `mat @ direction`, with less overhead
        if infra_red:  # infra-red sees its own robot too (Webots' docs), from the front only (see rays)
            dist, geom = caster.cast(pos, world_dir, max_range, True, _NO_BODIES, -1, True)
        else:
            dist, geom = caster.cast(pos, world_dir, max_range, False, sensor.skip_bodies, sensor.body)
        # A sonar echo returns only when the ray meets the surface within π/8 of its normal.
        if sonar and geom >= 0 and abs(float(normal.dot(world_dir))) < _SONAR_COS:
            dist = math.inf
        hit = math.isfinite(dist)
        if laser:
            sensor.spot = laser_spot(pos, world_dir, dist, normal, sensor.aperture) if hit else None
        nearest = min(nearest, dist)
        d = dist if hit else max_range
        # Infra-red: dark surfaces reflect less and look farther (reflection 0.2 + 0.8 red), the red
        # being the surface's colour where the ray lands (texture included).
        reflect = 0.2 + 0.8 * sim.surface.red(sim.data, geom, pos + world_dir * dist) if (infra_red and hit) else 1.0
        num += weight * d
        den += weight * reflect
    if sonar or laser:
        return nearest if math.isfinite(nearest) else max_range
    return num / den


def laser_spot(pos: np.ndarray, direction: np.ndarray, dist: float, normal: np.ndarray,
               aperture: float) -> tuple[np.ndarray, np.ndarray, float] | None:
    """Webots' laser spot, or None when there is none.

    A disc of radius `aperture` on the surface, drawn when the beam meets it within 80° (1.3963 rad)
    of its normal, 0.5 mm towards the sensor (lineScale 0.1 / 200) so that it is not hidden in it.
    """
    if aperture <= 0:
        return None
    towards = -np.asarray(direction, dtype=float)
    facing = np.array(normal, dtype=float)  # a copy: the ray caster reuses its normal buffer
    if float(facing @ towards) < 0:  # the normal may point into the surface: turn it out
        facing = -facing
    if math.acos(min(1.0, float(facing @ towards) / max(float(np.linalg.norm(facing)), 1e-12))) >= 1.3963:
        return None
    return np.asarray(pos, dtype=float) - towards * dist + towards * 0.0005, facing, aperture
