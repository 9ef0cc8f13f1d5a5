"""The function that takes one MuJoCo substep: `mj_step`, or a split step where Webots' contact rules act.

Webots decides some things per contact that MuJoCo's model cannot say: the directions of
asymmetric friction (`contact_frames`) and the surface velocity of Tracks' belts (`tracks`). When a
world has either, each substep runs `mj_step1`, then the rules on this substep's contacts (the
friction directions first, as they rebuild the constraints, then the belts' velocities), then
`mj_step2`; otherwise it is plain `mj_step`.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import mujoco

from wbtc.runtime import tracks
from wbtc.runtime.contact_frames import ContactFrames

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

Step = Callable[[mujoco.MjModel, mujoco.MjData], None]


def substep_function(sim: Simulation, model: mujoco.MjModel) -> Step:
    """`mj_step`, or the split step running this world's contact rules between MuJoCo's halves."""
    hooks: list[Step] = []
    if sim.table.asymmetric_friction is not None:
        if sim.frames is None or sim.frames.model is not model:  # made once per model
            sim.frames = ContactFrames(model, sim.table.asymmetric_friction)
        hooks.append(sim.frames.orient)
    belts = tracks.surface_hook(sim)
    if belts is not None:
        hooks.append(belts)
    if not hooks:
        return mujoco.mj_step

    def step(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        mujoco.mj_step1(model, data)
        for hook in hooks:
            hook(model, data)
        mujoco.mj_step2(model, data)

    return step
