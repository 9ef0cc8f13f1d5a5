"""Appearance, Material, PBRAppearance and ImageTexture to MuJoCo colours, materials and textures.

A Shape's colour becomes its geom's rgba and its material's (MuJoCo draws the geom's rgba unless it
is the default grey). Every appearance gets a material, which carries its highlight: MuJoCo gives a
geom without one a bright default specular that Webots' default Material does not have. A texture
becomes a MuJoCo 2D texture and material, the image converted to PNG and handed to MuJoCo through
the spec's in-memory assets. Emissive colours are folded into the rgba with the material's
`emission` so lit LEDs glow.

Highlights: a Material's `specularColor` (its mean: MuJoCo has one level) and `shininess`; a
PBRAppearance's from roughness and metalness (`_pbr_specular`).

Ambient light (`world.set_ambient`): a Phong Material is lit by the lights' ambientIntensity × its
own `ambientIntensity`, a PBRAppearance by the Background; MuJoCo has one ambient for all, so each
material's `ambient_roles` entry lets its emission make up the rest. An Appearance without Material is
unlit in Webots (white, or its texture's colour): cameras draw it so (`unlit`, `UNLIT_K`); MuJoCo's
viewer still lights it.

Not honoured yet: a coloured specular; PBRAppearance maps other than
`baseColorMap` (roughness, metalness, normal, occlusion, emissive maps), `IBLStrength`;
TextureTransform `center`, `rotation` and `translation` on primitives (a mesh's texture coordinates
carry the whole transform: `geometry._mesh`); ImageTexture `filtering`.
"""

from __future__ import annotations

import hashlib
import math

import mujoco
import numpy as np

from wbtc.compile import display_texture, remote, textures
from wbtc.compile.context import CompileContext, info
from wbtc.errors import UNREADABLE_FILE
from wbtc.scene.model import Node

_UNHONOURED = frozenset({"roughnessMap", "metalnessMap", "normalMap", "occlusionMap", "emissiveColorMap",
                         "center", "filtering"})
#: Webots' colour when a Shape has no appearance at all.
DEFAULT_RGBA = np.array([1.0, 1.0, 1.0, 1.0])


def shape_look(shape: Node, ctx: CompileContext) -> tuple[np.ndarray, str | None, str | None]:
    """The rgba, MuJoCo material name and texture image path of a Shape's appearance."""
    appearance = shape.get("appearance")
    if not isinstance(appearance, Node):
        # A material all the same: the Background's ambient reaches it through its emission.
        name = _material(ctx, DEFAULT_RGBA.copy(), 0.0, 0.5, 0.5, None, (1.0, 1.0), shape)
        return DEFAULT_RGBA.copy(), name, None
    ctx.unhonoured(appearance, _UNHONOURED)
    if appearance.base_type == "PBRAppearance":
        rgba, emission, texture_node = _pbr(appearance)
        specular, shininess = _pbr_specular(appearance)
    else:
        rgba, emission, texture_node = _phong(appearance)
        specular, shininess = _phong_specular(appearance)
    path = None
    if isinstance(texture_node, Node) and texture_node.base_type == "ImageTexture":
        urls = [str(u) for u in texture_node.get("url") or []]
        path = textures.resolve_url(urls, texture_node.span.file)
        if path is None and urls:
            why = f" ({remote.failure(urls[0])})" if remote.is_remote(urls[0]) else ""
            ctx.warn(f"the texture {urls[0]!r} cannot be found{why}; the shape keeps its plain colour",
                     texture_node.span, UNREADABLE_FILE)
    shown = display_texture.display_texture(ctx, texture_node, path) if isinstance(texture_node, Node) else None
    if shown is not None:
        # A Display draws on this texture: a texture of its own at the display's size (no clamp, no file).
        name = _material(ctx, rgba, emission, specular, shininess, None, _texture_repeat(appearance), appearance,
                         texture=shown)
        return np.array([1.0, 1.0, 1.0, rgba[3]]), name, None
    geometry_node = shape.get("geometry")
    meshed = isinstance(geometry_node, Node) and geometry_node.base_type in ("IndexedFaceSet", "Mesh")
    # A mesh's texture coordinates carry the TextureTransform (geometry._mesh); MuJoCo's own texture
    # mapping of primitives only gets the transform's scale, as the material's repeat.
    repeat = (1.0, 1.0) if meshed else _texture_repeat(appearance)
    name = _material(ctx, rgba, emission, specular, shininess, path, repeat, appearance)
    if path is not None:
        # A textured material carries the colour; the geom's rgba stays white so it does not tint twice.
        return np.array([1.0, 1.0, 1.0, rgba[3]]), name, path
    return rgba, name, None


