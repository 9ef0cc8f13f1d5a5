"""CadShape files (Wavefront .obj with its .mtl, COLLADA .dae) to one triangle mesh per material.

Webots reads a CadShape's file with Assimp and turns each of its meshes into a renderable with a
PBRAppearance made from the mesh's material (WbCadShape.cpp, WbPbrAppearance's aiMaterial
constructor); this module reads the same facts. Each part is a `MeshData` in the file's own axes and
units (COLLADA's axis and unit conversion: `cad_dae`) with a `CadMaterial`:

* `base`: the diffuse colour (OBJ `Kd`, COLLADA `<diffuse>`; Assimp's default 0.6 grey when none is
  written, or when a face uses no material or an unknown one);
* `emissive`: OBJ `Ke`, COLLADA `<emission>` (black by default);
* `transparency`: 1 − opacity (OBJ `d`, or `Tr` as 1 − opacity; COLLADA: see `cad_dae`);
* `roughness`: 1 − shininess / 255 (OBJ `Ns`, default 0; COLLADA `<shininess>`, default 10), out of
  [0, 1] clamped (Webots resets an out-of-range roughness to 0); metalness is always 0;
* `texture`: the diffuse map (OBJ `map_Kd`, COLLADA `<diffuse><texture>`) as written, to be found
  relative to the .obj/.dae file itself (Webots' rule, whatever folder the .mtl is in).

OBJ faces with more than three corners are fanned from their first corner; faces of one material
form one part wherever they are in the file (Webots draws one renderable per Assimp mesh: the same
picture). Vertices without texture coordinates get (0.5, 0.5), as in Webots. Loaded files are cached
by path and modification time (the .mtl files' included).

Not read: OBJ `Ka`, `Ks`, `illum`, `Ni`, `Pr`/`Pm` and maps other than `map_Kd` (Webots' PBR
conversion ignores the first ones; roughness, metalness, normal, occlusion and emissive maps are not
honoured by wbtc's PBRAppearance either), texture options (`-s`, `-o`, `-clamp`), OBJ lines, points
and free-form geometry.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from wbtc.compile.mesh_data import MeshData
from wbtc.errors import UNREADABLE_FILE

#: Assimp's colour for a mesh without a material of its own (ObjFile::Material, Collada::Effect).
DEFAULT_BASE = (0.6, 0.6, 0.6)
#: OBJ faces written before any `usemtl` (or naming a material no .mtl defines).
_DEFAULT_NAME = "DefaultMaterial"


@dataclass(frozen=True)
class CadMaterial:
    """A part's look, as the fields of the PBRAppearance Webots makes for it."""

    base: tuple[float, float, float] = DEFAULT_BASE
    emissive: tuple[float, float, float] = (0.0, 0.0, 0.0)
    transparency: float = 0.0
    roughness: float = 1.0
    texture: str | None = None


@dataclass
class CadPart:
    """The faces of one material: a triangle mesh (counter-clockwise as written) and its material."""

    mesh: MeshData
    material: CadMaterial
    name: str = ""


@dataclass
class CadFile:
    """What a CadShape file gave: its parts, what was odd while reading it, the other files it read.

    Attributes:
        parts: one per material.
        messages: warnings as (message, topic): `UNREADABLE_FILE` for a file that cannot be had or read.
        depends: the companion files read (an OBJ's .mtl files): the cache follows their changes too.
    """

    parts: list[CadPart]
    messages: list[tuple[str, str | None]] = field(default_factory=list)
    depends: list[str] = field(default_factory=list)


#: Companion files (an OBJ's .mtl) named as written -> the local file, or None when it cannot be had.
Locate = Callable[[str], "str | None"]

#: Loaded files: (path, source key) -> (their modification times, the result).
_CACHE: dict[tuple[str, str], tuple[tuple[int, ...], CadFile]] = {}


def roughness(shininess: float) -> float:
    """Webots' roughness from an Assimp shininess: 1 − shininess / 255, kept within [0, 1]."""
    return float(min(max(1.0 - shininess / 255.0, 0.0), 1.0))


