"""The typed scene: nodes with checked values, and the world that holds them.

A `Node` is either a built-in node (its `schema` is set and `fields` hold typed values) or a PROTO
instance (`schema` is None and `fields` hold the values as written, with nested nodes already
built; the PROTO stage types them against the PROTO's interface). A USE refers to the very node
object of its DEF, as Webots' USE is an exact copy of the DEF node.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import Any

from wbtc.errors import Diagnostic, Span
from wbtc.schema.registry import NodeSchema
from wbtc.vrml import syntax as s
from wbtc.vrml.header import Version

#: The type name of a placeholder for a USE whose DEF may come from a PROTO field's default.
PENDING_USE = "USE"

#: Python frames a world may need: building, expanding and compiling a node take about five frames per
#: level of nesting, so the interpreter's default limit (1000) stopped a world at about 200 levels: a
#: chain robot of 150 links (each a HingeJoint and its Solid, in the last link's children) did not load.
RECURSION_LIMIT = 20000


def allow_deep_worlds() -> None:
    """Raise the interpreter's recursion limit to RECURSION_LIMIT (never lower it): Webots has none."""
    if sys.getrecursionlimit() < RECURSION_LIMIT:
        sys.setrecursionlimit(RECURSION_LIMIT)


class Node:
    """One node of a scene.

    Attributes:
        type_name: the node type as written ("Solid", "E-puck").
        fields: the fields written in the file (typed for built-in nodes, raw for PROTO instances).
        span: where the node type name is.
        def_name: the DEF name, if any.
        schema: the built-in node type, or None for a PROTO instance.
        hidden: `hidden name value` lines of a PROTO instance (saved state, kept as written).
        field_spans: where each written field's name is.
        origin: for nodes made by a PROTO, the span of the instance that made them.
        links: for nodes made by a PROTO body, their fields written `IS param` (field name -> param name).
        link_owner: the PROTO instance (`proto.expand.ProtoInstance`) whose params `links` name.
    """

    __slots__ = ("type_name", "fields", "span", "def_name", "schema", "hidden", "field_spans", "origin",
                 "proto", "links", "link_owner")

    def __init__(self, type_name: str, span: Span, schema: NodeSchema | None, def_name: str | None = None) -> None:
        self.type_name = type_name
        self.span = span
        self.schema = schema
        self.def_name = def_name
        self.fields: dict[str, Any] = {}
        self.field_spans: dict[str, Span] = {}
        self.hidden: dict[str, s.Value] = {}
        self.origin: Span | None = None
        self.proto: Any = None
        self.links: dict[str, str] | None = None
        self.link_owner: Any = None

    @property
    def pending_use(self) -> str | None:
        """For a USE written in a PROTO instance's field whose DEF is not in the file: the DEF name.

        Webots gives the instance its fields in the PROTO's interface order, defaults included, so
        the DEF may be in the default value of an earlier field; the PROTO stage binds it.
        """
        return self.def_name if self.type_name == PENDING_USE else None

    @property
    def is_proto(self) -> bool:
        """True for a PROTO instance (a node type that is not built in)."""
        return self.schema is None

    @property
    def base_type(self) -> str:
        """The built-in type name (the schema's name, so old aliases read as the new name)."""
        return self.schema.name if self.schema is not None else self.type_name

    def get(self, name: str) -> Any:
        """A field's value: the written one, else the schema default (None if neither exists)."""
        if name in self.fields:
            return self.fields[name]
        if self.schema is not None:
            field_schema = self.schema.field(name)
            if field_schema is not None:
                return field_schema.default
        return None

    def is_a(self, type_name: str) -> bool:
        """True if this built-in node is `type_name` or derives from it."""
        return self.schema is not None and self.schema.is_a(type_name)

    def child_nodes(self) -> Iterator[Node]:
        """Nodes held directly in this node's fields (written values only, in field order)."""
        for value in self.fields.values():
            yield from nodes_in(value)

    def __repr__(self) -> str:
        prefix = f"DEF {self.def_name} " if self.def_name else ""
        return f"<{prefix}{self.type_name} at {self.span}>"


def tree_edges(parent: Any, children: list, hidden: bool = True) -> Iterator[tuple[Any, Node]]:
    """(parent, child) pairs depth first in file order, as a supervisor walks the scene.

    A PROTO instance's interface values come first, then (with `hidden`) the nodes of its body.
    This order numbers the nodes (`wbtc.runtime.scene_tree.SceneTree` ids).
    """
    for child in children:
        if not isinstance(child, Node):
            continue
        yield parent, child
        yield from tree_edges(child, list(visible_nodes(child)), hidden)
        if hidden and child.proto is not None:
            yield from tree_edges(child, list(child.child_nodes()), hidden)


def visible_nodes(node: Node) -> Iterator[Node]:
    """The nodes a supervisor reaches from `node` through its fields (a PROTO instance's: its interface values)."""
    if node.proto is not None:
        for value in node.proto.values.values():
            yield from nodes_in(value)
    else:
        yield from node.child_nodes()


def nodes_in(value: Any) -> Iterator[Node]:
    """The nodes held in a field value (a node, or a list of them), in order."""
    if isinstance(value, Node):
        yield value
    elif isinstance(value, list):
        for item in value:
            yield from nodes_in(item)
    elif isinstance(value, s.MFList):
        for item in value.items:
            yield from nodes_in(item)


def walk(nodes: list[Node], seen: set[int] | None = None) -> Iterator[Node]:
    """Every node reachable from `nodes`, depth first, each once (USEd nodes are not revisited)."""
    seen = set() if seen is None else seen
    for node in nodes:
        if id(node) in seen:
            continue
        seen.add(id(node))
        yield node
        yield from walk(list(node.child_nodes()), seen)


@dataclass(slots=True)
class Scene:
    """A world read into typed nodes.

    Attributes:
        path: the world file.
        version: the header's Webots version.
        info: the header comment lines.
        nodes: the top-level nodes in file order.
        externprotos: the EXTERNPROTO declarations.
        protos: PROTOs declared in the world file itself.
        coordinate_system: "ENU", "NUE" or "EUN" (NUE for files older than R2020b without the field).
        legacy_axes: the file predates R2022a (cylinders along y, cameras along -z).
        pre_externproto: the file predates R2022b (library PROTOs are named without EXTERNPROTO).
        node_count: how many nodes the file writes (USE not counted).
        warnings: what is odd but not wrong.
    """

    path: str
    version: Version
    info: list[str]
    nodes: list[Node]
    externprotos: list[s.ExternProto]
    protos: list[s.ProtoSyntax]
    coordinate_system: str
    legacy_axes: bool
    pre_externproto: bool
    node_count: int
    warnings: list[Diagnostic] = field(default_factory=list)

    def world_info(self) -> Node | None:
        """The WorldInfo node, if the world has one."""
        return next((n for n in self.nodes if n.base_type == "WorldInfo"), None)

    def walk(self) -> Iterator[Node]:
        """Every node of the world, depth first, each once."""
        return walk(self.nodes)
