"""wbtc's Pioneer 3-AT: Webots' device names and order, its 12 kg, and four driven wheels of radius 0.11 m."""

import json
from pathlib import Path

import pytest
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 10 10
}
Pioneer3at {
  controller "forward"
}
"""
CONTROLLER = """from controller import Robot

robot = Robot()
for name in ("front left wheel", "front right wheel", "back left wheel", "back right wheel"):
    motor = robot.getDevice(name)
    motor.setPosition(float("inf"))
    motor.setVelocity(2.0)
while robot.step() != -1:
    pass
"""


def _world(tmp_path: Path) -> Path:
    return project_with_controller(tmp_path, "pioneer3at.wbt", WORLD, "forward", CONTROLLER)


def test_devices_in_webots_order_and_the_mass(tmp_path):
    result, _ = compile_world(_world(tmp_path))
    robot = result.table.robots[0]
    wheels = [f"{side} wheel{suffix}" for side in ("back left", "back right", "front left", "front right")
              for suffix in ("", " sensor")]
    sonars = ["so0", "so1", "so10", "so11", "so12", "so13", "so14", "so15"] + [f"so{i}" for i in range(2, 10)]
    assert [d.name for d in robot.devices] == wheels + sonars
    model = result.model
    assert model.body_subtreemass[model.body(robot.body).id] == pytest.approx(8.8 + 4 * 0.8)


def test_four_wheels_at_two_radians_a_second_roll_it_forwards(tmp_path):
    result = CliRunner().invoke(app, ["run", str(_world(tmp_path)), "--headless", "--json", "--duration", "2"])
    assert result.exit_code == 0, result.output
    x, y, z = json.loads(result.stdout.strip().splitlines()[-1])["robots"][0]["position"]
    assert abs(x - 2.0 * 0.11 * 2.0) < 0.03 * 0.44  # 0.44 m, less what the start takes
    assert abs(y) < 1e-3
