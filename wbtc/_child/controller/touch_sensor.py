"""``TouchSensor``: bumper (0/1), force (N) or force-3d ([x, y, z] N)."""

from __future__ import annotations

from . import _session
from .device import checked
from .sensor import NAN, Sensor, flat_lookup_table

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

_KINDS = {"bumper": 0, "force": 1, "force-3d": 2}


class TouchSensor(Sensor):
    """A TouchSensor node; values are NaN until the first sample."""

    BUMPER = 0
    FORCE = 1
    FORCE3D = 2
    _C = "wb_touch_sensor"
    _TYPES = ("TouchSensor",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = [NAN, NAN, NAN]
        state.kind = _KINDS.get(str(state.field("type", "bumper")), 0)

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        if isinstance(value, (list, tuple)):
            state.value = [float(v) for v in value]
        else:
            state.value = [float(value), state.value[1], state.value[2]]

    @checked("get_value", NAN)
    def getValue(self) -> float:
        """The bumper state (0/1) or the force (N) of a "bumper" or "force" sensor."""
        if self._s.kind == TouchSensor.FORCE3D:
            _session.error(
                'Error: wb_touch_sensor_get_value() must be used with a TouchSensor of type "bumper" or "force"'
            )
            _session.error("Error: you should use wb_touch_sensor_get_values() instead.")
            return NAN
        return self._sampled("get_value").value[0]

    @checked("get_values")
    def getValues(self) -> list[float] | None:
        """The force vector [x, y, z] (N) of a "force-3d" sensor."""
        if self._s.kind != TouchSensor.FORCE3D:
            _session.error('Error: wb_touch_sensor_get_values() must be used with a TouchSensor of type "force-3d"')
            _session.error("Error: you should use wb_touch_sensor_get_value() instead.")
            return None
        return list(self._sampled("get_values").value)

    @checked("get_lookup_table", [])
    def getLookupTable(self) -> list[float]:
        """The lookup table as a flat list of 3·n floats."""
        return flat_lookup_table(self._s.field("lookupTable", [[0, 0, 0], [5000, 50000, 0]]))

    @checked("get_type", 0)
    def getType(self) -> int:
        """BUMPER, FORCE or FORCE3D."""
        return self._s.kind

    @property
    def value(self) -> float:
        """The bumper state or force."""
        return self.getValue()

    @property
    def values(self) -> list[float] | None:
        """The force vector."""
        return self.getValues()

    @property
    def lookup_table(self) -> list[float]:
        """The flat lookup table."""
        return self.getLookupTable()

    @property
    def type(self) -> int:
        """The sensor type constant."""
        return self.getType()
