"""Free bodies integrated at their centre of mass, as ODE integrates them (`--ode-contacts`).

ODE, Webots' engine, keeps a body's position at its centre of mass and integrates it there: a step
moves the centre of mass by the step times its new velocity, and turns the body about it. MuJoCo
keeps a free joint at the body's frame origin (Webots' Solid origin, which the compiler keeps) and
moves that origin by the step times its own new velocity, in a straight line, then turns the body
about it. When the centre of mass is off the origin and the body turns, the two differ: the centre
of mass follows the chord of the origin's turn. A body spinning freely at 16 rad/s with its centre of
mass 3 cm from its origin (Webots' `dynamic_light_sensor_rays` robot, whose wheels' motors spin its
body about its axle) has its centre of mass moved 4 mm by one 32 ms step in MuJoCo, where ODE's stays
put; at wbtc's 2 ms substeps the same turn moves it 0.25 mm, summed over the substeps. The rows that
hold such a body see the same difference (`ComIntegration.hook`): on its wheels, that robot was
thrown 7 mm up by its contacts in the next step.

Under `--ode-contacts` (wbtc.runtime.substeps) each substep's rows get references for velocities of
centres of mass (`hook`, after `mj_step1`), and after the substep every free joint is moved so that
its body's centre of mass is where ODE's step puts it (`wrap`), and turned as ODE turns it: by
q + h/2 (0, w) q, normalised, that is by 2 atan(|w| h / 2) per step where MuJoCo turns it by |w| h
(0.516 rad against 0.528 for 16.5 rad/s at 32 ms). By default (MuJoCo's contact) nothing changes:
at 2 ms substeps the differences are small and the correction would cost more than the contact.
Not honoured: the same rotation for the bodies a joint moves (MuJoCo integrates joint angles; in ODE
every body is free and turned so).
"""

from __future__ import annotations

from collections.abc import Callable

import mujoco
import numpy as np

Step = Callable[[mujoco.MjModel, mujoco.MjData], None]
Start = tuple[tuple[float, float, float], list[float], tuple[float, float, float], tuple[float, float, float],
              list[float]]


