"""``Display``: a 2D drawing surface; drawing commands reach the simulator at the next step."""

from __future__ import annotations

import itertools
import os

from . import _session
from .device import Device, checked

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

_handles = itertools.count(1)


class Display(Device):
    """A Display node; every call is sent as ``(tag, method name, *args)``; image handles are ints."""

    RGB = 3
    RGBA = 4
    ARGB = 5
    BGRA = 6
    ABGR = 7
    _C = "wb_display"
    _TYPES = ("Display",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    def _draw(self, op: str, *args: Any) -> None:
        if self._s is None:
            _session.error(f"Error: wb_display_{op}(): invalid device tag.")
            return
        self._queue(op, *args)

    def attachCamera(self, camera: Any) -> None:
        """Show a camera's images on the display."""
        self._draw("attachCamera", camera._tag)

    def detachCamera(self) -> None:
        """Stop showing the attached camera."""
        self._draw("detachCamera")

    def drawLine(self, x1: int, y1: int, x2: int, y2: int) -> None:
        """Draw a line."""
        self._draw("drawLine", int(x1), int(y1), int(x2), int(y2))

    def drawOval(self, cx: int, cy: int, a: int, b: int) -> None:
        """Draw an ellipse outline."""
        self._draw("drawOval", int(cx), int(cy), int(a), int(b))

    def drawPixel(self, x: int, y: int) -> None:
        """Draw one pixel."""
        self._draw("drawPixel", int(x), int(y))

    def drawPolygon(self, x: list[int], y: list[int]) -> None:
        """Draw a polygon outline."""
        n = min(len(x), len(y))
        self._draw("drawPolygon", [int(v) for v in x[:n]], [int(v) for v in y[:n]])

    def drawRectangle(self, x: int, y: int, width: int, height: int) -> None:
        """Draw a rectangle outline."""
        self._draw("drawRectangle", int(x), int(y), int(width), int(height))

    def drawText(self, text: str, x: int, y: int) -> None:
        """Draw text with its top-left corner at (x, y)."""
        self._draw("drawText", str(text), int(x), int(y))

    def fillOval(self, cx: int, cy: int, a: int, b: int) -> None:
        """Draw a filled ellipse."""
        self._draw("fillOval", int(cx), int(cy), int(a), int(b))

    def fillPolygon(self, x: list[int], y: list[int]) -> None:
        """Draw a filled polygon."""
        n = min(len(x), len(y))
        self._draw("fillPolygon", [int(v) for v in x[:n]], [int(v) for v in y[:n]])

    def fillRectangle(self, x: int, y: int, width: int, height: int) -> None:
        """Draw a filled rectangle."""
        self._draw("fillRectangle", int(x), int(y), int(width), int(height))

    def setAlpha(self, alpha: float) -> None:
        """Set the drawing alpha in [0, 1]."""
        self._draw("setAlpha", float(alpha))

    def setColor(self, color: int) -> None:
        """Set the drawing colour (0xRRGGBB)."""
        self._draw("setColor", int(color))

    def setFont(self, font: str, size: int, anti_aliasing: bool) -> None:
        """Set the text font."""
        self._draw("setFont", str(font), int(size), bool(anti_aliasing))

    def setOpacity(self, opacity: float) -> None:
        """Set the drawing opacity in [0, 1]."""
        self._draw("setOpacity", float(opacity))

    def imageNew(self, data: Any, format: int, width: int, height: int) -> int:
        """Create an image from pixel bytes in one of the RGB/RGBA/ARGB/BGRA/ABGR formats; returns its handle."""
        handle = next(_handles)
        self._draw("imageNew", handle, bytes(data), int(format), int(width), int(height))
        return handle

    def imageCopy(self, x: int, y: int, width: int, height: int) -> int:
        """Copy a region of the display into a new image; returns its handle."""
        handle = next(_handles)
        self._draw("imageCopy", handle, int(x), int(y), int(width), int(height))
        return handle

    def imageLoad(self, filename: str) -> int:
        """Load an image file (path relative to the controller's directory); returns its handle."""
        handle = next(_handles)
        self._draw("imageLoad", handle, os.path.abspath(filename))
        return handle

    def imagePaste(self, image: int, x: int, y: int, blend: bool) -> None:
        """Paste an image at (x, y)."""
        self._draw("imagePaste", int(image), int(x), int(y), bool(blend))

    def imageSave(self, image: int | None, filename: str) -> None:
        """Save an image (None: the whole display) to a file."""
        self._draw("imageSave", None if image is None else int(image), os.path.abspath(filename))

    def imageDelete(self, image: int) -> None:
        """Forget an image."""
        self._draw("imageDelete", int(image))

    @checked("get_width", 0)
    def getWidth(self) -> int:
        """Display width (pixels)."""
        return int(self._s.field("width", 64))

    @checked("get_height", 0)
    def getHeight(self) -> int:
        """Display height (pixels)."""
        return int(self._s.field("height", 64))

    alpha = property(fset=setAlpha, doc="Write-only: the drawing alpha.")
    color = property(fset=setColor, doc="Write-only: the drawing colour.")
    opacity = property(fset=setOpacity, doc="Write-only: the drawing opacity.")
    width = property(getWidth, doc="Display width.")
    height = property(getHeight, doc="Display height.")
