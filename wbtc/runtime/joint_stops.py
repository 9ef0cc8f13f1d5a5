"""Which joint stops act during a basic step: those the joint is at or beyond when the step starts.

ODE decides a joint's limit row once per step, from the joint's position at the step's start
(`dxJointLimitMotor::testRotationalLimit`: at or past `lostop`/`histop`); a joint inside its range
then moves freely for the whole step, and may end it past its stop by up to its velocity × the step.
Webots takes one ODE step per `basicTimeStep`, so a joint reaching its stop during a step is only
stopped from the next one on. wbtc's MuJoCo takes several substeps per basic step and would stop it
within a substep instead, which Webots' backlash joints tell apart: their gear turns past its stop
during the step in which its controller reverses the motor, and in Webots it has not pushed the
endPoint at all (protos/hinge_joint_with_backlash checks the pendulum to 1e-7 m).

So at the start of each basic step the stops are decided as ODE decides them: a limited hinge or
slider whose position is at or past one of its stops keeps its MuJoCo limit for the step (MuJoCo
then adds the row in the substeps where the joint is still past the stop), every other one has its
limit switched off (`jnt_limited` 0) until the next basic step.

The joints' stop rows themselves are ODE's (wbtc.compile.joint_stops). Ball joints have no stops in
wbtc.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco
import numpy as np


@dataclass(frozen=True)
class Engaged:
    """The stops that act during one basic step."""

    dofs: np.ndarray  # their joints' dofs
    sides: np.ndarray  # -1 where the joint is at its lower stop, +1 at its upper one


class StopGate:
    """The limited hinges and sliders of one model, and which of their stops act this basic step."""

    def __init__(self, model: mujoco.MjModel) -> None:
        self.model = model
        kinds = model.jnt_type
        hinge_or_slide = (kinds == mujoco.mjtJoint.mjJNT_HINGE) | (kinds == mujoco.mjtJoint.mjJNT_SLIDE)
        # The joints written with stops: read from their ranges, which wbtc gives only to them, as
        # `jnt_limited` is switched per step (and a model may be simulated again, after a reset).
        self.joints = np.flatnonzero((model.jnt_range[:, 0] < model.jnt_range[:, 1]) & hinge_or_slide)
        self.qpos = model.jnt_qposadr[self.joints]
        self.dofs = model.jnt_dofadr[self.joints]
        self.low = model.jnt_range[self.joints, 0].copy()
        self.high = model.jnt_range[self.joints, 1].copy()

    def engage(self, data: mujoco.MjData) -> Engaged:
        """Switch on the stops the joints are at or past now, switch off the others."""
        position = data.qpos[self.qpos]
        low, high = position <= self.low, position >= self.high
        engaged = low | high
        self.model.jnt_limited[self.joints] = engaged
        return Engaged(self.dofs[engaged], np.where(high, 1.0, -1.0)[engaged])
