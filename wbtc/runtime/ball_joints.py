"""A device-less BallJoint's three positions, on the one MuJoCo ball joint wbtc makes of it.

Webots turns a BallJoint's endPoint by its three positions (θ1, θ2, θ3) about three axes of the
joint's parent frame: `axis` (jointParameters2's), `axis3` (jointParameters3's) and between them
`axis2 = axis3 × axis`, composed as q(axis, θ1)·q(axis2, θ2)·q(axis3, θ3) about the anchor
(WbBallJoint::computeEndPointSolidPositionFromParameters). Its ODE motor reads the same Euler
angles back. wbtc writes the endPoint at the positions of the world file (θ⁰) and lets MuJoCo's
ball joint turn it from there, so the current positions are the Euler angles of the current turn
composed with Q(θ⁰), and writing one position is writing the ball joint's quaternion anew.

The axis2 ⟂ axis and axis2 ⟂ axis3 of that construction make the angles Davenport angles: turning
axis3 onto axis × axis2 about axis2 (by α) makes them the x-y-z Euler angles of a right-handed
basis. Of the two solutions (and their 2π turns) the one nearest the world file's positions is taken,
as Webots follows its positions continuously from there.
"""

from __future__ import annotations

import math

import numpy as np

from wbtc.compile.frames import axis_angle_quat, quat_conj, quat_mul, quat_to_mat


def _unit(v: np.ndarray) -> np.ndarray:
    return np.asarray(v, dtype=float) / float(np.linalg.norm(v))


class EulerAxes:
    """A BallJoint's three axes, in whatever frame they are given."""

    def __init__(self, axis: np.ndarray, axis3: np.ndarray) -> None:
        """Take `axis` and `axis3` (any length); `axis2 = axis3 × axis`."""
        self.axes = (_unit(axis), _unit(np.cross(axis3, axis)), _unit(axis3))
        e1, e2 = self.axes[0], self.axes[1]
        self.basis = np.column_stack([e1, e2, np.cross(e1, e2)])  # right-handed: axis, axis2, axis × axis2
        # The turn about axis2 that takes axis × axis2 onto axis3 (0 when axis ⟂ axis3).
        self.alpha = math.atan2(float(np.dot(e1, self.axes[2])), float(np.dot(self.basis[:, 2], self.axes[2])))

    def quat(self, angles: tuple[float, float, float] | np.ndarray) -> np.ndarray:
        """q(axis, θ1)·q(axis2, θ2)·q(axis3, θ3)."""
        q = axis_angle_quat(self.axes[0], float(angles[0]))
        q = quat_mul(q, axis_angle_quat(self.axes[1], float(angles[1])))
        return quat_mul(q, axis_angle_quat(self.axes[2], float(angles[2])))

    def angles(self, q: np.ndarray, near: tuple[float, float, float] | np.ndarray) -> np.ndarray:
        """The positions (θ1, θ2, θ3) whose `quat` is `q`, the solution nearest `near`."""
        turn = quat_to_mat(quat_mul(q, axis_angle_quat(self.axes[1], self.alpha)))
        m = self.basis.T @ turn @ self.basis  # = Rx(θ1)·Ry(θ2 + α)·Rz(θ3)
        near = np.asarray(near, dtype=float)
        cos_b = math.hypot(float(m[1, 2]), float(m[2, 2]))
        b = math.atan2(float(m[0, 2]), cos_b)
        if cos_b < 1e-9:  # gimbal lock: only θ1 ± θ3 is known; keep θ1
            a = float(near[0])
            c = math.atan2(float(m[1, 0]), float(m[1, 1])) + (-a if m[0, 2] > 0 else a)
            candidates = [np.array([a, b, c])]
        else:
            a, c = math.atan2(-float(m[1, 2]), float(m[2, 2])), math.atan2(-float(m[0, 1]), float(m[0, 0]))
            candidates = [np.array([a, b, c]), np.array([a + math.pi, math.pi - b, c + math.pi])]
        best = None
        for candidate in candidates:
            candidate[1] -= self.alpha
            candidate = near + np.remainder(candidate - near + math.pi, 2 * math.pi) - math.pi
            if best is None or np.sum((candidate - near) ** 2) < np.sum((best - near) ** 2):
                best = candidate
        return best


def current_angles(axes: EulerAxes, written: np.ndarray, turn: np.ndarray, start: np.ndarray) -> np.ndarray:
    """The BallJoint's positions now.

    Args:
        axes: its axes in the endPoint body's parent frame.
        written: the endPoint body's written orientation in that frame (at the positions `start`).
        turn: the MuJoCo ball joint's quaternion (a turn in the endPoint body's frame).
        start: the positions of the world file.
    """
    delta = quat_mul(quat_mul(written, turn), quat_conj(written))  # the same turn, in the parent frame
    return axes.angles(quat_mul(delta, axes.quat(start)), start)


def ball_turn(axes: EulerAxes, written: np.ndarray, angles: np.ndarray, start: np.ndarray) -> np.ndarray:
    """The MuJoCo ball joint's quaternion that puts the endPoint at `angles` (see `current_angles`)."""
    delta = quat_mul(axes.quat(angles), quat_conj(axes.quat(start)))
    turn = quat_mul(quat_mul(quat_conj(written), delta), written)
    return turn / float(np.linalg.norm(turn))
