"""``LightSensor``: irradiance through the sensor's lookup table."""

from __future__ import annotations

from . import _session
from .device import checked
from .sensor import NAN, Sensor, flat_lookup_table


class LightSensor(Sensor):
    """A LightSensor node; ``getValue()`` is NaN until the first sample."""

    _C = "wb_light_sensor"
    _TYPES = ("LightSensor",)

    def __init__(self, name: str | int, sampling_period: int | None = None) -> None:
        super().__init__(name, sampling_period)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = NAN

    @checked("get_value", NAN)
    def getValue(self) -> float:
        """The last sampled value."""
        return self._sampled("get_value").value

    @checked("get_lookup_table", [])
    def getLookupTable(self) -> list[float]:
        """The lookup table as a flat list of 3·n floats."""
        return flat_lookup_table(self._s.field("lookupTable", [[0, 0, 0], [1, 1000, 0]]))

    @property
    def lookup_table(self) -> list[float]:
        """The flat lookup table."""
        return self.getLookupTable()

    @property
    def value(self) -> float:
        """The last sampled value."""
        return self.getValue()
