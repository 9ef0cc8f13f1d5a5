"""``Joystick``: a game controller attached to the simulator (wbtc has none: never connected)."""

from __future__ import annotations

from . import _session


class Joystick:
    """The joystick; wbtc has no joystick support, so ``isConnected()`` is False and nothing is pressed."""

    def __init__(self, sampling_period: int | None = None) -> None:
        self._period = 0
        if sampling_period != 0:
            self.enable(int(_session.require().basic_time_step) if sampling_period is None else sampling_period)

    def enable(self, p: int) -> None:
        """Sample the joystick every ``p`` ms."""
        self._period = int(p)

    def disable(self) -> None:
        """Stop sampling the joystick."""
        self._period = 0

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms)."""
        return self._period

    def isConnected(self) -> bool:
        """Whether a joystick is connected: never."""
        return False

    def getModel(self) -> str:
        """The joystick model: empty."""
        return ""

    def getNumberOfAxes(self) -> int:
        """Number of axes: 0."""
        return 0

    def getAxisValue(self, axis: int) -> int:
        """Value of an axis: 0."""
        return 0

    def getNumberOfPovs(self) -> int:
        """Number of points of view: 0."""
        return 0

    def getPovValue(self, pov: int) -> int:
        """Value of a point of view: 0."""
        return 0

    def getPressedButton(self) -> int:
        """The next pressed button: -1 (none)."""
        return -1

    def setConstantForce(self, level: int) -> None:
        """Force feedback: ignored."""

    def setConstantForceDuration(self, duration: float) -> None:
        """Force feedback: ignored."""

    def setAutoCenteringGain(self, gain: float) -> None:
        """Force feedback: ignored."""

    def setResistanceGain(self, gain: float) -> None:
        """Force feedback: ignored."""

    def setForceAxis(self, axis: int) -> None:
        """Force feedback: ignored."""

    @property
    def sampling_period(self) -> int:
        """The sampling period; setting it enables the joystick (None disables)."""
        return self._period

    @sampling_period.setter
    def sampling_period(self, p: int | None) -> None:
        self.enable(0 if p is None else p)

    is_connected = property(isConnected, doc="Never connected.")
    model = property(getModel, doc="Empty.")
    number_of_axes = property(getNumberOfAxes, doc="0.")
    number_of_povs = property(getNumberOfPovs, doc="0.")
    pressed_button = property(getPressedButton, doc="-1.")
