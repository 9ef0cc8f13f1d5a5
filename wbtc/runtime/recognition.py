"""Camera object recognition (a Camera with a Recognition node): which Solids the camera sees, and where.

Only Solids with a non-empty `recognitionColors` are recognized (the compiler lists them in
`DeviceTable.recognizable`), never the camera's own robot or its parts. For each one, following
Webots' WbCamera/WbObjectDetection (read for their rules):

- its extent is the union, in the camera frame, of what is seen of each of its bounding objects
  (its own and its descendant Solids' collision geoms) by the frustum rules of
  `recognition_bounds` (box and mesh corners, round geoms by their centre); a Solid with no
  bounding object at all (nor any below it) stands as its shapes' bounding sphere;
- `position` is that box's centre, `size` its extent along the camera's x and y axes (depth and
  width: what Webots' controller API receives, though its overlay shows y and z); the object
  is dropped when its centre is farther ahead (or behind) than `maxRange` plus half its depth;
- `occlusion` 1: a ray from the camera to the Solid's origin that meets another bounding object
  more than half the object's depth before its end hides it; `occlusion` 2: rays from the camera to
  the Solid's origin plus each corner of the box (6 extreme points for round-only objects),
  Webots adding the camera-frame corner offsets to world-frame positions as they are, hide it when
  every ray meets another bounding object more than half the box's extent along x, x, y, y, z, z
  (and 0 for the 7th and 8th ray, where Webots reads past its size vector) before its end;
- `position_on_image`/`size_on_image`: the box's corners (6 extreme points for round-only objects;
  plus its centre for non-planar cameras) projected by `camera_projection`, the centre of their
  pixel box (rounded) and its size (ceil); an object under one pixel wide or high is dropped;
- `orientation`: the Solid's rotation in the camera frame (axis-angle); `colors`:
  `recognitionColors`; `model`: the Solid's `model` field; `id`: the Webots node id (the scene
  tree's, else 1 + the Solid's index among the recognizable ones);
- `maxObjects` > 0 keeps the ones biggest on the image.

Not honoured yet: `frameColor`/`frameThickness` overlays, `lens` distortion, pre-R2022a cameras'
axes (their frame is used as is); Webots' bounding sphere of several shapes is approximated by one
enclosing their geoms' bounding spheres.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import mujoco
import numpy as np

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP
from wbtc.compile.frames import mat_to_quat, quat_to_axis_angle
from wbtc.compile.table import Recognizable
from wbtc.runtime.camera_projection import Optics, project
from wbtc.runtime.recognition_bounds import Bounds, Frustum, point_bounds, rod_extent, round_bounds
from wbtc.runtime.recognition_bounds import clip_to_view as clip_to_view  # the Radar's
from wbtc.runtime.recognition_bounds import geom_corners as geom_corners  # the Radar's

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

_CORNERS = np.array([[sx, sy, sz] for sz in (1, -1) for sy in (1, -1) for sx in (1, -1)], dtype=float)
_EXTREMES = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)
_SPHERE, _CAPSULE, _ELLIPSOID, _CYLINDER, _BOX, _MESH = (
    int(kind) for kind in (mujoco.mjtGeom.mjGEOM_SPHERE, mujoco.mjtGeom.mjGEOM_CAPSULE, mujoco.mjtGeom.mjGEOM_ELLIPSOID,
                           mujoco.mjtGeom.mjGEOM_CYLINDER, mujoco.mjtGeom.mjGEOM_BOX, mujoco.mjtGeom.mjGEOM_MESH))
_ROUND = (_SPHERE, _CYLINDER, _CAPSULE, _ELLIPSOID)


@dataclass
class Target:
    """A recognizable Solid in one compiled model.

    `geoms` are its bounding objects' geoms (its subtree's collision geoms); with none, `sphere`
    holds its shapes' bounding sphere (centre in its body frame, radius).
    """

    entry: Recognizable
    index: int
    body: int
    bodies: frozenset[int]
    geoms: list[int]
    sphere: tuple[np.ndarray, float] | None = None


@dataclass
class Settings:
    """A Recognition node's fields."""

    max_range: float = 100.0
    max_objects: int = -1
    occlusion: int = 1
    segmentation: bool = False

    @classmethod
    def of(cls, fields: dict[str, Any] | None) -> Settings:
        """From the node's plain fields (defaults for missing ones)."""
        fields = fields or {}
        # `occlusion` was an SFBool before R2023a (TRUE: the centre check, i.e. 1).
        return cls(float(fields.get("maxRange", 100.0)), int(fields.get("maxObjects", -1)),
                   int(fields.get("occlusion", 1)), bool(fields.get("segmentation", False)))


