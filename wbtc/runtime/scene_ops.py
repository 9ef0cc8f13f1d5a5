"""Scene edits a Supervisor makes: field values, imported and removed nodes, PROTO re-expansion.

Edits change the expanded scene in place; the supervisor then recompiles it. A PROTO instance is
its expanded root node with `node.proto` holding the interface values: changing one of those
values expands the PROTO anew from them (`reexpand`) and puts the new root where the old one was,
under the same node id. Webots regenerates a template PROTO only for a field its code reads
(`regenerates`): its nodes are made anew (a robot among them restarts its controller, old internal
node references die, and so does every PROTO-internal field reference the controllers hold, as
libController drops them); any other change keeps the nodes inside with their ids. Imported VRML
text is parsed, typed and expanded like a world's nodes, with the world's PROTO resolver.

Not honoured yet: importing into a field of a node hidden inside a PROTO instance; USE of DEF
names of the world inside imported text.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from wbtc.errors import WbtcError
from wbtc.proto.expand import Expander
from wbtc.proto.instances import ProtoInstance, Typed
from wbtc.proto.model import load_proto
from wbtc.proto.resolve import Resolver
from wbtc.proto.template_render import fields_read
from wbtc.runtime.scene_tree import FieldRef, SceneTree, items_of, to_typed
from wbtc.scene.build import NodeBuilder
from wbtc.scene.model import Node
from wbtc.scene.printer import format_node
from wbtc.vrml.parser import parse_body
from wbtc.vrml.values import format_value

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


def set_value(tree: SceneTree, ref: FieldRef, index: int, value: Any) -> None:
    """`setSF*` (index -1) or `setMF*`: store the typed value."""
    if ref.type.startswith("MF"):
        items = items_of(tree.raw(ref))
        if not -len(items) <= index < len(items):
            raise WbtcError(f"index {index} out of range for field '{ref.name}'")
        items[index] = to_typed(ref.type, value)
        tree.store(ref, items)
    else:
        tree.store(ref, to_typed(ref.type, value))


def insert_value(tree: SceneTree, ref: FieldRef, index: int, value: Any) -> None:
    """`insertMF*`: a new item before `index` (the end when index equals the count)."""
    items = items_of(tree.raw(ref))
    items.insert(index if index >= 0 else len(items) + index + 1, to_typed(ref.type, value))
    tree.store(ref, items)


def remove_value(tree: SceneTree, ref: FieldRef, index: int) -> None:
    """`removeMF`: drop one item."""
    items = items_of(tree.raw(ref))
    if not -len(items) <= index < len(items):
        raise WbtcError(f"index {index} out of range for field '{ref.name}'")
    del items[index]
    tree.store(ref, items)


def import_node(tree: SceneTree, ref: FieldRef, position: int, text: str) -> Node:
    """Parse, expand and insert the nodes written in VRML into an SFNode or MFNode field.

    An MFNode field gets every node of the text, in order, from `position` on (Webots imports
    "Solid { } Solid { }" as two nodes); an SFNode field gets the first one. The text may USE the
    world's DEF nodes. Returns the first node.
    """
    scene = tree.scene
    items = parse_body("{ " + text + " }", str(scene.path))
    builder = NodeBuilder(str(scene.path), scene.version)
    # The text may USE the world's own DEF nodes (Webots: those before the insertion point; wbtc
    # takes every DEF outside PROTO bodies, the last one of a name winning, as a world file's USE).
    for _, node in tree._edges(tree.root, scene.nodes, hidden=False):
        if node.def_name:
            builder.defs[node.def_name] = node
    built = builder.build(items)
    if builder.errors:
        raise WbtcError(builder.errors[0].message)
    if not built:
        raise WbtcError("the text holds no node")
    expander = Expander(scene)
    expander.last_context_id = max(tree.by_id)  # templates' `context.id`s after every id in use
    resolver = Resolver(Path(scene.path), scene.externprotos, Path(scene.path))
    nodes = []
    for raw in built if ref.type != "SFNode" else built[:1]:
        node = expander.expand(raw, resolver, top_level=ref.node is tree.root)
        if expander.result.errors:
            raise WbtcError(expander.result.errors[0].message)
        if node is None:
            raise WbtcError(f"the PROTO of '{raw.type_name}' was not found")
        nodes.append(node)
    if ref.type == "SFNode":
        tree.store(ref, nodes[0])
    else:
        items = tree.raw(ref)
        if items is None:
            items = []
            tree.store(ref, items)
        at = position if position >= 0 else len(items) + position + 1
        items[at:at] = nodes
        if ref.node is not tree.root and ref.node.proto is None:
            ref.node.fields[ref.name] = items
    tree.refresh()
    return nodes[0]


def reexpand(tree: SceneTree, node: Node, regenerate: bool | None = None, forget: bool = False) -> Node:
    """Expand a PROTO instance anew from its (changed) interface values; same id, same place.

    Args:
        tree: the scene tree holding `node`.
        node: the instance's root node.
        regenerate: whether Webots makes the instance's nodes anew (see `regenerates`); None: when
            any of its PROTO levels is a template.
        forget: a regenerated instance's old internal nodes lose their ids, as Webots deletes them
            when a supervisor's write regenerates it (a reset keeps them: its values are copies).
    """
    info = node.proto
    model = load_proto(info.source.path)
    raw = Node(info.name, info.span, None, info.def_name)
    raw.fields = {name: Typed(model.fields[name].type, value) for name, value in info.values.items()
                  if name in model.fields}
    scene = tree.scene
    expander = Expander(scene)
    # The regenerated node keeps its id, which its template reads again as `context.id`; templates
    # inside it are numbered after every id in use.
    expander.context_ids[id(raw)] = tree.node_id(node)
    expander.last_context_id = max(tree.by_id)
    resolver = Resolver(Path(scene.path), scene.externprotos, Path(scene.path))
    new = expander.expand(raw, resolver, top_level=True)
    if new is None or expander.result.errors:
        raise WbtcError(f"PROTO {info.name} cannot be expanded with the new values")
    if regenerate is None:
        regenerate = any(load_proto(level.source.path).is_template for level in _levels(info))
    _replace(tree, node, new, keep_inside=not regenerate, forget=forget)
    return new


def regenerates(node: Node, field: str) -> bool:
    """Whether a change of an instance's interface field makes Webots regenerate it.

    Webots regenerates a template PROTO when a field its code reads changes (at any level of a
    derived PROTO: the field passed on by IS); a field only used by IS is passed to the nodes.
    """
    names = {field}
    for level in _levels(node.proto) if node.proto is not None else []:
        if level is not node.proto:  # this level's fields that take the names of the level above by IS
            names = {own for own, outer in (level.links or {}).items() if outer in names}
        model = load_proto(level.source.path)
        if model.is_template and names & fields_read(model.syntax.template or ""):
            return True
    return False


def _levels(info: ProtoInstance) -> list[ProtoInstance]:
    """The PROTO levels of an instance: its own, then the one it derives from, and so on."""
    levels: list[ProtoInstance] = []
    level: ProtoInstance | None = info
    while level is not None:
        levels.append(level)
        level = level.inner
    return levels


def _inside(tree: SceneTree, node: Node) -> list[Node]:
    """The nodes inside a PROTO instance (interface values and body, internals included), in order."""
    return [n for _, n in tree._edges(node, [*tree.visible_children(node), *node.child_nodes()], True)]


def _carry_ids(tree: SceneTree, old: Node, new: Node) -> dict[int, Node] | None:
    """Give the nodes inside `new` the ids of their counterparts inside `old`; None when they differ in shape."""
    before, after = _inside(tree, old), _inside(tree, new)
    if [n.type_name for n in before] != [n.type_name for n in after]:
        return None
    moved: dict[int, Node] = {}
    for was, now in zip(before, after, strict=True):
        if id(was) in tree.ids and id(now) not in tree.ids:
            node_id = tree.ids.pop(id(was))
            tree.ids[id(now)] = node_id
            tree.by_id[node_id] = now
            moved[id(was)] = now
    return moved


def _retarget(tree: SceneTree, ref: FieldRef, node: Node) -> None:
    """A field reference now reads `node` (the same field, found again under its new node)."""
    if tree.field_keys.get((id(ref.node), ref.name, ref.proto)) == ref.id:
        del tree.field_keys[(id(ref.node), ref.name, ref.proto)]
    ref.node = node
    tree.field_keys[(id(node), ref.name, ref.proto)] = ref.id


def _replace(tree: SceneTree, old: Node, new: Node, keep_inside: bool = False, forget: bool = False) -> None:
    """Put `new` where `old` is, with its id.

    A template PROTO (at any level) is regenerated: references to its internal nodes and fields
    become invalid, as in Webots. Any other PROTO is not regenerated by Webots, only its fields
    follow their parameters (`keep_inside`): the nodes inside keep their ids and field references.
    """
    node_id = tree.node_id(old)
    parent = tree.by_id.get(tree.parents.get(node_id, -1))
    if parent is None or parent is tree.root:
        tree.scene.nodes[:] = [new if item is old else item for item in tree.scene.nodes]
    else:
        _swap_inside(parent, old, new)
    # The old root is dropped: its Python id may be reused by a node made later, which must not pass for it.
    tree.ids.pop(id(old), None)
    tree.ids[id(new)] = node_id
    tree.by_id[node_id] = new
    moved = _carry_ids(tree, old, new) if keep_inside else None
    # A regenerated instance: references to its internal fields (and to fields of the nodes inside it)
    # become invalid; its interface fields stay valid and now belong to the new root.
    inside = {id(old)} | {id(n) for n in _inside(tree, old)}
    for ref in tree.fields:
        if id(ref.node) not in inside:
            continue
        if ref.node is old and (ref.proto or moved is not None):
            _retarget(tree, ref, new)
        elif moved is not None and id(ref.node) in moved:
            _retarget(tree, ref, moved[id(ref.node)])
        elif ref.id not in tree.dead_fields:
            tree.dead_fields.append(ref.id)
            tree.field_keys.pop((id(ref.node), ref.name, ref.proto), None)
    if forget and not keep_inside:
        _forget_internals(tree, old, new)
    tree.refresh()


def _forget_internals(tree: SceneTree, old: Node, new: Node) -> None:
    """What a supervisor's regeneration of a PROTO makes invalid, as Webots and its controller library do.

    Webots deletes the regenerated instance's old internal nodes: references to them become invalid
    (nodes given as parameters are the same objects in the new instance and stay). And the controller
    library, told that a node was regenerated, drops every PROTO-internal field reference it holds,
    of any PROTO (libController's `remove_internal_proto_nodes_and_fields_from_list`): they have to
    be looked up again.
    """
    kept = {id(n) for n in _inside(tree, new)}
    for gone in _inside(tree, old):
        if id(gone) not in kept and id(gone) in tree.ids:
            tree.by_id.pop(tree.ids.pop(id(gone)), None)
    visible = {id(n) for _, n in tree._edges(tree.root, tree.scene.nodes, hidden=False)}
    for ref in tree.fields:
        internal = not ref.proto and (ref.node.proto is not None or id(ref.node) not in visible)
        if internal and ref.id not in tree.dead_fields:
            tree.dead_fields.append(ref.id)
            tree.field_keys.pop((id(ref.node), ref.name, ref.proto), None)


def _swap_inside(root: Node, old: Node, new: Node) -> None:
    """Put `new` wherever `old` is in the fields of `root` and of every node inside it, PROTO internals included.

    A node given as a PROTO parameter is also in the fields of the PROTO's body that take the
    parameter by IS (each holds its own copy of the parameter's list), and in the values of the PROTO
    levels it went through: Webots regenerates it in all of them, and the compiler reads the body's.
    """
    seen: set[int] = set()
    stack = [root]
    while stack:
        node = stack.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        # A derived PROTO keeps each level's values.
        levels = [node.fields] + ([level.values for level in _levels(node.proto)] if node.proto else [])
        for fields in levels:
            for name, value in fields.items():
                if value is old:
                    fields[name] = new
                elif isinstance(value, Node):
                    stack.append(value)
                elif isinstance(value, list):
                    for i, item in enumerate(value):
                        if item is old:
                            value[i] = new
                        elif isinstance(item, Node):
                            stack.append(item)


def export_string(node: Node, hidden: list[str] | None = None) -> str:
    """`exportString`: the node as VRML (a PROTO instance with its interface values).

    Args:
        node: the node (the expanded root of a PROTO instance is written as the instance).
        hidden: `hidden NAME value` lines to close a PROTO instance with (worldSave's saved state).
    """
    if node.proto is None:
        return format_node(node, omit_defaults=True)
    model = load_proto(node.proto.source.path)
    head = f"DEF {node.proto.def_name} " if node.proto.def_name else ""
    lines = [f"{head}{node.proto.name} {{"]
    for name, value in node.proto.values.items():
        interface = model.fields.get(name)
        # An empty MF value (a list, or an empty array for numeric MF fields) is the default: not written.
        if interface is None or value is None or (hasattr(value, "__len__") and len(value) == 0):
            continue
        lines.append(f"  {name} {format_value(value, interface.type, lambda n: format_node(n, '  ', True))}")
    lines += [f"  {line}" for line in hidden or []]
    lines.append("}")
    return "\n".join(lines)


def export_image(sim: Simulation, path: str, quality: int) -> None:
    """`exportImage`: the Viewpoint's view saved as PNG or JPEG (by extension)."""
    from PIL import Image

    try:
        camera = sim.model.camera("viewpoint").id
    except KeyError:
        camera = -1
    rgb = sim.render(camera, 640, 480)
    image = Image.fromarray(rgb)
    if path.lower().endswith((".jpg", ".jpeg")):
        image.save(path, quality=max(1, min(int(quality), 100)))
    else:
        image.save(path)
