"""``Brake``: a damping torque or force on a joint."""

from __future__ import annotations

from . import _session
from .constants import LINEAR, ROTATIONAL
from .device import Device, checked

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class Brake(Device):
    """A Brake node; ``setDampingConstant`` reaches the simulator at the next step."""

    ROTATIONAL = ROTATIONAL
    LINEAR = LINEAR
    _C = "wb_brake"
    _TYPES = ("Brake",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        # The simulator gives a brake the tags of the motor and position sensor on its joint axis;
        # without them, the motor naming this brake leads to both.
        motor, sensor = state.info.get("motor"), state.info.get("sensor")
        state.motor = session.by_tag.get(motor) if motor is not None else next(
            (s for s in session.states if s.info.get("brake") == state.tag), None)
        if sensor is None and state.motor is not None:
            sensor = state.motor.info.get("sensor")
        state.sensor = None if sensor is None else session.by_tag.get(sensor)
        state.kind = LINEAR if state.motor is not None and state.motor.type == "LinearMotor" else ROTATIONAL

    @checked("set_damping_constant")
    def setDampingConstant(self, dampingConstant: float) -> None:
        """Damping constant of the brake (N·m·s/rad or N·s/m)."""
        self._queue("setDampingConstant", float(dampingConstant))

    @checked("get_type", ROTATIONAL)
    def getType(self) -> int:
        """ROTATIONAL or LINEAR."""
        return self._s.kind

    @checked("get_motor")
    def getMotor(self) -> Any:
        """The Motor on the same joint, or None."""
        from .motor import Motor

        return None if self._s.motor is None else Motor(self._s.motor.tag)

    @checked("get_position_sensor")
    def getPositionSensor(self) -> Any:
        """The PositionSensor on the same joint, or None."""
        from .position_sensor import PositionSensor

        return None if self._s.sensor is None else PositionSensor(self._s.sensor.tag)

    dampingConstant = property(fset=setDampingConstant, doc="Write-only: the damping constant.")
    type = property(getType, doc="ROTATIONAL or LINEAR.")
    motor = property(getMotor, doc="The Motor on the same joint, or None.")
    position_sensor = property(getPositionSensor, doc="The PositionSensor on the same joint, or None.")
