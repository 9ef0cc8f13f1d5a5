"""The images of Lua-GD (`require("gd")` in a Lua template), drawn with Pillow.

Webots ships Lua-GD for Lua templates that draw a texture and write it into
`context.temporary_files_path` (Webots runs Lua templates in that folder, so a relative file name lands
there). wbtc's `gd` module (`js/lua/gd.lua`) keeps the Lua side (image objects, method calls) and calls
these host functions with an image number:

* images: `create` (palette: the first colour allocated is the background, as in GD),
  `createTrueColor` (black), `createFromPng`/`Jpeg`/`Gif`; `sizeX`/`sizeY`;
* colours: `colorAllocate[Alpha]`, `colorExact[Alpha]`, `colorResolve[Alpha]`, `colorClosest[Alpha]`
  (a palette index, or GD's packed truecolor `alpha << 24 | r << 16 | g << 8 | b` with alpha 0 opaque
  to 127 transparent), `red`/`green`/`blue`/`alpha`, `getPixel`, `setPixel`;
* drawing: `line`, `rectangle`, `filledRectangle`, `filledEllipse`, `ellipse`, `polygon`,
  `filledPolygon`, `fill` (flood fill), `copy`, `copyResized`, `copyResampled`;
* files: `png`, `jpeg`, `gif` (relative names against the template's folder).

Not honoured yet: text (`string`, `stringFT`: Webots' fonts are not shipped), brushes, tiles, styles,
line thickness, arcs and alpha blending while drawing (a drawn pixel replaces what was there).
"""

from __future__ import annotations

import os
from dataclasses import dataclass, field

from PIL import Image, ImageDraw


@dataclass
class _Picture:
    image: Image.Image  # RGBA
    palette: list[tuple[int, int, int, int]] | None = field(default=None)  # (r, g, b, gd alpha) by index


