"""wbtc's ROBOTIS OP2 and its Webots 7 name DARwInOP: Webots' 20 servos, sensors, masses and kinematics."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/robotis/darwin-op/protos/RobotisOp2.proto"
WorldInfo { basicTimeStep 8 }
Floor { size 4 4 }
RobotisOp2 { controller "<none>" }
"""
SERVOS = ["Neck", "Head",
          "PelvYL", "PelvL", "LegUpperL", "LegLowerL", "AnkleL", "FootL",
          "PelvYR", "PelvR", "LegUpperR", "LegLowerR", "AnkleR", "FootR",
          "ShoulderL", "ArmUpperL", "ArmLowerL", "ShoulderR", "ArmUpperR", "ArmLowerR"]
DEVICES = (["BackLedGreen", "BackLedBlue", "BackLedRed", "Speaker", "Accelerometer", "Gyro", "receiver", "emitter",
            "super_emitter", "Neck", "NeckS", "Head", "HeadS", "Camera", "EyeLed", "HeadLed"]
           + [n for s in SERVOS[2:] for n in (s, f"{s}S")])
# Body 0.975599, neck, head, two legs (pelvis yaw, pelvis, thigh, shin, ankle, foot), two arms.
MASS = (0.975599 + 0.0243577 + 0.158042 + 2 * (0.0270692 + 0.167108 + 0.119043 + 0.0703098 + 0.167108 + 0.0794462)
        + 2 * (0.025913 + 0.168377 + 0.0592885))


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "op2.wbt")
    yield simulation
    simulation.close()


def _axis(sim, name: str) -> np.ndarray:
    """A servo's axis in the robot's frame, at the current pose."""
    entry = sim.table.robots[0]
    device = next(d for d in entry.devices if d.name == name)
    joint = sim.model.joint(device.joint)
    return sim.data.xaxis[joint.id]


def test_devices_in_webots_order_limits_and_the_mass(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == DEVICES
    devices = {d.name: d for d in entry.devices}
    assert [devices[n].type for n in ("Neck", "NeckS", "Camera", "EyeLed", "Gyro")] == [
        "RotationalMotor", "PositionSensor", "Camera", "LED", "Gyro"]
    for name in SERVOS:
        assert devices[name].fields["maxVelocity"] == 12.26
        assert devices[name].fields["maxTorque"] == 2.5
    limits = {"Neck": (-1.81, 1.81), "Head": (-0.36, 0.94), "LegUpperL": (-0.5, 1.68), "LegLowerR": (-0.02, 2.25),
              "AnkleL": (-1.39, 1.22), "ShoulderR": (-3.14, 3.14), "ArmLowerL": (-1.18, 1.63)}
    for name, (low, high) in limits.items():
        assert (devices[name].fields["minPosition"], devices[name].fields["maxPosition"]) == (low, high), name
    assert (devices["Camera"].fields["width"], devices["Camera"].fields["height"]) == (160, 120)
    assert devices["Camera"].fields["fieldOfView"] == 1.0123
    assert devices["super_emitter"].fields["channel"] == 2
    model = sim.model
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(MASS, abs=1e-6)
    assert MASS == pytest.approx(2.925, abs=1e-3)


def test_axes_and_the_straight_pose_at_zero_angles(sim):
    model, data = sim.model, sim.data
    data.qpos[:] = 0.0  # free joint at the origin, every servo at 0 rad: legs straight down
    data.qpos[3] = 1.0
    mujoco.mj_kinematics(model, data)
    expected = {"Neck": (0, 0, 1), "Head": (0, -1, 0), "PelvYL": (0, 0, -1), "PelvL": (-1, 0, 0),
                "LegUpperL": (0, -1, 0), "LegUpperR": (0, 1, 0), "LegLowerL": (0, -1, 0), "AnkleL": (0, 1, 0),
                "FootR": (1, 0, 0), "ShoulderL": (0, 1, 0), "ShoulderR": (0, -1, 0), "ArmUpperL": (-1, 0, 0),
                "ArmLowerL": (0, 0.7071, 0.7071)}
    for name, axis in expected.items():
        assert _axis(sim, name) == pytest.approx(np.array(axis) / np.linalg.norm(axis), abs=1e-4), name
    # Ankles under the hips: 0.1222 m, then a 0.093 m thigh and a 0.093 m shin.
    for side, y in (("L", 0.037), ("R", -0.037)):
        ankle = data.xpos[model.body(f"ROBOTIS OP2/ankle{side}").id]
        assert ankle == pytest.approx([-0.005, y, -0.1222 - 0.186], abs=2e-4)
    # Elbows: shoulder 0.082 m to the side, upper arm 0.06 m along its 45-degree slope, 0.016 m forward.
    elbow = data.xpos[model.body("ROBOTIS OP2/armLowerL").id]
    assert elbow == pytest.approx([0.016, 0.082 + 0.06 * np.sqrt(0.5), -0.016 - 0.06 * np.sqrt(0.5)], abs=2e-4)


def test_it_stands_crouched_with_its_motors_holding(sim):
    model, data = sim.model, sim.data
    head = model.body("ROBOTIS OP2/head").id
    body = model.body(sim.table.robots[0].body).id
    initial = {d.name: d.initial_position for d in sim.table.robots[0].devices if d.type == "RotationalMotor"}
    assert (initial["LegUpperL"], initial["LegLowerL"], initial["AnkleL"]) == (1.15, -2.25, -1.23)
    for _ in range(125):  # 1 s
        sim.step()
    # Webots' crouch: the torso frame 0.234 m up (hip 0.1222 m below it, thigh and shin folded, 0.0335 m
    # from ankle to sole), the head above 0.28 m, upright and where it was put.
    assert data.xpos[body][2] == pytest.approx(0.234, abs=0.005)
    assert data.xpos[head][2] > 0.28
    assert data.xmat[body][8] > 0.99
    assert abs(data.xpos[body][0]) < 0.05 and abs(data.xpos[body][1]) < 0.01
    for device in sim.table.robots[0].devices:
        if device.type == "RotationalMotor":
            joint = model.joint(device.joint)
            assert data.qpos[joint.qposadr[0]] == pytest.approx(initial[device.name], abs=0.05), device.name


def test_old_darwin_op_world_gets_the_same_robot(tmp_path: Path):
    """A Webots 7 world (y up) with the DARwInOP of its day: the same devices, and it stands."""
    world = tmp_path / "darwin.wbt"
    world.write_text("""#VRML_SIM V7.4.3 utf8
WorldInfo {
  basicTimeStep 8
}
Solid {
  translation 0 -0.01 0
  children [ Shape { geometry Box { size 4 0.02 4 } } ]
  boundingObject Box { size 4 0.02 4 }
}
DARwInOP {
  translation 0 0.235 0
  controller "void"
  cameraWidth 320
  cameraHeight 240
}
""", encoding="utf-8")
    result, _ = compile_world(world)
    entry = result.table.robots[0]
    assert [d.name for d in entry.devices] == DEVICES
    camera = next(d for d in entry.devices if d.name == "Camera")
    assert (camera.fields["width"], camera.fields["height"]) == (320, 240)
    sim = Simulation(result, noise=False)
    try:
        for _ in range(125):
            sim.step()
        assert sim.data.xpos[sim.model.body(entry.body).id][2] == pytest.approx(0.234, abs=0.005)
    finally:
        sim.close()
