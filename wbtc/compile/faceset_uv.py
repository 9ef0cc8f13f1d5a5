"""An IndexedFaceSet without its own texture coordinates, as a Pen paints it: Webots' non-repeating mapping.

Webots shows the texture of an IndexedFaceSet whose texture coordinates are not valid (no `texCoord`,
or a `texCoordIndex` of another length than `coordIndex`) through its default mapping
(`faceset._default_texcoords`), but paints a pen's ink through a second mapping that never repeats, on
a layer 4 x 2 times the image's size (`PAINT_GRID`; with valid coordinates the layer is the image's
size and the coordinates are the texture's own). That second mapping, per triangle:

- the ray from the triangle's centroid along its normal ((v1 - v0) x (v2 - v0), the corners counter-
  clockwise seen from outside) meets the bounding box of all the coordinates (used or not) where it
  leaves it (slab method: the entry distance, or the exit distance when the entry is behind the
  centroid, as it always is: the centroid lies in the box);
- the box face it meets is named, with a 1e-9 tolerance, in this order: +x, -x, -z, +z, +y, -y;
- every corner of the triangle is projected on that face and its (u, v) on the face, each in [0, 1],
  put in the face's cell of the layer (`_CELLS`).

Convention: Webots' (u, v) count v from the layer's first row (the image's top), as MuJoCo's texture
coordinates do; `MeshData` counts t upwards, so the mesh carries (u, 1 - v). The faces are named in
Webots' R2022a axes (z up), for every file.

MuJoCo draws one texture per shape: the mesh's coordinates address the paint layer, and the layer is
drawn with the image each triangle shows through the default mapping (and the TextureTransform),
texel by texel (`draw_layer`). Not honoured yet: where triangles share texels of the layer (a concave
mesh, or faces behind one another seen from a box face) the last one's image is drawn there; Webots
shows each surface's own image under the shared ink. Triangles are those of `faceset`, not GLU's: a
polygon split along another diagonal can have a centroid that leaves the box through another face.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from wbtc.compile import faceset, textures
from wbtc.compile.mesh_data import MeshData
from wbtc.compile.primitive_uv import Painted
from wbtc.errors import Diagnostic

#: The non-repeating layer's size in images (columns, rows): Webots' size factor for the default mapping.
PAINT_GRID = (4, 2)
#: Candidate texels drawn at once (memory bound of `draw_layer`).
_CHUNK_TEXELS = 1 << 21
#: Webots' tolerance when it names the box face a point lies on.
_ON_FACE = 1e-9
#: Per box face (+x, -x, +y, -y, +z, -z): the axis giving u and whether it runs reversed, the axis
#: giving v and whether it runs reversed, and the cell's corner (u0, v0); a cell is 1/4 wide, 1/2 high.
#: (u, v) are the corner's offsets in the box, from its minimum and as fractions of its size, before
#: the reversal (1 - value); v counts from the layer's top row.
_CELLS = {
    "+x": (1, False, 2, True, 0.75, 0.5),
    "-x": (1, True, 2, True, 0.25, 0.5),
    "+y": (0, True, 2, True, 0.0, 0.5),
    "-y": (0, False, 2, True, 0.5, 0.5),
    "+z": (0, False, 1, True, 0.5, 0.0),
    "-z": (0, False, 1, False, 0.0, 0.0),
}
#: The order in which Webots names the face a point lies on: (axis, bound (1: maximum), face).
_FACE_ORDER = ((0, 1, "+x"), (0, 0, "-x"), (2, 0, "-z"), (2, 1, "+z"), (1, 1, "+y"), (1, 0, "-y"))


def painted_faceset(node: Any, warnings: list[Diagnostic] | None = None) -> Painted | None:
    """The paint mesh of an IndexedFaceSet that Webots paints through its non-repeating mapping.

    Args:
        node: the IndexedFaceSet.
        warnings: where the triangulation's warnings go (only when a mesh is returned: otherwise the
            geometry is read again, and warns, as any IndexedFaceSet).

    Returns:
        None when the node has valid texture coordinates (Webots paints through them, on a layer of
        the image's size) or no triangle; else the mesh, its vertices split where triangles meeting
        there lie in different cells, with the layer's coordinates, and `image_uv` the image's.
    """
    if faceset.has_texture_coordinates(node):
        return None
    found: list[Diagnostic] = []
    data = faceset.indexed_face_set(node, found)
    points = faceset.coordinates(node)
    if data is None or data.texcoords is None or points is None:
        return None
    if warnings is not None:
        warnings.extend(found)
    corners = np.asarray(data.vertices, dtype=float)[data.faces]
    layer_uv = layer_coordinates(corners, points.min(axis=0), points.max(axis=0))
    # One vertex per (vertex, layer coordinate): triangles of different cells do not share corners.
    keys = np.column_stack([data.faces.reshape(-1), np.round(layer_uv.reshape(-1, 2), 9)])
    unique, first, inverse = np.unique(keys, axis=0, return_index=True, return_inverse=True)
    source = unique[:, 0].astype(int)
    uv = layer_uv.reshape(-1, 2)[first]
    # MeshData counts t upwards; Webots' v counts down from the layer's top row.
    mesh = MeshData(data.vertices[source], inverse.reshape(-1, 3).astype(np.int32),
                    np.column_stack([uv[:, 0], 1.0 - uv[:, 1]]).astype(np.float32))
    return Painted(mesh, PAINT_GRID, [], image_uv=np.asarray(data.texcoords, dtype=float)[source])


def layer_coordinates(corners: np.ndarray, low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """Webots' non-repeating (u, v) of every triangle corner (v from the layer's top row).

    Args:
        corners: (m, 3, 3) triangle corners, counter-clockwise seen from outside.
        low: the minimum of all the coordinates, per axis.
        high: their maximum.

    Returns:
        (m, 3, 2) layer coordinates.
    """
    faces = box_faces(corners, low, high)
    size = high - low
    # A flat box (a planar mesh) has no extent across: its fraction there is 0 (Webots divides by 0).
    fraction = (corners - low) / np.where(size > 0, size, np.inf)
    out = np.zeros(corners.shape[:2] + (2,))
    for face, (u_axis, u_flip, v_axis, v_flip, u0, v0) in _CELLS.items():
        rows = faces == face
        u, v = fraction[rows][..., u_axis], fraction[rows][..., v_axis]
        u, v = (1.0 - u if u_flip else u), (1.0 - v if v_flip else v)
        out[rows] = np.stack([u0 + u / PAINT_GRID[0], v0 + v / PAINT_GRID[1]], axis=-1)
    return out


def box_faces(corners: np.ndarray, low: np.ndarray, high: np.ndarray) -> np.ndarray:
    """The bounding-box face ("+x" ... "-z") each triangle's normal from its centroid meets.

    Args:
        corners: (m, 3, 3) triangle corners, counter-clockwise seen from outside.
        low: the box's minimum corner.
        high: its maximum corner.

    Returns:
        (m,) face names ("" for none: a point the tolerance places on no face).
    """
    centre = corners.mean(axis=1)
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    normal /= np.maximum(np.linalg.norm(normal, axis=1, keepdims=True), 1e-300)
    with np.errstate(divide="ignore", invalid="ignore"):
        # Slab method: per axis, the distances to the planes the ray crosses first and last; an
        # axis the ray runs along does not bound it.
        near = np.where(normal > 0, low, high)
        far = np.where(normal > 0, high, low)
        moving = normal != 0
        enter = np.where(moving, (near - centre) / np.where(moving, normal, 1.0), -np.inf).max(axis=1)
        leave = np.where(moving, (far - centre) / np.where(moving, normal, 1.0), np.inf).min(axis=1)
    distance = np.where(enter < 0, leave, enter)
    point = centre + distance[:, None] * normal
    named = np.full(len(corners), "", dtype=object)
    bounds = (low, high)
    for axis, bound, face in reversed(_FACE_ORDER):  # the first in Webots' order is written last
        on = np.abs(point[:, axis] - bounds[bound][axis]) < _ON_FACE
        named[on] = face
    return named


def draw_layer(pixels: np.ndarray, painted: Painted, size: tuple[int, int], transform: Any) -> np.ndarray:
    """The paint layer of a non-repeating mesh, with the image each triangle shows drawn into its texels.

    Args:
        pixels: the image, (rows, columns, channels), row 0 at the top.
        painted: the mesh (texture coordinates in the layer, t upwards) and `image_uv`, the image's
            coordinates at its vertices (the default mapping, t upwards).
        size: the layer's (width, height) in texels.
        transform: the appearance's TextureTransform (moves the image's coordinates), or None.

    Returns:
        The layer, white where no triangle lies (and a 2-texel rim around each triangle, so that
        filtering at a triangle's edge does not show white).
    """
    width, height = size
    rows_in, cols_in = pixels.shape[:2]
    layer = np.full((height, width, pixels.shape[2]), 255, dtype=np.uint8)
    drawn = np.zeros((height, width), dtype=bool)
    uv = np.asarray(painted.mesh.texcoords, dtype=float)
    # Corners in texel units of the layer, x along the row and y down from the first row.
    spots = np.column_stack([uv[:, 0] * width, (1.0 - uv[:, 1]) * height])[painted.mesh.faces]
    images = np.asarray(painted.image_uv, dtype=float)[painted.mesh.faces]
    # Each triangle's texels: the centres inside it, among those of its bounding rectangle.
    low = np.floor(spots.min(axis=1)).astype(int).clip(0, [width - 1, height - 1])
    high = np.ceil(spots.max(axis=1)).astype(int).clip(1, [width, height])
    span = np.maximum(high - low, 0)
    counts = span[:, 0] * span[:, 1]
    for chunk in _chunks(counts, _CHUNK_TEXELS):
        tri = np.repeat(chunk, counts[chunk])
        k = np.arange(len(tri)) - np.repeat(np.cumsum(counts[chunk]) - counts[chunk], counts[chunk])
        tx = low[tri, 0] + k % span[tri, 0]
        ty = low[tri, 1] + k // span[tri, 0]
        weights = _barycentric(spots[tri], tx + 0.5, ty + 0.5)
        inside = (weights >= -1e-9).all(axis=1)
        tri, tx, ty, weights = tri[inside], tx[inside], ty[inside], weights[inside]
        # The image's coordinates at the texel centres, through the TextureTransform; the image repeats
        # and its row 0 is t = 1. Where triangles share a texel, the last one's image stays.
        moved = textures.apply_texture_transform(np.einsum("nk,nkj->nj", weights, images[tri]), transform)
        cols = np.floor(np.mod(moved[:, 0], 1.0) * cols_in).astype(int).clip(0, cols_in - 1)
        picked = np.floor(np.mod(1.0 - moved[:, 1], 1.0) * rows_in).astype(int).clip(0, rows_in - 1)
        layer[ty, tx] = pixels[picked, cols]
        drawn[ty, tx] = True
    return _grow(layer, drawn, 2)


def _chunks(counts: np.ndarray, limit: int) -> list[np.ndarray]:
    """Consecutive triangle indices in groups of about `limit` candidate texels (one group per triangle beyond)."""
    groups, start, total = [], 0, 0
    for index, count in enumerate(counts.tolist()):
        if total and total + count > limit:
            groups.append(np.arange(start, index))
            start, total = index, 0
        total += count
    if start < len(counts):
        groups.append(np.arange(start, len(counts)))
    return groups


def _barycentric(triangles: np.ndarray, xs: np.ndarray, ys: np.ndarray) -> np.ndarray:
    """The barycentric weights (n, 3) of points in 2-D triangles (n, 3, 2); NaN for a triangle without area."""
    a, b, c = triangles[:, 0], triangles[:, 1], triangles[:, 2]
    det = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1])
    det = np.where(np.abs(det) < 1e-12, np.nan, det)
    w1 = ((xs - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (ys - a[:, 1])) / det
    w2 = ((b[:, 0] - a[:, 0]) * (ys - a[:, 1]) - (xs - a[:, 0]) * (b[:, 1] - a[:, 1])) / det
    return np.column_stack([1.0 - w1 - w2, w1, w2])


def _grow(layer: np.ndarray, drawn: np.ndarray, steps: int) -> np.ndarray:
    """Copy drawn texels into their undrawn neighbours (4-connected), `steps` times."""
    for _ in range(steps):
        for dy, dx in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            source = np.roll(drawn, (dy, dx), axis=(0, 1))
            # np.roll wraps round: the first row or column moved in is not a neighbour.
            if dy:
                source[0 if dy > 0 else -1, :] = False
            else:
                source[:, 0 if dx > 0 else -1] = False
            take = source & ~drawn
            if take.any():
                layer[take] = np.roll(layer, (dy, dx), axis=(0, 1))[take]
                drawn = drawn | take
    return layer
