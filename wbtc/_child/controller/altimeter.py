"""``Altimeter``: the device's altitude."""

from __future__ import annotations

from . import _session
from .device import checked
from .sensor import NAN, Sensor


class Altimeter(Sensor):
    """An Altimeter node; ``getValue()`` is NaN until the first sample."""

    _C = "wb_altimeter"
    _TYPES = ("Altimeter",)

    def __init__(self, name: str | int, sampling_period: int | None = None) -> None:
        super().__init__(name, sampling_period)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = NAN

    @checked("get_value", NAN)
    def getValue(self) -> float:
        """The last sampled altitude (m)."""
        return self._sampled("get_value").value

    @property
    def value(self) -> float:
        """The last sampled altitude (m)."""
        return self.getValue()
