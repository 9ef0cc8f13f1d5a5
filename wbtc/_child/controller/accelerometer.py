"""``Accelerometer``: three values per sample, the acceleration in m/s² (specific force) in the sensor frame."""

from __future__ import annotations

from .sensor import Vector3Sensor


class Accelerometer(Vector3Sensor):
    """A Accelerometer node; ``getValues()`` is [NaN, NaN, NaN] until the first sample."""

    _C = "wb_accelerometer"
    _TYPES = ("Accelerometer",)

