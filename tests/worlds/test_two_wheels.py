"""The two-wheel-robot lesson (worlds/two_wheels.wbt): a robot built from base nodes, and a supervisor.

The robot (controller my_robot) has wheels of radius 0.05 m (1 rad/s: 5 cm/s), its front sensor
DisSensFront 0.1 m ahead of its centre with Webots' default lookup table (value = 10000 x distance,
1000 beyond 0.1 m): it stops when the sensor reads below 850, i.e. 8.5 cm from what is ahead. It
starts at x = 0.1 facing +x; the arena's wall (inner face) is at x = 0.75.
The supervisor (my_supervisor) moves DEF Obstacle (a 10 cm box) to (-0.3, 0.45, 0.05) at once and to
(0.65, 0, 0.05) after 300 steps of 16 ms (4.8 s), and changes DEF light's pointLightIntensity by 0.1
on each UP or DOWN key.
The robot's run goes through probe_controller.py (LED changes, camera brightness), as does the
supervisor's (what it sets and reads back); the images the robot saves land in controllers/probe.
"""

import re
from pathlib import Path

import pytest
from lesson_runs import probed_world, run_world, speed

ROBOT = "my robot"
STOP_DISTANCE = 0.1 + 0.085  # from the robot's centre to what it stops in front of
KEYS = "1.0 DOWN\n1.5 DOWN\n2.0 DOWN\n2.5 DOWN\n3.0 DOWN\n4.0 UP\n"
FIELDS = "fields=Obstacle.translation,light.pointLightIntensity"


@pytest.fixture(scope="module")
def alone(tmp_path_factory):
    """The robot without its supervisor: nothing moves the obstacle (left in a corner by the world)."""
    world = probed_world(tmp_path_factory.mktemp("two_wheels_alone"), "two_wheels",
                         {"my_robot": ("leds", "sensors")},
                         replace={'controller "my_supervisor"': 'controller "<none>"'})
    return run_world(world, 13, world.parent)


def test_robot_drives_straight_at_5_cm_s_blinking_its_led(alone):
    assert speed(alone.at(ROBOT, 0.5), alone.at(ROBOT, 8.0)) == pytest.approx(1.0 * 0.05, rel=0.03)
    assert abs(alone.at(ROBOT, 8.0).y) < 0.002 and abs(alone.at(ROBOT, 8.0).yaw) < 0.01  # no sensor sees a side
    # The LED toggles every 10 steps (160 ms) while the robot runs: on at step 0, off at 10, on at 20...
    leds = [(t, text) for t, text in alone.probe(ROBOT) if t < 8.0 and text.startswith("LED")]
    assert [text for _, text in leds[:4]] == ["LED led 1", "LED led 0", "LED led 1", "LED led 0"]
    assert all(b[0] - a[0] == pytest.approx(0.16) for a, b in zip(leds, leds[1:], strict=False))


def alone_dir(run):
    """The folder where the probed robot ran (its working directory)."""
    return Path(run.data["world"]).parent.parent / "controllers" / "probe"


def _first_stop(run):
    """The time of the first step where DisSensFront reads below 850."""
    return next(t for t, text in run.probe(ROBOT) if text.startswith("sensor DisSensFront")
                and float(text.split()[-1]) < 850)


