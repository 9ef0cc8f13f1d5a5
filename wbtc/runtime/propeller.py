"""Webots' Propeller: the RotationalMotor of a propeller, turned into thrust and torque.

Webots turns a Propeller's motor kinematically (no joint: the helix angle is integrated from the
motor's velocity, which follows Webots' motor rules: the requested velocity in velocity control,
the PID towards the target otherwise, the acceleration limit either way) and, every basic time
step, pushes the Solid above it with

    T = t1 |ω| ω − t2 |ω| V   along the shaft axis, at the center of thrust,
    Q = q1 |ω| ω − q2 |ω| V   (clamped to the motor's maxTorque), a torque of −Q about the shaft axis,

V being the velocity of the center of thrust along the shaft axis. Here the force and torque are
a `Push` on the body the compiler put the propeller on, held for the basic step's substeps as Webots
holds them for its physics step.

Not honoured yet: the helix does not turn on screen, and the fast helix is never shown (the
compiler draws the slow one); torque feedback reads 0.
"""

from __future__ import annotations

import mujoco
import numpy as np

from wbtc.compile.table import DeviceEntry
from wbtc.runtime.joint_stops import Engaged
from wbtc.runtime.motors import Motor
from wbtc.runtime.pushes import Push


class PropellerMotor(Motor):
    """A Propeller's RotationalMotor: Webots' motor state, a helix angle, and the thrust it makes."""

    def __init__(self, entry: DeviceEntry, model: mujoco.MjModel, robot_name: str) -> None:
        self._setup(entry, robot_name)
        info = entry.propeller or {}
        self.site = model.site(entry.site).id
        self.body = int(model.site_bodyid[self.site])
        self.axis = np.asarray(info.get("axis", [1.0, 0.0, 0.0]), dtype=float)  # in the site's frame
        self.thrust_constants = [float(v) for v in info.get("thrust", [1.0, 0.0])]
        self.torque_constants = [float(v) for v in info.get("torque", [1.0, 0.0])]
        self.angle = 0.0
        self.thrust = self.torque_value = 0.0
        self._velocity6 = np.zeros(6)
        self.push = Push()  # its share of qfrc_applied

    def update(self, model: mujoco.MjModel, data: mujoco.MjData, ts: float, stops: Engaged | None = None) -> None:
        """Turn the helix for the coming basic step and apply its thrust and torque to the body.

        `stops` (the joint stops acting in the step) does not concern a propeller.
        """
        omega = 0.0 if self.torque is not None else self.velocity_command(ts, self.angle)
        omega = min(max(omega, -self.max_velocity), self.max_velocity)
        self.angle += omega * ts
        axis = data.site_xmat[self.site].reshape(3, 3) @ self.axis
        point = data.site_xpos[self.site]
        # The velocity of the center of thrust (world frame, linear part last), along the shaft.
        mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_SITE, self.site, self._velocity6, 0)
        along = float(self._velocity6[3:] @ axis)
        spin = abs(omega) * omega
        t1, t2 = self.thrust_constants
        q1, q2 = self.torque_constants
        self.thrust = t1 * spin - t2 * abs(omega) * along
        torque = q1 * spin - q2 * abs(omega) * along
        self.torque_value = min(max(torque, -self.max_torque), self.max_torque)
        self.push.apply(model, data, self.thrust * axis, -self.torque_value * axis, point, self.body)

    def feedback(self, data: mujoco.MjData) -> float:
        """Torque feedback: not modelled for a propeller's motor (see the module docstring)."""
        return 0.0
