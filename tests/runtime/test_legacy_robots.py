"""Robots of Webots 7 worlds: DifferentialWheels (both modes), the EPuck library name, the Supervisor node.

The expected figures are Webots' own arithmetic: a kinematic DifferentialWheels ramps each wheel's
speed by maxAcceleration (default 10 rad/s²) every step up to speed × speedUnit, moves by the mean
wheel speed × wheelRadius, and counts encoderResolution encoder steps per radian.
"""

import json
import math
from pathlib import Path

from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

WORLDS = Path(__file__).parent / "fixtures" / "legacy" / "worlds"
STEP = 0.032
RADIUS = 0.0205
RESOLUTION = 159.23
SPEED = 500 * 0.00628  # rad/s


def run(name: str, duration: str = "5") -> tuple[dict, str]:
    result = CliRunner().invoke(app, ["run", str(WORLDS / name), "--json", "--headless", "--duration", duration])
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout.strip().splitlines()[-1]), result.output


def ramped_angle(steps: int, acceleration: float = 10.0) -> float:
    """The angle a kinematic DifferentialWheels' wheel turns in `steps` steps from rest."""
    return sum(min(acceleration * STEP * k, SPEED) for k in range(1, steps + 1)) * STEP


def encoder_line(output: str) -> tuple[float, float]:
    line = next(x for x in output.splitlines() if "] encoders " in x and " set " not in x)
    left, right = line.split("] encoders ")[1].split()
    return float(left), float(right)


def test_a_kinematic_differential_wheels_epuck_drives_as_webots_computes():
    data, output = run("dw_kinematic.wbt")
    robot = data["robots"][0]
    # 157 steps (5.024 s): the speeds were set before the first step.
    travelled = ramped_angle(157) * RADIUS
    assert math.isclose(travelled, 0.3143, abs_tol=1e-4)
    assert math.isclose(0.5 - robot["position"][2], travelled, abs_tol=1e-9)
    assert abs(robot["position"][0]) < 1e-12 and abs(robot["position"][1]) < 1e-12  # no gravity, no drift
    assert "[e-puck] speed unit 0.00628, max speed 1000" in output
    # Encoders read at 4.992 s (156 steps), set to (0, 100) at 2.016 s (63 steps).
    turned = (ramped_angle(156) - ramped_angle(63)) * RESOLUTION
    left, right = encoder_line(output)
    assert math.isclose(left, turned, abs_tol=0.01)
    assert math.isclose(right, 100 + turned, abs_tol=0.01)


def test_the_physics_mode_rolls_the_wheels_on_the_floor():
    data, output = run("dw_physics.wbt")
    robot = data["robots"][0]
    rolled = SPEED * 5.024 * RADIUS  # 0.3234 m: maxForce 0.3 N·m brings the light wheels to speed at once
    assert abs((0.5 - robot["position"][2]) - rolled) < 0.004
    left, right = encoder_line(output)
    turned = SPEED * (4.992 - 2.016) * RESOLUTION
    assert abs(left - turned) < 0.01 * turned and abs(right - 100 - turned) < 0.01 * turned


def test_a_kinematic_robot_stops_at_a_wall_and_negative_encoder_noise_keeps_the_encoders_still():
    data, output = run("dw_wall.wbt")
    robot = data["robots"][0]
    # The wall's near face is at z = 0.21; the robot's bounding cylinder has a radius of 0.037.
    assert math.isclose(robot["position"][2], 0.21 + 0.037, abs_tol=0.003)
    assert encoder_line(output) == (0.0, 100.0)


def test_webots_7_epuck_library_name_drives_through_the_differential_wheels_api():
    data, output = run("epuck7.wbt")
    robot = data["robots"][0]
    # wbtc's E-puck (wheel radius 0.02 m) without Physics: Webots' kinematic motor rule ramps its wheels
    # at their maxTorque 10 N·m read as 10 rad/s² (acceleration -1), 0.32 rad/s a step up to speed.
    assert math.isclose(0.5 - robot["position"][2], ramped_angle(157, 10.0) * 0.02, abs_tol=1e-6)
    left, _ = encoder_line(output)
    assert math.isclose(left, SPEED * (4.992 - 2.016) * RESOLUTION, abs_tol=0.01)
    result, _ = compile_world(WORLDS / "epuck7.wbt")
    names = [d.name for d in result.table.robots[0].devices]
    assert ["gs0", "gs1", "gs2"] == [n for n in names if n.startswith("gs")]


def test_a_supervisor_node_is_a_robot_with_supervisor_rights():
    result, _ = compile_world(WORLDS / "supervisor7.wbt")
    referee = result.table.robots[1]
    assert referee.supervisor and [d.type for d in referee.devices] == ["Emitter"]
    _, output = run("supervisor7.wbt", "3")
    # The packet sent after the step ending at 0.992 s arrives with the next one (1.024 s); the robot
    # then drives from that step on: 61 steps by 2.976 s.
    assert "[e-puck] got b'go' at 1.024 s" in output
    line = next(x for x in output.splitlines() if "e-puck at z" in x)
    assert math.isclose(float(line.split()[-1]), 0.5 - ramped_angle(61) * RADIUS, abs_tol=1e-5)


def test_what_was_converted_is_said():
    result = CliRunner().invoke(app, ["check", str(WORLDS / "supervisor7.wbt")])
    assert result.exit_code == 0, result.output
    assert ("warning: Supervisor is an old node type (before R2018b): Webots reads it as a Robot with "
            "supervisor TRUE") in result.output
    assert ('warning: DifferentialWheels robot "e-puck" runs in kinematics mode: its wheels turn on hinges '
            'with motors "left wheel motor"/"right wheel motor"') in result.output
