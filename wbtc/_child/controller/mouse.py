"""``Mouse`` and ``MouseState``: the mouse over the simulator's 3D view (wbtc has none: no clicks ever)."""

from __future__ import annotations

from . import _session

NAN = _session.NAN


class MouseState:
    """Mouse position in the view (u, v), in the world (x, y, z) and button states."""

    def __init__(self, u: float, v: float, x: float, y: float, z: float, left: bool, middle: bool, right: bool) -> None:
        self.u = u
        self.v = v
        self.x = x
        self.y = y
        self.z = z
        self.left = left
        self.middle = middle
        self.right = right


class Mouse:
    """The mouse; wbtc runs without a 3D view, so the state never changes."""

    def __init__(self, sampling_period: int | None = None) -> None:
        self._period = 0
        self._3d = False
        if sampling_period != 0:
            self.enable(int(_session.require().basic_time_step) if sampling_period is None else sampling_period)

    def enable(self, p: int) -> None:
        """Sample the mouse every ``p`` ms."""
        self._period = int(p)

    def disable(self) -> None:
        """Stop sampling the mouse."""
        self._period = 0

    def getSamplingPeriod(self) -> int:
        """The sampling period (ms)."""
        return self._period

    def getState(self) -> MouseState:
        """The mouse state: NaN coordinates, no button pressed."""
        return MouseState(NAN, NAN, NAN, NAN, NAN, False, False, False)

    def enable3dPosition(self) -> None:
        """Also compute the 3D position under the mouse."""
        self._3d = True

    def disable3dPosition(self) -> None:
        """Stop computing the 3D position."""
        self._3d = False

    def is3dPositionEnabled(self) -> bool:
        """Whether the 3D position is computed."""
        return self._3d

    @property
    def sampling_period(self) -> int:
        """The sampling period; setting it enables the mouse (None disables)."""
        return self._period

    @sampling_period.setter
    def sampling_period(self, p: int | None) -> None:
        self.enable(0 if p is None else p)
