"""Webots `IndexedFaceSet` to a triangle mesh (`MeshData`).

What it maps: `coord`, `coordIndex` (faces separated by -1, a missing trailing -1 is fine), `ccw`,
`texCoord` and `texCoordIndex`. Polygons are triangulated: a fan for convex faces, a split at the
reflex corner for concave quads, ear clipping for other concave polygons (keyhole polygons, a hole
joined to the outline by a doubled edge, included). Faces with an out-of-range index and degenerate
faces (fewer than three distinct corners, zero area) are skipped with a warning, as Webots does.
Without `texCoord`, Webots' default texture mapping is generated (see `_default_texcoords`).

Not honoured yet: `normal`, `normalIndex`, `normalPerVertex` and `creaseAngle` (they only change
shading in Webots; MuJoCo computes its own normals). `convex` is ignored: every polygon is
triangulated as if it could be concave. Self-intersecting polygons are triangulated with a fan (with
a warning), where Webots' GLU tesselator would cut them at the crossings. Polygons are assumed
planar: a warped polygon is triangulated in the plane of its average normal.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from wbtc.compile.mesh_data import MeshData, finish, warn
from wbtc.errors import Diagnostic


def indexed_face_set(node: Any, warnings: list[Diagnostic] | None = None) -> MeshData | None:
    """Triangulate an IndexedFaceSet node.

    Args:
        node: the IndexedFaceSet scene node.
        warnings: a list to append warnings to (skipped faces, bad texture mapping, no geometry).

    Returns:
        The mesh, with one texture coordinate per vertex (vertices are split where a coordinate is
        used with several texture coordinates), or None when no valid triangle remains.
    """
    found: list[Diagnostic] = []
    result = _indexed_face_set(node, found)
    if result is not None:
        result.warnings = found
    finish(found, warnings)
    return result


def _points(node: Any, name: str, width: int) -> np.ndarray | None:
    if node is None:
        return None
    value = node.get(name)
    if value is None:
        return None
    array = np.asarray(value, dtype=np.float64)
    if array.size == 0:
        return None
    return array.reshape(-1, width)


def coordinates(node: Any) -> np.ndarray | None:
    """All the (n, 3) coordinates of an IndexedFaceSet, used by a face or not (None: it has none)."""
    return _points(node.get("coord"), "point", 3)


def has_texture_coordinates(node: Any) -> bool:
    """Whether an IndexedFaceSet's own texture coordinates are used (else Webots' default mapping is).

    As WbTriangleMesh decides: `texCoord` has points, and `texCoordIndex` is empty (then `coordIndex`
    indexes them) or as long as `coordIndex`.
    """
    if _points(node.get("texCoord"), "point", 2) is None:
        return False
    tex_index = node.get("texCoordIndex")
    coord_index = node.get("coordIndex")
    if tex_index is None or len(tex_index) == 0:
        return True
    return len(tex_index) == len(coord_index if coord_index is not None else [])


def _indexed_face_set(node: Any, warnings: list[Diagnostic]) -> MeshData | None:
    points = _points(node.get("coord"), "point", 3)
    coord_index = np.asarray(node.get("coordIndex") if node.get("coordIndex") is not None else [], dtype=np.int64)
    if points is None:
        warn(warnings, node, "IndexedFaceSet has no coordinates ('coord' is empty): no geometry")
        return None
    if coord_index.size == 0:
        warn(warnings, node, "IndexedFaceSet has no faces ('coordIndex' is empty): no geometry")
        return None

    # Texture coordinates, as WbTriangleMesh decides: an empty texCoordIndex means "use coordIndex";
    # a texCoordIndex of another length than coordIndex is ignored in favour of the default mapping.
    tex_points = _points(node.get("texCoord"), "point", 2)
    tex_index = np.asarray(node.get("texCoordIndex") if node.get("texCoordIndex") is not None else [],
                           dtype=np.int64)
    if tex_points is not None:
        if tex_index.size == 0:
            tex_index = coord_index
        elif tex_index.size != coord_index.size:
            warn(warnings, node, "the sizes of 'coordIndex' and 'texCoordIndex' differ: the default texture "
                                  "mapping is used, as in Webots")
            tex_points = None
    if tex_points is None:
        tex_index = coord_index

    corners, tex_corners = _triangulate_faces(points, coord_index, tex_index, node, warnings)
    if corners.shape[0] == 0:
        warn(warnings, node, "IndexedFaceSet has no valid triangle: no geometry")
        return None

    # ccw FALSE: the faces are listed clockwise seen from outside; swap two corners of every triangle
    # so that the result is counter-clockwise, which is what MuJoCo (and Webots' renderer) assume.
    if node.get("ccw") is False:
        corners = corners[:, [0, 2, 1]]
        tex_corners = tex_corners[:, [0, 2, 1]]

    if tex_points is not None:
        # One vertex per distinct (coordinate, texture coordinate) pair. An out-of-range texture
        # index reads as (0.5, 0.5), as in Webots; it gets an extra row at the end of the table.
        n_tex = tex_points.shape[0]
        bad = (tex_corners < 0) | (tex_corners >= n_tex)
        if bad.any():
            warn(warnings, node, f"{int(bad.sum())} texture coordinate index(es) out of range: (0.5, 0.5) used")
        tex_corners = np.where(bad, n_tex, tex_corners)
        table = np.vstack([tex_points, [[0.5, 0.5]]])
        keys = corners * (n_tex + 1) + tex_corners
        unique, inverse = np.unique(keys.ravel(), return_inverse=True)
        vertices = points[unique // (n_tex + 1)]
        texcoords = table[unique % (n_tex + 1)]
    else:
        # No texture coordinates: no vertex needs splitting; keep only the referenced coordinates
        # (MuJoCo builds its collision hull from every vertex, used or not).
        unique, inverse = np.unique(corners.ravel(), return_inverse=True)
        vertices = points[unique]
        texcoords = _default_texcoords(points)[unique]
    faces = inverse.reshape(-1, 3).astype(np.int32)
    return MeshData(vertices.astype(np.float64), faces, texcoords.astype(np.float32))


def _default_texcoords(points: np.ndarray) -> np.ndarray:
    """Webots' default IndexedFaceSet texture mapping (WbTriangleMesh::setDefaultTextureCoordinates).

    The bounding box of *all* the coordinates (used or not) is taken; s runs along its longest side
    from 0 to 1 and t along its second-longest side, scaled by the *longest* side (so t stops below 1
    on a non-square box). Ties go to the first axis (x before y before z). Webots stores 1 - t
    internally (image rows from the top); here t is in the VRML convention like explicit coordinates.
    """
    low = points.min(axis=0)
    size = points.max(axis=0) - low
    longest = second = -1
    for axis in range(3):
        if longest < 0 or size[axis] > size[longest]:
            second, longest = longest, axis
        elif second < 0 or size[axis] > size[second]:
            second = axis
    scale = size[longest] if size[longest] > 0 else 1.0
    s = (points[:, longest] - low[longest]) / scale
    t = (points[:, second] - low[second]) / scale
    return np.column_stack([s, t])


def _triangulate_faces(points: np.ndarray, coord_index: np.ndarray, tex_index: np.ndarray, node: Any,
                       warnings: list[Diagnostic]) -> tuple[np.ndarray, np.ndarray]:
    """Split coordIndex at -1 and triangulate each face; returns (m, 3) coordinate and texture indices."""
    n_points = points.shape[0]
    separators = np.flatnonzero(coord_index == -1)
    starts = np.concatenate(([0], separators + 1))
    ends = np.concatenate((separators, [coord_index.size]))
    keep = ends > starts  # "-1 -1" and a trailing -1 make empty faces: nothing to report
    starts, ends = starts[keep], ends[keep]

    out_of_range: list[list[int]] = []
    degenerate = 0
    not_simple = 0
    tri_coord: list[np.ndarray] = []
    tri_tex: list[np.ndarray] = []
    tri_face: list[np.ndarray] = []

    lengths = ends - starts
    # Fast path: faces that are already triangles (the common case for generated meshes).
    tri_faces = np.flatnonzero(lengths == 3)
    if tri_faces.size:
        offsets = starts[tri_faces, None] + np.arange(3)
        coords = coord_index[offsets]
        texs = tex_index[offsets]
        valid = ((coords >= 0) & (coords < n_points)).all(axis=1)
        for face in coords[~valid][:5]:
            out_of_range.append(face.tolist())
        out_of_range_count = int((~valid).sum())
        distinct = valid & (coords[:, 0] != coords[:, 1]) & (coords[:, 1] != coords[:, 2]) & (
            coords[:, 0] != coords[:, 2])
        degenerate += int((valid & ~distinct).sum())
        tri_coord.append(coords[distinct])
        tri_tex.append(texs[distinct])
        tri_face.append(tri_faces[distinct])
    else:
        out_of_range_count = 0

    # Second fast path: quads with four distinct, valid corners (the other common case).
    quad_faces = np.flatnonzero(lengths == 4)
    slow = lengths != 3
    if quad_faces.size:
        offsets = starts[quad_faces, None] + np.arange(4)
        coords = coord_index[offsets]
        plain = ((coords >= 0) & (coords < n_points)).all(axis=1)
        plain &= np.array([len(set(face)) == 4 for face in coords.tolist()], dtype=bool)
        if plain.any():
            local, simple = _triangulate_quads(points[coords[plain]])
            rows = np.arange(int(plain.sum()))[:, None, None]
            tri_coord.append(coords[plain][rows, local].reshape(-1, 3))
            tri_tex.append(tex_index[offsets[plain]][rows, local].reshape(-1, 3))
            tri_face.append(np.repeat(quad_faces[plain], 2))
            not_simple += int((~simple).sum())
            slow[quad_faces[plain]] = False

    for face_id in np.flatnonzero(slow):
        coords = coord_index[starts[face_id]:ends[face_id]]
        texs = tex_index[starts[face_id]:ends[face_id]]
        if ((coords < 0) | (coords >= n_points)).any():
            out_of_range_count += 1
            if len(out_of_range) < 5:
                out_of_range.append(coords.tolist())
            continue
        # Drop repeated corners (consecutive, and the last one repeating the first, as in
        # "0 1 2 0 -1"): they add no area.
        keep_corner = coords != np.roll(coords, -1)
        if not keep_corner.any():
            keep_corner[0] = True
        coords, texs = coords[keep_corner], texs[keep_corner]
        if coords.size < 3:
            degenerate += 1
            continue
        if coords.size == 3:
            triangles: list[tuple[int, int, int]] | None = [(0, 1, 2)]
        else:
            triangles, simple = _triangulate_polygon(points[coords])
            if triangles is None:
                degenerate += 1
                continue
            not_simple += 0 if simple else 1
        local = np.asarray(triangles, dtype=np.int64)
        tri_coord.append(coords[local])
        tri_tex.append(texs[local])
        tri_face.append(np.full(local.shape[0], face_id))

    if out_of_range_count:
        shown = ", ".join(str(face) for face in out_of_range)
        warn(warnings, node, f"{out_of_range_count} face(s) with an out-of-range coordinate index skipped "
                              f"({n_points} coordinates): {shown}")
    if not_simple:
        warn(warnings, node, f"{not_simple} self-intersecting polygon(s) triangulated as a fan: "
                              "they may cover the wrong area")

    if not tri_coord:
        corners = np.zeros((0, 3), dtype=np.int64)
        tex_corners = np.zeros((0, 3), dtype=np.int64)
    else:
        # Keep the file's face order (triangles and polygons were processed in two passes).
        order = np.argsort(np.concatenate(tri_face), kind="stable")
        corners = np.concatenate(tri_coord)[order]
        tex_corners = np.concatenate(tri_tex)[order]

    # Zero-area triangles (collinear corners, or distinct indices at the same place) are skipped:
    # they have no normal, and Webots refuses them too ("Null normal for face ...").
    if corners.shape[0]:
        a, b, c = (points[corners[:, k]] for k in range(3))
        area2 = np.linalg.norm(np.cross(b - a, c - a), axis=1)
        extent = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
        flat = area2 <= 1e-12 * max(extent, 1e-300) ** 2
        degenerate += int(flat.sum())
        corners, tex_corners = corners[~flat], tex_corners[~flat]
    if degenerate:
        warn(warnings, node, f"{degenerate} degenerate face(s) or triangle(s) skipped (fewer than 3 distinct "
                              "corners, or no area)")
    return corners, tex_corners


def _triangulate_quads(quads: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Split (q, 4, 3) quads into two triangles each: (q, 2, 3) corner positions and a "simple" mask.

    A convex quad is split from corner 0; a concave one (a simple quad has at most one reflex corner)
    from its reflex corner, so that both triangles stay inside. A quad with two reflex corners is a
    "bow tie" (self-intersecting): split from corner 0 and reported as not simple.
    """
    following = np.roll(quads, -1, axis=1)
    normal = np.cross(quads, following).sum(axis=1)  # Newell's normal, along the quad's winding
    edges = following - quads
    incoming = np.roll(edges, 1, axis=1)
    turns = np.einsum("qkj,qj->qk", np.cross(incoming, edges), normal)
    scale = np.abs(edges).max(axis=(1, 2)) ** 2 * np.linalg.norm(normal, axis=1)
    reflex = turns < -1e-12 * scale[:, None]
    count = reflex.sum(axis=1)
    start = np.where(count == 1, reflex.argmax(axis=1), 0)
    pattern = np.array([[0, 1, 2], [0, 2, 3]])
    local = (start[:, None, None] + pattern[None]) % 4
    flat = np.linalg.norm(normal, axis=1) <= 1e-12 * np.abs(edges).max(axis=(1, 2)) ** 2
    return local, (count <= 1) & ~flat


