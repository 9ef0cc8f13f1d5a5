"""The Viewpoint following a Solid, as its `position` and `orientation` fields say (what a supervisor reads).

Webots moves the Viewpoint node itself after every step when its `follow` names a Solid
(WbViewpoint::updateFollowUp), so a supervisor reading the Viewpoint's fields sees it move:

- "Tracking Shot" (the default): the Viewpoint is pulled along by the Solid's displacement. With
  `followSmoothness` below 0.05 it takes the whole displacement at once; otherwise the displacement
  builds up an "equilibrium" vector that accelerates the Viewpoint (mass = smoothness, at most 1),
  whose speed is braked towards the Solid's (friction 0.05 / mass), step by step.
- "Mounted Shot": the Viewpoint keeps the pose it had relative to the Solid when following began.

`follow` names a Solid by its unique name: the names of the Solids from the top of the scene down
to it, joined by ':' ("robot:arm"), or its own name when unique at the top. Positions are in the
world's own axes (`poses.world_pose`). Not honoured: "Pan and Tilt Shot" (the fields stay; the
window and recordings turn the view, `record.Follow`), a Viewpoint moved by a supervisor while it
follows (Webots takes the new pose as the new reference), the drag-rotation centre.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from wbtc.compile.frames import axis_angle_quat, mat_to_quat, quat_to_axis_angle, quat_to_mat
from wbtc.compile.solid import world_viewpoint
from wbtc.runtime import poses
from wbtc.runtime.scene_tree import store_pose, to_typed

if TYPE_CHECKING:
    from wbtc.runtime.scene_tree import SceneTree
    from wbtc.runtime.simulation import Simulation
    from wbtc.scene.model import Node


class ViewpointFollow:
    """One world's Viewpoint following its Solid (see the module docstring)."""

    def __init__(self, tree: SceneTree, sim: Simulation) -> None:
        self.tree = tree
        self.viewpoint = world_viewpoint(tree.scene)
        self.target = str(self.viewpoint.get("follow") or "") if self.viewpoint is not None else ""
        self.solid = find_solid(tree, self.target) if self.target else None
        if self.solid is None:
            return
        rot, pos = poses.world_pose(sim, self.solid, tree.frame_parent)
        self.previous = pos.copy()
        self.reference_rotation = rot.copy()
        r = [float(v) for v in self.viewpoint.get("orientation")]
        self.view_rotation = quat_to_mat(axis_angle_quat((r[0], r[1], r[2]), r[3]))
        self.offset = np.asarray(self.viewpoint.get("position"), dtype=float) - pos
        self.equilibrium = np.zeros(3)
        self.velocity = np.zeros(3)

    def step(self, sim: Simulation, step_s: float) -> None:
        """After a step: move the Viewpoint's fields as Webots does."""
        if self.solid is None:
            return
        rot, pos = poses.world_pose(sim, self.solid, self.tree.frame_parent)
        delta = pos - self.previous
        self.previous = pos.copy()
        kind = str(self.viewpoint.get("followType") or "Tracking Shot")
        position = np.asarray(self.viewpoint.get("position"), dtype=float)
        if kind == "Mounted Shot":
            turn = rot @ self.reference_rotation.T
            self._set("orientation", turn @ self.view_rotation)
            self._set("position", pos + turn @ self.offset)
        elif kind == "Tracking Shot":
            self._set("position", self._track(position, pos, delta, step_s))

    def _track(self, position: np.ndarray, solid: np.ndarray, delta: np.ndarray, step_s: float) -> np.ndarray:
        """Where a Tracking Shot puts the Viewpoint after this step (Webots' spring with friction)."""
        self.equilibrium += delta
        smoothness = float(self.viewpoint.get("followSmoothness") or 0.0)
        mass = 0.0 if smoothness < 0.05 else min(smoothness, 1.0)
        if mass == 0.0:
            # Webots adds each step's displacement; the sum of them is taken at once here, which is the
            # same but for the rounding of the sum (the Viewpoint then stays exactly level with the Solid).
            self.equilibrium, self.velocity = np.zeros(3), np.zeros(3)
            return solid + self.offset
        self.velocity = self.velocity + self.equilibrium / mass * step_s
        speed = float(np.linalg.norm(self.velocity))
        target_speed = 0.0
        if np.linalg.norm(delta) > 0.0 and speed > 0.0:
            target_speed = float(np.dot(delta / step_s, self.velocity)) / speed
        if speed > target_speed:  # faster than the Solid: slowed down, so as not to oscillate
            relative = speed - target_speed
            if relative < 0.0001:
                self.velocity = self.velocity * (target_speed / speed)
            else:
                self.velocity = self.velocity * ((speed - relative * min(0.05 / mass, 1.0)) / speed)
        moved = self.velocity * step_s
        self.equilibrium = self.equilibrium - moved
        self.offset = position + moved - solid  # where a rigid follow would go on from
        return position + moved

    def _set(self, name: str, value: np.ndarray) -> None:
        if name == "orientation":  # a rotation matrix, stored as Webots' axis-angle
            value = np.asarray(quat_to_axis_angle(mat_to_quat(value)))
            store_pose(self.viewpoint, name, to_typed("SFRotation", value))
        else:
            store_pose(self.viewpoint, name, to_typed("SFVec3f", value))


def current_follower(follower: ViewpointFollow | None, tree: SceneTree, sim: Simulation) -> ViewpointFollow:
    """`follower`, or a new one when the scene, its Viewpoint or what the Viewpoint follows changed."""
    viewpoint = world_viewpoint(tree.scene)
    target = str(viewpoint.get("follow") or "") if viewpoint is not None else ""
    same = follower is not None and follower.tree is tree and follower.viewpoint is viewpoint
    return follower if same and follower.target == target else ViewpointFollow(tree, sim)


def find_solid(tree: SceneTree, unique_name: str) -> Node | None:
    """The Solid of a Webots unique name ("robot:arm": Solid names from the top, ':'-joined), or None."""
    wanted = unique_name.split(":")
    for _, node in tree._edges(tree.root, tree.scene.nodes, hidden=True):
        if not node.is_a("Solid") or str(node.get("name")) != wanted[-1]:
            continue
        path, parent = [str(node.get("name"))], tree.parent(node)
        while parent is not None:
            if parent.is_a("Solid"):
                path.insert(0, str(parent.get("name")))
            parent = tree.parent(parent)
        if path == wanted:
            return node
    return None
