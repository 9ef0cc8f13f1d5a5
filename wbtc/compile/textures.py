"""Webots texture files and URLs for MuJoCo: resolving, reading, converting to PNG, average colour.

What it maps:

* `ImageTexture.url` (and any other MFString url field, e.g. Mesh) -> a local file: `resolve_url`.
  Relative URLs resolve against the folder of the file the node was written in (the world, or the
  PROTO for nodes a PROTO made); absolute paths are taken as they are; `webots://` and `http(s)://`
  URLs through `wbtc.compile.remote` (a Webots installation, wbtc's asset cache, or a download).
* Image files -> `TextureData` (8-bit RGB rows, top row first, plus whether the image is
  transparent) through Pillow: JPEG and PNG as in Webots, and whatever else Pillow reads.
* Image files -> PNG copies for MJCF output (`texture_to_png`): MuJoCo reads PNG textures only.
* `TextureTransform` -> transformed texture coordinates of meshes (`apply_texture_transform`), since
  MuJoCo has no texture transform of its own.

Not honoured yet:

* ImageTexture `repeatS`/`repeatT` FALSE (MuJoCo always repeats: a clamped texture's coordinates
  outside [0, 1] show it again instead of its edge texels) and `filtering` (rendering only).
* Image orientation metadata (EXIF): ignored, as Webots' Qt image reader ignores it.
"""

from __future__ import annotations

import hashlib
import io
import math
import os
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from wbtc.compile import remote

#: Lists that collect every path `resolve_url` looks at, found or not (`wbtc.world_cache` watches
#: what a world's result depends on this way).
LOOKED_AT: list[list[str]] = []


def resolve_url(urls: list[str], base_file: str) -> str | None:
    """The first URL of a Webots url field that names an existing local file.

    Args:
        urls: the url field's entries, in order.
        base_file: the file the node was written in (its folder anchors relative URLs).

    Returns:
        The file's path (normalised, absolute when `base_file` is), or None when no entry names a
        file that exists, is installed, cached or can be downloaded (`wbtc.compile.remote`).
    """
    folder = os.path.dirname(base_file)
    for url in urls:
        if not url:
            continue
        if remote.is_remote(url):
            found = remote.local_copy(url, LOOKED_AT)
            if found is not None:
                return found
            continue
        path = url if os.path.isabs(url) else os.path.join(folder, url)
        path = os.path.normpath(path)
        for watcher in LOOKED_AT:
            watcher.append(path)
        if os.path.isfile(path):
            return path
    return None


@dataclass(frozen=True)
class TextureData:
    """A decoded image.

    Attributes:
        width: pixels per row.
        height: rows.
        rgb: (height, width, 3) uint8, row 0 is the top row of the image (read-only array).
        alpha: the image has an alpha channel (or a transparent palette entry) and at least one
            pixel that is not fully opaque.
        alpha_values: (height, width) uint8 opacities when `alpha` is True, else None.
    """

    width: int
    height: int
    rgb: np.ndarray
    alpha: bool
    alpha_values: np.ndarray | None = None


#: Decoded images: (absolute path, mtime_ns, size) -> texture.
_TEXTURE_CACHE: dict[tuple[str, int, int], TextureData] = {}


def _key(path: str) -> tuple[str, int, int]:
    absolute = os.path.abspath(path)
    stat = os.stat(absolute)
    return absolute, stat.st_mtime_ns, stat.st_size


def load_texture(path: str) -> TextureData:
    """Read an image file into 8-bit RGB, cached by (path, modification time).

    Args:
        path: the image file.

    Returns:
        The decoded image (its arrays are shared with the cache and read-only).

    Raises:
        OSError: the file cannot be read or is not an image Pillow knows.
    """
    key = _key(path)
    cached = _TEXTURE_CACHE.get(key)
    if cached is not None:
        return cached
    from PIL import Image

    with Image.open(key[0]) as image:
        image.load()
        if image.mode.startswith("I;16") or image.mode in ("I", "F"):
            # 16-bit and float greyscale: scale to 8 bits (Pillow's own conversion would clip).
            values = np.asarray(image, dtype=np.float64)
            top = 65535.0 if image.mode != "F" else max(float(values.max()), 1.0)
            image = Image.fromarray(np.clip(values / top * 255.0 + 0.5, 0, 255).astype(np.uint8), "L")
        has_alpha_channel = image.mode in ("RGBA", "LA", "PA", "La", "RGBa") or "transparency" in image.info
        alpha_values = None
        if has_alpha_channel:
            rgba = np.asarray(image.convert("RGBA"))
            rgb = np.ascontiguousarray(rgba[:, :, :3])
            if (rgba[:, :, 3] < 255).any():
                alpha_values = np.ascontiguousarray(rgba[:, :, 3])
        else:
            rgb = np.ascontiguousarray(np.asarray(image.convert("RGB")))
    rgb.setflags(write=False)
    if alpha_values is not None:
        alpha_values.setflags(write=False)
    texture = TextureData(width=rgb.shape[1], height=rgb.shape[0], rgb=rgb, alpha=alpha_values is not None,
                          alpha_values=alpha_values)
    _TEXTURE_CACHE[key] = texture
    return texture


