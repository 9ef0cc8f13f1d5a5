"""Parse Webots world and PROTO text into the syntax tree of `wbtc.vrml.syntax`.

The grammar is `grammars/vrml.lark`, run by lark's LALR parser with its tables cached on disk and
the tree built by an embedded transformer (no intermediate parse tree). Template PROTO bodies are
split off before parsing and kept as text for the PROTO stage. Lark's exceptions become
`WbtSyntaxError`s with plain sentences (`wbtc.vrml.errors`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from wbtc.errors import Diagnostic, Span, WbtSyntaxError
from wbtc.vrml import syntax as s
from wbtc.vrml.header import read_header, template_language
from wbtc.vrml.scan import split_proto


def _run(text: str, start: str, path: str) -> Any:
    from wbtc.vrml.lalr import run  # lark is imported by the first parse

    return run(text, start, path)


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
        data = path.read_bytes()
    except OSError as exc:
        raise WbtSyntaxError(f"cannot read {path}: {exc.strerror}", None) from None
    text, bad = _decode(data, str(path))
    kind = "proto" if path.suffix.lower() == ".proto" else "world"
    result = parse_text(text, str(path), kind)
    if bad is not None:
        result.warnings.insert(0, bad)
    return result


def _decode(data: bytes, path: str) -> tuple[str, Diagnostic | None]:
    """A file's text as UTF-8 (a byte-order mark skipped), and a warning when some bytes are not UTF-8.

    Webots reads world and PROTO files as UTF-8 and turns bytes that are not (an é saved as Latin-1 by
    an old editor) into U+FFFD, the replacement character, and goes on; so does wbtc, with a warning at
    the first of them.
    """
    try:
        return data.decode("utf-8-sig"), None
    except UnicodeDecodeError as exc:
        text = data.decode("utf-8-sig", errors="replace")
        before = data[:exc.start].decode("utf-8-sig", errors="replace")
        line = before.count("\n") + 1
        column = len(before) - (before.rfind("\n") + 1) + 1
        byte = data[exc.start]
        return text, Diagnostic(f"byte 0x{byte:02x} is not UTF-8 (the file may be Latin-1): it and the other such "
                                "bytes are read as U+FFFD, as Webots reads them", Span(path, line, column),
                                severity="warning")


def parse_value(text: str, path: str = "<value>") -> s.Value:
    """Parse one field value written as VRML text (used by the schema and by tests)."""
    return _run(text, "value_only", path)


def parse_body(text: str, path: str, line: int = 1, column: int = 1) -> list[s.NodeSyntax | s.Use]:
    """Parse a PROTO body (`{ node }`, e.g. a rendered template) whose text starts at line:column."""
    padded = "\n" * (line - 1) + " " * (column - 1) + text
    return [item for item in _run(padded, "proto_body", path) if not isinstance(item, s.ProtoSyntax)]