def _triangulate_polygon(polygon: np.ndarray) -> tuple[list[tuple[int, int, int]] | None, bool]:
    """Triangulate one planar-ish polygon of k >= 4 corners.

    Returns the triangles as corner positions (keeping the polygon's winding) and whether the
    polygon was simple; (None, True) when the polygon has no area.
    """
    # Newell's normal follows the polygon's winding, so projecting on a basis (u, v) with u x v = n
    # makes the 2-D polygon counter-clockwise.
    following = np.roll(polygon, -1, axis=0)
    normal = np.cross(polygon, following).sum(axis=0)
    length = float(np.linalg.norm(normal))
    if length <= 1e-300:
        return None, True
    normal /= length
    helper = np.array([1.0, 0.0, 0.0]) if abs(normal[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(helper, normal)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    flat = np.column_stack([polygon @ u, polygon @ v])
    k = flat.shape[0]

    edges = np.roll(flat, -1, axis=0) - flat
    turns = edges[:, 0] * np.roll(edges, -1, axis=0)[:, 1] - edges[:, 1] * np.roll(edges, -1, axis=0)[:, 0]
    scale = float(np.abs(edges).max()) ** 2
    if (turns >= -1e-12 * scale).all():
        # Convex (collinear corners allowed): a fan from the first corner.
        return [(0, i, i + 1) for i in range(1, k - 1)], True

    triangles = _ear_clip(flat, 1e-12 * scale)
    if triangles is not None:
        return triangles, True
    return [(0, i, i + 1) for i in range(1, k - 1)], False


def _ear_clip(flat: np.ndarray, eps: float) -> list[tuple[int, int, int]] | None:
    """Ear clipping of a counter-clockwise simple polygon; None when it is not simple."""

    def cross(o: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
        return float((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]))

    remaining = list(range(flat.shape[0]))
    triangles: list[tuple[int, int, int]] = []
    while len(remaining) > 3:
        count = len(remaining)
        for i in range(count):
            a, b, c = remaining[i - 1], remaining[i], remaining[(i + 1) % count]
            pa, pb, pc = flat[a], flat[b], flat[c]
            if cross(pa, pb, pc) <= eps:
                continue  # reflex or flat corner: not an ear
            inside = False
            for j in remaining:
                p = flat[j]
                if j in (a, b, c) or (p == pa).all() or (p == pb).all() or (p == pc).all():
                    continue  # a corner, or a repeat of one (keyhole polygons: a hole joined by a bridge)
                if cross(pa, pb, p) >= -eps and cross(pb, pc, p) >= -eps and cross(pc, pa, p) >= -eps:
                    inside = True
                    break
            if not inside:
                triangles.append((a, b, c))
                del remaining[i]
                break
        else:
            # No ear: drop a flat corner (it lies on a straight edge and adds no area) or give up.
            flat_corner = next((i for i in range(count)
                                if abs(cross(flat[remaining[i - 1]], flat[remaining[i]],
                                             flat[remaining[(i + 1) % count]])) <= eps), None)
            if flat_corner is None:
                return None
            del remaining[flat_corner]
    triangles.append((remaining[0], remaining[1], remaining[2]))
    return triangles
