"""The MF item accessors of ``Field``: ``getMF*``, ``setMF*``, ``insertMF*``, ``removeMF`` and ``importMFNode...``.

``Field`` inherits them from ``MFItems``; they rely on its plumbing (``_check``, ``_get``, ``_set``,
``_immediate``, ``_node``...), declared here for type checkers only. Reads and writes of items behave as the SF
values do (writes leave with the next step); inserts and removals are immediate, as in Webots.
"""

from __future__ import annotations

import operator

from . import _session
from ._field_values import (
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
    SIZES,
    to_double,
    to_doubles,
    to_int,
    to_str,
)

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

    from .node import Node

NAN = _session.NAN

_error = _session.error


class MFItems:
    """The item accessors of an MF field, mixed into ``Field``."""

    if TYPE_CHECKING:
        type: int
        type_name: str
        _count: int

        def _writable(self, function: str) -> bool: ...

        def _current_count(self) -> int: ...

        def _check(
            self, function: str, expected: int, index: Any = None, check_type: bool = True, importing: bool = False,
            writing: bool = False,
        ) -> int | None: ...

        def _get(self, function: str, index: int) -> Any: ...

        def _set(self, function: str, index: int, value: Any) -> None: ...

        def _immediate(self, function: str, op: str, *args: Any) -> None: ...

        def _node(self, ref: Any) -> Node | None: ...

        @staticmethod
        def _valid_item(function: str, kind: int, value: Any) -> bool: ...

    # -- reads ------------------------------------------------------------------------------------------------
    def _get_mf(self, suffix: str, kind: int, index: int) -> tuple[bool, Any]:
        function = f"wb_supervisor_field_get_mf_{suffix}"
        resolved = self._check(function, kind, index)
        if resolved is None:
            return False, None
        return True, self._get(function, resolved)

    def _get_mf_vector(self, suffix: str, kind: int, index: int) -> list[float]:
        ok, result = self._get_mf(suffix, kind, index)
        if not ok:
            raise ValueError("NULL pointer access")  # what Webots' Python package hits after the C error
        size = SIZES[kind]
        return [float(v) for v in result[:size]] if result is not None else [NAN] * size

    def getMFBool(self, index: int) -> bool:
        """Item ``index`` (negative: from the end)."""
        return bool(self._get_mf("bool", MF_BOOL, index)[1])

    def getMFInt32(self, index: int) -> int:
        """Item ``index`` (negative: from the end)."""
        result = self._get_mf("int32", MF_INT32, index)[1]
        return int(result) if result is not None else 0

    def getMFFloat(self, index: int) -> float:
        """Item ``index`` (negative: from the end)."""
        result = self._get_mf("float", MF_FLOAT, index)[1]
        return float(result) if result is not None else 0.0

    def getMFString(self, index: int) -> str:
        """Item ``index`` (negative: from the end)."""
        result = self._get_mf("string", MF_STRING, index)[1]
        return str(result) if result is not None else ""

    def getMFVec2f(self, index: int) -> list[float]:
        """Item ``index`` (negative: from the end)."""
        return self._get_mf_vector("vec2f", MF_VEC2F, index)

    def getMFVec3f(self, index: int) -> list[float]:
        """Item ``index`` (negative: from the end)."""
        return self._get_mf_vector("vec3f", MF_VEC3F, index)

    def getMFRotation(self, index: int) -> list[float]:
        """Item ``index`` (negative: from the end)."""
        return self._get_mf_vector("rotation", MF_ROTATION, index)

    def getMFColor(self, index: int) -> list[float]:
        """Item ``index`` (negative: from the end)."""
        return self._get_mf_vector("color", MF_COLOR, index)

    def getMFNode(self, index: int) -> Node | None:
        """Node ``index`` (negative: from the end), or None."""
        return self._node(self._get_mf("node", MF_NODE, index)[1])

    # -- writes -----------------------------------------------------------------------------------------------
    def _set_mf(self, suffix: str, kind: int, index: int, value: Any) -> None:
        function = f"wb_supervisor_field_set_mf_{suffix}"
        resolved = self._check(function, kind, index, writing=True)
        if resolved is None or not self._valid_item(function, kind, value):
            return
        self._set(function, resolved, value)

    def setMFBool(self, index: int, value: bool) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("bool", MF_BOOL, index, bool(value))

    def setMFInt32(self, index: int, value: int) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("int32", MF_INT32, index, to_int(value, 3))

    def setMFFloat(self, index: int, value: float) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("float", MF_FLOAT, index, to_double(value))

    def setMFVec2f(self, index: int, value: list[float]) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("vec2f", MF_VEC2F, index, to_doubles(value, 2))

    def setMFVec3f(self, index: int, value: list[float]) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("vec3f", MF_VEC3F, index, to_doubles(value, 3))

    def setMFRotation(self, index: int, value: list[float]) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("rotation", MF_ROTATION, index, to_doubles(value, 4))

    def setMFColor(self, index: int, value: list[float]) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("color", MF_COLOR, index, to_doubles(value, 3))

    def setMFString(self, index: int, value: str) -> None:
        """Set item ``index`` (sent with the next step)."""
        self._set_mf("string", MF_STRING, index, to_str(value))

    # -- inserts, removals and node imports (immediate) -------------------------------------------------------
    def _insert_mf(self, suffix: str, kind: int, index: int, value: Any) -> None:
        function = f"wb_supervisor_field_insert_mf_{suffix}"
        resolved = self._check(function, kind, index, importing=True, writing=True)
        if resolved is None or not self._valid_item(function, kind, value):
            return
        self._count += 1
        self._immediate(function, "field.insert", resolved, value)

    def insertMFBool(self, index: int, value: bool) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("bool", MF_BOOL, index, bool(value))

    def insertMFInt32(self, index: int, value: int) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("int32", MF_INT32, index, to_int(value, 3))

    def insertMFFloat(self, index: int, value: float) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("float", MF_FLOAT, index, to_double(value))

    def insertMFVec2f(self, index: int, value: list[float]) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("vec2f", MF_VEC2F, index, to_doubles(value, 2))

    def insertMFVec3f(self, index: int, value: list[float]) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("vec3f", MF_VEC3F, index, to_doubles(value, 3))

    def insertMFRotation(self, index: int, value: list[float]) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("rotation", MF_ROTATION, index, to_doubles(value, 4))

    def insertMFColor(self, index: int, value: list[float]) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("color", MF_COLOR, index, to_doubles(value, 3))

    def insertMFString(self, index: int, value: str) -> None:
        """Insert an item before ``index`` (``count`` or -1: at the end)."""
        self._insert_mf("string", MF_STRING, index, to_str(value))

    def removeMF(self, index: int) -> None:
        """Remove item ``index`` of an MF field (negative: from the end)."""
        function = "wb_supervisor_field_remove_mf"
        if self.type & MF and self._current_count() == 0:
            _error(f"Error: {function}() called for an empty field.")
            return
        resolved = self._check(function, MF, index, check_type=False, writing=True)
        if resolved is None:
            return
        self._count -= 1
        self._immediate(function, "field.remove", resolved)

    def importMFNodeFromString(self, position: int, nodeString: str) -> None:
        """Insert the node described in VRML by ``nodeString`` before ``position`` (-1: at the end)."""
        function = "wb_supervisor_field_import_mf_node_from_string"
        if not self._writable(function):
            return
        if self.type != MF_NODE:
            _error(f"Error: {function}() called with a wrong field type: {self.type_name}.")
            return
        if not nodeString:
            _error(f"Error: {function}() called with a NULL or empty 'node_string' argument.")
            return
        position = operator.index(position)
        count = self._current_count()
        if position < -(count + 1) or position > count:
            _error(
                f"Error: {function}() called with an out-of-bound index: {position} (should be between "
                f"{-(count + 1)} and {count})."
            )
            return
        if position < 0:
            position = count + position + 1
        self._count += 1
        self._immediate(function, "field.importMFNode", position, to_str(nodeString))
