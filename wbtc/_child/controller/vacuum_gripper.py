"""``VacuumGripper``: sticks to what it touches when on; presence tells whether something is held."""

from __future__ import annotations

from . import _session
from .device import Device, checked


class VacuumGripper(Device):
    """A VacuumGripper node; ``turnOn``/``turnOff`` and presence sampling reach the simulator at the next step."""

    _C = "wb_vacuum_gripper"
    _TYPES = ("VacuumGripper",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = 0
        state.locked = bool(state.field("isOn", False))

    @checked("enable_presence")
    def enablePresence(self, sampling_period: int) -> None:
        """Sample whether an object is held every ``sampling_period`` ms."""
        period = int(sampling_period)
        if period < 0:
            _session.error(f"Error: {self._C}_enable_presence() called with negative sampling period.")
            return
        self._s.period = period
        if period:
            self._queue("enablePresence", period)
        else:
            self._queue("disablePresence")

    @checked("disable_presence")
    def disablePresence(self) -> None:
        """Stop sampling the presence."""
        self._s.period = 0
        self._queue("disablePresence")

    @checked("get_presence_sampling_period", 0)
    def getPresenceSamplingPeriod(self) -> int:
        """The presence sampling period (ms)."""
        return self._s.period

    @checked("get_presence", False)
    def getPresence(self) -> bool:
        """Whether an object is held (False before the first sample)."""
        if self._s.period <= 0:
            _session.error(
                f"Error: {self._C}_get_presence() called for a disabled device! "
                f"Please use: {self._C}_enable_presence()."
            )
        return self._s.value > 0

    @checked("turn_on")
    def turnOn(self) -> None:
        """Switch the suction on."""
        self._s.locked = True
        self._queue("turnOn")

    @checked("turn_off")
    def turnOff(self) -> None:
        """Switch the suction off."""
        self._s.locked = False
        self._queue("turnOff")

    @checked("is_on", False)
    def isOn(self) -> bool:
        """Whether ``turnOn()`` was called last (rather than ``turnOff()``)."""
        return self._s.locked

    on = property(isOn, doc="Whether the gripper is on.")
    presence = property(getPresence, doc="The last presence sample.")
    presence_sampling_period = property(getPresenceSamplingPeriod, doc="The presence sampling period.")
