"""wbtc's UR5e: Webots' device names, the arm's published kinematics and masses, motors that hold it."""

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/universal_robots/protos/UR5e.proto"
WorldInfo { basicTimeStep 16 }
UR5e {
  controller "<none>"
  toolSlot [ Solid { name "tool" } ]
}
"""
JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]


@pytest.fixture
def sim(tmp_path):
    simulation = simulation_of(tmp_path, WORLD, "ur5e.wbt")
    yield simulation
    simulation.close()


def test_devices_masses_and_the_tool_at_zero_angles(sim):
    entry = sim.table.robots[0]
    names = [d.name for d in entry.devices]
    assert names == [n for j in JOINTS for n in (j, f"{j}_sensor")]
    model = sim.model
    links = ["shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"]
    masses = [model.body_mass[model.body(f"UR5e/{link}").id] for link in links]
    assert masses == pytest.approx([3.761, 8.058, 2.846, 1.37, 1.3, 0.365])
    # Zero angles: the arm lies along +x, a2 + a3 = 0.425 + 0.392 m out, the wrists' offsets to the side
    # (0.138 - 0.131 + 0.127 + 0.1 m) and down (0.163 - 0.1 m).
    tool = sim.data.xpos[model.body("UR5e/tool").id]
    assert tool == pytest.approx([0.817, 0.234, 0.063], abs=1e-6)


def test_motors_hold_the_horizontal_arm_and_reach_their_targets(sim):
    model = sim.model
    tool = model.body("UR5e/tool").id
    start = sim.data.xpos[tool].copy()
    for _ in range(60):  # untouched motors hold their joints against gravity (about 50 N m at the shoulder)
        sim.step()
    assert np.linalg.norm(sim.data.xpos[tool] - start) < 0.005
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    robot.motors[tags["shoulder_lift_joint"]].apply("setPosition", (-np.pi / 2,), sim.time_ms)
    for _ in range(120):  # 1.9 s: a quarter turn at up to 3.14 rad/s
        sim.step()
    joint = model.joint(robot.entry.devices[tags["shoulder_lift_joint"]].joint)
    assert sim.data.qpos[joint.qposadr[0]] == pytest.approx(-np.pi / 2, abs=0.01)
    # Lifted a quarter turn about +y (negative: upwards), the arm points straight up from the shoulder.
    assert sim.data.xpos[tool][2] == pytest.approx(0.163 + 0.817, abs=0.01)
    mujoco.mj_forward(model, sim.data)
