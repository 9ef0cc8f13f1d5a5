"""A light scanner for brackets: splits PROTO files and explains unbalanced brackets.

It knows only what matters for bracket matching: strings (with backslash escapes) and `#`
comments. It never runs on the fast path of a valid world: the parser uses it to find where a
PROTO body starts (template bodies are not VRML) and, after a syntax error, to name the bracket
that was left open.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass

from wbtc.errors import Span, WbtSyntaxError

_INTERESTING = re.compile(r'"(?:[^"\\\n]|\\.)*"?|#[^\n]*|[\[\]{}]|\bPROTO\b')
_CLOSERS = {"]": "[", "}": "{"}


@dataclass(frozen=True, slots=True)
class Bracket:
    """An opening bracket and where it is."""

    char: str
    offset: int
    line: int
    column: int


def _tokens(text: str, stop: int | None = None) -> Iterator[re.Match[str]]:
    for match in _INTERESTING.finditer(text, 0, len(text) if stop is None else stop):
        if match.group()[0] not in '"#':
            yield match


def _line_col(text: str, offset: int) -> tuple[int, int]:
    line = text.count("\n", 0, offset) + 1
    column = offset - (text.rfind("\n", 0, offset) + 1) + 1
    return line, column


def open_brackets(text: str, stop: int | None = None) -> list[Bracket]:
    """The brackets still open at `stop` (the whole text by default), outermost first.

    A closing bracket of the wrong kind pops nothing, so the innermost open bracket stays the one
    the writer most likely forgot to close.
    """
    stack: list[tuple[str, int]] = []
    for match in _tokens(text, stop):
        char = match.group()
        if char in "[{":
            stack.append((char, match.start()))
        elif char in _CLOSERS and stack and stack[-1][0] == _CLOSERS[char]:
            stack.pop()
    return [Bracket(char, offset, *_line_col(text, offset)) for char, offset in stack]


@dataclass(frozen=True, slots=True)
class ProtoSplit:
    """Where a PROTO file's interface ends and its body starts."""

    head_end: int
    body_start: int
    body_line: int
    body_column: int


def split_proto(text: str, path: str) -> ProtoSplit:
    """Find the end of the interface (after its `]`) and the start of the body (its `{`).

    Raises:
        WbtSyntaxError: there is no `PROTO Name [ ... ] {` in the file.
    """
    depth = 0
    state = "before"
    for match in _tokens(text):
        token = match.group()
        if state == "before":
            if token == "PROTO":
                state = "interface"
            continue
        if state == "interface":
            if token in "[{":
                depth += 1
            elif token in "]}":
                depth -= 1
                if depth == 0 and token == "]":
                    state = "after"
                    head_end = match.end()
            continue
        if token == "{":
            line, column = _line_col(text, match.start())
            return ProtoSplit(head_end, match.start(), line, column)
        break
    line, column = _line_col(text, len(text))
    raise WbtSyntaxError("expected 'PROTO Name [ interface ] { body }' in a PROTO file",
                         Span(path, line, column))
