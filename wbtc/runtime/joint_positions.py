"""A joint whose `position` field changed goes there when the world is recompiled.

Webots moves a joint's endPoint when a supervisor writes its `position` (directly, or through a
PROTO field such as the Pedestrian's angles). A recompiled model writes that value as the joint's
`ref` (see `wbtc.compile.joint`); the rebuild then starts the joint there instead of carrying the
old angle over.
"""

from __future__ import annotations

import mujoco


def moved_to_new_position(old_model: mujoco.MjModel, old_joint: int, model: mujoco.MjModel, joint: int) -> bool:
    """Whether a hinge or slider's written position (its qpos0) differs between the two models."""
    if int(model.jnt_type[joint]) not in (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE)):
        return False
    return abs(float(model.qpos0[model.jnt_qposadr[joint]]) -
               float(old_model.qpos0[old_model.jnt_qposadr[old_joint]])) > 1e-12
