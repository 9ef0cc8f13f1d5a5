"""Pieces shared by the JavaScript and Lua PROTO template engines.

A procedural PROTO body is VRML text with embedded template statements: ``%< code >%`` and
``%<= expression >%`` in JavaScript PROTOs, ``%{ code }%`` and ``%{= expression }%`` in Lua ones.
This module splits a body into text, code and expression chunks, converts field values the way
Webots hands them to templates, and maps engine errors back to places in the PROTO file.

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

#: Opening and closing tokens of template statements per language.
TOKENS: dict[str, tuple[str, str]] = {"javascript": ("%<", ">%"), "lua": ("%{", "}%")}

#: Webots release whose behaviour wbtc reproduces (passed as ``context.webots_version``).
DEFAULT_WEBOTS_VERSION = {"major": "R2025a", "revision": "0"}

_LUA_SPACE = " \t\n\v\f\r"


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
# Splitting a body into chunks


def strip_lua_vrml_comments(body: str) -> str:
    """Remove VRML ``#`` comments from a Lua template body, as Webots does before evaluating it.

    Per line, a ``#`` outside template statements and outside double quotes ends the line; the
    line breaks are kept so that line numbers do not move. Statement boundaries are tracked with
    the bare ``%{`` / ``}%`` digraphs and quotes with unescaped ``"``, exactly as simply as Webots
    tracks them.
    """
    if "#" not in body:
        return body
    inside_statement = False
    lines = []
    for line in body.split("\n"):
        inside_quotes = False
        previous = ""
        cut = len(line)
        for index, char in enumerate(line):
            if char == "{" and previous == "%":
                inside_statement = True
            elif char == "%" and previous == "}":
                inside_statement = False
            elif char == '"' and previous != "\\":
                inside_quotes = not inside_quotes
            elif char == "#" and not inside_statement and not inside_quotes:
                cut = index
                break
            previous = char
        lines.append(line[:cut])
    return "\n".join(lines)


def is_procedural(body: str, language: str) -> bool:
    """Whether Webots would treat a PROTO body as a template.

    Webots' tokenizer marks a PROTO as procedural when one of its tokens starts with the opening
    token. Statements that only occur inside VRML strings (``url "%<= x >%"``) or comments do not
    count: such a body is used as plain VRML and its statements are kept literally.

    Args:
        body: the PROTO body text.
        language: ``"javascript"`` or ``"lua"``.

    Returns:
        True when the body must go through the template engine.
    """
    opening = TOKENS[_language(language)][0]
    if opening not in body:
        return False
    # Runs of ordinary characters, comments and strings are matched (and skipped) as a whole;
    # a '%' counts when it begins the opening token at the start of a token, i.e. after a
    # separator (white space, ',' or a bracket).
    separators = " \t\r\n\v\f,{}[]"
    for match in _PROCEDURAL_SCAN.finditer(body):
        start = match.start()
        if (match.group() == "%" and body.startswith(opening, start)
                and (start == 0 or body[start - 1] in separators or body[start - 1].isspace())):
            return True
    return False


_PROCEDURAL_SCAN = re.compile(r'[^#"%]+|#[^\n]*|"(?:[^"\\\n]|\\.)*"?|%')


def split_template(body: str, language: str) -> list[Chunk]:
    """Split a template body into text, code and expression chunks.

    Consecutive text is merged into one chunk. For Lua the body must already have gone through
    `strip_lua_vrml_comments`.

    Args:
        body: the template text.
        language: ``"javascript"`` or ``"lua"``.

    Returns:
        The chunks in order; their offsets cover the body.

    Raises:
        TemplateSyntaxError: a statement has no closing token.
    """
    language = _language(language)
    opening, closing = TOKENS[language]
    find_close = _find_js_close if language == "javascript" else _find_lua_close
    chunks: list[Chunk] = []
    position = 0
    n = len(body)
    while position < n:
        start = body.find(opening, position)
        if start < 0:
            _add_text(chunks, body[position:], position, n)
            break
        if start > position:
            _add_text(chunks, body[position:start], position, start)
        inner_start = start + len(opening)
        comments: list[tuple[int, int]] = []
        close = find_close(body, inner_start, comments)
        if close < 0:
            # String tracking found no end (an odd literal such as a regex with a quote): fall
            # back on the plain search Webots itself uses, without blanking any comment.
            comments = []
            close = body.find(closing, inner_start)
        if close < 0:
            name = "JavaScript" if language == "javascript" else "Lua"
            raise TemplateSyntaxError(f"expected {name} closing token '{closing}' is missing", start)
        inner = _blank(body, inner_start, close, comments)
        chunks.append(_statement(inner, language, start, close + len(closing)))
        position = close + len(closing)
    return chunks


def _language(language: str) -> str:
    key = language.strip().lower()
    if key not in TOKENS:
        raise ValueError(f"unknown template language {language!r} (expected 'javascript' or 'lua')")
    return key


def _add_text(chunks: list[Chunk], text: str, start: int, end: int) -> None:
    if chunks and chunks[-1].kind == "text":
        previous = chunks[-1]
        previous.text += text
        previous.end = end
    else:
        chunks.append(Chunk("text", text, start, end))


def _statement(inner: str, language: str, start: int, end: int) -> Chunk:
    trim_left = trim_right = None
    if language == "lua":
        # liluat reads an optional trim marker right after the opening token and right before
        # the closing one: '-' trims the surrounding text, '+' keeps it.
        if inner[:1] in ("+", "-"):
            trim_left = inner[0] == "-"
            inner = inner[1:]
        if inner[-1:] in ("+", "-"):
            trim_right = inner[-1] == "-"
            inner = inner[:-1]
    if inner.startswith("="):
        return Chunk("expr", inner[1:], start, end, trim_left, trim_right)
    return Chunk("code", inner, start, end, trim_left, trim_right)


def _blank(body: str, start: int, end: int, comments: list[tuple[int, int]]) -> str:
    """``body[start:end]`` with comment ranges replaced by spaces (line breaks kept)."""
    if not comments:
        return body[start:end]
    parts = []
    cursor = start
    for first, last in comments:
        parts.append(body[cursor:first])
        parts.append(re.sub(r"[^\n]", " ", body[first:last]))
        cursor = last
    parts.append(body[cursor:end])
    return "".join(parts)


_JS_WORD = re.compile(r"[A-Za-z0-9_$]+")
_JS_REGEX_AFTER_CHARS = set("(,=:[!&|?{};+-*%<>~^}")
_JS_REGEX_AFTER_WORDS = {"return", "typeof", "instanceof", "in", "of", "new", "delete", "void",
                         "throw", "case", "do", "else", "yield", "await"}


def _find_js_close(src: str, i: int, comments: list[tuple[int, int]]) -> int:
    """Offset of the ``>%`` that ends a JavaScript statement starting at ``i``, or -1."""
    return _scan_js(src, i, comments, interpolation=False)


def _scan_js(src: str, i: int, comments: list[tuple[int, int]], *, interpolation: bool) -> int:
    # Scans code, skipping strings, template literals, regex literals and block comments. When
    # `interpolation` is set it scans the inside of a `${...}` and returns its closing brace.
    n = len(src)
    depth = 0
    previous = ""  # last significant token, to tell a regex literal from a division
    while i < n:
        char = src[i]
        if char == ">" and not interpolation and src.startswith(">%", i):
            return i
        if char.isspace():
            i += 1
            continue
        if interpolation and char in "{}":
            if char == "}":
                if depth == 0:
                    return i
                depth -= 1
            else:
                depth += 1
        if char == "/" and src.startswith("//", i):
            end = src.find("\n", i)
            end = n if end < 0 else end
            close = src.find(">%", i, end)
            if close >= 0 and not interpolation:
                comments.append((i, close))
                return close
            comments.append((i, end))
            i = end
            continue
        if char == "/" and src.startswith("/*", i):
            end = src.find("*/", i + 2)
            if end < 0:
                return -1
            i = end + 2
            continue
        if char == "/" and (previous == "" or previous in _JS_REGEX_AFTER_CHARS
                            or previous in _JS_REGEX_AFTER_WORDS):
            end = _skip_js_regex(src, i)
            if end > 0:
                i = end
                previous = "a"
                continue
        if char in "'\"":
            end = _skip_quoted(src, i)
            if end < 0:
                # No closing quote on this line: not a string after all, keep scanning.
                previous = char
                i += 1
                continue
            i = end
            previous = "a"
            continue
        if char == "`":
            j = i + 1
            while j < n and src[j] != "`":
                if src[j] == "\\":
                    j += 2
                elif src.startswith("${", j):
                    close = _scan_js(src, j + 2, comments, interpolation=True)
                    if close < 0:
                        return -1
                    j = close + 1
                else:
                    j += 1
            if j >= n:
                return -1
            i = j + 1
            previous = "a"
            continue
        match = _JS_WORD.match(src, i)
        if match:
            word = match.group()
            previous = word if word in _JS_REGEX_AFTER_WORDS else "a"
            i = match.end()
            continue
        previous = "a" if char in ")]" else char
        i += 1
    return -1


def _skip_js_regex(src: str, i: int) -> int:
    """Offset after the regex literal starting at ``i`` (flags included), or -1."""
    n = len(src)
    j = i + 1
    in_class = False
    while j < n:
        char = src[j]
        if char == "\n":
            return -1
        if char == "\\":
            j += 2
            continue
        if in_class:
            in_class = char != "]"
        elif char == "[":
            in_class = True
        elif char == "/":
            j += 1
            while j < n and (src[j].isalnum() or src[j] == "_"):
                j += 1
            return j
        j += 1
    return -1


def _skip_quoted(src: str, i: int) -> int:
    """Offset after the quoted string starting at ``i``, or -1 if the line ends first."""
    quote = src[i]
    n = len(src)
    j = i + 1
    while j < n:
        char = src[j]
        if char == "\\":
            if src.startswith("z", j + 1):  # Lua's \z skips the following white space
                j += 2
                while j < n and src[j] in _LUA_SPACE:
                    j += 1
                continue
            j += 2
            continue
        if char == quote:
            return j + 1
        if char == "\n":
            return -1
        j += 1
    return -1


_LUA_LONG_BRACKET = re.compile(r"\[(=*)\[")


def _find_lua_close(src: str, i: int, comments: list[tuple[int, int]]) -> int:
    """Offset of the ``}%`` that ends a Lua statement starting at ``i``, or -1."""
    n = len(src)
    while i < n:
        char = src[i]
        if char == "}" and src.startswith("}%", i):
            return i
        if char == "-" and src.startswith("--", i):
            long_open = _LUA_LONG_BRACKET.match(src, i + 2)
            if long_open:
                closing = "]" + long_open.group(1) + "]"
                end = src.find(closing, long_open.end())
                if end < 0:
                    return -1
                comments.append((i, end + len(closing)))
                i = end + len(closing)
                continue
            end = src.find("\n", i)
            end = n if end < 0 else end
            close = src.find("}%", i, end)
            if close >= 0:
                # liluat's plain search ends the statement here, inside the comment.
                comments.append((i, close))
                return close
            comments.append((i, end))
            i = end
            continue
        if char in "'\"":
            end = _skip_quoted(src, i)
            i = i + 1 if end < 0 else end
            continue
        if char == "[":
            long_open = _LUA_LONG_BRACKET.match(src, i)
            if long_open:
                closing = "]" + long_open.group(1) + "]"
                end = src.find(closing, long_open.end())
                if end < 0:
                    return -1
                i = end + len(closing)
                continue
        i += 1
    return -1


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
        # Output that template code appended without markers (e.g. to ___vrml directly) shows up
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
