"""Lark's LALR parser of `grammars/vrml.lark` and the transformer that builds `wbtc.vrml.syntax` objects.

Kept apart from `wbtc.vrml.parser` so that lark is imported when something is first parsed, not
by every module that uses the syntax classes (a `wbtc run` taken from the world cache parses nothing).
"""

from __future__ import annotations

import threading
from functools import lru_cache
from typing import Any

import lark

from wbtc.errors import Span
from wbtc.resources import grammar_path
from wbtc.vrml import syntax as s
from wbtc.vrml.errors import syntax_error_from_lark


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


def run(text: str, start: str, path: str) -> Any:
    """Parse `text` from the grammar rule `start`; lark's errors become `WbtSyntaxError`s."""
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
