"""``Lidar``: range images (and optionally point clouds) over one or several layers."""

from __future__ import annotations

from array import array

from . import _session
from .device import checked
from .lidar_point import LidarPoint
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class Lidar(Sensor):
    """A Lidar node; ``getRangeImage()`` holds horizontalResolution × numberOfLayers floats (inf: no hit)."""

    _C = "wb_lidar"
    _TYPES = ("Lidar",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.resolution = int(state.field("horizontalResolution", 512))
        state.layers = int(state.field("numberOfLayers", 4))
        state.frequency = float(state.field("defaultFrequency", 10.0))
        state.point_cloud = False
        # Webots hands out its zero-filled image memory until the first sample lands in it.
        state.value = [0.0] * (state.resolution * state.layers)
        state.points = []

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        if value.get("ranges") is not None:
            state.value = array("f", value["ranges"]).tolist()  # Webots hands out C floats
        if value.get("points") is not None:
            state.points = [
                LidarPoint(float(x), float(y), float(z), int(layer), float(t)) for x, y, z, layer, t in value["points"]
            ]

    @checked("get_range_image")
    def getRangeImage(self) -> list[float]:
        """Every layer's ranges, layer after layer (m)."""
        return list(self._sampled("get_range_image").value)

    @checked("get_layer_range_image")
    def getLayerRangeImage(self, layer: int) -> list[float] | None:
        """The ranges of one layer (m)."""
        state = self._s
        if state.period <= 0:
            _session.error(
                "Error: wb_lidar_get_layer_range_image() called for a disabled device! Please use: wb_lidar_enable()."
            )
            return None
        if layer >= state.layers:
            _session.error(
                f"Error: wb_lidar_get_layer_range_image() called with a 'layer' argument ({layer}) bigger or equal to "
                f"the number of layers of this lidar ({state.layers})."
            )
            return None
        if layer < 0:
            _session.error("Error: wb_lidar_get_layer_range_image() called with a negative 'layer' argument.")
            return None
        return state.value[layer * state.resolution:(layer + 1) * state.resolution]

    def getRangeImageArray(self) -> list[list[float] | None]:
        """The range image as one list per layer."""
        return [self.getLayerRangeImage(layer) for layer in range(self.getNumberOfLayers())]

    def _cloud(self, function: str) -> bool:
        if not self._s.point_cloud:
            _session.error(
                f"Error: {function}() called for a lidar with point cloud disabled. "
                "Please use: wb_lidar_enable_point_cloud()."
            )
            return False
        if self._s.period <= 0:
            _session.error(f"Error: {function}() called for a disabled device! Please use: wb_lidar_enable().")
            return False
        return True

    @checked("get_point_cloud", [])
    def getPointCloud(self) -> list[LidarPoint]:
        """Every point of the last scan (point cloud must be enabled)."""
        if not self._cloud("wb_lidar_get_point_cloud"):
            return []
        if not self._s.points:  # before the first sample: the zero-filled memory Webots hands out
            count, width = self._s.resolution * self._s.layers, self._s.resolution
            return [LidarPoint(0.0, 0.0, 0.0, i // width, 0.0) for i in range(count)]
        return list(self._s.points)

    @checked("get_layer_point_cloud", [])
    def getLayerPointCloud(self, layer: int) -> list[LidarPoint]:
        """The points of one layer."""
        if not self._cloud("wb_lidar_get_layer_point_cloud"):
            return []
        return [point for point in self._s.points if point.layer == layer]

    @checked("get_number_of_points", 0)
    def getNumberOfPoints(self) -> int:
        """The number of points per scan (0 and an error when the point cloud is off)."""
        ok = self._cloud("wb_lidar_get_number_of_points")
        return self._s.resolution * self._s.layers if ok else 0

    @checked("enable_point_cloud")
    def enablePointCloud(self) -> None:
        """Also compute point clouds."""
        self._s.point_cloud = True
        self._queue("enablePointCloud")

    @checked("disable_point_cloud")
    def disablePointCloud(self) -> None:
        """Stop computing point clouds."""
        self._s.point_cloud = False
        self._queue("disablePointCloud")

    @checked("is_point_cloud_enabled", False)
    def isPointCloudEnabled(self) -> bool:
        """Whether point clouds are computed."""
        return self._s.point_cloud

    @checked("get_frequency", NAN)
    def getFrequency(self) -> float:
        """Rotation frequency of a rotating lidar (Hz)."""
        return self._s.frequency

    @checked("set_frequency")
    def setFrequency(self, frequency: float) -> None:
        """Change the rotation frequency within [minFrequency, maxFrequency]."""
        frequency = float(frequency)
        low, high = self.getMinFrequency(), self.getMaxFrequency()
        if frequency < low or frequency > high:
            _session.error(f"Error: wb_lidar_set_frequency() out of frequency range [{low:f}, {high:f}].")
            return
        self._s.frequency = frequency
        self._queue("setFrequency", frequency)

    @checked("get_horizontal_resolution", 0)
    def getHorizontalResolution(self) -> int:
        """Points per layer."""
        return self._s.resolution

    @checked("get_number_of_layers", 0)
    def getNumberOfLayers(self) -> int:
        """Number of layers."""
        return self._s.layers

    @checked("get_min_frequency", NAN)
    def getMinFrequency(self) -> float:
        """The ``minFrequency`` field (Hz)."""
        return float(self._s.field("minFrequency", 1.0))

    @checked("get_max_frequency", NAN)
    def getMaxFrequency(self) -> float:
        """The ``maxFrequency`` field (Hz)."""
        return float(self._s.field("maxFrequency", 25.0))

    @checked("get_fov", NAN)
    def getFov(self) -> float:
        """Horizontal field of view (rad)."""
        return float(self._s.field("fieldOfView", 1.5708))

    @checked("get_vertical_fov", NAN)
    def getVerticalFov(self) -> float:
        """Vertical field of view (rad)."""
        return float(self._s.field("verticalFieldOfView", 0.2))

    @checked("get_min_range", NAN)
    def getMinRange(self) -> float:
        """The ``minRange`` field (m)."""
        return float(self._s.field("minRange", 0.01))

    @checked("get_max_range", NAN)
    def getMaxRange(self) -> float:
        """The ``maxRange`` field (m)."""
        return float(self._s.field("maxRange", 1.0))

    range_image = property(getRangeImage, doc="The range image.")
    fov = property(getFov, doc="The horizontal field of view.")
    vertical_fov = property(getVerticalFov, doc="The vertical field of view.")
    max_frequency = property(getMaxFrequency, doc="The maxFrequency field.")
    min_frequency = property(getMinFrequency, doc="The minFrequency field.")
    max_range = property(getMaxRange, doc="The maxRange field.")
    min_range = property(getMinRange, doc="The minRange field.")
    horizontal_resolution = property(getHorizontalResolution, doc="Points per layer.")
    number_of_layers = property(getNumberOfLayers, doc="Number of layers.")
    frequency = property(getFrequency, setFrequency, doc="The rotation frequency.")
    number_of_points = property(getNumberOfPoints, doc="Points per scan.")
