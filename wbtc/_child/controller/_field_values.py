"""Field type constants and the value checks and conversions of ``Field`` (also used by ``Node``).

The checks are those of Webots' C library (NaN and FLT_MAX, rotation axis, colour range), printing its messages;
the conversions reproduce what the ctypes calls of Webots' Python package accept and raise.
"""

from __future__ import annotations

import math

from . import _session

TYPE_CHECKING = False  # typing itself is not imported: it costs a controller's start-up milliseconds
if TYPE_CHECKING:
    from typing import Any

FLT_MAX = 3.4028234663852886e38

SF_BOOL = 0x01
SF_INT32 = 0x02
SF_FLOAT = 0x03
SF_VEC2F = 0x04
SF_VEC3F = 0x05
SF_ROTATION = 0x06
SF_COLOR = 0x07
SF_STRING = 0x08
SF_NODE = 0x09
MF = 0x10
MF_BOOL = 0x11
MF_INT32 = 0x12
MF_FLOAT = 0x13
MF_VEC2F = 0x14
MF_VEC3F = 0x15
MF_ROTATION = 0x16
MF_COLOR = 0x17
MF_STRING = 0x18
MF_NODE = 0x19

TYPE_NAMES: dict[int, str] = {
    SF_BOOL: "SFBool", SF_INT32: "SFInt32", SF_FLOAT: "SFFloat", SF_VEC2F: "SFVec2f", SF_VEC3F: "SFVec3f",
    SF_ROTATION: "SFRotation", SF_COLOR: "SFColor", SF_STRING: "SFString", SF_NODE: "SFNode",
    MF_BOOL: "MFBool", MF_INT32: "MFInt32", MF_FLOAT: "MFFloat", MF_VEC2F: "MFVec2f", MF_VEC3F: "MFVec3f",
    MF_ROTATION: "MFRotation", MF_COLOR: "MFColor", MF_STRING: "MFString", MF_NODE: "MFNode",
}

#: Vector sizes of the float-vector types.
SIZES: dict[int, int] = {
    SF_VEC2F: 2, SF_VEC3F: 3, SF_ROTATION: 4, SF_COLOR: 3, MF_VEC2F: 2, MF_VEC3F: 3, MF_ROTATION: 4, MF_COLOR: 3,
}

_error = _session.error


def check_float(function: str, value: float) -> bool:
    """Webots' ``check_float``: NaN and values beyond FLT_MAX are refused with its message.

    Args:
        function: The C function name used in the error message.
        value: The number to check.

    Returns:
        Whether the value is acceptable.
    """
    if math.isnan(value):
        _error(f"Error: {function}() called with a NaN value.")
        return False
    if value > FLT_MAX:
        _error(f"Error: {function}() called with a value greater than FLX_MAX: {value:g} > {FLT_MAX:g}.")
        return False
    if value < -FLT_MAX:
        _error(f"Error: {function}() called with a value smaller than -FLX_MAX): {value:g} < {-FLT_MAX:g}.")
        return False
    return True


def check_vector(function: str, values: list[float]) -> bool:
    """Webots' ``check_vector``: every item passes ``check_float``.

    Args:
        function: The C function name used in the error message.
        values: The numbers to check.

    Returns:
        Whether every item is acceptable (the first bad one prints the error).
    """
    return all(check_float(function, v) for v in values)


def to_doubles(values: Any, size: int) -> list[float]:
    """What ``(ctypes.c_double * size)(*values)`` makes of ``values`` in Webots' Python package.

    Missing items are 0.0; too many raise IndexError and non-numbers TypeError, as ctypes does.

    Args:
        values: An iterable of numbers.
        size: The length of the C array.

    Returns:
        ``size`` floats.

    Raises:
        IndexError: More than ``size`` items.
        TypeError: An item is not a real number.
    """
    items = list(values)
    if len(items) > size:
        raise IndexError("invalid index")
    doubles = []
    for item in items:
        if isinstance(item, (str, bytes)) or not isinstance(item, (int, float)):
            raise TypeError(f"must be real number, not {type(item).__name__}")
        doubles.append(float(item))
    return doubles + [0.0] * (size - len(doubles))


def to_double(value: Any) -> float:
    """What ``ctypes.c_double(value)`` accepts: a real number.

    Args:
        value: The value to convert.

    Returns:
        The value as a float.

    Raises:
        TypeError: The value is not a real number.
    """
    if isinstance(value, (str, bytes)) or not isinstance(value, (int, float)):
        raise TypeError(f"must be real number, not {type(value).__name__}")
    return float(value)


def to_int(value: Any, position: int) -> int:
    """A Python int as ctypes passes it to an ``int`` parameter (anything else is refused).

    Args:
        value: The value to convert.
        position: The argument's position, for the ctypes error message.

    Returns:
        The value as an int.

    Raises:
        TypeError: The value is not an int.
    """
    if not isinstance(value, int):
        raise TypeError(f"argument {position}: Don't know how to convert parameter {position}")
    return int(value)


def to_str(value: Any) -> str:
    """What ``str.encode(value)`` accepts: a str.

    Args:
        value: The value to check.

    Returns:
        The value itself.

    Raises:
        TypeError: The value is not a str.
    """
    if not isinstance(value, str):
        raise TypeError(f"descriptor 'encode' for 'str' objects doesn't apply to a '{type(value).__name__}' object")
    return value


def valid_rotation(function: str, values: list[float]) -> bool:
    """Whether a rotation has a non-null axis (otherwise prints Webots' error).

    Args:
        function: The C function name used in the error message.
        values: The rotation, axis x, y, z and angle.

    Returns:
        Whether the axis is valid.
    """
    if values[0] == 0.0 and values[1] == 0.0 and values[2] == 0.0:
        _error(f"Error: {function}() called with invalid values for the [x y z] axis.")
        return False
    return True


def valid_color(function: str, values: list[float]) -> bool:
    """Whether every component of a colour is in [0, 1] (otherwise prints Webots' error).

    Args:
        function: The C function name used in the error message.
        values: The colour, r, g, b.

    Returns:
        Whether the colour is valid.
    """
    if not all(0.0 <= v <= 1.0 for v in values):
        _error(f"Error: {function}() called with invalid RGB values (outside [0,1] range).")
        return False
    return True


def valid_item(function: str, kind: int, value: Any) -> bool:
    """The C library's checks on a value of an SF type or an MF item.

    Args:
        function: The C function name used in the error message.
        kind: The field type (SF or MF).
        value: The value (an MF field: one item).

    Returns:
        Whether the value is acceptable.
    """
    base = kind & ~MF
    if base == SF_FLOAT:
        return check_float(function, value)
    if base in (SF_VEC2F, SF_VEC3F):
        return check_vector(function, value)
    if base == SF_ROTATION:
        return check_vector(function, value) and valid_rotation(function, value)
    if base == SF_COLOR:
        return valid_color(function, value)
    return True