class GdHost:
    """The images of one template render and the host functions the Lua `gd` module calls."""

    def __init__(self) -> None:
        self._pictures: dict[int, _Picture] = {}
        self.folder = ""

    def reset(self, folder: str) -> None:
        """Forget every image (a new render starts) and resolve relative file names in `folder`."""
        self._pictures.clear()
        self.folder = folder

    def functions(self) -> dict[str, object]:
        """The host functions by name, for the Lua module's table."""
        names = ("create", "load", "save", "size", "allocate", "exact", "closest", "components", "get_pixel",
                 "set_pixel", "line", "rectangle", "ellipse", "polygon", "fill", "copy", "destroy")
        return {name: getattr(self, name) for name in names}

    # ---------------------------------------------------------------------------------- images
    def create(self, width: int, height: int, truecolor: bool) -> int | None:
        """A new image (`gd.create` when not `truecolor`, `gd.createTrueColor`); None for an empty size."""
        if width <= 0 or height <= 0:
            return None
        picture = _Picture(Image.new("RGBA", (int(width), int(height)), (0, 0, 0, 255)), None if truecolor else [])
        return self._keep(picture)

    def load(self, path: str) -> int | None:
        """An image read from a PNG, JPEG or GIF file; None when it cannot be read, as Lua-GD."""
        try:
            with Image.open(self._path(path)) as image:
                return self._keep(_Picture(image.convert("RGBA")))
        except OSError:
            return None  # Lua-GD returns nil for a missing or unreadable file

    def save(self, number: int, path: str, kind: str, quality: int) -> bool:
        """Write the image as `kind` (png, jpeg or gif); False when the file cannot be written."""
        image = self._pictures[number].image
        try:
            if kind == "jpeg":
                image.convert("RGB").save(self._path(path), "JPEG", quality=quality if quality > 0 else 75)
            else:
                image.save(self._path(path), kind.upper())
        except OSError:
            return False
        return True

    def size(self, number: int) -> tuple[int, int]:
        """(width, height)."""
        return self._pictures[number].image.size

    def destroy(self, number: int) -> None:
        """Forget an image (`im:destroy()`)."""
        self._pictures.pop(number, None)

    # ---------------------------------------------------------------------------------- colours
    def allocate(self, number: int, r: int, g: int, b: int, a: int, reuse: bool) -> int:
        """A colour: a new palette entry (or the exact one when `reuse`), or the packed truecolor."""
        picture = self._pictures[number]
        rgba = (int(r) & 255, int(g) & 255, int(b) & 255, min(max(int(a), 0), 127))
        if picture.palette is None:
            return rgba[3] << 24 | rgba[0] << 16 | rgba[1] << 8 | rgba[2]
        if reuse and rgba in picture.palette:
            return picture.palette.index(rgba)
        if len(picture.palette) >= 256:
            return -1
        picture.palette.append(rgba)
        if len(picture.palette) == 1:
            # GD's palette image starts as index 0 everywhere: the first colour is the background.
            picture.image.paste(self._fill(picture, 0), (0, 0, *picture.image.size))
        return len(picture.palette) - 1

    def exact(self, number: int, r: int, g: int, b: int, a: int) -> int:
        """The palette index of exactly this colour, or -1 (a truecolor image packs it)."""
        picture = self._pictures[number]
        if picture.palette is None:
            return self.allocate(number, r, g, b, a, False)
        rgba = (int(r), int(g), int(b), int(a))
        return picture.palette.index(rgba) if rgba in picture.palette else -1

    def closest(self, number: int, r: int, g: int, b: int, a: int) -> int:
        """The palette index of the nearest colour, or -1 for an empty palette (a truecolor image packs it)."""
        picture = self._pictures[number]
        if picture.palette is None:
            return self.allocate(number, r, g, b, a, False)
        if not picture.palette:
            return -1
        distances = [(pr - r) ** 2 + (pg - g) ** 2 + (pb - b) ** 2 + (pa - a) ** 2
                     for pr, pg, pb, pa in picture.palette]
        return distances.index(min(distances))

    def components(self, number: int, color: int) -> tuple[int, int, int, int]:
        """(r, g, b, gd alpha) of a colour of the image."""
        return _components(self._pictures[number], int(color))

    def get_pixel(self, number: int, x: int, y: int) -> int:
        """The colour of a pixel (0 outside the image), as a palette index or packed truecolor."""
        picture = self._pictures[number]
        width, height = picture.image.size
        if not (0 <= x < width and 0 <= y < height):
            return 0
        r, g, b, a = picture.image.getpixel((int(x), int(y)))
        alpha = (255 - a) // 2
        if picture.palette is not None:
            return self.closest(number, r, g, b, alpha)
        return alpha << 24 | r << 16 | g << 8 | b

    def set_pixel(self, number: int, x: int, y: int, color: int) -> None:
        """Paint one pixel (nothing outside the image)."""
        picture = self._pictures[number]
        width, height = picture.image.size
        if 0 <= x < width and 0 <= y < height:
            picture.image.putpixel((int(x), int(y)), self._fill(picture, color))

    # ---------------------------------------------------------------------------------- drawing
    def line(self, number: int, x1: int, y1: int, x2: int, y2: int, color: int) -> None:
        """A one-pixel line between two pixels, both included."""
        picture = self._pictures[number]
        ImageDraw.Draw(picture.image).line([(x1, y1), (x2, y2)], fill=self._fill(picture, color))

    def rectangle(self, number: int, x1: int, y1: int, x2: int, y2: int, color: int, filled: bool) -> None:
        """A rectangle's outline, or the whole of it when `filled`."""
        picture = self._pictures[number]
        box = [(min(x1, x2), min(y1, y2)), (max(x1, x2), max(y1, y2))]  # GD's corners are both inside
        colour = self._fill(picture, color)
        ImageDraw.Draw(picture.image).rectangle(box, fill=colour if filled else None, outline=colour)

    def ellipse(self, number: int, cx: int, cy: int, width: int, height: int, color: int, filled: bool) -> None:
        """An ellipse of the given width and height about a centre, its outline or the whole of it."""
        picture = self._pictures[number]
        box = [(cx - width / 2, cy - height / 2), (cx + width / 2, cy + height / 2)]
        colour = self._fill(picture, color)
        ImageDraw.Draw(picture.image).ellipse(box, fill=colour if filled else None, outline=colour)

    def polygon(self, number: int, color: int, filled: bool, *points: int) -> None:
        """A polygon through the corners (x1, y1, x2, y2, ...), its outline or the whole of it."""
        picture = self._pictures[number]
        corners = list(zip(points[0::2], points[1::2], strict=False))
        colour = self._fill(picture, color)
        ImageDraw.Draw(picture.image).polygon(corners, fill=colour if filled else None, outline=colour)

    def fill(self, number: int, x: int, y: int, color: int) -> None:
        """Flood fill from a pixel: the region of its colour takes the new one."""
        picture = self._pictures[number]
        width, height = picture.image.size
        if 0 <= x < width and 0 <= y < height:
            ImageDraw.floodfill(picture.image, (int(x), int(y)), self._fill(picture, color))

    def copy(self, target: int, source: int, *box_and_resample: int | bool) -> None:
        """Copy the source rectangle (sx, sy, sw, sh) to the target's (dx, dy, dw, dh), scaled when they differ.

        The arguments after the images: dx, dy, sx, sy, dw, dh, sw, sh, then whether to resample.
        """
        *box, resample = box_and_resample
        dx, dy, sx, sy, dw, dh, sw, sh = (int(v) for v in box)
        if sw <= 0 or sh <= 0 or dw <= 0 or dh <= 0:
            return
        piece = self._pictures[source].image.crop((sx, sy, sx + sw, sy + sh))
        if (dw, dh) != (sw, sh):
            piece = piece.resize((dw, dh), Image.Resampling.BILINEAR if resample else Image.Resampling.NEAREST)
        self._pictures[target].image.paste(piece, (dx, dy))

    # ---------------------------------------------------------------------------------- helpers
    def _keep(self, picture: _Picture) -> int:
        number = max(self._pictures, default=0) + 1
        self._pictures[number] = picture
        return number

    def _fill(self, picture: _Picture, color: int) -> tuple[int, int, int, int]:
        r, g, b, alpha = _components(picture, int(color))
        # GD's alpha runs from 0 (opaque) to 127 (transparent).
        return r, g, b, 255 - round(alpha * 255 / 127)

    def _path(self, path: str) -> str:
        return path if os.path.isabs(path) or not self.folder else os.path.join(self.folder, path)


def _components(picture: _Picture, color: int) -> tuple[int, int, int, int]:
    if picture.palette is not None:
        return picture.palette[color] if 0 <= color < len(picture.palette) else (0, 0, 0, 0)
    return color >> 16 & 255, color >> 8 & 255, color & 255, color >> 24 & 127
