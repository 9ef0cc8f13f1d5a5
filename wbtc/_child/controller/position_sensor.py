"""``PositionSensor``: the position of a joint (rad or m)."""

from __future__ import annotations

from . import _session
from .constants import LINEAR, ROTATIONAL
from .device import checked
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class PositionSensor(Sensor):
    """A PositionSensor node; ``getValue()`` is NaN until the first sample."""

    ROTATIONAL = ROTATIONAL
    LINEAR = LINEAR
    _C = "wb_position_sensor"
    _TYPES = ("PositionSensor",)

    def __init__(self, name: str | int, sampling_period: int | None = None) -> None:
        super().__init__(name, sampling_period)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = NAN
        motor = session.by_tag.get(state.info.get("motor")) if state.info.get("motor") is not None else None
        state.motor = motor
        state.kind = LINEAR if motor is not None and motor.type == "LinearMotor" else ROTATIONAL

    @checked("get_value", NAN)
    def getValue(self) -> float:
        """The last sampled joint position."""
        return self._sampled("get_value").value

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

        motor = self._s.motor
        tag = None if motor is None else motor.info.get("brake")
        return None if tag is None else Brake(int(tag))

    value = property(getValue, doc="The last sampled joint position.")
    type = property(getType, doc="ROTATIONAL or LINEAR.")
    motor = property(getMotor, doc="The Motor on the same joint, or None.")
    brake = property(getBrake, doc="The Brake on the same joint, or None.")
