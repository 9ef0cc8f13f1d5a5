"""Bumper TouchSensors as Webots reads them: touching at the end of a physics step, held until read.

Webots' ODE steps the world, then detects collisions at the pose the step ended in
(`dWorldStepAndSpaceCollide`; those contacts act in the next step). A bumper's flag is set there and
cleared only when the sensor is read (`WbTouchSensor::computeValue`), so a bumper sampled every
few steps reads 1 when any of those steps ended touching. MuJoCo collides at the start of a
substep: after a step its contacts are those of the pose before the last substep, a whole basic
step old under `--physics-step 1000`, where a falling bar reached Webots' touch sensor one step
late (`physics/hinge_joint_slot`). So after each basic step wbtc collides the end pose again in a
scratch `MjData` (the live one keeps the contacts and constraint forces the step solved), and adds
what the split substeps saw touching (`wbtc.runtime.substeps`: contacts that bounce may last less
than a basic step).

As in Webots the flag is raised whether the sensor is enabled or not: a bumper enabled late reads,
at its first sample, a touch from before. Not honoured: a GUI touch (a user's click on the sensor).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import mujoco
import numpy as np

from wbtc.runtime.sensors import TouchSensor

if TYPE_CHECKING:
    from wbtc.runtime.simulation import Simulation


class Bumpers:
    """The bumper TouchSensors of one model, and the scratch data that collides the end pose."""

    def __init__(self, sim: Simulation) -> None:
        self.model, self.robots = sim.model, sim.robots  # a supervisor's recompile makes new ones of both
        self.sensors = [s for r in sim.robots for s in r.sensors.values()
                        if isinstance(s, TouchSensor) and s.kind == "bumper"]
        self._scratch = mujoco.MjData(self.model) if self.sensors else None

    def latch(self, sim: Simulation) -> None:
        """Raise the flag of each bumper whose body touches something as this step ends."""
        bodies = self.touching(sim.data)
        if sim.touched:
            bodies |= sim.touched
        for sensor in self.sensors:
            sensor.latched = sensor.latched or sensor.body in bodies

    def touching(self, data: mujoco.MjData) -> set[int]:
        """The bodies in contact with another body at `data`'s pose (its own contacts left as they are)."""
        scratch = self._scratch
        assert scratch is not None  # made whenever there is a bumper to latch
        scratch.qpos[:] = data.qpos
        mujoco.mj_kinematics(self.model, scratch)
        mujoco.mj_collision(self.model, scratch)
        if not scratch.ncon:
            return set()
        bodies = self.model.geom_bodyid[scratch.contact.geom]
        return set(np.unique(bodies[bodies[:, 0] != bodies[:, 1]]).tolist())
