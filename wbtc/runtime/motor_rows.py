"""ODE's motor row under `--ode-contacts`: a motor as a velocity constraint with a force limit.

Webots drives a joint's motor through ODE's joint motor (`dParamVel`, `dParamFMax`): a constraint row
asking the joint for the motor's velocity at the end of the step, with a force bounded by the
available torque, solved together with the contacts and every other row of the step. So a motor holds
any load within its torque without giving way (a vacuum cup's slider lifting 2 kg), and a wheel keeps
its speed against the floor's friction unless that takes more than its torque.

wbtc's default motor is a velocity servo of MuJoCo's (wbtc.runtime.motors), which needs a velocity
error to give a force. Under `--ode-contacts` each motor in position or velocity control is instead
its joint's friction-loss row in MuJoCo: a row on the joint's degree of freedom, its force within
±`dof_frictionloss`. The row's bound is set to the available torque at each basic step (Motor.update),
and after `mj_step1` has made the rows its reference becomes ODE's: the velocity change to Webots'
velocity command within the substep, −(v − v_command) / h, with ODE's hard regularisation (WorldInfo's
default `CFM`, 1e-5, over the step). wbtc.runtime.ode_solve solves these rows with the contacts.

A motor in torque or force control has no row (ODE's motor gets no force then either); its joint's
own `staticFriction` is what the compiler wrote. Motors of trees without Physics keep Webots'
kinematic rule (wbtc.runtime.kinematic_motors).

A joint's damping (`dampingConstant`, brakes) is ODE's too: Webots solves it as an implicit row with
the motor's (WbBasicJoint's spring-and-damper motor), so a motor reaches its velocity against the
damping while its torque allows; wbtc.runtime.ode_solve adds that row to the islands it solves.
Islands holding motor rows are solved there, contacts or not: MuJoCo's Newton solver leaves hard
rows on light links far from settled.

Not honoured: a joint's `staticFriction` while its motor is in position or velocity control (the
joint's friction-loss row is the motor's).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import mujoco
import numpy as np

if TYPE_CHECKING:
    from wbtc.runtime.motors import Motor

#: ODE's constraint force mixing of a motor row (WorldInfo `CFM`'s default), as a regularisation
#: R = CFM / h: the row is hard.
MOTOR_CFM = 1e-5

Hook = Callable[[mujoco.MjModel, mujoco.MjData], None]
_FRICTION_DOF = int(mujoco.mjtConstraint.mjCNSTR_FRICTION_DOF)


def update(motor: Motor, model: mujoco.MjModel, data: mujoco.MjData, ts: float) -> None:
    """A motor's basic step as ODE's motor row, in place of its servo (Motor.update)."""
    a, d = motor.actuator, motor.dof_adr
    motor.plain(model)  # its ctrl a force: 0, but under torque control
    if motor.torque is not None:
        model.dof_frictionloss[d] = motor.static_friction
        data.ctrl[a] = motor.torque
        motor.row_command = None
        return
    data.ctrl[a] = 0.0
    motor.row_command = motor.velocity_command(ts, float(data.qpos[motor.qpos_adr]))
    # The row's bound (no row at all when no torque is available).
    model.dof_frictionloss[d] = motor.available


def rows_of(data: mujoco.MjData, dofs: np.ndarray) -> np.ndarray:
    """The friction-loss row of each degree of freedom in `dofs` in this substep (-1 where it has none)."""
    nefc = data.nefc
    rows = np.nonzero(data.efc_type[:nefc] == _FRICTION_DOF)[0]
    found = np.full(len(dofs), -1)
    if len(rows):
        where = {int(dof): int(row) for dof, row in zip(data.efc_id[rows].tolist(), rows.tolist(), strict=True)}
        found[:] = [where.get(int(dof), -1) for dof in dofs.tolist()]
    return found


def hook_for(dofs: list[int], commands: list[float]) -> Hook | None:
    """The substep hook that gives the rows of `dofs` ODE's reference towards `commands` (rad/s or m/s)."""
    if not dofs:
        return None
    dof_array, wanted = np.array(dofs), np.array(commands)

    def hook(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        found = rows_of(data, dof_array)
        present = found >= 0
        if not present.any():
            return
        rows = found[present]
        h = model.opt.timestep
        data.efc_aref[rows] = (wanted[present] - data.efc_vel[rows]) / h
        data.efc_R[rows] = MOTOR_CFM / h
        data.efc_D[rows] = h / MOTOR_CFM
        mujoco.mj_island(model, data)  # the islands' copies of D, as mj_step1 made them
        mujoco.mj_projectConstraint(model, data)

    return hook


def row_forces(data: mujoco.MjData, dofs: np.ndarray) -> np.ndarray:
    """The force each row of `dofs` gives its joint in this substep (0 where it has none)."""
    found = rows_of(data, dofs)
    forces = np.zeros(len(dofs))
    present = found >= 0
    forces[present] = data.efc_force[found[present]]
    return forces
