"""``Altimeter``: the device's altitude (m)."""

from __future__ import annotations

from .sensor import ScalarSensor


class Altimeter(ScalarSensor):
    """An Altimeter node; ``getValue()`` (the altitude, m) is NaN until the first sample."""

    _C = "wb_altimeter"
    _TYPES = ("Altimeter",)
