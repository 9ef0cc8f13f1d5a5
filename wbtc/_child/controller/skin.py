"""``Skin``: a skinned mesh whose bones the controller moves."""

from __future__ import annotations

from . import _session
from .device import Device, checked

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any


class Skin(Device):
    """A Skin node; bone setters reach the simulator at the next step, bone getters ask it synchronously."""

    _C = "wb_skin"
    _TYPES = ("Skin",)

    def __init__(self, name: str | int) -> None:
        super().__init__(name)

    @checked("get_bone_count", 0)
    def getBoneCount(self) -> int:
        """Number of bones."""
        return len(self._s.info.get("bones") or [])

    @checked("get_bone_name", "")
    def getBoneName(self, index: int) -> str:
        """Name of a bone."""
        bones = self._s.info.get("bones") or []
        return str(bones[index]) if 0 <= index < len(bones) else ""

    @checked("get_bone_orientation")
    def getBoneOrientation(self, index: int, absolute: bool) -> Any:
        """Orientation of a bone (axis-angle), asked to the simulator."""
        function = "wb_skin_get_bone_orientation"
        return _session.require().call(self._tag, "getBoneOrientation", int(index), bool(absolute), function=function)

    @checked("get_bone_position")
    def getBonePosition(self, index: int, absolute: bool) -> Any:
        """Position of a bone, asked to the simulator."""
        function = "wb_skin_get_bone_position"
        return _session.require().call(self._tag, "getBonePosition", int(index), bool(absolute), function=function)

    @checked("set_bone_orientation")
    def setBoneOrientation(self, index: int, orientation: list[float], absolute: bool) -> None:
        """Rotate a bone (axis-angle)."""
        self._queue("setBoneOrientation", int(index), [float(v) for v in orientation[:4]], bool(absolute))

    @checked("set_bone_position")
    def setBonePosition(self, index: int, position: list[float], absolute: bool) -> None:
        """Move a bone."""
        self._queue("setBonePosition", int(index), [float(v) for v in position[:3]], bool(absolute))

    bone_count = property(getBoneCount, doc="Number of bones.")
