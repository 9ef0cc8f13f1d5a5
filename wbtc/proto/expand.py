"""Expand PROTO instances into built-in nodes: interface values, IS links, templates, nesting.

For each instance: resolve the PROTO (`wbtc.proto.resolve`), type the instance's values against
the interface (unknown fields get a "did you mean"), fill the defaults, render the body when it is
a template, build the body in its own DEF scope, replace every `IS` by the interface value, and
expand what the body holds (derived PROTOs, nested instances) with the PROTO file's own resolver.
An unresolved PROTO is a warning and the node is left out (`strict` makes it an error).

The `hidden` state lines of instances are applied to the Solids and joints inside them (`hidden`).

Not honoured yet: re-expansion when a field changes at run time (supervisor, issue 7).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from wbtc.errors import Diagnostic, ProtoError, SchemaError, Span
from wbtc.proto.hidden import apply_hidden
from wbtc.proto.instances import Expansion, ProtoInstance, Typed
from wbtc.proto.model import InterfaceField, ProtoModel, load_proto, written_version
from wbtc.proto.resolve import ProtoSource, Resolver
from wbtc.proto.template_render import render_body, template_context
from wbtc.scene.build import NodeBuilder
from wbtc.scene.legacy_nodes import convert_differential_wheels
from wbtc.scene.model import Node, Scene, nodes_in, tree_edges, walk
from wbtc.schema.registry import suggest
from wbtc.vrml import syntax as s
from wbtc.vrml.header import before_r2022a
from wbtc.vrml.values import coerce, format_value

#: Deeper nesting than this is taken for a PROTO that contains itself.
MAX_DEPTH = 40


def _is_node(value: Any) -> bool:
    return isinstance(value, Node)


class Expander:
    """Expands every PROTO instance of one world."""

    def __init__(self, scene: Scene, strict: bool = False) -> None:
        self.scene = scene
        self.world_path = Path(scene.path)
        self.strict = strict
        self.result = Expansion()
        self._memo: dict[int, tuple[Node, Node | None]] = {}
        self._resolvers: dict[Path, Resolver] = {}
        self._depth = 0
        self.last_context_id = 1  # the last `context.id` given to a nested instance
        #: The `context.id` an instance node's template gets when known beforehand: a top-level
        #: node's place in the scene's numbering, a regenerated node's id. A nested instance takes
        #: the next number after `last_context_id`.
        self.context_ids: dict[int, int] = {}
        #: The ids the templates that read `context.id` were given: their nodes must get them.
        self.claims: dict[int, int] = {}
        self._instances: dict[int, ProtoInstance] = {}  # id of an instance node -> what it expanded to

    # --- traversal -----------------------------------------------------------------------------

    def expand_list(self, nodes: list[Any], resolver: Resolver) -> list[Node]:
        """Expand each node of a list, dropping the ones left out."""
        out = []
        for node in nodes:
            expanded = self.expand(node, resolver)
            if expanded is not None:
                out.append(expanded)
        return out

    def expand(self, node: Node, resolver: Resolver, top_level: bool = False) -> Node | None:
        """The built-in node tree for `node` (itself, with its subtree expanded, if built in)."""
        key = id(node)
        known = self._memo.get(key)
        if known is not None and known[0] is node:
            return known[1]
        if node.pending_use is not None:  # left by `_bind_defaults` when no default DEF has the name
            self.result.errors.append(Diagnostic(f"USE {node.pending_use} refers to no DEF before it", node.span))
            return None
        if node.is_proto:
            if top_level:
                self.result.counts[node.type_name] += 1
            result = self._instantiate(node, resolver, top_level)
        else:
            self._memo[key] = (node, node)  # before the children: a USE below refers back to this node
            self._expand_fields(node, resolver, top_level)
            result = node
        # The node is kept in the memo with its result so that its id is never reused meanwhile.
        self._memo[key] = (node, result)
        return result

    def _expand_fields(self, node: Node, resolver: Resolver, top_level: bool) -> None:
        for name, value in node.fields.items():
            if isinstance(value, Node):
                node.fields[name] = self.expand(value, resolver, top_level)
            elif isinstance(value, list) and value and isinstance(value[0], Node):
                node.fields[name] = [n for n in (self.expand(v, resolver, top_level) for v in value) if n]

    def resolver_for(self, model: ProtoModel) -> Resolver:
        """The resolver of a PROTO file (its own EXTERNPROTO lines, the world's project)."""
        resolver = self._resolvers.get(model.path)
        if resolver is None:
            resolver = Resolver(model.path, model.file.externprotos, self.world_path)
            self._resolvers[model.path] = resolver
        return resolver

    # --- one instance --------------------------------------------------------------------------

    def _instantiate(self, node: Node, resolver: Resolver, top_level: bool) -> Node | None:
        source = resolver.resolve(node.type_name)
        self.result.sources.setdefault(node.type_name, source)
        if source is None:
            self._unresolved(node, resolver)
            return None
        model = load_proto(source.path)
        if self._depth >= MAX_DEPTH:
            raise ProtoError(f"PROTO {node.type_name} nests itself more than {MAX_DEPTH} levels deep", node.span)
        self._depth += 1
        try:
            root = self._build_instance(node, model, source, resolver, top_level)
        finally:
            self._depth -= 1
        return root

    def _unresolved(self, node: Node, resolver: Resolver) -> None:
        places = "; ".join(resolver.searched(node.type_name))
        message = f"unknown PROTO '{node.type_name}': the node is left out of the simulation"
        diag = Diagnostic(message, node.span, "error" if self.strict else "warning", hint=f"searched: {places}")
        (self.result.errors if self.strict else self.result.warnings).append(diag)

    def _build_instance(self, node: Node, model: ProtoModel, source: ProtoSource, resolver: Resolver,
                        top_level: bool) -> Node | None:
        proto_resolver = self.resolver_for(model)
        values, defaults = self._values(node, model, resolver, proto_resolver)
        _bind_defaults(node, model, values)
        self._old_fields(node, model, source, values)
        fields = self._template_fields(model, values, defaults, resolver) if model.is_template else None
        for name, value in values.items():
            if model.fields[name].has_nodes:
                # Values written with the instance resolve PROTOs where the instance was written;
                # defaults where the PROTO was.
                own = name in node.fields
                values[name] = self._expand_value(value, resolver if own else proto_resolver, top_level and own)
        body = self._render(model, fields, node) if fields is not None else model.syntax.body
        builder = NodeBuilder(str(model.path), model.version, in_proto=True)
        roots = builder.build(body)
        self._collect(builder, model)
        if not roots:
            return None
        created = list(walk(roots))
        for made in created:
            made.origin = node.span
            self._link(made, model, values)
        expanded = self.expand(roots[0], proto_resolver)
        if expanded is not None and node.hidden:
            apply_hidden(expanded, node.hidden, set(model.fields))
        if expanded is not None:
            info = ProtoInstance(node.type_name, source, values, node.span, node.def_name, expanded.proto,
                                 links=node.links, context_id=self.claims.get(id(node)))
            self._instances[id(node)] = info
            expanded.proto = info
            if node.def_name is not None:
                expanded.def_name = node.def_name
            # What this body's nodes and instances link to by IS is a parameter of this instance.
            for made in created:
                inner = self._instances.get(id(made))
                if inner is not None and inner.owner is None:
                    inner.owner = info
                elif made.links and made.link_owner is None:
                    made.link_owner = info
        return expanded

    def _expand_value(self, value: Any, resolver: Resolver, top_level: bool) -> Any:
        if isinstance(value, Node):
            return self.expand(value, resolver, top_level)
        if isinstance(value, list):
            return [n for n in (self.expand(v, resolver, top_level) for v in value) if n is not None]
        return value

    def _template_fields(self, model: ProtoModel, values: dict[str, Any], defaults: dict[str, Any],
                         resolver: Resolver) -> dict[str, dict[str, Any]]:
        from wbtc.proto.jsvalues import to_template_value

        return {name: {"value": to_template_value(values[name], model.fields[name].type, self, resolver),
                       "defaultValue": to_template_value(defaults[name], model.fields[name].type, self,
                                                         self.resolver_for(model))}
                for name in model.fields}

    def _collect(self, builder: NodeBuilder, model: ProtoModel) -> None:
        for diag in builder.errors:
            self.result.errors.append(replace(diag, message=f"in PROTO {model.name}: {diag.message}"))
        self.result.warnings.extend(builder.warnings)

    def _values(self, node: Node, model: ProtoModel, resolver: Resolver,
                proto_resolver: Resolver) -> tuple[dict[str, Any], dict[str, Any]]:
        values: dict[str, Any] = {}
        for name, raw in node.fields.items():
            interface = model.fields.get(name)
            if interface is None:
                close = suggest(name, model.fields)
                self.result.errors.append(Diagnostic(
                    f"unknown field '{name}' in PROTO {model.name}", node.field_spans.get(name, node.span),
                    hint=f"did you mean '{close}'?" if close else None))
                continue
            typed = self._typed(raw, interface, model, node.field_spans.get(name, node.span))
            if typed is not _FAILED:
                values[name] = typed
        defaults = {}
        for name, interface in model.fields.items():
            defaults[name] = self._default(interface, model, proto_resolver)
            if name not in values:
                values[name] = defaults[name]
        return values, defaults

    def _old_fields(self, node: Node, model: ProtoModel, source: ProtoSource, values: dict[str, Any]) -> None:
        """Fields of an R2022a+ object written in an older file that name axes, in the new axes.

        Its `size` (x, height, z) becomes (x, z, height).

        Before R2022a, Webots' objects stood along y; since, along z (see `wbtc.compile.legacy_protos`,
        which turns the object's frame back). Robots keep their fields. A Road's `wayPoints` (x, height,
        z) become (x, −z, height) and its `startingAngle` / `endingAngle` (minus a heading measured
        from x towards the old z, towards −y now) change sign.
        """
        written = written_version(str(node.span.file), str(self.scene.path), self.scene.version)
        if source.path.parent.name == "robots" or not before_r2022a(written) or before_r2022a(model.version):
            return
        if model.name == "Road":
            if "wayPoints" in node.fields:
                values["wayPoints"] = [[x, -z, height] for x, height, z in values["wayPoints"]]
            for name in ("startingAngle", "endingAngle"):
                if name in node.fields:
                    values[name] = [-angle for angle in values[name]]
        interface = model.fields.get("size")
        if "size" not in node.fields or interface is None or interface.type != "SFVec3f":
            return
        x, height, z = values["size"]
        values["size"] = [x, z, height]

    def _typed(self, raw: Any, interface: InterfaceField, model: ProtoModel, span: Span) -> Any:
        if isinstance(raw, Typed):
            if raw.type != interface.type:
                self.result.errors.append(Diagnostic(
                    f"IS links a {raw.type} to field '{interface.name}' of PROTO {model.name}, "
                    f"which is an {interface.type}", raw.span or span))
                return _FAILED
            return raw.value
        try:
            typed = coerce(raw, interface.type, f"field '{interface.name}' of PROTO {model.name}", _is_node)
        except SchemaError as exc:
            self.result.errors.append(Diagnostic(exc.message, exc.span or span))
            return _FAILED
        if interface.allowed is not None and not interface.type.startswith("MF") and typed not in interface.allowed:
            shown = ", ".join(format_value(a, interface.type) for a in interface.allowed)
            self.result.warnings.append(Diagnostic(
                f"{format_value(typed, interface.type)} is not an allowed value of field '{interface.name}' of "
                f"PROTO {model.name} (allowed: {shown})", span, "warning"))
        return typed

    def _default(self, interface: InterfaceField, model: ProtoModel, proto_resolver: Resolver) -> Any:
        if not interface.has_nodes:
            return interface.default
        builder = NodeBuilder(str(model.path), model.version)
        raw = builder.value(interface.default)
        self._collect(builder, model)
        return coerce(raw, interface.type, f"default of field '{interface.name}'", _is_node)

    def _link(self, made: Node, model: ProtoModel, values: dict[str, Any]) -> None:
        for name, value in list(made.fields.items()):
            if not isinstance(value, s.IsRef):
                continue
            if value.name in model.fields:  # remembered for Field.getActualField and live reads
                made.links = {**(made.links or {}), name: value.name}
            interface = model.fields.get(value.name)
            if interface is None:
                close = suggest(value.name, model.fields)
                self.result.errors.append(Diagnostic(
                    f"IS {value.name}: PROTO {model.name} has no such field", value.span,
                    hint=f"did you mean '{close}'?" if close else None))
                del made.fields[name]
                continue
            linked = values.get(value.name)
            if made.is_proto:
                made.fields[name] = Typed(interface.type, linked, value.span)
                continue
            own = made.schema.field(name) if made.schema else None
            if own is not None and own.type == "MF" + interface.type[2:] and interface.type.startswith("SF"):
                # Old Webots had SF versions of some fields (controllerArgs): one value makes a list.
                made.fields[name] = coerce(s.MFList([], value.span), own.type, name, _is_node) if linked is None \
                    else _one_element(linked, own.type)
                continue
            if own is not None and own.type != interface.type:
                self.result.errors.append(Diagnostic(
                    f"IS links field '{name}' of {made.type_name} ({own.type}) to PROTO field '{value.name}' "
                    f"({interface.type}): the types must be the same", value.span))
                del made.fields[name]
                continue
            made.fields[name] = list(linked) if isinstance(linked, list) else linked

    # --- templates (see `template_render`) -------------------------------------------------------

    def _render(self, model: ProtoModel, fields: dict[str, dict[str, Any]], node: Node) -> list[s.NodeSyntax | s.Use]:
        # Webots gives a template the id of the node it makes (`context.id`), which the supervisor
        # API returns for that node: the scene tree gives the node this number (`SceneTree.refresh`).
        context_id = self.context_ids.get(id(node))
        if context_id is None:
            self.last_context_id += 1
            context_id = self.context_ids[id(node)] = self.last_context_id
        if "context.id" in (model.syntax.template or ""):
            self.claims[id(node)] = context_id
        context = template_context(model, self.world_path, self.scene, context_id)
        return render_body(model, fields, node, context, self.result.console)


_FAILED = object()

def _one_element(value: Any, mf_type: str) -> Any:
    if mf_type in ("MFString", "MFBool", "MFNode"):
        return [value]
    return np.asarray([value], dtype=np.int64 if mf_type == "MFInt32" else np.float64)


def _bind_defaults(node: Node, model: ProtoModel, values: dict[str, Any]) -> None:
    """Bind the USEs written in an instance's fields to DEFs in the default values of earlier fields.

    Webots gives an instance its fields in the PROTO's interface order, an omitted field taking its
    default, whose DEF names the fields after it may USE.
    """
    defs: dict[str, Node] = {}
    seen: set[int] = set()

    def bind(value: Any) -> Any:
        if isinstance(value, list):
            return [bind(item) for item in value]
        if not isinstance(value, Node):
            return value
        if value.pending_use is not None:
            return defs.get(value.pending_use, value)
        if id(value) not in seen:
            seen.add(id(value))
            for name, inner in value.fields.items():
                value.fields[name] = bind(inner)
        return value

    for name in model.fields:
        if name in node.fields:
            values[name] = bind(values[name])
        else:
            defs.update((n.def_name, n) for n in walk(list(nodes_in(values[name]))) if n.def_name)


def expand_scene(scene: Scene, strict: bool = False) -> tuple[Scene, Expansion]:
    """Expand every PROTO instance of a scene into built-in nodes.

    Args:
        scene: the typed scene of a world.
        strict: make unresolved PROTOs errors instead of warnings.

    Returns:
        The scene holding only built-in nodes, and what the expansion found.

    Raises:
        ProtoError: with every error found (unknown PROTO fields, bad values, template errors).
    """
    expander = Expander(scene, strict)
    resolver = Resolver(Path(scene.path), scene.externprotos, Path(scene.path))
    nodes: list[Node] = []
    numbered: set[int] = set()  # the nodes numbered so far, as the supervisor API numbers them (root 0)
    for node in scene.nodes:
        expander.context_ids.setdefault(id(node), len(numbered) + 1)
        expanded = expander.expand(node, resolver, top_level=True)
        if expanded is not None:
            nodes.append(expanded)
            numbered |= {id(n) for _, n in tree_edges(None, [expanded])}
    result = expander.result
    if result.errors:
        raise ProtoError("", diagnostics=result.errors[:40])
    result.warnings += convert_differential_wheels(nodes)
    expanded_scene = replace(scene, nodes=nodes, warnings=scene.warnings + result.warnings)
    return expanded_scene, result


def as_array(value: Any) -> Any:
    """Numpy arrays as nested lists (for templates and JSON)."""
    return value.tolist() if isinstance(value, np.ndarray) else value
