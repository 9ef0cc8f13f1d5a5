"""The syntax tree of a Webots file: what was written, with where it was written.

Values here are untyped: a run of numbers is kept as its text, and only the node schema (for
built-in nodes) or the PROTO interface (for PROTO instances) says what type it must have. The scene
builder (`wbtc.scene.build`) turns these into typed values.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from wbtc.errors import Diagnostic, Span


@dataclass(slots=True)
class Numbers:
    """One or more runs of numbers, as written (commas and spaces between them)."""

    runs: list[str]
    span: Span

    def tokens(self) -> list[str]:
        """Every number of the runs as its own text."""
        return " ".join(self.runs).replace(",", " ").split()


@dataclass(slots=True)
class String:
    """A string literal, unescaped."""

    value: str
    span: Span


@dataclass(slots=True)
class Bool:
    """TRUE or FALSE."""

    value: bool
    span: Span


@dataclass(slots=True)
class Null:
    """NULL."""

    span: Span


@dataclass(slots=True)
class Use:
    """USE name."""

    name: str
    span: Span


@dataclass(slots=True)
class MFList:
    """A bracketed list of items: [ ... ]."""

    items: list[Item]
    span: Span


@dataclass(slots=True)
class IsRef:
    """`field IS protoField` inside a PROTO body."""

    name: str
    span: Span


@dataclass(slots=True)
class FieldSyntax:
    """One `name value` line of a node, or a `hidden name value` line of a PROTO instance."""

    name: str
    value: Value
    span: Span
    hidden: bool = False


@dataclass(slots=True)
class NodeSyntax:
    """`[DEF name] Type { fields }`; `span` is the place of the type name."""

    type_name: str
    fields: list[FieldSyntax]
    span: Span
    def_name: str | None = None
    def_span: Span | None = None


@dataclass(slots=True)
class ExternProto:
    """`[IMPORTABLE] EXTERNPROTO "url"`."""

    url: str
    span: Span
    importable: bool = False


@dataclass(slots=True)
class FieldDeclSyntax:
    """One interface line of a PROTO: `field SFVec3f translation 0 0 0`."""

    kind: str
    type: str
    name: str
    default: Value
    span: Span
    restriction: list[Item] | None = None


@dataclass(slots=True)
class ProtoSyntax:
    """A PROTO declaration: its interface, and its body as nodes or as template text."""

    name: str
    fields: list[FieldDeclSyntax]
    span: Span
    body: list[NodeSyntax | Use] = field(default_factory=list)
    template: str | None = None
    template_language: str | None = None
    template_span: Span | None = None
    nested: list[ProtoSyntax] = field(default_factory=list)


@dataclass(slots=True)
class FileSyntax:
    """A parsed world or PROTO file.

    Attributes:
        path: the file name used in spans.
        version: the header version text ("R2023b"), or None for a file without header.
        info: the comment lines at the top of the file (header included), without '#'.
        externprotos: EXTERNPROTO lines in order.
        nodes: the top-level nodes (worlds).
        protos: the PROTO declarations (one for a .proto file).
        text: the whole source text (error messages show its lines).
        warnings: problems that do not stop reading (a PROTO file without header).
    """

    path: str
    version: str | None
    info: list[str]
    externprotos: list[ExternProto]
    nodes: list[NodeSyntax | Use]
    protos: list[ProtoSyntax]
    text: str = field(repr=False, default="")
    warnings: list[Diagnostic] = field(default_factory=list)


Item = Numbers | String | Bool | Null | NodeSyntax | Use
Value = Item | MFList | IsRef
