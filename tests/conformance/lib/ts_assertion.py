"""wbtc's stand-in for Webots' test-suite helpers (`tests/lib/ts_assertion.h` and `ts_utils.h`).

The conformance controllers are Python ports of Webots' C test controllers; they call these
functions with the C names, expected values, tolerances and printf-style messages of the
originals, so that a port reads line for line like its source.

A controller calls `ts_setup(robot)` once its Robot exists, asserts, and ends with
`ts_send_success()`. A failed assertion prints `FAILURE with NAME: message` and ends the controller
with exit code 1, as the C helpers do. Each event is also appended to the file named by the
environment variable `WBTC_TS_RESULTS` (when set), one line each, which the conformance runner
reads: `START name pid`, `OK name pid`, `FAILURE name pid message`, or `EXIT name pid message`
when the controller ended without a verdict (an exception, or `step()` returning -1 first).

Comparisons follow the C macros: a double matches when both are NaN, both infinite, or within
the delta; so NaN matches only NaN.
"""

from __future__ import annotations

import atexit
import math
import os
import sys
import traceback
from collections.abc import Sequence
from typing import Any

_state: dict[str, Any] = {"name": None, "done": False}


def _record(kind: str, message: str = "") -> None:
    """Append one event line to the results file, if the runner asked for one."""
    path = os.environ.get("WBTC_TS_RESULTS")
    if not path:
        return
    flat = " ".join(message.split())
    with open(path, "a", encoding="utf-8") as out:
        out.write(f"{kind} {_state['name']} {os.getpid()} {flat}".rstrip() + "\n")


def _excepthook(kind: type[BaseException], value: BaseException, tb: Any) -> None:
    if not _state["done"] and _state["name"] is not None:
        last = traceback.format_exception_only(kind, value)[-1].strip()
        _state["done"] = True
        _record("EXIT", f"raised {last}")
    sys.__excepthook__(kind, value, tb)


def _at_exit() -> None:
    if not _state["done"] and _state["name"] is not None:
        _state["done"] = True
        _record("EXIT", "ended without ts_send_success()")


def ts_setup(robot: Any = None, name: str | None = None) -> None:
    """Register this controller as a test (C: `ts_setup(argv[0])`, after `wb_robot_init`)."""
    base = os.path.basename(name or sys.argv[0] or "controller")
    # The results file is space-separated: a name such as "template_nested (lua)" (the Lua variants'
    # controllerArgs) is written "template_nested_(lua)".
    _state["name"] = base.split(".")[0].replace(" ", "_")
    sys.excepthook = _excepthook
    atexit.register(_at_exit)
    _record("START")


def ts_send_success() -> None:
    """Report success and end the controller (C: `ts_send_success`)."""
    _state["done"] = True
    print(f"OK: {_state['name']}", flush=True)
    _record("OK")
    sys.exit(0)


def ts_send_error_and_exit(message: str, *args: Any) -> None:
    """Report a failure and end the controller with exit code 1."""
    text = message % args if args else message
    _state["done"] = True
    print(f"FAILURE with {_state['name']}: {text}", flush=True)
    _record("FAILURE", text)
    sys.exit(1)


def _check(correct: bool, message: str, args: tuple[Any, ...]) -> None:
    if not correct:
        ts_send_error_and_exit(message, *args)


def _in_delta(value: float, expected: float, delta: float) -> bool:
    """C's TS_DOUBLE_IN_DELTA: both NaN, both infinite, or within delta."""
    if math.isnan(value) and math.isnan(expected):
        return True
    if math.isinf(value) and math.isinf(expected):
        return True
    return abs(value - expected) <= delta


def ts_assert_boolean_equal(value: bool, message: str, *args: Any) -> None:
    """Fails unless `value` is true."""
    _check(bool(value), message, args)


def ts_assert_boolean_not_equal(value: bool, message: str, *args: Any) -> None:
    """Fails unless `value` is false."""
    _check(not value, message, args)


def ts_assert_pointer_null(value: Any, message: str, *args: Any) -> None:
    """Fails unless `value` is None (a NULL pointer in C)."""
    _check(value is None, message, args)


def ts_assert_pointer_not_null(value: Any, message: str, *args: Any) -> None:
    """Fails when `value` is None."""
    _check(value is not None, message, args)


def ts_assert_int_equal(value: int, expected: int, message: str, *args: Any) -> None:
    """Fails unless value == expected."""
    _check(value == expected, message, args)


def ts_assert_int_not_equal(value: int, not_expected: int, message: str, *args: Any) -> None:
    """Fails when value == not_expected."""
    _check(value != not_expected, message, args)


def ts_assert_int_in_delta(value: int, expected: int, delta: int, message: str, *args: Any) -> None:
    """Fails unless |value - expected| <= delta."""
    _check(abs(value - expected) <= delta, message, args)


