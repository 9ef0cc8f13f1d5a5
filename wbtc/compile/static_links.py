"""Bodies jointed to the static environment never touch static geometry, as in Webots.

Webots' collision callback (WbSimulationCluster::odeNearCallback) skips two geoms whose bodies are
connected by a joint, and also a body attached to the static environment by a joint against any
geom without a body (a Solid without Physics): ODE's `dAreConnectedExcluding(b, 0,
dJointTypeContact)` is true for a body with a joint to the world, whatever the static geom. So a
robot arm's first link, hinged to a base without Physics, touches neither that base nor the floor
nor a table without Physics, and a door hinged to a static frame passes static walls. The arm's
other links and everything with Physics still touch them.

MuJoCo's own filter (`filterparent`) skips a body and its parent only when the parent is not
welded to the world. So every body with a joint other than a free one (ODE has no joint for a free
body) whose parent is welded to the world, together with the bodies welded to it (one ODE body in
Webots), gets an explicit `exclude` with every body welded to the world, without Physics, that has
collision geoms. A Solid with Physics fixed to a static parent (a TouchSensor on a static robot) has
an ODE body in Webots and is still touched.

Webots' other skip, bodies linked through a chain of hinges sharing one anchor, is
wbtc.compile.hinge_chains.
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco


def exclude_static_links(spec: mujoco.MjSpec, moves: Callable[[mujoco.MjsBody], bool]) -> int:
    """Add Webots' exclusions between static bodies and the bodies jointed to them.

    Args:
        spec: the model being built.
        moves: `moves(body) -> bool`, whether a body can move (is not welded to the world).

    Returns:
        The number of excludes added.
    """
    bodies = [spec.worldbody, *spec.worldbody.find_all(mujoco.mjtObj.mjOBJ_BODY)]
    # Static: welded to the world and without Physics (mass 0). A Solid with Physics fixed to a static
    # parent has an ODE body of its own in Webots, so the rule does not spare it.
    static = [b for b in bodies if not moves(b) and b.mass == 0 and collides(b)]
    if not static:
        return 0
    existing = {frozenset((e.bodyname1, e.bodyname2)) for e in spec.excludes}
    added = 0
    for body in bodies:
        if body is spec.worldbody or not _jointed(body) or moves(body.parent):
            continue
        for linked in welded_group(body):
            if not collides(linked):
                continue
            for other in static:
                key = frozenset((other.name, linked.name))
                if key in existing:
                    continue
                existing.add(key)
                spec.add_exclude(bodyname1=other.name, bodyname2=linked.name)
                added += 1
    return added


def _jointed(body: mujoco.MjsBody) -> bool:
    """Whether a body hangs on joints ODE would have (any but a free joint)."""
    return any(j.type != mujoco.mjtJoint.mjJNT_FREE for j in body.joints)


def welded_group(body: mujoco.MjsBody) -> list[mujoco.MjsBody]:
    """`body` and the bodies fixed to it (descendants reached without crossing a joint)."""
    group, stack = [], [body]
    while stack:
        current = stack.pop()
        group.append(current)
        stack.extend(child for child in current.bodies if not len(child.joints))
    return group


def collides(body: mujoco.MjsBody) -> bool:
    """Whether any of the body's geoms takes part in collisions."""
    return any(g.contype or g.conaffinity for g in body.geoms)
