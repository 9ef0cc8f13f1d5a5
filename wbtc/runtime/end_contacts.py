"""Contacts as Webots reports them: found at the pose a physics step ended in.

Webots' ODE steps the world, then detects collisions at the pose the step ended in
(`dWorldStepAndSpaceCollide`; those contacts act in the next step), so what a step reports touching
is what touches where it left the bodies. MuJoCo collides at the start of a substep: after a step
its contacts are those of the pose before the last substep, a whole basic step old under
`--physics-step 1000`, where a falling bar reached Webots' touch sensor one step late
(`physics/hinge_joint_slot`). `EndContacts` collides the end pose again in a scratch `MjData`; the
live one keeps the contacts and constraint forces the step solved (force TouchSensors read those, as
Webots reads its contact joints' feedback).

- Bumper TouchSensors (`Bumpers`): a bumper's flag is raised at every step that ends touching (or,
  with split substeps, touched during it: `wbtc.runtime.substeps`, contacts that bounce may last
  less than a basic step) and cleared when the sensor is read (`WbTouchSensor::computeValue`), so a
  bumper sampled every few steps reads 1 when any of those steps touched. As in Webots the flag is
  raised whether the sensor is enabled or not.
- `Node.getContactPoints` (`wbtc.runtime.supervisor_queries`) lists the end pose's contacts (with
  `--ode-contacts`, a cylinder on a plane at Webots' points: `wbtc.runtime.ode_cylinders`).

Not honoured: a GUI touch (a user's click on a bumper); contacts asked for after a supervisor moved a
body in the same step are those of the moved pose (Webots keeps the step's until the next step).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.runtime import ode_cylinders, ode_solve
from wbtc.runtime.sensors import TouchSensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class EndContacts:
    """A scratch `MjData` of one model whose contacts are those of the live data's current pose."""

    def __init__(self, model: mujoco.MjModel) -> None:
        self.model = model
        self.data = mujoco.MjData(model)
        self.cylinders = ode_solve.applies(model) and ode_cylinders.applies(model)
        self._pose: tuple[int, np.ndarray] | None = None  # (step count, qpos) the scratch data last collided

    def collide(self, sim: Simulation) -> mujoco.MjData:
        """The scratch data, collided at the live data's pose (once per step, unless that pose changed)."""
        qpos = sim.data.qpos
        if self._pose is None or self._pose[0] != sim.steps or not np.array_equal(self._pose[1], qpos):
            scratch = self.data
            scratch.qpos[:] = qpos
            mujoco.mj_kinematics(self.model, scratch)
            mujoco.mj_collision(self.model, scratch)
            if self.cylinders:
                ode_cylinders.rewrite(self.model, scratch)  # Webots' cylinder-plane points, as the substeps
            self._pose = (sim.steps, qpos.copy())
        return self.data

    def touching(self, sim: Simulation) -> set[int]:
        """The bodies in contact with another body at the live data's pose."""
        scratch = self.collide(sim)
        if not scratch.ncon:
            return set()
        bodies = self.model.geom_bodyid[scratch.contact.geom]
        return set(np.unique(bodies[bodies[:, 0] != bodies[:, 1]]).tolist())


class Bumpers:
    """The bumper TouchSensors of one model's robots, whose flags each step raises."""

    def __init__(self, sim: Simulation) -> None:
        self.model, self.robots = sim.model, sim.robots  # a supervisor's recompile makes new ones of both
        self.sensors = [s for r in sim.robots for s in r.sensors.values()
                        if isinstance(s, TouchSensor) and s.kind == "bumper"]

    def latch(self, sim: Simulation) -> None:
        """Raise the flag of each bumper whose body touches something as this step ends (or touched in it)."""
        bodies = sim.end_contacts().touching(sim)
        if sim.touched:
            bodies |= sim.touched
        for sensor in self.sensors:
            sensor.latched = sensor.latched or sensor.body in bodies
