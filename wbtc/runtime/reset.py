"""What a Supervisor's `simulationReset` does to the scene, after Webots' Reset/Reload matrix.

Webots' "Reset from Supervisor" is not a reload: it resets the time, the physics and the random
seeds, removes the nodes added since the world was loaded, and puts back a few fields per node type
(`RESET_FIELDS`: a Solid's `translation` and `rotation`, a joint's `position`, a Robot's `battery`
...). Every other field keeps what a supervisor wrote (a controller's arguments, a colour), and a
removed node stays removed. PROTOs tagged `nonDeterministic` are generated anew.

`Initial.capture` keeps, when the world is loaded, the node ids and those fields' values;
`Initial.apply` brings the scene tree back to them before the world is compiled again (the
supervisor then swaps the model in with time 0, see `SupervisorHub`).

Not honoured yet: a Display's, Pen's or Emitter's own reset (their state lives in the run, which
the supervisor carries over or clears), LED colours, Track texture offsets.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass, field
from typing import Any

from wbtc.proto.model import load_proto
from wbtc.proto.template_files import regenerate_non_deterministic
from wbtc.runtime import scene_ops
from wbtc.runtime.scene_tree import SceneTree
from wbtc.scene.model import Node

#: The fields a reset puts back, by node type (and the types deriving from it).
RESET_FIELDS: dict[str, tuple[str, ...]] = {
    "Solid": ("translation", "rotation"),
    "Robot": ("battery",),
    "Charger": ("battery",),
    "Connector": ("isLocked",),
    "JointParameters": ("position",),
    "HingeJointParameters": ("position",),
    "BallJointParameters": ("position",),
    "Viewpoint": ("orientation", "position", "near", "far", "fieldOfView"),
}

_ABSENT = object()


@dataclass
class Initial:
    """The scene as loaded, as far as a reset needs it."""

    ids: set[int] = field(default_factory=set)
    values: list[tuple[Node, str, Any, Any]] = field(default_factory=list)  # node, field, fields' value, PROTO's

    @classmethod
    def capture(cls, tree: SceneTree) -> Initial:
        """The node ids and the resettable fields' values of `tree` now."""
        initial = cls(ids=set(tree.by_id))
        for node in tree.by_id.values():
            for base, names in RESET_FIELDS.items():
                if not node.is_a(base):
                    continue
                for name in names:
                    own = node.fields.get(name, _ABSENT)
                    proto = node.proto.values.get(name, _ABSENT) if node.proto is not None else _ABSENT
                    if own is not _ABSENT or proto is not _ABSENT:
                        initial.values.append((node, name, copy.deepcopy(own), copy.deepcopy(proto)))
        return initial

    def apply(self, tree: SceneTree) -> None:
        """Bring `tree` back as a reset does: added nodes out, fields back, nonDeterministic PROTOs anew."""
        added = [child for parent, child in tree._edges(tree.root, tree.scene.nodes, hidden=False)
                 if tree.node_id(child) not in self.ids and tree.node_id(parent) in self.ids]
        for node in added:
            tree.remove(node)
        for node, name, own, proto in self.values:
            if own is not _ABSENT:
                node.fields[name] = copy.deepcopy(own)
            if proto is not _ABSENT and node.proto is not None:
                node.proto.values[name] = copy.deepcopy(proto)
        regenerate = [node for _, node in tree._edges(tree.root, tree.scene.nodes, hidden=False)
                      if node.proto is not None and "nonDeterministic" in load_proto(node.proto.source.path).tags]
        if regenerate:
            regenerate_non_deterministic()
        for node in regenerate:
            scene_ops.reexpand(tree, node)
        tree.refresh()
