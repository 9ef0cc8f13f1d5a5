"""Helpers shared by the JavaScript and Lua template tests (imported by them as ``template_helpers``)."""

from __future__ import annotations

import re
from pathlib import Path

from conftest import CORPUS

from wbtc.proto.template import render_template

FIXTURES = Path(__file__).parent / "fixtures" / "templates"


def corpus_file(name: str) -> Path:
    found = sorted(CORPUS.rglob(name))
    assert found, f"{name} is missing from the shared corpus {CORPUS}"
    return found[0]


def split_proto(path: Path) -> tuple[str, int, int]:
    """The body of a PROTO file (text after the interface's closing ']') and where it starts."""
    text = path.read_text(encoding="utf-8")
    i = text.index("[", re.search(r"^\s*PROTO\s", text, re.MULTILINE).end())
    depth = 0
    while True:
        char = text[i]
        if char == "#":
            i = text.index("\n", i)
            continue
        if char == '"':
            i = text.index('"', i + 1) + 1
            continue
        depth += {"[": 1, "]": -1}.get(char, 0)
        if char == "]" and depth == 0:
            break
        i += 1
    start = i + 1
    line = text.count("\n", 0, start) + 1
    column = start - (text.rfind("\n", 0, start) + 1) + 1
    return text[start:], line, column


def field(value, default=...):
    return {"value": value, "defaultValue": value if default is ... else default}


def render(language: str, body: str, fields: dict | None = None, context: dict | None = None, *,
           proto_path: str = "/protos/Test.proto", body_line: int = 1, body_column: int = 1):
    return render_template(body, language=language, fields=fields or {}, context=context or {},
                           proto_path=proto_path, body_line=body_line, body_column=body_column)