class ComIntegration:
    """The free joints of one model."""

    def __init__(self, model: mujoco.MjModel) -> None:
        free = np.nonzero(model.jnt_type == int(mujoco.mjtJoint.mjJNT_FREE))[0]
        self.bodies = model.jnt_bodyid[free]
        self.offsets = model.body_ipos[self.bodies].copy()  # centre of mass, body frame
        # Per body: its id, its free joint's qpos and qvel addresses.
        self._each = list(zip(self.bodies.tolist(), model.jnt_qposadr[free].tolist(),
                              model.jnt_dofadr[free].tolist(), strict=True))
        self._shift = np.zeros(model.nv)  # the rows' correction, as joint accelerations
        self._rows = np.zeros(0)
        # Per body at the substep's start (`hook`): centre of mass, orientation (xmat), arm (origin to
        # centre of mass), the origin's centripetal acceleration, all in world axes; its quaternion.
        self._start: list[Start] | None = None

    def __bool__(self) -> bool:
        return len(self.offsets) > 0

    def hook(self, model: mujoco.MjModel, data: mujoco.MjData) -> None:
        """After `mj_step1`: the rows' reference accelerations for velocities of centres of mass.

        MuJoCo's rows see a point's velocity after the step as J times the new joint velocities at the
        step's start pose, in which a spinning free body's origin velocity has turned about its centre
        of mass (MuJoCo's bias force: the origin's centripetal acceleration w x (w x arm)). Integrated at
        the centre of mass (`wrap`), the body's points move by that much more: its rows would push
        against an acceleration the body does not have (a robot spinning on its axle at 16 rad/s, its
        origin 3 cm off, pressed 4 N harder on its wheels). So each row's reference loses J times that
        acceleration on the free joints' linear velocities. Also notes the start pose for `wrap`.

        Per body in plain floats: robots are a few bodies, and numpy's per-call cost is what counts.
        """
        start: list[Start] = []
        xipos, xpos, xmat, cvel, shift = data.xipos, data.xpos, data.xmat, data.cvel, self._shift
        for body, adr, dof in self._each:
            cx, cy, cz = xipos[body].tolist()  # mj_step1's kinematics, at the substep's start
            ox, oy, oz = xpos[body].tolist()
            ax, ay, az = cx - ox, cy - oy, cz - oz  # the arm, origin to centre of mass
            wx, wy, wz = cvel[body, :3].tolist()  # the spin, world axes
            wa, ww = wx * ax + wy * ay + wz * az, wx * wx + wy * wy + wz * wz
            centripetal = (wx * wa - ax * ww, wy * wa - ay * ww, wz * wa - az * ww)  # w x (w x a)
            start.append(((cx, cy, cz), xmat[body].tolist(), (ax, ay, az), centripetal,
                          data.qpos[adr + 3:adr + 7].tolist()))
            shift[dof:dof + 3] = centripetal
        self._start = start
        nefc = data.nefc
        if not nefc:
            return
        if len(self._rows) < nefc:
            self._rows = np.zeros(max(nefc, 2 * len(self._rows)))
        rows = self._rows[:nefc]
        mujoco.mj_mulJacVec(model, data, rows, shift)
        data.efc_aref[:nefc] -= rows

    def wrap(self, step: Step) -> Step:
        """`step` (one substep, running `hook` after `mj_step1`), then its free bodies moved as ODE's.

        ODE's step moves a centre of mass by the step times its new velocity. MuJoCo's new velocities
        are taken at the step's start pose: there the centre of mass's is the origin's plus w x arm, plus
        the origin's centripetal acceleration over the step that MuJoCo's bias force put in the origin's.
        The body is turned from its start orientation as ODE turns it, its origin put where that centre
        of mass is for that orientation, and given the velocity that keeps the centre of mass's.
        """
        moves = [(adr, dof, offset) for (_, adr, dof), offset in zip(self._each, self.offsets.tolist(), strict=True)]

        def corrected(model: mujoco.MjModel, data: mujoco.MjData) -> None:
            self._start = None
            step(model, data)
            if self._start is None:  # `hook` did not run: nothing to correct by
                return
            h, qpos, qvel = model.opt.timestep, data.qpos, data.qvel
            for (adr, dof, offset), (com, m, arm, centripetal, quat) in zip(moves, self._start, strict=True):
                vx, vy, vz, sx, sy, sz = qvel[dof:dof + 6].tolist()  # angular: body axes
                # The new spin in world axes at the start pose, then the centre of mass's velocity.
                wx = m[0] * sx + m[1] * sy + m[2] * sz
                wy = m[3] * sx + m[4] * sy + m[5] * sz
                wz = m[6] * sx + m[7] * sy + m[8] * sz
                ax, ay, az = arm
                ux = vx + wy * az - wz * ay + h * centripetal[0]
                uy = vy + wz * ax - wx * az + h * centripetal[1]
                uz = vz + wx * ay - wy * ax + h * centripetal[2]
                # ODE's rotation (dxStepBody without finite rotation): q + h/2 (0, w) q, normalised, which
                # turns by 2 atan(|w| h / 2) where MuJoCo turns by |w| h; then the arm and the spin in
                # world axes at the new orientation.
                w0, x0, y0, z0 = quat
                k = 0.5 * h  # (0, w_world) q = q (0, w_body)
                quat = (w0 - k * (x0 * sx + y0 * sy + z0 * sz), x0 + k * (w0 * sx + y0 * sz - z0 * sy),
                        y0 + k * (w0 * sy + z0 * sx - x0 * sz), z0 + k * (w0 * sz + x0 * sy - y0 * sx))
                n = _Rotation(quat)
                qpos[adr + 3:adr + 7] = (n.w, n.x, n.y, n.z)
                bx, by, bz = n.turn(offset)
                wx, wy, wz = n.turn((sx, sy, sz))
                qpos[adr:adr + 3] = (com[0] + h * ux - bx, com[1] + h * uy - by, com[2] + h * uz - bz)
                qvel[dof:dof + 3] = (ux - (wy * bz - wz * by), uy - (wz * bx - wx * bz), uz - (wx * by - wy * bx))

        return corrected


class _Rotation:
    """A unit quaternion's rotation (w first), as plain floats."""

    def __init__(self, quat: list[float]) -> None:
        w, x, y, z = quat
        norm = (w * w + x * x + y * y + z * z) ** 0.5  # as ODE's step normalises it (dNormalize4)
        self.w, self.x, self.y, self.z = w / norm, x / norm, y / norm, z / norm

    def turn(self, v: tuple[float, float, float] | list[float]) -> tuple[float, float, float]:
        """`v` turned: v + 2w (u x v) + 2u x (u x v), u the quaternion's vector part."""
        w, x, y, z = self.w, self.x, self.y, self.z
        tx, ty, tz = y * v[2] - z * v[1], z * v[0] - x * v[2], x * v[1] - y * v[0]
        return (v[0] + 2 * (w * tx + y * tz - z * ty),
                v[1] + 2 * (w * ty + z * tx - x * tz),
                v[2] + 2 * (w * tz + x * ty - y * tx))
