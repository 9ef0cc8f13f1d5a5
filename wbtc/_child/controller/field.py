"""``Field``: one field of a scene-tree node, read and written through the Supervisor API.

Reads ask the simulator (``field.get``); writes are buffered and leave with the next step, and until then a read
of what was just written answers the written value, as Webots' C library does. Inserting, removing and importing
are immediate in Webots: they are queued and then flushed (see ``_session.Session.flush``).

The argument checks follow Webots: the SF setters go through the ``value`` property, which accepts only the exact
Python type (``bool``, ``int``, ``float``, ``str``, or a ``list`` of the right length) and otherwise prints
``Error: new field value has wrong type or length.``; the C library's checks (field type, index bounds, NaN and
FLT_MAX, rotation axis, colour range, read-only PROTO internal fields) print its messages. As in Webots' Python
package, ``getSFFloat()`` and its siblings return the field's value whatever its SF type.

The type constants, value checks and conversions live in ``_field_values``; the MF item accessors (``getMF*``,
``setMF*``, ``insertMF*``, ``removeMF``, ``importMFNodeFromString``) in ``_field_mf``, whose ``MFItems`` ``Field``
inherits.
"""

from __future__ import annotations

import operator

from . import _session
from ._field_mf import MFItems
from ._field_values import (
    FLT_MAX,  # noqa: F401 (re-exported)
    MF,
    MF_BOOL,
    MF_COLOR,
    MF_FLOAT,
    MF_INT32,
    MF_NODE,
    MF_ROTATION,
    MF_STRING,
    MF_VEC2F,
    MF_VEC3F,
    SF_BOOL,
    SF_COLOR,
    SF_FLOAT,
    SF_INT32,
    SF_NODE,
    SF_ROTATION,
    SF_STRING,
    SF_VEC2F,
    SF_VEC3F,
    SIZES,
    TYPE_NAMES,
    check_float,  # noqa: F401 (re-exported)
    check_vector,  # noqa: F401 (re-exported)
    to_double,  # noqa: F401 (re-exported)
    to_doubles,
    to_str,
    valid_item,
)

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

    from .node import Node

ROBOT_TAG = _session.ROBOT_TAG
NAN = _session.NAN

_error = _session.error


