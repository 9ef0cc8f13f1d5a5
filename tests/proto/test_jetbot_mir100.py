"""wbtc's JetBot and MiR100: Webots' device names and order, masses, wheels and joints, and driving."""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

JETBOT_WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/nvidia/jetbot/protos/JetBot.proto"
WorldInfo {
  basicTimeStep 16
  contactProperties [
    ContactProperties {
      material1 "jetbot rear wheel"
      coulombFriction [ 0 ]
    }
  ]
}
Floor {
  size 10 10
}
DEF JETBOT JetBot {
  controller "<none>"
}
"""
MIR_WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/mir/mir100/protos/Mir100.proto"
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 10 10
}
DEF MIR Mir100 {
  controller "<none>"
}
Solid {
  translation -0.6844 0 0.2
  children [
    Shape {
      geometry Box {
        size 0.02 2 0.4
      }
    }
  ]
  boundingObject Box {
    size 0.02 2 0.4
  }
}
"""
JETBOT_DEVICES = [("display", "Display"), ("camera", "Camera"),
                  ("left_wheel_hinge", "RotationalMotor"), ("right_wheel_hinge", "RotationalMotor")]
CORNERS = ("front_left", "front_right", "back_left", "back_right")
MIR_DEVICES = [
    ("imu_data accelerometer", "Accelerometer"), ("imu_data gyro", "Gyro"), ("imu_data compass", "Compass"),
    *[(f"ds{i}", "DistanceSensor") for i in range(4)],
    ("depth_camera", "RangeFinder"),
    *[(n, t) for side in ("left", "right") for n, t in ((f"middle_{side}_wheel_joint", "RotationalMotor"),
                                                         (f"middle_{side}_wheel_joint_sensor", "PositionSensor"))],
    *[(f"{c}_{part}_joint_sensor", "PositionSensor") for c in CORNERS for part in ("caster", "wheel")],
]
DENSITY = 1000.0  # Webots' default Physics.density (kg/m³)


@pytest.fixture
def jetbot(tmp_path: Path):
    simulation = simulation_of(tmp_path, JETBOT_WORLD, "jetbot.wbt")
    yield simulation
    simulation.close()


@pytest.fixture
def mir(tmp_path: Path):
    simulation = simulation_of(tmp_path, MIR_WORLD, "mir100.wbt")
    yield simulation
    simulation.close()


def _body(sim: Simulation, name: str) -> int:
    return sim.model.body(name).id


def _drive(sim: Simulation, motors: list[str], speed: float, seconds: float) -> None:
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    for name in motors:
        motor = robot.motors[tags[name]]
        motor.apply("setPosition", (float("inf"),), sim.time_ms)
        motor.apply("setVelocity", (speed,), sim.time_ms)
    end = sim.time + seconds
    while sim.time < end - 1e-9:
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)


def _turned(sim: Simulation, joint: str) -> float:
    return float(sim.data.qpos[sim.model.jnt_qposadr[sim.model.joint(joint).id]])


# ----------------------------------------------------------------------------------------------- JetBot


def test_jetbot_devices_in_webots_order_and_the_nested_jetson_nano(jetbot):
    entry, nano = jetbot.table.robots
    assert [(d.name, d.type) for d in entry.devices] == JETBOT_DEVICES
    devices = {d.name: d for d in entry.devices}
    for motor in ("left_wheel_hinge", "right_wheel_hinge"):
        assert (devices[motor].fields["maxVelocity"], devices[motor].fields["maxTorque"]) == (50, 5)
    assert (devices["display"].fields["width"], devices["display"].fields["height"]) == (128, 32)
    camera = devices["camera"].fields
    assert (camera["width"], camera["height"], camera["fieldOfView"]) == (1280, 720, 2.79253)
    # The Jetson Nano is a robot of its own, without devices or controller, as in Webots.
    assert (nano.name, nano.controller, nano.devices) == ("NVIDIA Jetson Nano", "<none>", [])


