"""wbtc's NAO: Webots' devices and their order, masses, kinematics, standing, the head motor, NUE worlds."""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "https://raw.githubusercontent.com/cyberbotics/webots/R2025a/projects/robots/softbank/nao/protos/Nao.proto"
WorldInfo { basicTimeStep 20 }
Floor { size 4 4 }
Nao { controller "<none>" %s }
"""
STEPS_PER_SECOND = 50  # basicTimeStep 20 ms


def _pairs(names: list[str]) -> list[str]:
    """Each motor followed by its PositionSensor ("HeadYaw", "HeadYawS", ...)."""
    return [n for name in names for n in (name, f"{name}S")]


def _arm(side: str, fingers: bool = True) -> list[str]:
    """An arm's devices in Webots' order: shoulder, elbow, then wrist and fingers of the 25-motor NAO."""
    joints = ["ShoulderPitch", "ShoulderRoll", "ElbowYaw", "ElbowRoll"]
    if fingers:
        joints += ["WristYaw"] + [f"Phalanx{i}" for i in range(1, 9)]
    return _pairs([side + j for j in joints])


def _leg(side: str) -> list[str]:
    """A leg's devices in Webots' order: six motors, then the foot's force sensor, LED and bumpers (outer first)."""
    outer, inner = ("Right", "Left") if side == "R" else ("Left", "Right")
    return (_pairs([side + j for j in ("HipYawPitch", "HipRoll", "HipPitch", "KneePitch", "AnklePitch", "AnkleRoll")])
            + [f"{side}Fsr", f"{side}Foot/Led", f"{side}Foot/Bumper/{outer}", f"{side}Foot/Bumper/{inner}"])


TORSO = ["ChestBoard/Led", "gps", "receiver", "emitter", "super_emitter", "accelerometer", "gyro", "inertial unit",
         "Sonar/Right", "Sonar/Left"]
HEAD = _pairs(["HeadYaw", "HeadPitch"]) + ["CameraTop", "CameraBottom", "Face/Led/Right", "Face/Led/Left",
                                          "Ears/Led/Right", "Ears/Led/Left"]
DEVICES = TORSO + HEAD + _arm("R") + _arm("L") + _leg("R") + _leg("L")
# Webots' V5 masses: torso, head, per arm shoulder, elbow, forearm, hand, per leg hip, pelvis, thigh, tibia, ankle,
# foot and force sensor, and 16 finger links of density 200 (capsules of radius 0.0055 m, 0.01 m long).
FINGER = 200 * (math.pi * 0.0055 ** 2 * 0.01 + 4 / 3 * math.pi * 0.0055 ** 3)
MASS_V5 = (1.04956 + 0.68375 + 2 * (0.25081 + 0.06483 + 0.07761 + 0.18533)
           + 2 * (0.06981 + 0.14053 + 0.38968 + 0.30142 + 0.13416 + 0.09127 + 0.08057) + 16 * FINGER)
# The 21-motor V4: V4 masses, and forearm and hand in one piece (0.18405 kg) with no fingers.
MASS_V4_21 = (1.04956 + 0.66975 + 2 * (0.23281 + 0.06483 + 0.18405)
              + 2 * (0.06981 + 0.13053 + 0.38968 + 0.29142 + 0.13416 + 0.08127 + 0.08057))


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD % "", "nao.wbt")
    yield simulation
    simulation.close()


def _tags(sim) -> dict[str, int]:
    return {d.name: tag for tag, d in enumerate(sim.robots[0].entry.devices)}


def _run(sim, seconds: float) -> None:
    for _ in range(round(seconds * STEPS_PER_SECOND)):
        sim.step()


def test_devices_in_webots_order(sim):
    # A Hinge2Joint's device and device2 come before its endPoint's devices (WbHinge2Joint::devices).
    assert [d.name for d in sim.table.robots[0].devices] == DEVICES


