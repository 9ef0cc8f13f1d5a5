"""``LidarPoint``: one point of a lidar's point cloud."""

from __future__ import annotations


class LidarPoint:
    """A point in the lidar's frame (m), with its layer and the time it was measured at (s)."""

    __slots__ = ("x", "y", "z", "layer", "time")

    def __init__(self, x: float, y: float, z: float, layer: int, time: float) -> None:
        self.x = x
        self.y = y
        self.z = z
        self.layer = layer
        self.time = time

    def __repr__(self) -> str:
        return f"LidarPoint(x={self.x}, y={self.y}, z={self.z}, layer={self.layer}, time={self.time})"
