"""A template PROTO's body for one instance: its context, its text (shared when it would be the same), parsed.

- `template_context`: what a template reads besides its fields (`context.world`, `proto`,
  `project_path`, `coordinate_system`, `webots_version`, `os`, `id`, `temporary_files_path`);
- `render_body`: runs the template (JavaScript or Lua, `wbtc.proto.template`) and parses the VRML it
  writes. Webots generates a template again only when a field it reads changes, so instances that
  agree on the fields the template names and on the context share one text (kept for the process);
  a `nonDeterministic` PROTO is generated anew at each simulation reset (`template_files.generation`).

Not honoured yet: `context.webots_home` (wbtc has no Webots installation: empty).
"""

from __future__ import annotations

import json
import re
from functools import lru_cache
from pathlib import Path
from typing import Any

from wbtc.errors import ProtoError, WbtcError
from wbtc.proto.model import ProtoModel
from wbtc.proto.template_files import generation, temporary_files_path
from wbtc.scene.model import Node, Scene
from wbtc.vrml import syntax as s
from wbtc.vrml.parser import parse_body

_RENDERED: dict[tuple[Any, ...], str] = {}
_FIELD_NAMES = re.compile(r"fields\s*\.\s*([A-Za-z_][A-Za-z0-9_]*)")
#: A template that names its temporary folder, or may read or write files (Lua's io, Lua-GD), gets the
#: folder: Webots runs Lua templates in it, so a relative file name lands there.
_USES_FILES = re.compile(r"temporary_files_path|\bio\s*\.\s*(?:open|lines)\b|require\s*\(?\s*['\"]gd['\"]")


@lru_cache(maxsize=256)
def fields_read(template: str) -> frozenset[str]:
    """The fields a template's code reads (`fields.NAME`): Webots regenerates it when one changes."""
    return frozenset(_FIELD_NAMES.findall(template))


def template_context(model: ProtoModel, world_path: Path, scene: Scene, instance_id: int) -> dict[str, Any]:
    """The `context` object of one instance's template."""
    world = world_path.resolve()
    project = world.parent.parent if world.parent.name == "worlds" else world.parent
    version = str(scene.version) if scene.version.major > 1000 else "R2025a"
    return {
        "world": str(world), "proto": str(model.path), "project_path": str(project),
        "coordinate_system": scene.coordinate_system,
        "webots_version": {"major": version.split()[0], "revision": "0"},
        "webots_home": "", "os": "linux", "id": instance_id,
        # made only for a template that uses it (a folder per run)
        "temporary_files_path": temporary_files_path() if _USES_FILES.search(model.syntax.template or "") else "",
    }


def render_body(model: ProtoModel, fields: dict[str, dict[str, Any]], node: Node, context: dict[str, Any],
                console: list[str]) -> list[s.NodeSyntax | s.Use]:
    """The nodes one instance's template writes (its console lines are appended to `console`).

    Raises:
        ProtoError: the template fails or writes text that is not VRML.
    """
    from wbtc.proto.template import render_template

    span = model.syntax.template_span
    assert span is not None and model.syntax.template is not None
    # Everything the template can read is in the key: the fields it names and the whole context (the
    # world's version, axes and paths), the instance id only when the template reads it.
    read = fields_read(model.syntax.template)
    shared = {k: v for k, v in context.items() if k != "id"}
    key = (model.path, json.dumps({k: v for k, v in fields.items() if k in read}, sort_keys=True, default=str),
           json.dumps(shared, sort_keys=True, default=str), "context.id" in model.syntax.template and context["id"])
    # A nonDeterministic PROTO (random numbers, files) is generated anew at each reset, as in Webots;
    # within one generation the world's several loads (check, compile) share its text.
    if "nonDeterministic" in model.tags:
        key = (*key, "generation", generation())
    cached = _RENDERED.get(key)
    if cached is not None:
        return parse_body(cached, str(model.path), span.line, span.column)
    text, lines = render_template(model.syntax.template, language=model.syntax.template_language or "javascript",
                                  fields=fields, context=context, proto_path=str(model.path),
                                  body_line=span.line, body_column=span.column)
    console.extend(f"{model.name}: {line}" for line in lines)
    _RENDERED[key] = text
    try:
        return parse_body(text, str(model.path), span.line, span.column)
    except WbtcError as exc:
        raise ProtoError(f"the template of PROTO {model.name} produced invalid VRML: {exc.message}",
                         exc.span, hint=f"instance at {node.span}") from None
