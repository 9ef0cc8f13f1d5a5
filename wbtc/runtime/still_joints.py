"""Joints of physics-free trees stay exactly where a step found them, as in Webots.

`wbtc.compile.still_joints` holds each motorless hinge or slider of a tree without Physics by a
MuJoCo joint equality named `PREFIX + joint`. An equality is a soft constraint (a slider along
gravity sags by about 0.3 mm), while Webots does not move such a joint at all: its position only
changes when a supervisor writes it. So every step records these joints' positions before the
physics runs and writes them back, with zero velocity, after it; a supervisor's write between steps
is what the next step keeps. Motor-driven joints of such trees (`KINEMATIC_PREFIX`) are kept the
same way, at the position their motor moved them to before the step (`wbtc.runtime.kinematic_motors`).
"""

from __future__ import annotations

import mujoco
import numpy as np

from wbtc.compile.still_joints import KINEMATIC_PREFIX, PREFIX


class StillJoints:
    """The held joints of one model: their qpos and dof addresses."""

    def __init__(self, model: mujoco.MjModel) -> None:
        """Find the joints the compiler held (equalities named with `PREFIX`)."""
        self.model = model
        qpos, dofs = [], []
        for index in range(model.neq):
            name = model.eq(index).name
            held = name.startswith((PREFIX, KINEMATIC_PREFIX))
            if int(model.eq_type[index]) != int(mujoco.mjtEq.mjEQ_JOINT) or not held:
                continue
            joint = int(model.eq_obj1id[index])
            qpos.append(int(model.jnt_qposadr[joint]))
            dofs.append(int(model.jnt_dofadr[joint]))
        self.qpos = np.array(qpos, dtype=int)
        self.dofs = np.array(dofs, dtype=int)

    def positions(self, data: mujoco.MjData) -> np.ndarray:
        """The held joints' positions now (before a step)."""
        return data.qpos[self.qpos].copy()

    def restore(self, data: mujoco.MjData, positions: np.ndarray) -> None:
        """Put the held joints back at `positions`, at rest."""
        data.qpos[self.qpos] = positions
        data.qvel[self.dofs] = 0.0
