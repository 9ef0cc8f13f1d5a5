"""Webots' Radar: the Solids with a `radarCrossSection` in its field of view, as targets.

A Solid is seen when part of its bounding objects is in the radar's frustum (along the radar's +x
axis, `horizontalFieldOfView` × `verticalFieldOfView`, up to `maxRange`), clipped to it as camera
recognition clips them (`wbtc.runtime.recognition`, after WbObjectDetection), and, with `occlusion`,
when the ray to its origin meets no other bounding object more than half its depth before. For each
target, as WbRadar computes:

- distance: from the radar to the centre of the target's part in view, plus `rangeNoise`; closer
  than `minRange` less half the target's depth it is not seen; then clamped to [minRange, maxRange];
- received power: the radar equation, Pt·G²·λ²·σ / ((4π)³·d⁴) with Pt = `transmittedPower` (dBm),
  G = `antennaGain` (dBi), λ = c / `frequency` (GHz), σ = the cross section; below
  `minDetectableSignal` (dBm) the target is lost; reported in dBm;
- speed: the radial speed (positive away from the radar) of the target relative to the radar, both
  velocities measured from their positions at the last sample (0 at the first), plus `speedNoise`,
  filtered by `minRadialSpeed`/`maxRadialSpeed` and `minAbsoluteRadialSpeed`;
- azimuth: the horizontal angle, positive to the radar's right (Webots' sign), clamped to the field of
  view, plus `angularNoise`.

Targets closer to each other than `cellDistance` (and `cellSpeed`, when set) merge into one, their
values averaged with the received powers as weights, as WbRadar::mergeTargets.

A target without bounding objects is seen through its shapes (Webots uses their bounding sphere).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP
from wbtc.compile.table import DeviceEntry
from wbtc.runtime.recognition import clip_to_view, geom_corners
from wbtc.runtime.sensors import Sensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

#: Speed of light (m/s), for the wavelength.
LIGHT_SPEED = 299792458.0


def _dbm_to_watts(dbm: float) -> float:
    return 0.001 * 10.0 ** (dbm / 10.0)


class Radar(Sensor):
    """One Radar device; its value is a list of (distance, received power, speed, azimuth) tuples."""

    def __init__(self, entry: DeviceEntry, sim: Simulation, skip_bodies: frozenset[int]) -> None:
        super().__init__(entry, sim, skip_bodies)
        f = entry.fields
        self.min_range = float(f.get("minRange", 1.0))
        self.max_range = float(f.get("maxRange", 50.0))
        self.horizontal = float(f.get("horizontalFieldOfView", 0.78))
        self.vertical = float(f.get("verticalFieldOfView", 0.1))
        self.min_abs_speed = float(f.get("minAbsoluteRadialSpeed", 0.0))
        self.min_speed = float(f.get("minRadialSpeed", 0.0))
        self.max_speed = float(f.get("maxRadialSpeed", 0.0))
        if (self.min_speed or self.max_speed) and self.max_speed <= self.min_speed:
            self.max_speed = self.min_speed + 1.0  # Webots' correction (it warns on load)
        self.cell_distance = float(f.get("cellDistance", 0.0))
        self.cell_speed = float(f.get("cellSpeed", 0.0))
        self.noise = (float(f.get("rangeNoise", 0.0)), float(f.get("speedNoise", 0.0)),
                      float(f.get("angularNoise", 0.0)))
        self.occlusion = bool(f.get("occlusion", False))
        wavelength = LIGHT_SPEED / (float(f.get("frequency", 24.0)) * 1e9)
        gain = 10.0 ** (float(f.get("antennaGain", 20.0)) / 10.0)
        self.power_factor = (_dbm_to_watts(float(f.get("transmittedPower", 20.0))) * gain * gain * wavelength ** 2
                             / (4.0 * math.pi) ** 3)
        self.threshold = _dbm_to_watts(float(f.get("minDetectableSignal", -100.0)))
        self._targets: tuple[Any, list[tuple[int, float, float]]] = (None, [])
        self._previous: dict[int, np.ndarray] = {}  # the targets' positions at the last sample
        self._last_radar = np.zeros(3)
        self._last_time: float | None = None

    def _target_bodies(self, sim: Simulation) -> list[tuple[int, float, frozenset[int], list[int]]]:
        """(body, cross section, the bodies below it, their collision geoms) of every target, per model."""
        model = sim.model
        if self._targets[0] is not model:
            found = []
            for name, cross_section in sim.table.radar_targets:
                body = model.body(name).id
                below = frozenset(b for b in range(model.nbody) if b == body or _descends(model, b, body))
                mine = [g for g in range(model.ngeom) if int(model.geom_bodyid[g]) in below
                        and model.geom_type[g] != mujoco.mjtGeom.mjGEOM_PLANE]
                # Its bounding objects; without any, its shapes (Webots then uses their bounding sphere).
                geoms = [g for g in mine if model.geom_group[g] == COLLISION_GROUP] or \
                    [g for g in mine if model.geom_group[g] == VISUAL_GROUP]
                found.append((body, cross_section, below, geoms))
            self._targets = (model, found)
        return self._targets[1]

    def _extent(self, sim: Simulation, geoms: list[int], pos: np.ndarray, rot_t: np.ndarray) -> tuple | None:
        """(centre, size) in the radar frame of what of the target's bounding objects is in the frustum."""
        tan_x, tan_y = math.tan(self.horizontal / 2), math.tan(self.vertical / 2)
        low = high = None
        for geom in geoms:
            corners = geom_corners(sim.model, sim.data, geom, pos, rot_t)
            if sim.model.geom_type[geom] in _ROUND:
                box = _round_in_view(corners, tan_x, tan_y, self.horizontal <= math.pi / 2)
            else:
                box = clip_to_view(corners, tan_x, tan_y)
            if box is None:
                continue
            low = box[0] if low is None else np.minimum(low, box[0])
            high = box[1] if high is None else np.maximum(high, box[1])
        if low is None or high is None:
            return None
        return (low + high) / 2, high - low

    def sample(self, sim: Simulation) -> list[tuple[float, float, float, float]]:
        """The targets seen now."""
        pos, mat = self.frame(sim)
        rng = sim.noise_rng
        # Speeds as WbRadar measures them: positions now against the last sample's, over the time between.
        elapsed = (sim.time_ms - self._last_time) / 1000.0 if self._last_time is not None else 0.0
        radar_velocity = (pos - self._last_radar) / elapsed if elapsed > 0 else np.zeros(3)
        previous, self._previous = self._previous, {}
        for body, *_ in self._target_bodies(sim):
            self._previous[body] = np.array(sim.data.xpos[body])
        self._last_radar, self._last_time = np.array(pos), sim.time_ms
        targets = []
        for body, cross_section, below, geoms in self._target_bodies(sim):
            if body == self.body or not geoms:
                continue
            extent = self._extent(sim, geoms, pos, mat.T)
            if extent is None:
                continue
            centre, size = extent
            if float(np.linalg.norm(centre)) > self.max_range + size[0] / 2:  # a radar's distance: straight
                continue
            world = sim.data.xpos[body] - pos
            if self.occlusion and self._occluded(sim, pos, world, size[0], below):
                continue
            distance = float(np.linalg.norm(centre))
            if rng is not None and self.noise[0] > 0:
                distance += self.noise[0] * rng.normal()
            if distance < self.min_range - size[0] / 2:
                continue
            distance = min(max(distance, self.min_range), self.max_range)
            power = self.power_factor * cross_section / distance ** 4
            if power < self.threshold:
                continue
            target_velocity = (sim.data.xpos[body] - previous[body]) / elapsed if body in previous and elapsed > 0 \
                else np.zeros(3)
            relative = target_velocity - radar_velocity
            norm = float(np.linalg.norm(world))
            speed = float(np.dot(world / norm, relative)) if norm > 0 else 0.0
            if rng is not None and self.noise[1] > 0:
                speed += self.noise[1] * rng.normal()
            if (self.min_speed != 0.0 or self.max_speed != 0.0) and not self.min_speed <= speed <= self.max_speed:
                continue
            if self.min_abs_speed > 0 and abs(speed) < self.min_abs_speed:
                continue
            azimuth = math.atan2(-centre[1], centre[0])  # positive to the right
            azimuth = min(max(azimuth, -self.horizontal / 2), self.horizontal / 2)
            if rng is not None and self.noise[2] > 0:
                azimuth += self.noise[2] * rng.normal()
            targets.append([distance, power, speed, azimuth])
        if self.cell_distance > 0:
            targets = _merge(targets, self.cell_distance, self.cell_speed)
        return [(d, 10.0 * math.log10(p / 0.001), s, a) for d, p, s, a in targets]

    def _occluded(self, sim: Simulation, pos: np.ndarray, world: np.ndarray, depth: float,
                  target: frozenset[int]) -> bool:
        """Another body's bounding object more than half the target's depth before its origin hides it."""
        length = float(np.linalg.norm(world))
        if length <= 0:
            return False
        hit, _ = sim.rays.cast(pos, world / length, length, False, self.skip_bodies | target)
        return math.isfinite(hit) and length - hit > depth / 2


