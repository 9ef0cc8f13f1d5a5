"""Emitter/Receiver, GPS, Compass, Accelerometer, Gyro, InertialUnit, TouchSensor and LightSensor read as in Webots."""

import json
import math
import struct
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wbtc.cli import app

FIXTURES = Path(__file__).parent / "fixtures"
G = 9.81


@pytest.fixture(scope="module")
def run() -> tuple[dict, dict[str, list[str]]]:
    """devices.wbt for 1.2 s: the JSON result and each robot's printed lines."""
    result = CliRunner().invoke(app, ["run", str(FIXTURES / "devices.wbt"), "--json", "--headless",
                                      "--duration", "1.2"])
    assert result.exit_code == 0, result.output
    lines = result.stdout.strip().splitlines()
    printed: dict[str, list[str]] = {}
    for line in lines[:-1]:
        robot, _, text = line.partition("] ")
        printed.setdefault(robot.lstrip("["), []).append(text)
    return json.loads(lines[-1]), printed


def readings(printed: dict[str, list[str]], robot: str) -> dict[str, list[float]]:
    """`name: v1 v2 ...` lines of device_probe.py."""
    out = {}
    for line in printed[robot]:
        name, _, values = line.partition(": ")
        out[name] = [float(v) for v in values.split()]
    return out


def test_packets_on_channel_1_arrive_in_order_one_step_later(run):
    _, printed = run
    sent = {line.split()[0]: float(line.split()[1]) for line in printed["sender"]}
    packets = [line.split() for line in printed["listener"] if line.startswith("packet")]
    expected = [b"hello", b"\x00\x01\xff", struct.pack("2d", 1.5, -2.25), struct.pack("3i", 7, 8, 9), b"first",
                b"second"]
    assert [bytes.fromhex(p[3]) for p in packets] == expected
    # Each packet is readable after the step that follows its send (16 ms basic time step).
    times = [float(p[1]) for p in packets]
    assert times == pytest.approx([sent[f"sent{i}"] + 0.016 for i in (0, 1, 2, 3, 4, 4)])
    assert [int(p[2]) for p in packets] == [1, 1, 1, 1, 2, 2]  # getQueueLength before reading
    assert [float(p[4]) for p in packets] == pytest.approx([1 / 0.2**2] * 6)  # signal strength 1/r², r = 0.2 m
    assert "string hello" in printed["listener"]
    assert "floats 1.5 -2.25" in printed["listener"]


def test_a_receiver_on_channel_2_gets_nothing(run):
    _, printed = run
    assert printed["other"] == ["channel 2"]


def test_gps_reads_the_robot_position_within_1_mm(run):
    data, printed = run
    robot = next(r for r in data["robots"] if r["name"] == "imu")
    gps = readings(printed, "imu")["gps"]
    assert gps == pytest.approx(robot["position"], abs=0.001)
    assert gps == pytest.approx([0.3, -0.2, 0.05], abs=0.001)


def test_compass_points_north_in_the_device_frame(run):
    _, printed = run
    assert readings(printed, "imu")["compass"] == pytest.approx([0.0, 1.0, 0.0], abs=1e-3)  # facing east
    assert readings(printed, "bumpy")["compass"] == pytest.approx([1.0, 0.0, 0.0], abs=1e-3)  # facing north


def test_accelerometer_gyro_and_inertial_unit_at_rest(run):
    _, printed = run
    values = readings(printed, "imu")
    assert values["accelerometer"] == pytest.approx([0.0, 0.0, G], abs=0.01)
    assert max(abs(v) for v in values["gyro"]) < 1e-3
    assert values["inertial unit"] == pytest.approx([0.0, 0.0, 0.0], abs=1e-3)


def test_bumpers_read_1_on_the_floor_and_0_in_the_air(run):
    _, printed = run
    values = readings(printed, "bumpy")
    assert values["bottom"] == [1.0]
    assert values["top"] == [0.0]


def test_force_feet_carry_the_robot_weight_through_the_default_table(run):
    _, printed = run
    values = readings(printed, "imu")
    (foot,) = values["foot"]  # "force", x axis pointing down: the floor pushes along -x
    fx, fy, fz = values["foot3d"]  # "force-3d", upright: the push is +z in its frame
    # The default table maps N to tenths of N; the robot weighs 1 kg plus two 1 g feet.
    assert foot + fz == pytest.approx(10 * 1.002 * G, rel=0.01)
    assert foot == pytest.approx(10 * 1.002 * G / 2, rel=0.1)
    assert abs(fx) < 0.5 and abs(fy) < 0.5


def test_light_sensors_under_a_lamp_follow_the_cosine_law_plus_ambient(run):
    _, printed = run
    values = readings(printed, "photo")
    # Lamp 1 m above: E = intensity 0.8 · cos + ambientIntensity 0.1; lookup [0 0, 1 1000].
    assert values["up"] == pytest.approx([900.0], abs=0.5)
    assert values["slant"] == pytest.approx([800 * math.cos(math.pi / 3) + 100], abs=0.5)
    assert values["side"] == pytest.approx([100.0], abs=0.5)
    assert values["down"] == pytest.approx([100.0], abs=0.5)


def test_infra_red_emitters_and_receivers_need_each_other_in_their_cones():
    from wbtc.pipeline import compile_world
    from wbtc.runtime.devices import Emitter, Receiver
    from wbtc.runtime.simulation import Simulation

    result, _ = compile_world(Path(__file__).parent / "fixtures" / "ir_cone.wbt")
    sim = Simulation(result, noise=False)
    receivers = {}
    for robot in sim.robots:
        for sensor in robot.sensors.values():
            if isinstance(sensor, Receiver):
                sensor.enable(16, 0.0)
                receivers[robot.entry.name] = sensor
    emitter = next(e for r in sim.robots for e in r.emitters.values() if isinstance(e, Emitter))
    sim.packets.append((emitter, b"hello", emitter.channel))
    sim.step()
    # "ahead" sits on the emitter's axis; "aside" is 90 degrees off its 0.5 rad cone; "looking away" is in
    # the emitter's cone but faces away from it with a cone of its own.
    # (Each receiver sampled at the end of that step: what it got is its value.)
    assert [len(receivers[name].value) for name in ("ahead", "aside", "looking away")] == [1, 0, 0]
    sim.close()
