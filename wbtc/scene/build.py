"""Build a typed scene from a syntax tree: schema checks, DEF/USE binding, legacy values.

Rules, as Webots applies them:

* A USE refers to the closest preceding DEF of that name; a DEF name may repeat. A DEF counts from
  the end of its node, so a node cannot USE itself.
* An unknown field of a built-in node is an error with a "did you mean" (Webots skips it and says
  so); a value of the wrong type or length is an error.
* Node types that are not built in are PROTO instances: their fields are kept as written (nested
  nodes built) and checked against the PROTO interface in the PROTO stage.
* `IS` is only allowed inside PROTO bodies; `hidden` lines are saved state and are kept unchecked.
* Legacy values are converted with a warning: a gravity vector (files before R2020b) becomes its
  length; a boolean ImageTexture `filtering` (files before 8.6) becomes 4 or 0.

Not honoured yet: Webots' per-node value limits (e.g. negative Box sizes are reported later by the
compiler, not here).
"""

from __future__ import annotations

import math
from typing import Any

from wbtc.errors import Diagnostic, SchemaError, Span
from wbtc.scene.model import PENDING_USE, Node, Scene, allow_deep_worlds
from wbtc.schema.registry import FieldSchema, node_schema, suggest
from wbtc.vrml import syntax as s
from wbtc.vrml.header import R2020B, R2022B, Version, before_r2022a
from wbtc.vrml.values import coerce, format_value

#: Errors reported before the builder gives up on a file.
MAX_ERRORS = 20


class NodeBuilder:
    """Turns syntax nodes into scene nodes for one DEF scope (a world file or one PROTO body).

    Attributes:
        errors: the errors found so far (building goes on after an error, up to `MAX_ERRORS`).
        warnings: the warnings found so far.
        count: how many nodes were built.
    """

    def __init__(self, path: str, version: Version | None, in_proto: bool = False) -> None:
        self.path = path
        self.version = version
        self.in_proto = in_proto
        self.defs: dict[str, Node] = {}
        self.errors: list[Diagnostic] = []
        self.warnings: list[Diagnostic] = []
        self.count = 0
        self._missing_uses: list[s.Use] = []
        self._instance_depth = 0  # how many PROTO instances' fields are being built
        self._warned: set[tuple[str, str]] = set()

    def build(self, items: list[s.NodeSyntax | s.Use]) -> list[Node]:
        """Build top-level nodes (or a PROTO body), then explain USEs that found no DEF."""
        nodes = [n for n in (self.value(item) for item in items) if isinstance(n, Node)]
        for use in self._missing_uses:
            later = self.defs.get(use.name)
            hint = (f"DEF {use.name} comes later, at line {later.span.line}: a USE must come after its DEF"
                    if later is not None else None)
            self._error(f"USE {use.name} refers to no DEF before it", use.span, hint)
        self._missing_uses.clear()
        return nodes

    def _error(self, message: str, span: Span | None, hint: str | None = None) -> None:
        if len(self.errors) < MAX_ERRORS:
            self.errors.append(Diagnostic(message, span, hint=hint))

    def _warn(self, message: str, span: Span | None, hint: str | None = None) -> None:
        self.warnings.append(Diagnostic(message, span, severity="warning", hint=hint))

    def value(self, value: Any) -> Any:
        """A syntax value with every nested node built and every USE bound (`_MISSING` for a bad USE)."""
        if isinstance(value, s.NodeSyntax):
            return self.node(value)
        if isinstance(value, s.Use):
            target = self.defs.get(value.name)
            if target is None and self._instance_depth:
                # Inside a PROTO instance's field: the DEF may be in the default value of one of its
                # earlier fields, which the PROTO stage knows (it reports the USE if not).
                return Node(PENDING_USE, value.span, None, value.name)
            if target is None:
                self._missing_uses.append(value)
                return _MISSING
            return target
        if isinstance(value, s.MFList):
            items = [self.value(item) for item in value.items]
            return s.MFList([i for i in items if i is not _MISSING], value.span)
        if isinstance(value, s.IsRef) and not self.in_proto:
            self._error("'IS' is only allowed in a field of a PROTO body", value.span)
        return value

    def node(self, syntax: s.NodeSyntax) -> Node:
        """Build one node and register its DEF name (after the node, as Webots does)."""
        schema = node_schema(syntax.type_name)
        node = Node(syntax.type_name, syntax.span, schema, syntax.def_name)
        self.count += 1
        if syntax.type_name == "Supervisor" and schema is not None:
            # A Supervisor node (before R2018b) is a Robot with supervisor rights, as Webots converts it.
            node.fields["supervisor"] = True
            self._warn_once(syntax.type_name, "", "Supervisor is an old node type (before R2018b): Webots reads "
                            "it as a Robot with supervisor TRUE", syntax.span)
        elif schema is not None and schema.name != syntax.type_name:
            self._warn_once(syntax.type_name, "", f"{syntax.type_name} is an old name: Webots reads it as "
                            f"{schema.name}", syntax.span)
        elif schema is not None and schema.deprecated:
            self._warn_once(syntax.type_name, "", f"{syntax.type_name} is an old node type that current Webots "
                            "no longer has", syntax.span)
        self._instance_depth += schema is None
        for field in syntax.fields:
            self._field(node, field)
        self._instance_depth -= schema is None
        if syntax.def_name is not None:
            self.defs[syntax.def_name] = node
        return node

    def _warn_once(self, type_name: str, field: str, message: str, span: Span) -> None:
        if (type_name, field) not in self._warned:
            self._warned.add((type_name, field))
            self._warn(message, span)

    def _field(self, node: Node, field: s.FieldSyntax) -> None:
        value = self.value(field.value)
        if value is _MISSING:  # reported once the whole scope is read
            return
        if field.hidden:
            node.hidden[field.name] = value
            return
        if field.name in node.fields:
            self._warn(f"field '{field.name}' is given twice in {node.type_name}: the last one counts", field.span)
        node.field_spans[field.name] = field.span
        if node.schema is None:  # PROTO instance: typed later against the PROTO interface
            node.fields[field.name] = value
            return
        field_schema = node.schema.field(field.name)
        if field_schema is None:
            close = node.schema.suggest(field.name)
            self._error(f"unknown field '{field.name}' in {node.type_name}", field.span,
                        f"did you mean '{close}'?" if close else None)
            return
        if isinstance(value, s.IsRef):
            node.fields[field.name] = value
            return
        typed = self._typed(node, field_schema, value, field.span)
        if typed is _FAILED:
            return
        if field_schema.kind == "deprecatedField":
            self._warn_once(node.type_name, field.name,
                            f"field '{field.name}' of {node.type_name} is deprecated", field.span)
        self._check_nodes(node, field_schema, typed)
        self._check_allowed(node, field_schema, typed, field.span)
        node.fields[field.name] = typed

    def _typed(self, node: Node, field_schema: FieldSchema, value: Any, span: Span) -> Any:
        what = f"field '{field_schema.name}' of {node.type_name}"
        try:
            return coerce(value, field_schema.type, what, _is_node)
        except SchemaError as exc:
            legacy = _legacy(node.base_type, field_schema.name, value)
            if legacy is not None:
                converted, message = legacy
                self._warn(message, span)
                return converted
            self._error(exc.message, exc.span or span)
            return _FAILED

    def _check_nodes(self, node: Node, field_schema: FieldSchema, typed: Any) -> None:
        accepts = field_schema.accepts
        if accepts is None:
            return
        for child in typed if isinstance(typed, list) else [typed]:
            if isinstance(child, Node) and child.schema is not None and child.schema.role not in accepts:
                self._error(f"{child.type_name} cannot be used in field '{field_schema.name}' of "
                            f"{node.type_name}", child.span,
                            f"that field takes {_roles_text(accepts)} nodes")

    def _check_allowed(self, node: Node, field_schema: FieldSchema, typed: Any, span: Span) -> None:
        allowed = field_schema.allowed
        if allowed is None or field_schema.type.startswith("MF") or typed in allowed:
            return
        shown = ", ".join(format_value(a, field_schema.type) for a in allowed)
        close = suggest(str(typed), [str(a) for a in allowed]) if isinstance(typed, str) else None
        self._warn(f"{format_value(typed, field_schema.type)} is not an allowed value of field "
                   f"'{field_schema.name}' of {node.type_name} (allowed: {shown})", span,
                   f"did you mean \"{close}\"?" if close else None)


