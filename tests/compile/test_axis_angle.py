"""Quaternions back to Webots' axis-angle rotations (what worldSave and getField write)."""

import math

import numpy as np

from wbtc.compile.frames import axis_angle_quat, quat_to_axis_angle


def test_quarter_turn_round_trips() -> None:
    x, y, z, angle = quat_to_axis_angle(axis_angle_quat((0.0, 1.0, 0.0), math.pi / 2))
    assert (x, y, z) == (0.0, 1.0, 0.0)
    assert angle == math.pi / 2


def test_near_identity_off_unit_length_keeps_a_unit_axis() -> None:
    # 1 + 1e-15 in w and a zero vector part: once written as "0 0 0 6e-08", an axis of zeros.
    assert quat_to_axis_angle(np.array([1.0 - 1.2e-15, 0.0, 0.0, 0.0])) == (0.0, 0.0, 1.0, 0.0)


def test_tiny_rotation_axis_is_normalised() -> None:
    x, y, z, angle = quat_to_axis_angle(np.array([1.0, 0.0, 0.0, 1e-8]))
    assert (x, y, z) == (0.0, 0.0, 1.0)
    assert abs(angle - 2e-8) < 1e-20
