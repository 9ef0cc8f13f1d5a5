"""The `hidden` lines of a PROTO instance: the saved state of the Solids and joints inside it.

Webots saves what a PROTO's interface does not expose as `hidden NAME_INDEX value` lines of the
instance: `translation_N`, `rotation_N`, `linearVelocity_N`, `angularVelocity_N` for the N-th Solid
inside the PROTO (depth first through `children` and joint `endPoint`s, the PROTO's own root Solid
being 0), and `position_N_J` (`position2_N_J`, `position3_N_J` for the other axes) for the J-th joint
among the children of Solid N. They are written into the expanded nodes, so the world starts where
it was saved. A root-Solid value whose field the PROTO exposes is left to the interface.

Not honoured yet: hidden lines naming a Solid or joint index the PROTO does not have are ignored.
"""

from __future__ import annotations

import re
from typing import Any

from wbtc.errors import SchemaError
from wbtc.scene.model import Node
from wbtc.vrml.values import coerce

_POSE = re.compile(r"(translation|rotation|linearVelocity|angularVelocity)_(\d+)")
_POSITION = re.compile(r"position([23]?)_(\d+)_(\d+)")
_JOINTS = ("HingeJoint", "SliderJoint", "Hinge2Joint", "BallJoint")


def apply_hidden(root: Node, hidden: dict[str, Any], exposed: set[str]) -> None:
    """Write an instance's hidden values into its expanded nodes (`exposed`: the PROTO's interface fields)."""
    solids = solids_of(root)
    for key, raw in hidden.items():
        pose = _POSE.fullmatch(key)
        if pose is not None:
            index = int(pose.group(2))
            if index < len(solids) and not (index == 0 and pose.group(1) in exposed):
                _store(solids[index], pose.group(1), raw)
            continue
        position = _POSITION.fullmatch(key)
        if position is None:
            continue
        axis, index, number = position.group(1) or "", int(position.group(2)), int(position.group(3))
        if index >= len(solids):
            continue
        joints = joints_of(solids[index])
        if number < len(joints):
            parameters = joints[number].get(f"jointParameters{axis}")
            if isinstance(parameters, Node):
                _store(parameters, "position", raw)


def solids_of(root: Node) -> list[Node]:
    """The Solids of an expanded PROTO body in Webots' order: depth first through children and end points."""
    found: list[Node] = []

    def visit(node: Node) -> None:
        if node.is_a("Solid"):
            found.append(node)
        if node.base_type in _JOINTS or node.base_type == "Slot":  # a Slot passes its endPoint on too
            end = node.get("endPoint")
            if isinstance(end, Node):
                visit(end)
            return
        has_children = node.schema is not None and node.schema.field("children") is not None
        for child in (node.get("children") or []) if has_children else []:
            if isinstance(child, Node):
                visit(child)

    visit(root)
    return found


def joints_of(solid: Node) -> list[Node]:
    """The joints of a Solid, in order (the J of `position_N_J`).

    As Webots counts them: among its children and inside the grouping nodes (Pose, Transform, Group)
    among them, depth first, never inside another Solid.
    """
    found: list[Node] = []

    def visit(children: Any) -> None:
        for child in children or []:
            if not isinstance(child, Node) or child.is_a("Solid"):
                continue
            if child.base_type in _JOINTS:
                found.append(child)
            elif child.schema is not None and child.schema.field("children") is not None:
                visit(child.get("children"))

    visit(solid.get("children"))
    return found


def _store(node: Node, name: str, raw: Any) -> None:
    field = node.schema.field(name) if node.schema is not None else None
    if field is None:
        return
    try:
        node.fields[name] = coerce(raw, field.type, f"hidden field '{name}'", lambda v: isinstance(v, Node))
    except SchemaError:
        pass  # a malformed saved value: the node keeps what the PROTO gave it
