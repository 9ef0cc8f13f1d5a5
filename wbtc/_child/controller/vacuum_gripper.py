"""``VacuumGripper``: sticks to what it touches when on; presence tells whether something is held."""

from __future__ import annotations

from . import _session
from ._presence import PresenceDevice
from .device import checked


class VacuumGripper(PresenceDevice):
    """A VacuumGripper node; ``turnOn``/``turnOff`` and presence sampling reach the simulator at the next step."""

    _C = "wb_vacuum_gripper"
    _TYPES = ("VacuumGripper",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = 0
        state.locked = bool(state.field("isOn", False))

    @checked("get_presence", False)
    def getPresence(self) -> bool:
        """Whether an object is held (False before the first sample)."""
        return self._presence() > 0

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
