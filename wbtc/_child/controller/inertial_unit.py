"""``InertialUnit``: orientation as a quaternion and as roll/pitch/yaw angles."""

from __future__ import annotations

import math

from . import _session
from .device import checked
from .sensor import NAN, Sensor, flat_lookup_table

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


def roll_pitch_yaw(q: list[float], coordinate_system: str) -> list[float]:
    """Roll, pitch and yaw (rad) of the quaternion [x, y, z, w] by Webots' formulas for ENU (and EUN) or NUE."""
    x, y, z, w = q
    if coordinate_system == "NUE":
        # extrinsic Y(yaw) Z(pitch) X(roll); no clamping in Webots: |arg| > 1 gives NaN
        yaw = math.atan2(2 * y * w - 2 * x * z, 1 - 2 * y * y - 2 * z * z)
        roll = math.atan2(2 * x * w - 2 * y * z, 1 - 2 * x * x - 2 * z * z)
        s = 2 * x * y + 2 * z * w
        pitch = math.asin(s) if -1.0 <= s <= 1.0 else NAN
        return [roll, pitch, yaw]
    # extrinsic Z(yaw) Y(pitch) X(roll)
    roll = math.atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    s = 2.0 * (w * y - z * x)
    pitch = NAN if math.isnan(s) else math.asin(max(-1.0, min(1.0, s)))
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return [roll, pitch, yaw]


class InertialUnit(Sensor):
    """An InertialUnit node; values are NaN until the first sample."""

    _C = "wb_inertial_unit"
    _TYPES = ("InertialUnit",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = [NAN] * 4
        state.coordinate_system = session.coordinate_system

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        state.value = [float(v) for v in value]

    @checked("get_roll_pitch_yaw")
    def getRollPitchYaw(self) -> list[float]:
        """[roll, pitch, yaw] in rad."""
        state = self._sampled("get_roll_pitch_yaw")
        return roll_pitch_yaw(state.value, state.coordinate_system)

    @checked("get_quaternion")
    def getQuaternion(self) -> list[float]:
        """The orientation quaternion [x, y, z, w] in world coordinates."""
        return list(self._sampled("get_quaternion").value)

    @checked("get_lookup_table", [])
    def getLookupTable(self) -> list[float]:
        """The (deprecated) lookupTable field as a flat list of 3·n floats, as C's wb_inertial_unit_get_lookup_table."""
        return flat_lookup_table(self._s.field("lookupTable", []))

    @checked("get_noise", 0.0)
    def getNoise(self) -> float:
        """The ``noise`` field."""
        return float(self._s.field("noise", 0.0))

    @property
    def roll_pitch_yaw(self) -> list[float]:
        """[roll, pitch, yaw] in rad."""
        return self.getRollPitchYaw()

    @property
    def quaternion(self) -> list[float]:
        """[x, y, z, w]."""
        return self.getQuaternion()

    @property
    def noise(self) -> float:
        """The noise field."""
        return self.getNoise()
