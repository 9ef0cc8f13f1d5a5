"""``Gyro``: three values per sample, the angular velocity in rad/s in the sensor frame."""

from __future__ import annotations

from .sensor import Vector3Sensor


class Gyro(Vector3Sensor):
    """A Gyro node; ``getValues()`` is [NaN, NaN, NaN] until the first sample."""

    _C = "wb_gyro"
    _TYPES = ("Gyro",)

