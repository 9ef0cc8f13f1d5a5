"""The workshop's camera lessons (examples 6-9): an e-puck (52x39 camera) in front of coloured rocks.

The rocks are cylinders of radius 5 cm and height 10 cm with a plain PBR base colour (red 1 0 0, blue
0 0 1, ...), matte (roughness 1, metalness 0), lit by the TexturedBackgroundLight. "Red" and "blue"
are the lessons' own tests: red > 100, green < 45, blue < 45 (and the same with red and blue swapped).
Speeds: a wheel speed w on both wheels moves the e-puck at w * 0.02 m/s; (w, -w) spins it on the spot
at w * 0.02 / 0.026 rad/s.
"""

import math
import re

import pytest
from lesson_runs import EPUCK_AXLE, EPUCK_RADIUS, EPUCK_WHEEL, WORLDS, run_world, speed

PIXEL = re.compile(r"Color of the central pixel: R=(\d+), G=(\d+), B=(\d+)")


def is_red(r, g, b):
    return r > 100 and g < 45 and b < 45


def is_blue(r, g, b):
    return b > 100 and g < 45 and r < 45


def pixels(run, robot="e-puck"):
    return [tuple(int(v) for v in m.groups()) for m in map(PIXEL.match, run.lines(robot)) if m]


def test_ex06_prints_the_image_size_and_a_red_central_pixel(tmp_path):
    run = run_world(WORLDS / "ex06_camera_capture.wbt", 0.5, tmp_path)
    lines = run.lines("e-puck")
    assert lines[0] == "Captured an image of size: 52x39"
    seen = pixels(run)
    assert len(seen) == len([line for line in lines if line.startswith("Captured")]) >= 7  # one per 64 ms step
    # The robot stands 0.25 m in front of the red rock: the central pixel is red at every step.
    assert all(is_red(*p) for p in seen), seen[:3]


@pytest.fixture(scope="module")
def ex07(tmp_path_factory):
    return run_world(WORLDS / "ex07_red_obstacle.wbt", 2.5, tmp_path_factory.mktemp("ex07"))


def test_ex07_turns_right_while_the_red_rock_is_ahead(ex07):
    seen = pixels(ex07)
    assert is_red(*seen[0])
    # Pixel i is printed after step i + 1 (64 ms steps); while it is red the next step spins the robot
    # right at 2 * 0.02 / 0.026 = 1.54 rad/s. The rock (5 cm radius, 0.3 m ahead) covers 0.17 rad on
    # each side of the centre, so one or two such steps (0.10 rad each) and a few pixels' worth of
    # turning (the image is 0.84 rad wide over 52 pixels) take it out of the centre.
    red_steps = next(i for i, p in enumerate(seen) if not is_red(*p))
    turned = ex07.at("e-puck", (red_steps + 1) * 0.064 + 0.064).yaw
    rate = 2 * EPUCK_WHEEL / (EPUCK_AXLE / 2)
    assert -0.35 < turned < 0, f"heading after {red_steps} red steps: {turned:.3f} rad (one step: {-rate * 0.064:.2f})"
    # Having turned right, it never sees the rock in the centre again.
    assert [i for i, p in enumerate(seen) if is_red(*p) and i > red_steps] == []


def test_ex07_drives_on_once_the_rock_is_not_in_the_centre(ex07):
    start = (next(i for i, p in enumerate(pixels(ex07)) if not is_red(*p)) + 1) * 0.064 + 0.3
    a, b = ex07.at("e-puck", start), ex07.at("e-puck", start + 1.0)
    assert speed(a, b) == pytest.approx(5 * EPUCK_WHEEL, rel=0.03)  # forward at 5 rad/s: 0.1 m/s
    assert abs(b.yaw - a.yaw) < 0.02
    # It keeps the heading it turned to: to the right of the rock (centre at the origin).
    assert b.yaw < 0 and b.y < 0, f"heading {b.yaw:.3f} rad, y {b.y:.3f} m"


@pytest.fixture(scope="module")
def ex08(tmp_path_factory):
    return run_world(WORLDS / "ex08_color_navigation.wbt", 3, tmp_path_factory.mktemp("ex08"))


def test_ex08_turns_right_away_from_the_red_rock_then_drives_past_it(ex08):
    # (5, -5) spins at 5 * 0.02 / 0.026 = 3.85 rad/s: 0.25 rad per 64 ms step. The rock (0.45 m ahead,
    # radius 5 cm) covers 0.11 rad each side of the centre (plus one pixel for the 3x3 block), so
    # one step of spinning, two at most, clear it.
    poses = ex08.trace["e-puck red"]
    heading = ex08.at("e-puck red", 0.5).yaw
    assert -0.55 < heading < -0.17
    a, b = ex08.at("e-puck red", 0.5), ex08.at("e-puck red", 2.5)
    assert speed(a, b) == pytest.approx(5 * EPUCK_WHEEL, rel=0.03)
    assert abs(b.yaw - a.yaw) < 0.02
    # It passes the rock (centre (0, 0.3)) without touching it.
    assert min(math.hypot(p.x, p.y - 0.3) for p in poses) > 0.05 + EPUCK_RADIUS


def test_ex08_backs_away_from_the_blue_rock(ex08):
    poses = ex08.trace["e-puck blue"]
    a, b = ex08.at("e-puck blue", 0.5), poses[-1]
    assert speed(a, b) == pytest.approx(5 * EPUCK_WHEEL, rel=0.03)  # (-5, -5): 0.1 m/s backwards
    assert b.x < a.x  # away from the rock at x = 0.2
    assert abs(b.yaw) < 0.01 and abs(b.y + 0.3) < 0.001  # straight back


def test_ex09_lesson_listing_backs_slowly_with_the_fixed_score(tmp_path):
    run = run_world(WORLDS / "ex09_color_score_speed.wbt", 3, tmp_path)
    # color_score = 3: speed = 0.2 * 3 - 1 = -0.4 rad/s on both wheels, 0.8 cm/s backwards.
    a, b = run.at("e-puck", 0.5), run.trace["e-puck"][-1]
    assert speed(a, b) == pytest.approx(0.4 * EPUCK_WHEEL, rel=0.03)
    assert b.x < a.x and abs(b.yaw) < 0.01


@pytest.fixture(scope="module")
def ex09(tmp_path_factory):
    return run_world(WORLDS / "ex09_color_score_camera.wbt", 3, tmp_path_factory.mktemp("ex09"))


@pytest.mark.parametrize(("robot", "score"), [("e-puck red", 0.0), ("e-puck yellow", 2.5), ("e-puck green", 5.0)])
def test_ex09_camera_scores_the_rock_and_sets_the_speed(ex09, robot, score):
    printed = [re.match(r"colour score: ([-0-9.]+), speed: ([-0-9.]+)", line) for line in ex09.lines(robot)]
    assert printed and all(printed)
    # Red has hue 0 (score 0), yellow 60 degrees (2.5), green 120 (5); speed = 0.2 * score - 1.
    for match in printed:
        assert float(match[1]) == pytest.approx(score, abs=0.1)
        assert float(match[2]) == pytest.approx(0.2 * float(match[1]) - 1, abs=0.006)
    a, b = ex09.at(robot, 0.5), ex09.trace[robot][-1]
    expected = (1 - 0.2 * score) * EPUCK_WHEEL  # backwards
    if expected == 0:
        assert math.hypot(b.x - a.x, b.y - a.y) < 0.001
    else:
        assert speed(a, b) == pytest.approx(expected, rel=0.03)
        assert b.x < a.x
