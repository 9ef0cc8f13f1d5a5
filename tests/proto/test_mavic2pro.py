"""wbtc's Mavic 2 Pro: Webots' device names and order, its mass, and a hover with Webots' published gains."""

import json
import math
import shutil
from pathlib import Path

import pytest
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

FIXTURES = Path(__file__).parent / "fixtures"
# As Webots' mavic_2_pro.wbt: 8 ms steps and a default damping of half the speed a second.
WORLD = """#VRML_SIM R2023b utf8
EXTERNPROTO "webots://projects/robots/dji/mavic/protos/Mavic2Pro.proto"
WorldInfo {
  basicTimeStep 8
  defaultDamping Damping {
    linear 0.5
    angular 0.5
  }
}
Floor {
  size 10 10
}
Mavic2Pro {
  controller "mavic_hover"
  controllerArgs [ "ARG" ]
}
"""


def _world(tmp_path: Path, yaw: float) -> Path:
    shutil.copy(FIXTURES / "mavic_hover.py", tmp_path / "mavic_hover.py")
    world = tmp_path / "mavic.wbt"
    world.write_text(WORLD.replace("ARG", str(yaw)), encoding="utf-8")
    return world


def _run(world: Path, seconds: float) -> tuple[dict, str]:
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--json", "--duration", str(seconds)])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout.strip().splitlines()[-1]), result.output


def test_devices_in_webots_order_and_the_mass_that_flies(tmp_path):
    result, _ = compile_world(_world(tmp_path, 0.0))
    robot = result.table.robots[0]
    assert [d.name for d in robot.devices] == [
        "compass", "gps", "gyro", "inertial unit", "rear left propeller", "rear right propeller",
        "front right propeller", "camera yaw", "camera yaw sensor", "camera pitch", "camera pitch sensor",
        "camera roll", "camera roll sensor", "camera", "front right led", "front left led", "front left propeller"]
    # The 0.4 kg body, three 0.0333 kg gimbal links and two 0.0035 kg LEDs; the helices weigh nothing.
    model = result.model
    assert model.body_subtreemass[model.body(robot.body).id] == pytest.approx(0.4 + 3 * 0.0333 + 2 * 0.0035)
    propellers = {d.name: d.propeller for d in robot.devices if d.propeller}
    assert propellers["front left propeller"]["thrust"] == [0.00026, 0.0]
    assert propellers["front right propeller"]["thrust"] == [-0.00026, 0.0]


def test_webots_example_gains_hold_it_at_one_metre(tmp_path):
    # The example's cubic altitude term balances the 0.507 kg at 69.15 rad/s (0.00026 · 4 · ω² = m g),
    # which it commands exactly when the drone is at its 1 m target: if the mass or the thrust were
    # off, it would settle elsewhere.
    data, output = _run(_world(tmp_path, 0.0), 30)
    assert "[Mavic 2 PRO] at 5 s" in output
    robot = data["robots"][0]
    assert robot["position"][2] == pytest.approx(1.0, abs=0.01)
    axis, angle = robot["rotation"][:3], robot["rotation"][3]
    tilt = math.degrees(angle) * math.hypot(axis[0], axis[1])
    assert tilt < 2.0  # level: roll and pitch held by the gains 50 and 30


def test_speeding_up_the_clockwise_rotors_yaws_it_anticlockwise(tmp_path):
    # A yaw input (from 6 s) speeds up the front-right and rear-left rotors (turning clockwise, at
    # negative velocities) and slows the others: their reaction torques, −Q about the shaft, turn the
    # drone anticlockwise seen from above, compared with the same flight without the input.
    def yaw_at(seconds: float, disturbance: float, folder: Path) -> float:
        folder.mkdir()
        data, _ = _run(_world(folder, disturbance), seconds)
        axis, angle = data["robots"][0]["rotation"][:3], data["robots"][0]["rotation"][3]
        return axis[2] * angle

    turned = yaw_at(7.5, 1.3, tmp_path / "turned") - yaw_at(7.5, 0.0, tmp_path / "plain")
    assert turned > 0.5
