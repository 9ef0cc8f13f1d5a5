"""``Camera``: BGRA images, plus object recognition when the camera has a Recognition node."""

from __future__ import annotations

import math

from . import _images, _session
from .camera_recognition_object import CameraRecognitionObject
from .device import checked
from .sensor import NAN, Sensor

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


def _node(state: _session.DeviceState, name: str) -> dict | None:
    node = state.field(name)
    if not isinstance(node, dict):
        return None
    fields = node.get("fields")
    return fields if isinstance(fields, dict) else node


class Camera(Sensor):
    """A Camera node: ``getImage()`` returns 4·width·height BGRA bytes (None before the first sample)."""

    _C = "wb_camera"
    _TYPES = ("Camera",)

    @staticmethod
    def _setup(state: _session.DeviceState, session: _session.Session) -> None:
        state.width = int(state.field("width", 64))
        state.height = int(state.field("height", 64))
        state.fov = float(state.field("fieldOfView", 0.785398))
        state.near = float(state.field("near", 0.01))
        state.exposure = float(state.field("exposure", 1.0))
        state.planar = str(state.field("projection", "planar")) == "planar" and not state.field("spherical", False)
        zoom, focus, recognition = _node(state, "zoom"), _node(state, "focus"), _node(state, "recognition")
        state.min_fov = float(zoom.get("minFieldOfView", 0.5)) if zoom else state.fov
        state.max_fov = float(zoom.get("maxFieldOfView", 1.5)) if zoom else state.fov
        focus = focus or {}
        state.focal_length = float(focus.get("focalLength", 0.0))
        state.focal_distance = float(focus.get("focalDistance", 0.0))
        state.min_focal_distance = float(focus.get("minFocalDistance", 0.0))
        state.max_focal_distance = float(focus.get("maxFocalDistance", 0.0))
        state.has_recognition = recognition is not None
        state.segmentation = bool(recognition.get("segmentation", False)) if recognition else False
        state.segmentation_enabled = False
        state.segmentation_image = None
        state.recognition_period = 0
        state.objects = []
        state.value = None

    @staticmethod
    def _absorb(state: _session.DeviceState, value: Any) -> None:
        width, height = int(value.get("width", state.width)), int(value.get("height", state.height))
        image = _images.image_bytes(value, 4 * width * height)
        if image is not None:
            state.value = image
        if value.get("objects") is not None:
            state.objects = [CameraRecognitionObject(obj) for obj in value["objects"]]
        if value.get("has_segmentation") is not None:
            # Webots tells the controller when the Recognition node's `segmentation` field changes,
            # and turning it off turns the segmentation images off.
            state.segmentation = bool(value["has_segmentation"])
            state.segmentation_enabled = state.segmentation_enabled and state.segmentation
        if value.get("segmentation") is not None:
            state.segmentation_image = bytes(value["segmentation"])

    # -- image ----------------------------------------------------------------------------------------------
    @checked("get_image")
    def getImage(self) -> bytes | None:
        """The last image: BGRA bytes, pixel (x, y) at offset 4·(y·width + x).

        None before the camera is enabled and until a step has passed since; from then on, until
        its first sample, a black image (Webots' image memory exists once the step that follows
        the enable has run, filled with zeros).
        """
        state = self._s
        if state.period <= 0:
            _session.error("Error: wb_camera_get_image() called for a disabled device! Please use: wb_camera_enable().")
            return None
        if state.value is None and _session.require().time > state.enabled_at:
            return bytes(4 * self.getWidth() * self.getHeight())
        return state.value

    def _set_period(self, period: int) -> None:
        super()._set_period(period)
        if period and self._s.enabled_at == math.inf:
            self._s.enabled_at = _session.require().time

    def getImageArray(self) -> list[list[list[int]]] | None:
        """The image as ``width`` lists of ``height`` [r, g, b] pixels, filled in memory order like Webots does."""
        image = self.getImage()
        if not image:
            return None
        width, height = self.getWidth(), self.getHeight()
        array = []
        i = 0
        for _ in range(width):
            line = []
            for _ in range(height):
                line.append([image[i + 2], image[i + 1], image[i]])
                i += 4
            array.append(line)
        return array

    @staticmethod
    def imageGetRed(image: bytes, width: int, x: int, y: int) -> int:
        """The red byte of pixel (x, y)."""
        return image[4 * (y * width + x) + 2]

    @staticmethod
    def imageGetGreen(image: bytes, width: int, x: int, y: int) -> int:
        """The green byte of pixel (x, y)."""
        return image[4 * (y * width + x) + 1]

    @staticmethod
    def imageGetBlue(image: bytes, width: int, x: int, y: int) -> int:
        """The blue byte of pixel (x, y)."""
        return image[4 * (y * width + x)]

    @staticmethod
    def imageGetGray(image: bytes, width: int, x: int, y: int) -> float:
        """The mean of the red, green and blue bytes of pixel (x, y), as a float."""
        i = 4 * (y * width + x)
        return (image[i + 2] + image[i + 1] + image[i]) / 3

    @checked("save_image", -1)
    def saveImage(self, filename: str, quality: int) -> int:
        """Save the last image as PNG or JPEG (``quality`` 1-100); returns 0 on success, -1 otherwise."""
        image = self._s.value
        rgba = None if image is None else _images.bgra_to_rgba(image)
        return _images.save_image("wb_camera_save_image", filename, quality, self._s.width, self._s.height, rgba)

    # -- geometry and optics --------------------------------------------------------------------------------
    @checked("get_width", -1)
    def getWidth(self) -> int:
        """Image width (pixels)."""
        return self._s.width

    @checked("get_height", -1)
    def getHeight(self) -> int:
        """Image height (pixels)."""
        return self._s.height

    @checked("get_fov", NAN)
    def getFov(self) -> float:
        """Horizontal field of view (rad)."""
        return self._s.fov

    @checked("get_min_fov", NAN)
    def getMinFov(self) -> float:
        """Smallest field of view of the zoom (rad)."""
        return self._s.min_fov

    @checked("get_max_fov", NAN)
    def getMaxFov(self) -> float:
        """Largest field of view of the zoom (rad)."""
        return self._s.max_fov

    @checked("set_fov")
    def setFov(self, fov: float) -> None:
        """Change the field of view within the zoom range."""
        state, fov = self._s, float(fov)
        if not state.planar and not 0.0 <= fov <= 2.0 * math.pi:
            _session.error("Error: wb_camera_set_fov() called with 'fov' argument outside of the [0, 2.0*pi] range.")
        elif state.planar and not 0.0 <= fov <= math.pi:
            _session.error("Error: wb_camera_set_fov() called with 'fov' argument outside of the [0, pi] range.")
        elif fov < state.min_fov or fov > state.max_fov:
            _session.error(f"Error: wb_camera_set_fov() out of zoom range [{state.min_fov:f}, {state.max_fov:f}].")
        else:
            state.fov = fov
            self._queue("setFov", fov)

    @checked("get_exposure", NAN)
    def getExposure(self) -> float:
        """Exposure (J/m²)."""
        return self._s.exposure

    @checked("set_exposure")
    def setExposure(self, exposure: float) -> None:
        """Change the exposure (>= 0)."""
        exposure = float(exposure)
        if exposure < 0:
            _session.error("Error: 'exposure' argument of wb_camera_set_exposure() can't be negative.")
            return
        self._s.exposure = exposure
        self._queue("setExposure", exposure)

    @checked("get_focal_length", NAN)
    def getFocalLength(self) -> float:
        """Focal length (m)."""
        return self._s.focal_length

    @checked("get_focal_distance", NAN)
    def getFocalDistance(self) -> float:
        """Focal distance (m)."""
        return self._s.focal_distance

    @checked("get_min_focal_distance", NAN)
    def getMinFocalDistance(self) -> float:
        """Smallest focal distance (m)."""
        return self._s.min_focal_distance

    @checked("get_max_focal_distance", NAN)
    def getMaxFocalDistance(self) -> float:
        """Largest focal distance (m)."""
        return self._s.max_focal_distance

    @checked("set_focal_distance")
    def setFocalDistance(self, focalDistance: float) -> None:
        """Change the focal distance within the focus range (planar cameras)."""
        state, distance = self._s, float(focalDistance)
        if not state.planar:
            _session.error("Error: wb_camera_set_focal_distance() can only be called on a planar camera.")
        elif distance < state.min_focal_distance or distance > state.max_focal_distance:
            _session.error(
                "Error: wb_camera_set_focal_distance() out of focus range "
                f"[{state.min_focal_distance:f}, {state.max_focal_distance:f}]."
            )
        else:
            state.focal_distance = distance
            self._queue("setFocalDistance", distance)

    @checked("get_near", NAN)
    def getNear(self) -> float:
        """Near clipping distance (m)."""
        return self._s.near

    # -- recognition ----------------------------------------------------------------------------------------
    def _recognition(self, function: str) -> bool:
        if not self._s.has_recognition:
            _session.error(f"Error: {function}() called on a Camera without Recognition node.")
            return False
        return True

    def _recognition_enabled(self, function: str) -> bool:
        if not self._recognition(function):
            return False
        if self._s.recognition_period == 0:
            _session.error(
                f"Error: {function}() called for a disabled device! Please use: wb_camera_recognition_enable()."
            )
            return False
        return True

    @checked("has_recognition", False)
    def hasRecognition(self) -> bool:
        """Whether the camera has a Recognition node."""
        return self._s.has_recognition

    @checked("recognition_enable")
    def recognitionEnable(self, samplingPeriod: int) -> None:
        """Recognize objects every ``samplingPeriod`` ms."""
        period = int(samplingPeriod)
        if period < 0:
            _session.error("Error: wb_camera_recognition_enable() called with negative sampling period.")
        elif self._recognition("wb_camera_recognition_enable"):
            self._s.recognition_period = period
            if period:
                self._queue("recognitionEnable", period)
            else:
                self._queue("recognitionDisable")

    @checked("recognition_disable")
    def recognitionDisable(self) -> None:
        """Stop recognizing objects."""
        if self._recognition("wb_camera_recognition_disable"):
            self._s.recognition_period = 0
            self._queue("recognitionDisable")

    @checked("recognition_get_sampling_period", 0)
    def getRecognitionSamplingPeriod(self) -> int:
        """The recognition sampling period (ms)."""
        return self._s.recognition_period if self._recognition("wb_camera_recognition_get_sampling_period") else 0

    @checked("recognition_get_number_of_objects", 0)
    def getRecognitionNumberOfObjects(self) -> int:
        """The number of objects recognized at the last sample."""
        ok = self._recognition_enabled("wb_camera_recognition_get_number_of_objects")
        return len(self._s.objects) if ok else 0

    @checked("recognition_get_objects", [])
    def getRecognitionObjects(self) -> list[CameraRecognitionObject]:
        """The objects recognized at the last sample."""
        return list(self._s.objects) if self._recognition_enabled("wb_camera_recognition_get_objects") else []

    @checked("recognition_has_segmentation", False)
    def hasRecognitionSegmentation(self) -> bool:
        """Whether the Recognition node has segmentation on."""
        return self._s.segmentation

    @checked("recognition_enable_segmentation")
    def enableRecognitionSegmentation(self) -> None:
        """Ask for segmentation images, made with each recognition sample."""
        if not self._recognition_enabled("wb_camera_recognition_enable_segmentation"):
            return
        if not self._s.segmentation:
            _session.error(
                "Error: wb_camera_recognition_enable_segmentation(): segmentation is disabled in Recognition node."
            )
            return
        self._s.segmentation_enabled = True
        self._queue("enableSegmentation")

    @checked("recognition_disable_segmentation")
    def disableRecognitionSegmentation(self) -> None:
        """Stop asking for segmentation images."""
        if self._recognition("wb_camera_recognition_disable_segmentation"):
            self._s.segmentation_enabled = False
            self._s.segmentation_image = None
            self._queue("disableSegmentation")

    @checked("recognition_is_segmentation_enabled", False)
    def isRecognitionSegmentationEnabled(self) -> bool:
        """Whether segmentation images were asked for."""
        ok = self._recognition("wb_camera_recognition_is_segmentation_enabled")
        return ok and self._s.segmentation_enabled

    @checked("recognition_get_segmentation_image")
    def getRecognitionSegmentationImage(self) -> bytes | None:
        """The last segmentation image (BGRA, like `getImage`); None while segmentation is off.

        Until the first one arrives, a black image (Webots fills the image memory with opaque black).
        """
        state = self._s
        if not state.segmentation_enabled:
            return None
        if state.segmentation_image is None:
            return bytes([0, 0, 0, 255]) * (self.getWidth() * self.getHeight())
        return state.segmentation_image

    def getRecognitionSegmentationImageArray(self) -> list[list[list[int]]] | None:
        """The segmentation image as ``width`` lists of ``height`` [r, g, b] pixels, as `getImageArray`."""
        image = self.getRecognitionSegmentationImage()
        if not image:
            return None
        width, height = self.getWidth(), self.getHeight()
        pixels = iter(range(0, 4 * width * height, 4))
        return [[[image[i + 2], image[i + 1], image[i]] for i in (next(pixels) for _ in range(height))]
                for _ in range(width)]

    def saveRecognitionSegmentationImage(self, filename: str, quality: int) -> int:
        """Save the segmentation image as PNG or JPEG; returns 0 on success, -1 otherwise (none to save)."""
        image = self.getRecognitionSegmentationImage()
        rgba = None if image is None else _images.bgra_to_rgba(image)
        return _images.save_image("wb_camera_recognition_save_segmentation_image", filename, quality,
                                  self._s.width, self._s.height, rgba)

    image = property(getImage, doc="The last image.")
    segmentation_image = property(getRecognitionSegmentationImage, doc="The last segmentation image.")
    exposure = property(getExposure, setExposure, doc="The exposure.")
    focal_distance = property(getFocalDistance, setFocalDistance, doc="The focal distance.")
    focal_length = property(getFocalLength, doc="The focal length.")
    max_focal_distance = property(getMaxFocalDistance, doc="The largest focal distance.")
    min_focal_distance = property(getMinFocalDistance, doc="The smallest focal distance.")
    fov = property(getFov, setFov, doc="The field of view.")
    min_fov = property(getMinFov, doc="The smallest field of view.")
    max_fov = property(getMaxFov, doc="The largest field of view.")
    width = property(getWidth, doc="The image width.")
    height = property(getHeight, doc="The image height.")
    near = property(getNear, doc="The near clipping distance.")
