"""Which part of a geom a recognizing camera sees: Webots' frustum planes and per-geom bounds.

Everything here is in the camera frame (x ahead, y left, z up, origin at the camera), following
Webots' WbObjectDetection (src/webots/.../WbObjectDetection.cpp, read for its rules):

- the frustum's four side planes pass through the camera and its corners (x, ±y, ±z); for a planar
  camera, or one whose horizontal field of view is under π, (x, y, z) = (1, tan(fovX/2), tan(fovY/2));
  for a wider (omnidirectional) one, Webots computes the corners from spherical angles in a loop
  whose last pass (+fovX/2, +fovY/2) alone is kept, which gives a thin wedge behind the camera;
  half angles are single-precision floats, as in Webots;
- point geoms (a box's corners, a mesh's vertices): a point ahead of the camera outside a side plane
  is moved by `n (n·p)` (Webots' `vectorProjection`, which moves it *away* from the plane, to twice
  its distance, not onto it), plane after plane; points behind the camera are kept only if some
  point is in front; when no point is inside, the object counts only if it crosses the view
  (outside the left and right planes and on the inner side of the top and bottom ones, or the
  other way round). An omnidirectional camera takes every point ahead of it, and behind it the
  points outside the back wedge (those inside it are moved off its nearest plane);
- round geoms (sphere, cylinder, capsule, and a Solid's bounding sphere when it has no bounding
  object at all) are judged by their centre's distance to each plane against half their extent
  (a cylinder's extent along each camera axis from its axis' direction); a camera of horizontal
  field of view up to π/2 trims the part outside the view from the extent and moves the centre.

`geom_corners` and `clip_to_view` are the simpler rules the Radar uses (points projected onto the
planes, every round geom as its box's corners).

Not honoured: ElevationGrid bounding objects use their bounding box corners, not their grid points.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

_SIGNS = np.array([[sx, sy, sz] for sx in (1, -1) for sy in (1, -1) for sz in (1, -1)], dtype=float)

# Webots' plane order (WbObjectDetection::FrustumPlane).
LEFT, BOTTOM, RIGHT, TOP = range(4)


@dataclass
class Frustum:
    """A camera's side planes (inward unit normals, camera frame) and whether it is omnidirectional."""

    normals: np.ndarray  # (4, 3): LEFT, BOTTOM, RIGHT, TOP
    omni: bool
    fov_x: float

    @classmethod
    def of(cls, fov_x: float, fov_y: float, planar: bool) -> Frustum:
        """The frustum of a camera with these fields of view (fov_y as Webots computes it)."""
        half_x, half_y = np.float32(fov_x / 2), np.float32(fov_y / 2)
        if planar or half_x < math.pi / 2:
            x, y, z = 1.0, math.tan(half_x), math.tan(half_y)
        else:
            cos_y = np.cos(half_y, dtype=np.float32)
            if half_y > math.pi / 4 or half_y < -math.pi / 4:
                y = float(np.cos(np.float32(half_y + np.float32(math.pi / 2))) * np.sin(half_x))
            else:
                y = float(cos_y * np.sin(half_x))
            z = float(np.sin(half_y))
            x = float(cos_y * np.cos(half_x))
        top_right, top_left = np.array([x, -y, z]), np.array([x, y, z])
        bottom_right, bottom_left = np.array([x, -y, -z]), np.array([x, y, -z])
        # Each plane through the camera and two corners, its normal the cross product in Webots' order.
        normals = np.array([np.cross(bottom_left, top_left), np.cross(bottom_right, bottom_left),
                            np.cross(top_right, bottom_right), np.cross(top_left, top_right)])
        normals /= np.linalg.norm(normals, axis=1)[:, None]
        return cls(normals, fov_x > math.pi, fov_x)


@dataclass
class Bounds:
    """The camera-frame box of what is seen of one object so far (Webots' mergeBounds keeps a box)."""

    low: np.ndarray | None = None
    high: np.ndarray | None = None
    sphere_only: bool = True  # only round geoms so far: 6 extreme points stand for it on the image

    def add(self, low: np.ndarray, high: np.ndarray) -> None:
        """Merge a box into the bounds."""
        if self.low is None or self.high is None:
            self.low, self.high = low.copy(), high.copy()
        else:
            self.low, self.high = np.minimum(self.low, low), np.maximum(self.high, high)


def point_bounds(points: np.ndarray, frustum: Frustum) -> tuple[np.ndarray, np.ndarray] | None:
    """The box of a point geom's points as Webots keeps them, or None if the geom is not seen."""
    normals = frustum.normals
    kept, behind = [], []
    outside = [False] * 4
    correct = [False] * 4
    inside_count = 0
    for point in points:
        p = np.array(point, dtype=float)
        if frustum.omni:
            inside = p[0] > 0
            if not inside:
                distances = normals @ p
                inside = bool((distances < 0).any())
                if not inside:
                    j = int(np.argmin(distances))
                    p = p + normals[j] * distances[j]
                    outside = [True] * 4
            if inside:
                correct = [True] * 4
        elif p[0] > 0:
            inside = True
            for j, normal in enumerate(normals):
                d = float(normal @ p)
                if d < 0:
                    p = p + normal * d  # Webots' vectorProjection: v + n (v·n)
                    outside[j] = True
                    inside = False
                else:
                    correct[j] = True
        else:
            behind.append(p)
            continue
        inside_count += inside
        kept.append(p)
    if not kept:
        return None
    if inside_count == 0 and not _crosses_view(outside, correct):
        return None
    every = np.array(kept + behind)
    return every.min(axis=0), every.max(axis=0)