def targets(sim: Simulation) -> list[Target]:
    """The recognizable Solids of the simulation's model."""
    model, data = sim.model, sim.data
    children: dict[int, list[int]] = {}
    for b in range(1, model.nbody):
        children.setdefault(int(model.body_parentid[b]), []).append(b)
    out = []
    for index, entry in enumerate(getattr(sim.table, "recognizable", [])):
        try:
            body = model.body(entry.body).id
        except KeyError:
            continue
        bodies, stack = {body}, [body]
        while stack:
            for child in children.get(stack.pop(), []):
                bodies.add(child)
                stack.append(child)
        mine = [g for g in range(model.ngeom) if int(model.geom_bodyid[g]) in bodies
                and model.geom_type[g] != mujoco.mjtGeom.mjGEOM_PLANE]
        geoms = [g for g in mine if model.geom_group[g] == COLLISION_GROUP]
        sphere = None if geoms else _bounding_sphere(model, data, body, [g for g in mine
                                                                          if model.geom_group[g] == VISUAL_GROUP])
        out.append(Target(entry, index, body, frozenset(bodies), geoms, sphere))
    return out


def _bounding_sphere(model: mujoco.MjModel, data: mujoco.MjData, body: int,
                     geoms: list[int]) -> tuple[np.ndarray, float] | None:
    """A sphere around the geoms' bounding spheres, centre in the body's frame (exact for one geom)."""
    if not geoms:
        return None
    rot_t = data.xmat[body].reshape(3, 3).T
    centres = np.array([rot_t @ (data.geom_xpos[g] - data.xpos[body]) for g in geoms])
    radii = np.array([float(model.geom_rbound[g]) for g in geoms])
    centre = ((centres - radii[:, None]).min(axis=0) + (centres + radii[:, None]).max(axis=0)) / 2
    return centre, float(np.max(np.linalg.norm(centres - centre, axis=1) + radii))


def _geom_box(model: mujoco.MjModel, data: mujoco.MjData, geom: int, origin: np.ndarray, rot_t: np.ndarray,
              frustum: Frustum, bounds: Bounds) -> None:
    """Add what the camera sees of one bounding-object geom to `bounds`."""
    centre = rot_t @ (data.geom_xpos[geom] - origin)
    kind = int(model.geom_type[geom])
    size = model.geom_size[geom]
    mat = rot_t @ data.geom_xmat[geom].reshape(3, 3)
    if kind in _ROUND:
        if kind == _SPHERE:
            extent = np.full(3, 2 * size[0])
        elif kind == _ELLIPSOID:
            extent = 2 * np.sqrt((mat * mat) @ (size * size))
        else:
            radius = size[0]
            length = 2 * size[1] + (2 * radius if kind == _CAPSULE else 0.0)
            extent = rod_extent(mat[:, 2], length, radius)
            bounds.sphere_only = False  # Webots sets this before it checks the view
        box = round_bounds(centre, extent, frustum)
    else:
        box = point_bounds(centre + _points(model, geom) @ mat.T, frustum)
        if box is not None:
            bounds.sphere_only = False
    if box is not None:
        bounds.add(*box)


def _points(model: mujoco.MjModel, geom: int) -> np.ndarray:
    """A point geom's points in its own frame: a mesh's vertices, else its bounding box's corners."""
    if int(model.geom_type[geom]) == _MESH:
        mesh = int(model.geom_dataid[geom])
        start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
        return np.asarray(model.mesh_vert[start:start + count], dtype=float)
    if int(model.geom_type[geom]) == _BOX:
        return _CORNERS * model.geom_size[geom]
    aabb = model.geom_aabb[geom]
    return aabb[:3] + _CORNERS * aabb[3:]


def _round_half_away(value: float) -> int:
    return int(math.floor(value + 0.5)) if value >= 0 else -int(math.floor(-value + 0.5))


