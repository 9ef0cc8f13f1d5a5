"""``Connector``: docks to another connector (lock/unlock); presence tells whether one is in range."""

from __future__ import annotations

from . import _session
from ._presence import PresenceDevice
from .device import checked


class Connector(PresenceDevice):
    """A Connector node; ``lock``/``unlock`` and presence sampling reach the simulator at the next step."""

    _C = "wb_connector"
    _TYPES = ("Connector",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = -1
        state.locked = bool(state.field("isLocked", False))

    @checked("get_presence", -1)
    def getPresence(self) -> int:
        """1 when a compatible connector is in range, 0 when not, -1 before the first sample."""
        return self._presence()

    @checked("lock")
    def lock(self) -> None:
        """Lock onto a compatible connector in range."""
        self._s.locked = True
        self._queue("lock")

    @checked("unlock")
    def unlock(self) -> None:
        """Release the connection."""
        self._s.locked = False
        self._queue("unlock")

    @checked("is_locked", False)
    def isLocked(self) -> bool:
        """Whether ``lock()`` was called last (rather than ``unlock()``)."""
        return self._s.locked

    locked = property(isLocked, doc="Whether the connector is locked.")
    presence = property(getPresence, doc="The last presence sample.")
