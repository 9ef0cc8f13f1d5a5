"""``Compass``: three values per sample, the direction of the north in the sensor frame."""

from __future__ import annotations

from .sensor import Vector3Sensor


class Compass(Vector3Sensor):
    """A Compass node; ``getValues()`` is [NaN, NaN, NaN] until the first sample."""

    _C = "wb_compass"
    _TYPES = ("Compass",)

