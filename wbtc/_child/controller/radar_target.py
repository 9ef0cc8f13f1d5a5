"""``RadarTarget``: one target detected by a radar."""

from __future__ import annotations


class RadarTarget:
    """Distance (m), received power (dBm), radial speed (m/s) and azimuth (rad) of a target."""

    def __init__(self, distance: float, receiver_power: float, speed: float, azimuth: float) -> None:
        self.distance = distance
        self.receiver_power = receiver_power
        self.speed = speed
        self.azimuth = azimuth

    def __repr__(self) -> str:
        return (
            f"RadarTarget(distance={self.distance}, receiver_power={self.receiver_power}, speed={self.speed}, "
            f"azimuth={self.azimuth})"
        )
