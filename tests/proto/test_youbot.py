"""wbtc's KUKA youBot: Webots' device names and limits, an arm that reaches its targets, mecanum wheels."""

from pathlib import Path

import numpy as np
import pytest
from conftest import CORPUS, simulation_of

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/kuka/youbot/protos/Youbot.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 10 10 }
Youbot { controller "<none>" }
"""
ARM = [f"arm{i}" for i in range(1, 6)]
WHEELS = [f"wheel{i}" for i in range(1, 5)]
LIMITS = {"arm1": (-2.9496, 2.9496), "arm2": (-1.13446, 1.5708), "arm3": (-2.63545, 2.54818),
          "arm4": (-1.78024, 1.78024), "arm5": (-2.92343, 2.92343), "finger::left": (0.0, 0.025),
          "finger::right": (0.0, 0.025)}


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "youbot.wbt")
    yield simulation
    simulation.close()


def _drive(sim: Simulation, speeds: dict[str, float], steps: int) -> None:
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    for name, value in speeds.items():
        motor = robot.motors[tags[name]]
        if name.startswith("wheel"):
            motor.apply("setPosition", (float("inf"),), sim.time_ms)
            motor.apply("setVelocity", (value,), sim.time_ms)
        else:
            motor.apply("setPosition", (value,), sim.time_ms)
    for _ in range(steps):
        sim.step()


def test_devices_limits_and_masses(sim):
    entry = sim.table.robots[0]
    names = [d.name for d in entry.devices]
    fingers = ["finger::left", "finger::leftsensor", "finger::right", "finger::rightsensor"]
    assert names == [n for a in ARM for n in (a, f"{a}sensor")] + fingers + [
        n for w in WHEELS for n in (w, f"{w}sensor")]
    devices = {d.name: d for d in entry.devices}
    for name, (low, high) in LIMITS.items():
        assert (devices[name].fields["minPosition"], devices[name].fields["maxPosition"]) == (low, high)
    assert [devices[a].fields["maxTorque"] for a in ARM] == [9.5, 9.5, 6, 2, 1]
    assert all(devices[a].fields["maxVelocity"] == 1.5708 for a in ARM)
    assert all(devices[w].fields["maxVelocity"] == 14.81 for w in WHEELS)
    # Base 22, turret and links 0.845 + 2.412 + 1.155 + 0.934 + 0.877 + 0.251, fingers 2 x 0.03,
    # four 0.4 kg wheels (hub and rollers), the 0.5 kg plate.
    model = sim.model
    total = 22 + 0.845 + 2.412 + 1.155 + 0.934 + 0.877 + 0.251 + 0.06 + 4 * 0.4 + 0.5
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(total, abs=1e-6)


def test_the_arm_reaches_a_commanded_pose(sim):
    pose = {"arm1": 0.5, "arm2": 0.6, "arm3": -1.0, "arm4": 0.8, "arm5": -0.4, "finger::left": 0.02,
            "finger::right": 0.02}
    _drive(sim, pose, 150)  # 2.4 s: one radian at 1.5708 rad/s, and settling
    robot = sim.robots[0]
    for device in robot.entry.devices:
        if device.name in pose:
            joint = sim.model.joint(device.joint)
            assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(pose[device.name], abs=0.01), device.name


def test_four_wheels_forward_roll_it_forward_and_crosswise_slide_it_sideways(sim):
    body = sim.robots[0].body
    for _ in range(30):  # settle on the wheels: the frame 0.055 m above the wheels' centres
        sim.step()
    start = sim.data.xpos[body].copy()
    assert start[2] == pytest.approx(0.055 + 0.05, abs=0.003)
    _drive(sim, dict.fromkeys(WHEELS, 4.0), 125)  # 2 s at 4 rad/s x 0.05 m: 0.4 m, less the start
    moved = sim.data.xpos[body] - start
    assert moved[0] == pytest.approx(0.4, abs=0.03)
    assert abs(moved[1]) < 0.01
    # Mecanum rollers: wheel1 and wheel4 forwards, wheel2 and wheel3 backwards strafe to the left.
    start = sim.data.xpos[body].copy()
    _drive(sim, {"wheel1": 4.0, "wheel2": -4.0, "wheel3": -4.0, "wheel4": 4.0}, 125)
    moved = sim.data.xpos[body] - start
    assert moved[1] == pytest.approx(0.4, abs=0.05)
    assert abs(moved[0]) < 0.05


def test_an_r2020a_world_stands_it_up_with_the_old_default_rotation():
    world = CORPUS / "projects/Thequantums__ECE183DB_final_project/protos/Hippo/worlds/youbot.wbt"
    if not world.exists():
        pytest.skip("the shared corpus is missing")
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    try:
        for _ in range(30):
            sim.step()
        body = sim.robots[0].body
        up = sim.data.xmat[body].reshape(3, 3)[:, 2]
        assert up == pytest.approx([0, 0, 1], abs=1e-3)
        assert sim.data.xpos[body][2] == pytest.approx(0.105, abs=0.003)
    finally:
        sim.close()
    assert np.isfinite(sim.data.qpos).all()