def recognize(sim: Simulation, found: list[Target], origin: np.ndarray, rotation: np.ndarray, optics: Optics,
              settings: Settings, skip_bodies: frozenset[int]) -> list[dict[str, Any]]:
    """The recognition objects seen from a camera frame (model frame position and rotation matrix)."""
    model, data = sim.model, sim.data
    rot_t = rotation.T
    frustum = Frustum.of(optics.fov, optics.fov_y_frustum(), optics.planar)
    objects: list[tuple[int, dict[str, Any]]] = []
    tree = sim.tree
    for target in found:
        if target.body in skip_bodies or not (target.geoms or target.sphere):
            continue
        if np.linalg.norm(data.xpos[target.body] - origin) > settings.max_range + _radius(model, target):
            continue
        bounds = Bounds()
        if target.sphere is not None:
            local, radius = target.sphere
            world = data.xpos[target.body] + data.xmat[target.body].reshape(3, 3) @ local
            box = round_bounds(rot_t @ (world - origin), np.full(3, 2 * radius), frustum)
            if box is not None:
                bounds.add(*box)
        for geom in target.geoms:
            _geom_box(model, data, geom, origin, rot_t, frustum, bounds)
        if bounds.low is None or bounds.high is None:
            continue
        centre, size = (bounds.low + bounds.high) / 2, bounds.high - bounds.low
        if abs(centre[0]) > settings.max_range + size[0] / 2:
            continue
        corners = (_EXTREMES if bounds.sphere_only else _CORNERS) * size / 2
        if settings.occlusion >= 2:
            if _hidden_from_corners(sim, target, origin, corners, size, skip_bodies):
                continue
        elif settings.occlusion == 1 and _occluded(sim, target, origin, size[0], skip_bodies):
            continue
        points = list(corners) + ([] if optics.planar else [np.zeros(3)])
        us, vs = zip(*(project(centre + corner, optics) for corner in points), strict=True)
        min_u, max_u, min_v, max_v = min(us), max(us), min(vs), max(vs)
        pixel_size = (math.ceil(max_u - min_u), math.ceil(max_v - min_v))
        if pixel_size[0] < 1 or pixel_size[1] < 1:
            continue
        relative = rot_t @ data.xmat[target.body].reshape(3, 3)
        node_id = tree.node_id(target.entry.node) if tree is not None else -1
        objects.append((pixel_size[0] * pixel_size[1], {
            "id": node_id if node_id >= 0 else target.index + 1,
            "position": [float(c) for c in centre],
            "orientation": [float(c) for c in quat_to_axis_angle(mat_to_quat(relative))],
            # Webots sends the box's extents along x and y (its depth and width), not y and z.
            "size": [float(size[0]), float(size[1])],
            "position_on_image": [_round_half_away((min_u + max_u) / 2), _round_half_away((min_v + max_v) / 2)],
            "size_on_image": list(pixel_size),
            "colors": [list(c) for c in target.entry.colors],
            "model": target.entry.model,
        }))
    if settings.max_objects > 0 and len(objects) > settings.max_objects:
        objects.sort(key=lambda item: -item[0])  # stable: ties keep the scene order
        objects = objects[:settings.max_objects]
    return [obj for _, obj in objects]


def _radius(model: mujoco.MjModel, target: Target) -> float:
    """A radius around the Solid's origin holding all its geoms (for early culling)."""
    if target.sphere is not None:
        return float(np.linalg.norm(target.sphere[0])) + target.sphere[1]
    return max((float(np.linalg.norm(model.geom_pos[g])) + float(model.geom_rbound[g]) for g in target.geoms
                if int(model.geom_bodyid[g]) == target.body), default=0.0) + \
        (math.inf if any(int(model.geom_bodyid[g]) != target.body for g in target.geoms) else 0.0)


def _blocked_by(sim: Simulation, target: Target, origin: np.ndarray, delta: np.ndarray,
                skip_bodies: frozenset[int]) -> float:
    """How far before the end of the ray origin → origin + delta another bounding object stands (0: none)."""
    length = float(np.linalg.norm(delta))
    if length <= 0:
        return 0.0
    hit, _ = sim.rays.cast(origin, delta / length, length, False, skip_bodies | target.bodies)
    return length - hit if math.isfinite(hit) else 0.0


def _occluded(sim: Simulation, target: Target, origin: np.ndarray, depth: float, skip_bodies: frozenset[int]) -> bool:
    """Occlusion 1: another bounding object stands between the camera and the Solid's origin."""
    delta = sim.data.xpos[target.body] - origin
    return _blocked_by(sim, target, origin, delta, skip_bodies) > depth / 2


def _hidden_from_corners(sim: Simulation, target: Target, origin: np.ndarray, corners: np.ndarray,
                         size: np.ndarray, skip_bodies: frozenset[int]) -> bool:
    """Occlusion 2: every ray to the Solid's origin plus a corner offset is blocked (Webots' thresholds)."""
    offset = sim.data.xpos[target.body] - origin
    # Webots adds camera-frame offsets to a world-frame vector as they are: the world's axes, not the model's.
    to_model = np.asarray(getattr(sim.table, "to_model", np.eye(3)))
    for i, corner in enumerate(corners):
        axis = i // 2
        threshold = 0.5 * size[axis] if axis < 3 else 0.0
        if _blocked_by(sim, target, origin, to_model @ corner + offset, skip_bodies) <= threshold:
            return False
    return True