_FAILED = object()
_MISSING = object()


def _is_node(value: Any) -> bool:
    return isinstance(value, Node)


def _roles_text(roles: frozenset[str]) -> str:
    names = sorted(r.replace("_", " ") for r in roles)
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " or " + names[-1]


def _legacy(type_name: str, field_name: str, value: Any) -> tuple[Any, str] | None:
    """Old values Webots converts on load: returns (new value, warning) or None."""
    if type_name == "WorldInfo" and field_name == "gravity" and isinstance(value, s.Numbers):
        numbers = [float(t) for t in value.tokens()]
        if len(numbers) == 3:
            length = math.sqrt(sum(v * v for v in numbers))
            return length, (f"deprecated gravity vector ({' '.join(value.tokens())}) in WorldInfo: "
                            f"using its length {length:g}")
    if type_name == "ImageTexture" and field_name == "filtering" and isinstance(value, s.Bool):
        return (4 if value.value else 0), "boolean 'filtering' values are deprecated since Webots 8.6: converted"
    return None


def build_scene(syntax: s.FileSyntax) -> Scene:
    """Build the typed scene of a parsed world file.

    Args:
        syntax: the syntax tree of a .wbt file.

    Returns:
        The scene, with its version, coordinate system and legacy flags.

    Raises:
        SchemaError: with every error found (up to `MAX_ERRORS`), when the world breaks the schema.
    """
    allow_deep_worlds()
    version = Version.parse(syntax.version or "") or R2022B
    builder = NodeBuilder(syntax.path, version)
    for extern in syntax.externprotos:
        if not extern.url.lower().endswith(".proto"):
            builder._error(f"EXTERNPROTO URL must end with '.proto': \"{extern.url}\"", extern.span)
    nodes = builder.build(syntax.nodes)
    if builder.errors:
        raise SchemaError("", diagnostics=builder.errors)
    scene = Scene(syntax.path, version, syntax.info, nodes, syntax.externprotos, syntax.protos,
                  _coordinate_system(nodes, version), before_r2022a(version), version < R2022B, builder.count,
                  list(syntax.warnings) + builder.warnings)
    return scene


def _coordinate_system(nodes: list[Node], version: Version) -> str:
    # Webots reads coordinateSystem only from R2020b files; older worlds are NUE.
    if version < R2020B:
        return "NUE"
    info = next((n for n in nodes if n.base_type == "WorldInfo"), None)
    value = info.fields.get("coordinateSystem") if info is not None else None
    return value if isinstance(value, str) else "ENU"
