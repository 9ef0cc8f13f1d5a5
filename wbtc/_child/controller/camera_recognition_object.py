"""``CameraRecognitionObject``: one object a Camera's Recognition node sees, as Webots' controller gives it."""

from __future__ import annotations

from .sensor import NAN


class CameraRecognitionObject:
    """An object recognized by a camera, relative to the camera."""

    def __init__(self, data: dict) -> None:
        self.id = int(data.get("id", 0))
        self.position = [float(v) for v in data.get("position", (NAN, NAN, NAN))]
        self.orientation = [float(v) for v in data.get("orientation", (NAN, NAN, NAN, NAN))]
        self.size = [float(v) for v in data.get("size", (NAN, NAN))]
        self.position_on_image = [int(v) for v in data.get("position_on_image", (0, 0))]
        self.size_on_image = [int(v) for v in data.get("size_on_image", (0, 0))]
        colors: list[float] = []
        for color in data.get("colors") or []:
            colors.extend(float(c) for c in color) if isinstance(color, (list, tuple)) else colors.append(float(color))
        self.colors = colors
        self.number_of_colors = len(colors) // 3
        self.model = str(data.get("model") or "")

    def getId(self) -> int:
        """The node id of the object."""
        return self.id

    def getPosition(self) -> list[float]:
        """The position in the camera frame (m)."""
        return self.position

    def getOrientation(self) -> list[float]:
        """The orientation in the camera frame (axis-angle)."""
        return self.orientation

    def getSize(self) -> list[float]:
        """The size (m)."""
        return self.size

    def getPositionOnImage(self) -> list[int]:
        """The position on the image (pixels)."""
        return self.position_on_image

    def getSizeOnImage(self) -> list[int]:
        """The size on the image (pixels)."""
        return self.size_on_image

    def getNumberOfColors(self) -> int:
        """The number of recognition colors."""
        return self.number_of_colors

    def getColors(self) -> list[float]:
        """The recognition colors, flat [r, g, b, r, g, b, ...]."""
        return self.colors

    def getModel(self) -> str:
        """The object's model."""
        return self.model
