"""Rigid-frame arithmetic shared by the emitters: Webots rotations to MuJoCo quaternions, composition.

Webots writes orientations as an axis and an angle (`rotation x y z a`); MuJoCo wants unit quaternions
in (w, x, y, z) order. A `Frame` is a position and such a quaternion, expressed in the frame of the
MuJoCo body that holds it, plus the accumulated `scale` of Transform nodes (Webots scales graphics
and bounding objects, never bodies or joints).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

IDENTITY_QUAT = np.array([1.0, 0.0, 0.0, 0.0])


def axis_angle_quat(axis: tuple[float, float, float] | np.ndarray, angle: float) -> np.ndarray:
    """Webots' axis-angle rotation as a MuJoCo quaternion (w, x, y, z).

    A zero axis is what some files write for "no rotation"; it gives the identity, as in Webots.
    """
    v = np.asarray(axis, dtype=float)
    norm = float(np.linalg.norm(v))
    if norm < 1e-12 or angle == 0.0:
        return IDENTITY_QUAT.copy()
    half = 0.5 * float(angle)
    return np.concatenate(([math.cos(half)], math.sin(half) * v / norm))


def quat_mul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Hamilton product a ⊗ b (apply b, then a)."""
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return np.array([
        aw * bw - ax * bx - ay * by - az * bz,
        aw * bx + ax * bw + ay * bz - az * by,
        aw * by - ax * bz + ay * bw + az * bx,
        aw * bz + ax * by - ay * bx + az * bw,
    ])


def quat_conj(q: np.ndarray) -> np.ndarray:
    """The inverse of a unit quaternion."""
    return np.array([q[0], -q[1], -q[2], -q[3]])


def quat_rotate(q: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Rotate vector v by unit quaternion q."""
    return quat_to_mat(q) @ np.asarray(v, dtype=float)


def quat_to_mat(q: np.ndarray) -> np.ndarray:
    """3x3 rotation matrix of a unit quaternion (w, x, y, z)."""
    w, x, y, z = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ])


def mat_to_quat(m: np.ndarray) -> np.ndarray:
    """Unit quaternion (w, x, y, z) of a rotation matrix (Shepperd's method, numerically safe)."""
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = [0.25 * s, (m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s]
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = [(m[2, 1] - m[1, 2]) / s, 0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s]
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = [(m[0, 2] - m[2, 0]) / s, (m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s]
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = [(m[1, 0] - m[0, 1]) / s, (m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s]
    out = np.array(q)
    return out / np.linalg.norm(out)


def quat_to_axis_angle(q: np.ndarray) -> tuple[float, float, float, float]:
    """A quaternion back to Webots' (x, y, z, angle), angle in [0, π], axis 0 0 1 for no rotation."""
    q = np.asarray(q, dtype=float)
    if q[0] < 0:
        q = -q
    # The axis from the vector part itself: a quaternion a rounding off unit length would otherwise
    # give a tiny angle about an axis of zeros (written "0 0 0 6e-08", which no reader accepts).
    s = math.sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3])
    angle = 2.0 * math.atan2(s, q[0])
    if s < 1e-12:
        return (0.0, 0.0, 1.0, 0.0)
    return (q[1] / s, q[2] / s, q[3] / s, angle)


def euler_quat(rx: float, ry: float, rz: float) -> np.ndarray:
    """Extrinsic x, then y, then z rotation (the form Webots' conversion table writes)."""
    qx = axis_angle_quat((1, 0, 0), rx)
    qy = axis_angle_quat((0, 1, 0), ry)
    qz = axis_angle_quat((0, 0, 1), rz)
    return quat_mul(qz, quat_mul(qy, qx))


@dataclass(frozen=True)
class Frame:
    """A pose relative to the enclosing MuJoCo body, with the Transform scale accumulated so far."""

    pos: np.ndarray
    quat: np.ndarray
    scale: np.ndarray

    @staticmethod
    def identity() -> Frame:
        """The body's own frame."""
        return Frame(np.zeros(3), IDENTITY_QUAT.copy(), np.ones(3))

    def compose(self, translation: np.ndarray, quat: np.ndarray, scale: np.ndarray | None = None) -> Frame:
        """Compose this frame with a child pose written in it.

        The child's translation is scaled by this frame's scale (a Transform scales everything below
        it); rotations are not affected by a uniform scale, which is the only kind Webots honours
        for bodies.
        """
        local = np.asarray(translation, dtype=float) * self.scale
        pos = self.pos + quat_rotate(self.quat, local)
        new_scale = self.scale if scale is None else self.scale * np.asarray(scale, dtype=float)
        return Frame(pos, quat_mul(self.quat, quat), new_scale)

    def apply(self, point: np.ndarray) -> np.ndarray:
        """A point written in this frame, in the body frame."""
        return self.pos + quat_rotate(self.quat, np.asarray(point, dtype=float) * self.scale)

    def rotate(self, vector: np.ndarray) -> np.ndarray:
        """A direction written in this frame, in the body frame."""
        return quat_rotate(self.quat, vector)

    def inverse_apply(self, point: np.ndarray) -> np.ndarray:
        """A body-frame point expressed in this frame (scale ignored: used for bodies and joints)."""
        return quat_rotate(quat_conj(self.quat), np.asarray(point, dtype=float) - self.pos)


# NUE worlds (x north, y up, z east) become ENU (x east, y north, z up): ENU x = NUE z,
# ENU y = NUE x, ENU z = NUE y. The columns below are the NUE axes written in ENU.
NUE_TO_ENU = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
NUE_TO_ENU_QUAT = mat_to_quat(NUE_TO_ENU)

# Before R2022a a Cylinder, Capsule, Cone, Plane or ElevationGrid had its axis along local y; MuJoCo's
# primitives (and R2022a Webots) use local z. A rotation of -π/2 about x turns z into y.
LEGACY_PRIMITIVE_QUAT = axis_angle_quat((1, 0, 0), -math.pi / 2)
