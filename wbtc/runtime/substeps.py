"""The function that takes one MuJoCo substep: `mj_step`, or a split step where Webots' contact rules act.

Webots decides some things per contact that MuJoCo's model cannot say: the directions of asymmetric
friction (`contact_frames`), the surface velocity of Tracks' belts (`tracks`), ODE's push-out speed
of bodies placed inside each other (`recovery`, while they are), and with `--ode-contacts` Webots'
cylinder-on-plane points (`ode_cylinders`) and restitution (`bounce`). When a step has any, each
substep runs `mj_step1`, then the rules on this substep's contacts (the cylinder points and then the
friction directions first, as they rebuild the constraints, then the belts' velocities), then
`mj_step2`; otherwise it is plain `mj_step`. With `--ode-contacts`, the motors' rows take ODE's
motor reference (`motor_rows`), `mj_step2` is replaced by its stages with ODE's contact solve
(`ode_solve`) before the integration, and free bodies are integrated at their centre of mass, as
ODE's (`com_integration`).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

import mujoco

from wbtc.runtime import motor_rows, ode_cylinders, ode_solve, tracks
from wbtc.runtime.bounce import bounce_hook
from wbtc.runtime.com_integration import ComIntegration
from wbtc.runtime.contact_frames import ContactFrames
from wbtc.runtime.recovery import recovery_for
from wbtc.runtime.sensors import TouchSensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation

Step = Callable[[mujoco.MjModel, mujoco.MjData], None]


def substep_function(sim: Simulation, model: mujoco.MjModel) -> Step:
    """`mj_step`, or the split step running this world's contact rules between MuJoCo's halves."""
    hooks: list[Step] = []
    ode = ode_solve.applies(model)  # --ode-contacts
    if sim.per_model[0] is not model:  # made once per model (robots and sensors change with it)
        touch = any(isinstance(s, TouchSensor) for r in sim.robots for s in r.sensors.values())
        cylinders = ode_cylinders.hook_for(model) if ode else None
        com = ComIntegration(model) if ode else None
        sim.per_model = (model, bounce_hook(sim.table.bounce, model), touch,
                         recovery_for(sim.table.recovery, model), cylinders, com or None)
        sim.moved = True  # a new model: look for placed overlaps
    _, bounces, touch, recover, cylinders, com = sim.per_model
    if cylinders is not None:
        hooks.append(cylinders)  # first: the other rules read the contacts it writes
    if sim.table.asymmetric_friction is not None:
        if sim.frames is None or sim.frames.model is not model:  # made once per model
            sim.frames = ContactFrames(model, sim.table.asymmetric_friction)
        hooks.append(sim.frames.orient)
    belts = tracks.surface_hook(sim)
    if belts is not None:
        hooks.append(belts)
    if ode:
        # ODE's motor rows (motor_rows) in place of the servos: after the rules that rebuild the rows.
        rows = [m for r in sim.robots for m in r.motors.values() if m.row_command is not None]
        motors = motor_rows.hook_for([m.dof_adr for m in rows], [m.row_command for m in rows])
        if motors is not None:
            hooks.append(motors)
    if recover is not None:
        if sim.moved:
            recover.find(model, sim.data)
        if recover.pairs:
            hooks.append(recover.hook)
    sim.moved = False
    if bounces is not None:
        hooks.append(bounces)  # the rows' references as the other rules leave them
    if com is not None:
        hooks.append(com.hook)  # after every rule that sets the rows' references: it shifts them
    # Under ODE's contacts each substep's contact rows are solved again, ODE's way, before integrating.
    finish = ode_solve.step2 if ode else mujoco.mj_step2
    if not hooks and finish is mujoco.mj_step2:
        sim.touched = None
        return mujoco.mj_step
    if touch:
        sim.touched = set()  # this basic step's, filled substep by substep
        hooks.append(_touch_recorder(sim.touched))
    else:
        sim.touched = None

    def step(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        mujoco.mj_step1(model, data)
        for hook in hooks:
            hook(model, data)
        finish(model, data)

    return com.wrap(step) if com is not None else step


def _touch_recorder(touched: set[int]) -> Step:
    """A hook that adds the bodies of each substep's contacts to `touched`, but the first substep's.

    Webots' bumper reads the contacts found at the end of its one ODE step (wbtc.runtime.end_contacts); a
    contact that bounces (wbtc.runtime.bounce) may last less than a basic step here, so a bumper reads
    what touched in any substep too. The first substep starts at the pose the last step ended in,
    which that step's end already counted.
    """
    first = [True]

    def record(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        if first[0]:
            first[0] = False
        elif data.ncon:
            bodies = model.geom_bodyid[data.contact.geom]
            touched.update(bodies[bodies[:, 0] != bodies[:, 1]].ravel().tolist())

    return record
