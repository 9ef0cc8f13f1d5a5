"""Turn lark's parse exceptions into plain sentences a Webots user understands."""

from __future__ import annotations

import re

import lark

from wbtc.errors import Span, WbtSyntaxError
from wbtc.vrml.scan import open_brackets

_NAMES = {
    "ID": "a name",
    "NUMBERS": "a number",
    "STRING": "a string",
    "LBRACE": "'{'",
    "RBRACE": "'}'",
    "LSQB": "'['",
    "RSQB": "']'",
    "TRUE": "TRUE",
    "FALSE": "FALSE",
    "NULL": "NULL",
    "DEF": "DEF",
    "USE": "USE",
    "IS": "IS",
    "PROTO": "PROTO",
    "EXTERNPROTO": "EXTERNPROTO",
    "IMPORTABLE": "IMPORTABLE",
    "HIDDEN": "hidden",
    "FIELD_KW": "a field declaration",
    "FIELD_TYPE": "a field type",
    "$END": "the end of the file",
}
_WORD = re.compile(r"[^\s,\[\]{}#\"]+")


def _describe(token: lark.Token) -> str:
    if token.type == "$END":
        return "the end of the file"
    if token.type in ("ID", "NUMBERS"):
        return f"'{token.value.split()[0]}'" if token.value.strip() else _NAMES[token.type]
    if token.type == "STRING":
        return f"string {token.value}"
    return f"'{token.value}'"


def _expected(names: set[str]) -> str:
    if "RSQB" in names and "NUMBERS" in names:
        return "a value or ']'"
    if "RBRACE" in names and "ID" in names:
        return "a field name or '}'"
    words = sorted({_NAMES.get(name, name) for name in names})
    if len(words) > 4:
        return "a value"
    return " or ".join(words) if len(words) <= 2 else ", ".join(words[:-1]) + " or " + words[-1]


def _unclosed_hint(text: str, stop: int) -> str | None:
    still_open = open_brackets(text, stop)
    if not still_open:
        return None
    inner = still_open[-1]
    closer = "]" if inner.char == "[" else "}"
    return f"the '{inner.char}' at line {inner.line}, column {inner.column} is still open: is a '{closer}' missing?"


def syntax_error_from_lark(exc: lark.exceptions.UnexpectedInput, text: str, path: str) -> WbtSyntaxError:
    """Build the WbtSyntaxError for a lark exception, with a message and a hint."""
    if isinstance(exc, lark.exceptions.UnexpectedCharacters):
        return _bad_character(exc, text, path)
    token = getattr(exc, "token", None)
    expected = set(getattr(exc, "expected", ()) or getattr(exc, "accepts", ()) or ())
    if token is None or token.type == "$END":
        return _unexpected_end(text, path, expected)
    span = Span(path, token.line, token.column)
    found = _describe(token)
    if token.type == "IS" or (token.type == "ID" and token.value == "IS"):
        return WbtSyntaxError("'IS' is only allowed in a field of a PROTO body", span)
    if token.type in ("RSQB", "RBRACE"):
        if not open_brackets(text, token.start_pos):
            opener = "[" if token.type == "RSQB" else "{"
            return WbtSyntaxError(f"unexpected {found}: there is no open '{opener}' to close", span)
        still_open = open_brackets(text, token.start_pos)
        opener = "[" if token.type == "RSQB" else "{"
        hint = _unclosed_hint(text, token.start_pos) if still_open[-1].char != opener else None
        return WbtSyntaxError(f"unexpected {found}: expected {_expected(expected)}", span, hint=hint)
    if expected == {"LBRACE"}:
        return _not_a_value(text, token, path)
    if token.type == "LBRACE" and "ID" in expected:
        return WbtSyntaxError("unexpected '{': a node type name must come before '{'", span)
    if "RBRACE" in expected and token.type in ("NUMBERS", "STRING", "TRUE", "FALSE", "NULL", "LSQB"):
        return WbtSyntaxError(f"unexpected {found}: expected a field name or '}}'", span,
                              hint="a value has more parts than its field takes, or a field name is missing")
    return WbtSyntaxError(f"unexpected {found}: expected {_expected(expected)}", span)


def _not_a_value(text: str, token: lark.Token, path: str) -> WbtSyntaxError:
    """A name stood where a value was expected (`name = "gps"`): lark read it as a node type."""
    words = list(re.finditer(r"[^\s,\[\]{}#\"]+", text[:token.start_pos]))
    if not words:
        return WbtSyntaxError(f"unexpected {_describe(token)}: expected '{{'", Span(path, token.line, token.column))
    word = words[-1]
    line = text.count("\n", 0, word.start()) + 1
    column = word.start() - (text.rfind("\n", 0, word.start()) + 1) + 1
    span = Span(path, line, column)
    if word.group().startswith(("%<", "%{")):
        return WbtSyntaxError("template statements ('%<', '%{') are only allowed in a PROTO body", span)
    if word.group()[0].isupper():
        return WbtSyntaxError(f"expected '{{' after node type {word.group()}, found {_describe(token)}",
                              Span(path, token.line, token.column))
    still_open = open_brackets(text, word.start())
    if still_open and still_open[-1].char == "[":  # a field name inside a list: the list was not closed
        opener = still_open[-1]
        return WbtSyntaxError(f"'{word.group()}' cannot be an item of the list opened at line {opener.line}", span,
                              hint=_unclosed_hint(text, word.start()))
    return WbtSyntaxError(f"'{word.group()}' is not a field value", span,
                          hint="write the value right after the field name, e.g. name \"gps\"")


def _bad_character(exc: lark.exceptions.UnexpectedCharacters, text: str, path: str) -> WbtSyntaxError:
    span = Span(path, exc.line, exc.column)
    char = exc.char
    if char == '"':
        return WbtSyntaxError("unclosed string: a string must end with '\"' on the same line", span)
    word = _WORD.match(text, exc.pos_in_stream)
    word_text = word.group() if word else char
    if char in "+-.0123456789":
        return WbtSyntaxError(f"invalid number '{word_text}'", span)
    if char == "%":
        return WbtSyntaxError("template statements ('%<', '%{') are only allowed in a PROTO body", span)
    if char == "\\":
        return WbtSyntaxError("unexpected '\\' outside a string", span)
    return WbtSyntaxError(f"unexpected character '{char}'", span)


def _unexpected_end(text: str, path: str, expected: set[str]) -> WbtSyntaxError:
    still_open = open_brackets(text)
    if still_open:
        inner = still_open[-1]
        closer = "]" if inner.char == "[" else "}"
        return WbtSyntaxError(f"'{inner.char}' is never closed: missing '{closer}'",
                              Span(path, inner.line, inner.column),
                              hint="the file ends before its matching bracket")
    line = text.count("\n") + 1
    column = len(text) - (text.rfind("\n") + 1) + 1
    return WbtSyntaxError(f"unexpected end of file: expected {_expected(expected)}", Span(path, line, column))
