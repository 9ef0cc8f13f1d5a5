"""Typed values as PROTO templates see them (`fields.NAME.value`), in Webots' type mapping.

SFVec2f -> {x, y}; SFVec3f -> {x, y, z}; SFColor -> {r, g, b}; SFRotation -> {x, y, z, a};
SFNode -> {node_name, fields} (fields of a built-in node: every field with its default; of a PROTO
instance: its interface values) or None for NULL; MF -> lists of the SF forms.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.proto.expand import Expander
    from wbtc.proto.instances import ProtoInstance
    from wbtc.proto.model import ProtoModel
    from wbtc.proto.resolve import Resolver

_KEYS = {"Vec2f": ("x", "y"), "Vec3f": ("x", "y", "z"), "Color": ("r", "g", "b"), "Rotation": ("x", "y", "z", "a")}


def to_template_value(value: Any, field_type: str, expander: Expander, resolver: Resolver) -> Any:
    """Convert a typed value to the plain Python structure handed to the template engine."""
    elem = field_type[2:]
    if field_type.startswith("MF"):
        if isinstance(value, np.ndarray):
            if elem in _KEYS:
                return [dict(zip(_KEYS[elem], map(float, row), strict=True)) for row in value.tolist()]
            return [int(v) for v in value.tolist()] if elem == "Int32" else [float(v) for v in value.tolist()]
        return [to_template_value(v, "SF" + elem, expander, resolver) for v in value]
    if elem in _KEYS:
        return dict(zip(_KEYS[elem], map(float, value), strict=True))
    if elem == "Node":
        return _node_value(value, expander, resolver) if isinstance(value, Node) else None
    return value


def _node_value(node: Node, expander: Expander, resolver: Resolver) -> dict[str, Any]:
    fields: dict[str, Any] = {}
    if node.proto is not None:
        # A PROTO instance an outer PROTO already expanded (a node it passes on by IS, as
        # StraightRoadSegment passes its `lines` of RoadLines to Road): the template sees the PROTO
        # and its interface values, as Webots shows it, not the base node it expanded into.
        return _instance_value(node.proto, expander, resolver)
    if node.schema is not None:
        for name, schema in node.schema.fields.items():
            value = node.get(name)
            fields[name] = {"value": _safe(value, schema.type, expander, resolver),
                            "defaultValue": _safe(schema.default, schema.type, expander, resolver)}
        return {"node_name": node.type_name, "fields": fields}
    source = resolver.resolve(node.type_name)
    if source is None:
        return {"node_name": node.type_name, "fields": {}}
    from wbtc.proto.model import load_proto

    model = load_proto(source.path)
    values, defaults = expander._values(node, model, resolver, expander.resolver_for(model))
    return {"node_name": node.type_name, "fields": _proto_fields(model, values, defaults, expander, resolver)}


def _instance_value(instance: ProtoInstance, expander: Expander, resolver: Resolver) -> dict[str, Any]:
    """{node_name, fields} of an expanded PROTO instance: its values, and its PROTO's defaults."""
    from wbtc.proto.model import load_proto

    model = load_proto(instance.source.path)
    defaults = {name: expander._default(interface, model, expander.resolver_for(model))
                for name, interface in model.fields.items()}
    values = {name: instance.values.get(name, default) for name, default in defaults.items()}
    return {"node_name": instance.name, "fields": _proto_fields(model, values, defaults, expander, resolver)}


def _proto_fields(model: ProtoModel, values: dict[str, Any], defaults: dict[str, Any], expander: Expander,
                  resolver: Resolver) -> dict[str, Any]:
    """A PROTO instance's `fields` as templates see them: each interface field's value and default."""
    return {name: {"value": _safe(values[name], interface.type, expander, resolver),
                   "defaultValue": _safe(defaults[name], interface.type, expander, resolver)}
            for name, interface in model.fields.items()}


def _safe(value: Any, field_type: str, expander: Expander, resolver: Resolver) -> Any:
    if isinstance(value, Node | list) or field_type.endswith("Node"):
        if isinstance(value, Node):
            return _node_value(value, expander, resolver)
        if isinstance(value, list):
            return [_node_value(v, expander, resolver) if isinstance(v, Node) else None for v in value]
        return None
    return to_template_value(value, field_type, expander, resolver)