def ts_assert_integers_in_delta(size: int, values: Sequence[int], expected: Sequence[int], delta: int, message: str,
                                *args: Any) -> None:
    """Fails unless the first `size` integers are each within delta."""
    _check(all(abs(values[i] - expected[i]) <= delta for i in range(size)), message, args)


def ts_assert_int_is_bigger(value: int, compared: int, message: str, *args: Any) -> None:
    """Fails unless value > compared."""
    _check(value > compared, message, args)


def ts_assert_double_equal(value: float, expected: float, message: str, *args: Any) -> None:
    """Fails unless value equals expected exactly (NaN matches NaN)."""
    _check(_in_delta(value, expected, 0.0), message, args)


def ts_assert_double_not_equal(value: float, not_expected: float, message: str, *args: Any) -> None:
    """Fails when value equals not_expected exactly."""
    _check(not _in_delta(value, not_expected, 0.0), message, args)


def ts_assert_double_in_delta(value: float, expected: float, delta: float, message: str, *args: Any) -> None:
    """Fails unless |value - expected| <= delta (NaN matches only NaN)."""
    _check(_in_delta(value, expected, delta), message, args)


def ts_assert_double_is_bigger(value: float, compared: float, message: str, *args: Any) -> None:
    """Fails unless value > compared."""
    _check(value > compared, message, args)


def ts_assert_vec3_equal(v0: float, v1: float, v2: float, e0: float, e1: float, e2: float, message: str,
                         *args: Any) -> None:
    """Fails unless the three values equal the three expected ones exactly."""
    _check(_in_delta(v0, e0, 0.0) and _in_delta(v1, e1, 0.0) and _in_delta(v2, e2, 0.0), message, args)


def ts_assert_vec3_in_delta(v0: float, v1: float, v2: float, e0: float, e1: float, e2: float, delta: float,
                            message: str, *args: Any) -> None:
    """Fails unless each of the three values is within delta of its expected value."""
    _check(_in_delta(v0, e0, delta) and _in_delta(v1, e1, delta) and _in_delta(v2, e2, delta), message, args)


def ts_assert_vec3_not_in_delta(v0: float, v1: float, v2: float, e0: float, e1: float, e2: float, delta: float,
                                message: str, *args: Any) -> None:
    """Fails when all three values are within delta of the given ones."""
    same = _in_delta(v0, e0, delta) and _in_delta(v1, e1, delta) and _in_delta(v2, e2, delta)
    _check(not same, message, args)


def ts_assert_doubles_equal(size: int, values: Sequence[float], expected: Sequence[float], message: str,
                            *args: Any) -> None:
    """Fails unless the first `size` doubles equal the expected ones exactly."""
    _check(all(_in_delta(values[i], expected[i], 0.0) for i in range(size)), message, args)


def ts_assert_doubles_in_delta(size: int, values: Sequence[float], expected: Sequence[float], delta: float,
                               message: str, *args: Any) -> None:
    """Fails unless the first `size` doubles are each within delta."""
    _check(all(_in_delta(values[i], expected[i], delta) for i in range(size)), message, args)


def ts_assert_doubles_out_delta(size: int, values: Sequence[float], expected: Sequence[float], delta: float,
                                message: str, *args: Any) -> None:
    """Fails when the first `size` doubles are all within delta."""
    _check(not all(_in_delta(values[i], expected[i], delta) for i in range(size)), message, args)


def _normal_angle(angle: float) -> float:
    while angle < -math.pi:
        angle += 2.0 * math.pi
    while angle > math.pi:
        angle -= 2.0 * math.pi
    return angle


def ts_assert_rotation_equals(rot_a: Sequence[float], rot_b: Sequence[float], tolerance: float, message: str,
                              *args: Any) -> None:
    """Fails unless two axis-angle rotations are the same (an axis and angle, or both negated)."""
    angle_a, angle_b = _normal_angle(rot_a[3]), _normal_angle(rot_b[3])
    correct = False
    for sign in (1.0, -1.0):
        if abs(angle_a - sign * angle_b) < tolerance:
            correct = abs(angle_a) < tolerance or all(abs(rot_a[i] - sign * rot_b[i]) < tolerance for i in range(3))
            break
    _check(correct, message, args)


def ts_assert_string_equal(value: str | None, expected: str | None, message: str, *args: Any) -> None:
    """Fails unless the strings are equal (two None match)."""
    _check(value == expected, message, args)


def ts_assert_string_contains(haystack: str | None, needle: str | None, message: str, *args: Any) -> None:
    """Fails unless `needle` is in `haystack` (two None match)."""
    if haystack is None or needle is None:
        correct = haystack is None and needle is None
    else:
        correct = needle in haystack
    _check(correct, message, args)


def ts_assert_color_in_delta(red: int, green: int, blue: int, e_red: int, e_green: int, e_blue: int, delta: int,
                             message: str, *args: Any) -> None:
    """Fails unless each colour channel is within delta."""
    correct = abs(red - e_red) <= delta and abs(green - e_green) <= delta and abs(blue - e_blue) <= delta
    _check(correct, message, args)
