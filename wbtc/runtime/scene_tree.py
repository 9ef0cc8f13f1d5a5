"""The world as a Supervisor sees it: node ids, DEF names, parents, fields and their values.

Webots gives every node a unique id (the root Group is 0) and shows a PROTO instance as one node
whose fields are the PROTO's interface; the nodes inside it are hidden except for those passed in
through its fields (`getFromProtoDef` and `getBaseNodeField` reach the rest). Here the expanded
scene is walked the same way: a PROTO instance is its expanded root node, with `node.proto`
remembering the instance (name, interface values).

Field values cross the wire as plain Python (lists of floats, str, bool, int); `to_typed` turns
them back into the scene's typed values (NamedTuples) when a supervisor writes a field.

Not honoured yet: fields of nodes hidden inside PROTO instances when read through a node reached
by `getFromProtoDef` are read from the expanded node (as `getBaseNodeField` does).
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import Any

import numpy as np

from wbtc.proto.model import load_proto
from wbtc.scene.model import Node, Scene, tree_edges, visible_nodes
from wbtc.vrml.values import _TUPLES

#: Webots' field type codes (WB_SF_*; WB_MF_* = WB_SF_* | 0x10).
TYPE_CODES = {"SFBool": 0x01, "SFInt32": 0x02, "SFFloat": 0x03, "SFVec2f": 0x04, "SFVec3f": 0x05,
              "SFRotation": 0x06, "SFColor": 0x07, "SFString": 0x08, "SFNode": 0x09}
TYPE_CODES.update({"MF" + name[2:]: code | 0x10 for name, code in list(TYPE_CODES.items())})

#: The root Group's id, as in Webots.
ROOT_ID = 0


@dataclass
class FieldRef:
    """One field of one node as a supervisor holds it."""

    id: int
    node: Node
    name: str
    type: str
    # 0 (False): a field of the (expanded) built-in node; 1 (True): an interface field of the node's
    # PROTO; 2, 3...: a parameter of the PROTO it derives from, and so on (read-only).
    proto: int


class SceneTree:
    """Ids, parents and DEF names of every node of an expanded scene."""

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self.root = Node("Group", scene.nodes[0].span if scene.nodes else None, None)  # type: ignore[arg-type]
        self.by_id: dict[int, Node] = {ROOT_ID: self.root}
        self.ids: dict[int, int] = {id(self.root): ROOT_ID}
        self.parents: dict[int, int] = {}
        self.fields: list[FieldRef] = []
        self.field_keys: dict[tuple[int, str, int], int] = {}
        self.dead_fields: list[int] = []  # field ids a PROTO regeneration made invalid, in order
        self.dead_nodes: list[int] = []  # ids of nodes deleted from the scene, in order (see `prune`)
        self._pose_links: dict[int, tuple[Node, str]] | None = None  # see `linked_pose`
        self.refresh()

    # -- ids ----------------------------------------------------------------------------------------
    def refresh(self) -> None:
        """Give ids to nodes not seen yet (after an import) and recompute every parent."""
        self.parents = {}
        self._frame_parents: dict[int, int] | None = None  # see `frame_parent`, found on demand
        self._pose_links = None
        edges = list(self._edges(self.root, self.scene.nodes, hidden=True))
        # A template PROTO's node takes the id its template was given as `context.id`, as in Webots.
        claimed = {id(node): number for _, node in edges if id(node) not in self.ids
                   and node.proto is not None
                   and (number := node.proto.claimed_id()) is not None and number not in self.by_id}
        taken = set(claimed.values())
        following = max(self.by_id) + 1  # the id after the largest given (kept here: `max` per node is quadratic)
        for parent, node in edges:
            if id(node) not in self.ids:
                new = claimed.get(id(node))
                if new is None:
                    new = following
                    while new in taken:
                        new += 1
                following = max(following, new + 1)
                self.ids[id(node)] = new
                self.by_id[new] = node
            self.parents.setdefault(self.ids[id(node)], self.ids[id(parent)])

    def prune(self) -> None:
        """Forget the nodes no field holds any more (removed, or inside a removed or replaced node).

        Webots deletes a removed node with everything inside it: their ids then name no node
        (`getFromId` answers None) and references to their fields are invalid. The ids go to
        `dead_nodes` and the fields to `dead_fields`, which each supervisor's controller is told of.
        """
        self.refresh()
        gone = [node_id for node_id in self.by_id if node_id != ROOT_ID and node_id not in self.parents]
        if not gone:
            return
        objects = set()
        for node_id in gone:
            node = self.by_id.pop(node_id)
            self.ids.pop(id(node), None)
            objects.add(id(node))
            self.dead_nodes.append(node_id)
        for ref in self.fields:
            if id(ref.node) in objects and ref.id not in self.dead_fields:
                self.dead_fields.append(ref.id)
                self.field_keys.pop((id(ref.node), ref.name, ref.proto), None)

    def _edges(self, parent: Node, children: list, hidden: bool) -> Iterator[tuple[Node, Node]]:
        """(parent, child) pairs depth first, in file order; `hidden` also enters PROTO internals."""
        return tree_edges(parent, children, hidden)

    def visible_children(self, node: Node) -> Iterator[Node]:
        """The nodes a supervisor reaches from `node` through its fields."""
        if node is self.root:
            yield from self.scene.nodes
        else:
            yield from visible_nodes(node)

    def parent(self, node: Node) -> Node | None:
        """The node holding `node` (None for top-level nodes and the root)."""
        parent_id = self.parents.get(self.node_id(node))
        return None if parent_id in (None, ROOT_ID) else self.by_id[parent_id]

    def frame_parent(self, node: Node) -> Node | None:
        """The node whose frame `node` stands in.

        That is `parent`, but for a PROTO parameter's node: the body node (a Pose, a Solid) its PROTO's
        body puts it in, not the PROTO instance.
        """
        node_id = self.node_id(node)
        if self._frame_parents is None:
            self._frame_parents = self._find_frame_parents()
        parent_id = self._frame_parents.get(node_id)
        return None if parent_id in (None, ROOT_ID) else self.by_id[parent_id]

    def _find_frame_parents(self) -> dict[int, int]:
        """Node id -> frame parent id: the holder in the innermost PROTO body, the first one there.

        A PROTO parameter's node is met as the instance's interface value, then in every body that
        takes it by IS (several fields may take the same parameter: Webots places the node by the first).
        """
        found: dict[int, tuple[int, int]] = {}  # node id -> (body depth, parent id)

        def walk(parent: Node, children: list, depth: int) -> None:
            for child in children:
                if not isinstance(child, Node) or id(child) not in self.ids:
                    continue
                known = found.get(self.ids[id(child)])
                if known is None or depth > known[0]:
                    found[self.ids[id(child)]] = (depth, self.ids[id(parent)])
                walk(child, list(self.visible_children(child)), depth)
                if child.proto is not None:
                    walk(child, list(child.child_nodes()), depth + 1)

        walk(self.root, self.scene.nodes, 0)
        return {node_id: parent_id for node_id, (_, parent_id) in found.items()}

    def node_id(self, node: Node) -> int:
        """The id of a node (assigned on first sight)."""
        if id(node) not in self.ids:
            self.refresh()
        return self.ids.get(id(node), -1)

    def remove(self, node: Node) -> bool:
        """Take a node out of the field that holds it; False if it is not in a children-like list."""
        parent_id = self.parents.get(self.node_id(node))
        if parent_id is None:
            return False
        parent = self.by_id[parent_id]
        holders = [self.scene.nodes] if parent is self.root else _lists_of(parent)
        for holder in holders:
            for i, item in enumerate(holder):
                if item is node:
                    del holder[i]
                    self.refresh()
                    return True
        for name, value in list(_fields_of(parent).items()):
            if value is node:
                _fields_of(parent)[name] = None
                self.refresh()
                return True
        return False

    # -- references ------------------------------------------------------------------------------
    def ref(self, node: Node | None) -> dict[str, Any] | None:
        """The wire's node ref for a node (None for None)."""
        if node is None:
            return None
        nid = self.node_id(node)
        if node is self.root:
            return {"id": ROOT_ID, "def": "", "type": "Group", "base_type": "Group", "proto": False, "parent": -1}
        return {"id": nid, "def": def_name(node), "type": type_name(node), "base_type": node.base_type,
                "proto": node.proto is not None, "parent": self.parents.get(nid, -1)}

    def from_def(self, path: str, inside: Node | None = None) -> Node | None:
        """`getFromDef`: the first node with that DEF name, depth first; `A.B` looks for B below A."""
        start = inside if inside is not None else self.root
        node: Node | None = start
        for part in path.split("."):
            if node is None:
                return None
            node = self._find_def(node, part, hidden=inside is not None and node is start)
        return node

    def _find_def(self, start: Node, name: str, hidden: bool) -> Node | None:
        children = list(start.child_nodes()) if hidden else list(self.visible_children(start))
        for _, node in self._edges(start, children, hidden=False):
            if def_name(node) == name:
                return node
        return None

    # -- fields ------------------------------------------------------------------------------------
    def linked_pose(self, ref: FieldRef) -> tuple[Node, str] | None:
        """The inner Solid and pose field (translation, rotation) a PROTO parameter is written into by `IS`.

        Found once per tree state: every node's pose field linked outwards, by the parameter it reaches.
        """
        if self._pose_links is None:
            self._pose_links = {}
            for node in list(self.by_id.values()):
                for name, param in ((node.links or {}).items() if isinstance(node, Node) else ()):
                    inner = self.field(node, name, 0) if name in ("translation", "rotation") and param else None
                    actual = actual_field(self, inner) if inner is not None else None
                    if actual is not None and actual is not inner and actual.type == inner.type:
                        self._pose_links.setdefault(actual.id, (node, name))
        return self._pose_links.get(ref.id)

    def field_names(self, node: Node, proto: int) -> list[tuple[str, str]]:
        """(name, type) of a node's fields in declaration order; a PROTO level's interface when `proto`."""
        if node is self.root:
            return [("children", "MFNode")]
        if proto:
            instance = instance_at(node, proto)
            if instance is None:
                return []
            model = load_proto(instance.source.path)
            return [(f.name, f.type) for f in model.fields.values()]
        if node.schema is None:
            return []
        names = _SCHEMA_FIELDS.get(node.schema.name)
        if names is None:  # once per node type: field lookups go through here on every supervisor call
            names = _SCHEMA_FIELDS[node.schema.name] = _webots_order(
                [(f.name, f.type) for f in node.schema.fields.values() if f.kind != "deprecatedField"])
        return names

    def field(self, node: Node, name: str, proto: int) -> FieldRef | None:
        """A field ref, allocated once per (node, name, kind)."""
        types = dict(self.field_names(node, proto))
        if name not in types:
            return None
        key = (id(node), name, int(proto))
        fid = self.field_keys.get(key)
        if fid is None:
            fid = len(self.fields)
            self.field_keys[key] = fid
            self.fields.append(FieldRef(fid, node, name, types[name], int(proto)))
        return self.fields[fid]

    def field_ref(self, ref: FieldRef) -> dict[str, Any]:
        """The wire's field ref."""
        count = len(items_of(self.raw(ref))) if ref.type.startswith("MF") else -1
        return {"id": ref.id, "name": ref.name, "type": TYPE_CODES[ref.type], "count": count}

    def raw(self, ref: FieldRef) -> Any:
        """A field's stored (typed) value."""
        if ref.node is self.root:
            return self.scene.nodes
        if ref.proto:
            instance = instance_at(ref.node, ref.proto)
            return instance.values.get(ref.name) if instance is not None else None
        return ref.node.get(ref.name)

    def store(self, ref: FieldRef, value: Any) -> None:
        """Replace a field's stored value."""
        if ref.node is self.root:
            self.scene.nodes[:] = value
        elif ref.proto:
            ref.node.proto.values[ref.name] = value
        else:
            ref.node.fields[ref.name] = value

    def plain(self, ref: FieldRef, index: int) -> Any:
        """A field's value (one item for MF fields) as the wire carries it."""
        value = self.raw(ref)
        if ref.type.startswith("MF"):
            items = items_of(value)
            if not -len(items) <= index < len(items):
                raise IndexError(index)
            value = items[index]
        if ref.type.endswith("Node"):
            return self.ref(value) if isinstance(value, Node) else None
        return to_plain(value)


