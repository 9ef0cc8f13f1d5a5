"""Splitting a procedural PROTO body into text, code and expression chunks (JavaScript and Lua).

A body holds ``%< code >%`` and ``%<= expression >%`` statements (JavaScript) or ``%{ code }%`` and
``%{= expression }%`` (Lua). As Webots' tokenizer does, the end of a statement is found by skipping
string literals (and Lua comments) on the way, so that a ``>%`` inside a JavaScript string does not
end it; a closing token inside a ``//`` or ``--`` line comment still ends it. In Lua PROTOs a VRML
``#`` comment outside statements and double quotes removes the rest of its line before evaluation.
"""

from __future__ import annotations

import re

from wbtc.proto.template_common import Chunk, TemplateSyntaxError

#: Opening and closing tokens of template statements per language.
TOKENS: dict[str, tuple[str, str]] = {"javascript": ("%<", ">%"), "lua": ("%{", "}%")}
_LUA_SPACE = " \t\n\v\f\r"


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
