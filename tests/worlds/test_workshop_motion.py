"""The workshop's e-puck lessons that use motors, proximity sensors and LEDs (examples 1-5 and 10).

Expected numbers come from the lesson code and the e-puck geometry (lesson_runs.EPUCK_*): a wheel
speed w (rad/s) on both wheels drives the e-puck at w * 0.02 m/s; one wheel at w and the other
stopped turns it at w * 0.02 / 0.052 rad/s about the stopped wheel. Sensor noise is seeded by the
world (randomSeed 0), so every run is the same.
"""

import math

import pytest
from lesson_runs import EPUCK_AXLE, EPUCK_RADIUS, EPUCK_WHEEL, WORLDS, probed_world, run_world, speed

MAX_SPEED = 6.28


@pytest.fixture(scope="module")
def ex01(tmp_path_factory):
    return run_world(WORLDS / "ex01_go_forward.wbt", 6, tmp_path_factory.mktemp("ex01"))


def test_ex01_drives_straight_at_ten_percent_of_max_speed(ex01):
    expected = 0.1 * MAX_SPEED * EPUCK_WHEEL  # 1.256 cm/s
    # After the first 0.5 s (the robot starts from rest and rocks a little on its two wheels) the
    # speed is the wheel speed times the radius: 2 % covers the rolling contact's small slip.
    assert speed(ex01.at("e-puck", 0.5), ex01.at("e-puck", 6)) == pytest.approx(expected, rel=0.02)
    end = ex01.trace["e-puck"][-1]
    assert end.x - (-0.4) == pytest.approx(expected * end.t, rel=0.03)
    assert abs(end.y) < 0.001 and abs(end.yaw) < 0.01  # straight ahead along +x
    assert ex01.robot("e-puck")["status"] == "running"  # "forever": the controller is still looping


@pytest.fixture(scope="module")
def ex02(tmp_path_factory):
    return run_world(WORLDS / "ex02_forward_turn_right.wbt", 3, tmp_path_factory.mktemp("ex02"))


def test_ex02_goes_forward_for_ten_steps(ex02):
    # 10 steps of 64 ms with both wheels at 50 %: 3.14 rad/s * 0.02 m * 0.64 s = 4.02 cm.
    expected = 0.5 * MAX_SPEED * EPUCK_WHEEL * 0.64
    at = ex02.at("e-puck", 0.64)
    assert at.x == pytest.approx(expected, rel=0.05)  # 5 %: the start from rest
    assert abs(at.yaw) < 0.01


def test_ex02_turns_right_about_the_right_wheel_then_stays_still(ex02):
    # The second loop runs 10 steps with the left wheel at 3.14 rad/s and the right wheel stopped; the
    # `while` loop then steps once more before it sets both wheels to 0: 11 steps (0.704 s) of turning
    # at 3.14 * 0.02 / 0.052 = 1.208 rad/s, 0.850 rad (48.7 degrees) clockwise about the right wheel.
    turned = 11 * 0.064 * 0.5 * MAX_SPEED * EPUCK_WHEEL / EPUCK_AXLE
    forward = 0.5 * MAX_SPEED * EPUCK_WHEEL * 0.64
    half = EPUCK_AXLE / 2
    expected_x, expected_y = forward + half * math.sin(turned), -half + half * math.cos(turned)
    end = ex02.trace["e-puck"][-1]
    # 10 %: the right wheel stops at once from 3.14 rad/s and skids a little before the pivot settles.
    assert end.yaw == pytest.approx(-turned, rel=0.10)
    # The centre moves on a 2.6 cm circle about the right wheel; 1 cm covers the same skid.
    assert math.hypot(end.x - expected_x, end.y - expected_y) < 0.01
    settled = ex02.at("e-puck", 1.6)
    assert math.hypot(end.x - settled.x, end.y - settled.y) < 0.001
    assert abs(end.yaw - settled.yaw) < 0.01


@pytest.fixture(scope="module")
def ex03(tmp_path_factory):
    return run_world(WORLDS / "ex03_avoid_obstacle_ps0.wbt", 8, tmp_path_factory.mktemp("ex03"))


def test_ex03_cruises_then_turns_right_before_the_wall(ex03):
    values = [float(line) for line in ex03.lines("e-puck")]
    # The controller prints ps0 once per 64 ms step: value i is read at (i + 1) * 0.064 s.
    first = next(i for i, v in enumerate(values) if v > 80)
    seen = (first + 1) * 0.064
    assert max(values[:first]) < 80
    cruise = 0.1 * MAX_SPEED * EPUCK_WHEEL
    assert speed(ex03.at("e-puck", 0.5), ex03.at("e-puck", seen)) == pytest.approx(cruise, rel=0.03)
    assert abs(ex03.at("e-puck", seen).yaw) < 0.01
    # The wall's inner face is at x = 0.5: when ps0 sees it the body is still at least 1 cm away.
    assert 0.5 - (ex03.at("e-puck", seen).x + EPUCK_RADIUS) > 0.01
    # Then it spins right while ps0 sees the wall and cruises on: by 8 s it heads more than 20 degrees
    # to the right, and it never went through the wall.
    assert ex03.trace["e-puck"][-1].yaw < -math.radians(20)
    assert max(p.x for p in ex03.trace["e-puck"]) + EPUCK_RADIUS < 0.5 + 0.002


@pytest.fixture(scope="module")
def ex04(tmp_path_factory):
    return run_world(WORLDS / "epuck_obstacles.wbt", 7, tmp_path_factory.mktemp("ex04"))


