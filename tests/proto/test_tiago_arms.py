"""wbtc's TIAGo Iron, Steel and TIAGo++ and their arms and gripper: Webots' devices, masses, limits, kinematics."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo { basicTimeStep 16 }\nFloor { size 20 20 }\n"
TORSO = np.array([-0.054, 0, 0.095 + 0.193 + 0.6])  # TiagoBase + TiagoBody + the lift's endPoint, in the world
RADIUS = 0.0985
ACCELERATION = 5.0762  # the wheel motors' rad/s²
BASE = ["accelerometer", "inertial unit", "gyro", "base_cover_link", "base_sonar_03_link", "base_sonar_02_link",
        "base_sonar_01_link", "wheel_right_joint", "wheel_right_joint_sensor", "wheel_left_joint",
        "wheel_left_joint_sensor"]
HEAD = ["head_1_joint", "head_1_joint_sensor", "head_2_joint", "head_2_joint_sensor"]
LIFT = ["torso_lift_joint", "torso_lift_joint_sensor"]
ARM_MASSES = [6.93198, 1.563428, 1.800397, 2.343502, 1.432697, 1.655819, 0.370063, 0.234, 0.1]  # shoulder to wrist
GRIPPER_MASS = 1 + 2 * 0.10998
BODY_MASS = 14.0136 + 6.93198 + 0.6222 + 0.66123
BASE_MASS = 28.26649 + 0.25821 + 2 * 1.82362 + 4 * (0.051448 + 0.088558)

# Webots' numbers for each arm, shoulder outwards: [axis, anchor, written position, endPoint translation,
# endPoint rotation, (minPosition, maxPosition, maxVelocity, maxTorque)].
FRONT = [
    [(0, 0, 1), (0.025, 0.194, -0.16), 0.071, (0.0251, 0.194, -0.171), (0, 0, 1, 0.01), (0.07, 2.68, 1.95, 43)],
    [(0, -1, 0), (0.125, 0.0195, -0.031), 0, (0.125, 0.018, -0.031), (1, 0, 0, 1.5708), (-1.5, 1.02, 1.95, 43)],
    [(-1, 0, 0), (0.0895, 0, -0.0015), 0, (0.0872, 0, -0.0015), (-0.5774, -0.5773, 0.5773, 2.09446),
     (-3.46, 1.5, 2.35, 26)],
    [(0, 1, 0), (-0.02, -0.027, -0.222), 0, (-0.02, -0.027, -0.222), (-0.5774, -0.5774, -0.5774, 2.0944),
     (-0.32, 2.29, 2.35, 26)],
    [(-1, 0, 0), (-0.162, 0.02, 0.027), 0, (-0.162, 0.02, 0.027), (0, -1, 0, 1.5708), (-2.07, 2.07, 1.95, 3)],
    [(0, 1, 0), (0, 0, 0.15), 0, (0, 0, 0.15), (-0.5774, -0.5774, -0.5774, 2.0944), (-1.39, 1.39, 1.76, 6.6)],
    [(1, 0, 0), (0, 0, 0), 0, (0.055, 0, 0), (0.5774, 0.5774, 0.5774, 2.0944), (-2.07, 2.07, 1.76, 6.6)],
]
RIGHT = [
    [(0, 0, 1), (0.025, -0.194, -0.17), 0, (0.0251, -0.194, -0.171), (0, 0, 1, 1.5708), (-1.11, 1.5, 1.95, 43)],
    [(0, -1, 0), (-0.125, 0.0195, -0.031), 0, (-0.125, 0.018, -0.031), (1, 0, 0, 1.5708), (-1.11, 1.5, 1.95, 43)],
    [(1, 0, 0), (0.0895, 0, -0.0015), 0, (-0.0866, 0, 0), (0.5774, 0.5774, 0.5774, 2.0944), (-0.72, 3.86, 2.35, 26)],
    [(0, -1, 0), (0.02, 0, -0.223), 0, (0.02, -0.026, -0.223), (-0.5774, 0.5774, 0.5774, 2.0944),
     (-0.32, 2.29, 2.35, 26)],
    [(1, 0, 0), (0.163, 0.02, 0.027), 0, (0.163, 0.02, 0.027), (0.7071, 0, 0.7071, 3.1416), (-2.07, 2.07, 1.95, 3)],
    [(0, -1, 0), (0, 0, 0.15), 0, (0, 0, 0.15), (-0.5774, 0.5774, 0.5774, 2.0944), (-1.39, 1.39, 1.76, 6.6)],
    [(-1, 0, 0), (0, 0, 0), 0, (-0.055, 0, 0), (-0.5774, -0.5774, 0.5774, 2.0944), (-2.07, 2.07, 1.76, 6.6)],
]
LEFT = [
    [(0, 0, -1), (0.025, 0.194, -0.16), 0, (0.0251, 0.194, -0.171), (0, 0, 1, 1.5708), (-1.11, 1.5, 1.95, 43)],
    [(0, 1, 0), (0.125, 0.0195, -0.031), 0, (0.125, 0.018, -0.031), (1, 0, 0, 1.5708), (-1.11, 1.5, 1.95, 43)],
    [(1, 0, 0), (0.0895, 0, -0.0015), 0, (0.0872, 0, -0.0015), (-0.5773, 0.5774, 0.5773, -2.0944),
     (-0.72, 3.86, 2.35, 26)],
    [(0, 1, 0), (-0.02, -0.027, -0.222), 0, (-0.02, -0.027, -0.222), (-0.5774, -0.5774, -0.5774, 2.0944),
     (-0.32, 2.29, 2.35, 26)],
    [(1, 0, 0), (-0.162, 0.02, 0.027), 0, (-0.162, 0.02, 0.027), (0, -1, 0, 1.5708), (-2.07, 2.07, 1.95, 3)],
    [(0, -1, 0), (0, 0, 0.15), 0, (0, 0, 0.15), (-0.5774, -0.5774, -0.5774, 2.0944), (-1.39, 1.39, 1.76, 6.6)],
    [(-1, 0, 0), (0, 0, 0), 0, (0.055, 0, 0), (0.5774, 0.5774, 0.5774, 2.0944), (-2.07, 2.07, 1.76, 6.6)],
]
# Torso to shoulder (TiagoBody's slot Pose, then the arm's own translation and rotation), and the wrist
# connector to the gripper's palm (the wrist's Solid, its slot Pose, TiagoGripper's default placement).
MOUNT = {"front": [((-0.037, 0.0388, 0.0224), (0, 0, 1, -1.5708))],
         "right": [((0.05, 0, 0), (0, 0, 1, 3.1416)), ((0.05, 0, 0), (0, 0, 1, 3.14159))],
         "left": [((0, 0, 0), (0, 0, 1, 0))]}
WRIST = {"front": (0, 0, 1, -1.5708), "right": (0, 0, -1, 1.5708), "left": (0, 0, 1, -1.5708)}


def _rotation(axis_angle) -> np.ndarray:
    x, y, z, angle = axis_angle
    k = np.array([x, y, z], dtype=float) / np.linalg.norm([x, y, z])
    skew = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * skew + (1 - np.cos(angle)) * skew @ skew


def _pose(translation, rotation) -> np.ndarray:
    pose = np.eye(4)
    pose[:3, :3], pose[:3, 3] = _rotation(rotation), translation
    return pose


def _palm(arm: str, angles) -> np.ndarray:
    """The gripper palm's world pose from Webots' numbers: each endPoint's written pose, turned about its
    hinge (through the anchor, along the axis, both in the parent's frame) by the angle less the written
    position."""
    pose = _pose(TORSO, (0, 0, 1, 0))
    for step in MOUNT[arm]:
        pose = pose @ _pose(*step)
    for (axis, anchor, written, translation, rotation, _), angle in zip(
            {"front": FRONT, "right": RIGHT, "left": LEFT}[arm], angles, strict=True):
        turn = _pose((0, 0, 0), (*axis, angle - written))
        turn[:3, 3] = np.asarray(anchor) - turn[:3, :3] @ np.asarray(anchor)
        pose = pose @ turn @ _pose(translation, rotation)
    pose = pose @ _pose((0, 0, 0.012725), (-0.5774, -0.5774, -0.5774, 2.0944)) @ _pose((0, 0, 0), WRIST[arm])
    return pose @ _pose((0, 0.016, 0), (0.5774, 0.5774, -0.5774, 2.0944))


def _world(name: str, extra: str = "", wall: str = "") -> str:
    return HEADER + wall + f"{name} {{ controller \"<none>\" {extra}}}\n"


@pytest.fixture
def steel(tmp_path: Path):
    sim = simulation_of(tmp_path, _world("TiagoSteel"), "tiago_steel.wbt")
    yield sim
    sim.close()


@pytest.fixture
def twin(tmp_path: Path):
    sim = simulation_of(tmp_path, _world("Tiago++"), "tiago_pp.wbt")
    yield sim
    sim.close()


def _arm_devices(prefix: str, hand: str) -> list[str]:
    motors = [f"arm_{prefix}{k}_joint" for k in range(1, 8)]
    fingers = [f"{hand}gripper_{side}_{kind}finger_joint" for side in ("left", "right") for kind in ("", "sensor_")]
    return [n for m in motors for n in (m, f"{m}_sensor")] + fingers


def _joint(sim: Simulation, name: str) -> int:
    device = next(d for d in sim.robots[0].entry.devices if d.name == name)
    return sim.model.joint(device.joint).qposadr[0]


def _command(sim: Simulation, name: str, command: str, value: float) -> None:
    robot = sim.robots[0]
    tag = [d.name for d in robot.entry.devices].index(name)
    robot.motors[tag].apply(command, (value,), sim.time_ms)


def _palm_pose(sim: Simulation, body: str) -> np.ndarray:
    pose = np.eye(4)
    index = sim.model.body(body).id
    pose[:3, :3], pose[:3, 3] = sim.data.xmat[index].reshape(3, 3), sim.data.xpos[index]
    return pose


def test_steel_devices_masses_and_limits_are_webots(steel):
    entry = steel.table.robots[0]
    assert [d.name for d in entry.devices] == (LIFT + _arm_devices("", "") + HEAD + ["Hokuyo URG-04LX-UG01"] + BASE)
    model = steel.model
    links = ["TIAGo front arm", "TIAGo front arm(1)"] + [f"arm_{k}_link" for k in range(2, 8)] + ["wrist_ft_tool_link"]
    assert [model.body_mass[model.body(f"TIAGo Steel/{n}").id] for n in links] == pytest.approx(ARM_MASSES)
    assert model.body_mass[model.body("TIAGo Steel/front").id] == pytest.approx(1)
    total = BASE_MASS + BODY_MASS + 0.16 + sum(ARM_MASSES) + GRIPPER_MASS  # 72.77 kg with the Hokuyo
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(total)
    fields = {d.name: d.fields for d in entry.devices}
    for k, (*_, (low, high, speed, torque)) in enumerate(FRONT, start=1):
        motor = fields[f"arm_{k}_joint"]
        assert (motor["minPosition"], motor["maxPosition"]) == pytest.approx((low, high))
        assert (motor["maxVelocity"], motor["maxTorque"]) == pytest.approx((speed, torque))
    for side in ("left", "right"):
        finger = fields[f"gripper_{side}_finger_joint"]
        assert (finger["maxPosition"], finger["maxVelocity"], finger["maxForce"]) == pytest.approx((0.045, 0.05, 16))
    # The arm starts at Webots' written 0.071 rad on its first hinge.
    assert steel.data.qpos[_joint(steel, "arm_1_joint")] == pytest.approx(0.071)


def test_the_steel_tool_is_where_webots_numbers_put_it(steel):
    model, data = steel.model, steel.data
    start = [0.071, 0, 0, 0, 0, 0, 0]
    assert _palm_pose(steel, "TIAGo Steel/front") == pytest.approx(_palm("front", start), abs=2e-4)
    # At Webots' initial pose the arm stretches out level to the right: the palm 0.82 m right of the torso.
    assert data.xpos[model.body("TIAGo Steel/front").id] - TORSO == pytest.approx([0.185, -0.816, -0.18], abs=0.002)
    bent = [1.2, -0.6, -1.5, 1.8, 0.7, -1.0, 1.3]
    for k, angle in enumerate(bent, start=1):
        data.qpos[_joint(steel, f"arm_{k}_joint")] = angle
    mujoco.mj_kinematics(model, data)
    assert _palm_pose(steel, "TIAGo Steel/front") == pytest.approx(_palm("front", bent), abs=2e-4)


def test_tiago_pp_devices_masses_and_its_two_tools(twin):
    entry = twin.table.robots[0]
    expected = (LIFT + _arm_devices("right_", "right_hand_") + _arm_devices("left_", "left_hand_") + HEAD
                + ["Astra rgb", "Astra depth", "Hokuyo URG-04LX-UG01"] + BASE)
    assert [d.name for d in entry.devices] == expected
    model, data = twin.model, twin.data
    total = BASE_MASS + BODY_MASS + 0.16 + 0.19 + 2 * (sum(ARM_MASSES) + GRIPPER_MASS)  # 90.61 kg
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(total)
    fields = {d.name: d.fields for d in entry.devices}
    for prefix, table in (("right", RIGHT), ("left", LEFT)):
        for k, (*_, (low, high, speed, torque)) in enumerate(table, start=1):
            motor = fields[f"arm_{prefix}_{k}_joint"]
            assert (motor["minPosition"], motor["maxPosition"], motor["maxVelocity"], motor["maxTorque"]) == \
                pytest.approx((low, high, speed, torque))
    # At zero both arms stretch out sideways, level, the palms 1.03 m either side of the torso.
    right, left = model.body("TIAGo++/right").id, model.body("TIAGo++/left").id
    assert data.xpos[right] - TORSO == pytest.approx([0.008, -1.025, -0.202], abs=0.002)
    assert data.xpos[left] - TORSO == pytest.approx([0.006, 1.024, -0.202], abs=0.002)
    assert _palm_pose(twin, "TIAGo++/right") == pytest.approx(_palm("right", [0] * 7), abs=2e-4)
    assert _palm_pose(twin, "TIAGo++/left") == pytest.approx(_palm("left", [0] * 7), abs=2e-4)
    bent = [0.8, 1.0, 2.0, 1.5, -1.2, 0.9, -0.5]
    for prefix in ("right", "left"):
        for k, angle in enumerate(bent, start=1):
            data.qpos[_joint(twin, f"arm_{prefix}_{k}_joint")] = angle
    mujoco.mj_kinematics(model, data)
    assert _palm_pose(twin, "TIAGo++/right") == pytest.approx(_palm("right", bent), abs=2e-4)
    assert _palm_pose(twin, "TIAGo++/left") == pytest.approx(_palm("left", bent), abs=2e-4)


def test_the_steel_motors_move_the_arm_and_open_the_gripper(steel):
    model, data = steel.model, steel.data
    target = [1.5, 0.5, -1.0, 1.2, 0.4, 0.6, -0.8]
    for k, angle in enumerate(target, start=1):
        _command(steel, f"arm_{k}_joint", "setPosition", angle)
    for side in ("left", "right"):
        _command(steel, f"gripper_{side}_finger_joint", "setPosition", 0.04)
    for _ in range(160):  # 2.56 s: 1.43 rad at 1.95 rad/s, 4 cm at 5 cm/s
        steel.step()
    for k, angle in enumerate(target, start=1):
        assert data.qpos[_joint(steel, f"arm_{k}_joint")] == pytest.approx(angle, abs=0.02), k
    for side in ("left", "right"):
        assert data.qpos[_joint(steel, f"gripper_{side}_finger_joint")] == pytest.approx(0.04, abs=0.002)
    # The palm sits where Webots' numbers put it, in the torso's frame (the base may rock a little).
    torso_pose = _palm_pose(steel, "TIAGo Steel/torso_lift_link")
    palm = np.linalg.inv(torso_pose) @ _palm_pose(steel, "TIAGo Steel/front")
    expected = np.linalg.inv(_pose(TORSO, (0, 0, 1, 0))) @ _palm("front", [data.qpos[_joint(steel, f"arm_{k}_joint")]
                                                                            for k in range(1, 8)])
    assert palm[:3, 3] == pytest.approx(expected[:3, 3], abs=0.003)
    # Each finger slid 4 cm out along the palm's x, the two in opposite directions.
    fingers = [data.xpos[model.body(f"TIAGo Steel/gripper_{side}_finger_link").id] for side in ("left", "right")]
    assert np.linalg.norm(fingers[0] - fingers[1]) == pytest.approx(0.08, abs=0.002)


@pytest.mark.parametrize("name", ["TiagoIron", "TiagoSteel", "Tiago++"])
def test_both_wheels_drive_the_robot_forwards(tmp_path: Path, name: str):
    sim = simulation_of(tmp_path, _world(name))
    try:
        body = sim.model.body(sim.table.robots[0].body).id
        for _ in range(30):
            sim.step()
        start = sim.data.xpos[body].copy()
        assert start[2] == pytest.approx(RADIUS, abs=0.003)  # the axle one wheel radius up
        omega, seconds = 5.0, 2.0
        for wheel in ("wheel_left_joint", "wheel_right_joint"):
            _command(sim, wheel, "setPosition", float("inf"))
            _command(sim, wheel, "setVelocity", omega)
        for _ in range(round(seconds * 1000 / 16)):
            sim.step()
        moved = sim.data.xpos[body] - start
        # r * omega * t, less the 0.98 s the motors take to reach omega at 5.0762 rad/s²: 0.742 m.
        expected = RADIUS * (omega * seconds - omega**2 / (2 * ACCELERATION))
        assert moved[0] == pytest.approx(expected, rel=0.02)
        assert abs(moved[1]) < 0.01
    finally:
        sim.close()
