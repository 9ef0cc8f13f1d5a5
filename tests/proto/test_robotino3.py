"""wbtc's Festo Robotino 3 and its platform: Webots' device names and order, masses, omni-wheel driving."""

from pathlib import Path

import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/festo/robotino3/protos/Robotino3.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 10 10 }
Robotino3 {
  controller "<none>"
  cameraSlot [
    DistanceSensor { translation 0 -0.2 0.23 rotation 0 0 -1 1.5708 name "ds" }
  ]
}
"""
WHEELS = [n for i in range(3) for n in (f"wheel{i}_joint", f"wheel{i}_joint_sensor")]
DEVICES = WHEELS + ["ds", "accelerometer", "inertial unit", "gyro", "compass"] + [f"ir{i}" for i in range(1, 10)]


def _sim(tmp_path: Path, world: str = WORLD) -> Simulation:
    return simulation_of(tmp_path, world, "robotino3.wbt")


def _drive(sim: Simulation, speeds: tuple[float, float, float], steps: int) -> tuple[np.ndarray, float]:
    """Settles the robot, turns its wheels at `speeds` (rad/s) for `steps` steps; its move and turn."""
    body = sim.model.body(sim.table.robots[0].body).id
    for _ in range(20):
        sim.step()
    start = sim.data.xpos[body].copy()
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    for i, speed in enumerate(speeds):
        motor = robot.motors[tags[f"wheel{i}_joint"]]
        motor.apply("setPosition", (float("inf"),), sim.time_ms)
        motor.apply("setVelocity", (speed,), sim.time_ms)
    for _ in range(steps):
        sim.step()
    yaw = float(np.arctan2(sim.data.xmat[body][3], sim.data.xmat[body][0]))
    return sim.data.xpos[body] - start, yaw


def test_devices_in_webots_order_and_the_mass(tmp_path):
    sim = _sim(tmp_path)
    try:
        entry = sim.table.robots[0]
        assert [d.name for d in entry.devices] == DEVICES
        devices = {d.name: d for d in entry.devices}
        assert devices["wheel1_joint"].fields["maxVelocity"] == 137.46
        table = devices["ir4"].fields["lookupTable"]
        assert table[5] == pytest.approx([0.03, 3.03, 0.1])  # GP2Y0A41SK0F's peak
        model = sim.model
        assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(20 + 3 * 1)
        # The camera slot's frame is turned a quarter turn: the world's sensor ends up 0.2 m ahead.
        ds = model.site(devices["ds"].site).id
        assert sim.data.site_xpos[ds] == pytest.approx([0.2, 0, 0.23], abs=1e-4)
        ir1 = model.site(devices["ir1"].site).id
        assert sim.data.site_xpos[ir1] == pytest.approx([0.2264, 0, 0.0566], abs=1e-4)
        assert sim.data.site_xmat[ir1][0] == pytest.approx(1, abs=1e-3)  # looks forward
    finally:
        sim.close()


def test_the_long_range_sensor_model_changes_the_tables(tmp_path):
    sim = _sim(tmp_path, WORLD.replace('controller "<none>"',
                                       'controller "<none>" infraredSensorModel "SharpGP2Y0A02YK0F"'))
    try:
        devices = {d.name: d for d in sim.table.robots[0].devices}
        table = devices["ir9"].fields["lookupTable"]
        assert len(table) == 17 and table[2] == pytest.approx([0.015, 2.75, 0.1])
    finally:
        sim.close()


@pytest.mark.parametrize(("speeds", "velocity"), [
    ((0.0, -5.0, 5.0), (5 * 0.063 / np.cos(np.pi / 6), 0.0)),  # front wheels opposite: forwards
    ((4.0, -2.0, -2.0), (0.0, 4 * 0.063)),  # back wheel one way, front ones half the other: to the left
])
def test_three_wheels_translate_it_without_turning(tmp_path, speeds, velocity):
    sim = _sim(tmp_path)
    try:
        moved, yaw = _drive(sim, speeds, 125)  # 2 s
        assert moved[:2] == pytest.approx(2 * np.array(velocity), abs=0.04)
        assert abs(yaw) < 0.02
    finally:
        sim.close()


def test_all_wheels_alike_spin_it_on_the_spot(tmp_path):
    sim = _sim(tmp_path)
    try:
        moved, yaw = _drive(sim, (3.0, 3.0, 3.0), 62)  # 1 s at 3 * 0.063 / 0.1826 = 1.035 rad/s, clockwise
        assert yaw == pytest.approx(-1.035, abs=0.05)
        assert np.linalg.norm(moved[:2]) < 0.005
    finally:
        sim.close()


def test_platform_on_the_robot(tmp_path):
    sim = _sim(tmp_path, WORLD.replace("cameraSlot", "bodySlot [ Robotino3Platform { height 0.3 } ]\n  cameraSlot"))
    try:
        model = sim.model
        platform = model.body("Robotino 3/Platform for Robotino 3").id
        # Webots' default density: the 0.408 m table 15 mm thick and the post (section 3.42e-3 m²).
        assert model.body_mass[platform] == pytest.approx(1000 * (np.pi * 0.204 ** 2 * 0.015 + 0.0034203 * 0.3),
                                                          rel=1e-3)
        for _ in range(20):
            sim.step()
        top = sim.data.xpos[platform][2] + 0.3 + 0.006553 + 0.0075  # post's foot, post, table's half thickness
        assert top == pytest.approx(0.0035 + 0.28 + 0.3 + 0.014, abs=0.002)
    finally:
        sim.close()
