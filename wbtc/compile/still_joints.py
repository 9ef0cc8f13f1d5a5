"""Joints in worlds' physics-free trees stay where they are unless a motor turns them.

Webots moves Solids without Physics kinematically: a joint whose endPoint (and every Solid around
it) has no Physics turns only when its motor turns it or a supervisor writes its `position`. wbtc
gives such endPoints a tiny mass (`KINEMATIC_MASS`) so that MuJoCo can carry the joint; a motor then
holds it, but a joint without one would swing under gravity. Each such joint is held at the value
its endPoint was written at (its `ref`, Webots' `position`) by a MuJoCo joint equality (which holds
the joint's offset from its qpos0 = ref at zero).

A joint of such a tree that a motor drives is held the same way under `KINEMATIC_PREFIX`: Webots
moves it by its motor's kinematic rule (`wbtc.runtime.kinematic_motors`), not by a force, and the
runtime moves the equality's target with it.

Only trees that hang from the world without a free joint and whose bodies are all massless or
`KINEMATIC_MASS` count (a robot or object without any Physics, such as Webots' Pedestrian).
An equality is soft (a slider along z sags 0.3 mm under gravity), so the runtime also puts each
held joint back where the step found it (`wbtc.runtime.still_joints`): Webots' value exactly.
"""

from __future__ import annotations

import mujoco

from wbtc.compile.context import KINEMATIC_MASS

#: Name prefix of the holding equalities (wbtc.runtime.still_joints puts the joints back exactly).
PREFIX = "wbtc-still:"
#: Name prefix of the equalities of motor-driven joints in such trees (moved kinematically).
KINEMATIC_PREFIX = "wbtc-kinematic:"
_MOVING = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))


def _subtree(body: mujoco.MjsBody) -> list[mujoco.MjsBody]:
    bodies = [body]
    for child in body.bodies:
        bodies += _subtree(child)
    return bodies


def hold_still_joints(spec: mujoco.MjSpec) -> None:
    """Pin every hinge or slider of a physics-free tree at its written position (a motor moves its own)."""
    driven = {a.target for a in spec.actuators}
    for top in spec.worldbody.bodies:
        bodies = _subtree(top)
        if any(int(j.type) == int(mujoco.mjtJoint.mjJNT_FREE) for b in bodies for j in b.joints):
            continue
        if any(b.mass > KINEMATIC_MASS * (1 + 1e-9) for b in bodies):
            continue
        for body in bodies:
            for joint in body.joints:
                if int(joint.type) not in _MOVING:
                    continue
                hold = spec.add_equality()
                # The runtime finds the held joints by this name (a motor's joint is moved by its motor).
                hold.name = (KINEMATIC_PREFIX if joint.name in driven else PREFIX) + joint.name
                hold.type = mujoco.mjtEq.mjEQ_JOINT
                hold.objtype = mujoco.mjtObj.mjOBJ_JOINT
                hold.name1 = joint.name  # MuJoCo holds q - qpos0 (qpos0 = ref) at data[0] = 0
                hold.data[0] = 0.0