def _crosses_view(outside: np.ndarray | list[bool], correct: np.ndarray | list[bool]) -> bool:
    """With no point inside: whether the object still spans the view, from side to side or top to bottom.

    `outside[j]` says a point lay beyond frustum plane j, `correct[j]` that one lay on its inner side.
    """
    across = outside[RIGHT] and outside[LEFT] and correct[BOTTOM] and correct[TOP]
    up_down = outside[BOTTOM] and outside[TOP] and correct[RIGHT] and correct[LEFT]
    return bool(across or up_down)


def round_bounds(centre: np.ndarray, size: np.ndarray, frustum: Frustum) -> tuple[np.ndarray, np.ndarray] | None:
    """The box of a round geom (centre and extent along the camera axes), or None if it is not seen."""
    normals = frustum.normals
    outside = np.zeros(4)
    size = np.array(size, dtype=float)
    if not frustum.omni or centre[0] < 0.0:
        # An omnidirectional camera only checks objects behind it (against its back wedge).
        inside = False
        for j, normal in enumerate(normals):
            d = float(normal @ centre)
            half = size[j % 2 + 1] / 2
            if frustum.omni:
                if d < -half:
                    inside = True
                    break
            else:
                if d < -half:
                    return None
                if d < half:
                    outside[j] = half - d
                inside = True
        if not inside:
            return None
    position = np.array(centre, dtype=float)
    if frustum.fov_x <= math.pi / 2:
        size[1] -= outside[RIGHT] + outside[LEFT]
        size[2] -= outside[BOTTOM] + outside[TOP]
        position += 0.5 * np.array([0.0, outside[RIGHT] - outside[LEFT], outside[BOTTOM] - outside[TOP]])
    return position - size / 2, position + size / 2


def rod_extent(axis: np.ndarray, length: float, radius: float) -> np.ndarray:
    """A cylinder's (or capsule's, tips included in `length`) extent along each camera axis."""
    return np.abs(axis) * length + 2 * radius * np.sqrt(np.maximum(0.0, 1.0 - axis * axis))


def geom_corners(model: mujoco.MjModel, data: mujoco.MjData, geom: int, origin: np.ndarray,
             rot_t: np.ndarray) -> np.ndarray:
    """Eight points bounding one geom, in the camera frame."""
    centre = rot_t @ (data.geom_xpos[geom] - origin)
    kind = model.geom_type[geom]
    size = model.geom_size[geom]
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return centre + _SIGNS * size[0]
    if kind in (mujoco.mjtGeom.mjGEOM_CYLINDER, mujoco.mjtGeom.mjGEOM_CAPSULE):
        radius = size[0]
        length = 2 * size[1] + (2 * radius if kind == mujoco.mjtGeom.mjGEOM_CAPSULE else 0.0)
        axis = rot_t @ data.geom_xmat[geom].reshape(3, 3)[:, 2]
        extent = np.abs(axis) * length + 2 * radius * np.sqrt(np.maximum(0.0, 1.0 - axis * axis))
        return centre + _SIGNS * extent / 2
    aabb = model.geom_aabb[geom]
    local = aabb[:3] + _SIGNS * aabb[3:]
    mat = rot_t @ data.geom_xmat[geom].reshape(3, 3)
    return centre + local @ mat.T


def clip_to_view(points: np.ndarray, tan_x: float, tan_y: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The box (min, max) of a geom's points once clipped to the view, or None if it is not in view.

    The Radar's reading: points ahead of the camera outside a side plane are projected onto it (not
    moved away from it as in `point_bounds`), points behind it are kept as they are, provided the geom
    is seen at all.
    """
    # Inward normals of the right, bottom, left and top planes (camera frame: x ahead, y left, z up).
    normals = np.array([[tan_x, 1.0, 0.0], [tan_y, 0.0, 1.0], [tan_x, -1.0, 0.0], [tan_y, 0.0, -1.0]])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    ahead, behind = [], []
    outside = [False] * 4
    correct = [False] * 4
    inside_count = 0
    for point in points:
        if point[0] <= 0:
            behind.append(point)
            continue
        p = point.copy()
        inside = True
        for j, normal in enumerate(normals):
            d = float(normal @ p)
            if d < 0:
                p = p - d * normal
                outside[j] = True
                inside = False
            else:
                correct[j] = True
        inside_count += inside
        ahead.append(p)
    if not ahead:
        return None
    if inside_count == 0 and not _crosses_view(outside, correct):
        return None
    kept = np.array(ahead + behind)
    return kept.min(axis=0), kept.max(axis=0)