class Field(MFItems):
    """A field of a node (or of a PROTO's base node); ``Node.getField()`` gives the one object per field."""

    SF_BOOL = SF_BOOL
    SF_INT32 = SF_INT32
    SF_FLOAT = SF_FLOAT
    SF_VEC2F = SF_VEC2F
    SF_VEC3F = SF_VEC3F
    SF_ROTATION = SF_ROTATION
    SF_COLOR = SF_COLOR
    SF_STRING = SF_STRING
    SF_NODE = SF_NODE
    MF = MF
    MF_BOOL = MF_BOOL
    MF_INT32 = MF_INT32
    MF_FLOAT = MF_FLOAT
    MF_VEC2F = MF_VEC2F
    MF_VEC3F = MF_VEC3F
    MF_ROTATION = MF_ROTATION
    MF_COLOR = MF_COLOR
    MF_STRING = MF_STRING
    MF_NODE = MF_NODE

    def __init__(self, ref: dict, read_only: bool = False) -> None:
        """Wrap a field ref of the wire protocol; use ``Field._from_ref`` so that each field has one object."""
        self._id = int(ref["id"])
        self._name = str(ref.get("name") or "")
        self.type: int = int(ref.get("type") or 0)
        self._count = int(ref.get("count", -1))
        self._count_epoch = _session.require().epoch
        self._read_only = read_only

    @classmethod
    def _from_ref(cls, ref: dict | None, read_only: bool = False) -> Field | None:
        """The Field object for a field ref (the same object each time for one field id), or None."""
        if not ref:
            return None
        session = _session.require()
        # A read-only view (a PROTO level's field, a base node's field) is another object than the field
        # itself, as in Webots: writing through it is refused, getActualField leads to the writable one.
        table = session.view_fields if read_only else session.fields
        field = table.get(int(ref["id"]))
        if field is None:
            field = cls(ref, read_only)
            table[field._id] = field
        else:
            if "count" in ref:
                field._count = int(ref["count"])
                field._count_epoch = session.epoch
        return field

    # -- description ------------------------------------------------------------------------------------------
    def getName(self) -> str:
        """The field's name."""
        return self.name

    def getType(self) -> int:
        """The field's type, ``Field.SF_BOOL`` ... ``Field.MF_NODE``."""
        return self.type

    def getTypeName(self) -> str:
        """The field's type as in VRML: ``"SFVec3f"``, ``"MFNode"``..."""
        return self.type_name

    def getCount(self) -> int:
        """The number of items of an MF field; -1 for an SF field."""
        return self.count

    def getActualField(self) -> Field | None:
        """The scene-tree field this one is linked to by IS (itself for a scene-tree field); None if unlinked."""
        function = "wb_supervisor_field_get_actual_field"
        session = _session.require()
        if not session.check_supervisor(function):
            return None
        ref = session.call(ROBOT_TAG, "field.getActualField", self._id, function=function)
        return Field._from_ref(ref)

    def enableSFTracking(self, samplingPeriod: int) -> None:
        """Webots streams the field's value every period; wbtc always asks afresh, so only the check remains."""
        if samplingPeriod < 0:
            _error("Error: wb_supervisor_field_enable_sf_tracking() called with negative sampling period.")

    def disableSFTracking(self) -> None:
        """Stop the tracking (nothing to stop in wbtc)."""

    @property
    def name(self) -> str:
        """The field's name."""
        return self._name

    @property
    def type_name(self) -> str:
        """The field's type name."""
        return TYPE_NAMES.get(self.type, "")

    @property
    def count(self) -> int:
        """The number of items of an MF field; -1 for an SF field."""
        return self._current_count() if self.type & MF else -1

    # -- plumbing ---------------------------------------------------------------------------------------------
    def _current_count(self) -> int:
        session = _session.require()
        if self._count_epoch != session.epoch:
            count = session.call(ROBOT_TAG, "field.getCount", self._id, function="wb_supervisor_field_get_count")
            if count is not None:
                self._count = int(count)
                self._count_epoch = session.epoch
        return self._count

    def _check(
        self, function: str, expected: int, index: Any = None, check_type: bool = True, importing: bool = False,
        writing: bool = False,
    ) -> int | None:
        """Webots' ``check_field``: the resolved index (-1 for SF) or None after printing the error."""
        if writing and self._read_only:
            _error(f"Error: {function}() called on a read-only PROTO internal field.")
            return None
        if check_type and self.type != expected:
            _error(f"Error: {function}() called with wrong field type: {self.type_name}.")
            return None
        if not expected & MF:
            return -1
        index = operator.index(index)
        count = self._current_count() if self.type & MF else -1
        offset = 0 if importing else -1
        if index < -(count + 1 + offset) or index > count + offset:
            if count == 0:
                _error(f"Error: {function}() called on an empty list.")
            else:
                _error(
                    f"Error: {function}() called with an out-of-bound index: {index} (should be between "
                    f"{-count - 1 - offset} and {count + offset})."
                )
            return None
        return index + count + 1 + offset if index < 0 else index

    def _get(self, function: str, index: int) -> Any:
        session = _session.require()
        if not session.check_supervisor(function):
            return None
        key = (self._id, index)
        if key in session.pending_fields:
            return session.pending_fields[key]
        return session.call(ROBOT_TAG, "field.get", self._id, index, function=function)

    def _set(self, function: str, index: int, value: Any) -> None:
        session = _session.require()
        if not session.check_supervisor(function):
            return
        session.queue(ROBOT_TAG, "field.set", self._id, index, value)
        session.pending_fields[(self._id, index)] = value

    def _immediate(self, function: str, op: str, *args: Any) -> None:
        """Queue an operation Webots performs at once, then flush it."""
        session = _session.require()
        if not session.check_supervisor(function):
            return
        session.queue(ROBOT_TAG, op, self._id, *args)
        session.flush(function)

    def _writable(self, function: str) -> bool:
        if self._read_only:
            _error(f"Error: {function}() called on a read-only PROTO internal field.")
            return False
        return True

    def _node(self, ref: Any) -> Node | None:
        from .node import Node

        return Node._from_ref(ref, internal=self._read_only)

    # -- SF values --------------------------------------------------------------------------------------------
    @property
    def value(self) -> Any:
        """The value of an SF field (None for an MF field); setting it checks the Python type strictly."""
        kind = self.type
        if kind == SF_BOOL:
            result = self._get("wb_supervisor_field_get_sf_bool", -1)
            return bool(result) if result is not None else False
        if kind == SF_INT32:
            result = self._get("wb_supervisor_field_get_sf_int32", -1)
            return int(result) if result is not None else 0
        if kind == SF_FLOAT:
            result = self._get("wb_supervisor_field_get_sf_float", -1)
            return float(result) if result is not None else 0.0
        if kind == SF_STRING:
            result = self._get("wb_supervisor_field_get_sf_string", -1)
            return str(result) if result is not None else ""
        if kind in (SF_VEC2F, SF_VEC3F, SF_ROTATION, SF_COLOR):
            function = "wb_supervisor_field_get_sf_" + TYPE_NAMES[kind][2:].lower()
            result = self._get(function, -1)
            size = SIZES[kind]
            return [float(v) for v in result[:size]] if result is not None else [NAN] * size
        if kind == SF_NODE:
            return self.getSFNode()
        return None

    @value.setter
    def value(self, value: Any) -> None:
        kind = self.type
        if kind == SF_BOOL and isinstance(value, bool):
            self._set_sf("wb_supervisor_field_set_sf_bool", value)
        elif kind == SF_INT32 and isinstance(value, int):
            self._set_sf("wb_supervisor_field_set_sf_int32", int(value))
        elif kind == SF_FLOAT and isinstance(value, float):
            self._set_sf("wb_supervisor_field_set_sf_float", value)
        elif kind == SF_STRING and isinstance(value, str):
            self._set_sf("wb_supervisor_field_set_sf_string", value)
        elif kind in SIZES and not kind & MF and isinstance(value, list) and len(value) == SIZES[kind]:
            doubles = to_doubles(value, SIZES[kind])
            self._set_sf("wb_supervisor_field_set_sf_" + TYPE_NAMES[kind][2:].lower(), doubles)
        else:
            _error("Error: new field value has wrong type or length.")

    def _set_sf(self, function: str, value: Any) -> None:
        if not self._writable(function):
            return
        if not self._valid_item(function, self.type, value):
            return
        self._set(function, -1, value)

    _valid_item = staticmethod(valid_item)

    def getSFBool(self) -> bool:
        """The value of the field (Webots' Python package returns ``value`` whatever the SF type)."""
        return self.value

    def getSFInt32(self) -> int:
        """The value of the field."""
        return self.value

    def getSFFloat(self) -> float:
        """The value of the field."""
        return self.value

    def getSFVec2f(self) -> list[float]:
        """The value of the field."""
        return self.value

    def getSFVec3f(self) -> list[float]:
        """The value of the field."""
        return self.value

    def getSFRotation(self) -> list[float]:
        """The value of the field (axis x, y, z and angle)."""
        return self.value

    def getSFColor(self) -> list[float]:
        """The value of the field (r, g, b)."""
        return self.value

    def getSFString(self) -> str:
        """The value of the field."""
        return self.value

    def getSFNode(self) -> Node | None:
        """The node of an SFNode field, or None."""
        function = "wb_supervisor_field_get_sf_node"
        if self._check(function, SF_NODE) is None:
            return None
        return self._node(self._get(function, -1))

    def setSFBool(self, value: bool) -> None:
        """Set the value (sent with the next step)."""
        self.value = value

    def setSFInt32(self, value: int) -> None:
        """Set the value (sent with the next step)."""
        self.value = value

    def setSFFloat(self, value: float) -> None:
        """Set the value (sent with the next step); it must be a ``float``."""
        self.value = value

    def setSFVec2f(self, value: list[float]) -> None:
        """Set the value, a ``list`` of two numbers (sent with the next step)."""
        if len(value) == 2:
            self.value = value
        else:
            _error("Error: setSFVec2f(): length of 'value' argument should be 2.")

    def setSFVec3f(self, value: list[float]) -> None:
        """Set the value, a ``list`` of three numbers (sent with the next step)."""
        if len(value) == 3:
            self.value = value
        else:
            _error("Error: setSFVec3f(): length of 'value' argument should be 3.")

    def setSFRotation(self, value: list[float]) -> None:
        """Set the value, a ``list`` [x, y, z, angle] (sent with the next step)."""
        if len(value) == 4:
            self.value = value
        else:
            _error("Error: setSFRotation(): length of 'value' argument should be 4.")

    def setSFColor(self, value: list[float]) -> None:
        """Set the value, a ``list`` [r, g, b] in [0, 1] (sent with the next step)."""
        if len(value) == 3:
            self.value = value
        else:
            _error("Error: setSFColor(): length of 'value' argument should be 3.")

    def setSFString(self, value: str) -> None:
        """Set the value (sent with the next step)."""
        self.value = value

    # -- SF nodes (MF nodes: MFItems.importMFNodeFromString) --------------------------------------------------
    def importSFNodeFromString(self, nodeString: str) -> None:
        """Put the node described in VRML by ``nodeString`` into an empty SFNode field."""
        function = "wb_supervisor_field_import_sf_node_from_string"
        if not self._writable(function):
            return
        if self.type != SF_NODE:
            _error(f"Error: {function}() called with a wrong field type: {self.type_name}.")
            return
        if not nodeString:
            _error(f"Error: {function}() called with a NULL or empty 'node_string' argument.")
            return
        if self._get(function, -1) is not None:
            _error(f"Error: {function}() called with a non-empty field.")
            return
        self._immediate(function, "field.importSFNode", to_str(nodeString))

    def removeSF(self) -> None:
        """Remove the node of an SFNode field."""
        function = "wb_supervisor_field_remove_sf"
        if self.type == SF_NODE and self._get(function, -1) is None:
            _error(f"Error: {function}() called for an empty field.")
            return
        if self._check(function, SF_NODE, writing=True) is None:
            return
        self._immediate(function, "field.removeSF")

    def __repr__(self) -> str:
        return f"<Field {self._name!r} {self.type_name}>"
