"""wbtc's Boston Dynamics Spot: Webots' devices in order, limits, masses, leg kinematics, standing."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/boston_dynamics/spot/protos/Spot.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 10 10 }
Spot { controller "<none>" %s }
"""
LEGS = [("front left", -1), ("front right", 1), ("rear left", -1), ("rear right", 1)]
LEDS = ["left top led", "left middle up led", "left middle down led", "right top led", "right middle up led",
        "right middle down led", "right bottom led", "left bottom led"]
CAMERAS = ["right head camera", "left head camera", "right flank camera", "left flank camera", "rear camera"]
DEVICES = (["accelerometer", "gps", "gyro", "inertial unit"] + LEDS + CAMERAS
           + [f"{leg} {d}" for leg, _ in LEGS for d in (
               "shoulder abduction sensor", "shoulder abduction motor", "shoulder rotation sensor",
               "shoulder rotation motor", "piston motor", "elbow sensor", "elbow motor")])
# Webots' Spot.proto and SpotLeg.proto (R2023b). Each leg is a Pose at HIPS[leg] turned by Y_UP (2.094389 rad
# about (0.57735, -0.577354, -0.577346): the leg's +y is up, +z backwards, +x to the robot's right). In it,
# with s = -1 for a left leg and 1 for a right one, the joints (anchor = endPoint translation, axis):
# abduction (s 0.0528, 0.0006, 0) about z, shoulder rotation (0, -0.00053, 0) about x, elbow
# (s 0.1122, -0.319729, 0.182338) about x; the foot is the forearm's cylinder at (s 0.001038, -0.271321,
# -0.225038), radius 0.035094 m.
HIPS = {"front": (0.3635, 0, 0.0118), "rear": (-0.3084, 0, 0.0117)}
Y_UP = ((0.57735, -0.577354, -0.577346), 2.094389)
LIMITS = {"shoulder abduction motor": (-0.6, 0.5, 50), "shoulder rotation motor": (-1.7, 1.7, 50),
          "elbow motor": (-0.45, 1.6, 50), "piston motor": (0, 0, 10)}
FOOT_RADIUS = 0.035094
# Webots' masses: body, then per leg shoulder, upper arm and forearm (the piston rod has no Physics).
BODY, SHOULDER, UPPERARM, FOREARM = 14.40973585, 2.131962264, 0.934886792, 0.137150943


def _rotation(axis, angle: float) -> np.ndarray:
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def _leg_points(leg: str, s: int, angles) -> tuple[np.ndarray, np.ndarray]:
    """The elbow (forearm origin) and the foot centre in the robot's frame, from Webots' numbers."""
    chain = [((s * 0.0528, 0.0006, 0), (0, 0, 1)), ((0, -0.00053, 0), (1, 0, 0)),
             ((s * 0.1122, -0.319729, 0.182338), (1, 0, 0))]
    position, frame = np.array(HIPS[leg.split()[0]], float), _rotation(*Y_UP)
    for (offset, axis), angle in zip(chain, angles, strict=True):
        position = position + frame @ np.array(offset)
        frame = frame @ _rotation(axis, angle)
    return position, position + frame @ np.array([s * 0.001038, -0.271321, -0.225038])


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD % "translation 0 0 0", "spot.wbt")
    yield simulation
    simulation.close()


def _foot(model, leg: str) -> int:
    """The foot: the forearm's collision cylinder of Webots' foot radius (wbtc rounds it as a wheel's)."""
    body = model.body(f"Spot/{leg} forearm").id
    [geom] = [g for g in range(model.ngeom) if model.geom_bodyid[g] == body
              and model.geom_size[g][0] == pytest.approx(FOOT_RADIUS) and model.geom_contype[g]]
    return geom