def instance_at(node: Node, level: int) -> Any:
    """The PROTO instance a node expands from at `level` (1: its own; 2: the one that PROTO's body is)."""
    instance = node.proto
    for _ in range(int(level) - 1):
        instance = instance.inner if instance is not None else None
    return instance


def proto_names(node: Node) -> list[str]:
    """The node's PROTO chain, its own PROTO first (empty for a built-in node)."""
    names, instance = [], node.proto
    while instance is not None:
        names.append(instance.name)
        instance = instance.inner
    return names


def items_of(value: Any) -> list:
    """An MF value's items as a list (MF numeric fields may be stored as numpy arrays)."""
    return [] if value is None else list(value)


def to_plain(value: Any) -> Any:
    """A typed scalar or vector value as plain Python."""
    if isinstance(value, np.ndarray):
        return [float(v) for v in value.ravel()]
    if isinstance(value, tuple):
        return [float(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def to_typed(field_type: str, value: Any) -> Any:
    """A plain value (one element) typed as the scene stores it for `field_type`."""
    elem = field_type[2:]
    if elem in _TUPLES:
        return _TUPLES[elem](*(float(v) for v in value))
    if elem == "Float":
        return float(value)
    if elem == "Int32":
        return int(value)
    if elem == "Bool":
        return bool(value)
    return value


def def_name(node: Node) -> str:
    """A node's DEF name ('' when none); a PROTO instance's is the instance's."""
    if node.proto is not None and node.proto.def_name:
        return node.proto.def_name
    return node.def_name or ""


def type_name(node: Node) -> str:
    """`getTypeName`: the PROTO name for instances, else the built-in type."""
    return node.proto.name if node.proto is not None else node.base_type


def _fields_of(node: Node) -> dict[str, Any]:
    return node.proto.values if node.proto is not None else node.fields


def _lists_of(node: Node) -> list[list]:
    return [value for value in _fields_of(node).values() if isinstance(value, list)]


#: Each built-in node type's fields as a supervisor sees them (`SceneTree.field_names`).
_SCHEMA_FIELDS: dict[str, list[tuple[str, str]]] = {}
#: Where Webots' node definitions put a Pose's (or Transform's) fields: the frame and the children first,
#: the GUI steps and the hidden velocities last (Solid.wrl: translation, rotation, children, name, ...).
_FIRST = ("translation", "rotation", "scale", "children")
_LAST = ("translationStep", "rotationStep", "linearVelocity", "angularVelocity")


def _webots_order(fields: list[tuple[str, str]]) -> list[tuple[str, str]]:
    """A node's fields in Webots' order (wbtc's schema lists inherited fields first: Group's children)."""
    names = [name for name, _ in fields]
    if "translation" not in names or "children" not in names:
        return fields
    rank = {name: i for i, name in enumerate(_FIRST)}
    last = {name: i for i, name in enumerate(_LAST)}
    return sorted(fields, key=lambda item: (0, rank[item[0]]) if item[0] in rank
                  else (2, last[item[0]]) if item[0] in last else (1, names.index(item[0])))



def actual_field(tree: SceneTree, ref: FieldRef) -> FieldRef | None:
    """`Field.getActualField`: the scene-tree field a field is linked to by IS, itself for one; None if unlinked.

    A PROTO's parameter (a level of an instance's chain) or a field of a node its body made follows
    the body's `IS` links outwards, level by level, to a parameter of an instance written in the world;
    a link missing on the way (an unconnected field) ends it with None.
    """
    if ref.proto:
        instance, name = instance_at(ref.node, ref.proto), ref.name
    elif ref.node.link_owner is None:
        return ref  # a field of a node written in the world
    else:
        instance, name = ref.node.link_owner, (ref.node.links or {}).get(ref.name)
    while instance is not None and name is not None:
        if instance.owner is None:  # an instance written in the world: its own parameter
            node = next((n for n in tree.by_id.values() if isinstance(n, Node) and n.proto is instance), None)
            return tree.field(node, name, 1) if node is not None else None
        instance, name = instance.owner, (instance.links or {}).get(name)
    return None


def store_pose(node: Node, name: str, value: Any) -> None:
    """Remember a moved Solid's new translation/rotation (recompiles place static bodies from it)."""
    node.fields[name] = value
    if node.proto is not None and name in node.proto.values:
        node.proto.values[name] = value