#: Geometries WbObjectDetection tests by their centre's distance to the frustum's planes.
_ROUND = (mujoco.mjtGeom.mjGEOM_SPHERE, mujoco.mjtGeom.mjGEOM_CYLINDER, mujoco.mjtGeom.mjGEOM_CAPSULE)


def _round_in_view(corners: np.ndarray, tan_x: float, tan_y: float, trim: bool) -> tuple | None:
    """A sphere's, cylinder's or capsule's (low, high) box in the radar frame, or None out of view.

    As WbObjectDetection: it is out of view when its centre is farther outside a side plane than
    half its size across that plane; what sticks out is trimmed off its box (for fields of view up
    to 90°).
    """
    low, high = corners.min(axis=0), corners.max(axis=0)
    centre, size = (low + high) / 2, high - low
    # Inward normals of the right, bottom, left and top planes (x ahead, y left, z up).
    normals = np.array([[tan_x, 1.0, 0.0], [tan_y, 0.0, 1.0], [tan_x, -1.0, 0.0], [tan_y, 0.0, -1.0]])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    outside = np.zeros(4)
    for j, normal in enumerate(normals):
        d, half = float(normal @ centre), size[1 + j % 2] / 2
        if d < -half:
            return None
        if d < half:
            outside[j] = half - d
    if trim:
        right, bottom, left, top = outside
        size = size - np.array([0.0, right + left, bottom + top])
        centre = centre + 0.5 * np.array([0.0, right - left, bottom - top])
    return centre - size / 2, centre + size / 2


def _descends(model: mujoco.MjModel, body: int, ancestor: int) -> bool:
    while body > 0:
        body = int(model.body_parentid[body])
        if body == ancestor:
            return True
    return False


def _merge(targets: list[list[float]], cell_distance: float, cell_speed: float) -> list[list[float]]:
    """Merge targets closer than a cell (WbRadar::mergeTargets): power-weighted means, first one kept."""
    i = 0
    while i < len(targets) - 1:
        first = targets[i]
        close = [j for j in range(i + 1, len(targets))
                 if abs(first[0] - targets[j][0]) < cell_distance
                 and (cell_speed <= 0.0 or abs(first[2] - targets[j][2]) < cell_speed)]
        if not close:
            i += 1
            continue
        group = [first] + [targets[j] for j in close]
        power = sum(t[1] for t in group)
        targets[i] = [sum(t[0] * t[1] for t in group) / power, power,
                      sum(t[2] * t[1] for t in group) / power, sum(t[3] * t[1] for t in group) / power]
        for j in reversed(close):
            del targets[j]
    return targets
