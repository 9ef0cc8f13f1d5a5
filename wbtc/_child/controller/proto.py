"""``Proto``: the PROTO a node is an instance of (Webots R2023b+ ``Node.getProto()``).

A PROTO whose body is an instance of another PROTO is *derived*; ``getParent()`` climbs that chain.
The fields of the node's own PROTO are its interface fields (the ``Field`` objects ``Node.getField``
gives); those of a parent PROTO are the values the derived PROTO gave it, read-only. The names of
Webots' released API (``getParent``, ``getField``, ``getFieldByIndex``, ``getNumberOfFields``) and
the earlier ones (``getProtoParent``, ``getParameter``...) both work.
"""

from __future__ import annotations

from . import _session

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

    from .field import Field


class Proto:
    """One level of a node's PROTO chain (level 1: the node's own PROTO)."""

    def __init__(self, node_id: int, names: list[str], level: int = 1) -> None:
        self._id = node_id
        self._names = list(names)
        self._level = level

    def _call(self, op: str, *args: Any, function: str) -> Any:
        return _session.require().call(_session.ROBOT_TAG, op, self._id, self._level, *args, function=function)

    def getTypeName(self) -> str:
        """The PROTO's name."""
        return self._names[self._level - 1]

    def getProtoParent(self) -> Proto | None:
        """The PROTO this one is derived from, or None."""
        return Proto(self._id, self._names, self._level + 1) if self.isDerived() else None

    def isDerived(self) -> bool:
        """Whether this PROTO's body is an instance of another PROTO."""
        return self._level < len(self._names)

    def getField(self, name: str) -> Field | None:
        """The field (interface parameter) with that name, or None."""
        from .field import Field

        function = "wb_supervisor_proto_get_field"
        if not name:
            _session.error(f"Error: {function}() called with a NULL or empty 'name' argument.")
            return None
        ref = self._call("proto.getParameter", str(name), function=function)
        return Field._from_ref(ref, read_only=True)  # Webots: a PROTO's fields are read-only views

    def getFieldByIndex(self, index: int) -> Field | None:
        """The field at ``index`` in the PROTO's interface order, or None."""
        from .field import Field

        function = "wb_supervisor_proto_get_field_by_index"
        if index < 0:
            _session.error(f"Error: {function}() called with a negative 'index' argument: {index}.")
            return None
        ref = self._call("proto.getParameterByIndex", int(index), function=function)
        return Field._from_ref(ref, read_only=True)  # Webots: a PROTO's fields are read-only views

    def getNumberOfFields(self) -> int:
        """How many fields (parameters) the PROTO declares."""
        count = self._call("proto.getNumberOfParameters", function="wb_supervisor_proto_get_number_of_fields")
        return int(count) if count is not None else -1

    getParent = getProtoParent
    getParameter = getField
    getParameterByIndex = getFieldByIndex
    getNumberOfParameters = getNumberOfFields

    @property
    def type_name(self) -> str:
        """The PROTO's name."""
        return self.getTypeName()

    @property
    def number_of_fields(self) -> int:
        """How many fields the PROTO declares."""
        return self.getNumberOfFields()

    number_of_parameters = number_of_fields
    is_derived = property(isDerived, doc="Whether this PROTO's body is an instance of another PROTO.")
