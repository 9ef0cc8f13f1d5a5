"""Typed field values: checking untyped syntax against a field type, and printing values back.

Type mapping (what a scene holds for each VRML type):

| VRML type | Python value |
|---|---|
| SFBool, SFInt32, SFFloat, SFString | bool, int, float, str |
| SFVec2f, SFVec3f, SFColor, SFRotation | `Vec2f`, `Vec3f`, `Color`, `Rotation` (named tuples) |
| SFNode | a node object, or None for NULL |
| MFBool, MFString, MFNode | list of the SF values |
| MFInt32, MFFloat | 1-D numpy array (int64, float64) |
| MFVec2f, MFVec3f, MFColor, MFRotation | n×2, n×3, n×3, n×4 numpy float64 array |

Numeric lists are arrays because real worlds hold IndexedFaceSets of tens of thousands of numbers
and the compiler wants them as arrays anyway.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, NamedTuple

import numpy as np

from wbtc.errors import SchemaError, Span
from wbtc.vrml import syntax as s


class Vec2f(NamedTuple):
    """An SFVec2f value."""

    x: float
    y: float


class Vec3f(NamedTuple):
    """An SFVec3f value."""

    x: float
    y: float
    z: float


class Color(NamedTuple):
    """An SFColor value (components in 0..1)."""

    r: float
    g: float
    b: float


class Rotation(NamedTuple):
    """An SFRotation value: axis (x, y, z) and angle in radians."""

    x: float
    y: float
    z: float
    angle: float


#: Number of floats in one element of each numeric type.
ARITY = {"Int32": 1, "Float": 1, "Vec2f": 2, "Vec3f": 3, "Color": 3, "Rotation": 4}
_TUPLES: dict[str, Callable[..., tuple[float, ...]]] = {
    "Vec2f": Vec2f, "Vec3f": Vec3f, "Color": Color, "Rotation": Rotation,
}
_DESCRIBE = {
    "Bool": "TRUE or FALSE", "Int32": "an integer", "Float": "a number", "Vec2f": "2 numbers",
    "Vec3f": "3 numbers", "Color": "3 numbers (red green blue)", "Rotation": "4 numbers (axis x y z, angle)",
    "String": "a string in double quotes", "Node": "a node, USE or NULL",
}

_ITEM_WORDS = {"Bool": "TRUE or FALSE", "String": "strings in double quotes", "Node": "nodes or USE"}


def is_mf(field_type: str) -> bool:
    """True for MF types."""
    return field_type.startswith("MF")


def element_type(field_type: str) -> str:
    """'MFVec3f' -> 'Vec3f'; 'SFBool' -> 'Bool'."""
    return field_type[2:]


def expected_text(field_type: str) -> str:
    """What one value of this type looks like, in words."""
    base = _DESCRIBE[element_type(field_type)]
    return f"a list of {base.removeprefix('a ').removeprefix('an ')} values in [ ]" if is_mf(field_type) else base


def _describe_found(value: s.Value | Any) -> str:
    if isinstance(value, s.Numbers):
        count = len(value.tokens())
        return f"{count} number{'s' if count != 1 else ''}"
    if isinstance(value, s.String):
        return "a string"
    if isinstance(value, s.Bool):
        return "TRUE" if value.value else "FALSE"
    if isinstance(value, s.Null):
        return "NULL"
    if isinstance(value, s.MFList):
        return "a list in [ ]"
    if isinstance(value, s.IsRef):
        return "IS"
    return "a node"


def _to_float(token: str, span: Span) -> float:
    try:
        return float(token)
    except ValueError:
        raise SchemaError(f"invalid number '{token}'", span) from None


def _to_int(token: str, span: Span, what: str) -> int:
    try:
        return int(token)
    except ValueError:
        number = _to_float(token, span)
        if not number.is_integer():
            raise SchemaError(f"{what} must be an integer, found '{token}'", span) from None
        return int(number)


def _numbers(tokens: list[str], span: Span) -> list[float]:
    try:
        return [float(t) for t in tokens]
    except ValueError:
        bad = next(t for t in tokens if not _is_float(t))
        raise SchemaError(f"invalid number '{bad}'", span) from None


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def coerce(value: Any, field_type: str, what: str, is_node: Callable[[Any], bool]) -> Any:
    """Check an untyped value against a field type and return the typed value.

    Args:
        value: the syntax value, in which nodes may already be built into node objects.
        field_type: the VRML type ("SFVec3f", "MFNode", ...).
        what: how to name the field in messages ("field 'size' of Box").
        is_node: tells whether an object is a built node (SFNode values).

    Returns:
        The typed value (see the module's table).

    Raises:
        SchemaError: the value does not fit the type.
    """
    elem = element_type(field_type)
    span = getattr(value, "span", None)
    if isinstance(value, s.IsRef):
        raise SchemaError("'IS' is only allowed in a field of a PROTO body", span)
    if not is_mf(field_type):
        return _coerce_single(value, elem, what, is_node, field_type)
    if isinstance(value, s.MFList):
        items = value.items
    elif isinstance(value, s.Null) and elem == "Node":
        return []  # Webots reads NULL as no node at all (WbMFNode appends only the nodes it reads)
    else:
        items = [value]  # one element may be written without brackets
    return _coerce_list(items, elem, what, is_node, field_type, span)


def _coerce_single(value: Any, elem: str, what: str, is_node: Callable[[Any], bool], field_type: str) -> Any:
    span = getattr(value, "span", None)
    if elem in ARITY:
        if not isinstance(value, s.Numbers):
            raise SchemaError(f"{what} is an {field_type}: expected {_DESCRIBE[elem]}, found {_describe_found(value)}",
                              span)
        tokens = value.tokens()
        if len(tokens) != ARITY[elem]:
            raise SchemaError(f"{what} is an {field_type}: expected {_DESCRIBE[elem]}, found {len(tokens)}", span)
        if elem == "Int32":
            return _to_int(tokens[0], span, what)
        numbers = _numbers(tokens, span)
        return numbers[0] if elem == "Float" else _TUPLES[elem](*numbers)
    if elem == "Bool" and isinstance(value, s.Bool):
        return value.value
    if elem == "String" and isinstance(value, s.String):
        return value.value
    if elem == "Node":
        if isinstance(value, s.Null):
            return None
        if is_node(value):
            return value
    raise SchemaError(f"{what} is an {field_type}: expected {_DESCRIBE[elem]}, found {_describe_found(value)}", span)


def _coerce_list(items: list[Any], elem: str, what: str, is_node: Callable[[Any], bool], field_type: str,
                 span: Span | None) -> Any:
    if elem in ARITY:
        tokens: list[str] = []
        for item in items:
            if not isinstance(item, s.Numbers):
                raise SchemaError(f"{what} is an {field_type}: its items must be numbers, found "
                                  f"{_describe_found(item)}", getattr(item, "span", span))
            tokens.extend(item.tokens())
        arity = ARITY[elem]
        if len(tokens) % arity:
            raise SchemaError(f"{what} is an {field_type}: expected groups of {arity} numbers, found "
                              f"{len(tokens)} numbers", span)
        if elem == "Int32":
            return np.array([_to_int(t, span, what) for t in tokens], dtype=np.int64)
        array = np.array(_numbers(tokens, span), dtype=np.float64)
        return array if arity == 1 else array.reshape(-1, arity)
    typed = []
    for item in items:
        if elem == "Node" and isinstance(item, s.Null):
            continue  # as above: a NULL item adds nothing
        try:
            typed.append(_coerce_single(item, elem, what, is_node, "SF" + elem))
        except SchemaError:
            raise SchemaError(f"{what} is an {field_type}: its items must be {_ITEM_WORDS[elem]}, found "
                              f"{_describe_found(item)}", getattr(item, "span", span)) from None
    return typed


# --- printing -------------------------------------------------------------------------------------

def format_number(number: float | int) -> str:
    """Shortest text that reads back to the same number (integers without '.0')."""
    if isinstance(number, bool):
        raise TypeError("a bool is not a number")
    if isinstance(number, int | np.integer):
        return str(int(number))
    number = float(number)
    if math.isnan(number) or math.isinf(number):
        raise ValueError(f"{number} has no VRML form")
    if number.is_integer() and abs(number) < 1e16:
        return str(int(number)) if number != 0 or math.copysign(1.0, number) > 0 else "-0"
    return repr(number)


def quote(text: str) -> str:
    """A VRML string literal for `text` (only double quotes and backslashes need escaping)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def format_value(value: Any, field_type: str, format_node: Callable[[Any], str] | None = None) -> str:
    """Print a typed value as VRML text that `parse_value` + `coerce` read back to the same value.

    Args:
        value: the typed value.
        field_type: its VRML type.
        format_node: prints a node (needed only for SFNode/MFNode values).

    Returns:
        The VRML text.
    """
    elem = element_type(field_type)
    if is_mf(field_type):
        if elem in ARITY:
            flat = np.asarray(value).reshape(-1, ARITY[elem])
            rows = [" ".join(format_number(v) for v in row) for row in flat.tolist()]
            return "[ " + ", ".join(rows) + " ]" if rows else "[]"
        parts = [format_value(v, "SF" + elem, format_node) for v in value]
        return "[ " + " ".join(parts) + " ]" if parts else "[]"
    if elem in ARITY:
        numbers = [value] if ARITY[elem] == 1 else list(value)
        return " ".join(format_number(v) for v in numbers)
    if elem == "Bool":
        return "TRUE" if value else "FALSE"
    if elem == "String":
        return quote(value)
    if value is None:
        return "NULL"
    if format_node is None:
        raise ValueError("format_node is needed to print node values")
    return format_node(value)
