"""Pieces shared by the JavaScript and Lua PROTO template engines.

A procedural PROTO body is VRML text with embedded template statements: ``%< code >%`` and
``%<= expression >%`` in JavaScript PROTOs, ``%{ code }%`` and ``%{= expression }%`` in Lua ones.
This module holds the chunk and output types, converts field values the way Webots hands them to
templates, and maps engine errors back to places in the PROTO file (`template_split` splits a body
into chunks).

Behaviour reproduced from Webots (``WbTemplateEngine``, ``WbProtoTemplateEngine``, ``WbProtoModel``,
``WbTokenizer`` and the bundled ``liluat``):

* The engines find the end of a statement with a plain search for the closing token. wbtc also
  skips string literals (and Lua comments) on the way, as the Webots tokenizer does, so that a
  ``>%`` inside a JavaScript string does not end the statement; a closing token inside a
  ``//`` or ``--`` line comment still ends it, which is where the plain search stops too.
* In Lua PROTOs a VRML ``#`` comment outside statements and double quotes removes the rest of its
  line before evaluation (``#`` is Lua's length operator inside statements).
* Field values reach templates through text ``QString::arg(double)`` produced, i.e. with six
  significant digits (``%g``); string values are re-read as JavaScript (or Lua) string literals,
  so backslash sequences are interpreted.
"""

from __future__ import annotations

import bisect
import math
import numbers
import platform
import re
from dataclasses import dataclass, field
from pathlib import Path

from wbtc.errors import ProtoError, Span

#: Webots release whose behaviour wbtc reproduces (passed as ``context.webots_version``).
DEFAULT_WEBOTS_VERSION = {"major": "R2025a", "revision": "0"}



@dataclass(slots=True)
class Chunk:
    """One piece of a template body.

    Attributes:
        kind: ``"text"`` (plain VRML), ``"code"`` (statements) or ``"expr"`` (an expression).
        text: the VRML text, or the code between the tokens (without ``=`` and trim markers,
            with comments blanked out).
        start: offset of the chunk in the body (of its opening token for statements).
        end: offset just after the chunk (after its closing token for statements).
        trim_left: liluat's ``%{-`` / ``%{+`` marker (True / False), None when absent.
        trim_right: liluat's ``-}%`` / ``+}%`` marker, None when absent.
    """

    kind: str
    text: str
    start: int
    end: int
    trim_left: bool | None = None
    trim_right: bool | None = None


class TemplateSyntaxError(Exception):
    """A statement is not closed; ``offset`` is where its opening token is."""

    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message)
        self.offset = offset


@dataclass(frozen=True, slots=True)
class TemplateOutput:
    """The result of evaluating a template.

    Attributes:
        text: the generated VRML text.
        stdout: console output entries (``console.log``/``info``/``warn``/``debug``, Lua ``print``
            and ``io.stdout:write``).
        stderr: console error entries (``console.error``, the modules' error messages, Lua
            ``io.stderr:write``).
        console: every entry in the order Webots shows them (JavaScript: output then errors;
            Lua: errors then output).
        line_map: for each line of ``text`` (index 0 = first line), the PROTO file line it comes
            from: a text line maps to its own line, an expression value to the line of its
            statement.
    """

    text: str
    stdout: list[str] = field(default_factory=list)
    stderr: list[str] = field(default_factory=list)
    console: list[str] = field(default_factory=list)
    line_map: list[int] = field(default_factory=list)


