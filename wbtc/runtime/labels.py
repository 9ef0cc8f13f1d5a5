"""Supervisor labels (`setLabel`) drawn over an image, as Webots draws them over its 3D view.

A label is `(text, x, y, size, 0xRRGGBB, transparency, font)`: `x`, `y` place its top-left corner
as fractions of the view's width and height, `size` is its height as a fraction of the view's.
Recordings and the viewer window draw them with the same function.

Not honoured yet: the label's `font` (PIL's default font stands in for every font).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from PIL import Image, ImageDraw, ImageFont


class LabelPainter:
    """Draws labels over RGB images, keeping the fonts it has loaded (one per pixel size)."""

    def __init__(self) -> None:
        self._fonts: dict[int, Any] = {}

    def font(self, pixels: int) -> Any:
        """The font `pixels` high."""
        font = self._fonts.get(pixels)
        if font is None:
            font = self._fonts[pixels] = ImageFont.load_default(size=pixels)
        return font

    def sprite(self, label: tuple, width: int, height: int) -> tuple[np.ndarray, int, int] | None:
        """One label alone, as RGBA rows from the top, and its top-left corner in a `width`×`height` view.

        None for an empty label.
        """
        text, x, y, size, color, transparency = label[:6]
        if not text:
            return None
        font = self.font(max(1, round(float(size) * height)))
        scratch = ImageDraw.Draw(Image.new("RGBA", (1, 1)))
        left, top, right, bottom = scratch.multiline_textbbox((0, 0), str(text), font=font)
        image = Image.new("RGBA", (max(right, 1), max(bottom, 1)), (0, 0, 0, 0))
        alpha = round(255 * (1.0 - min(max(float(transparency), 0.0), 1.0)))
        fill = ((int(color) >> 16) & 255, (int(color) >> 8) & 255, int(color) & 255, alpha)
        ImageDraw.Draw(image).multiline_text((0, 0), str(text), font=font, fill=fill)
        return np.asarray(image), round(float(x) * width), round(float(y) * height)

    def draw(self, rgb: np.ndarray, labels: dict[int, tuple]) -> np.ndarray:
        """`rgb` (rows from the top) with every label drawn over it, in id order."""
        height, width = rgb.shape[:2]
        base = Image.fromarray(rgb).convert("RGBA")
        overlay = Image.new("RGBA", base.size, (0, 0, 0, 0))
        draw = ImageDraw.Draw(overlay)
        for _, label in sorted(labels.items()):
            text, x, y, size, color, transparency = label[:6]
            if not text:
                continue
            font = self.font(max(1, round(float(size) * height)))
            alpha = round(255 * (1.0 - min(max(float(transparency), 0.0), 1.0)))
            fill = ((int(color) >> 16) & 255, (int(color) >> 8) & 255, int(color) & 255, alpha)
            draw.multiline_text((float(x) * width, float(y) * height), str(text), font=font, fill=fill)
        return np.asarray(Image.alpha_composite(base, overlay).convert("RGB"))
