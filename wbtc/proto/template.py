"""Evaluation of procedural PROTO bodies (Webots templates) into plain VRML text.

A PROTO body may embed template statements -- JavaScript ``%< ... >%`` / ``%<= ... >%`` (PROTOs
whose header says ``# template language: javascript``) or Lua ``%{ ... }%`` / ``%{= ... }%`` --
that Webots evaluates before parsing the body. `render_template` does the same, with QuickJS for
JavaScript (`wbtc.proto.template_js`) and Lua 5.2 for Lua (`wbtc.proto.template_lua`), and wbtc's
own implementations of the Webots template modules (``wbtc/proto/js``).

The output keeps the line structure of the body as far as the template allows: JavaScript output
is the text chunks verbatim plus the expression values, so a body without loops produces exactly
as many lines as it has; Lua output follows liluat's trimming, which removes lines holding only a
statement. Errors are `wbtc.errors.ProtoError` located at the failing template line of the PROTO
file.

Typical use, with the body taken from just after the interface's closing ``]``::

    text, console = render_template(body, language="javascript", fields=fields,
                                    context={"coordinate_system": "ENU", "id": 7},
                                    proto_path="/path/Parquetry.proto", body_line=17)
"""

from __future__ import annotations

from wbtc.proto import template_js, template_lua
from wbtc.proto.template_common import (
    DEFAULT_WEBOTS_VERSION,
    SourceMap,
    TemplateOutput,
    TemplateSyntaxError,
    context_values,
    proto_error,
)
from wbtc.proto.template_split import is_procedural, split_template, strip_lua_vrml_comments

__all__ = [
    "DEFAULT_WEBOTS_VERSION",
    "TemplateOutput",
    "evaluate_template",
    "is_procedural",
    "render_template",
]


def render_template(body: str, *, language: str, fields: dict[str, dict], context: dict,
                    proto_path: str, body_line: int, body_column: int = 1) -> tuple[str, list[str]]:
    """Evaluate a PROTO body template and return (vrml_text, console_lines).

    Args:
        body: the template text, e.g. everything after the interface's closing ``]`` (the outer
            braces may be included; all of it is treated as template text).
        language: ``"javascript"`` or ``"lua"``.
        fields: ``{name: {"value": v, "defaultValue": d}}`` with values already mapped to Python
            values (SFVec3f ``{"x", "y", "z"}``, SFNode ``{"node_name", "fields"}`` or None, MF
            lists, ...). Floats are rounded to 6 significant digits as Webots does.
        context: ``world``, ``proto``, ``project_path``, ``coordinate_system``,
            ``webots_version`` (``{"major": "R2025a", "revision": "0"}``), ``webots_home``,
            ``temporary_files_path``, ``os``, ``id``; missing keys get neutral defaults.
        proto_path: the PROTO file (used in error messages and spans).
        body_line: the file line on which ``body`` starts (1-based).
        body_column: the file column on which ``body`` starts (1-based).

    Returns:
        The generated VRML text and the console lines (``console.log``/``error`` in
        JavaScript, ``print``/``io.stderr:write`` in Lua) in the order Webots shows them.

    Raises:
        ProtoError: the template cannot be evaluated (unclosed statement, unknown module,
            syntax error, uncaught exception); the span is the failing line of the PROTO file.
        ValueError: ``language`` is neither JavaScript nor Lua.
    """
    output = evaluate_template(body, language=language, fields=fields, context=context,
                               proto_path=proto_path, body_line=body_line, body_column=body_column)
    return output.text, output.console


def evaluate_template(body: str, *, language: str, fields: dict[str, dict], context: dict,
                      proto_path: str, body_line: int, body_column: int = 1) -> TemplateOutput:
    """Like `render_template`, with the output and error streams kept apart.

    Args:
        body: the template text.
        language: ``"javascript"`` or ``"lua"``.
        fields: template fields, see `render_template`.
        context: template context, see `render_template`.
        proto_path: the PROTO file.
        body_line: the file line on which ``body`` starts.
        body_column: the file column on which ``body`` starts.

    Returns:
        A `TemplateOutput`. A body that Webots would not treat as a template (no statement
        outside strings and comments, see `is_procedural`) is returned unchanged, with an
        identity line map.

    Raises:
        ProtoError: as for `render_template`.
        ValueError: unknown language.
    """
    key = language.strip().lower()
    if key not in ("javascript", "lua"):
        raise ValueError(f"unknown template language {language!r} (expected 'javascript' or 'lua')")
    source = strip_lua_vrml_comments(body) if key == "lua" else body
    if not is_procedural(source, key):
        return TemplateOutput(body, line_map=[body_line + i for i in range(body.count("\n") + 1)])

    # Comment stripping only shortens lines, so offsets in `source` give the file's lines/columns.
    source_map = SourceMap(source, proto_path, body_line, body_column)
    try:
        chunks = split_template(source, key)
    except TemplateSyntaxError as error:
        raise proto_error(str(error), proto_path, source_map.span_at(error.offset)) from None
    backend = template_js.engine() if key == "javascript" else template_lua.engine()
    return backend.render(chunks, source_map, fields, context_values(context), proto_path)