def load_cad(path: str, locate: Locate, key: str = "") -> CadFile:
    """Read a CadShape file (.obj or .dae), cached by path and modification times.

    Args:
        path: the local file.
        locate: finds a companion file (an .mtl) named relative to the CadShape's file.
        key: what `locate` depends on besides `path` (the remote URL the file came from).

    Returns:
        Its parts (none when it cannot be read) and messages.

    Raises:
        Nothing: a file that cannot be read gives no part and a message saying why.
    """
    absolute = os.path.abspath(path)
    cached = _CACHE.get((absolute, key))
    if cached is not None and cached[0] == _stamps([absolute, *cached[1].depends]):
        return cached[1]
    try:
        if absolute.lower().endswith(".dae"):
            from wbtc.compile.cad_dae import read_dae

            result = read_dae(absolute)
        else:
            result = read_obj(absolute, locate)
    except ImportError as exc:  # pycollada is an optional package of trimesh's
        result = CadFile([], [(f"cannot read {path}: a Python package is missing ({exc})", UNREADABLE_FILE)])
    except Exception as exc:  # noqa: BLE001 - broken files raise many kinds of errors; the node is left out
        result = CadFile([], [(f"cannot read {path}: {type(exc).__name__}: {exc}", UNREADABLE_FILE)])
    _CACHE[(absolute, key)] = (_stamps([absolute, *result.depends]), result)
    return result


def clear_cad_cache() -> None:
    """Forget every loaded CadShape file."""
    _CACHE.clear()


def _stamps(paths: list[str]) -> tuple[int, ...]:
    return tuple(os.stat(p).st_mtime_ns if os.path.isfile(p) else -1 for p in paths)


def read_obj(path: str, locate: Locate) -> CadFile:
    """The parts of a Wavefront file, one per material of its .mtl files (see the module docstring)."""
    positions: list[list[float]] = []
    uvs: list[list[float]] = []
    corners: dict[str, list[tuple[int, int]]] = {}  # material -> (position, uv or -1) per triangle corner
    libraries: list[str] = []
    messages: list[tuple[str, str | None]] = []
    current, bad_faces = _DEFAULT_NAME, 0
    with open(path, encoding="utf-8", errors="replace") as handle:
        for line in handle:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            keyword = words[0]
            if keyword == "v" and len(words) >= 4:
                positions.append([float(w) for w in words[1:4]])
            elif keyword == "vt" and len(words) >= 2:
                uvs.append([float(words[1]), float(words[2]) if len(words) > 2 else 0.0])
            elif keyword == "f":
                read = [_corner(w, len(positions), len(uvs)) for w in words[1:]]
                face = [c for c in read if c is not None]
                if len(face) < 3 or len(face) < len(read):
                    bad_faces += 1
                    continue
                target = corners.setdefault(current, [])
                for i in range(1, len(face) - 1):  # a polygon as a fan of triangles from its first corner
                    target += [face[0], face[i], face[i + 1]]
            elif keyword == "usemtl":
                current = line.strip()[len("usemtl"):].strip() or _DEFAULT_NAME
            elif keyword == "mtllib":
                libraries += _library_names(line.strip()[len("mtllib"):].strip())
    if bad_faces:
        messages.append((f"{bad_faces} face(s) with fewer than 3 corners or a missing vertex skipped in {path}",
                         None))
    materials, depends = _materials(libraries, locate, messages)
    parts = []
    position_array, uv_array = np.asarray(positions, dtype=float), np.asarray(uvs, dtype=float).reshape(-1, 2)
    for name, found in corners.items():
        mesh = _part_mesh(position_array, uv_array, np.asarray(found, dtype=np.int64))
        if mesh is not None:
            # Assimp gives a face without a material, or naming one no .mtl defines, a default material.
            parts.append(CadPart(mesh, materials.get(name, CadMaterial()), name))
    if not parts:
        messages.append((f"no triangle in {path}", None))
    return CadFile(parts, messages, depends)


def _corner(word: str, n_positions: int, n_uvs: int) -> tuple[int, int] | None:
    """A face corner `v`, `v/vt`, `v//vn` or `v/vt/vn` as 0-based (position, uv or -1); None if out of range."""
    pieces = word.split("/")
    try:
        vertex = int(pieces[0])
        uv = int(pieces[1]) if len(pieces) > 1 and pieces[1] else 0
    except ValueError:
        return None
    # OBJ indices count from 1; negative ones count back from the last element read so far.
    vertex = vertex - 1 if vertex > 0 else n_positions + vertex
    uv = -1 if uv == 0 else (uv - 1 if uv > 0 else n_uvs + uv)
    if not 0 <= vertex < n_positions or uv >= n_uvs or uv < -1:
        return None
    return vertex, uv


