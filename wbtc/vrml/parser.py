"""Parse Webots world and PROTO text into the syntax tree of `wbtc.vrml.syntax`.

The grammar is `grammars/vrml.lark`, run by lark's LALR parser with its tables cached on disk and
the tree built by an embedded transformer (no intermediate parse tree). Template PROTO bodies are
split off before parsing and kept as text for the PROTO stage. Lark's exceptions become
`WbtSyntaxError`s with plain sentences (`wbtc.vrml.errors`).
"""

from __future__ import annotations

import threading
from functools import lru_cache
from pathlib import Path
from typing import Any

import lark

from wbtc.errors import Diagnostic, Span, WbtSyntaxError
from wbtc.resources import grammar_path
from wbtc.vrml import syntax as s
from wbtc.vrml.errors import syntax_error_from_lark
from wbtc.vrml.header import read_header, template_language
from wbtc.vrml.scan import split_proto


class _Builder(lark.Transformer):
    """Builds syntax objects while the LALR parser reduces (one instance, path set per parse)."""

    path = "<string>"

    def _span(self, token: lark.Token) -> Span:
        return Span(self.path, token.line, token.column)

    def world(self, children: list[Any]) -> list[Any]:
        return children

    def externproto(self, children: list[Any]) -> s.ExternProto:
        importable = len(children) == 2
        token = children[-1]
        return s.ExternProto(_unescape(token.value), self._span(children[0]), importable)

    def node(self, children: list[Any]) -> s.NodeSyntax:
        if len(children) >= 2 and isinstance(children[1], lark.Token):
            def_token, type_token = children[0], children[1]
            return s.NodeSyntax(type_token.value, children[2:], self._span(type_token),
                                def_token.value, self._span(def_token))
        return s.NodeSyntax(children[0].value, children[1:], self._span(children[0]))

    def use(self, children: list[Any]) -> s.Use:
        return s.Use(children[0].value, self._span(children[0]))

    def field(self, children: list[Any]) -> s.FieldSyntax:
        return s.FieldSyntax(children[0].value, children[1], self._span(children[0]))

    def is_field(self, children: list[Any]) -> s.FieldSyntax:
        name, target = children
        return s.FieldSyntax(name.value, s.IsRef(target.value, self._span(target)), self._span(name))

    def hidden_field(self, children: list[Any]) -> s.FieldSyntax:
        _, name, value = children
        return s.FieldSyntax(name.value, value, self._span(name), hidden=True)

    def numbers(self, children: list[lark.Token]) -> s.Numbers:
        return s.Numbers([t.value for t in children], self._span(children[0]))

    def string(self, children: list[lark.Token]) -> s.String:
        return s.String(_unescape(children[0].value), self._span(children[0]))

    def true(self, children: list[lark.Token]) -> s.Bool:
        return s.Bool(True, self._span(children[0]))

    def false(self, children: list[lark.Token]) -> s.Bool:
        return s.Bool(False, self._span(children[0]))

    def null(self, children: list[lark.Token]) -> s.Null:
        return s.Null(self._span(children[0]))

    def mf(self, children: list[Any]) -> s.MFList:
        return s.MFList(children[1:], self._span(children[0]))

    def decl(self, children: list[Any]) -> s.FieldDeclSyntax:
        kind, ftype = children[0], children[1]
        restriction = children[2] if isinstance(children[2], list) else None
        name, default = children[-2], children[-1]
        return s.FieldDeclSyntax(kind.value, ftype.value, name.value, default, self._span(kind), restriction)

    def restriction(self, children: list[Any]) -> list[Any]:
        return children

    def proto_decl(self, children: list[Any]) -> s.ProtoSyntax:
        name = children[0]
        proto = s.ProtoSyntax(name.value, [], self._span(name))
        for child in children[1:]:
            if isinstance(child, lark.Token):  # the interface's "["
                continue
            if isinstance(child, s.FieldDeclSyntax):
                proto.fields.append(child)
            elif isinstance(child, s.ProtoSyntax):
                proto.nested.append(child)
            else:
                proto.body.append(child)
        return proto

    def proto_head(self, children: list[Any]) -> tuple[list[s.ExternProto], s.ProtoSyntax]:
        externs = [c for c in children if isinstance(c, s.ExternProto)]
        rest = [c for c in children[len(externs):] if not (isinstance(c, lark.Token) and c.type == "LSQB")]
        name = rest[0]
        return externs, s.ProtoSyntax(name.value, list(rest[1:]), self._span(name))

    def proto_file(self, children: list[Any]) -> tuple[list[s.ExternProto], s.ProtoSyntax]:
        return children[:-1], children[-1]

    def value_only(self, children: list[Any]) -> Any:
        return children[0]

    def proto_body(self, children: list[Any]) -> list[Any]:
        return children


_BUILDER = _Builder()
_LOCK = threading.Lock()