def _phong(appearance: Node) -> tuple[np.ndarray, float, Node | None]:
    material = appearance.get("material")
    texture = appearance.get("texture")
    if not isinstance(material, Node):
        # Webots draws a textured shape without a Material at full texture colour, and an
        # untextured one white.
        return DEFAULT_RGBA.copy(), 0.0, texture
    diffuse = np.asarray(material.get("diffuseColor"), dtype=float)
    emissive = np.asarray(material.get("emissiveColor"), dtype=float)
    alpha = 1.0 - float(material.get("transparency"))
    return _fold_emission(diffuse, emissive, alpha), _emission(diffuse, emissive), texture


def _pbr(appearance: Node) -> tuple[np.ndarray, float, Node | None]:
    base = np.asarray(appearance.get("baseColor"), dtype=float)
    emissive = np.asarray(appearance.get("emissiveColor"), dtype=float) * float(appearance.get("emissiveIntensity"))
    alpha = 1.0 - float(appearance.get("transparency"))
    return _fold_emission(base, emissive, alpha), _emission(base, emissive), appearance.get("baseColorMap")


#: The share of direct light an unlit material takes in cameras: none to speak of. Cameras draw a
#: material's colour × k and its emission ÷ k (`world.set_ambient`), so an emission of 1 / k draws the
#: colour itself; MuJoCo has no unlit materials, and lights add k × their light (1e-4: under a level).
UNLIT_K = 1e-4


def _phong_specular(appearance: Node) -> tuple[float, float]:
    """MuJoCo's specular and shininess for a Phong Appearance: the Material's own (no Material: a dull one).

    Webots' Material has no highlight by default (specularColor 0 0 0); MuJoCo's one specular level
    is the mean of specularColor, and `shininess` carries over (both in [0, 1]).
    """
    material = appearance.get("material")
    if not isinstance(material, Node):
        return 0.0, 0.5  # unlit (see _camera_terms): no highlight either
    colour = np.asarray(material.get("specularColor"), dtype=float)
    return float(np.clip(colour.mean(), 0.0, 1.0)), float(np.clip(float(material.get("shininess")), 0.0, 1.0))


def _pbr_specular(appearance: Node) -> tuple[float, float]:
    """MuJoCo's specular and shininess for a PBRAppearance: smooth surfaces shine, metals in their own colour.

    A dielectric reflects white highlights, stronger the smoother it is: 0.5 · (1 − roughness). A metal
    reflects in its base colour (physically based shading's F0 blends from white to baseColor with
    metalness), so a black metal shows no highlight. MuJoCo's highlight is white (its level scales the
    light's specular colour), so a metal's level is its base colour's weakest channel: a white
    highlight at the mean would add red and green to a blue metal, which reflects none (Webots' blue
    metal background reads red 0 in `camera_color_motion_blur`); a grey metal keeps its level.
    """
    roughness = float(np.clip(float(appearance.get("roughness")), 0.0, 1.0))
    metalness = float(np.clip(float(appearance.get("metalness")), 0.0, 1.0))
    tint = (1 - metalness) + metalness * float(np.min(np.asarray(appearance.get("baseColor"), dtype=float)))
    return 0.5 * (1 - roughness) * tint, 1 - roughness


def unlit(node: Node) -> bool:
    """Whether Webots draws an appearance unlit: an Appearance without Material.

    Webots' Appearance documents it ("lighting is off ... the unlit object color is (1,1,1)"), and wren
    draws it with its default shader: white, or the texture's colour, whatever the lights.
    """
    return node.base_type == "Appearance" and not isinstance(node.get("material"), Node)