def _part_mesh(positions: np.ndarray, uvs: np.ndarray, corners: np.ndarray) -> MeshData | None:
    """The triangle mesh of one material's corners: one vertex per distinct (position, uv) pair."""
    # One integer per (position, uv) pair: a 1-D unique is much faster than a unique of rows.
    keys, inverse = np.unique(corners[:, 0] * (len(uvs) + 1) + corners[:, 1] + 1, return_inverse=True)
    unique = np.column_stack([keys // (len(uvs) + 1), keys % (len(uvs) + 1) - 1])
    faces = inverse.reshape(-1, 3)
    keep = (faces[:, 0] != faces[:, 1]) & (faces[:, 1] != faces[:, 2]) & (faces[:, 0] != faces[:, 2])
    faces = faces[keep]
    if len(faces) == 0:
        return None
    texcoords = None
    if (unique[:, 1] >= 0).any():
        # Webots gives (0.5, 0.5) to vertices without texture coordinates.
        texcoords = np.where(unique[:, 1:2] >= 0, uvs[np.maximum(unique[:, 1], 0)], 0.5).astype(np.float32)
    return MeshData(positions[unique[:, 0]], np.ascontiguousarray(faces, dtype=np.int32), texcoords)


def _library_names(text: str) -> list[str]:
    """The .mtl files of an `mtllib` line: several, or one whose name has spaces (as Webots splits them)."""
    text = text.replace('"', "")
    names = [name + ".mtl" for name in text.split(".mtl ")[:-1]] + [text.split(".mtl ")[-1]]
    return [name.strip() for name in names if name.strip()]


def _materials(libraries: list[str], locate: Locate,
               messages: list[tuple[str, str | None]]) -> tuple[dict[str, CadMaterial], list[str]]:
    """The materials of the .mtl files (the first definition of a name wins) and the files read."""
    materials: dict[str, CadMaterial] = {}
    depends: list[str] = []
    for name in libraries:
        found = locate(name)
        if found is None:
            messages.append((f"material file {name!r} not found beside the CAD file: its parts are grey",
                             UNREADABLE_FILE))
            continue
        depends.append(found)
        for material_name, material in read_mtl(found).items():
            materials.setdefault(material_name, material)
    return materials, depends


def read_mtl(path: str) -> dict[str, CadMaterial]:
    """The materials of a .mtl file, with the fields Webots' PBR conversion reads (module docstring)."""
    materials: dict[str, CadMaterial] = {}
    fields: dict[str, Any] = {}
    name = None

    def close() -> None:
        if name is not None:
            shininess = float(fields.pop("shininess", 0.0))  # Assimp's default Ns: 0, roughness 1
            materials[name] = CadMaterial(roughness=roughness(shininess), **fields)

    with open(path, encoding="utf-8", errors="replace") as handle:
        for line in handle:
            words = line.split()
            if not words or words[0].startswith("#"):
                continue
            keyword = words[0].lower()
            values = words[1:]
            if keyword == "newmtl":
                close()
                name, fields = line.strip()[len("newmtl"):].strip(), {}
            elif keyword in ("kd", "ke") and values:
                colour = _floats(values, 3)
                if len(colour) == 1:
                    colour *= 3  # one value stands for grey
                if len(colour) == 3:
                    fields["base" if keyword == "kd" else "emissive"] = tuple(colour)
            elif keyword in ("d", "tr") and _floats(values, 1):
                value = _floats(values, 1)[0]
                fields["transparency"] = 1.0 - value if keyword == "d" else value  # d: opacity, Tr: 1 − opacity
            elif keyword == "ns" and _floats(values, 1):
                fields["shininess"] = _floats(values, 1)[0]
            elif keyword == "map_kd" and values:
                fields["texture"] = _texture_name(values)
    close()
    return materials


def _floats(words: list[str], count: int) -> list[float]:
    out = []
    for word in words[:count]:
        try:
            out.append(float(word))
        except ValueError:
            break
    return out


#: Texture map options and how many arguments they take (`-o`, `-s`, `-t`: up to three numbers).
_OPTIONS = {"-blendu": 1, "-blendv": 1, "-cc": 1, "-clamp": 1, "-imfchan": 1, "-type": 1, "-texres": 1, "-bm": 1,
            "-boost": 1, "-mm": 2, "-o": 3, "-s": 3, "-t": 3}


def _texture_name(words: list[str]) -> str:
    """The file of a `map_Kd` line: what follows its options (`-o 0 0 0`, `-clamp on`...), spaces kept."""
    i = 0
    while i < len(words) - 1 and words[i].lower() in _OPTIONS:
        count = _OPTIONS[words[i].lower()]
        i += 1
        for _ in range(count):
            numeric = bool(_floats(words[i:i + 1], 1))
            if i >= len(words) - 1 or (count == 3 and not numeric):
                break
            i += 1
    return " ".join(words[i:]).replace("\\", "/")
