"""Supervisor queries about where things are: node poses, contact points, and pose fields read live.

`SupervisorHub.call` answers these from the simulation as of the last step:

- `Node.getPosition` / `getOrientation` / `getPose`: the node's world pose in the world's axes (NaN
  for a node that is no Pose, as Webots answers for a Group or an Appearance); `getPose(other)` is
  relative to another node's pose;
- `Node.getContactPoints(includeDescendants)`: each contact point of the Solid's body (and of its
  descendants' bodies when asked, for a top Solid only, as Webots), with the node id of the Solid
  that owns the touching body, at the pose the last step ended in (`wbtc.runtime.end_contacts`);
- `Node.getStaticBalance`: whether a top Solid's centre of mass projects, along gravity, inside the
  convex hull of its contact points (its support polygon), as Webots documents it;
- a field's value: a Solid's `translation` / `rotation` (or a PROTO parameter written `IS` into an
  inner Solid's) read where the body is now, every other field as the scene holds it.

The contact points come Solid by Solid: the node's own first, then each descendant's in scene order;
within a Solid, in MuJoCo's collider order (Webots': ODE's). Not honoured yet: contact point tracking
(Webots' `enableContactPointsTracking` keeps points between calls; here they are read on demand).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from wbtc.runtime import poses
from wbtc.runtime.scene_tree import FieldRef, SceneTree
from wbtc.runtime.simulation import descends
from wbtc.scene.model import Node

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

_POSE_FIELDS = ("translation", "rotation")
_POSE_SIZES = {"getPosition": 3, "getOrientation": 9, "getPose": 16}


def pose(sim: Simulation, tree: SceneTree, node: Node, op: str, relative_to: Node | None = None) -> list[float]:
    """`getPosition` (3), `getOrientation` (9, row-major) or `getPose` (16, row-major 4x4) of `node`."""
    if not node.is_a("Pose"):  # Webots: a node that is no Pose (a Group, an Appearance) has no pose
        return [math.nan] * _POSE_SIZES[op]
    rot, pos = poses.world_pose(sim, node, tree.frame_parent)
    if op == "getPosition":
        return [float(v) for v in pos]
    if op == "getOrientation":
        return [float(v) for v in rot.ravel()]
    matrix = np.eye(4)
    matrix[:3, :3], matrix[:3, 3] = rot, pos
    if relative_to is not None:
        frot, fpos = poses.world_pose(sim, relative_to, tree.frame_parent)
        base = np.eye(4)
        base[:3, :3], base[:3, 3] = frot, fpos
        matrix = np.linalg.inv(base) @ matrix
    return [float(v) for v in matrix.ravel()]


def contact_points(sim: Simulation, tree: SceneTree, node: Node, descendants: bool) -> list[tuple[list[float], int]]:
    """The contact points touching `node`'s body (and its descendants'), each with its owner's node id."""
    return [([float(v) for v in sim.from_model @ point], owner)
            for point, owner in _model_points(sim, tree, node, descendants)]


def static_balance(sim: Simulation, tree: SceneTree, node: Node, body: int) -> bool:
    """Webots' static balance of a top Solid (`is_top_solid`) whose body is `body`.

    Whether its centre of mass lies above its support polygon: the convex hull of the Solid's contact
    points (its descendants' included) projected on the plane orthogonal to gravity; the test is whether
    the centre of mass (the whole tree's, as `getCenterOfMass`) projects inside it, its edges included.
    Fewer than three points that are not in a line make no polygon: not balanced. Gravity 0 has no
    such plane: not balanced.
    """
    gravity = np.asarray(sim.model.opt.gravity, float)
    if not gravity.any():
        return False
    down = gravity / np.linalg.norm(gravity)
    # Two axes across gravity (model axes): any vector not along it, then their cross products.
    first = np.cross(down, (1.0, 0.0, 0.0) if abs(down[0]) < 0.9 else (0.0, 1.0, 0.0))
    first /= np.linalg.norm(first)
    second = np.cross(down, first)
    flat = [(float(first @ point), float(second @ point)) for point, _ in _model_points(sim, tree, node, True)]
    hull = _convex_hull(flat)
    if len(hull) < 3:
        return False
    com = sim.data.subtree_com[body]
    return _inside((float(first @ com), float(second @ com)), hull)


