"""The wbtc error hierarchy and source spans.

Every stage raises a `WbtcError` subclass carrying one or more `Diagnostic`s, each with a `Span`
(file, line, column; 1-based, as editors count). The library never prints; only `wbtc.cli` turns
diagnostics into ``path:line:col: error: message`` with the source line and a caret.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path


@dataclass(frozen=True, slots=True)
class Span:
    """A place in a source file (1-based line and column)."""

    file: str
    line: int
    column: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


#: `Diagnostic.topic` of a warning about a texture or mesh file that cannot be read (`wbtc check` lists them).
UNREADABLE_FILE = "unreadable file"
#: `Diagnostic.topic` of a warning about a Joint that Webots leaves unattached (`wbtc check` lists them).
UNATTACHED_JOINT = "unattached joint"
#: `Diagnostic.topic` of a warning about a value Webots replaces when it loads the world (`wbtc check` lists them).
INVALID_VALUE = "invalid value"


@dataclass(frozen=True, slots=True)
class Diagnostic:
    """One error or warning at one place.

    Attributes:
        message: a plain sentence, without the location.
        span: where it happened, or None when no place applies.
        severity: "error" or "warning".
        hint: an optional second sentence, such as a "did you mean" suggestion.
        source_line: the text of the offending line when the file is not on disk (snippets).
        topic: what kind of problem it is, for callers that pick some out (`UNREADABLE_FILE`), or None.
    """

    message: str
    span: Span | None = None
    severity: str = "error"
    hint: str | None = None
    source_line: str | None = field(default=None, compare=False)
    topic: str | None = field(default=None, compare=False)

    def __str__(self) -> str:
        where = f"{self.span}: " if self.span else ""
        text = f"{where}{self.severity}: {self.message}"
        return f"{text} ({self.hint})" if self.hint else text


class WbtcError(Exception):
    """Base of every error wbtc raises for a problem in the user's input."""

    def __init__(self, message: str, span: Span | None = None, *, hint: str | None = None,
                 diagnostics: list[Diagnostic] | None = None) -> None:
        self.diagnostics: list[Diagnostic] = diagnostics or [Diagnostic(message, span, hint=hint)]
        super().__init__(str(self.diagnostics[0]))

    @property
    def span(self) -> Span | None:
        """The place of the first diagnostic."""
        return self.diagnostics[0].span

    @property
    def message(self) -> str:
        """The sentence of the first diagnostic."""
        return self.diagnostics[0].message


class WbtSyntaxError(WbtcError):
    """The text is not valid Webots VRML (bad token, missing bracket, bad header)."""


class SchemaError(WbtcError):
    """A node or value does not fit the node schema (unknown field, wrong value count)."""


class ProtoError(WbtcError):
    """A PROTO cannot be found, instantiated or its template evaluated."""


class CompileError(WbtcError):
    """The scene cannot be turned into a MuJoCo model."""


class ControllerError(WbtcError):
    """A controller cannot be found or started."""


def render_diagnostic(diag: Diagnostic, color: bool = False) -> str:
    """Format a diagnostic as ``path:line:col: severity: message``, the line and a caret.

    Args:
        diag: the diagnostic to show.
        color: whether to use ANSI colours.

    Returns:
        The text to print (without a trailing newline).
    """
    head = str(diag.span) + ": " if diag.span else ""
    sev = diag.severity
    if color:
        sev = ("\x1b[1;31m" if sev == "error" else "\x1b[1;35m") + sev + "\x1b[0m"
    lines = [f"{head}{sev}: {diag.message}"]
    if diag.span is not None:
        src = diag.source_line if diag.source_line is not None else _read_line(diag.span)
        if src is not None:
            shown = src.rstrip("\n").expandtabs(1)
            lines.append(f"    {shown}")
            lines.append("    " + " " * max(diag.span.column - 1, 0) + "^")
    if diag.hint:
        lines.append(f"  hint: {diag.hint}")
    return "\n".join(lines)


def _read_line(span: Span) -> str | None:
    try:
        with Path(span.file).open(encoding="utf-8", errors="replace") as handle:
            for number, text in enumerate(handle, start=1):
                if number == span.line:
                    return text
    except OSError:
        return None
    return None
