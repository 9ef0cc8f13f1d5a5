"""Webots mesh-like geometry to triangle meshes and MuJoCo height fields.

What it maps:

* `IndexedFaceSet` -> `MeshData`: `coord`, `coordIndex` (faces separated by -1, a missing trailing -1
  is fine), `ccw`, `texCoord` and `texCoordIndex`. Polygons are triangulated: a fan for convex faces,
  a split at the reflex corner for concave quads, ear clipping for other concave polygons (keyhole
  polygons, a hole joined to the outline by a doubled edge, included). Faces with an out-of-range
  index and degenerate faces (fewer than three distinct corners, zero area) are skipped with a
  warning, as Webots does. Without `texCoord`, Webots' default texture mapping is generated (see
  `_default_texcoords`).
* `Mesh` -> `MeshData`: `url` (the first entry that exists), `ccw`, `name` (sub-mesh filter),
  texture coordinates when the file has them. Files are read with trimesh: OBJ, STL, PLY, OFF, GLTF;
  COLLADA (.dae) only when the optional `pycollada` package is installed.
* `ElevationGrid` -> `HeightField`: `height`, `xDimension`, `xSpacing`, `yDimension`, `ySpacing`
  (`zDimension`, `zSpacing` in files older than R2022a), `thickness`; with the conversions to
  MuJoCo's centred, normalised `hfield` (see `HeightField`).
* `mesh_volume_and_inertia`: volume, centre of mass and unit-density inertia of a `MeshData`.

Not honoured yet:

* IndexedFaceSet `normal`, `normalIndex`, `normalPerVertex` and `creaseAngle`: they only change
  shading in Webots (visual only; MuJoCo computes its own normals). `convex` is ignored: every
  polygon is triangulated as if it could be concave. Self-intersecting polygons are triangulated
  with a fan (with a warning), where Webots' GLU tesselator would cut them at the crossings.
* Mesh `materialIndex` (a warning is given when it is set), FBX files (trimesh cannot read them),
  `webots://` and `http(s)://` URLs (no Webots installation and no network: a warning, no mesh), and
  Assimp's COLLADA/FBX up-axis and unit-scale metadata handling.
* ElevationGrid texture mapping (the caller maps the texture over the whole grid).
* Polygons are assumed planar: a warped polygon is triangulated in the plane of its average normal.

Every function that can warn takes an optional `warnings` list and appends `Diagnostic`s (severity
"warning", at the node's span) to it; the same warnings are kept on the result when there is one.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from wbtc.errors import Diagnostic

#: Smallest MuJoCo hfield elevation range and base depth (MuJoCo needs both strictly positive).
MIN_HFIELD_SIZE = 1e-4


@dataclass
class MeshData:
    """A triangle mesh.

    Attributes:
        vertices: (n, 3) float64 positions in the node's frame, metres.
        faces: (m, 3) int32 vertex indices, counter-clockwise seen from outside (MuJoCo's convention).
        texcoords: (n, 2) float32, one per vertex, in the VRML/OBJ convention: (s, t) with t = 0 at
            the bottom row of the image. MuJoCo counts v from the top row: use `mujoco_texcoords()`.
            None when the mesh has no texture coordinates.
        warnings: what was skipped or odd while reading the geometry.
    """

    vertices: np.ndarray
    faces: np.ndarray
    texcoords: np.ndarray | None = None
    warnings: list[Diagnostic] = field(default_factory=list)

    def mujoco_texcoords(self) -> np.ndarray | None:
        """The texture coordinates as MuJoCo's `usertexcoord` wants them: (s, 1 - t), float32, or None."""
        if self.texcoords is None:
            return None
        # VRML/OBJ count t upwards from the bottom image row; MuJoCo counts v downwards from the top
        # row (it stores 1 - vt when it reads an OBJ file itself).
        return np.column_stack([self.texcoords[:, 0], 1.0 - self.texcoords[:, 1]]).astype(np.float32)


def _warn(warnings: list[Diagnostic], node: Any, message: str) -> None:
    warnings.append(Diagnostic(message, getattr(node, "span", None), severity="warning"))


def _finish(warnings: list[Diagnostic], sink: list[Diagnostic] | None) -> None:
    if sink is not None:
        sink.extend(warnings)


# ---------------------------------------------------------------------------------- IndexedFaceSet


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
    _finish(found, warnings)
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


def _indexed_face_set(node: Any, warnings: list[Diagnostic]) -> MeshData | None:
    points = _points(node.get("coord"), "point", 3)
    coord_index = np.asarray(node.get("coordIndex") if node.get("coordIndex") is not None else [], dtype=np.int64)
    if points is None:
        _warn(warnings, node, "IndexedFaceSet has no coordinates ('coord' is empty): no geometry")
        return None
    if coord_index.size == 0:
        _warn(warnings, node, "IndexedFaceSet has no faces ('coordIndex' is empty): no geometry")
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
            _warn(warnings, node, "the sizes of 'coordIndex' and 'texCoordIndex' differ: the default texture "
                                  "mapping is used, as in Webots")
            tex_points = None
    if tex_points is None:
        tex_index = coord_index

    corners, tex_corners = _triangulate_faces(points, coord_index, tex_index, node, warnings)
    if corners.shape[0] == 0:
        _warn(warnings, node, "IndexedFaceSet has no valid triangle: no geometry")
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
            _warn(warnings, node, f"{int(bad.sum())} texture coordinate index(es) out of range: (0.5, 0.5) used")
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
        _warn(warnings, node, f"{out_of_range_count} face(s) with an out-of-range coordinate index skipped "
                              f"({n_points} coordinates): {shown}")
    if not_simple:
        _warn(warnings, node, f"{not_simple} self-intersecting polygon(s) triangulated as a fan: "
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
        _warn(warnings, node, f"{degenerate} degenerate face(s) or triangle(s) skipped (fewer than 3 distinct "
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


# ---------------------------------------------------------------------------------- Mesh files

#: Loaded mesh files: (absolute path, mtime_ns, name filter) -> (mesh before `ccw`, file warnings).
_MESH_CACHE: dict[tuple[str, int, str], tuple[MeshData | None, list[str]]] = {}


def mesh_file(node: Any, warnings: list[Diagnostic] | None = None) -> MeshData | None:
    """Load the file of a Mesh node.

    The first `url` entry that exists is used (relative URLs resolve against the folder of the file
    the node was written in: the world, or the PROTO for nodes a PROTO made). Files are cached by
    (path, modification time, name filter).

    Args:
        node: the Mesh scene node.
        warnings: a list to append warnings to (unresolvable URL, unreadable file, unknown name).

    Returns:
        The mesh (sub-meshes merged with their scene-graph transforms applied), or None.
    """
    from wbtc.compile.textures import resolve_url

    found: list[Diagnostic] = []
    urls = list(node.get("url") or [])
    name = node.get("name") or ""
    result: MeshData | None = None
    base_file = node.span.file if getattr(node, "span", None) is not None else ""
    path = resolve_url(urls, base_file)
    if not urls:
        _warn(found, node, "Mesh has no url: no geometry")
    elif path is None:
        remote = [u for u in urls if u.startswith(("webots://", "http://", "https://"))]
        if remote:
            _warn(found, node, f"Mesh url {remote[0]!r} cannot be read offline (no Webots installation, no "
                               "network): no geometry")
        else:
            _warn(found, node, f"Mesh file not found: {urls[0]!r} (relative to {os.path.dirname(base_file) or '.'})")
    else:
        materialindex = node.get("materialIndex")
        if materialindex is not None and materialindex >= 0:
            _warn(found, node, "Mesh 'materialIndex' is not honoured yet: every sub-mesh is used")
        mesh, messages = _load_mesh_cached(path, name)
        for message in messages:
            _warn(found, node, message)
        if mesh is not None:
            faces = mesh.faces
            if node.get("ccw") is False:
                # ccw FALSE: clockwise faces in the file; swap two corners to make them counter-clockwise.
                faces = faces[:, [0, 2, 1]]
            texcoords = None if mesh.texcoords is None else mesh.texcoords.copy()
            result = MeshData(mesh.vertices.copy(), np.ascontiguousarray(faces, dtype=np.int32), texcoords, found)
    _finish(found, warnings)
    return result


def _load_mesh_cached(path: str, name: str) -> tuple[MeshData | None, list[str]]:
    absolute = os.path.abspath(path)
    key = (absolute, os.stat(absolute).st_mtime_ns, name)
    if key not in _MESH_CACHE:
        messages: list[str] = []
        try:
            mesh = _load_mesh(absolute, name, messages)
        except ImportError as exc:  # trimesh reads COLLADA with the optional pycollada package
            mesh = None
            messages.append(f"cannot read mesh file {path}: a Python package is missing ({exc})")
        except Exception as exc:  # trimesh raises many kinds of errors on bad or unsupported files
            mesh = None
            messages.append(f"cannot read mesh file {path}: {type(exc).__name__}: {exc}")
        _MESH_CACHE[key] = (mesh, messages)
    return _MESH_CACHE[key]


def _load_mesh(path: str, name: str, messages: list[str]) -> MeshData | None:
    import trimesh

    suffix = Path(path).suffix.lower()
    if suffix == ".fbx":
        messages.append(f"FBX mesh files are not supported (trimesh cannot read them): {path}")
        return None
    kwargs: dict[str, Any] = {}
    if suffix == ".obj":
        # One geometry per OBJ object ("o"), named after it, so that `name` can select one; faces of
        # one object that use several materials stay together.
        kwargs = {"split_objects": True, "group_material": False}
    # process=False keeps the file's vertices and faces as written (no merging, no reordering).
    scene = trimesh.load(path, force="scene", process=False, **kwargs)

    parts: list[tuple[np.ndarray, np.ndarray, np.ndarray | None]] = []
    names_seen: list[str] = []
    for node_name in scene.graph.nodes_geometry:
        transform, geometry_name = scene.graph[node_name]
        geometry = scene.geometry.get(geometry_name)
        if not isinstance(geometry, trimesh.Trimesh) or len(geometry.faces) == 0:
            continue
        names_seen.append(str(geometry_name))
        if name and name not in (str(geometry_name), str(node_name), geometry.metadata.get("name")):
            continue
        vertices = np.asarray(geometry.vertices, dtype=np.float64)
        # Sub-meshes sit in the file's scene graph: apply each one's world transform, as Webots does.
        vertices = vertices @ np.asarray(transform[:3, :3]).T + np.asarray(transform[:3, 3])
        uv = getattr(geometry.visual, "uv", None)
        uv = None if uv is None or len(uv) != len(vertices) else np.asarray(uv, dtype=np.float64)[:, :2]
        faces = np.asarray(geometry.faces, dtype=np.int64)
        if np.linalg.det(np.asarray(transform[:3, :3])) < 0:
            faces = faces[:, [0, 2, 1]]  # a mirroring transform turns the winding inside out
        parts.append((vertices, faces, uv))

    if not parts:
        if name and names_seen:
            messages.append(f"no sub-mesh named {name!r} in {path} (it has: {', '.join(sorted(names_seen))})")
        else:
            messages.append(f"no triangle in mesh file {path}")
        return None

    vertices_list, faces_list, uv_list = [], [], []
    offset = 0
    any_uv = any(uv is not None for _, _, uv in parts)
    for vertices, faces, uv in parts:
        vertices_list.append(vertices)
        faces_list.append(faces + offset)
        if any_uv:
            # Webots gives (0.5, 0.5) to the vertices of sub-meshes without texture coordinates.
            uv_list.append(uv if uv is not None else np.full((len(vertices), 2), 0.5))
        offset += len(vertices)
    vertices = np.concatenate(vertices_list)
    faces = np.concatenate(faces_list)
    uv = np.concatenate(uv_list) if any_uv else None

    # Merge exact duplicates of (position, texture coordinate): STL files repeat every corner.
    rows = vertices if uv is None else np.column_stack([vertices, uv])
    _, first, inverse = np.unique(rows, axis=0, return_index=True, return_inverse=True)
    order = np.argsort(first)  # keep the file's vertex order
    rank = np.empty_like(order)
    rank[order] = np.arange(order.size)
    faces = rank[inverse.ravel()][faces]
    vertices = vertices[first[order]]
    uv = None if uv is None else uv[first[order]]

    bad = (faces[:, 0] == faces[:, 1]) | (faces[:, 1] == faces[:, 2]) | (faces[:, 0] == faces[:, 2])
    if bad.any():
        messages.append(f"{int(bad.sum())} degenerate triangle(s) skipped in {path}")
        faces = faces[~bad]
    if faces.shape[0] == 0:
        messages.append(f"no triangle in mesh file {path}")
        return None
    texcoords = None if uv is None else uv.astype(np.float32)
    return MeshData(vertices, faces.astype(np.int32), texcoords)


def clear_mesh_cache() -> None:
    """Forget every loaded mesh file."""
    _MESH_CACHE.clear()


# ---------------------------------------------------------------------------------- mass properties


def mesh_volume_and_inertia(mesh: MeshData) -> tuple[float, np.ndarray, np.ndarray]:
    """Volume, centre of mass and inertia of a mesh of unit density.

    A closed mesh (watertight once coincident vertices are merged, consistently wound) is integrated
    exactly; an inside-out closed mesh is measured as if turned the right way. An open mesh is
    replaced by its convex hull (computed by MuJoCo, which measures mesh geoms the same way). A mesh
    without volume (flat) gives (0, centroid of its vertices, zeros).

    Args:
        mesh: the mesh.

    Returns:
        (volume in m^3, centre of mass (3,), inertia tensor (3, 3) about the centre of mass in the
        mesh frame, in kg m^2 for a density of 1 kg/m^3).
    """
    import trimesh

    vertices = np.asarray(mesh.vertices, dtype=np.float64)
    if mesh.faces.shape[0] and vertices.shape[0] >= 4:
        closed = trimesh.Trimesh(vertices, np.asarray(mesh.faces), process=True, validate=False)
        if closed.is_watertight and closed.is_winding_consistent:
            props = closed.mass_properties
            volume = float(props.volume)
            if volume < 0:
                closed.invert()
                props = closed.mass_properties
                volume = float(props.volume)
            if volume > 0:
                return volume, np.asarray(props.center_mass, dtype=np.float64), np.asarray(
                    props.inertia, dtype=np.float64)
    hull = _convex_hull_mass_properties(vertices)
    if hull is not None:
        return hull
    centroid = vertices.mean(axis=0) if vertices.size else np.zeros(3)
    return 0.0, centroid, np.zeros((3, 3))


def _convex_hull_mass_properties(vertices: np.ndarray) -> tuple[float, np.ndarray, np.ndarray] | None:
    """Unit-density mass properties of the convex hull of `vertices`, measured by MuJoCo (qhull)."""
    import mujoco

    if vertices.shape[0] < 4:
        return None
    # A flat (or nearly flat) point set has no volume; qhull would only complain about it on stderr.
    spread = np.linalg.svd(vertices - vertices.mean(axis=0), compute_uv=False)
    if not spread[0] > 0 or spread[2] <= 1e-6 * spread[0]:
        return None
    spec = mujoco.MjSpec()
    asset = spec.add_mesh()
    asset.name = "hull"
    asset.uservert = vertices.astype(np.float32).ravel().tolist()
    asset.inertia = mujoco.mjtMeshInertia.mjMESH_INERTIA_CONVEX
    body = spec.worldbody.add_body()
    geom = body.add_geom()
    geom.type = mujoco.mjtGeom.mjGEOM_MESH
    geom.meshname = "hull"
    geom.density = 1.0
    try:
        model = spec.compile()
    except Exception:  # coplanar or too few distinct points: no volume
        return None
    volume = float(model.body_mass[1])
    if not volume > 0:
        return None
    rotation = np.zeros(9)
    mujoco.mju_quat2Mat(rotation, model.body_iquat[1])
    rotation = rotation.reshape(3, 3)
    inertia = rotation @ np.diag(model.body_inertia[1]) @ rotation.T
    return volume, np.array(model.body_ipos[1], dtype=np.float64), inertia


# ---------------------------------------------------------------------------------- ElevationGrid


@dataclass
class HeightField:
    """An ElevationGrid as a MuJoCo height field.

    Webots puts grid point (i, j) at (i * xSpacing, j * ySpacing, height[i + j * xDimension]) in the
    node's frame: the grid starts at the node's origin and spreads towards +x and +y. Files older
    than R2022a (`legacy`) use (i * xSpacing, height[i + j * xDimension], j * zSpacing): heights along
    +y over an x-z grid.

    MuJoCo's hfield is centred on its geom frame, its elevation runs along the geom's +z from 0 (the
    lowest point, elevation 0) to `size[2]` (elevation 1), with a base box of depth `size[3]` below,
    and its data rows run along the geom's +y (row 0 at -y, columns along +x, row-major). So the
    caller adds a geom with `hfield size = mujoco_size()`, `elevation = normalized()`, `pos =
    center_offset` and `quat = quat` in the node's frame; then the MuJoCo surface matches Webots'.

    Attributes:
        nrow: grid points along the second axis (yDimension; zDimension in legacy files).
        ncol: grid points along x (xDimension).
        heights: (nrow, ncol) float32 heights in metres, Webots' order: row j is the j-th grid line
            along the second axis (row 0 at y = 0, the smallest y), column i the i-th along x.
        x_size: full extent along x, (xDimension - 1) * xSpacing.
        y_size: full extent along the second axis, (yDimension - 1) * ySpacing.
        thickness: Webots' `thickness` (depth of the solid added below the lowest point).
        legacy: the node is pre-R2022a (heights along +y, second grid axis +z).
        warnings: what was fixed while reading the node.
    """

    nrow: int
    ncol: int
    heights: np.ndarray
    x_size: float
    y_size: float
    thickness: float
    legacy: bool = False
    warnings: list[Diagnostic] = field(default_factory=list)

    @property
    def min_height(self) -> float:
        """The lowest height, metres."""
        return float(self.heights.min())

    @property
    def max_height(self) -> float:
        """The highest height, metres."""
        return float(self.heights.max())

    def mujoco_size(self) -> tuple[float, float, float, float]:
        """MuJoCo's hfield `size`: (radius x, radius y, elevation range z, base depth z).

        The radii are half the grid extents. The elevation range is max - min height (a flat grid
        gets a tiny positive range, MuJoCo needs one); the base depth is `thickness` (at least
        `MIN_HFIELD_SIZE`, for the same reason).
        """
        elevation = max(self.max_height - self.min_height, MIN_HFIELD_SIZE)
        return (self.x_size / 2.0, self.y_size / 2.0, float(elevation), max(float(self.thickness), MIN_HFIELD_SIZE))

    def normalized(self) -> np.ndarray:
        """The elevation data for MuJoCo: flat float32 array of nrow * ncol values in [0, 1], row-major.

        Value = (height - min) / (max - min) (0 everywhere on a flat grid). MuJoCo row r lies at
        geom y = -radius_y + r * 2 radius_y / (nrow - 1), column c at x = -radius_x + c * 2 radius_x /
        (ncol - 1). With `quat` identity that is Webots' row order; for legacy grids `quat` turns the
        geom's +y towards the node's -z, so the rows are reversed.
        """
        low, high = self.min_height, self.max_height
        data = (self.heights.astype(np.float64) - low) / (high - low) if high > low else np.zeros(self.heights.shape)
        if self.legacy:
            data = data[::-1]
        return np.ascontiguousarray(data, dtype=np.float32).ravel()

    @property
    def center_offset(self) -> tuple[float, float, float]:
        """Where the MuJoCo hfield geom goes in the node's frame.

        The grid's centre (Webots' grid starts at the node's origin, MuJoCo's is centred), raised to
        the lowest height (MuJoCo's elevation 0). Legacy grids: (x/2, min height, z/2).
        """
        if self.legacy:
            return (self.x_size / 2.0, self.min_height, self.y_size / 2.0)
        return (self.x_size / 2.0, self.y_size / 2.0, self.min_height)

    @property
    def quat(self) -> tuple[float, float, float, float]:
        """Orientation (w, x, y, z) of the hfield geom in the node's frame.

        Identity, except for legacy grids: -90 degrees about x, which turns the geom's +z (up) to the
        node's +y and the geom's +y to the node's -z; the same rotation Webots applies to old
        ElevationGrids (and to old cylinders) when it opens a pre-R2022a world.
        """
        if self.legacy:
            half = math.sqrt(0.5)
            return (half, -half, 0.0, 0.0)
        return (1.0, 0.0, 0.0, 0.0)


def elevation_grid(node: Any, legacy_axes: bool, warnings: list[Diagnostic] | None = None) -> HeightField | None:
    """Read an ElevationGrid node.

    Args:
        node: the ElevationGrid scene node.
        legacy_axes: the world predates R2022a: read `zDimension`/`zSpacing` (falling back to the
            y fields when only those are written) and lay the grid over x-z with heights along +y.
        warnings: a list to append warnings to.

    Returns:
        The height field, or None when the grid has fewer than 2 x 2 points.
    """
    found: list[Diagnostic] = []
    result = _elevation_grid(node, legacy_axes, found)
    if result is not None:
        result.warnings = found
    _finish(found, warnings)
    return result


def _elevation_grid(node: Any, legacy: bool, warnings: list[Diagnostic]) -> HeightField | None:
    fields = getattr(node, "fields", {})
    # R2022a renamed zDimension/zSpacing to yDimension/ySpacing. Take the names the file's era uses,
    # or the other ones when only those are written.
    first, other = (("zDimension", "zSpacing"), ("yDimension", "ySpacing")) if legacy else (
        ("yDimension", "ySpacing"), ("zDimension", "zSpacing"))
    names = first if first[0] in fields or other[0] not in fields else other
    x_dim = int(node.get("xDimension") or 0)
    y_dim = int(node.get(names[0]) or 0)
    x_spacing = float(node.get("xSpacing") if node.get("xSpacing") is not None else 1.0)
    y_spacing = float(node.get(names[1]) if node.get(names[1]) is not None else 1.0)
    thickness = float(node.get("thickness") if node.get("thickness") is not None else 1.0)

    # Webots' sanitizeFields: non-positive spacings become 1, a negative thickness 0.
    if x_spacing <= 0:
        _warn(warnings, node, "'xSpacing' must be positive: 1 used, as in Webots")
        x_spacing = 1.0
    if y_spacing <= 0:
        _warn(warnings, node, f"'{names[1]}' must be positive: 1 used, as in Webots")
        y_spacing = 1.0
    if thickness < 0:
        _warn(warnings, node, "'thickness' must not be negative: 0 used, as in Webots")
        thickness = 0.0
    if x_dim < 2 or y_dim < 2:
        _warn(warnings, node, f"ElevationGrid of {x_dim} x {y_dim} points has no cell: no geometry")
        return None

    heights = np.asarray(node.get("height") if node.get("height") is not None else [], dtype=np.float64).ravel()
    count = x_dim * y_dim
    if heights.size > count:
        _warn(warnings, node, f"'height' has {heights.size - count} extra value(s), ignored")
        heights = heights[:count]
    elif heights.size < count:
        # Webots pads missing heights with zeros.
        _warn(warnings, node, f"'height' has {heights.size} value(s) for {count} grid points: the rest are 0")
        heights = np.concatenate([heights, np.zeros(count - heights.size)])
    # height[i + j * xDimension]: x varies fastest, so a row of the (y_dim, x_dim) array is one grid
    # line along x, and row 0 is at the grid's origin (smallest y, or smallest z in legacy files).
    grid = heights.reshape(y_dim, x_dim).astype(np.float32)
    return HeightField(nrow=y_dim, ncol=x_dim, heights=grid, x_size=(x_dim - 1) * x_spacing,
                       y_size=(y_dim - 1) * y_spacing, thickness=thickness, legacy=legacy)
