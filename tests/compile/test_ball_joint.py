"""A BallJoint with motors: three hinges composing Webots' Euler angles (axis, axis3 × axis, axis3)."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world

WORLD = Path(__file__).parent / "fixtures" / "worlds" / "ball_joint_motors.wbt"


def test_three_hinges_on_webots_axes() -> None:
    result, _ = compile_world(WORLD)
    model = result.model
    hinges = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE]
    assert len(hinges) == 3 and all(model.jnt_bodyid[j] == model.jnt_bodyid[hinges[0]] for j in hinges)
    # jointParameters2 gives the first axis (0 1 0); with no jointParameters3, the third is
    # axis × x = (0, 0, -1); the middle one is axis3 × axis = (1, 0, 0).
    np.testing.assert_allclose([model.jnt_axis[j] for j in hinges], [[0, 1, 0], [1, 0, 0], [0, 0, -1]], atol=1e-12)
    np.testing.assert_allclose(model.jnt_pos[hinges[0]], [0.0, 0.0, -0.1], atol=1e-12)  # the anchor, endPoint frame


def test_devices_and_the_middle_motor_limit() -> None:
    result, _ = compile_world(WORLD)
    robot = result.table.robots[0]
    assert [d.name for d in robot.devices] == ["m1", "s1", "m2", "m3"]
    assert robot.device("m1").sensor == "s1" and robot.device("s1").motor == "m1"
    m2, m3 = robot.device("m2"), robot.device("m3")
    assert (m2.fields["minPosition"], m2.fields["maxPosition"]) == pytest.approx((-np.pi / 2, np.pi / 2))
    assert (m3.fields["minPosition"], m3.fields["maxPosition"]) == (-3.0, 3.0)
    assert len({robot.device(n).joint for n in ("m1", "m2", "m3")}) == 3
