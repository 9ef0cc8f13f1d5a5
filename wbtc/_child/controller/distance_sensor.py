"""``DistanceSensor``: one value per sample, read through the sensor's lookup table by the simulator."""

from __future__ import annotations

from . import _session
from .device import checked
from .sensor import NAN, ScalarSensor, flat_lookup_table

_KINDS = {"generic": 0, "infra-red": 1, "sonar": 2, "laser": 3}


class DistanceSensor(ScalarSensor):
    """A DistanceSensor node; ``getValue()`` is NaN until the first sample after ``enable()``."""

    GENERIC = 0
    INFRA_RED = 1
    SONAR = 2
    LASER = 3
    _C = "wb_distance_sensor"
    _TYPES = ("DistanceSensor",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        ScalarSensor._setup(state, session)
        outputs = [float(row[1]) for row in state.field("lookupTable", [[0, 0, 0], [0.1, 1000, 0]])]
        state.min_value = min(outputs) if outputs else 0.0
        state.max_value = max(outputs) if outputs else 0.0

    @checked("get_max_value", NAN)
    def getMaxValue(self) -> float:
        """The largest output of the lookup table."""
        return self._s.max_value

    @checked("get_min_value", NAN)
    def getMinValue(self) -> float:
        """The smallest output of the lookup table."""
        return self._s.min_value

    @checked("get_aperture", NAN)
    def getAperture(self) -> float:
        """The ``aperture`` field (rad)."""
        return float(self._s.field("aperture", 1.5708))

    @checked("get_lookup_table", [])
    def getLookupTable(self) -> list[float]:
        """The lookup table as a flat list of 3·n floats."""
        return flat_lookup_table(self._s.field("lookupTable", [[0, 0, 0], [0.1, 1000, 0]]))

    @checked("get_type", 0)
    def getType(self) -> int:
        """GENERIC, INFRA_RED, SONAR or LASER."""
        return _KINDS.get(str(self._s.field("type", "generic")), 0)

    @property
    def aperture(self) -> float:
        """The aperture (rad)."""
        return self.getAperture()

    @property
    def lookup_table(self) -> list[float]:
        """The flat lookup table."""
        return self.getLookupTable()

    @property
    def max_value(self) -> float:
        """The largest table output."""
        return self.getMaxValue()

    @property
    def min_value(self) -> float:
        """The smallest table output."""
        return self.getMinValue()

    @property
    def type(self) -> int:
        """The sensor type constant."""
        return self.getType()