def test_jetbot_masses_from_webots_numbers_and_densities(jetbot):
    model = jetbot.model
    body = _body(jetbot, jetbot.table.bodies["JETBOT"])
    assert model.body_mass[body] == pytest.approx(0.5641)
    assert model.body_ipos[body] == pytest.approx([-0.015, 0, 0.07])
    # The caster and the wheels have Physics {}: Webots' density times their collision volumes.
    caster = DENSITY * (math.pi * 0.0153 ** 2 * 0.032 + 4 / 3 * math.pi * 0.0127 ** 3)
    wheel = DENSITY * math.pi * 0.0299 ** 2 * 0.0078
    assert model.body_mass[_body(jetbot, "JetBot/rear_wheel")] == pytest.approx(caster)
    assert model.body_mass[_body(jetbot, "JetBot/left wheel")] == pytest.approx(wheel)
    assert model.body_mass[_body(jetbot, "JetBot/right wheel")] == pytest.approx(wheel)
    assert model.body_subtreemass[body] == pytest.approx(0.5641 + caster + 2 * wheel)


def test_jetbot_wheels_hinges_and_caster_where_webots_puts_them(jetbot):
    model, data = jetbot.model, jetbot.data
    mujoco.mj_forward(model, data)
    for wheel, anchor, tyre_y in (("left wheel", 0.05215, 0.05616), ("right wheel", -0.0595, -0.05549)):
        joint = model.joint(f"JetBot/{wheel}")
        assert model.jnt_type[joint.id] == mujoco.mjtJoint.mjJNT_HINGE
        assert not model.jnt_limited[joint.id]  # wheels turn freely, as in Webots
        assert data.xanchor[joint.id] == pytest.approx([0.03, anchor, 0.03], abs=1e-6)
        assert abs(data.xaxis[joint.id] @ [0, 1, 0]) == pytest.approx(1.0)
        (geom,) = [g for g in range(model.ngeom) if model.geom_bodyid[g] == _body(jetbot, f"JetBot/{wheel}")
                   and model.geom_contype[g] | model.geom_conaffinity[g]]
        # (wbtc collides a wheel's cylinder as an ellipsoid of its radius and half width: compile.joint)
        assert model.geom_size[geom] == pytest.approx([0.0299, 0.0299, 0.0039])
        # Webots' tyres sit 4.01 mm left of each wheel's frame.
        assert data.geom_xpos[geom] == pytest.approx([0.03, tyre_y, 0.03], abs=1e-6)
    # The caster's ball touches the ground below the body's back.
    caster = _body(jetbot, "JetBot/rear_wheel")
    balls = [g for g in range(model.ngeom) if model.geom_bodyid[g] == caster
             and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_SPHERE and model.geom_contype[g]]
    (ball,) = balls
    assert data.geom_xpos[ball] == pytest.approx([-0.051, 0, 0.0127], abs=1e-6)
    assert model.geom_size[ball][0] == pytest.approx(0.0127)


def test_jetbot_camera_looks_ahead_and_down_from_webots_pose(jetbot):
    model, data = jetbot.model, jetbot.data
    mujoco.mj_forward(model, data)
    entry = jetbot.table.robots[0]
    (camera,) = [d for d in entry.devices if d.name == "camera"]
    site = model.site(camera.site).id
    # The camera board is 0.0488 m ahead and 0.085 m up, turned 0.316799 rad about y; the Camera itself
    # is 0.5 mm ahead of and 1.3 mm above the board's centre.
    pitch = 0.316799
    expected = np.array([0.0488, 0, 0.085]) + [0.0005 * math.cos(pitch) + 0.0013 * math.sin(pitch), 0,
                                                 -0.0005 * math.sin(pitch) + 0.0013 * math.cos(pitch)]
    assert data.site_xpos[site] == pytest.approx(expected, abs=1e-6)
    forward = data.site_xmat[site].reshape(3, 3)[:, 0]
    assert forward == pytest.approx([math.cos(pitch), 0, -math.sin(pitch)], abs=1e-5)


