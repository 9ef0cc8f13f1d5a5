"""The Thymio II activities (position control): worlds/thymio_*.wbt.

Thymio II geometry (protos/robots/Thymio2.proto, as Webots' Thymio2.proto): wheel radius 0.021 m,
wheels at y = +-0.05 m (axle 0.1 m), maximum wheel speed 9.53 rad/s. In position control a motor runs
at the requested velocity (default: the maximum) until it reaches its target.
"""

import math

import pytest
from lesson_runs import WORLDS, run_world

WHEEL = 0.021
AXLE = 0.1


def test_move_to_target_drives_12_rad_of_wheel_and_stops(tmp_path):
    run = run_world(WORLDS / "thymio_move_to_target.wbt", 4, tmp_path)
    # stdout and stderr are forwarded separately, so the sample error message may come first.
    assert "Move the motors of the Thymio II to position 12." in run.lines("Thymio II")
    # The controller ends without calling robot.step(); Webots' Robot.__del__ (wb_robot_cleanup)
    # still sends its last commands, so both wheels turn to 12 rad: 12 * 0.021 = 0.252 m ahead, reached
    # after 12 / 9.53 = 1.3 s at full speed.
    end, before = run.trace["Thymio II"][-1], run.at("Thymio II", 3.0)
    assert end.x - (-0.15) == pytest.approx(12 * WHEEL, rel=0.03)
    assert abs(end.y) < 0.005 and abs(end.yaw) < 0.02
    assert math.hypot(end.x - before.x, end.y - before.y) < 0.001


def test_turn_on_spot_spins_42_rad_anticlockwise_and_stops(tmp_path):
    run = run_world(WORLDS / "thymio_turn_on_spot.wbt", 12, tmp_path)
    # Left wheel to -100 rad, right wheel to +100 rad: each wheel rolls 100 * 0.021 = 2.1 m in
    # opposite directions, turning the robot by 2 * 2.1 / 0.1 = 42 rad about its centre, in
    # 100 / 9.53 = 10.5 s, if the wheels did not slip. They do: 39.3 rad measured (6.5 % less), where
    # an ODE model of the Thymio with Webots' contact settings at this 20 ms step spins 38.6 rad (its
    # two contacts per wheel, one at each rim, settle differently at each step size). In wbtc the loss
    # comes from the caster ball bouncing (MuJoCo's sliding contact pushes it out of the floor), not
    # from ODE's rim contacts: the same figure for another reason. Hence 10 %.
    poses = run.trace["Thymio II"]
    assert poses[-1].yaw == pytest.approx(2 * 100 * WHEEL / AXLE, rel=0.10)
    assert max(math.hypot(p.x, p.y) for p in poses) < 0.01  # on the spot
    assert abs(poses[-1].yaw - run.at("Thymio II", 11.5).yaw) < 0.01  # stopped


@pytest.fixture(scope="module")
def shapes(tmp_path_factory):
    return run_world(WORLDS / "thymio_shapes.wbt", 20, tmp_path_factory.mktemp("shapes"))


SIDE = 7 * WHEEL * 1.0  # 1 s at 7 rad/s: 0.147 m
WHEELS_TURN = 2 * 7 * WHEEL * 0.6 / AXLE  # 0.6 s of wheels at +-7 rad/s: 1.764 rad (101 degrees) without slip


def test_shapes_draws_two_squares_that_close(shapes):
    # The two squares: 8 times 1 s forward then 0.6 s clockwise on the spot. Each side within 5 % (the
    # wheels take a few steps to reverse). The wheels alone would turn the robot 101 degrees, but they
    # slip: each spin is a right angle (88.9 to 90 degrees measured), which is what the lesson's 0.6 s
    # was chosen for, and each square closes. An ODE model of the Thymio with Webots' contact settings
    # at this 20 ms step turns 90.4 to 90.9 degrees; in wbtc the slip comes from the front caster ball
    # (friction 0.7) bouncing off the floor as it slides, in ODE from how its two rim contacts per
    # wheel settle at a 20 ms step (at 10 ms and below ODE grips at the outer rims: 85 degrees).
    for k in range(8):
        start, corner, turned = (shapes.at("Thymio II", 1.6 * k + dt) for dt in (0.0, 1.0, 1.6))
        assert math.hypot(corner.x - start.x, corner.y - start.y) == pytest.approx(SIDE, rel=0.05), f"side {k + 1}"
        assert corner.yaw - turned.yaw == pytest.approx(math.pi / 2, rel=0.03), f"spin {k + 1}"
        assert corner.yaw - turned.yaw < 0.95 * WHEELS_TURN, f"spin {k + 1} does not slip"
        assert math.hypot(turned.x - corner.x, turned.y - corner.y) < 0.01, f"spin {k + 1} is not on the spot"
    for square in range(2):
        first, last = shapes.at("Thymio II", 6.4 * square), shapes.at("Thymio II", 6.4 * (square + 1))
        assert math.hypot(last.x - first.x, last.y - first.y) < 0.05, f"square {square + 1} does not close"
    assert max(p.z for p in shapes.trace["Thymio II"]) < 0.01  # it stays on its wheels


def test_shapes_zig_zags_and_stops(shapes):
    # After the squares (12.8 s): forward, clockwise, forward, anticlockwise, twice (6.4 s), then
    # stopRobot() and the controller ends (Webots sends that last command when it ends).
    start = shapes.at("Thymio II", 12.8)
    for k in range(4):
        a, b = shapes.at("Thymio II", 12.8 + 1.6 * k), shapes.at("Thymio II", 13.8 + 1.6 * k)
        assert math.hypot(b.x - a.x, b.y - a.y) == pytest.approx(SIDE, rel=0.05), f"zig-zag side {k + 1}"
    # Clockwise and anticlockwise spins cancel: the heading ends where the zig-zag began.
    assert shapes.at("Thymio II", 19.2).yaw == pytest.approx(start.yaw, abs=0.2)
    end, before = shapes.trace["Thymio II"][-1], shapes.at("Thymio II", 19.5)
    assert math.hypot(end.x - before.x, end.y - before.y) < 0.001
    assert abs(end.yaw - before.yaw) < 0.01, "the robot goes on spinning after stopRobot()"
