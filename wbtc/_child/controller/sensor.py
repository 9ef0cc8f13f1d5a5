"""``Sensor``: a device with a sampling period (enable/disable), and helpers shared by the sensor classes."""

from __future__ import annotations

from . import _session
from .device import Device, checked

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

NAN = _session.NAN


def flat_lookup_table(rows: Any) -> list[float]:
    """A lookupTable field (rows ``[in, out, noise]``) as Webots' flat list of 3·n floats."""
    flat: list[float] = []
    for row in rows or []:
        flat.extend(float(x) for x in row)
    return flat


class Sensor(Device):
    """A device that samples every ``sampling_period`` ms once enabled.

    Constructing a sensor by name (``DistanceSensor('ps0')``) enables it at once with ``int(basicTimeStep)`` (or the
    given period), as Webots' Python package does; objects created from tags (``Robot.getDevice``) stay disabled.
    """

    def __init__(self, name: str | int, sampling_period: int | None = None) -> None:
        super().__init__(name)
        if isinstance(name, str):
            period = int(_session.require().basic_time_step) if sampling_period is None else sampling_period
            self.sampling_period = period

    @checked("enable")
    def enable(self, p: int) -> None:
        """Start sampling every ``p`` ms (0 disables)."""
        period = int(p)
        if period < 0:
            _session.error(f"Error: {self._C}_enable() called with negative sampling period.")
            return
        self._set_period(period)

    @checked("disable")
    def disable(self) -> None:
        """Stop sampling; the last value stays readable (with an error message)."""
        self._set_period(0)

    @checked("get_sampling_period", 0)
    def getSamplingPeriod(self) -> int:
        """The sampling period in ms, 0 when disabled."""
        return self._s.period

    def _set_period(self, period: int) -> None:
        self._s.period = period
        if period:
            self._queue("enable", period)
        else:
            self._queue("disable")

    def _sampled(self, suffix: str) -> _session.DeviceState:
        """The state, after printing Webots' disabled-device error when sampling is off."""
        state = self._s
        if state.period <= 0:
            _session.error(
                f"Error: {self._C}_{suffix}() called for a disabled device! Please use: {self._C}_enable()."
            )
        return state

    @property
    def sampling_period(self) -> int:
        """The sampling period in ms; setting it enables the sensor (None disables)."""
        return self.getSamplingPeriod()

    @sampling_period.setter
    def sampling_period(self, p: int | None) -> None:
        self.enable(0 if p is None else p)


class Vector3Sensor(Sensor):
    """The shared shape of Accelerometer, Gyro and Compass: three values per sample and a lookup table."""

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = [NAN, NAN, NAN]

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        state.value = [float(v) for v in value]

    @checked("get_values")
    def getValues(self) -> list[float]:
        """The last sample as [x, y, z] (NaN before the first sample)."""
        return list(self._sampled("get_values").value)

    @checked("get_lookup_table", [])
    def getLookupTable(self) -> list[float]:
        """The lookup table as a flat list of 3·n floats."""
        return flat_lookup_table(self._s.field("lookupTable", []))

    @property
    def value(self) -> list[float]:
        """The last sample."""
        return self.getValues()

    @property
    def lookup_table(self) -> list[float]:
        """The flat lookup table."""
        return self.getLookupTable()


class ScalarSensor(Sensor):
    """A sensor that reads one number: NaN until its first sample (``getValue()``, ``value``)."""

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = NAN

    @checked("get_value", NAN)
    def getValue(self) -> float:
        """The last sampled value (NaN before the first sample)."""
        return self._sampled("get_value").value

    @property
    def value(self) -> float:
        """The last sampled value."""
        return self.getValue()
