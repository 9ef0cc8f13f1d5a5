"""The Supervisor's `worldSave`: the running world written back as a .wbt file, as it is now.

The file keeps the original's header version (so its axes conventions still apply) and everything
it wrote before its first node (EXTERNPROTO lines, PROTOs declared in the file, comments), then
each top-level node: built-in nodes with all their fields, PROTO instances with their interface
values. Solids that move are written where they are, and a Joint's `position` is its current
angle or length (with its endPoint where the joint put it), as Webots saves them; the scene itself
is left as it was.

A top-level PROTO instance also gets Webots' `hidden` lines for the state its interface does not
expose (`wbtc.proto.hidden` reads them back): `position_N_J` (and `position2_`, `position3_`) of
its joints not at 0, and `translation_N`, `rotation_N`, `linearVelocity_N`, `angularVelocity_N`
of its Solids that move (velocities when not zero).

Not honoured yet: hidden lines of PROTO instances nested in built-in nodes, a BallJoint's
positions; EXTERNPROTO lines for PROTOs first used by
nodes a supervisor imported, a Joint whose `jointParameters` is NULL (its position is not saved).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from wbtc.proto.hidden import joints_of, solids_of
from wbtc.proto.model import load_proto
from wbtc.runtime import poses
from wbtc.runtime.scene_ops import export_string
from wbtc.runtime.scene_tree import SceneTree, store_pose
from wbtc.scene.model import Node
from wbtc.vrml.values import format_value

if TYPE_CHECKING:
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
        nodes = [export_string(node, _hidden_lines(sim, node)) for node in tree.visible_children(tree.root)]
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


def _hidden_lines(sim: Simulation, node: Node) -> list[str]:
    """The `hidden` lines of a PROTO instance (after `_live_values` put the live state in its nodes)."""
    if node.proto is None:
        return []
    exposed = set(load_proto(node.proto.source.path).fields)
    lines: list[str] = []
    for index, solid in enumerate(solids_of(node)):
        body = poses.solid_body(sim, solid)
        if body is not None and _moves(sim, body):
            velocity = poses.velocity(sim, solid)
            state = (("translation", "SFVec3f", solid.get("translation")),
                     ("rotation", "SFRotation", solid.get("rotation")),
                     ("linearVelocity", "SFVec3f", velocity[:3] if any(velocity[:3]) else None),
                     ("angularVelocity", "SFVec3f", velocity[3:] if any(velocity[3:]) else None))
            for name, kind, value in state:
                if value is not None and not (index == 0 and name in exposed):
                    lines.append(f"hidden {name}_{index} {format_value(value, kind)}")
        for number, joint in enumerate(joints_of(solid)):
            for axis, field_name in (("", "jointParameters"), ("2", "jointParameters2"), ("3", "jointParameters3")):
                params = joint.get(field_name) if joint.schema and joint.schema.field(field_name) else None
                position = params.get("position") if isinstance(params, Node) else None
                if position:
                    lines.append(f"hidden position{axis}_{index}_{number} {format_value(position, 'SFFloat')}")
    return lines


def _moves(sim: Simulation, body: int) -> bool:
    """Whether a body has a degree of freedom, its own or an ancestor's."""
    while body > 0:
        if int(sim.model.body_dofnum[body]):
            return True
        body = int(sim.model.body_parentid[body])
    return False


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
