"""wbtc's Crazyflie: Webots' device names and order, the 50 g body, and lift from its four propellers."""

import json
import math
from pathlib import Path

import pytest
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 8
}
Floor {
}
Crazyflie {
  controller "climb"
}
"""
# Every rotor at 1.1 times the hover speed: thrust 4e-5 ω² each, 4 of them, against 0.05 kg × 9.81.
HOVER = math.sqrt(0.05 * 9.81 / (4 * 4e-05))
CONTROLLER = f"""from controller import Robot

robot = Robot()
for name, sign in (("m1_motor", -1), ("m2_motor", 1), ("m3_motor", -1), ("m4_motor", 1)):
    motor = robot.getDevice(name)
    motor.setPosition(float("inf"))
    motor.setVelocity(sign * 1.1 * {HOVER!r})
while robot.step() != -1:
    pass
"""


def _world(tmp_path: Path) -> Path:
    return project_with_controller(tmp_path, "crazyflie.wbt", WORLD, "climb", CONTROLLER)


def test_devices_in_webots_order_and_the_mass(tmp_path):
    result, _ = compile_world(_world(tmp_path))
    robot = result.table.robots[0]
    assert [d.name for d in robot.devices] == [
        "range_right", "range_back", "range_left", "range_front", "camera", "gps", "gyro", "inertial unit",
        "m1_motor", "m2_motor", "m3_motor", "m4_motor"]
    model = result.model
    assert model.body_subtreemass[model.body(robot.body).id] == pytest.approx(0.05)
    propellers = {d.name: d.propeller for d in robot.devices if d.propeller}
    assert propellers["m1_motor"]["thrust"] == [-4e-05, 0.0]
    assert propellers["m2_motor"]["thrust"] == [4e-05, 0.0]


def test_ten_percent_over_hover_speed_climbs_straight_up(tmp_path):
    result = CliRunner().invoke(app, ["run", str(_world(tmp_path)), "--headless", "--json", "--duration", "1"])
    assert result.exit_code == 0, result.output
    robot = json.loads(result.stdout.strip().splitlines()[-1])["robots"][0]
    climb = 0.5 * 9.81 * (1.1**2 - 1)  # 1.03 m in 1 s
    x, y, z = robot["position"]
    assert abs(z - 0.015 - climb) < 0.01 * climb  # 1.0321 m: the motors reach their speed at once
    assert abs(x) < 1e-3 and abs(y) < 1e-3  # the four thrusts and torques balance
    assert abs(robot["rotation"][3]) < 1e-6  # and the rotors' drag torques cancel: no yaw
