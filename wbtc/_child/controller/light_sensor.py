"""``LightSensor``: irradiance through the sensor's lookup table."""

from __future__ import annotations

from .device import checked
from .sensor import ScalarSensor, flat_lookup_table


class LightSensor(ScalarSensor):
    """A LightSensor node; ``getValue()`` is NaN until the first sample."""

    _C = "wb_light_sensor"
    _TYPES = ("LightSensor",)

    @checked("get_lookup_table", [])
    def getLookupTable(self) -> list[float]:
        """The lookup table as a flat list of 3·n floats."""
        return flat_lookup_table(self._s.field("lookupTable", [[0, 0, 0], [1, 1000, 0]]))

    @property
    def lookup_table(self) -> list[float]:
        """The flat lookup table."""
        return self.getLookupTable()

