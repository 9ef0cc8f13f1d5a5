"""One contributor's share of MuJoCo's `qfrc_applied`, replaced at every update.

Propellers and damping drags push bodies with forces the runtime computes each basic step and holds
for its substeps. Each keeps its own share of the generalised forces: an update takes the previous
share back and adds the new one, so contributors (and a supervisor's `xfrc_applied` forces) never
overwrite each other.
"""

from __future__ import annotations

import mujoco
import numpy as np


class Push:
    """A force and torque on a body at a point, as one share of `qfrc_applied`."""

    def __init__(self) -> None:
        self._share: tuple[mujoco.MjData | None, np.ndarray | None] = (None, None)

    def apply(self, model: mujoco.MjModel, data: mujoco.MjData, force: np.ndarray, torque: np.ndarray,
              point: np.ndarray, body: int) -> None:
        """Replace this push's share by `force` at `point` (world frame) and `torque` on `body`."""
        share = np.zeros(model.nv)
        if body > 0:
            mujoco.mj_applyFT(model, data, force, torque, point, body, share)
        last_data, last = self._share
        if last_data is data and last is not None:  # a new MjData (a recompile) starts from zero
            data.qfrc_applied -= last
        data.qfrc_applied += share
        self._share = (data, share)
