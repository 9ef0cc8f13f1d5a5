"""``GPS``: position and velocity of the device in world coordinates."""

from __future__ import annotations

import math

from . import _session
from .device import checked
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class GPS(Sensor):
    """A GPS node; values are NaN until the first sample."""

    LOCAL = 0
    WGS84 = 1
    _C = "wb_gps"
    _TYPES = ("GPS",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = [NAN] * 6

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        values = [float(v) for v in value]
        state.value = (values + [NAN] * 6)[:6]

    @checked("get_values")
    def getValues(self) -> list[float]:
        """The position [x, y, z] (m)."""
        return self._sampled("get_values").value[:3]

    @checked("get_speed", NAN)
    def getSpeed(self) -> float:
        """The speed (m/s), the norm of the speed vector."""
        vx, vy, vz = self._sampled("get_speed").value[3:6]
        return math.sqrt(vx * vx + vy * vy + vz * vz)

    @checked("get_speed_vector")
    def getSpeedVector(self) -> list[float]:
        """The velocity [vx, vy, vz] in world coordinates (m/s)."""
        return self._sampled("get_speed_vector").value[3:6]

    @checked("get_coordinate_system", 0)
    def getCoordinateSystem(self) -> int:
        """LOCAL or WGS84: the world's `WorldInfo.gpsCoordinateSystem`."""
        return GPS.WGS84 if _session.require().robot.get("gps_wgs84") else GPS.LOCAL

    @staticmethod
    def convertToDegreesMinutesSeconds(decimalDegrees: float) -> str:
        """Format decimal degrees as ``D° M′ S″`` in whole numbers (``wb_gps_convert_to_degrees_minutes_seconds``)."""
        degrees = int(decimalDegrees)
        minutes = int((decimalDegrees - degrees) * 60)
        seconds = int(((decimalDegrees - degrees) * 60 - minutes) * 60)
        return f"{degrees}° {minutes}′ {seconds}″"

    @property
    def value(self) -> list[float]:
        """The position."""
        return self.getValues()

    @property
    def speed(self) -> float:
        """The speed."""
        return self.getSpeed()

    @property
    def speed_vector(self) -> list[float]:
        """The velocity vector."""
        return self.getSpeedVector()

    @property
    def coordinate_system(self) -> int:
        """LOCAL or WGS84."""
        return self.getCoordinateSystem()
