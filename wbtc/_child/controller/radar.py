"""``Radar``: targets (distance, power, speed, azimuth) in the radar's field of view."""

from __future__ import annotations

from . import _session
from .device import checked
from .radar_target import RadarTarget
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


def _target(item: Any) -> RadarTarget:
    if isinstance(item, dict):
        item = (item.get("distance"), item.get("received_power", item.get("receiver_power")), item.get("speed"),
                item.get("azimuth"))
    distance, power, speed, azimuth = (float(v) for v in item)
    return RadarTarget(distance, power, speed, azimuth)


class Radar(Sensor):
    """A Radar node; targets are those of the last sample."""

    _C = "wb_radar"
    _TYPES = ("Radar",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.value = []

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        state.value = [_target(item) for item in value or []]

    @checked("get_number_of_targets", 0)
    def getNumberOfTargets(self) -> int:
        """The number of targets of the last sample."""
        return len(self._sampled("get_number_of_targets").value)

    @checked("get_targets", [])
    def getTargets(self) -> list[RadarTarget]:
        """The targets of the last sample."""
        return list(self._sampled("get_targets").value)

    @checked("get_min_range", NAN)
    def getMinRange(self) -> float:
        """The ``minRange`` field (m)."""
        return float(self._s.field("minRange", 1.0))

    @checked("get_max_range", NAN)
    def getMaxRange(self) -> float:
        """The ``maxRange`` field (m)."""
        return float(self._s.field("maxRange", 50.0))

    @checked("get_horizontal_fov", NAN)
    def getHorizontalFov(self) -> float:
        """The ``horizontalFieldOfView`` field (rad)."""
        return float(self._s.field("horizontalFieldOfView", 0.78))

    @checked("get_vertical_fov", NAN)
    def getVerticalFov(self) -> float:
        """The ``verticalFieldOfView`` field (rad)."""
        return float(self._s.field("verticalFieldOfView", 0.1))

    max_range = property(getMaxRange, doc="The maxRange field.")
    min_range = property(getMinRange, doc="The minRange field.")
    horizontal_fov = property(getHorizontalFov, doc="The horizontal field of view.")
    vertical_fov = property(getVerticalFov, doc="The vertical field of view.")
    number_of_targets = property(getNumberOfTargets, doc="The number of targets.")