def test_ex04_drives_at_5_rad_s_and_stops_in_front_of_the_wall(ex04):
    # Forward at 5 rad/s (0.1 m/s) along +x between the boxes, stop when ps0 or ps7 reads > 80.
    assert speed(ex04.at("e-puck", 0.5), ex04.at("e-puck", 3.5)) == pytest.approx(5 * EPUCK_WHEEL, rel=0.03)
    end, before = ex04.trace["e-puck"][-1], ex04.at("e-puck", 5.5)
    assert math.hypot(end.x - before.x, end.y - before.y) < 0.001  # standing still
    gap = 0.5 - (end.x + EPUCK_RADIUS)
    assert 0.005 < gap < 0.07  # in front of the wall, within the sensors' 7 cm range
    assert abs(end.yaw) < 0.05


@pytest.fixture(scope="module")
def ex05(tmp_path_factory):
    world = probed_world(tmp_path_factory.mktemp("ex05"), "ex05_obstacle_led",
                         {"ex05_obstacle_led": ("leds", "sensors")})
    return run_world(world, 4.5, world.parent)


def test_ex05_flashes_led0_three_times_when_it_sees_the_box(ex05):
    probe = ex05.probe("e-puck")
    leds = [(t, text) for t, text in probe if text.startswith("LED")]
    first_flash = leds[0][0]
    # The first flash follows the first step where ps0 or ps7 reads more than 80, never earlier.
    seen = [t for t, text in probe if text.startswith(("sensor ps0", "sensor ps7")) and float(text.split()[2]) > 80]
    assert seen and seen[0] == pytest.approx(first_flash)
    # flashLED(): on, off, on, off, on, off, one 64 ms step apart.
    assert [text for _, text in leds[:6]] == ["LED led0 1", "LED led0 0"] * 3
    times = [t for t, _ in leds[:6]]
    assert all(b - a == pytest.approx(0.064) for a, b in zip(times, times[1:], strict=False))
    # Every encounter flashes three times: the sets come in whole flashes.
    assert len(leds) % 6 == 0


def test_ex05_drives_at_5_rad_s_then_turns_right_at_the_box(ex05):
    first_flash = next(t for t, text in ex05.probe("e-puck") if text.startswith("LED"))
    assert speed(ex05.at("e-puck", 0.5), ex05.at("e-puck", first_flash)) == pytest.approx(0.1, rel=0.03)
    assert abs(ex05.at("e-puck", first_flash).yaw) < 0.01
    # While it flashes its wheels keep the last speeds: it goes on 6 * 64 ms * 0.1 m/s = 3.8 cm and
    # reaches the box (face at x = 0.2); it never goes through it.
    assert max(p.x for p in ex05.trace["e-puck"]) + EPUCK_RADIUS < 0.2 + 0.002
    # Then it turns right (5, -5) until neither front sensor sees the box, and drives off to the right.
    end = ex05.trace["e-puck"][-1]
    assert -math.pi < end.yaw < -math.radians(45)
    assert end.y < -0.1


@pytest.fixture(scope="module")
def ex10(tmp_path_factory):
    return run_world(WORLDS / "ex10_distance_speed.wbt", 10, tmp_path_factory.mktemp("ex10"))


def _ex10_printed(run):
    """(time, ps0 value, speed) of each step: line i is printed after step i + 1 (32 ms steps)."""
    rows = []
    for i, line in enumerate(run.lines("e-puck")):
        distance, _, rate = line.removeprefix("Distance: ").partition(", Speed: ")
        rows.append(((i + 1) * 0.032, float(distance), float(rate)))
    return rows


def test_ex10_speed_follows_the_linear_model_far_from_the_wall(ex10):
    rows = _ex10_printed(ex10)
    for _, distance, rate in rows:
        assert rate == pytest.approx(max(-10, min(10, -0.02 * distance + 5)))
    # Far from the wall ps0 reads about 67: speed 5 - 0.02 * 67 = 3.66 rad/s, 7.3 cm/s. Over 0.5-2.5 s
    # the robot covers the distance the printed speeds ask for (each applies during the next step),
    # within 3 %: the e-puck rolls without slipping.
    a, b = ex10.at("e-puck", 0.5), ex10.at("e-puck", 2.5)
    asked = sum(rate for t, _, rate in rows if a.t - 1e-9 <= t < b.t - 1e-9) * 0.032 * EPUCK_WHEEL
    moved = b.x - a.x
    assert moved == pytest.approx(asked, rel=0.03)


def test_ex10_slows_down_and_stops_before_the_wall(ex10):
    rows = _ex10_printed(ex10)
    far = speed(ex10.at("e-puck", 0.5), ex10.at("e-puck", 2.5))
    # Once ps0 reads more than 200 (about 3 cm from the wall) the speed is below 5 - 0.02 * 200 = 1 rad/s.
    close = next(t for t, distance, _ in rows if distance > 200)
    near = speed(ex10.at("e-puck", close), ex10.at("e-puck", close + 0.5))
    assert near < far / 2
    # It settles where 0.02 * value = 5, i.e. ps0 = 250 (about 2.5 cm from the wall): over the last
    # 3 s the values average 250 +- 30. There the value grows by about 15 per mm, so a 1 mm error
    # changes the speed by 0.3 rad/s (6 mm/s): the robot is held in place within a fraction of a
    # millimetre against the sensor noise (+-2.4 % of 250); 3 mm leaves room for its rocking.
    late = [distance for t, distance, _ in rows if t > 7]
    assert sum(late) / len(late) == pytest.approx(250, abs=30)
    positions = [p.x for p in ex10.between("e-puck", 7, 10)]
    assert max(positions) - min(positions) < 0.003
    gap = 0.5 - (max(p.x for p in ex10.trace["e-puck"]) + EPUCK_RADIUS)
    assert 0.005 < gap < 0.03
