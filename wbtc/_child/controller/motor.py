"""``Motor``: RotationalMotor and LinearMotor, commanded in position, velocity or force/torque.

Coupled motors (Webots' `multiplier`): motors of one robot named "GROUP::anything" with the same GROUP,
or sharing the very same name, move together. A command to one reaches the others scaled by the ratio
r = their multiplier / its multiplier: positions and torques times r, velocities times r (their size,
|r|, in position control), accelerations and available forces times |r|. At start, each coupled motor
takes the first one's limits scaled by its ratio to it (a negative ratio swaps min and max) and its
maxVelocity times |r|.
"""

from __future__ import annotations

import math

from . import _session
from .constants import LINEAR, ROTATIONAL
from .device import Device, checked

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

NAN = _session.NAN


def _nan(value: float, function: str, argument: str, suffix: str = " (NaN).") -> bool:
    if math.isnan(value):
        _session.error(f"Error: {function}() called with an invalid '{argument}' argument{suffix}")
        return True
    return False


def _clamped(state: _session.DeviceState, position: float, warn: bool) -> float:
    """A target inside the motor's limits (when it has some): Webots clamps it, with a warning."""
    low, high = state.min_position, state.max_position
    if (low, high) == (0.0, 0.0) or math.isinf(position):
        return position
    if warn and position > high:
        _session.error(f"Warning: too big requested position: {position:g} > {high:g}")
    elif warn and position < low:
        _session.error(f"Warning: too low requested position: {position:g} < {low:g}")
    return min(max(position, low), high)


def _coupling_key(name: str) -> str:
    """Motors with the same key are coupled: the part before "::", else the whole name."""
    return name.split("::", 1)[0] if "::" in name else "=" + name


def _couple(state: _session.DeviceState, session: _session.Session) -> None:
    """Find the motors coupled with `state` and take the group's limits from its first motor."""
    key = _coupling_key(state.name)
    group = [s for s in session.states if s.type in Motor._TYPES and _coupling_key(s.name) == key]
    state.coupled = [s for s in group if s is not state]
    first = group[0]
    if first is state:
        return
    ratio = state.multiplier / float(first.field("multiplier", 1.0) or 1.0)
    low = float(first.field("minPosition", 0.0)) * ratio
    high = float(first.field("maxPosition", 0.0)) * ratio
    state.min_position, state.max_position = min(low, high), max(low, high)
    state.max_velocity = state.velocity = float(first.field("maxVelocity", 10.0)) * abs(ratio)


def _coupled(state: _session.DeviceState) -> list[tuple[_session.DeviceState, float]]:
    """The motors coupled with `state` and their ratios to it (their multiplier / its multiplier)."""
    own = state.multiplier or 1.0
    return [(other, other.multiplier / own) for other in getattr(state, "coupled", ())]


