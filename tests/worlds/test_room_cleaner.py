"""The room-cleaner lesson (worlds/room_cleaner.wbt): a two-wheel robot with an IMU in a 4 x 4 m room.

The controller drives both wheels at 15 rad/s (wheels of radius 0.04 m: 0.6 m/s) while ds_front
reads more than 300, and prints round(yaw in degrees) + 180 at every step. ds_front sits 0.17 m ahead
of the robot's centre, on the edge of its 0.17 m body, with Webots' default table (1000 per 0.1 m:
300 is 3 cm); the wall ahead (inner face at x = 2) is 2 m from the start, facing +x (yaw 0: 180).
"""

import math

import pytest
from lesson_runs import WORLDS, run_world, speed


@pytest.fixture(scope="module")
def cleaner(tmp_path_factory):
    return run_world(WORLDS / "room_cleaner.wbt", 5, tmp_path_factory.mktemp("cleaner"))


def test_cleaner_prints_a_constant_yaw_of_180(cleaner):
    printed = cleaner.lines("cleaner")
    assert len(printed) > 250  # one line per 16 ms step
    assert set(printed) == {"180"}
    assert all(abs(p.yaw) < math.radians(0.5) for p in cleaner.trace["cleaner"])


def test_cleaner_drives_at_0_6_m_s_and_stops_within_5_cm_of_the_wall(cleaner):
    assert speed(cleaner.at("cleaner", 0.5), cleaner.at("cleaner", 2.0)) == pytest.approx(15 * 0.04, rel=0.03)
    end, before = cleaner.trace["cleaner"][-1], cleaner.at("cleaner", 4.0)
    assert math.hypot(end.x - before.x, end.y - before.y) < 0.001  # stopped
    # It stops in the step where ds_front reads <= 300 (the sensor 3 cm from the wall); that 16 ms step
    # at 0.6 m/s (1 cm) and braking at about the friction limit (v^2 / 2 mu g, about 2 cm) end at the wall.
    ahead = 2.0 - (end.x + 0.17)
    assert -0.002 <= ahead <= 0.05
    assert abs(end.y) < 0.01