def test_devices_their_parameters_and_the_mass(sim):
    entry = sim.table.robots[0]
    names = [d.name for d in entry.devices]
    assert sorted(names) == sorted(DEVICES) and len(DEVICES) == 104
    # Every device but the two Hinge2Joints' second motors and sensors is where Webots has it.
    second = {"HeadPitch", "HeadPitchS", "RShoulderRoll", "RShoulderRollS", "LShoulderRoll", "LShoulderRollS"}
    assert [n for n in names if n not in second] == [n for n in DEVICES if n not in second]
    devices = {d.name: d for d in entry.devices}
    assert [devices[n].type for n in ("HeadYaw", "HeadYawS", "CameraTop", "Sonar/Left", "RFsr", "LFoot/Bumper/Left",
                                      "inertial unit", "gps", "Ears/Led/Left")] == [
        "RotationalMotor", "PositionSensor", "Camera", "DistanceSensor", "TouchSensor", "TouchSensor", "InertialUnit",
        "GPS", "LED"]
    # [maxVelocity, minPosition, maxPosition, maxTorque] as Webots gives them (V5).
    motors = {"HeadYaw": (8.26797, -2.08567, 2.08567, 4), "HeadPitch": (7.19407, -0.671952, 0.514872, 5),
              "RShoulderRoll": (7.19407, -1.32645, 0.314159, 5), "LShoulderRoll": (7.19407, -0.314159, 1.32645, 5),
              "RElbowRoll": (7.19407, 0, 1.54462, 5), "LElbowRoll": (7.19407, -1.54462, 0, 5),
              "LWristYaw": (24.6229, -1.82387, 1.82387, 1.5), "RPhalanx3": (10, 0, 1, 10),
              "LHipYawPitch": (4.16174, -1.14529, 0.740718, 14.8), "RHipRoll": (4.16174, -0.738274, 0.449597, 14.8),
              "LHipPitch": (6.40239, -1.77378, 0.48398, 9.8), "RKneePitch": (6.40239, -0.0923279, 2.11255, 9.8),
              "RAnklePitch": (6.40239, -1.1863, 0.932006, 9.8), "LAnkleRoll": (4.16174, -0.39788, 0.769001, 14.8)}
    for name, values in motors.items():
        fields = devices[name].fields
        assert tuple(fields[f] for f in ("maxVelocity", "minPosition", "maxPosition", "maxTorque")) == values, name
    top = devices["CameraTop"].fields
    assert (top["width"], top["height"], top["fieldOfView"], top["near"]) == (160, 120, 1.064, 0.002)
    sonar = devices["Sonar/Right"].fields
    assert (sonar["type"], sonar["numberOfRays"], sonar["aperture"]) == ("sonar", 6, 1.04)
    assert devices["LFsr"].fields["type"] == "force-3d"
    assert devices["super_emitter"].fields["channel"] == 2
    model = sim.model
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(MASS_V5, abs=1e-6)
    assert MASS_V5 == pytest.approx(5.31, abs=0.005)


def test_link_lengths_and_axes_at_zero_angles(sim):
    model, data = sim.model, sim.data
    data.qpos[:] = 0.0  # torso frame at the origin, every joint at 0 rad: legs straight down, arms forward
    data.qpos[3] = 1.0
    mujoco.mj_kinematics(model, data)

    def at(solid: str) -> np.ndarray:
        return data.xpos[model.body(f"NAO/{solid}").id]

    assert at("head") == pytest.approx([0, 0, 0.1265])
    for side, y in (("L", 1), ("R", -1)):
        assert at(f"{side}Shoulder") == pytest.approx([0, 0.098 * y, 0.1])
        assert at(f"{side}Elbow") == pytest.approx([0.105, 0.113 * y, 0.1])
        assert at(f"{side}Hand") == pytest.approx([0.105 + 0.05595, 0.113 * y, 0.1])
        assert at(f"{side}Hip") == pytest.approx([0, 0.05 * y, -0.085])
        assert at(f"{side}Tibia") == pytest.approx([0, 0.05 * y, -0.185])
        assert at(f"{side}Foot") == pytest.approx([0, 0.05 * y, -0.2879])
    tags, entry = _tags(sim), sim.table.robots[0]

    def axis(name: str) -> np.ndarray:
        return data.xaxis[model.joint(entry.devices[tags[name]].joint).id]

    expected = {"HeadYaw": (0, 0, 1), "HeadPitch": (0, 1, 0), "LHipYawPitch": (0, 0.707107, -0.707107),
                "RHipYawPitch": (0, 0.707107, 0.707107), "RHipRoll": (1, 0, 0), "LKneePitch": (0, 1, 0),
                "RElbowYaw": (1, 0, 0), "LElbowRoll": (0, 0, 1), "RShoulderRoll": (0, 0, 1), "RPhalanx1": (0, -1, 0)}
    for name, value in expected.items():
        assert axis(name) == pytest.approx(value, abs=1e-5), name