class Motor(Device):
    """A motor; commands reach the simulator at the next ``step()``.

    Initially the target position is the joint's position, the velocity ``maxVelocity``, the available force or
    torque ``maxForce``/``maxTorque`` and the PID gains ``controlPID``, as after Webots' configuration message.
    """

    ROTATIONAL = ROTATIONAL
    LINEAR = LINEAR
    _C = "wb_motor"
    _TYPES = ("RotationalMotor", "LinearMotor")

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        linear = state.type == "LinearMotor"
        state.kind = LINEAR if linear else ROTATIONAL
        state.max_velocity = float(state.field("maxVelocity", 10.0))
        state.max_force = float(state.field("maxForce" if linear else "maxTorque", 10.0))
        state.min_position = float(state.field("minPosition", 0.0))
        state.max_position = float(state.field("maxPosition", 0.0))
        state.multiplier = float(state.field("multiplier", 1.0))
        state.target = float(state.info.get("position") or 0.0)
        state.velocity = state.max_velocity
        state.acceleration = float(state.field("acceleration", -1.0))
        state.available = state.max_force
        state.pid = [float(x) for x in state.field("controlPID", [10.0, 0.0, 0.0])]
        state.value = NAN  # force/torque feedback
        _couple(state, session)

    # -- commands -------------------------------------------------------------------------------------------
    @checked("set_position")
    def setPosition(self, position: float) -> None:
        """Target position (rad or m); ``float('inf')`` switches to velocity control."""
        position = float(position)
        if _nan(position, "wb_motor_set_position", "position"):
            return
        position = _clamped(self._s, position, warn=True)
        self._s.target = position
        self._queue("setPosition", position)
        for other, ratio in _coupled(self._s):
            other.target = _clamped(other, position * ratio, warn=False)
            _session.require().queue(other.tag, "setPosition", other.target)

    @checked("set_velocity")
    def setVelocity(self, velocity: float) -> None:
        """Velocity limit in position control, target velocity in velocity control (rad/s or m/s)."""
        velocity = float(velocity)
        if _nan(velocity, "wb_motor_set_velocity", "velocity", ".(NaN)"):
            return
        if velocity < 0.0 and not math.isinf(self._s.target):
            _session.error(
                "Error: wb_motor_set_velocity() called with negative 'velocity' argument in position control mode "
                f"({self._s.target:g})."
            )
            return
        self._s.velocity = velocity
        self._queue("setVelocity", velocity)
        for other, ratio in _coupled(self._s):
            other.velocity = velocity * ratio if math.isinf(other.target) else abs(velocity * ratio)
            _session.require().queue(other.tag, "setVelocity", other.velocity)

    @checked("set_acceleration")
    def setAcceleration(self, acceleration: float) -> None:
        """Acceleration limit (-1: none)."""
        acceleration = float(acceleration)
        if acceleration < 0.0 and acceleration != -1:
            _session.error("Error: wb_motor_set_acceleration() called with negative 'acceleration' argument.")
            return
        if _nan(acceleration, "wb_motor_set_acceleration", "acceleration"):
            return
        self._s.acceleration = acceleration
        self._queue("setAcceleration", acceleration)
        for other, ratio in _coupled(self._s):
            other.acceleration = acceleration if acceleration == -1 else acceleration * abs(ratio)
            _session.require().queue(other.tag, "setAcceleration", other.acceleration)

    def _set_available(self, op: str, force: float) -> None:
        force = float(force)
        if _nan(force, "wb_motor_set_available_force", "force"):
            return
        if force < 0.0:
            _session.error("Error: wb_motor_set_available_force() called with negative 'force' argument.")
            return
        self._s.available = force
        self._queue(op, force)
        for other, ratio in _coupled(self._s):
            other.available = force * abs(ratio)
            _session.require().queue(other.tag, op, other.available)

    @checked("set_available_force")
    def setAvailableForce(self, force: float) -> None:
        """Force limit of a linear motor (N)."""
        self._set_available("setAvailableForce", force)

    @checked("set_available_torque")
    def setAvailableTorque(self, torque: float) -> None:
        """Torque limit of a rotational motor (N·m)."""
        self._set_available("setAvailableTorque", torque)

    @checked("set_control_pid")
    def setControlPID(self, p: float, i: float, d: float) -> None:
        """PID gains of position control (p > 0, i >= 0, d >= 0)."""
        p, i, d = float(p), float(i), float(d)
        for bad, message in ((p <= 0.0, "negative or zero 'p'"), (i < 0.0, "negative 'i'"), (d < 0.0, "negative 'd'")):
            if bad:
                _session.error(f"Error: wb_motor_set_control_pid() called with {message} argument.")
                return
        self._s.pid = [p, i, d]
        self._queue("setControlPID", p, i, d)

    def _set_effort(self, op: str, force: float) -> None:
        force = float(force)
        if _nan(force, "wb_motor_set_force", "force"):
            return
        self._queue(op, force)
        for other, ratio in _coupled(self._s):
            _session.require().queue(other.tag, op, force * ratio)

    @checked("set_force")
    def setForce(self, force: float) -> None:
        """Apply a constant force (N), switching off position/velocity control."""
        self._set_effort("setForce", force)

    @checked("set_torque")
    def setTorque(self, torque: float) -> None:
        """Apply a constant torque (N·m), switching off position/velocity control."""
        self._set_effort("setTorque", torque)

    def _enable_feedback(self, op: str, sampling_period: int) -> None:
        period = int(sampling_period)
        if period < 0:
            _session.error("Error: wb_motor_enable_force_feedback() called with negative sampling period.")
            return
        self._s.period = period
        if period:
            self._queue(op, period)
        else:
            self._queue(op.replace("enable", "disable"))

    @checked("enable_force_feedback")
    def enableForceFeedback(self, sampling_period: int) -> None:
        """Sample the force applied by a linear motor every ``sampling_period`` ms."""
        self._enable_feedback("enableForceFeedback", sampling_period)

    @checked("disable_force_feedback")
    def disableForceFeedback(self) -> None:
        """Stop sampling the force feedback."""
        self._enable_feedback("enableForceFeedback", 0)

    @checked("enable_torque_feedback")
    def enableTorqueFeedback(self, sampling_period: int) -> None:
        """Sample the torque applied by a rotational motor every ``sampling_period`` ms."""
        self._enable_feedback("enableTorqueFeedback", sampling_period)

    @checked("disable_torque_feedback")
    def disableTorqueFeedback(self) -> None:
        """Stop sampling the torque feedback."""
        self._enable_feedback("enableTorqueFeedback", 0)

    # -- getters --------------------------------------------------------------------------------------------
    @checked("get_target_position", NAN)
    def getTargetPosition(self) -> float:
        """The last position passed to ``setPosition`` (initially the joint position)."""
        return self._s.target

    @checked("get_min_position", NAN)
    def getMinPosition(self) -> float:
        """The ``minPosition`` field."""
        return self._s.min_position

    @checked("get_max_position", NAN)
    def getMaxPosition(self) -> float:
        """The ``maxPosition`` field."""
        return self._s.max_position

    @checked("get_velocity", NAN)
    def getVelocity(self) -> float:
        """The last velocity set (initially ``maxVelocity``)."""
        return self._s.velocity

    @checked("get_max_velocity", NAN)
    def getMaxVelocity(self) -> float:
        """The ``maxVelocity`` field."""
        return self._s.max_velocity

    @checked("get_acceleration", NAN)
    def getAcceleration(self) -> float:
        """The acceleration limit (-1: none)."""
        return self._s.acceleration

    @checked("get_available_force", NAN)
    def getAvailableForce(self) -> float:
        """The force limit (initially ``maxForce``)."""
        return self._s.available

    @checked("get_available_torque", NAN)
    def getAvailableTorque(self) -> float:
        """The torque limit (initially ``maxTorque``)."""
        return self._s.available

    @checked("get_max_force", NAN)
    def getMaxForce(self) -> float:
        """The ``maxForce`` field."""
        return self._s.max_force

    @checked("get_max_torque", NAN)
    def getMaxTorque(self) -> float:
        """The ``maxTorque`` field."""
        return self._s.max_force

    @checked("get_multiplier", NAN)
    def getMultiplier(self) -> float:
        """The ``multiplier`` field."""
        return self._s.multiplier

    @checked("get_force_feedback_sampling_period", 0)
    def getForceFeedbackSamplingPeriod(self) -> int:
        """The force feedback sampling period (ms)."""
        return self._s.period

    @checked("get_torque_feedback_sampling_period", 0)
    def getTorqueFeedbackSamplingPeriod(self) -> int:
        """The torque feedback sampling period (ms)."""
        return self._s.period

    @checked("get_force_feedback", NAN)
    def getForceFeedback(self) -> float:
        """The last sampled force (NaN before the first sample)."""
        return self._s.value

    @checked("get_torque_feedback", NAN)
    def getTorqueFeedback(self) -> float:
        """The last sampled torque (NaN before the first sample)."""
        return self._s.value

    @checked("get_type", ROTATIONAL)
    def getType(self) -> int:
        """ROTATIONAL or LINEAR."""
        return self._s.kind

    @checked("get_brake")
    def getBrake(self) -> Any:
        """The Brake on the same joint, or None."""
        from .brake import Brake

        tag = self._s.info.get("brake")
        return None if tag is None else Brake(int(tag))

    @checked("get_position_sensor")
    def getPositionSensor(self) -> Any:
        """The PositionSensor on the same joint, or None."""
        from .position_sensor import PositionSensor

        tag = self._s.info.get("sensor")
        return None if tag is None else PositionSensor(int(tag))

    # -- snake_case properties ------------------------------------------------------------------------------
    target_position = property(getTargetPosition, setPosition, doc="The target position.")
    target_velocity = property(getVelocity, setVelocity, doc="The velocity.")
    target_acceleration = property(getAcceleration, setAcceleration, doc="The acceleration limit.")
    available_force = property(getAvailableForce, setAvailableForce, doc="The force limit.")
    available_torque = property(getAvailableTorque, setAvailableTorque, doc="The torque limit.")
    max_position = property(getMaxPosition, doc="The maxPosition field.")
    min_position = property(getMinPosition, doc="The minPosition field.")
    max_velocity = property(getMaxVelocity, doc="The maxVelocity field.")
    max_force = property(getMaxForce, doc="The maxForce field.")
    max_torque = property(getMaxTorque, doc="The maxTorque field.")
    multiplier = property(getMultiplier, doc="The multiplier field.")
    force_feedback = property(getForceFeedback, doc="The sampled force.")
    torque_feedback = property(getTorqueFeedback, doc="The sampled torque.")
    force_feedback_sampling_period = property(getForceFeedbackSamplingPeriod, enableForceFeedback)
    torque_feedback_sampling_period = property(getTorqueFeedbackSamplingPeriod, enableTorqueFeedback)
    force = property(fset=setForce, doc="Write-only: apply a constant force.")
    torque = property(fset=setTorque, doc="Write-only: apply a constant torque.")
    type = property(getType, doc="ROTATIONAL or LINEAR.")
    brake = property(getBrake, doc="The Brake on the same joint, or None.")
    position_sensor = property(getPositionSensor, doc="The PositionSensor on the same joint, or None.")