def test_jetbot_drives_straight_on_its_wheels(jetbot):
    body = _body(jetbot, jetbot.table.bodies["JETBOT"])
    wheels = ["JetBot/left wheel", "JetBot/right wheel"]
    # Half a second to get going (the wheels slip while the robot gathers speed), then 2 s at 10 rad/s.
    _drive(jetbot, ["left_wheel_hinge", "right_wheel_hinge"], 10.0, 0.5)
    start, turned_before = jetbot.data.xpos[body].copy(), [_turned(jetbot, w) for w in wheels]
    _drive(jetbot, ["left_wheel_hinge", "right_wheel_hinge"], 10.0, 2.0)
    dx, dy, _ = jetbot.data.xpos[body] - start
    turned = [_turned(jetbot, w) - before for w, before in zip(wheels, turned_before, strict=True)]
    assert turned == pytest.approx([20.0, 20.0], rel=0.02)
    # Rolling without slipping: the distance is the wheels' turn times their 0.0299 m radius.
    assert dx == pytest.approx(0.0299 * 20.0, rel=0.03)
    assert abs(dy) < 0.01
    assert jetbot.data.xpos[body][2] == pytest.approx(0.0, abs=2e-3)


# ----------------------------------------------------------------------------------------------- MiR100


def test_mir100_devices_in_webots_order_and_their_fields(mir):
    (entry,) = mir.table.robots
    assert [(d.name, d.type) for d in entry.devices] == MIR_DEVICES
    devices = {d.name: d.fields for d in entry.devices}
    for side in ("left", "right"):
        motor = devices[f"middle_{side}_wheel_joint"]
        assert (motor["maxVelocity"], motor["maxTorque"]) == (20, 100)
    assert devices["imu_data accelerometer"]["lookupTable"] == [[-100, -100, -0.002], [100, 100, 0.002]]
    assert devices["imu_data gyro"]["lookupTable"] == [[-100, -100, -0.002], [100, 100, 0.002]]
    assert devices["imu_data compass"]["lookupTable"] == [[-1, -1, -0.2], [1, 1, 0.2]]
    for name, table in (("ds0", [[0.2, 1000, 0], [0.3, 0, 0]]), ("ds1", [[0.01, 1000, 0], [0.35, 0, 0]]),
                        ("ds2", [[0.01, 1000, 0], [0.35, 0, 0]]), ("ds3", [[0.2, 1000, 0], [0.3, 0, 0]])):
        assert devices[name]["lookupTable"] == table
        assert devices[name]["type"] == "sonar"
    depth = devices["depth_camera"]
    assert (depth["width"], depth["height"], depth["fieldOfView"]) == (1280, 720, 2.05949)
    assert (depth["minRange"], depth["maxRange"]) == (0.18, 1.95)
    assert entry.node.get("model") == "Mobile Industrial Robots' MiR100"


def test_mir100_masses_and_inertias_as_webots_gives_them(mir):
    model = mir.model
    body = _body(mir, mir.table.bodies["MIR"])
    assert model.body_mass[body] == pytest.approx(70.0)
    wheels = ["left_wheel_link", "right_wheel_link", *[f"{c}_caster_wheel_link" for c in ("fl", "fr", "bl", "br")]]
    for wheel in wheels:
        b = _body(mir, f"Mir100/{wheel}")
        assert model.body_mass[b] == pytest.approx(1.0)
        assert sorted(model.body_inertia[b]) == pytest.approx([0.001061895, 0.001061895, 0.001953125])
    for corner in ("fl", "fr", "bl", "br"):
        b = _body(mir, f"Mir100/{corner}_caster_rotation_link")
        assert model.body_mass[b] == pytest.approx(0.309754)
        assert model.body_ipos[b] == pytest.approx([0, 0, -0.0425])
    for sonar in ("ds0", "ds1", "ds2", "ds3"):
        assert model.body_mass[_body(mir, f"Mir100/{sonar}")] == pytest.approx(0.0085)
    assert model.body_subtreemass[body] == pytest.approx(70 + 6 * 1 + 4 * 0.309754 + 4 * 0.0085)


