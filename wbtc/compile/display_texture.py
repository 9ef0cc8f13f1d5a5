"""The textures a Display draws on: found as Webots finds them, made as MuJoCo textures the runtime rewrites.

Webots shows a Display's image on the ImageTexture of the Display's first child when that child is a
Shape (an Appearance's `texture`, or a PBRAppearance's `baseColorMap` and `emissiveColorMap`), or on
those of every Shape found below it when the first child is a Group (Pose, Transform ...). Each such
ImageTexture gets a texture of its own here, at the display's size: its own image (resampled) when
its url can be read, else plain white, which is what the shape shows before the controller's first
drawing. The runtime (`runtime.display`) writes the display's image into these textures. They are
RGBA (opaque to start with): where the display is transparent, what is behind it shows, as in Webots.

Not honoured yet: a Display's textures keep MuJoCo's repeat and filtering (Webots' `filtering` field).
"""

from __future__ import annotations

import hashlib

import mujoco
import numpy as np

from wbtc.compile import textures
from wbtc.compile.context import CompileContext
from wbtc.compile.table import DeviceEntry
from wbtc.scene.model import Node

_GROUPS = frozenset({"Group", "Pose", "Transform"})


def register(node: Node, entry: DeviceEntry, ctx: CompileContext) -> None:
    """Remember which ImageTextures show the Display `node` (before its children are compiled)."""
    for texture in image_textures(node):
        ctx.display_textures[id(texture)] = entry


def image_textures(display: Node) -> list[Node]:
    """The ImageTexture nodes a Display draws on, in Webots' order."""
    children = [c for c in display.get("children") or [] if isinstance(c, Node)]
    if not children:
        return []
    first = children[0]
    if first.base_type == "Shape":
        return _shape_textures(first)
    if first.base_type in _GROUPS:
        return _group_textures(first)
    return []


def _group_textures(group: Node) -> list[Node]:
    found: list[Node] = []
    for child in group.get("children") or []:
        if not isinstance(child, Node):
            continue
        if child.base_type == "Shape":
            found += _shape_textures(child)
        elif child.base_type in _GROUPS:
            found += _group_textures(child)
    return found


def _shape_textures(shape: Node) -> list[Node]:
    look = shape.get("appearance")
    if not isinstance(look, Node):
        return []
    names = ("baseColorMap", "emissiveColorMap") if look.base_type == "PBRAppearance" else ("texture",)
    return [t for t in (look.get(n) for n in names) if isinstance(t, Node) and t.base_type == "ImageTexture"]


def display_texture(ctx: CompileContext, texture: Node, path: str | None) -> str | None:
    """The MuJoCo texture (made once) for an ImageTexture a Display draws on; None for other textures.

    Args:
        ctx: the compile context.
        texture: the ImageTexture node.
        path: its image file, when its url resolved.
    """
    entry = ctx.display_textures.get(id(texture))
    if not isinstance(entry, DeviceEntry):
        return None
    name = "display_" + hashlib.sha1(f"{entry.site}/{id(texture)}".encode()).hexdigest()[:10]
    if ctx.spec.texture(name) is not None:
        return name
    width, height = max(int(entry.fields.get("width", 64)), 1), max(int(entry.fields.get("height", 64)), 1)
    made = ctx.spec.add_texture(name=name, type=mujoco.mjtTexture.mjTEXTURE_2D)
    # Four channels: the display's alpha goes to the renderer (runtime.display turns blending on).
    made.width, made.height, made.nchannel = width, height, 4
    rgb = _initial_pixels(path, width, height)
    made.data = np.concatenate([rgb, np.full((height, width, 1), 255, np.uint8)], axis=2).tobytes()
    entry.textures.append(name)
    return name


def _initial_pixels(path: str | None, width: int, height: int) -> np.ndarray:
    """The texture's own image at the display's size (nearest pixel), else white; RGB rows from the top."""
    if path is not None:
        try:
            image = textures.load_texture(path)
            pixels = image.rgb
            rows = (np.arange(height) * pixels.shape[0]) // height
            cols = (np.arange(width) * pixels.shape[1]) // width
            return np.ascontiguousarray(pixels[rows][:, cols])
        except OSError:  # unreadable: the shape shows white until the first drawing
            pass
    return np.full((height, width, 3), 255, dtype=np.uint8)