def _convex_hull(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """The convex hull of 2-D points, counter-clockwise, without collinear points (Andrew's monotone chain)."""
    points = sorted(set(points))
    if len(points) < 3:
        return points

    def turn(o: tuple[float, float], a: tuple[float, float], b: tuple[float, float]) -> float:
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])

    lower: list[tuple[float, float]] = []
    upper: list[tuple[float, float]] = []
    for chain, ordered in ((lower, points), (upper, reversed(points))):
        for point in ordered:
            while len(chain) >= 2 and turn(chain[-2], chain[-1], point) <= 0:
                chain.pop()
            chain.append(point)
    return lower[:-1] + upper[:-1]


def _inside(point: tuple[float, float], hull: list[tuple[float, float]]) -> bool:
    """Whether `point` lies in the counter-clockwise convex polygon `hull` (edges included, to 1e-12)."""
    x, y = point
    for (ax, ay), (bx, by) in zip(hull, hull[1:] + hull[:1], strict=True):
        if (bx - ax) * (y - ay) - (by - ay) * (x - ax) < -1e-12:
            return False
    return True


def _model_points(sim: Simulation, tree: SceneTree, node: Node, descendants: bool) -> list[tuple[np.ndarray, int]]:
    """`contact_points` in the model's axes."""
    body = poses.solid_body(sim, node)
    if body is None:
        return []
    if descendants and _below_a_solid(tree, node):
        # Webots (WbSolid::extractContactPoints) lists descendants' points only for a top Solid: a point
        # counts when one of its solids' topSolid() is this node, so a Solid inside another lists none.
        return []
    owners = {sim.model.body(name).id: n for n in tree.by_id.values()
              if (name := (sim.table.solids.get(id(n)) or ("",))[0])}
    points = []
    found = sim.end_contacts().collide(sim)  # Webots' contacts: those found where the step left the bodies
    for i in range(found.ncon):
        contact = found.contact[i]
        for geom in (contact.geom1, contact.geom2):
            b = int(sim.model.geom_bodyid[geom])
            if b == body or (descendants and descends(sim.model, b, body)):
                owner = owners.get(b, node)
                points.append((b != body, b, np.array(contact.pos), tree.node_id(owner)))
                break
    # The node's own points first, then each descendant's in scene order (MuJoCo's bodies are numbered
    # in it), each Solid's in the collider's order: Webots lists ODE's contacts, whose collisions follow
    # the order its geoms were made in, and wbtc.runtime.ode_cylinders appends points after the others.
    points.sort(key=lambda point: point[:2])
    return [(point, owner) for _, _, point, owner in points]


def is_top_solid(tree: SceneTree, node: Node) -> bool:
    """Whether `node` is a Solid that no Solid holds (Webots' `isTopLevel`)."""
    return node.is_a("Solid") and not _below_a_solid(tree, node)


def _below_a_solid(tree: SceneTree, node: Node) -> bool:
    """Whether a Solid holds `node` somewhere above it (it is not a top Solid)."""
    parent = tree.parent(node)
    while parent is not None:
        if parent.is_a("Solid"):
            return True
        parent = tree.parent(parent)
    return False


def field_value(sim: Simulation, tree: SceneTree, ref: FieldRef, index: int) -> Any:
    """A field's value (item `index` of an MF field), poses read where the bodies are now.

    Raises:
        IndexError: `index` is past the end of an MF field.
    """
    if ref.name in _POSE_FIELDS and not ref.type.startswith("MF"):
        live = poses.local_pose(sim, ref.node)
        if live is not None:
            return live[0] if ref.name == "translation" else live[1]
    elif ref.proto == 1 and ref.type in ("SFVec3f", "SFRotation"):
        linked = _linked_pose(sim, tree, ref)
        if linked is not None:
            return linked
    return tree.plain(ref, index)


def _linked_pose(sim: Simulation, tree: SceneTree, ref: FieldRef) -> Any:
    """A PROTO parameter written `IS` into an inner Solid's translation or rotation reads where it is now."""
    linked = tree.linked_pose(ref)
    if linked is None:
        return None
    node, name = linked
    live = poses.local_pose(sim, node)
    return None if live is None else live[0] if name == "translation" else live[1]
