"""``PositionSensor``: the position of a joint (rad or m)."""

from __future__ import annotations

from . import _session
from .constants import LINEAR, ROTATIONAL
from .device import checked
from .sensor import ScalarSensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class PositionSensor(ScalarSensor):
    """A PositionSensor node; ``getValue()`` is NaN until the first sample."""

    ROTATIONAL = ROTATIONAL
    LINEAR = LINEAR
    _C = "wb_position_sensor"
    _TYPES = ("PositionSensor",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        ScalarSensor._setup(state, session)
        motor = session.by_tag.get(state.info.get("motor")) if state.info.get("motor") is not None else None
        state.motor = motor
        state.kind = LINEAR if motor is not None and motor.type == "LinearMotor" else ROTATIONAL

    @checked("get_type", ROTATIONAL)
    def getType(self) -> int:
        """ROTATIONAL or LINEAR."""
        return self._s.kind

    @checked("get_motor")
    def getMotor(self) -> Any:
        """The Motor on the same joint, or None."""
        from .motor import Motor

        return None if self._s.motor is None else Motor(self._s.motor.tag)

    @checked("get_brake")
    def getBrake(self) -> Any:
        """The Brake on the same joint, or None."""
        from .brake import Brake

        tag = self._s.info.get("brake")
        if tag is None and self._s.motor is not None:
            tag = self._s.motor.info.get("brake")
        return None if tag is None else Brake(int(tag))

    type = property(getType, doc="ROTATIONAL or LINEAR.")
    motor = property(getMotor, doc="The Motor on the same joint, or None.")
    brake = property(getBrake, doc="The Brake on the same joint, or None.")
