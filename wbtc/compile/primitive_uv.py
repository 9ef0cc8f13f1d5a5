"""Textured primitives as triangle meshes carrying a Pen's texture coordinates (Webots' paint layer).

Webots paints a pen's ink into a layer of its own over a shape's texture, addressed by a second set of
texture coordinates that never repeat: a Box's six faces each get their own slot of a 4 x 2 grid, a
Cylinder's side, top and bottom slots of a 2 x 2 one, a Cone's side and bottom a 2 x 1 one, so that
ink on one face stays on that face though the texture itself shows the whole image on each. The layer
is the image's size times the grid (a 256-pixel image gives a Box a 1024 x 512 layer).

MuJoCo draws one texture per shape, so a paintable shape is compiled as a mesh whose texture
coordinates are that layer's (`Painted.mesh`), and its texture is the layer with the image drawn
into each slot as the shape shows it (`Painted.regions`): the drawing is Webots', and the painter
(`runtime.pen_uv`) finds the layer's coordinate of any point of the surface from the mesh itself.

What each shape shows in its slots, in R2022a axes (the caller turns pre-R2022a Cylinders, Capsules,
Cones and Planes, whose axis was y, as it does for MuJoCo primitives), (s, t) with t upwards:

- Box: each face the whole image, upright on the four sides (t along +z), the top seen from above
  and the bottom seen from below (s along +x on both, t along +y on the top, -y on the bottom), each
  in Webots' slot of the layer (`BOX_SLOTS`).
- Plane: the image over the plane, s along +x, t along +y.
- Sphere: longitude and latitude: s goes once round the z axis from the back (-x) counter-clockwise
  seen from above, t from the south pole (0) to the north pole (1).
- Cylinder: the side once round, s from 0 at +y growing counter-clockwise seen from +z (Webots' seam
  and direction), t up the height; in the layer the side fills the top-left quarter, the top cap the
  top-right and the bottom cap the bottom-left one (Webots' layout; the side is one image wide, as
  Webots' is, so strokes keep its width round the side).
- Cone: the side as the sphere's (s round z from the back, t up the height).
- Cylinder and Cone caps: a disc cut out of the image centre (s along +x; t along +y on the top, -y
  on the bottom).
- Capsule: the side and both caps as one surface of revolution, t along the profile's length.
- ElevationGrid: the image over the whole grid, s along x, t along the second axis (y; z in
  pre-R2022a files).

Cylinders and Cones have `subdivision` flat sides, as Webots draws them. `open_revolution` draws a
Cylinder, Capsule or Cone without the parts its `side`, `top` or `bottom` turn off (the shape as
seen; the paint layer keeps every part). Not honoured yet: Sphere `subdivision` and `ico` (spheres
have `SEGMENTS` x `RINGS` faces), a painted shape's open parts. (A TextureTransform is drawn into
the layer by `paintable`.)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from wbtc.compile import heightfield
from wbtc.compile.mesh_data import MeshData
from wbtc.scene.model import Node

#: Sides of every round shape (Webots' default Cylinder subdivision is 36; 48 keeps them smooth).
SEGMENTS = 48
#: Rings from pole to pole of a sphere (and over each half of a capsule's caps).
RINGS = 24
#: Where each face of `box` (front +x, back -x, left +y, right -y, top +z, bottom -z) lies in a Box's
#: layer, as (s0, t0, s1, t1) with t upwards: Webots' slots (WbBox::computeTextureCoordinate for the
#: non-repeating coordinates, the second texture coordinates of wren's unit box). Counted from the layer's
#: first row (v = 1 - t), the side faces fill its lower half, left, back, right and front from u = 0, so that
#: they follow each other round the box; the bottom and the top share the upper half at u 0 to 0.25 and
#: 0.5 to 0.75 (the top's y = -h edge on the right face's top edge), the rest is unused. Webots' stroke is
#: not cut at a slot's edge: ink that spills out of a face's slot lands on whichever face holds the texels
#: beside it, so the layout decides where a stroke over an edge shows (the top face above the right one).
BOX_SLOTS = ((0.75, 0.0, 1.0, 0.5), (0.25, 0.0, 0.5, 0.5), (0.0, 0.0, 0.25, 0.5), (0.5, 0.0, 0.75, 0.5),
             (0.5, 0.5, 0.75, 1.0), (0.0, 0.5, 0.25, 1.0))
#: The geometry nodes this module makes meshes of.
MESHED_PRIMITIVES = frozenset({"Box", "Plane", "Sphere", "Cylinder", "Capsule", "Cone", "ElevationGrid"})


@dataclass
class Painted:
    """A paintable shape's mesh and the layout of its paint layer.

    Attributes:
        mesh: the triangles, texture coordinates (s, t, t upwards) in the whole layer.
        grid: the layer's size in images (columns, rows): (4, 2) for a Box.
        regions: where the image is drawn in the layer, as (s0, t0, s1, t1) rectangles.
        image_uv: instead of regions, the image's (s, t) at each vertex of the mesh (t upwards): each
            triangle is drawn into the layer with the image it shows (`faceset_uv.draw_layer`).
    """

    mesh: MeshData
    grid: tuple[int, int] = (1, 1)
    regions: list[tuple[float, float, float, float]] = field(default_factory=lambda: [(0.0, 0.0, 1.0, 1.0)])
    image_uv: np.ndarray | None = None


def primitive_mesh(node: Node, legacy: bool = False) -> Painted | None:
    """The mesh and paint layer of a primitive geometry node (None: not one, or empty).

    Args:
        node: a Box, Plane, Sphere, Cylinder, Capsule, Cone or ElevationGrid node.
        legacy: the node was written before R2022a (only an ElevationGrid builds differently: the
            other primitives are turned by the caller's frame).
    """
    kind = node.base_type
    if kind == "Box":
        return _slotted(box(np.abs(np.asarray(node.get("size"), dtype=float))), (4, 2), BOX_SLOTS)
    if kind == "Plane":
        return Painted(plane(np.asarray(node.get("size"), dtype=float)))
    if kind == "Sphere":
        return Painted(sphere(float(node.get("radius"))))
    sides = _sides(node)
    if kind == "Cylinder":
        # Webots' slots (WbCylinder, its unit mesh's second texture coordinates): the side in the top-left
        # quarter (one image around, as the texture shows it), the top cap top-right, the bottom cap
        # bottom-left; the bottom-right quarter stays unused. (s, t) here count t upwards.
        return _slotted(revolution(float(node.get("radius")), float(node.get("height")), "cylinder", sides), (2, 2),
                        [(0.0, 0.5, 0.5, 1.0), (0.5, 0.5, 1.0, 1.0), (0.0, 0.0, 0.5, 0.5)])
    if kind == "Capsule":
        return Painted(revolution(float(node.get("radius")), float(node.get("height")), "capsule")[0])
    if kind == "Cone":
        return _slotted(revolution(float(node.get("bottomRadius")), float(node.get("height")), "cone", sides), (2, 1),
                        [(0.0, 0.0, 0.5, 1.0), (0.5, 0.0, 1.0, 1.0)])
    if kind == "ElevationGrid":
        grid = heightfield.elevation_grid(node, legacy, [])
        made = None if grid is None else elevation_grid(grid)
        return None if made is None else Painted(made)
    return None


def _sides(node: Node) -> int:
    """How many flat sides Webots draws a Cylinder or Cone with: its `subdivision` (at least 3)."""
    try:
        return max(int(node.get("subdivision")), 3)
    except (TypeError, ValueError):
        return SEGMENTS


def _slotted(parts: list[MeshData], grid: tuple[int, int],
             regions: Sequence[tuple[float, float, float, float]] | None = None) -> Painted:
    """One mesh of `parts`, each part's texture coordinates squeezed into its region of the layer.

    Without `regions`, part i takes the i-th cell of the grid, row by row from the bottom.
    """
    if regions is None:
        columns, rows = grid
        regions = [((i % columns) / columns, (i // columns) / rows, (i % columns + 1) / columns,
                    (i // columns + 1) / rows) for i in range(len(parts))]
    placed = []
    for part, (s0, t0, s1, t1) in zip(parts, regions, strict=True):
        uv = part.texcoords.astype(float)
        # The part's own (s, t) in [0, 1] land in its rectangle of the layer.
        moved = np.column_stack([s0 + uv[:, 0] * (s1 - s0), t0 + uv[:, 1] * (t1 - t0)]).astype(np.float32)
        placed.append(MeshData(part.vertices, part.faces, moved))
    return Painted(_merge(placed), grid, list(regions))


def _quad_grid(points: np.ndarray, uv: np.ndarray) -> MeshData:
    """A mesh from a (rows, cols) grid of points and texture coordinates, two triangles per cell.

    The grid's rows and columns must run so that (col + 1, row + 1) turns counter-clockwise seen
    from outside (the face normal is d(col) × d(row)).
    """
    rows, cols = points.shape[:2]
    index = np.arange(rows * cols).reshape(rows, cols)
    a, b = index[:-1, :-1].ravel(), index[:-1, 1:].ravel()
    c, d = index[1:, 1:].ravel(), index[1:, :-1].ravel()
    faces = np.concatenate([np.column_stack([a, b, c]), np.column_stack([a, c, d])]).astype(np.int32)
    vertices = points.reshape(-1, 3).astype(float)
    # A pole or a cone's apex is a ring of one point: its cells' triangles there have no area.
    corners = vertices[faces]
    area = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    faces = faces[area > 1e-12 * max(float(np.abs(vertices).max()), 1e-9) ** 2]
    return MeshData(vertices, faces, uv.reshape(-1, 2).astype(np.float32))


def _merge(parts: list[MeshData]) -> MeshData:
    """One mesh of several (vertices are not shared: each part keeps its own texture coordinates)."""
    vertices, faces, uvs, offset = [], [], [], 0
    for part in parts:
        vertices.append(part.vertices)
        faces.append(part.faces + offset)
        uvs.append(part.texcoords)
        offset += len(part.vertices)
    return MeshData(np.vstack(vertices), np.vstack(faces).astype(np.int32), np.vstack(uvs).astype(np.float32))


def _face(origin: np.ndarray, s_axis: np.ndarray, t_axis: np.ndarray) -> MeshData:
    """One rectangle: `origin` at (s, t) = (0, 0), spanned by the full-length edges `s_axis` and `t_axis`."""
    s, t = np.meshgrid([0.0, 1.0], [0.0, 1.0])
    points = origin + s[..., None] * s_axis + t[..., None] * t_axis
    return _quad_grid(points, np.stack([s, t], axis=-1))


def box(size: np.ndarray) -> list[MeshData]:
    """A Box of full edge lengths `size`, centred, as its six faces, each showing the whole image."""
    hx, hy, hz = np.maximum(size, 1e-6) / 2
    x, y, z = np.eye(3)
    faces = [
        _face(np.array([hx, -hy, -hz]), 2 * hy * y, 2 * hz * z),  # +x (front): s along +y, t up
        _face(np.array([-hx, hy, -hz]), -2 * hy * y, 2 * hz * z),  # -x (back)
        _face(np.array([hx, hy, -hz]), -2 * hx * x, 2 * hz * z),  # +y (left)
        _face(np.array([-hx, -hy, -hz]), 2 * hx * x, 2 * hz * z),  # -y (right)
        _face(np.array([-hx, -hy, hz]), 2 * hx * x, 2 * hy * y),  # +z (top), seen from above
        _face(np.array([-hx, hy, -hz]), 2 * hx * x, -2 * hy * y),  # -z (bottom), seen from below
    ]
    return faces


def plane(size: np.ndarray) -> MeshData:
    """A Plane of full sizes `size` (x, y) in the xy plane, facing +z."""
    sx, sy = np.abs(size[:2])
    return _face(np.array([-sx / 2, -sy / 2, 0.0]), np.array([sx, 0.0, 0.0]), np.array([0.0, sy, 0.0]))


def _around(radii: np.ndarray, heights: np.ndarray, t: np.ndarray, sides: int = SEGMENTS,
            seam: float = math.pi) -> MeshData:
    """A surface of revolution about z: one ring per profile point (radius, height), s round the axis.

    s = 0 (and 1: the seam's vertices are doubled) lies at angle `seam` from +x (the back, -x, unless
    told) and grows counter-clockwise seen from +z. Profile points must run upwards (from the bottom
    pole or rim) for outward faces.
    """
    s = np.linspace(0.0, 1.0, sides + 1)
    angle = seam + 2 * math.pi * s  # from the seam, counter-clockwise about +z
    points = np.stack([radii[:, None] * np.cos(angle)[None, :], radii[:, None] * np.sin(angle)[None, :],
                       np.broadcast_to(heights[:, None], (len(heights), len(s)))], axis=-1)
    uv = np.stack(np.broadcast_arrays(s[None, :], t[:, None]), axis=-1)
    return _quad_grid(points, uv)


def _disc(radius: float, z: float, up: bool, sides: int = SEGMENTS, seam: float = math.pi) -> MeshData:
    """A cap of `radius` at height z, facing +z (`up`) or -z, showing the image's inscribed disc."""
    rim = np.linspace(0.0, 1.0, sides + 1)
    angle = seam + 2 * math.pi * rim  # the side's corners, from its seam
    sign = 1.0 if up else -1.0
    # Two rings (rim, centre) as a grid, in this order so that the faces look along +z (the bottom
    # cap's y is mirrored, which turns it to -z); its t axis runs along -y (seen from below).
    radii = np.array([radius, 0.0])
    x = radii[:, None] * np.cos(angle)[None, :]
    y = sign * radii[:, None] * np.sin(angle)[None, :]
    points = np.stack([x, y, np.full_like(x, z)], axis=-1)
    scale = max(radius, 1e-9) * 2
    uv = np.stack([0.5 + x / scale, 0.5 + sign * y / scale], axis=-1)
    return _quad_grid(points, uv)


def sphere(radius: float) -> MeshData:
    """A Sphere: longitude and latitude rings, t from the south pole up."""
    t = np.linspace(0.0, 1.0, RINGS + 1)
    polar = math.pi * (1.0 - t)  # angle from +z: pi at the south pole
    r = max(radius, 1e-6)
    return _around(r * np.sin(polar), r * np.cos(polar), t)


def revolution(radius: float, height: float, kind: str, sides: int = SEGMENTS) -> list[MeshData]:
    """A Cylinder (side, top, bottom), Capsule (one surface) or Cone (side, bottom) about z, centred on its height."""
    r, h = max(radius, 1e-6), max(height, 1e-6)
    if kind == "cylinder":
        # Webots' cylinder (Wren's unit cylinder) starts its side's texture at +y, where its first
        # corner is, and the image runs counter-clockwise seen from +z, as here: at angle pi / 2.
        seam = math.pi / 2
        side = _around(np.array([r, r]), np.array([-h / 2, h / 2]), np.array([0.0, 1.0]), sides, seam)
        return [side, _disc(r, h / 2, True, sides, seam), _disc(r, -h / 2, False, sides, seam)]
    if kind == "cone":
        side = _around(np.array([r, 0.0]), np.array([-h / 2, h / 2]), np.array([0.0, 1.0]), sides)
        return [side, _disc(r, -h / 2, False, sides)]
    # A capsule: the bottom hemisphere, the cylinder, the top hemisphere, t along the profile's length.
    quarter = np.linspace(0.0, math.pi / 2, RINGS // 2 + 1)
    bottom_r, bottom_z = r * np.sin(quarter), -h / 2 - r * np.cos(quarter)
    top_r, top_z = r * np.cos(quarter), h / 2 + r * np.sin(quarter)
    radii = np.concatenate([bottom_r, top_r])
    heights = np.concatenate([bottom_z, top_z])
    steps = np.hypot(np.diff(radii), np.diff(heights))
    t = np.concatenate([[0.0], np.cumsum(steps)]) / max(float(steps.sum()), 1e-12)
    return [_around(radii, heights, t, sides)]


def open_revolution(node: Node) -> MeshData | None:
    """A Cylinder, Capsule or Cone drawn without the parts its `side`, `top` or `bottom` leave out.

    None when every part is drawn (the MuJoCo primitive then shows it). A Capsule's parts are its
    tube and its two hemispheres (Webots' WbCapsule), each with t along its own profile.
    """
    kind = node.base_type
    names = ("side", "bottom") if kind == "Cone" else ("side", "top", "bottom")
    drawn = [node.get(name) is not False for name in names]
    if kind not in ("Cylinder", "Capsule", "Cone") or all(drawn):
        return None
    if kind == "Capsule":
        parts = _capsule_parts(float(node.get("radius")), float(node.get("height")), _sides(node))
    else:
        radius = float(node.get("bottomRadius" if kind == "Cone" else "radius"))
        parts = revolution(radius, float(node.get("height")), kind.lower(), _sides(node))
    kept = [part for part, keep in zip(parts, drawn, strict=True) if keep]
    return _merge(kept) if kept else None


def _capsule_parts(radius: float, height: float, sides: int) -> list[MeshData]:
    """A Capsule about z as its tube, top hemisphere and bottom hemisphere (profiles running upwards)."""
    r, h = max(radius, 1e-6), max(height, 1e-6)
    quarter = np.linspace(0.0, math.pi / 2, RINGS // 2 + 1)
    rising = np.linspace(0.0, 1.0, len(quarter))
    tube = _around(np.array([r, r]), np.array([-h / 2, h / 2]), np.array([0.0, 1.0]), sides)
    top = _around(r * np.cos(quarter), h / 2 + r * np.sin(quarter), rising, sides)
    bottom = _around(r * np.sin(quarter), -h / 2 - r * np.cos(quarter), rising, sides)
    return [tube, top, bottom]


def elevation_grid(grid: heightfield.HeightField) -> MeshData | None:
    """An ElevationGrid's surface (its top only: Webots' `thickness` is not drawn), the image over the grid."""
    if grid.nrow < 2 or grid.ncol < 2:
        return None
    heights = np.asarray(grid.heights, dtype=float)
    s = np.linspace(0.0, 1.0, grid.ncol)
    t = np.linspace(0.0, 1.0, grid.nrow)
    ss, tt = np.meshgrid(s, t)
    x, second = ss * grid.x_size, tt * grid.y_size
    if grid.legacy:
        # Heights along +y over an x-z grid; rows run along +z, so (col, row) turns clockwise seen
        # from +y: the rows are reversed to face up.
        points = np.stack([x, heights, second], axis=-1)[::-1]
        uv = np.stack([ss, tt], axis=-1)[::-1]
    else:
        points = np.stack([x, second, heights], axis=-1)
        uv = np.stack([ss, tt], axis=-1)
    return _quad_grid(points, uv)
