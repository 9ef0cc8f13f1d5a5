"""``LED``: a light whose state is an int (0 = off)."""

from __future__ import annotations

from . import _session
from .device import Device, checked


class LED(Device):
    """An LED node; ``set()`` reaches the simulator at the next step, ``get()`` returns the last value set."""

    _C = "wb_led"
    _TYPES = ("LED",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = 0

    @checked("set")
    def set(self, value: bool | int) -> None:
        """0 switches off; 1..n picks ``color[value-1]``, or the intensity/RGB value of a gradual LED."""
        value = (1 if value else 0) if isinstance(value, bool) else int(value)
        self._s.value = value
        self._queue("set", value)

    @checked("get", 0)
    def get(self) -> int:
        """The last value set (initially 0)."""
        return self._s.value

    value = property(get, set, doc="The LED state.")
