"""Presence sampling shared by ``Connector`` and ``VacuumGripper`` (same C calls, ``wb_<device>_*_presence``)."""

from __future__ import annotations

from . import _session
from .device import Device, checked


class PresenceDevice(Device):
    """A device whose presence (something docked or held) is sampled like a sensor."""

    @checked("enable_presence")
    def enablePresence(self, sampling_period: int) -> None:
        """Sample the presence every ``sampling_period`` ms."""
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

    def _presence(self) -> int:
        """The last presence sample, with Webots' error when presence is not enabled."""
        if self._s.period <= 0:
            _session.error(
                f"Error: {self._C}_get_presence() called for a disabled device! "
                f"Please use: {self._C}_enable_presence()."
            )
        return int(self._s.value)

    presence_sampling_period = property(getPresenceSamplingPeriod, doc="The presence sampling period.")