class SourceMap:
    """Turns offsets and body lines into 1-based places in the PROTO file."""

    def __init__(self, body: str, proto_path: str, body_line: int, body_column: int) -> None:
        self.body = body
        self.proto_path = proto_path
        self.body_line = body_line
        self.body_column = body_column
        self._starts = [0] + [m.end() for m in re.finditer("\n", body)]

    @property
    def line_count(self) -> int:
        """Number of lines of the body."""
        return len(self._starts)

    def line_col(self, offset: int) -> tuple[int, int]:
        """1-based (line, column) of an offset, both relative to the body."""
        index = bisect.bisect_right(self._starts, offset) - 1
        return index + 1, offset - self._starts[index] + 1

    def span(self, line: int, column: int) -> Span:
        """The file place of a body-relative (line, column)."""
        line = min(max(line, 1), self.line_count)
        if line == 1:
            column += self.body_column - 1
        return Span(self.proto_path, self.body_line + line - 1, column)

    def span_at(self, offset: int) -> Span:
        """The file place of a body offset."""
        return self.span(*self.line_col(offset))

    def first_column(self, line: int) -> int:
        """Column of the first non-blank character of a body line (1 for a blank line)."""
        line = min(max(line, 1), self.line_count)
        start = self._starts[line - 1]
        end = self._starts[line] - 1 if line < self.line_count else len(self.body)
        text = self.body[start:end]
        stripped = text.lstrip()
        return len(text) - len(stripped) + 1 if stripped else 1


def proto_error(message: str, proto_path: str, span: Span | None) -> ProtoError:
    """The ProtoError wbtc raises for a template problem.

    Args:
        message: what went wrong, e.g. ``ReferenceError: foo is not defined``.
        proto_path: the PROTO file, whose name prefixes the message.
        span: where in the file, if known.

    Returns:
        ``ProtoError("template error in NAME.proto: MESSAGE", span)``.
    """
    name = Path(proto_path).name or proto_path
    return ProtoError(f"template error in {name}: {message}", span)


# --------------------------------------------------------------------------------------------
# Field values and context


