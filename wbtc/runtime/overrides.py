"""Field overrides of a run (`wbtc.run(fields=...)`, a batch plan's `[fields]`): world edits before compiling.

A key names a node and one of its fields: `DEF_NAME.field` (a DEF path `A.B.field` looks for B below
A, as `getFromDef` does), else a Solid's `name` (`e-puck.translation`, `box 1.size`; robots first),
else the type of a top-level
node (`WorldInfo.basicTimeStep`). The value is plain Python: a number, a bool, a string, a list of
numbers for a vector, colour or rotation, a list of those for an MF field. A PROTO instance's
interface fields are set on the instance and the PROTO is expanded anew, as a supervisor's write
would; the fields of built-in nodes are set in place.

Not honoured yet: SFNode and MFNode values (a node cannot be written as a plain value).
"""

from __future__ import annotations

import difflib
from collections.abc import Mapping
from typing import Any

from wbtc.errors import WbtcError
from wbtc.runtime import scene_ops
from wbtc.runtime.scene_tree import FieldRef, SceneTree, to_typed
from wbtc.scene.model import Node, Scene

_WIDTHS = {"Vec2f": 2, "Vec3f": 3, "Color": 3, "Rotation": 4}


def apply_overrides(scene: Scene, fields: Mapping[str, Any]) -> None:
    """Set every `node.field` of `fields` in the expanded `scene`.

    Raises:
        WbtcError: a key names no node or no field, or a value does not fit the field's type.
    """
    if not fields:
        return
    tree = SceneTree(scene)
    for key, value in fields.items():
        node, ref = find_field(tree, key)
        typed = typed_value(key, ref.type, value)
        tree.store(ref, typed)
        if ref.proto:
            scene_ops.reexpand(tree, node)


def find_field(tree: SceneTree, key: str) -> tuple[Node, FieldRef]:
    """The node and field a `node.field` key names.

    Raises:
        WbtcError: no such node, or the node has no such field.
    """
    if "." not in key:
        raise WbtcError(f"'{key}' names no field: write NODE.FIELD, e.g. 'ROBOT.translation'")
    path, name = key.rsplit(".", 1)
    node = tree.from_def(path) or _by_name(tree.scene, path) or _by_type(tree.scene, path)
    if node is None:
        raise WbtcError(f"'{key}': no node with DEF name, Solid name or top-level type '{path}' in the world")
    for level in (1, 0) if node.proto is not None else (0,):
        ref = tree.field(node, name, level)
        if ref is not None:
            if ref.proto > 1:
                break
            return node, ref
    names = [n for level in (1, 0) for n, _ in tree.field_names(node, level)]
    close = difflib.get_close_matches(name, names, n=1)
    hint = f" (did you mean '{close[0]}'?)" if close else ""
    raise WbtcError(f"'{key}': {node.proto.name if node.proto else node.base_type} '{path}' has no field "
                    f"'{name}'{hint}")


def typed_value(key: str, field_type: str, value: Any) -> Any:
    """A plain value typed as the scene stores a `field_type` field.

    Raises:
        WbtcError: the value does not fit the type.
    """
    elem = field_type[2:]
    if elem == "Node":
        raise WbtcError(f"'{key}' is a node field ({field_type}): it cannot be set to a plain value")
    try:
        if field_type.startswith("MF"):
            if not isinstance(value, list | tuple):
                raise TypeError
            return [_one(elem, item) for item in value]
        return _one(elem, value)
    except (TypeError, ValueError):
        raise WbtcError(f"'{key}' is a {field_type} field: {value!r} does not fit it"
                        f"{_expected(elem, field_type)}") from None


def _one(elem: str, value: Any) -> Any:
    if elem in _WIDTHS:
        if not isinstance(value, list | tuple) or len(value) != _WIDTHS[elem]:
            raise ValueError(value)
        return to_typed("SF" + elem, value)
    if elem == "Bool" and not isinstance(value, bool):
        raise TypeError(value)
    if elem == "Int32" and (isinstance(value, bool) or float(value) != int(value)):
        raise ValueError(value)
    if elem in ("Float", "Int32") and isinstance(value, bool | str):
        raise TypeError(value)
    if elem == "String" and not isinstance(value, str):
        raise TypeError(value)
    return to_typed("SF" + elem, value)


def _expected(elem: str, field_type: str) -> str:
    one = {"Vec2f": "2 numbers", "Vec3f": "3 numbers", "Color": "3 numbers", "Rotation": "4 numbers (axis, angle)",
           "Float": "a number", "Int32": "an integer", "Bool": "true or false", "String": "a string"}.get(elem)
    if one is None:
        return ""
    return f" (expected a list of items of {one})" if field_type.startswith("MF") else f" (expected {one})"


def _by_name(scene: Scene, name: str) -> Node | None:
    """The first robot, else the first Solid, whose `name` is `name`."""
    solids = [node for node in scene.walk() if node.is_a("Solid") and str(node.get("name")) == name]
    return next((node for node in solids if node.is_a("Robot")), solids[0] if solids else None)


def _by_type(scene: Scene, type_name: str) -> Node | None:
    return next((n for n in scene.nodes if n.base_type == type_name or n.type_name == type_name), None)