def test_devices_in_webots_order_and_limits(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == DEVICES
    devices = {d.name: d for d in entry.devices}
    for leg, _ in LEGS:
        for motor, (low, high, torque) in LIMITS.items():
            fields = devices[f"{leg} {motor}"].fields
            assert (fields["minPosition"], fields["maxPosition"], fields["maxTorque"], fields["maxVelocity"]) == (
                low, high, torque, 10)
    for name in LEDS:
        assert devices[name].fields["color"] == [[0, 1, 0], [1, 1, 0], [1, 0, 0]]
    for name in CAMERAS:
        assert (devices[name].fields["width"], devices[name].fields["height"]) == (1080, 720)


def test_cameras_sit_at_webots_poses(sim):
    # Webots places the cameras in its mesh frame: 2.094389 rad about (0.57735, -0.577354, -0.577346) at
    # (-0.459994, -0.000019, -1.650002); a Webots camera looks along its +x (MuJoCo's along its -z).
    mesh = _rotation(*Y_UP)
    poses = {"right head camera": ((0.044898, 1.67797, -0.922603), (0.492404, -0.738106, -0.461236), -2.507618),
             "left head camera": ((-0.045109, 1.67955, -0.92325), (0.776783, -0.539742, -0.32448), -2.231426),
             "right flank camera": ((0.110163, 1.71561, -0.324321), (-0.958773, 0.200939, -0.200942), 1.612883),
             "left flank camera": ((-0.110127, 1.71553, -0.32432), (-0.143022, 0.699837, 0.699837), -2.857471),
             "rear camera": ((0.018113, 1.66256, -0.011864), (0.461984, 0.461983, 0.757062), -1.845577)}
    devices = {d.name: d for d in sim.table.robots[0].devices}
    for name, (translation, axis, angle) in poses.items():
        camera = sim.model.camera(devices[name].camera).id
        position = np.array([-0.459994, -0.000019, -1.650002]) + mesh @ np.array(translation)
        looks = (mesh @ _rotation(axis, angle))[:, 0]
        assert sim.data.cam_xpos[camera] == pytest.approx(position, abs=1e-6)
        assert -sim.data.cam_xmat[camera].reshape(3, 3)[:, 2] == pytest.approx(looks, abs=1e-5)


def test_masses_and_inertias_are_webots(sim):
    model = sim.model
    top = model.body(sim.table.robots[0].body).id
    assert model.body_mass[top] == pytest.approx(BODY)
    assert model.body_ipos[top] == pytest.approx([0.022374, 0, 0.02032])
    moving = 0.0
    for leg, s in LEGS:
        for part, mass in (("shoulder", SHOULDER), ("upperarm", UPPERARM), ("forearm", FOREARM)):
            assert model.body_mass[model.body(f"Spot/{leg} {part}").id] == pytest.approx(mass)
            moving += mass
        # Webots' inertia matrices (about the centre of mass): MuJoCo keeps their principal moments.
        upper = np.array([[0.1012996403729267, s * -0.02395093549986319, -0.04470786622876792],
                          [s * -0.02395093549986319, 0.09841956052568711, s * -0.03546126467713879],
                          [-0.04470786622876792, s * -0.03546126467713879, 0.06647528278171203]])
        body = model.body(f"Spot/{leg} upperarm").id
        assert sorted(model.body_inertia[body]) == pytest.approx(sorted(np.linalg.eigvalsh(upper)), rel=1e-6)
        assert model.body_ipos[body] == pytest.approx([s * 0.11714932354424774, -0.12276425577719878,
                                                       0.08285389390894864])
    physical = BODY + moving
    assert physical == pytest.approx(27.22573585)
    # Besides: four piston rods, moved by their motors without Physics (wbtc's token mass for such bodies).
    rods = model.body_subtreemass[top] - physical
    assert 0 <= rods < 0.01


def test_legs_follow_webots_kinematics(sim):
    model, data = sim.model, sim.data
    entry = sim.table.robots[0]
    devices = {d.name: d for d in entry.devices}
    # Zero angles: for the front left leg (s = -1), leg frame elbow (-0.165, -0.319659, 0.182338) and foot
    # (-0.166038, -0.59098, -0.0427), i.e. robot frame elbow (0.181162, 0.165, -0.307859), foot (0.4062,
    # 0.166038, -0.57918) if Y_UP were exactly the 2π/3 turn (it is within 5e-6 rad): the foot is 0.0427 m
    # ahead of the hip and its bottom 0.614274 m below the body.
    elbow, foot = _leg_points("front left", -1, [0, 0, 0])
    assert elbow == pytest.approx([0.181162, 0.165, -0.307859], abs=1e-5)
    assert foot == pytest.approx([0.4062, 0.166038, -0.57918], abs=1e-5)
    configurations = [[0, 0, 0] * 4, [-0.4, -0.99, 1.59, 0.4, -0.99, 1.59, -0.3, 0.5, -0.2, 0.25, 0.7, 1.2]]
    for angles in configurations:
        for (leg, _), triple in zip(LEGS, np.reshape(angles, (4, 3)), strict=True):
            for joint, angle in zip(("shoulder abduction", "shoulder rotation", "elbow"), triple, strict=True):
                data.qpos[model.joint(devices[f"{leg} {joint} motor"].joint).qposadr[0]] = angle
        mujoco.mj_forward(model, data)
        for (leg, s), triple in zip(LEGS, np.reshape(angles, (4, 3)), strict=True):
            elbow, foot = _leg_points(leg, s, triple)
            assert data.xpos[model.body(f"Spot/{leg} forearm").id] == pytest.approx(elbow, abs=1e-6)
            assert data.geom_xpos[_foot(model, leg)] == pytest.approx(foot, abs=1e-6)
        if angles == configurations[0]:
            bottoms = [data.geom_xpos[_foot(model, leg)][2] - FOOT_RADIUS for leg, _ in LEGS]
            assert bottoms == pytest.approx([-0.614274, -0.614274, -0.614374, -0.614374], abs=1e-5)


def test_spot_stands_and_holds_its_default_pose(tmp_path: Path):
    # Webots' default (0.624 m) leaves the feet 9.7 mm above the floor: Spot drops onto them and stands,
    # its untouched motors holding 0.
    simulation = simulation_of(tmp_path, WORLD % "", "spot.wbt")
    try:
        model, data = simulation.model, simulation.data
        top = simulation.table.robots[0].body
        body = model.body(top).id
        while simulation.time < 0.5:
            simulation.step()
        start = data.xpos[body].copy()
        assert 0.605 < start[2] < 0.615  # standing: the feet's bottoms are 0.614274 m below the body
        while simulation.time < 1.5:
            simulation.step()
        assert np.linalg.norm(data.xpos[body] - start) < 1e-3
        legs = [model.jnt_qposadr[j] for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_HINGE]
        assert abs(data.qpos[legs]).max() < 0.01
        assert data.xmat[body].reshape(3, 3)[2, 2] > 0.9999  # level
    finally:
        simulation.close()
