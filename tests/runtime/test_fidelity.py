"""Fidelity checks a Webots user can do by hand: speeds, turn rates, sensor values, IMU yaw, motors."""

import csv
import json
import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).parent / "fixtures"


def run_world(name: str, *args: str) -> tuple[dict, list[str]]:
    """`wbtc run --json` on a fixture world: the JSON object and the controllers' output lines."""
    result = CliRunner().invoke(app, ["run", str(FIXTURES / name), "--json", "--headless", *args])
    assert result.exit_code == 0, result.output
    lines = result.stdout.strip().splitlines()
    return json.loads(lines[-1]), lines[:-1]


def printed(lines: list[str], key: str) -> float:
    """The number a controller printed after `key`."""
    for line in lines:
        words = line.split()
        if len(words) == 3 and words[1] == key:
            return float(words[2])
    raise AssertionError(f"{key} not printed: {lines}")


def test_epuck_full_speed_for_5_s_travels_0_628_m():
    data, _ = run_world("open_floor.wbt", "--duration", "5")
    robot = data["robots"][0]
    assert data["sim_time"] == pytest.approx(5.0)
    assert robot["position"][0] == pytest.approx(6.28 * 0.02 * 5, rel=0.02)
    assert abs(robot["position"][1]) < 0.005


def test_epuck_spins_at_wheel_speed_times_radius_over_axle(tmp_path):
    trace = tmp_path / "spin.csv"
    run_world("spin.wbt", "--duration", "3", "--trace", str(trace))
    rows = list(csv.DictReader(trace.open()))
    yaw = {round(float(r["time"]), 3): float(r["angle"]) * math.copysign(1, float(r["axis_z"])) for r in rows}
    turned = math.remainder(yaw[2.0] - yaw[1.0], 2 * math.pi)
    assert abs(turned) == pytest.approx(2 * 2 * 0.02 / 0.052, rel=0.03)
    assert turned < 0  # left wheel forward, right backward: a clockwise (right) turn


@pytest.fixture(scope="module")
def wall_sim():
    result, _ = compile_world(FIXTURES / "wall.wbt")
    return result


@pytest.mark.parametrize(("gap", "expected"), [(0.02, 383.84), (0.03, 234.93), (0.05, 120.0)])
def test_ps0_reads_the_lookup_table_in_front_of_a_white_wall(wall_sim, gap, expected):
    sim = Simulation(wall_sim, noise=False)
    ps0 = next(s for s in sim.robots[0].sensors.values() if s.entry.name == "ps0")
    pos, mat = ps0.frame(sim)
    ray = mat[:, 0]
    wall_face = 0.09
    # Slide the robot along x so ps0's ray meets the wall after `gap` metres.
    sim.data.qpos[0] += (wall_face - pos[0]) - gap * ray[0]
    mujoco.mj_forward(sim.model, sim.data)
    assert ps0.sample(sim) == pytest.approx(expected, rel=0.05)


def test_ps0_reads_about_67_with_nothing_in_range(wall_sim):
    sim = Simulation(wall_sim, noise=False)
    sim.data.qpos[0] -= 0.5
    mujoco.mj_forward(sim.model, sim.data)
    ps0 = next(s for s in sim.robots[0].sensors.values() if s.entry.name == "ps0")
    assert ps0.sample(sim) == pytest.approx(67.19, abs=0.01)
    noisy = Simulation(wall_sim, seed=1)
    noisy.data.qpos[0] -= 0.5
    mujoco.mj_forward(noisy.model, noisy.data)
    ps0 = next(s for s in noisy.robots[0].sensors.values() if s.entry.name == "ps0")
    values = [ps0.sample(noisy) for _ in range(200)]
    assert np.mean(values) == pytest.approx(67.19, abs=1.0)
    assert 1.0 < np.std(values) < 5.0  # the table's 4.9 % noise


def test_generic_sensor_default_table_reads_1000_and_nan_first():
    _, lines = run_world("open_floor.wbt", "--duration", "1")
    assert "[e-puck] before nan" in lines
    assert printed(lines, "generic") == 1000.0


def test_imu_yaw_after_a_point_turn_matches_the_body(tmp_path):
    trace = tmp_path / "turn.csv"
    data, lines = run_world("turn.wbt", "--duration", "4", "--trace", str(trace))
    axis_angle = data["robots"][0]["rotation"]
    true_yaw = axis_angle[3] * math.copysign(1, axis_angle[2])
    imu_yaw = printed(lines, "yaw")
    assert abs(math.remainder(imu_yaw - true_yaw, 2 * math.pi)) < math.radians(0.5)
    # The controller stops at 90 degrees; the stop itself adds a few degrees of momentum.
    assert math.remainder(imu_yaw - 0.3, 2 * math.pi) == pytest.approx(math.pi / 2, abs=math.radians(8))


def test_position_control_reaches_10_rad_at_max_velocity_and_untouched_motor_holds():
    _, lines = run_world("position.wbt", "--duration", "5")
    assert printed(lines, "left") == pytest.approx(10.0, abs=0.01)
    # Speeds are estimated from a sensor with a 0.00628 rad resolution over 16 ms steps: ±0.3925 rad/s.
    quantum = 0.00628 / 0.016
    assert 6.28 - quantum <= printed(lines, "fastest") <= 6.28 + quantum
    assert printed(lines, "right") == pytest.approx(0.0, abs=0.00628)