def test_mir100_joints_from_webots_numbers(mir):
    model, data = mir.model, mir.data
    mujoco.mj_forward(model, data)
    hinge = mujoco.mjtJoint.mjJNT_HINGE
    for side, y in (("left", 0.222604), ("right", -0.222604)):
        joint = model.joint(f"Mir100/{side}_wheel_link").id
        assert data.xanchor[joint] == pytest.approx([0, y, 0.0625], abs=1e-6)
        assert abs(data.xaxis[joint] @ [0, 1, 0]) == pytest.approx(1.0)
    for corner, x, y in (("fl", 0.341346, 0.203), ("fr", 0.341346, -0.203),
                         ("bl", -0.270154, 0.203), ("br", -0.270154, -0.203)):
        swivel = model.joint(f"Mir100/{corner}_caster_rotation_link").id
        assert data.xanchor[swivel] == pytest.approx([x, y, 0.1565], abs=1e-6)
        assert data.xaxis[swivel] == pytest.approx([0, 0, 1], abs=1e-6)
        assert model.dof_damping[model.jnt_dofadr[swivel]] == pytest.approx(0.01)
        wheel = model.joint(f"Mir100/{corner}_caster_wheel_link").id
        # The caster wheel trails 0.0382 m behind its swivel, 0.094 m below it: its axle 0.0625 m up.
        assert data.xanchor[wheel] == pytest.approx([x - 0.0382, y, 0.0625], abs=1e-6)
        assert abs(data.xaxis[wheel] @ [0, 1, 0]) == pytest.approx(1.0)
    # Every joint of the MiR100 is an unlimited hinge.
    joints = [j for j in range(model.njnt) if model.jnt_bodyid[j] != _body(mir, mir.table.bodies["MIR"])]
    assert len(joints) == 10
    assert all(model.jnt_type[j] == hinge and not model.jnt_limited[j] for j in joints)
    # All six wheels (radius 0.0625 m) stand on the ground.
    for b in range(model.nbody):
        if model.body(b).name.endswith("wheel_link"):
            (geom,) = [g for g in range(model.ngeom) if model.geom_bodyid[g] == b and model.geom_contype[g]]
            assert model.geom_size[geom][0] == pytest.approx(0.0625)
            assert data.geom_xpos[geom][2] == pytest.approx(0.0625, abs=1e-6)


def test_mir100_back_sonars_echo_from_a_wall_behind(mir):
    robot = mir.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    for name in ("ds0", "ds1", "ds2", "ds3"):
        robot.sensors[tags[name]].enable(16, mir.time_ms)
    mir.step()
    # ds1 and ds2 look backwards from x = -0.3844; the wall's face is at x = -0.6744, 0.29 m behind them.
    expected = 1000 * (0.35 - 0.29) / (0.35 - 0.01)
    assert robot.sensors[tags["ds1"]].value == pytest.approx(expected, abs=1.0)
    assert robot.sensors[tags["ds2"]].value == pytest.approx(expected, abs=1.0)
    # The front ones see nothing within 0.3 m.
    assert robot.sensors[tags["ds0"]].value == pytest.approx(0.0)
    assert robot.sensors[tags["ds3"]].value == pytest.approx(0.0)


def test_mir100_drives_forwards_on_its_middle_wheels(mir):
    body = _body(mir, mir.table.bodies["MIR"])
    motors = ["middle_left_wheel_joint", "middle_right_wheel_joint"]
    wheels = ["Mir100/left_wheel_link", "Mir100/right_wheel_link"]
    # Half a second to get going and to turn the casters behind their swivels, then 2 s at 5 rad/s.
    _drive(mir, motors, 5.0, 0.5)
    start, turned_before = mir.data.xpos[body].copy(), [_turned(mir, w) for w in wheels]
    _drive(mir, motors, 5.0, 2.0)
    dx, dy, _ = mir.data.xpos[body] - start
    turned = [_turned(mir, w) - before for w, before in zip(wheels, turned_before, strict=True)]
    assert turned == pytest.approx([10.0, 10.0], rel=0.02)
    # Rolling without slipping on its 0.0625 m wheels: 0.625 m.
    assert dx == pytest.approx(0.0625 * 10.0, rel=0.03)
    assert abs(dy) < 0.01
    assert mir.data.xpos[body][2] == pytest.approx(0.0, abs=2e-3)
