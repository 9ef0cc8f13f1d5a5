"""DistanceSensor rays: directions, weights and what each ray hits (Webots' WbDistanceSensor rules).

Rays start at the sensor's origin along its +x axis; `numberOfRays` rays spread over a cone of
full angle `aperture`, weighted by exp(−(θ / (aperture · gaussianWidth))²). Generic, sonar and
laser sensors hit collision geometry (bounding objects); infra-red sensors hit visual geometry and
see its red channel (reflection factor 0.2 + 0.8 · red). Generic, sonar and laser rays never see
their own robot's bodies; infra-red rays see the robot itself, as in Webots, but only surfaces they
meet from the front (a ray leaving the body it starts in goes on), as rendered surfaces are seen.

Not honoured yet: the exact ring layout Webots uses beyond 10 rays (rings of up to 3k + 1 rays are
used here too, evenly spread), the laser's red spot, `redColorSensitivity`.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP

_mj_ray = mujoco.mj_ray  # bound once: sensors call it thousands of times a second

# (azimuth α, fraction t of the half aperture) for 1..10 rays, as Webots lays them out.
_POLAR: dict[int, list[tuple[float, float]]] = {
    1: [(0.0, 0.0)],
    2: [(math.pi / 2, 1.0), (-math.pi / 2, 1.0)],
    3: [(0.0, 1.0), (2 * math.pi / 3, 1.0), (-2 * math.pi / 3, 1.0)],
}
_POLAR[4] = [(0.0, 0.0)] + _POLAR[3]
_POLAR[5] = [(0.0, 0.0)] + [(k * math.pi / 2, 1.0) for k in range(4)]
_POLAR[6] = [(0.0, 0.0)] + [(k * 2 * math.pi / 5, 1.0) for k in range(5)]
_POLAR[7] = [(0.0, 0.0)] + [(k * math.pi / 3, 1.0) for k in range(6)]
_POLAR[8] = [(0.0, 0.0)] + [(k * 2 * math.pi / 7, 1.0) for k in range(7)]
_POLAR[9] = [(k * 2 * math.pi / 3, 0.3) for k in range(3)] + [(k * math.pi / 3, 1.0) for k in range(6)]
_POLAR[10] = [(0.0, 0.0)] + [(k * 2 * math.pi / 3, 0.5) for k in range(3)] + [(k * math.pi / 3, 1.0)
                                                                                  for k in range(6)]


def _polar(n: int) -> list[tuple[float, float]]:
    if n in _POLAR:
        return _POLAR[n]
    rings, count, k = [], 1, 1
    pairs = [(0.0, 0.0)]
    while count < n:
        size = min(3 * k + 1, n - count)
        rings.append((k, size))
        count += size
        k += 1
    for ring, size in rings:
        pairs += [(j * 2 * math.pi / size, ring / len(rings)) for j in range(size)]
    return pairs


def ray_pattern(n: int, aperture: float, gaussian_width: float) -> tuple[np.ndarray, np.ndarray]:
    """Unit ray directions (n, 3) in the sensor frame and their normalised weights."""
    if n <= 1 or aperture <= 0:
        return np.array([[1.0, 0.0, 0.0]]), np.array([1.0])
    dirs, weights = [], []
    for alpha, t in _polar(n):
        theta = t * aperture / 2
        a = alpha + math.pi / 2
        dirs.append((math.cos(theta), math.sin(theta) * math.sin(a), -math.sin(theta) * math.cos(a)))
        width = aperture * gaussian_width
        weights.append(math.exp(-((theta / width) ** 2)) if width > 0 else 1.0)
    w = np.array(weights)
    return np.array(dirs), w / w.sum()


class RayCaster:
    """Casts rays in one model, skipping a set of bodies (the sensor's own robot).

    Sensors cast a few rays every step, so the Python around each `mj_ray` is kept lean: the
    model's geom → body table is read once, continuation points are written into reused buffers
    from plain floats (the same IEEE operations as numpy's, so the same distances to the bit).
    """

    def __init__(self, model: mujoco.MjModel, data: mujoco.MjData, unseen: list[int] | None = None) -> None:
        self.model, self.data = model, data
        # Visual geoms infra-red rays pass through: CadShapes' (Webots' rays only meet Shape nodes).
        self._unseen = frozenset(unseen or ())
        self.visual = np.zeros(6, dtype=np.uint8)
        self.visual[VISUAL_GROUP] = 1
        self.collision = np.zeros(6, dtype=np.uint8)
        self.collision[COLLISION_GROUP] = 1
        self._geom = np.zeros(1, dtype=np.int32)
        self.normal = np.zeros(3)  # the surface normal at the last hit
        self._body: list[int] = model.geom_bodyid.tolist()  # a plain list: indexing numpy costs more
        self._point = np.zeros(3)  # where a ray goes on past a hit it does not count
        self._aside = np.zeros(3)  # the seam cast's origin

    def _past_seam(self, point: np.ndarray, direction: np.ndarray, groups: np.ndarray, exclude: int) -> float:
        """Cast again from 0.1 µm aside after a miss.

        MuJoCo's ray misses a mesh exactly on the edge between two of its triangles (a ground sensor
        right above a floor's grid line), where Webots' ray hits.
        """
        # direction × x̂ (or × ŷ when the ray runs along x), written out: np.cross costs ~70 µs a call.
        dx, dy, dz = direction.tolist()
        sx, sy, sz = (0.0, dz, -dy) if abs(dx) < 0.9 else (-dz, 0.0, dx)
        scale = 1e-7 / math.sqrt(sx * sx + sy * sy + sz * sz)
        px, py, pz = point.tolist()
        # point + side, element by element as numpy would add them (the same IEEE sums).
        aside = self._aside
        aside[0], aside[1], aside[2] = px + sx * scale, py + sy * scale, pz + sz * scale
        return _mj_ray(self.model, self.data, aside, direction, groups, 1, exclude, self._geom, self.normal)

    def cast(self, start: np.ndarray, direction: np.ndarray, max_range: float, visual: bool,
             skip_bodies: frozenset[int], exclude: int = -1, front_only: bool = False) -> tuple[float, int]:
        """Distance to the first hit within `max_range` (inf if none) and the geom hit (-1).

        Args:
            start: the ray's origin (model frame).
            direction: its unit direction.
            max_range: the longest distance that counts.
            visual: True for visual geoms (infra-red), False for collision geoms.
            skip_bodies: bodies the ray goes through (the sensor's robot).
            exclude: one of them that MuJoCo can skip by itself (the body the sensor is on), which
                saves casting again past its geoms.
            front_only: see only surfaces the ray meets from outside (a ray leaving a shape it starts
                in goes on), as rendered, back-face culled surfaces are seen.

        The hit surface's normal is left in `self.normal`.
        """
        groups = self.visual if visual else self.collision
        model, data, found, normal, body = self.model, self.data, self._geom, self.normal, self._body
        travelled, point = 0.0, start
        for _ in range(8):
            dist = _mj_ray(model, data, point, direction, groups, 1, exclude, found, normal)
            if dist < 0:
                dist = self._past_seam(point, direction, groups, exclude)
            if dist < 0 or travelled + dist > max_range:
                return math.inf, -1
            geom = int(found[0])
            # ndarray.dot: the same BLAS dot product as `@`, with less overhead.
            back = front_only and float(normal.dot(direction)) > 0.0
            if body[geom] not in skip_bodies and not back and not (visual and geom in self._unseen):
                return travelled + dist, geom
            # Another part of the robot (a wheel), a surface seen from behind, or a CadShape for an
            # infra-red ray: continue just past it
            # (point + direction · step, element by element as numpy would).
            step = dist + 1e-6
            travelled += step
            px, py, pz = point.tolist()
            dx, dy, dz = direction.tolist()
            point = self._point
            point[0], point[1], point[2] = px + dx * step, py + dy * step, pz + dz * step
        return math.inf, -1