def _camera_terms(node: Node) -> tuple[float, float, float]:
    """(k, a, g): how Webots' shaders scale a material's linear colour: direct light, ambient, own glow.

    k scales it for direct light and a for ambient light; g is the share of the colour shown whatever the
    lights (1 unlit, else 0).

    A Phong Material reflects direct light at its colour: k = 1; an unlit appearance reflects none (k is
    `UNLIT_K`, a is 0) and shows its colour itself (g = 1, which `world.set_ambient` turns into emission).
    Webots'
    PBR shader reflects it at (1 − 0.04)·(1 − metalness)/π of its base colour (Lambert's 1/π, no π in its
    light intensities), and the Background's uniform light at (1 − 0.04)·(1 − metalness) plus, for
    metals, about their base colour again (the sky's specular reflection): a. k is floored so that a
    full metal keeps a colour for its ambient to scale (MuJoCo's emission multiplies the colour).
    """
    if unlit(node):
        return UNLIT_K, 0.0, 1.0
    if node.base_type != "PBRAppearance":
        return 1.0, 1.0, 0.0
    metalness = float(np.clip(float(node.get("metalness")), 0.0, 1.0))
    diffuse = 0.96 * (1.0 - metalness)
    return max(diffuse / math.pi, 0.01), diffuse + metalness, 0.0


def _ambient_role(node: Node) -> float | None:
    """A Phong Material's ambientIntensity; None for what the Background lights (PBR, no Material)."""
    material = node.get("material") if node.base_type == "Appearance" else None
    return float(material.get("ambientIntensity")) if isinstance(material, Node) else None


def _infrared_factor(appearance: Node) -> float:
    """How much of its red a surface shows infra-red sensors beyond its colour: Webots' PBR term 1 − 0.5·roughness."""
    if appearance.base_type != "PBRAppearance":
        return 1.0
    return 1.0 - 0.5 * float(np.clip(float(appearance.get("roughness")), 0.0, 1.0))


def _fold_emission(diffuse: np.ndarray, emissive: np.ndarray, alpha: float) -> np.ndarray:
    # MuJoCo's emission scales the rgba itself, so a glowing surface takes the brighter of its
    # diffuse and emissive colours.
    colour = np.clip(np.maximum(diffuse, emissive), 0.0, 1.0)
    return np.concatenate([colour, [min(max(alpha, 0.0), 1.0)]])


def _emission(diffuse: np.ndarray, emissive: np.ndarray) -> float:
    return float(min(1.0, emissive.max())) if emissive.max() > 0 else 0.0


def _texture_repeat(appearance: Node) -> tuple[float, float]:
    transform = appearance.get("textureTransform")
    if isinstance(transform, Node):
        scale = transform.get("scale")
        return float(scale[0]), float(scale[1])
    return 1.0, 1.0


def _material(ctx: CompileContext, rgba: np.ndarray, emission: float, specular: float, shininess: float,
              path: str | None, repeat: tuple[float, float], node: Node, texture: str | None = None) -> str:
    infrared = _infrared_factor(node)
    ambient = _ambient_role(node)
    key = repr((np.round(rgba, 4).tolist(), round(emission, 4), path, repeat, round(specular, 4), round(shininess, 4),
                round(infrared, 4), ambient)) + (f"|{texture}" if texture else "")
    name = "mat_" + hashlib.sha1(key.encode()).hexdigest()[:10]
    if ctx.spec.material(name) is not None:
        return name
    material = ctx.spec.add_material(name=name)
    material.rgba = rgba if path is None and texture is None else [1.0, 1.0, 1.0, rgba[3]]
    material.emission = emission
    material.specular = specular
    material.shininess = shininess
    material.texrepeat = list(repeat)
    material.info = info(node)
    ctx.ambient_roles[name] = ambient
    ctx.camera_terms[name] = _camera_terms(node)
    if infrared != 1.0:
        ctx.table.infrared[name] = infrared
    if texture is not None:
        material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = texture
    elif path is not None:
        material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = _texture(ctx, path)
    return name


def _texture(ctx: CompileContext, path: str) -> str:
    name = "tex_" + hashlib.sha1(path.encode()).hexdigest()[:10]
    if ctx.spec.texture(name) is not None:
        return name
    file_name = f"{name}.png"
    ctx.spec.assets[file_name] = textures.png_bytes(path)
    texture = ctx.spec.add_texture(name=name, type=mujoco.mjtTexture.mjTEXTURE_2D)
    texture.file = file_name
    ctx.texture_paths[name] = path
    return name

