"""The Supervisor's `worldSave`: the running world written back as a .wbt file, as it is now.

The file keeps the original's header version (so its axes conventions still apply) and everything
it wrote before its first node (EXTERNPROTO lines, PROTOs declared in the file, comments), then
each top-level node: built-in nodes with all their fields, PROTO instances with their interface
values. Solids that move are written where they are, and a Joint's `position` is its current
angle or length (with its endPoint where the joint put it), as Webots saves them; the scene itself
is left as it was.

Not honoured yet: the hidden fields Webots writes for the joints inside a PROTO instance (an
E-puck's wheels are saved at their initial angles), EXTERNPROTO lines for PROTOs first used by
nodes a supervisor imported, a Joint whose `jointParameters` is NULL (its position is not saved).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from wbtc.runtime import poses
from wbtc.runtime.scene_ops import export_string, store_pose
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.scene_tree import SceneTree
    from wbtc.runtime.simulation import Simulation

_ABSENT = object()  # a field a node did not have before saving
_JOINT_PARAMETERS = {"HingeJoint": ("jointParameters",), "SliderJoint": ("jointParameters",),
                     "Hinge2Joint": ("jointParameters", "jointParameters2")}


def save_world(sim: Simulation, tree: SceneTree, source: Path, target: Path) -> None:
    """Write the world as it is now to `target` (`source`: the file it was loaded from).

    Raises:
        OSError: the file cannot be written.
    """
    undo: list[tuple[Any, str, Any, Any]] = []
    try:
        _live_values(sim, tree, undo)
        nodes = [export_string(node) for node in tree.visible_children(tree.root)]
    finally:
        for owner, name, field_value, proto_value in reversed(undo):
            if field_value is _ABSENT:
                owner.fields.pop(name, None)
            else:
                owner.fields[name] = field_value
            if owner.proto is not None and proto_value is not _ABSENT:
                owner.proto.values[name] = proto_value
    text = _prologue(source, tree) + "\n".join(nodes) + "\n"
    temp = target.with_name(f".{target.name}.part")
    temp.write_text(text, encoding="utf-8")
    temp.replace(target)


def _live_values(sim: Simulation, tree: SceneTree, undo: list) -> None:
    """Put the current poses and joint positions in the scene, remembering what to put back."""
    for node in list(tree.by_id.values()):
        if not isinstance(node, Node):
            continue
        live = poses.local_pose(sim, node)
        if live is not None:
            for name, value in zip(("translation", "rotation"), live, strict=True):
                _remember(node, name, undo)
                store_pose(node, name, value)
        for index, field_name in enumerate(_JOINT_PARAMETERS.get(node.base_type, ())):
            params, end = node.get(field_name), node.get("endPoint")
            body = poses.solid_body(sim, end) if isinstance(end, Node) else None
            if not isinstance(params, Node) or body is None or index >= int(sim.model.body_jntnum[body]):
                continue
            joint = int(sim.model.body_jntadr[body]) + index
            _remember(params, "position", undo)
            params.fields["position"] = float(sim.data.qpos[int(sim.model.jnt_qposadr[joint])])


def _remember(node: Node, name: str, undo: list) -> None:
    proto_value = node.proto.values.get(name, _ABSENT) if node.proto is not None else _ABSENT
    undo.append((node, name, node.fields.get(name, _ABSENT), proto_value))


def _prologue(source: Path, tree: SceneTree) -> str:
    """The source file's header line and everything it wrote before its first node."""
    lines = source.read_text(encoding="utf-8", errors="replace").splitlines(keepends=True)
    spans = [node.span.line for node in tree.visible_children(tree.root)
             if node.span is not None and Path(node.span.file).resolve() == source.resolve()]
    # Line 1 is always the header: nodes imported from strings at run time carry spans counted from
    # their own text's first line, which must not cut it off.
    first = max(min(spans) if spans else len(lines) + 1, 2)
    return "".join(lines[:first - 1]).rstrip("\n") + "\n"
