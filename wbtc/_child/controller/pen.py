"""``Pen``: paints the ground under the device."""

from __future__ import annotations

from .device import Device, checked


class Pen(Device):
    """A Pen node; commands reach the simulator at the next step."""

    _C = "wb_pen"
    _TYPES = ("Pen",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @checked("write")
    def write(self, write: bool) -> None:
        """Start (True) or stop (False) writing."""
        self._queue("write", bool(write))

    @checked("set_ink_color")
    def setInkColor(self, color: int, density: float) -> None:
        """Ink colour as 0xRRGGBB and density in [0, 1]."""
        self._queue("setInkColor", int(color), float(density))