def test_robot_turns_its_led_on_and_saves_both_images_when_it_sees_the_wall(alone):
    stop = _first_stop(alone)
    # 8.5 cm from the wall: the centre at 0.75 - 0.185 = 0.565 (one 16 ms step is 0.8 mm).
    assert alone.at(ROBOT, stop).x == pytest.approx(0.75 - STOP_DISTANCE, abs=0.002)
    assert "LED led 1" in [text for t, text in alone.probe(ROBOT) if t == pytest.approx(stop)]
    saved = alone_dir(alone)
    for name in ("left_img.png", "right_img.png"):
        data = (saved / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n"
        assert int.from_bytes(data[16:20], "big") == 64 and int.from_bytes(data[20:24], "big") == 64


def test_robot_stays_stopped_at_the_wall_with_its_led_on(alone):
    stop = _first_stop(alone)
    # Once stopped, the front sensor keeps reading below 850: the robot stands (its wheels at 0) and
    # every step sets the LED on.
    after = alone.between(ROBOT, stop + 0.5, 13)
    assert max(p.x for p in after) - min(p.x for p in after) < 0.001, (
        f"x between {min(p.x for p in after):.4f} and {max(p.x for p in after):.4f} after stopping at {stop:.3f} s")
    assert all(text == "LED led 1" for t, text in alone.probe(ROBOT) if t >= stop and text.startswith("LED"))


@pytest.fixture(scope="module")
def supervised(tmp_path_factory):
    world = probed_world(tmp_path_factory.mktemp("two_wheels_keys"), "two_wheels",
                         {"my_robot": ("cameras=0.5", "sensors"), "my_supervisor": (FIELDS,)})
    return run_world(world, 7.5, world.parent, keys=KEYS)


@pytest.fixture(scope="module")
def no_keys(tmp_path_factory):
    """The same world without key presses: the lamp stays at 1, for comparing the camera images."""
    world = probed_world(tmp_path_factory.mktemp("two_wheels_nokeys"), "two_wheels",
                         {"my_robot": ("cameras=0.5",), "my_supervisor": (FIELDS,)})
    return run_world(world, 4.0, world.parent)


def _vector(text):
    return [float(v) for v in re.findall(r"-?[0-9.]+(?:e-?\d+)?", text)]


def test_supervisor_moves_the_obstacle_and_reads_it_back(supervised):
    probe = supervised.probe("supervisor")
    sets = [(t, _vector(text.removeprefix("setSFVec3f translation"))) for t, text in probe
            if text.startswith("setSFVec3f translation")]
    assert sets == [(0.0, [-0.3, 0.45, 0.05]), (pytest.approx(4.8), [0.65, 0.0, 0.05])]
    reads = [(t, text) for t, text in probe if text.startswith("field Obstacle.translation")]
    # After the step that follows each set, the field reads back what was set and the node is there.
    for (t_set, value), (t_read, text) in zip(sets, reads, strict=True):
        assert t_read == pytest.approx(t_set + 0.016)
        numbers = _vector(text.removeprefix("field Obstacle.translation"))
        assert numbers[:3] == pytest.approx(value) and numbers[3:] == pytest.approx(value, abs=1e-6)


def test_robot_stops_in_front_of_the_obstacle_the_supervisor_moved(supervised):
    # The obstacle lands 0.45 m ahead of the robot's front at 4.8 s; the robot stops 8.5 cm before its
    # face (x = 0.6) instead of going on to the wall (test_robot_stays_stopped_... checks the standing).
    stop = _first_stop(supervised)
    assert stop > 4.8
    assert supervised.at(ROBOT, stop).x == pytest.approx(0.6 - STOP_DISTANCE, abs=0.002)
    assert max(p.x for p in supervised.trace[ROBOT]) < 0.6 - STOP_DISTANCE + 0.005


def test_up_and_down_keys_change_the_light_intensity(supervised):
    values = [float(text.split()[2]) for _, text in supervised.probe("supervisor")
              if text.startswith("field light.pointLightIntensity")]
    # 1 (the world's value), five DOWN presses (-0.1 each), one UP.
    assert values == pytest.approx([1.0, 0.9, 0.8, 0.7, 0.6, 0.5, 0.6])


def test_dimming_the_light_darkens_the_camera_images(supervised, no_keys):
    def brightness(run, t):
        return next(float(text.split()[-1]) for time, text in run.probe(ROBOT)
                    if text.startswith("camera CameraLeft") and time == pytest.approx(t, abs=0.01))

    # Same run up to the first key at 1 s: same images.
    assert brightness(supervised, 0.528) == pytest.approx(brightness(no_keys, 0.528))
    # At 3.6 s the lamp is at half its intensity: the image is darker, by little. The arena's PBR
    # surfaces take most of their light from the TexturedBackground, as in Webots, whose PBR shading
    # gives a 1 m-away point light 1/π of what a Phong Material gets; the sky does not change at all.
    dimmed, full = brightness(supervised, 3.6), brightness(no_keys, 3.6)
    assert dimmed < full - 0.5, f"mean grey {dimmed:.2f} with the lamp at 0.5, {full:.2f} at 1"
