"""Camera object recognition (a Camera with a Recognition node): which Solids the camera sees, and where.

Only Solids with a non-empty `recognitionColors` are recognized (the compiler lists them in
`DeviceTable.recognizable`), never the camera's own robot or its parts. For each one, following
Webots' WbCamera/WbObjectDetection:

- its extent is the box around its bounding objects (its own and its descendant Solids' collision
  geoms; the visual geoms when there are none), per geom: a box's or mesh's corners, a sphere as
  a cube of its diameter, a cylinder or capsule by its projected extent along each camera axis;
- corners in front of the camera but outside the frustum's side planes are projected onto those
  planes (an object entirely outside the view, or behind the camera, is not seen); the axis-aligned
  box, in the camera frame (x ahead, y left, z up), of what remains gives `position` (its centre)
  and the object's size;
- the object is dropped when its centre is farther ahead than `maxRange` plus half its depth;
- `occlusion` ≥ 1: a ray from the camera to the Solid's origin that meets another body's bounding
  object more than half the object's depth before that origin hides it;
- `position_on_image`/`size_on_image`: the box's corners projected with the camera's horizontal
  field of view (vertical one from the image's aspect), pixel = int((size − 1) · uv);
- `orientation`: the Solid's rotation in the camera frame (axis-angle); `colors`:
  `recognitionColors`; `model`: the Solid's `model` field; `id`: the Webots node id (the scene
  tree's, else 1 + the Solid's index among the recognizable ones);
- `maxObjects` > 0 keeps the ones biggest on the image.

`size` is reported as [width, height]: the box's extent along the camera's y and z axes.

Not honoured yet: `occlusion 2` (the object's outline) is checked like 1 (its centre only),
`segmentation` images, `frameColor`/`frameThickness` overlays, non-planar projections, `lens`
distortion, pre-R2022a cameras' axes (their frame is used as is), changes of `recognitionColors`
made by a supervisor after compilation.
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

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

_SIGNS = np.array([[sx, sy, sz] for sx in (1, -1) for sy in (1, -1) for sz in (1, -1)], dtype=float)


@dataclass
class Target:
    """A recognizable Solid in one compiled model."""

    entry: Recognizable
    index: int
    body: int
    bodies: frozenset[int]
    geoms: list[int]


@dataclass
class Settings:
    """A Recognition node's fields."""

    max_range: float = 100.0
    max_objects: int = -1
    occlusion: int = 1

    @classmethod
    def of(cls, fields: dict[str, Any] | None) -> Settings:
        """From the node's plain fields (defaults for missing ones)."""
        fields = fields or {}
        # `occlusion` was an SFBool before R2023a (TRUE: the centre check, i.e. 1).
        return cls(float(fields.get("maxRange", 100.0)), int(fields.get("maxObjects", -1)),
                   int(fields.get("occlusion", 1)))


def targets(sim: Simulation) -> list[Target]:
    """The recognizable Solids of the simulation's model."""
    model = sim.model
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
        geoms = [g for g in mine if model.geom_group[g] == COLLISION_GROUP] or \
            [g for g in mine if model.geom_group[g] == VISUAL_GROUP]
        out.append(Target(entry, index, body, frozenset(bodies), geoms))
    return out


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

    Points ahead of the camera outside a side plane are projected onto it (Webots' rule), points
    behind it are kept as they are, provided the geom is seen at all.
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
    if inside_count == 0:
        right, bottom, left, top = range(4)
        across = outside[right] and outside[left] and correct[bottom] and correct[top]
        up_down = outside[bottom] and outside[top] and correct[right] and correct[left]
        if not (across or up_down):
            return None
    kept = np.array(ahead + behind)
    return kept.min(axis=0), kept.max(axis=0)


def _pixel(point: np.ndarray, width: int, height: int, tan_x: float, tan_y: float) -> tuple[int, int]:
    """Webots' projection of a camera-frame point on the image (clamped to it)."""
    x, y, z = point
    if x < 0:
        u, v = (-0.5 if y > 0 else 0.5), (-0.5 if z > 0 else 0.5)
    else:
        ax = abs(x)
        u = 0.5 * (-y / ax) / tan_x if ax > 0 else (-0.5 if y > 0 else 0.5)
        v = -0.5 * (z / ax) / tan_y if ax > 0 else (-0.5 if z > 0 else 0.5)
    u = min(max(0.5 + u, 0.0), 1.0)
    v = min(max(0.5 + v, 0.0), 1.0)
    return int((width - 1) * u), int((height - 1) * v)


def _round(value: float) -> int:
    return int(math.floor(value + 0.5))


def recognize(sim: Simulation, found: list[Target], origin: np.ndarray, rotation: np.ndarray, fov: float,
              width: int, height: int, settings: Settings, skip_bodies: frozenset[int]) -> list[dict[str, Any]]:
    """The recognition objects seen from a camera frame (model frame position and rotation matrix)."""
    model, data = sim.model, sim.data
    rot_t = rotation.T
    tan_x = math.tan(fov / 2)
    tan_y = tan_x * height / max(width, 1)
    objects: list[tuple[int, dict[str, Any]]] = []
    tree = sim.tree
    for target in found:
        if target.body in skip_bodies or not target.geoms:
            continue
        if np.linalg.norm(data.xpos[target.body] - origin) > settings.max_range + _radius(model, target):
            continue
        low = high = None
        for geom in target.geoms:
            box = clip_to_view(geom_corners(model, data, geom, origin, rot_t), tan_x, tan_y)
            if box is None:
                continue
            low = box[0] if low is None else np.minimum(low, box[0])
            high = box[1] if high is None else np.maximum(high, box[1])
        if low is None or high is None:
            continue
        centre, size = (low + high) / 2, high - low
        if centre[0] > settings.max_range + size[0] / 2:
            continue
        if settings.occlusion and _occluded(sim, target, origin, size[0], skip_bodies):
            continue
        us, vs = zip(*(_pixel(centre + corner * size / 2, width, height, tan_x, tan_y) for corner in _SIGNS),
                     strict=True)
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
            "size": [float(size[1]), float(size[2])],
            "position_on_image": [_round((min_u + max_u) / 2), _round((min_v + max_v) / 2)],
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
    return max((float(np.linalg.norm(model.geom_pos[g])) + float(model.geom_rbound[g]) for g in target.geoms
                if int(model.geom_bodyid[g]) == target.body), default=0.0) + \
        (math.inf if any(int(model.geom_bodyid[g]) != target.body for g in target.geoms) else 0.0)


def _occluded(sim: Simulation, target: Target, origin: np.ndarray, depth: float, skip_bodies: frozenset[int]) -> bool:
    """Whether another body's bounding object stands between the camera and the Solid's origin."""
    delta = sim.data.xpos[target.body] - origin
    length = float(np.linalg.norm(delta))
    if length <= 0:
        return False
    hit, _ = sim.rays.cast(origin, delta / length, length, False, skip_bodies | target.bodies)
    return math.isfinite(hit) and length - hit > depth / 2
