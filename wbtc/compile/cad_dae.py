"""COLLADA (.dae) CadShape files to parts, read with pycollada as Webots reads them with Assimp.

Geometry: every triangle, polylist and polygon primitive of the default scene's geometry instances,
each placed by its nodes' transforms; lines are left out. Then the two conversions Webots' CadShape
gets (WbCadShape.cpp and Assimp's ColladaLoader):

* Assimp scales the scene by the file's `<unit meter>` and turns a `Z_UP` or `X_UP` file into `Y_UP`;
* Webots then turns the result a quarter turn about x (y up to z up), so a `Y_UP` file's (x, y, z)
  lands at (x, −z, y) and a `Z_UP` file keeps its axes.

Materials (`cad_files.CadMaterial`) come from each primitive's bound material's effect: `<diffuse>`
colour or texture, `<emission>`, `<shininess>` and the opacity Assimp derives from `<transparent>`,
`<transparency>` and the `opaque` mode (A_ONE: alpha × transparency; RGB_*: the transparent colour's
luminance × transparency; *_ZERO: one minus that). Effect fields the file does not write take
Assimp's defaults (diffuse 0.6 grey, shininess 10, transparency 1). A primitive whose material
symbol is not bound takes the instance's first bound material, else the file's first material.

Not read: texture coordinate sets other than the first, controllers (skinned meshes), morphs, a
mirroring node transform's effect on the winding, and Assimp's `<extra>` sampler options.
"""

from __future__ import annotations

import urllib.parse
import warnings
from typing import Any

import numpy as np

from wbtc.compile.cad_files import DEFAULT_BASE, CadFile, CadMaterial, CadPart, roughness
from wbtc.compile.mesh_data import MeshData

#: (file up axis) -> rotation to Webots' z-up axes: Webots' fixed quarter turn after Assimp's turn to y up.
_TURN_TO_Y_UP = {
    "Y_UP": np.eye(3),
    "Z_UP": np.array([[1.0, 0, 0], [0, 0, 1], [0, -1, 0]]),  # Assimp: (x, y, z) -> (x, z, −y)
    "X_UP": np.array([[0.0, -1, 0], [1, 0, 0], [0, 0, 1]]),  # Assimp: (x, y, z) -> (−y, x, z)
}
_Y_UP_TO_Z_UP = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])  # Webots: (x, y, z) -> (x, −z, y)
#: ITU-R BT.709 luminance weights: Assimp's opacity from an RGB `<transparent>` colour.
_LUMINANCE = (0.212671, 0.715160, 0.072169)


def read_dae(path: str) -> CadFile:
    """The parts of a COLLADA file, one per material, in Webots' axes and metres."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", PendingDeprecationWarning)  # pycollada's own use of numpy.matrix
        return _read(path)


def _read(path: str) -> CadFile:
    import collada
    from collada.common import DaeBrokenRefError, DaeIncompleteError, DaeUnsupportedError

    document = collada.Collada(path, ignore=[DaeUnsupportedError, DaeBrokenRefError, DaeIncompleteError])
    messages: list[tuple[str, str | None]] = []
    scene = document.scene if document.scene is not None else (document.scenes[0] if document.scenes else None)
    axis = str(getattr(document.assetInfo, "upaxis", "Y_UP") or "Y_UP")
    unit = float(getattr(document.assetInfo, "unitmeter", None) or 1.0)
    turn = unit * (_Y_UP_TO_Z_UP @ _TURN_TO_Y_UP.get(axis, np.eye(3)))
    groups: dict[int, tuple[Any, list[np.ndarray], list[np.ndarray | None]]] = {}
    for bound in scene.objects("geometry") if scene is not None else []:
        fallback = _first_bound_material(bound, document)
        for primitive in bound.primitives():
            triangles = _triangles(primitive)
            if triangles is None:
                continue
            corners, uv = triangles
            material = primitive.material if primitive.material is not None else fallback
            entry = groups.setdefault(id(material), (material, [], []))
            entry[1].append(corners @ turn.T)
            entry[2].append(uv)
    parts = []
    for material, corner_list, uv_list in groups.values():
        mesh = _mesh(corner_list, uv_list)
        if mesh is not None:
            parts.append(CadPart(mesh, _material(material), str(getattr(material, "name", "") or "")))
    if not parts:
        messages.append((f"no triangle in {path}", None))
    return CadFile(parts, messages)


def _first_bound_material(bound: Any, document: Any) -> Any:
    """What Assimp gives a primitive whose material symbol is not bound (see the module docstring)."""
    bound_materials = list(getattr(bound, "materialnodebysymbol", {}).values())
    for node in bound_materials:
        target = getattr(node, "target", None)
        if target is not None:
            return target
    return document.materials[0] if len(document.materials) else None


def _triangles(primitive: Any) -> tuple[np.ndarray, np.ndarray | None] | None:
    """A primitive's triangle corners (n × 3 rows of positions) and their first texture coordinates."""
    if not hasattr(primitive, "vertex_index") or primitive.vertex is None:
        return None  # a line set: Webots skips faces of fewer than three corners
    if hasattr(primitive, "triangleset") and not hasattr(primitive, "triangles"):
        primitive = primitive.triangleset()  # polylist and polygons, fanned
    index = np.asarray(primitive.vertex_index, dtype=np.int64).reshape(-1, 3)
    if len(index) == 0:
        return None
    corners = np.asarray(primitive.vertex, dtype=float)[index.ravel()]
    uv = None
    if len(primitive.texcoordset) and len(primitive.texcoord_indexset):
        uv_index = np.asarray(primitive.texcoord_indexset[0], dtype=np.int64).reshape(-1)
        uv = np.asarray(primitive.texcoordset[0], dtype=float)[uv_index][:, :2]
    return corners, uv