def clear_texture_cache() -> None:
    """Forget every decoded image."""
    _TEXTURE_CACHE.clear()


def texture_to_png(path: str, out_dir: str) -> str:
    """Write a PNG copy of an image for MJCF output (MuJoCo reads PNG textures only).

    The name is the source's name followed by a digest of its bytes, so the same image always gets
    the same name and two different images with the same name do not collide. An existing copy is
    not rewritten. Transparent images are written as RGBA, the others as RGB.

    Args:
        path: the source image (any format Pillow reads).
        out_dir: the folder to write into (created if needed).

    Returns:
        The PNG's file name (relative to `out_dir`).
    """
    with open(path, "rb") as source:
        digest = hashlib.sha256(source.read()).hexdigest()[:12]
    stem = re.sub(r"[^A-Za-z0-9_.-]+", "_", os.path.splitext(os.path.basename(path))[0]) or "texture"
    name = f"{stem}-{digest}.png"
    target = os.path.join(out_dir, name)
    if not os.path.exists(target):
        os.makedirs(out_dir, exist_ok=True)
        partial = f"{target}.{os.getpid()}.tmp"
        with open(partial, "wb") as out:
            out.write(png_bytes(path))
        os.replace(partial, target)  # no half-written file under the final name
    return name


def png_bytes(path: str) -> bytes:
    """The image at `path` as PNG bytes (MuJoCo reads PNG textures only): RGBA if transparent, else RGB."""
    from PIL import Image

    texture = load_texture(path)
    if texture.alpha and texture.alpha_values is not None:
        image = Image.fromarray(np.dstack([texture.rgb, texture.alpha_values]), "RGBA")
    else:
        image = Image.fromarray(texture.rgb, "RGB")
    buffer = io.BytesIO()
    image.save(buffer, format="PNG")
    return buffer.getvalue()


def mean_color(path: str) -> tuple[float, float, float]:
    """The average colour of an image, for cheap colour estimates.

    Transparent images are averaged with each pixel weighted by its opacity (fully transparent pixels
    do not count); a fully transparent image gives the plain average.

    Args:
        path: the image file.

    Returns:
        (r, g, b), each in [0, 1].
    """
    texture = load_texture(path)
    rgb = texture.rgb.reshape(-1, 3).astype(np.float64)
    if texture.alpha_values is not None and texture.alpha_values.any():
        weights = texture.alpha_values.reshape(-1).astype(np.float64)
        mean = (rgb * weights[:, None]).sum(axis=0) / weights.sum()
    else:
        mean = rgb.mean(axis=0)
    red, green, blue = (float(value) / 255.0 for value in mean)
    return red, green, blue


def apply_texture_transform(texcoords: np.ndarray, transform: Any) -> np.ndarray:
    """Apply a TextureTransform node to texture coordinates.

    X3D's rule, which Webots' renderer follows: Tc' = -C x S x R x C x T x Tc, i.e. translate by
    `translation`, then by `center`, rotate by `rotation` (radians, counter-clockwise), scale by
    `scale`, and translate back by -`center`. Coordinates are in the VRML convention (t upwards);
    Webots works on flipped rows internally, which gives the same result.

    Args:
        texcoords: (n, 2) texture coordinates.
        transform: the TextureTransform node, or None (coordinates returned unchanged).

    Returns:
        The transformed (n, 2) coordinates, float32.
    """
    coords = np.asarray(texcoords, dtype=np.float64).reshape(-1, 2)
    if transform is None:
        return coords.astype(np.float32)

    def vec2(name: str, default: tuple[float, float]) -> np.ndarray:
        value = transform.get(name)
        return np.asarray(default if value is None else tuple(value), dtype=np.float64)

    center = vec2("center", (0.0, 0.0))
    scale = vec2("scale", (1.0, 1.0))
    translation = vec2("translation", (0.0, 0.0))
    angle = float(transform.get("rotation") or 0.0)
    cos, sin = math.cos(angle), math.sin(angle)
    rotation = np.array([[cos, -sin], [sin, cos]])
    moved = coords + translation + center
    result = (moved @ rotation.T) * scale - center
    return result.astype(np.float32)