@lru_cache(maxsize=1)
def _parser() -> lark.Lark:
    return lark.Lark(
        grammar_path("vrml.lark").read_text(encoding="utf-8"),
        parser="lalr",
        lexer="contextual",
        start=["world", "proto_file", "proto_head", "value_only", "proto_body"],
        transformer=_BUILDER,
        cache=True,
        maybe_placeholders=False,
    )


def _run(text: str, start: str, path: str) -> Any:
    with _LOCK:
        _BUILDER.path = path
        try:
            return _parser().parse(text, start=start)
        except lark.exceptions.UnexpectedInput as exc:
            raise syntax_error_from_lark(exc, text, path) from None


def _unescape(quoted: str) -> str:
    body = quoted[1:-1]
    if "\\" not in body:
        return body
    out = []
    i = 0
    while i < len(body):
        char = body[i]
        if char == "\\" and i + 1 < len(body) and body[i + 1] in '"\\':
            out.append(body[i + 1])
            i += 2
            continue
        # Webots keeps other backslash sequences (\n stays two characters: a newline for display).
        out.append(char)
        i += 1
    return "".join(out)


def parse_text(text: str, path: str = "<string>", kind: str = "world") -> s.FileSyntax:
    """Parse the text of a world or PROTO file.

    Args:
        text: the whole file, header included.
        path: the name used in error messages and spans.
        kind: "world" for .wbt text, "proto" for .proto text.

    Returns:
        The syntax tree.

    Raises:
        WbtSyntaxError: the header or the text is malformed.
    """
    warnings: list[Diagnostic] = []
    try:
        version_text: str | None
        parsed_version, info = read_header(text, path)
        version_text = parsed_version.text
    except WbtSyntaxError as exc:
        if kind == "world":
            raise
        # Webots reads header-less PROTO files written for old versions; say so and go on.
        warnings.append(Diagnostic("PROTO file without '#VRML_SIM <version> utf8' header", exc.span,
                                   severity="warning"))
        version_text, info = None, _info_lines(text)
    if kind == "world":
        items = _run(text, "world", path)
        externs = [i for i in items if isinstance(i, s.ExternProto)]
        protos = [i for i in items if isinstance(i, s.ProtoSyntax)]
        nodes = [i for i in items if isinstance(i, s.NodeSyntax | s.Use)]
        return s.FileSyntax(path, version_text, info, externs, nodes, protos, text, warnings)
    if kind != "proto":
        raise ValueError(f"kind must be 'world' or 'proto', not {kind!r}")
    result = _parse_proto(text, path, version_text, info)
    result.warnings.extend(warnings)
    return result


def _info_lines(text: str) -> list[str]:
    info = []
    for line in text.splitlines():
        if not line.strip().startswith("#"):
            break
        info.append(line.strip()[1:].strip())
    return info


def _parse_proto(text: str, path: str, version: str | None, info: list[str]) -> s.FileSyntax:
    split = split_proto(text, path)
    body = text[split.body_start:]
    language = template_language(info)
    opener = "%<" if language == "javascript" else "%{"
    if language is None:
        opener = "%<" if "%<" in body else "%{"
        language = "javascript" if opener == "%<" else "lua"
    if opener in body:
        externs, proto = _run(text[:split.head_end], "proto_head", path)
        proto.template = body
        proto.template_language = language
        proto.template_span = Span(path, split.body_line, split.body_column)
    else:
        externs, proto = _run(text, "proto_file", path)
        if len(proto.body) != 1:
            where = proto.body[1].span if len(proto.body) > 1 else proto.span
            raise WbtSyntaxError(f"the body of PROTO {proto.name} must hold exactly one node, "
                                 f"found {len(proto.body)}", where)
    return s.FileSyntax(path, version, info, externs, [], [proto], text)


def parse_file(path: str | Path) -> s.FileSyntax:
    """Parse a .wbt or .proto file from disk (the kind follows the extension).

    Raises:
        WbtcError: the file cannot be read or is malformed.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        raise WbtSyntaxError(f"cannot read {path}: {exc.strerror if isinstance(exc, OSError) else exc}",
                             None) from None
    kind = "proto" if path.suffix.lower() == ".proto" else "world"
    return parse_text(text, str(path), kind)


def parse_value(text: str, path: str = "<value>") -> s.Value:
    """Parse one field value written as VRML text (used by the schema and by tests)."""
    return _run(text, "value_only", path)


def parse_body(text: str, path: str, line: int = 1, column: int = 1) -> list[s.NodeSyntax | s.Use]:
    """Parse a PROTO body (`{ node }`, e.g. a rendered template) whose text starts at line:column."""
    padded = "\n" * (line - 1) + " " * (column - 1) + text
    return [item for item in _run(padded, "proto_body", path) if not isinstance(item, s.ProtoSyntax)]
