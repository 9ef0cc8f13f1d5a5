"""Shapes a Pen can paint: each gets a texture and material of its own, and a mesh with Webots' mapping.

Webots paints ink on any Shape with a geometry a pen's ray meets (WbPaintTexture::isPaintable); the
ink stays on that shape, not on the image file other shapes share. A textured Shape's layer has its
image's size; an untextured one gets a layer of Webots' default size (`default_size`: 32 texels for
a small shape up to 1,024 for one whose bounding sphere's radius is 10 m, the nearest power of two)
in its own colour, which the material then no longer multiplies. So, in a world that has at least
one Pen, every visual Shape is compiled with:

- a MuJoCo texture of its own, Webots' paint layer with the image drawn in (`primitive_uv`: a Box's
  faces each get their own part of it; `faceset_uv`: an IndexedFaceSet without texture coordinates
  of its own is painted through Webots' non-repeating mapping, on a layer 4 x 2 times the image's
  size), which the runtime (`runtime.pen`) writes ink into;
- a material of its own showing that texture (a copy of the appearance's, without a repeat: the
  TextureTransform's scale is carried by the mesh's texture coordinates instead);
- a mesh geom, primitives included (`primitive_uv`, `faceset_uv`), whose texture coordinates address the layer:
  the runtime finds the texture coordinate of the point it paints from the mesh's triangles.

The DeviceTable's `paintable` names each such geom's texture, how many texels of Webots' layer a
metre of lead covers, the texture's texels per texel of Webots' layer and the geometry's node type.
Worlds without a Pen compile as before, and so does every world `wbtc compile` writes as MJCF
(`CompileOptions.paint` off): plain MuJoCo has no pen, and 777 paint layers made the corpus's IRB 4600
pen world's MJCF 441 MB of textures.

Not honoured yet: a texture a Display draws on is not paintable (the display's image wins); a Mesh
whose file has no texture coordinates, or an untextured Mesh, gets no ink (Webots paints it on a layer
4 x 2 times the image's size too); an untextured shape's default size ignores a Transform's scale;
a supervisor's change of an untextured paintable shape's colour multiplies its layer's colour;
cameras sample the whole texture texel by texel (`offscreen`), where Webots filters the image and
samples only the ink so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np

from wbtc.compile import faceset, faceset_uv, primitive_uv, textures
from wbtc.compile.context import CompileContext
from wbtc.scene.model import Node

#: The attributes a copied material keeps.
_MATERIAL_FIELDS = ("rgba", "emission", "specular", "shininess", "reflectance", "metallic", "roughness",
                    "texuniform", "info")
#: Longest side of a paint layer, texels.
_MAX_LAYER = 4096


def enabled(ctx: CompileContext) -> bool:
    """Whether the world has a Pen (then textured shapes are compiled paintable); found once per compile.

    Never for an MJCF written to disk (`CompileOptions.paint` off): nothing paints there.
    """
    if ctx.paint is None:
        ctx.paint = ctx.options.paint and any(node.base_type == "Pen" for node in ctx.scene.walk())
    return ctx.paint


@dataclass
class PaintSetup:
    """What a paintable shape is compiled with.

    Attributes:
        material: its own material (a copy of the appearance's).
        texture: its own texture, the paint layer with the image drawn in.
        painted: a primitive's, or a default-mapped IndexedFaceSet's, mesh and layer layout
            (`primitive_uv`, `faceset_uv`); None for an IndexedFaceSet with texture coordinates of its
            own or a Mesh, whose own texture coordinates address the layer (the image itself).
        image_width: the image's width in pixels (Webots sizes the lead by it).
        zoom: the layer's texels per texel of Webots' layer (more than 1 when a TextureTransform
            repeats the image within the layer of a primitive or a default-mapped IndexedFaceSet: each
            copy keeps its resolution).
    """

    material: str
    texture: str
    painted: primitive_uv.Painted | None
    image_width: int
    zoom: float = 1.0


def prepare(ctx: CompileContext, shape: Node, material: str, path: str | None,
            colour: np.ndarray | None = None) -> PaintSetup | None:
    """The material, texture and mesh that make a Shape paintable (None: it cannot be).

    Args:
        ctx: the compile context.
        shape: the Shape.
        material: the appearance's material (as `appearance.shape_look` made it).
        path: the ImageTexture's file; None for an untextured shape, whose layer is `colour`.
        colour: an untextured shape's rgba (0-1, sRGB, as `appearance.shape_look` gives it).

    Returns:
        None when the image cannot be read or the geometry is not one a pen paints (the shape then
        keeps the shared material).
    """
    geometry = shape.get("geometry")
    if not isinstance(geometry, Node):
        return None
    painted = None
    if geometry.base_type in primitive_uv.MESHED_PRIMITIVES:
        painted = primitive_uv.primitive_mesh(geometry, ctx.legacy_axes(geometry))
        if painted is None:
            return None
    elif geometry.base_type == "IndexedFaceSet":
        # None: its own texture coordinates address a layer of the image's size (Webots' size factor 1).
        painted = faceset_uv.painted_faceset(geometry, ctx.warnings)
    elif geometry.base_type != "Mesh" or path is None:
        return None
    if path is None:
        radius = _radius(painted.mesh.vertices if painted is not None else faceset.coordinates(geometry))
        if radius is None or colour is None:
            return None
        size = default_size(radius)
        pixels = np.empty((size, size, 3), dtype=np.uint8)
        pixels[:] = np.round(np.clip(np.asarray(colour[:3], dtype=float), 0.0, 1.0) * 255.0).astype(np.uint8)
        width = size
    else:
        try:
            image = textures.load_texture(path)
        except OSError:
            return None
        pixels = np.dstack([image.rgb, image.alpha_values]) if image.alpha and image.alpha_values is not None \
            else image.rgb
        width = image.width
    # The texture's name starts with "paint_": cameras sample it without mipmaps (offscreen.PAINT_TEXTURE_PREFIX).
    base = f"paint_{shape.span.line}"
    texture = ctx.spec.add_texture(name=ctx.unique("texture", base), type=mujoco.mjtTexture.mjTEXTURE_2D)
    zoom = 1.0
    if painted is not None:
        look = shape.get("appearance")
        transform = look.get("textureTransform") if isinstance(look, Node) else None
        pixels, zoom = _layer(pixels, painted, transform if isinstance(transform, Node) else None)
    # RGB(A) rows from the top of the image, as MuJoCo stores a PNG it reads itself.
    texture.height, texture.width, texture.nchannel = pixels.shape
    texture.data = np.ascontiguousarray(pixels, dtype=np.uint8).tobytes()
    copy = _copy_material(ctx, material, texture.name, base)
    if path is not None:
        ctx.texture_paths[texture.name] = path
    else:
        # The layer carries the colour now: the material no longer multiplies it (its alpha stays).
        ctx.spec.material(copy).rgba = [1.0, 1.0, 1.0, float(colour[3])]
    return PaintSetup(copy, texture.name, painted, width, zoom)


def default_size(radius: float) -> int:
    """Webots' paint layer side for an untextured shape whose bounding sphere has this radius (m).

    32 texels plus 992 per 10 m of radius (1,024 from 10 m on), rounded to the nearest power of two
    (WbPaintTexture::computeDefaultTextureSize; half-way goes up).
    """
    size = 1024.0 if radius > 10.0 else 32.0 + (1024.0 - 32.0) * radius / 10.0
    upper = 1 << max(0, math.ceil(math.log2(max(size, 1.0))))
    lower = upper // 2
    return lower if abs(upper - size) > abs(lower - size) else upper


def _radius(points: np.ndarray | None) -> float | None:
    """The radius of the sphere about the points' bounding box centre that holds them all."""
    if points is None or not len(points):
        return None
    vertices = np.asarray(points, dtype=float).reshape(-1, 3)
    centre = (vertices.min(axis=0) + vertices.max(axis=0)) / 2
    return float(np.linalg.norm(vertices - centre, axis=1).max())


def _layer(pixels: np.ndarray, painted: primitive_uv.Painted, transform: Node | None) -> tuple[np.ndarray, float]:
    """The paint layer of a primitive or a default-mapped IndexedFaceSet, and its texels per texel of Webots' layer.

    White, with the image in each region as the shape shows it: the region's own (s, t) go through the
    appearance's TextureTransform (which repeats, turns or moves the image) and pick the image's
    nearest pixel (an IndexedFaceSet's triangles each show the image through the default mapping:
    `faceset_uv.draw_layer`). Webots' layer is the image's size times the grid; here it is as many
    times larger again as the transform repeats the image (so that each copy keeps its pixels), 4096
    texels a side at most.
    """
    columns, rows = painted.grid
    height, width = pixels.shape[:2]
    repeat = 1.0
    if transform is not None and transform.get("scale") is not None:
        repeat = max(1.0, *(abs(float(v)) for v in transform.get("scale")))
    out_w = max(1, min(round(width * columns * repeat), _MAX_LAYER))
    out_h = max(1, min(round(height * rows * out_w / (width * columns)), _MAX_LAYER))
    if painted.image_uv is not None:
        return faceset_uv.draw_layer(pixels, painted, (out_w, out_h), transform), out_w / (width * columns)
    layer = np.full((out_h, out_w, pixels.shape[2]), 255, dtype=np.uint8)
    # Without a rotation the transform moves s and t each on its own (s' = f(s), t' = g(t)): the
    # image's columns follow from the region's columns alone, its rows from its rows, so one pass per
    # axis picks them (the same floating-point values as per texel: the rotation's 0 terms add 0).
    separable = transform is None or not float(transform.get("rotation") or 0.0)
    for s0, t0, s1, t1 in painted.regions:
        # (s, t) count t upwards; the layer's rows run from the top.
        c0, c1 = round(s0 * out_w), round(s1 * out_w)
        r0, r1 = round((1.0 - t1) * out_h), round((1.0 - t0) * out_h)
        if c1 <= c0 or r1 <= r0:
            continue
        # Each texel centre's (s, t) within the region, as the part's mesh has them.
        s = (np.arange(c1 - c0) + 0.5) / (c1 - c0)
        t = 1.0 - (np.arange(r1 - r0) + 0.5) / (r1 - r0)
        if separable:
            along_s = textures.apply_texture_transform(np.column_stack([s, np.zeros_like(s)]), transform)[:, 0]
            along_t = textures.apply_texture_transform(np.column_stack([np.zeros_like(t), t]), transform)[:, 1]
            layer[r0:r1, c0:c1] = pixels[np.ix_(_image_rows(along_t, height), _image_columns(along_s, width))]
            continue
        ss, tt = np.meshgrid(s, t)
        moved = textures.apply_texture_transform(np.column_stack([ss.ravel(), tt.ravel()]), transform)
        picked, cols = _image_rows(moved[:, 1], height), _image_columns(moved[:, 0], width)
        layer[r0:r1, c0:c1] = pixels[picked, cols].reshape(r1 - r0, c1 - c0, -1)
    return layer, out_w / (width * columns)


def _image_columns(s: np.ndarray, width: int) -> np.ndarray:
    """The image's pixel columns at texture coordinates s (the image repeats)."""
    return np.floor(np.mod(s, 1.0) * width).astype(int).clip(0, width - 1)


def _image_rows(t: np.ndarray, height: int) -> np.ndarray:
    """The image's pixel rows at texture coordinates t (the image repeats; its row 0 is t = 1)."""
    return np.floor(np.mod(1.0 - t, 1.0) * height).astype(int).clip(0, height - 1)


def _copy_material(ctx: CompileContext, material: str, texture: str, base: str) -> str:
    """A copy of `material` showing `texture`, lit as the original."""
    source = ctx.spec.material(material)
    copy = ctx.spec.add_material(name=ctx.unique("material", base))
    for name in _MATERIAL_FIELDS:
        setattr(copy, name, getattr(source, name))
    copy.texrepeat = [1.0, 1.0]  # a mesh's texture coordinates carry any TextureTransform
    copy.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = texture
    # The run-time lighting tables are keyed by material name: the copy is lit as the original.
    ctx.ambient_roles[copy.name] = ctx.ambient_roles.get(material)
    if material in ctx.camera_terms:
        ctx.camera_terms[copy.name] = ctx.camera_terms[material]
    if material in ctx.table.infrared:
        ctx.table.infrared[copy.name] = ctx.table.infrared[material]
    return copy.name


def register(ctx: CompileContext, geom: mujoco.MjsGeom, setup: PaintSetup, shape: Node) -> None:
    """Record a paintable geom (named here if it has no name yet), its texture and its lead scale.

    Webots sizes a pen's stroke in texels of the layer: leadSize x the image's width / the radius of the
    geometry's bounding sphere (scale included). That radius is taken from the mesh's scaled vertices:
    the farthest one from the centre of their bounding box.
    """
    if not geom.name:
        geom.name = ctx.unique("geom", f"paint_{shape.span.line}")
    mesh = ctx.spec.mesh(geom.meshname) if geom.meshname else None
    if mesh is None:
        return
    radius = _radius(np.asarray(mesh.uservert, dtype=float))
    if radius is None:
        return
    geometry = shape.get("geometry")
    kind = geometry.base_type if isinstance(geometry, Node) else ""
    ctx.table.paintable[geom.name] = (setup.texture, setup.image_width / max(radius, 1e-9), setup.zoom, kind)
