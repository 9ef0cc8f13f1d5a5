"""The linear part of Webots' Damping: a drag on each damped tree's centre of mass.

The compiler gives a damped Solid tree's free joint its rotational damping and leaves the linear
one here (`DeviceTable.linear_damping`, see `wbtc.compile.damping`): before each basic step, a
force −c·v on the tree's centre of mass, v its velocity, as a `Push`, held for the step's substeps
(explicit: c/m is at most −ln(0.001) ≈ 6.9 per second, small against a basic step).
"""

from __future__ import annotations

import mujoco
import numpy as np

from wbtc.runtime.pushes import Push


class CentreDrag:
    """The drag of one damped tree on its centre of mass."""

    def __init__(self, model: mujoco.MjModel, joint: str, coefficient: float) -> None:
        self.body = int(model.joint(joint).bodyid[0])
        self.coefficient = coefficient
        self.push = Push()

    def update(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Push the tree's centre of mass against its velocity for the coming step."""
        centre = data.subtree_com[self.body]
        velocity = np.zeros(6)
        # The velocity of the body's material point now at the centre of mass (world frame).
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_XBODY, self.body, velocity, 0)
        spin, origin = velocity[:3], data.xpos[self.body]
        linear = velocity[3:] + np.cross(spin, centre - origin)
        self.push.apply(model, data, -self.coefficient * linear, np.zeros(3), centre, self.body)


def drags(model: mujoco.MjModel, linear_damping: dict[str, float]) -> list[CentreDrag]:
    """One drag per damped tree of the model."""
    return [CentreDrag(model, joint, coefficient) for joint, coefficient in linear_damping.items()]
