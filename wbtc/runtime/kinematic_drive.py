"""Robots without Physics that Webots drives by kinematics: two wheel motors slide them over the ground.

Every basic step, before the physics, the robot's root body (static in MuJoCo: it has no joint) is
moved by the wheels' velocities, the motors' current velocities this step (`Motor.current_velocity`:
Webots' kinematic rule, ramped by their `acceleration`), times the wheel radius: the midpoint of the
wheels (their bodies' origins) moves along the travel direction at their mean speed and the robot
turns about the vertical at (right - left) / axle, integrated at the step's midpoint as
WbKinematicDifferentialWheels does. Which wheel is left is read from the model: a wheel's travel
direction is its axis × up, and the turn follows from where the wheels are.

After the move, the robot's collision geoms are pushed out of the static ones they went into, by the
mean of the horizontal parts of the penetrations (Webots' kinematic displacement): the robot stops at
walls, it does not climb them. Moving bodies are pushed by MuJoCo's contacts.

Not honoured yet: encoders that stop when the robot is blocked (the wheels turn on, as in Webots' code).
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from wbtc.compile.table import KinematicDrive
from wbtc.runtime.motors import Motor

#: The model's up axis (the model is ENU).
UP = np.array([0.0, 0.0, 1.0])


class DriveState:
    """One kinematic differential drive of a robot."""

    def __init__(self, spec: KinematicDrive, sim: Any, robot: Any) -> None:
        model = sim.model
        self.spec = spec
        self.sim = sim
        self.body = robot.body
        by_name = {m.entry.name: m for m in robot.motors.values() if isinstance(m, Motor)}
        self.motors = [by_name[name] for name in spec.motors]
        self.joints = [model.joint(m.entry.joint).id for m in self.motors]
        self.wheel_bodies = [int(model.jnt_bodyid[j]) for j in self.joints]
        self.qpos = [int(model.jnt_qposadr[j]) for j in self.joints]
        self.dofs = [int(model.jnt_dofadr[j]) for j in self.joints]
        self.angles = np.array([sim.data.qpos[a] for a in self.qpos], dtype=float)
        self.rates = np.zeros(2)
        self.geoms = [g for g in range(model.ngeom) if int(model.geom_bodyid[g]) in robot.bodies
                      and (model.geom_contype[g] or model.geom_conaffinity[g])]

    def move(self, ts: float) -> None:
        """Slide the robot by one step of its wheels' speeds."""
        model, data = self.sim.model, self.sim.data
        rates = np.array([m.current_velocity() for m in self.motors])
        noise = self.spec.slip_noise
        if noise and self.sim.noise_rng is not None:
            rates *= 1.0 - noise + self.sim.noise_rng.random(2) * 2.0 * noise
        self.rates = rates
        self.angles += rates * ts
        speeds = rates * self.spec.radius
        wheels = [np.array(data.xpos[b]) for b in self.wheel_bodies]
        travel = [np.cross(data.xaxis[j], UP) for j in self.joints]
        norm = float(np.linalg.norm(travel[0]))
        if norm < 1e-9:  # wheels lying flat: nothing rolls
            return
        forward = travel[0] / norm
        if float(np.dot(travel[1], forward)) < 0:  # axes set opposite ways: the second wheel rolls back
            speeds[1] = -speeds[1]
        side = np.cross(forward, UP)  # points to the robot's right
        across = float(np.dot(wheels[1] - wheels[0], side))
        axle = self.spec.axle if self.spec.axle is not None else abs(across)
        if axle <= 0:
            return
        yaw = (speeds[1] - speeds[0]) / (axle if across > 0 else -axle) * ts
        centre = 0.5 * (wheels[0] + wheels[1])
        half = _turn(yaw / 2)
        step = half @ forward * (0.5 * (speeds[0] + speeds[1]) * ts)
        rotation = _turn(yaw)
        # Turn about the vertical through the wheels' midpoint, and move along the half-turned heading.
        position = centre + rotation @ (np.array(data.xpos[self.body]) - centre) + step
        self._place(model, data, position, rotation @ data.xmat[self.body].reshape(3, 3))
        self._push_out(model, data)

    def turn_wheels(self) -> None:
        """After the physics step: the wheels turned by their speeds, whatever the ground did to them.

        Webots turns a kinematic robot's wheels itself; in MuJoCo they are light bodies on hinges that
        rub on the floor, which would hold them back (and the encoders with them).
        """
        data = self.sim.data
        data.qpos[self.qpos] = self.angles
        data.qvel[self.dofs] = self.rates

    def _place(self, model: mujoco.MjModel, data: mujoco.MjData, position: np.ndarray, matrix: np.ndarray) -> None:
        """Put the root body at a world pose (body_pos/body_quat are relative to its parent body)."""
        parent = int(model.body_parentid[self.body])
        parent_mat = data.xmat[parent].reshape(3, 3)
        model.body_pos[self.body] = parent_mat.T @ (position - data.xpos[parent])
        quat = np.zeros(4)
        mujoco.mju_mat2Quat(quat, (parent_mat.T @ matrix).ravel())
        model.body_quat[self.body] = quat
        mujoco.mj_kinematics(model, data)

    def _push_out(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """Move the robot back out of the static geoms it went into (horizontally)."""
        pushes = []
        fromto = np.zeros(6)
        for geom in self.geoms:
            for other in self._static_near(model, data, geom):
                distance = mujoco.mj_geomDistance(model, data, geom, other, 0.0, fromto)
                if distance < 0:
                    push = fromto[3:] - fromto[:3]  # from the robot's deepest point to the obstacle's surface
                    push -= np.dot(push, UP) * UP
                    if float(np.linalg.norm(push)) > 1e-9:
                        pushes.append(push)
        if pushes:
            position = np.array(data.xpos[self.body]) + np.mean(pushes, axis=0)
            self._place(model, data, position, np.array(data.xmat[self.body]).reshape(3, 3))

    def _static_near(self, model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> list[int]:
        """The collision geoms of bodies without joints, other than the robot's, within reach of `geom`."""
        reach = model.geom_rbound[geom] + model.geom_rbound
        near = np.linalg.norm(data.geom_xpos - data.geom_xpos[geom], axis=1) <= reach
        out = []
        for other in np.flatnonzero(near):
            body = int(model.geom_bodyid[other])
            if body == self.body or int(model.body_weldid[body]) != 0 or other in self.geoms:
                continue
            # Any colliding geom: Webots bumps a kinematic robot off static Solids although two body-less
            # geoms otherwise never touch (their contype/conaffinity bits keep MuJoCo from pairing them).
            if not (model.geom_contype[other] or model.geom_conaffinity[other]):
                continue
            out.append(int(other))
        return out


def _turn(angle: float) -> np.ndarray:
    """The rotation matrix of `angle` radians about the vertical."""
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
