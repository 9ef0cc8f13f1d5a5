"""``Connector``: docks to another connector (lock/unlock); presence tells whether one is in range."""

from __future__ import annotations

from . import _session
from .device import Device, checked


class Connector(Device):
    """A Connector node; ``lock``/``unlock`` and presence sampling reach the simulator at the next step."""

    _C = "wb_connector"
    _TYPES = ("Connector",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = -1
        state.locked = bool(state.field("isLocked", False))

    @checked("enable_presence")
    def enablePresence(self, sampling_period: int) -> None:
        """Sample the presence of a compatible connector every ``sampling_period`` ms."""
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

    @checked("get_presence", -1)
    def getPresence(self) -> int:
        """1 when a compatible connector is in range, 0 when not, -1 before the first sample."""
        if self._s.period <= 0:
            _session.error(
                f"Error: {self._C}_get_presence() called for a disabled device! "
                f"Please use: {self._C}_enable_presence()."
            )
        return int(self._s.value)

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
    presence_sampling_period = property(getPresenceSamplingPeriod, doc="The presence sampling period.")
