"""Webots' CadShape node (R2022b+) to visual mesh geoms, one per material of its .obj or .dae file.

What it maps: the file named by the first `url` entry (Webots uses that one only), relative to the
world or PROTO file that wrote the node; `webots://` and `http(s)://` URLs through
`wbtc.compile.remote`, and then the file's .mtl and textures are fetched from beside its remote
address, as Webots does. Only `.dae` and `.obj` files are read (Webots refuses others). Each
material's faces (`cad_files`, `cad_dae`) become one visual geom in group 1, massless and colliding
with nothing: a CadShape is never a bounding object and adds no mass. Its look is the PBRAppearance
Webots makes from the material (base colour, emissive colour, transparency, roughness from
shininess, metalness 0, the diffuse texture), compiled by `appearance` like any PBRAppearance, so
cameras, the viewer and recordings show it as they show Shapes. `ccw FALSE` turns every face over,
as Webots turns the renderables' front faces.

What sees it, as in Webots: cameras (segmentation included), RangeFinders and Lidars (Webots renders
CadShapes in its depth and segmentation passes too; wbtc's rays for them cast at visual geoms).
Generic, sonar and laser DistanceSensors see bounding objects only, so they do not see it in Webots
nor here. Infra-red DistanceSensors and Pens see through it (Webots' infra-red rays and pen only
meet Shape nodes: WbNodeUtilities::findIntersectingShape): its geoms are listed in the table
(`cad_geoms`) for wbtc.runtime.rays to pass, and get no paint layer.

A file that cannot be found or read gives a warning at the node (topic `UNREADABLE_FILE`, as Mesh
files do) and the node is left out; so does a url that is not a .dae or .obj file.

Not honoured yet: `castShadows` (MuJoCo has no per-geom shadow switch; wbtc's camera images have no
shadows) and `isPickable` (mouse picking), with a warning when set to FALSE. An LED does not light
a CadShape among its children, as in Webots (wbtc.compile.device.finish_led).
A textured part shows its texture alone, as Webots' baseColorMap overrides baseColor.
"""

from __future__ import annotations

import os
import posixpath
import urllib.parse

import mujoco
import numpy as np

from wbtc.compile import appearance, cad_files, geometry, remote, textures
from wbtc.compile.context import CompileContext
from wbtc.compile.frames import Frame
from wbtc.compile.mesh_data import MeshData
from wbtc.errors import UNREADABLE_FILE
from wbtc.scene.model import Node
from wbtc.schema.registry import node_schema

_UNHONOURED = frozenset({"castShadows", "isPickable"})
#: The files Webots' CadShape reads (WbCadShape::createWrenObjects).
_EXTENSIONS = (".dae", ".obj")


def add_cad_shape(node: Node, body: mujoco.MjsBody, frame: Frame, ctx: CompileContext) -> list[mujoco.MjsGeom]:
    """Add a CadShape's visual geoms to `body`.

    Args:
        node: the CadShape.
        body: the MuJoCo body it belongs to.
        frame: its frame in the body (Transform scale included).
        ctx: the compile context (warnings go there).

    Returns:
        The geoms made, one per material of the file (none when the file cannot be read).
    """
    ctx.unhonoured(node, _UNHONOURED)
    url = cad_url(node)
    if url is None:
        ctx.warn("CadShape has no url: it shows nothing", node.span)
        return []
    if not url.lower().split("?")[0].endswith(_EXTENSIONS):
        ctx.warn(f"CadShape url {url!r} is not a Collada ('.dae') or Wavefront ('.obj') file; it is left out",
                 node.span, UNREADABLE_FILE)
        return []
    path = textures.resolve_url([url], node.span.file)
    if path is None:
        if remote.is_remote(url):
            why = f"{remote.failure(url)}; not in WEBOTS_HOME or wbtc's asset cache"
            ctx.warn(f"CadShape url {url!r} cannot be read ({why}); it is left out", node.span, UNREADABLE_FILE)
        else:
            folder = os.path.dirname(node.span.file) or "."
            ctx.warn(f"CadShape file not found: {url!r} (relative to {folder}); it is left out", node.span,
                     UNREADABLE_FILE)
        return []
    base = url if remote.is_remote(url) else path
    loaded = cad_files.load_cad(path, lambda name: textures.resolve_url([companion(name, base)], ""),
                                base if remote.is_remote(base) else "")
    for message, topic in loaded.messages:
        ctx.warn(message, node.span, topic)
    if not loaded.parts:
        ctx.warn("the CadShape's file cannot be read; it is left out", node.span, UNREADABLE_FILE)
        return []
    made = []
    for part in loaded.parts:
        rgba, material, texture = appearance.shape_look(_shape(node, part.material, base), ctx)
        made.append(geometry.add_visual_mesh(body, node, _prepared(part.mesh, node), frame, ctx, rgba=rgba,
                                             material=material, textured=texture is not None))
    return made


def cad_url(node: Node) -> str | None:
    """The url a CadShape reads: its first entry (backslashes as slashes, as Webots rewrites them)."""
    urls = [str(u) for u in node.get("url") or []]
    return urls[0].replace("\\", "/") if urls and urls[0] else None


def companion(name: str, base: str) -> str:
    """A file named in a CAD file (an .mtl, a texture) as a url: relative to the CAD file, local or remote.

    Webots looks for them beside the CAD file only (no other search), and beside its remote address
    when it came from the web.
    """
    name = name.replace("\\", "/")
    if remote.is_remote(base):
        if remote.is_remote(name):
            return name
        scheme, _, rest = base.partition("://")
        rest = urllib.parse.urlsplit("//" + rest)
        joined = posixpath.normpath(posixpath.join(posixpath.dirname(rest.path), name))
        return f"{scheme}://{rest.netloc}{joined}"
    if os.path.isabs(name):
        return name
    return os.path.normpath(os.path.join(os.path.dirname(base), name))


def _shape(node: Node, material: cad_files.CadMaterial, base: str) -> Node:
    """The Shape and PBRAppearance Webots makes for one part, as nodes `appearance.shape_look` reads.

    They are placed at the CadShape, so that a texture that cannot be found is reported there.
    """
    look = _node("PBRAppearance", node, baseColor=material.base, emissiveColor=material.emissive,
                 transparency=material.transparency, roughness=material.roughness, metalness=0.0)
    if material.texture:
        # Webots' texture of a CAD material repeats (repeatS and repeatT TRUE): ImageTexture's defaults.
        look.fields["baseColorMap"] = _node("ImageTexture", node, url=[companion(material.texture, base)])
    return _node("Shape", node, appearance=look)


def _node(type_name: str, at: Node, **fields: object) -> Node:
    made = Node(type_name, at.span, node_schema(type_name))
    made.origin = at.origin
    made.fields.update(fields)
    return made


def _prepared(mesh: MeshData, node: Node) -> MeshData:
    """A part's mesh for MuJoCo: faces turned over for `ccw FALSE` (clockwise faces), at least 4 vertices."""
    vertices, faces, texcoords = mesh.vertices, mesh.faces, mesh.texcoords
    if node.get("ccw") is False:
        faces = np.ascontiguousarray(faces[:, [0, 2, 1]])
    if len(vertices) < 4:
        # MuJoCo refuses a mesh of fewer than 4 vertices (a part that is one triangle): repeat the first,
        # which no face uses.
        extra = 4 - len(vertices)
        vertices = np.vstack([vertices, np.repeat(vertices[:1], extra, axis=0)])
        if texcoords is not None:
            texcoords = np.vstack([texcoords, np.repeat(texcoords[:1], extra, axis=0)])
    return MeshData(vertices, faces, texcoords)
