"""Print scene nodes back as Webots VRML text (used by round-trip tests, later by exportString).

Built-in nodes print their written fields with typed values; PROTO instances print their fields as
written. USEd nodes are printed in full each time (no DEF/USE sharing is reconstructed yet).
"""

from __future__ import annotations

from typing import Any

from wbtc.scene.model import Node
from wbtc.vrml import syntax as s
from wbtc.vrml.values import format_value, quote


def format_node(node: Node, indent: str = "", omit_defaults: bool = False) -> str:
    """The VRML text of one node and its subtree.

    Args:
        node: the node.
        indent: the indentation of its first line's level.
        omit_defaults: leave out built-in fields whose value is their default, as Webots' exportString and
            worldSave do (the written text of the round-trip tests keeps every field).
    """
    head = f"DEF {node.def_name} " if node.def_name else ""
    inner = indent + "  "
    lines = [f"{head}{node.type_name} {{"]
    for name, value in node.fields.items():
        text = _field_text(node, name, value, inner, omit_defaults)
        if omit_defaults and text == _default_text(node, name, inner):
            continue
        lines.append(f"{inner}{name} {text}")
    if len(lines) == 1:
        return f"{head}{node.type_name} {{\n{indent}}}"
    lines.append(f"{indent}}}")
    return "\n".join(lines)


def _default_text(node: Node, name: str, indent: str) -> str | None:
    field_schema = node.schema.field(name) if node.schema is not None else None
    if field_schema is None or field_schema.type in ("SFNode", "MFNode"):
        return None
    return format_value(field_schema.default, field_schema.type, lambda n: format_node(n, indent))


def _field_text(node: Node, name: str, value: Any, indent: str, omit_defaults: bool = False) -> str:
    if isinstance(value, s.IsRef):
        return f"IS {value.name}"
    field_schema = node.schema.field(name) if node.schema is not None else None
    if field_schema is None:
        return format_raw(value, indent)
    return format_value(value, field_schema.type, lambda n: format_node(n, indent, omit_defaults))


def format_raw(value: Any, indent: str = "") -> str:
    """Print an untyped value (a PROTO instance's field) as it was written."""
    if isinstance(value, Node):
        return format_node(value, indent)
    if isinstance(value, s.Numbers):
        return " ".join(value.runs)
    if isinstance(value, s.String):
        return quote(value.value)
    if isinstance(value, s.Bool):
        return "TRUE" if value.value else "FALSE"
    if isinstance(value, s.Null):
        return "NULL"
    if isinstance(value, s.IsRef):
        return f"IS {value.name}"
    if isinstance(value, s.MFList):
        return "[ " + " ".join(format_raw(item, indent) for item in value.items) + " ]"
    raise TypeError(f"cannot print {type(value).__name__}")
