"""Motors of physics-free trees: Webots moves their joints kinematically, not by a force.

In Webots a joint whose Solids have no Physics has no ODE joint; each step its motor moves the
joint's position directly (WbMotor's kinematic control, before the physics step):

- nothing moves when the joint is at its target (within 1e-6), or, in velocity control
  (`setPosition(inf)`), when it is at a position limit and the velocity points past it; the
  motor's current velocity drops to 0 then;
- otherwise the current velocity moves towards the requested velocity (`setVelocity`, by default
  `maxVelocity`) by at most `acceleration` x step, where an unset acceleration (-1), or one above
  the available force or torque, is that force or torque taken as an acceleration (a quirk of
  Webots': `maxForce` 10 N makes a slider speed up at 10 m/s^2);
- the position moves towards the target by current velocity x step, stopping on the target.

The compiler holds such joints with MuJoCo joint equalities (`compile.still_joints`,
`KINEMATIC_PREFIX`); here the position is written into `qpos` and into the equality's target, and
`runtime.still_joints` puts the joint back on it exactly after the step. The joint's servo is off.

Not honoured yet: joints whose end point alone has no Physics inside a tree that has some (they are
driven by their servo, as joints with Physics).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import mujoco

from wbtc.compile.still_joints import KINEMATIC_PREFIX

if TYPE_CHECKING:
    from wbtc.runtime.motors import Motor

#: Below this distance to its target a kinematic joint does not move (WbMotor's threshold).
TARGET_POSITION_THRESHOLD = 1e-6
#: Below this difference the current velocity has reached the requested one.
TARGET_VELOCITY_THRESHOLD = 1e-6


def holding_equality(model: mujoco.MjModel, joint: str) -> int:
    """The id of the equality holding `joint` kinematically, or -1 when its motor drives it by force."""
    return mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_EQUALITY, KINEMATIC_PREFIX + joint)


def next_position(motor: Motor, ts: float, position: float) -> float:
    """Where Webots' kinematic control puts the joint after a step of `ts` seconds from `position`.

    Updates the motor's kinematic velocity (`motor.kinematic_velocity`, always >= 0 when the
    requested velocity is).
    """
    target = motor.target
    if math.isinf(target):
        limited = motor.max_position != motor.min_position
        idle = limited and ((position >= motor.max_position and motor.velocity >= 0.0)
                            or (position <= motor.min_position and motor.velocity <= 0.0))
    else:
        idle = abs(target - position) < TARGET_POSITION_THRESHOLD
    if idle:
        motor.kinematic_velocity = 0.0
        return position
    acceleration = motor.acceleration
    if acceleration == -1.0 or acceleration > motor.available:
        acceleration = motor.available  # the available force or torque, read as an acceleration
    current, wanted = motor.kinematic_velocity, motor.velocity
    if abs(wanted - current) > TARGET_VELOCITY_THRESHOLD:
        current = min(current + acceleration * ts, wanted) if wanted > current else max(current - acceleration * ts,
                                                                                          wanted)
    motor.kinematic_velocity = current
    if target > position:
        return min(position + current * ts, target)
    return max(position - current * ts, target)


def move(motor: Motor, model: mujoco.MjModel, data: mujoco.MjData, ts: float, equality: int) -> None:
    """Move a kinematic motor's joint for the coming step, its servo off."""
    a = motor.actuator
    if motor._written[0] is not model or motor._written[1] != 0.0:
        model.actuator_gainprm[a, 0] = 0.0
        model.actuator_biasprm[a, 2] = 0.0
        model.dof_armature[motor.dof_adr] = 0.0
        motor._written = (model, 0.0)
    data.ctrl[a] = 0.0
    position = next_position(motor, ts, float(data.qpos[motor.qpos_adr]))
    data.qpos[motor.qpos_adr] = position
    data.qvel[motor.dof_adr] = 0.0
    # The equality holds q - qpos0 at data[0] (compile.still_joints): its target moves with the joint.
    model.eq_data[equality, 0] = position - float(model.qpos0[motor.qpos_adr])