def plain_value(value: object) -> object:
    """A field or context value reduced to Python builtins (numpy scalars and arrays included).

    Raises:
        TypeError: the value has no template equivalent.
    """
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, numbers.Integral):
        return int(value)
    if isinstance(value, numbers.Real):
        return float(value)
    if isinstance(value, dict):
        return {str(key): plain_value(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [plain_value(item) for item in value]
    tolist = getattr(value, "tolist", None)  # numpy arrays and scalars such as numpy.bool_
    if callable(tolist):
        return plain_value(tolist())
    raise TypeError(f"cannot pass a {type(value).__name__} to a template")


def qt_double(value: float) -> float:
    """A double as Webots passes it to templates: printed with ``%g`` (6 significant digits)."""
    if math.isnan(value) or math.isinf(value):
        return value
    return float(f"{value:.6g}")


def number(value: bool | int | float) -> bool | int | float:
    """Round floats like `qt_double`; booleans and integers pass through unchanged."""
    if isinstance(value, float):
        return qt_double(value)
    return value


_JS_SIMPLE_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "b": "\b", "f": "\f", "v": "\v", "0": "\0"}
_JS_ESCAPE = re.compile(r"\\(u\{[0-9A-Fa-f]+\}|u[0-9A-Fa-f]{4}|x[0-9A-Fa-f]{2}|\r\n|[\s\S])")


def js_string_value(text: str) -> str:
    r"""The string a template sees for an SFString value in a JavaScript PROTO.

    Webots writes the value between quotes into JavaScript source without escaping backslashes,
    so escape sequences such as ``\\n`` are interpreted by the engine; this reproduces that.
    """
    if "\\" not in text:
        return text

    def replace(match: re.Match[str]) -> str:
        code = match.group(1)
        if code in _JS_SIMPLE_ESCAPES:
            return _JS_SIMPLE_ESCAPES[code]
        if code[0] == "u" and code[1:2] == "{":
            return chr(int(code[2:-1], 16))
        if code[0] in "ux" and len(code) > 1:
            return chr(int(code[1:], 16))
        if code in ("\n", "\r", "\r\n", "\u2028", "\u2029"):
            return ""  # line continuation
        return code

    return _JS_ESCAPE.sub(replace, text)


_LUA_SIMPLE_ESCAPES = {"a": "\a", "b": "\b", "f": "\f", "n": "\n", "r": "\r", "t": "\t", "v": "\v",
                       "\n": "\n"}
_LUA_ESCAPE = re.compile(r"\\(x[0-9A-Fa-f]{2}|[0-9]{1,3}|z\s*|[\s\S])")


def lua_string_value(text: str) -> str:
    """The string a template sees for an SFString value in a Lua PROTO.

    Webots converts its JavaScript field text to Lua by plain replacements applied to the whole
    text, string contents included: ``[``/``]`` become ``{``/``}``, ``": "`` becomes ``" = "``
    and ``'`` becomes ``"``; Lua then interprets backslash escape sequences.
    """
    text = text.replace("[", "{").replace("]", "}").replace(": ", " = ").replace("'", '"')
    if "\\" not in text:
        return text

    def replace(match: re.Match[str]) -> str:
        code = match.group(1)
        if code in _LUA_SIMPLE_ESCAPES:
            return _LUA_SIMPLE_ESCAPES[code]
        if code[0] == "x" and len(code) == 3:
            return chr(int(code[1:], 16))
        if code[0].isdigit():
            return chr(int(code) % 256)
        if code[0] == "z":
            return ""
        return code

    return _LUA_ESCAPE.sub(replace, text)


def context_values(context: dict) -> dict:
    """The ``context`` object of a template, with Webots' keys, order and value types.

    Missing keys get neutral values (empty paths, ``"ENU"``, ``id`` 0, the running OS, the
    Webots version wbtc follows). ``id`` and ``webots_version.revision`` are strings, as Webots
    writes them between quotes. Extra keys are kept after the standard ones.
    """
    system = platform.system()
    default_os = "windows" if system == "Windows" else "mac" if system == "Darwin" else "linux"
    version = dict(DEFAULT_WEBOTS_VERSION)
    given_version = context.get("webots_version")
    if isinstance(given_version, dict):
        version.update({k: v for k, v in given_version.items() if v is not None})
    elif isinstance(given_version, str):
        version["major"] = given_version
    values = {
        "os": str(context.get("os") or default_os),
        "world": str(context.get("world") or ""),
        "proto": str(context.get("proto") or ""),
        "webots_home": str(context.get("webots_home") or ""),
        "project_path": str(context.get("project_path") or ""),
        "temporary_files_path": str(context.get("temporary_files_path") or ""),
        "id": str(context.get("id", 0)),
        "coordinate_system": str(context.get("coordinate_system") or "ENU"),
        "webots_version": {"major": str(version["major"]), "revision": str(version["revision"])},
    }
    for key, value in context.items():
        if key not in values:
            values[key] = value
    return values


def line_map(segments: list[int], text: str, source_map: SourceMap) -> list[int]:
    """File line of every output line, from the segments recorded by an engine.

    Each appended piece is described by five numbers: line breaks already in the output, line
    breaks in the piece, body line of its chunk (negative for an expression value), whether it
    ends with a line break, whether it is non-empty. A line belongs to the piece in which it
    starts; inside a text piece the body line advances with each line break.
    """
    lines: list[int] = []
    starts_line = True  # the next non-empty piece starts a new output line
    for k in range(0, len(segments) - 4, 5):
        before, breaks, line, ends_with_break, non_empty = segments[k:k + 5]
        if not non_empty:
            continue
        is_text = line > 0
        line = abs(line)
        # Output that template code appended without markers (e.g. to ___out directly) shows up
        # as missing line starts: give them the last known line.
        expected = before + (0 if starts_line else 1)
        while len(lines) < expected:
            lines.append(lines[-1] if lines else line)
        if starts_line:
            lines.append(line)
        last = breaks - 1 if ends_with_break else breaks
        for j in range(1, last + 1):
            lines.append(line + j if is_text else line)
        starts_line = bool(ends_with_break)
    total = text.count("\n") + 1
    while len(lines) < total:
        lines.append(lines[-1] if lines else 1)
    del lines[total:]
    body_line = source_map.body_line
    last_line = source_map.line_count
    return [body_line + min(max(line, 1), last_line) - 1 for line in lines]


def console_lines(stream_text: str) -> list[str]:
    """Split collected Lua stream text into lines the way Webots does (empty parts dropped)."""
    return [line for line in stream_text.split("\n") if line]
