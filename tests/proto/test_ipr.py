"""wbtc's Neuronics IPR HD6M180: Webots' devices in order, joint limits and masses, joints reaching their targets."""

from pathlib import Path

import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/neuronics/ipr/protos/IprHd6m180.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 4 4 }
IprHd6m180 { controller "<none>" }
"""
MOTORS = ["base", "upperarm", "forearm", "wrist", "rotational_wrist"]
LIMITS = {"base": (0, 6.0335), "upperarm": (-2.44342, 0), "forearm": (0, 4.2149), "wrist": (-4.0491, 0),
          "rotational_wrist": (-5.79789, 0), "left_gripper": (-1.22171, 0), "right_gripper": (0, 1.22171)}
SPEEDS = {"base": 2.20894, "upperarm": 1.1908, "forearm": 1.38927, "wrist": 2.20894, "rotational_wrist": 2.20894,
          "left_gripper": 2.20894, "right_gripper": 2.20894}


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "ipr.wbt")
    yield simulation
    simulation.close()


def test_devices_in_webots_order_limits_and_masses(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == [n for m in MOTORS for n in (m, f"{m}_sensor")] + [
        "left_gripper", "left_gripper_sensor", "ds0", "ds1", "ds2", "ds3", "ts0", "ts1", "ds4",
        "right_gripper", "right_gripper_sensor", "ds5", "ds6", "ds7", "ds8", "ts2", "ts3"]
    devices = {d.name: d for d in entry.devices}
    for name, (low, high) in LIMITS.items():
        fields = devices[name].fields
        assert (fields["minPosition"], fields["maxPosition"], fields["maxVelocity"], fields["maxTorque"]) == (
            low, high, SPEEDS[name], 20)
    assert devices["ts0"].fields["type"] == "force" and devices["ds0"].fields["type"] == "infra-red"
    model = sim.model
    # Base, upper arm, forearm, wrist, hand, two fingers, four 50 g touch pads; the pedestal is fixed.
    total = 1.25 + 0.19 + 0.8 + 0.92 + 0.4 + 2 * 0.035 + 4 * 0.05
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(total, abs=1e-6)
    # The base joint 0.2035 m up, the forearm's joint 0.19 m along the upper arm.
    assert sim.data.xpos[model.body("IPR/base").id] == pytest.approx([0, 0, 0.2035], abs=1e-9)


def test_motors_hold_the_folded_arm_and_reach_their_targets(sim):
    for _ in range(60):  # untouched motors hold their joints against gravity
        sim.step()
    assert abs(sim.data.qpos).max() < 0.002
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    targets = {"base": 1.0, "upperarm": -1.0, "forearm": 1.5, "wrist": -1.0, "rotational_wrist": -2.0,
               "left_gripper": -0.8, "right_gripper": 0.8}
    for name, value in targets.items():
        robot.motors[tags[name]].apply("setPosition", (value,), sim.time_ms)
    for _ in range(150):  # 2.4 s: 1.5 rad at 1.38927 rad/s, and settling
        sim.step()
    for name, value in targets.items():
        joint = sim.model.joint(robot.entry.devices[tags[name]].joint)
        assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(value, abs=0.01), name
    forearm = robot.motors[tags["forearm"]]
    forearm.apply("setPosition", (9.0,), sim.time_ms)  # beyond maxPosition: Webots clamps the target
    assert forearm.target == pytest.approx(4.2149)