def test_it_stands_for_a_second_with_its_motors_holding(sim):
    model, data = sim.model, sim.data
    entry = sim.table.robots[0]
    torso, head = model.body(entry.body).id, model.body("NAO/head").id
    tags = _tags(sim)
    robot = sim.robots[0]
    for name in ("LFsr", "RFsr"):
        robot.sensors[tags[name]].enable(20, sim.time_ms)
    _run(sim, 1.0)
    # The force-sensor soles are 0.334 m below the torso frame: it stays there, upright, where it was put.
    assert data.xpos[torso] == pytest.approx([0, 0, 0.334], abs=0.003)
    assert data.xmat[torso][8] > 0.999
    assert data.xpos[head][2] == pytest.approx(0.334 + 0.1265, abs=0.003)
    for device in entry.devices:
        if device.type == "RotationalMotor":
            assert data.qpos[model.joint(device.joint).qposadr[0]] == pytest.approx(0, abs=0.02), device.name
    # Both feet carry the robot: each force sensor reads about half its weight along its z.
    left, right = robot.sensors[tags["LFsr"]].value, robot.sensors[tags["RFsr"]].value
    assert left[2] == pytest.approx(right[2], rel=0.1)
    assert left[2] + right[2] == pytest.approx(MASS_V5 * 9.81, rel=0.05)


def test_head_yaw_turns_to_half_a_radian(sim):
    tags = _tags(sim)
    robot = sim.robots[0]
    sensor = robot.sensors[tags["HeadYawS"]]
    sensor.enable(20, sim.time_ms)
    sim.step()
    assert sensor.value == pytest.approx(0, abs=1e-3)
    robot.motors[tags["HeadYaw"]].apply("setPosition", (0.5,), sim.time_ms)
    _run(sim, 1.0)
    assert sensor.value == pytest.approx(0.5, abs=0.005)
    # The head turned to the left about the neck; the torso did not.
    head = sim.data.xmat[sim.model.body("NAO/head").id].reshape(3, 3)
    assert head[:, 0] == pytest.approx([math.cos(0.5), math.sin(0.5), 0], abs=0.01)


def test_the_21_motor_v4_has_fixed_hands(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD % 'version "V4 (blue)" degreeOfFreedom 21 cameraWidth 320', "v4.wbt")
    try:
        entry = simulation.table.robots[0]
        assert sorted(d.name for d in entry.devices) == sorted(TORSO + HEAD + _arm("R", False) + _arm("L", False)
                                                               + _leg("R") + _leg("L"))
        assert sum(d.type == "RotationalMotor" for d in entry.devices) == 22
        assert next(d for d in entry.devices if d.name == "CameraTop").fields["width"] == 320
        model = simulation.model
        assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(MASS_V4_21, abs=1e-6)
        _run(simulation, 1.0)
        assert simulation.data.xpos[model.body(entry.body).id][2] == pytest.approx(0.334, abs=0.003)
    finally:
        simulation.close()


def test_an_old_nue_world_gets_the_same_robot_standing(tmp_path: Path):
    """A pre-R2022a world (y up) places the NAO with its old axes; it stands where the world put it."""
    old = """#VRML_SIM R2019b utf8
WorldInfo {
  basicTimeStep 20
}
Floor {
  size 4 4
}
Nao {
  translation 0.5 0.334 0.2
  controller "<none>"
}
"""
    simulation = simulation_of(tmp_path, old, "old.wbt")
    try:
        entry = simulation.table.robots[0]
        assert sorted(d.name for d in entry.devices) == sorted(DEVICES)
        _run(simulation, 1.0)
        # NUE (north, up, east) = (0.5, 0.334, 0.2) is ENU (0.2, 0.5, 0.334) in the model.
        torso = simulation.data.xpos[simulation.model.body(entry.body).id]
        assert torso == pytest.approx([0.2, 0.5, 0.334], abs=0.003)
    finally:
        simulation.close()


def test_an_old_nue_world_nao_at_its_default_rotation_faces_the_old_x(tmp_path: Path):
    """Before R2022a the NAO was built z-up and stood up by its default rotation `1 0 0 -1.5708`.

    Webots' R2020b humanoid-sprint world leaves it there and its 10 m track runs along +x: the robot
    looks along the old x, its left along the old -z, its up along the old y.
    """
    old = """#VRML_SIM R2020b utf8
WorldInfo {
  coordinateSystem "NUE"
}
Floor {
  size 4 4
}
Nao {
  translation -1 0.334 0
  controller "<none>"
}
"""
    simulation = simulation_of(tmp_path, old, "sprint.wbt")
    try:
        entry = simulation.table.robots[0]
        axes = simulation.from_model @ simulation.data.xmat[simulation.model.body(entry.body).id].reshape(3, 3)
        assert axes[:, 0] == pytest.approx([1, 0, 0], abs=1e-5)
        assert axes[:, 1] == pytest.approx([0, 0, -1], abs=1e-5)
        assert axes[:, 2] == pytest.approx([0, 1, 0], abs=1e-5)
    finally:
        simulation.close()
