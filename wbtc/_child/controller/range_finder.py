"""``RangeFinder``: depth images (m), width × height floats."""

from __future__ import annotations

import math
from array import array

from . import _images, _session
from .device import checked
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class RangeFinder(Sensor):
    """A RangeFinder node; ``getRangeImage()`` is row-major, ``inf`` where nothing is in range."""

    _C = "wb_range_finder"
    _TYPES = ("RangeFinder",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.width = int(state.field("width", 64))
        state.height = int(state.field("height", 64))
        state.value = array("f", [NAN]) * (state.width * state.height)

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        if isinstance(value, dict) and value.get("ranges") is None:
            raw = _images.image_bytes(value, 4 * state.width * state.height)
            if raw is not None:
                state.value = array("f", raw)
            return
        ranges = value.get("ranges") if isinstance(value, dict) else value
        state.value = array("f", ranges)

    @checked("get_range_image")
    def getRangeImage(self, data_type: str = "list") -> Any:
        """The depths as a list (``data_type='list'``) or as an ``array('f')`` buffer otherwise."""
        image = self._sampled("get_range_image").value
        return image.tolist() if data_type == "list" else array("f", image)

    def getRangeImageArray(self) -> list[list[float]] | None:
        """The depths as ``height`` rows of ``width`` floats."""
        image = self.getRangeImage()
        if image is None:
            return None
        width = self.getWidth()
        return [image[i * width:(i + 1) * width] for i in range(self.getHeight())]

    @staticmethod
    def rangeImageGetDepth(image: Any, width: int, x: int, y: int) -> float:
        """The depth of pixel (x, y)."""
        return image[y * width + x]

    @checked("save_image", -1)
    def saveImage(self, filename: str, quality: int) -> int:
        """Save the depths: an .hdr file keeps the metres, PNG/JPEG are grey (black at 0, white at maxRange)."""
        if filename and filename.lower().endswith(".hdr"):
            return _write_hdr(filename, self._s.width, self._s.height, self._s.value)
        top = self.getMaxRange() or 1.0
        grey = bytes(int(255 * max(0.0, min(1.0, d / top))) if d == d else 0 for d in self._s.value)
        rgba = bytes(b for g in grey for b in (g, g, g, 255))
        return _images.save_image("wb_range_finder_save_image", filename, quality, self._s.width, self._s.height, rgba)

    @checked("get_width", -1)
    def getWidth(self) -> int:
        """Image width (pixels)."""
        return self._s.width

    @checked("get_height", -1)
    def getHeight(self) -> int:
        """Image height (pixels)."""
        return self._s.height

    @checked("get_fov", NAN)
    def getFov(self) -> float:
        """Horizontal field of view (rad)."""
        return float(self._s.field("fieldOfView", 0.785398))

    @checked("get_min_range", NAN)
    def getMinRange(self) -> float:
        """The ``minRange`` field (m)."""
        return float(self._s.field("minRange", 0.01))

    @checked("get_max_range", NAN)
    def getMaxRange(self) -> float:
        """The ``maxRange`` field (m)."""
        return float(self._s.field("maxRange", 1.0))

    range_image = property(getRangeImage, doc="The depth image.")
    fov = property(getFov, doc="The field of view.")
    width = property(getWidth, doc="Image width.")
    height = property(getHeight, doc="Image height.")
    max_range = property(getMaxRange, doc="The maxRange field.")
    min_range = property(getMinRange, doc="The minRange field.")


def _rgbe(value: float) -> bytes:
    """One grey pixel of a Radiance picture: a shared 8-bit mantissa and the exponent + 128."""
    if not value > 1e-32 or value == float("inf"):  # nothing in range (inf, NaN) is stored as 0
        return b"\0\0\0\0"
    mantissa, exponent = math.frexp(value)
    level = int(mantissa * 256.0)
    return bytes((level, level, level, exponent + 128))


def _write_hdr(filename: str, width: int, height: int, depths: Any) -> int:
    """Write the depths (metres) as an uncompressed Radiance .hdr picture, rows from the top; 0 or -1."""
    header = f"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {height} +X {width}\n".encode("ascii")
    try:
        with open(filename, "wb") as out:
            out.write(header + b"".join(_rgbe(float(d)) for d in depths))
    except OSError:
        return -1
    return 0
