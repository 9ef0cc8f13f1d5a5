"""A Display's pixels and Webots' drawing rules: colour, alpha and opacity, lines, rectangles, ovals, polygons.

The image is an (height, width, 4) RGBA array, row 0 at the top, that starts opaque black as Webots'
does. Every drawn pixel goes "over" what is there with the drawing opacity: each colour channel
becomes ((255 − opacity) · old + opacity · colour) // 255 and the alpha channel the same with the
drawing alpha, integer arithmetic as in Webots, so values match its pixels exactly. Lines are
Bresenham's; ovals are the integer midpoint ellipse, a filled oval being a horizontal line per row at
the widest span the walk first reaches on that row; polygons are filled by even-odd scanlines with
their horizontal edges drawn as well. Everything is clipped to the display.

Not honoured yet: text is drawn with Pillow's built-in bitmap font at any `setFont` size (Webots
renders the named TrueType font, "Lucida Console" 8 by default, with anti-aliasing).
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np


class Raster:
    """One Display's image and drawing state (colour 0xRRGGBB, alpha, opacity)."""

    def __init__(self, width: int, height: int) -> None:
        self.width, self.height = max(int(width), 0), max(int(height), 0)
        self.pixels = np.zeros((self.height, self.width, 4), dtype=np.uint8)
        self.pixels[..., 3] = 255  # opaque black
        self.color = 0xFFFFFF
        self.alpha = 255
        self.opacity = 255

    def rgb(self) -> tuple[int, int, int]:
        """The drawing colour's red, green and blue bytes."""
        return (self.color >> 16) & 0xFF, (self.color >> 8) & 0xFF, self.color & 0xFF

    def paint(self, rows: np.ndarray | slice | int, cols: np.ndarray | slice | int) -> None:
        """Draw the drawing colour over the pixels at (rows, cols) (numpy indices, already clipped)."""
        region = self.pixels[rows, cols]
        if self.opacity == 255:
            region[...] = (*self.rgb(), self.alpha)
        else:
            keep, put = 255 - self.opacity, self.opacity
            source = np.array([*self.rgb(), self.alpha], dtype=np.int32)
            region[...] = ((keep * region.astype(np.int32) + put * source) // 255).astype(np.uint8)
        self.pixels[rows, cols] = region

    def pixel(self, x: int, y: int) -> None:
        """Draw one pixel (nothing outside the display)."""
        if 0 <= x < self.width and 0 <= y < self.height:
            self.paint(y, x)

    def line(self, x0: int, y0: int, x1: int, y1: int) -> None:
        """Bresenham's line from (x0, y0) to (x1, y1), both ends drawn."""
        if max(x0, x1) < 0 or max(y0, y1) < 0 or min(x0, x1) >= self.width or min(y0, y1) >= self.height:
            return
        for x, y in _line_points(x0, y0, x1, y1):
            self.pixel(x, y)

    def rectangle(self, x: int, y: int, w: int, h: int, fill: bool) -> None:
        """A w x h rectangle with its top-left corner at (x, y): filled, or its one-pixel frame."""
        if fill:
            x0, y0, x1, y1 = max(x, 0), max(y, 0), min(x + w, self.width), min(y + h, self.height)
            if x1 <= x0 or y1 <= y0:
                return
            if self.opacity == 255 and self.alpha == 0:
                self.pixels[y0:y1, x0:x1] = 0  # Webots clears the area to transparent black
            else:
                self.paint(slice(y0, y1), slice(x0, x1))
            return
        right, bottom = x + w - 1, y + h - 1
        for i in range(max(x, 0), min(right + 1, self.width)):
            self.pixel(i, y)
            if bottom != y:
                self.pixel(i, bottom)
        for j in range(max(y + 1, 0), min(bottom, self.height)):
            self.pixel(x, j)
            if right != x:
                self.pixel(right, j)

    def oval(self, cx: int, cy: int, a: int, b: int, fill: bool) -> None:
        """An ellipse of radii a (x) and b (y) centred on (cx, cy): filled, or its outline."""
        if a < 1 or b < 1 or cx + a < 0 or cx - a >= self.width or cy + b < 0 or cy - b >= self.height:
            return
        if fill:
            for dy, half in _oval_spans(a, b):
                self.line(cx - half, cy + dy, cx + half, cy + dy)
                if dy:
                    self.line(cx - half, cy - dy, cx + half, cy - dy)
            return
        # Each pixel once: a second pass would blend it twice under an opacity below 1.
        points = {(cx + sx * dx, cy + sy * dy) for dx, dy in _oval_outline(a, b) for sx in (-1, 1) for sy in (-1, 1)}
        for x, y in sorted(points):
            self.pixel(x, y)

    def polygon(self, xs: list[int], ys: list[int], fill: bool) -> None:
        """A polygon through the points (xs[i], ys[i]): filled by scanlines, or its crossings and flat edges."""
        n = min(len(xs), len(ys))
        if n == 0 or min(xs[:n]) >= self.width or min(ys[:n]) >= self.height or max(xs[:n]) < 0 or max(ys[:n]) < 0:
            return
        flat: list[tuple[int, int, int]] = []
        for row in range(max(0, min(ys[:n])), min(self.height - 1, max(ys[:n])) + 1):
            crossings = []
            for i in range(n):
                j = i - 1 if i else n - 1
                if (ys[i] < row <= ys[j]) or (ys[j] < row <= ys[i]):
                    # Integer division truncating towards zero, as C's.
                    step = (row - ys[i]) * (xs[j] - xs[i])
                    crossings.append(xs[i] + int(step / (ys[j] - ys[i])))
                elif ys[i] == row == ys[j]:
                    flat.append((row, min(xs[i], xs[j]), max(xs[i], xs[j])))
            crossings.sort()
            for k in range(2, len(crossings), 2):  # a pair that touches moves its start one pixel right
                if crossings[k - 1] == crossings[k]:
                    crossings[k] += 1
            for k in range(0, len(crossings) - 1, 2):
                left, right = crossings[k], crossings[k + 1]
                if fill:
                    self.rectangle(left, row, right - left + 1, 1, True)
                else:
                    self.pixel(left, row)
                    if right != left:
                        self.pixel(right, row)
        for row, left, right in flat:
            for x in range(left, right + 1):
                self.pixel(x, row)

    def copy(self, x: int, y: int, w: int, h: int) -> np.ndarray | None:
        """The pixels of a region, clipped to the display (None when nothing of it is on the display)."""
        x0, y0 = max(x, 0), max(y, 0)
        w, h = min(self.width - x0, w - (x0 - x)), min(self.height - y0, h - (y0 - y))
        if x0 >= self.width or y0 >= self.height or w < 1 or h < 1:
            return None
        return self.pixels[y0:y0 + h, x0:x0 + w].copy()

    def paste(self, image: np.ndarray, x: int, y: int, blend: bool) -> None:
        """Put an RGBA image with its top-left corner at (x, y); `blend` mixes it by its alpha."""
        height, width = image.shape[:2]
        x0, y0 = max(x, 0), max(y, 0)
        w, h = min(self.width - x0, width - (x0 - x)), min(self.height - y0, height - (y0 - y))
        if x0 >= self.width or y0 >= self.height or w < 1 or h < 1:
            return
        source = image[y0 - y:y0 - y + h, x0 - x:x0 - x + w]
        target = self.pixels[y0:y0 + h, x0:x0 + w]
        if not blend:
            target[...] = source
            return
        new_alpha = source[..., 3:4].astype(np.int32)
        mixed = ((255 - new_alpha) * target[..., :3].astype(np.int32) + new_alpha * source[..., :3]) // 255
        alpha = np.minimum(255, new_alpha[..., 0] + target[..., 3].astype(np.int32))
        target[..., :3], target[..., 3] = mixed.astype(np.uint8), alpha.astype(np.uint8)

    def text(self, text: str, x: int, y: int, size: int) -> None:
        """Draw text with its top-left corner at (x, y) (see the module docstring for the font)."""
        if x >= self.width or y >= self.height or not text:
            return
        from PIL import Image, ImageDraw, ImageFont

        font = ImageFont.load_default(size=max(int(size), 1)) if size else ImageFont.load_default()
        lines = text.split("\n")
        step = max(int(size), 8) + 2
        mask = Image.new("L", (self.width, self.height), 0)
        draw = ImageDraw.Draw(mask)
        for index, line in enumerate(lines):
            draw.text((x, y + index * step), line, fill=255, font=font)
        coverage = np.asarray(mask, dtype=np.int32)
        rows, cols = np.nonzero(coverage)
        saved = self.opacity
        for level in np.unique(coverage[rows, cols]):
            chosen = coverage[rows, cols] == level
            self.opacity = saved * int(level) // 255
            self.paint(rows[chosen], cols[chosen])
        self.opacity = saved


def _line_points(x0: int, y0: int, x1: int, y1: int) -> Iterator[tuple[int, int]]:
    """The pixels of Bresenham's line; the error term steps the minor axis once it reaches zero."""
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx, sy = (1 if x1 >= x0 else -1), (1 if y1 >= y0 else -1)
    yield x0, y0
    if dx > dy:
        error = 2 * dy - dx
        while x0 != x1:
            if error >= 0:
                y0 += sy
                error -= 2 * dx
            x0 += sx
            error += 2 * dy
            yield x0, y0
    else:
        error = 2 * dx - dy
        while y0 != y1:
            if error >= 0:
                x0 += sx
                error -= 2 * dy
            y0 += sy
            error += 2 * dx
            yield x0, y0


def _oval_walk(a: int, b: int) -> Iterator[tuple[int, int]]:
    """The midpoint ellipse walk from (a, 0) to (0, b): (half-width, row offset) after each move."""
    aa, bb = 2 * a * a, 2 * b * b
    error = a * b * b  # positive: move a row up; then, not positive: move a column in
    column_step, row_step = 2 * error, 0
    dx, dy = a, 0
    while dx > 0:
        if error > 0:
            dy += 1
            row_step += aa
            error -= row_step
        if error <= 0:
            dx -= 1
            column_step -= bb
            error += column_step
        yield dx, dy


def _oval_spans(a: int, b: int) -> list[tuple[int, int]]:
    """(row offset, half-width) of a filled oval: each row at the first (widest) span the walk reaches."""
    spans = {0: a}
    for dx, dy in _oval_walk(a, b):
        spans.setdefault(dy, dx)
    return sorted(spans.items())


def _oval_outline(a: int, b: int) -> list[tuple[int, int]]:
    """(half-width, row offset) of every outline pixel pair of an oval."""
    return [(a, 0), *_oval_walk(a, b)]
