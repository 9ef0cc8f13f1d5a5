"""Webots `Mesh` files to triangle meshes, and the mass properties of any triangle mesh.

What it maps: `Mesh` -> `MeshData`: `url` (the first entry that exists; `webots://` and `http(s)://`
URLs through `wbtc.compile.remote`, a warning and no mesh when they cannot be had), `ccw`, `name`
(sub-mesh filter), texture coordinates when the file has them. Files are read with trimesh: OBJ, STL,
PLY, OFF, GLTF; COLLADA (.dae) only when the optional `pycollada` package is installed. Loaded files
are cached by path, modification time and name filter. `mesh_volume_and_inertia`: volume, centre of
mass and unit-density inertia of a `MeshData` (IndexedFaceSets are read by `faceset`, ElevationGrids
by `heightfield`).

Not honoured yet: Mesh `materialIndex` (a warning is given when it is set), FBX files (trimesh cannot
read them), and Assimp's COLLADA/FBX up-axis and unit-scale metadata handling.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from wbtc.compile.mesh_data import MeshData, finish, warn
from wbtc.errors import UNREADABLE_FILE, Diagnostic

# ---------------------------------------------------------------------------------- Mesh files

#: Loaded mesh files: (absolute path, mtime_ns, name filter) -> (mesh before `ccw`, file warnings).
_MESH_CACHE: dict[tuple[str, int, str], tuple[MeshData | None, list[tuple[str, str | None]]]] = {}


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
    from wbtc.compile import remote
    from wbtc.compile.textures import resolve_url

    found: list[Diagnostic] = []
    urls = list(node.get("url") or [])
    name = node.get("name") or ""
    result: MeshData | None = None
    base_file = node.span.file if getattr(node, "span", None) is not None else ""
    path = resolve_url(urls, base_file)
    if not urls:
        warn(found, node, "Mesh has no url: no geometry")
    elif path is None:
        remote_urls = [u for u in urls if remote.is_remote(u)]
        if remote_urls:
            warn(found, node, f"Mesh url {remote_urls[0]!r} cannot be read ({remote.failure(remote_urls[0])}; "
                              "not in WEBOTS_HOME or wbtc's asset cache): no geometry", UNREADABLE_FILE)
        else:
            warn(found, node, f"Mesh file not found: {urls[0]!r} (relative to {os.path.dirname(base_file) or '.'})",
                 UNREADABLE_FILE)
    else:
        materialindex = node.get("materialIndex")
        if materialindex is not None and materialindex >= 0:
            warn(found, node, "Mesh 'materialIndex' is not honoured yet: every sub-mesh is used")
        mesh, messages = _load_mesh_cached(path, name)
        for message, topic in messages:
            warn(found, node, message, topic)
        if mesh is not None:
            faces = mesh.faces
            if node.get("ccw") is False:
                # ccw FALSE: clockwise faces in the file; swap two corners to make them counter-clockwise.
                faces = faces[:, [0, 2, 1]]
            texcoords = None if mesh.texcoords is None else mesh.texcoords.copy()
            result = MeshData(mesh.vertices.copy(), np.ascontiguousarray(faces, dtype=np.int32), texcoords, found)
    finish(found, warnings)
    return result


def _load_mesh_cached(path: str, name: str) -> tuple[MeshData | None, list[tuple[str, str | None]]]:
    """The mesh of a file (None when it cannot be read) and its warnings, as (message, topic) pairs."""
    absolute = os.path.abspath(path)
    key = (absolute, os.stat(absolute).st_mtime_ns, name)
    if key not in _MESH_CACHE:
        messages: list[str] = []
        failure = None
        try:
            mesh = _load_mesh(absolute, name, messages)
        except ImportError as exc:  # trimesh reads COLLADA with the optional pycollada package
            mesh, failure = None, f"cannot read mesh file {path}: a Python package is missing ({exc})"
        except Exception as exc:  # trimesh raises many kinds of errors on bad or unsupported files
            mesh, failure = None, f"cannot read mesh file {path}: {type(exc).__name__}: {exc}"
        notes: list[tuple[str, str | None]] = [(message, None) for message in messages]
        if failure is not None:
            notes.append((failure, UNREADABLE_FILE))
        _MESH_CACHE[key] = (mesh, notes)
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