def _mesh(corner_list: list[np.ndarray], uv_list: list[np.ndarray | None]) -> MeshData | None:
    """One material's triangles as a mesh with shared vertices (equal position and texture coordinate)."""
    corners = np.concatenate(corner_list)
    has_uv = any(uv is not None for uv in uv_list)
    if has_uv:
        # Webots gives (0.5, 0.5) to the vertices of meshes without texture coordinates.
        uvs = np.concatenate([uv if uv is not None else np.full((len(c), 2), 0.5)
                              for c, uv in zip(corner_list, uv_list, strict=True)])
        rows = np.column_stack([corners, uvs])
    else:
        rows = corners
    unique, inverse = np.unique(rows, axis=0, return_inverse=True)
    faces = inverse.reshape(-1, 3)
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])
    if not keep.any():
        return None
    texcoords = unique[:, 3:5].astype(np.float32) if has_uv else None
    return MeshData(unique[:, :3].copy(), np.ascontiguousarray(faces[keep], dtype=np.int32), texcoords)


def _material(material: Any) -> CadMaterial:
    """The PBR fields Webots makes of a COLLADA material's effect (module docstring)."""
    effect = getattr(material, "effect", None)
    if effect is None:
        return CadMaterial(roughness=roughness(10.0))
    diffuse, texture = getattr(effect, "diffuse", None), None
    base = DEFAULT_BASE
    if isinstance(diffuse, tuple | list) and len(diffuse) >= 3:
        base = (float(diffuse[0]), float(diffuse[1]), float(diffuse[2]))
    elif diffuse is not None:
        texture = _image_path(diffuse)
    emission = getattr(effect, "emission", None)
    emissive = (0.0, 0.0, 0.0)
    if isinstance(emission, tuple | list) and len(emission) >= 3:
        emissive = (float(emission[0]), float(emission[1]), float(emission[2]))
    shininess = getattr(effect, "shininess", None)
    shininess = float(shininess) if isinstance(shininess, int | float) else 10.0
    return CadMaterial(base, emissive, 1.0 - _opacity(effect), roughness(shininess), texture)


def _opacity(effect: Any) -> float:
    """Assimp's opacity of a COLLADA effect (ColladaLoader::FillMaterials)."""
    transparency = getattr(effect, "transparency", None)
    value = float(transparency) if isinstance(transparency, int | float) else 1.0
    written = getattr(effect, "transparent", None)
    colour = written if isinstance(written, tuple | list) and len(written) >= 4 else (0.0, 0.0, 0.0, 1.0)
    mode = str(getattr(effect, "opaque_mode", None) or "A_ONE")
    if not 0.0 <= value <= 1.0:
        return 1.0
    if mode in ("RGB_ZERO", "RGB_ONE"):
        value *= sum(w * float(c) for w, c in zip(_LUMINANCE, colour[:3], strict=True))
    else:
        value *= float(colour[3])
    if mode in ("RGB_ZERO", "A_ZERO"):
        value = 1.0 - value
    # Assimp sets an opacity only when the effect writes <transparent> or the value is below one.
    return value if written is not None or value < 1.0 else 1.0


def _image_path(texture_map: Any) -> str | None:
    """The image file a `<texture>` reads, as written (URL escapes and a `file://` prefix undone)."""
    image = getattr(getattr(getattr(texture_map, "sampler", None), "surface", None), "image", None)
    path = getattr(image, "path", None)
    if not path:
        return None
    path = urllib.parse.unquote(str(path)).replace("\\", "/")
    if path.startswith("file://"):
        path = path[len("file://"):]
        if len(path) > 2 and path[0] == "/" and path[2] == ":":
            path = path[1:]  # file:///C:/... names a Windows drive
    return path
