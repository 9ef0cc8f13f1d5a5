"""wbtc's UR3e and UR10e: Webots' devices in order, limits, kinematic chain and masses; motors that hold the arm."""

from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]
LINKS = ["shoulder_link", "upper_arm_link", "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"]
TWO_PI, PI = 6.28318530718, 3.14159265359


@dataclass(frozen=True)
class Arm:
    name: str
    chain: list  # per joint: (anchor = endPoint translation, axis, endPoint rotation about y in rad)
    tool: tuple  # the toolSlot Pose's translation in wrist_3_link
    zero: tuple  # the tool slot at zero angles, worked out by hand below
    masses: list  # the six links
    base: float  # the base's mass without staticBase
    torques: list


# Webots' UR3e.proto and UR10e.proto (R2023b, the newest stored): hinge anchors (each equal to its
# endPoint's translation), axes, the endPoint rotations 0 1 0 1.570796 of upper_arm_link and
# wrist_1_link, the tool slot's translation, link masses, the base's mass and the motors' maxTorque.
UR3E = Arm("UR3e",
           [((0, 0, 0.152), (0, 0, 1), 0), ((0, 0.12, 0), (0, 1, 0), 1.570796),
            ((0, -0.093, 0.244), (0, 1, 0), 0), ((0, 0, 0.213), (0, 1, 0), 1.570796),
            ((0, 0.104, 0), (0, 0, 1), 0), ((0, 0, 0.085), (0, 1, 0), 0)],
           (0, 0.09, 0),
           # x = 0.244 + 0.213, y = 0.12 - 0.093 + 0.104 + 0.09, z = 0.152 - 0.085 (the wrist is turned over).
           (0.457, 0.221, 0.067),
           [1.98, 3.4445, 1.437, 0.871, 0.805, 0.261], 2, [330, 330, 150, 54, 54, 54])
UR10E = Arm("UR10e",
            [((0, 0, 0.181), (0, 0, 1), 0), ((0, 0.176, 0), (0, 1, 0), 1.570796),
             ((0, -0.137, 0.613), (0, 1, 0), 0), ((0, 0, 0.571), (0, 1, 0), 1.570796),
             ((0, 0.135, 0), (0, 0, 1), 0), ((0, 0, 0.12), (0, 1, 0), 0)],
            (0, 0.12, 0),
            # x = 0.613 + 0.571, y = 0.176 - 0.137 + 0.135 + 0.12, z = 0.181 - 0.12.
            (1.184, 0.294, 0.061),
            [7.369, 13.051, 3.989, 2.1, 1.98, 0.615], 4, [330, 330, 150, 54, 54, 54])
ARMS = [UR3E, UR10E]


def _world(arm: Arm, extra: str = "") -> str:
    return (f'#VRML_SIM R2025a utf8\nEXTERNPROTO "webots://projects/robots/universal_robots/protos/{arm.name}.proto"\n'
            f'WorldInfo {{ basicTimeStep 16 }}\n{arm.name} {{\n  controller "<none>"\n{extra}'
            '  toolSlot [ Solid { name "tool" } ]\n}\n')


def _rotation(axis, angle: float) -> np.ndarray:
    x, y, z = axis
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]], dtype=float)
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def _tool(arm: Arm, angles) -> np.ndarray:
    """The tool slot's origin by forward kinematics of Webots' numbers (the base at the origin)."""
    position, frame = np.zeros(3), np.eye(3)
    for (anchor, axis, pitch), angle in zip(arm.chain, angles, strict=True):
        position = position + frame @ np.array(anchor, dtype=float)
        frame = frame @ _rotation(axis, angle) @ _rotation((0, 1, 0), pitch)
    return position + frame @ np.array(arm.tool, dtype=float)


@pytest.fixture(params=ARMS, ids=lambda arm: arm.name)
def arm_sim(request, tmp_path: Path):
    arm = request.param
    simulation = simulation_of(tmp_path, _world(arm), f"{arm.name}.wbt")
    yield arm, simulation
    simulation.close()


def test_devices_in_webots_order_and_their_limits(arm_sim):
    arm, sim = arm_sim
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == [n for j in JOINTS for n in (j, f"{j}_sensor")]
    devices = {d.name: d for d in entry.devices}
    speeds = [3.14, 3.14, 3.14, 6.28, 6.28, 6.28]
    ranges = [TWO_PI, TWO_PI, PI, TWO_PI, TWO_PI, TWO_PI]
    for joint, speed, limit, torque in zip(JOINTS, speeds, ranges, arm.torques, strict=True):
        fields = devices[joint].fields
        assert (fields["minPosition"], fields["maxPosition"], fields["maxVelocity"], fields["maxTorque"]) == (
            -limit, limit, speed, torque), joint
        assert devices[f"{joint}_sensor"].type == "PositionSensor"


def test_link_masses(arm_sim, tmp_path: Path):
    arm, sim = arm_sim
    model = sim.model
    masses = [model.body_mass[model.body(f"{arm.name}/{link}").id] for link in LINKS]
    assert masses == pytest.approx(arm.masses)
    free = simulation_of(tmp_path, _world(arm, "  staticBase FALSE\n"), "free.wbt")
    try:
        assert free.model.body_mass[free.model.body(arm.name).id] == pytest.approx(arm.base)
    finally:
        free.close()


def test_the_tool_slot_follows_webots_kinematics(arm_sim):
    arm, sim = arm_sim
    model, data = sim.model, sim.data
    tool = model.body(f"{arm.name}/tool").id
    assert _tool(arm, [0] * 6) == pytest.approx(arm.zero, abs=1e-5)
    assert data.xpos[tool] == pytest.approx(arm.zero, abs=1e-5)
    angles = [0.3, -0.8, 1.1, -0.5, 0.7, 1.2]
    entry = sim.table.robots[0]
    motors = {d.name: d for d in entry.devices}
    for joint, angle in zip(JOINTS, angles, strict=True):
        data.qpos[model.joint(motors[joint].joint).qposadr[0]] = angle
    mujoco.mj_forward(model, data)
    assert data.xpos[tool] == pytest.approx(_tool(arm, angles), abs=1e-5)


def test_motors_hold_the_default_pose_for_a_second(arm_sim):
    arm, sim = arm_sim
    tool = sim.model.body(f"{arm.name}/tool").id
    start = sim.data.xpos[tool].copy()
    while sim.time < 1.0:  # untouched motors hold the horizontal arm against gravity
        sim.step()
    assert np.linalg.norm(sim.data.xpos[tool] - start) < 1e-3
    assert abs(sim.data.qpos).max() < 1e-3
