"""wbtc's Franka Emika Panda and PandaHand: Webots' devices in order, limits, masses, kinematics, held pose."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/franka_emika/panda/protos/Panda.proto"
WorldInfo { basicTimeStep 16 }
Panda { controller "<none>" }
"""
JOINTS = [f"panda_joint{i}" for i in range(1, 8)]
FINGERS = ["panda_finger::right", "panda_finger::left"]
# Webots' Panda.proto (R2025b): each motor's minPosition, maxPosition, maxVelocity, maxTorque.
LIMITS = [(-2.9671, 2.9671, 2.5, 87), (-1.8326, 1.8326, 2.5, 87), (-2.9671, 2.9671, 2.5, 87),
          (-3.1416, -0.4, 2.5, 87), (-2.9671, 2.9671, 3, 12), (-0.0873, 3.8223, 3, 12), (-2.9671, 2.9671, 3, 12)]
# Webots' Panda.proto: per joint its axis, anchor and `position`, then its endPoint's translation and
# rotation (axis, angle), which Webots writes at that position. The end-effector slot is 0.107 m along
# link 7's z.
CHAIN = [((0, 0, 1), (0, 0, 0.14), 0, (0, 0, 0.333), ((0, 0, 1), 0)),
         ((0, 1, 0), (0, 0, 0), 0, (0, 0, 0), ((-1, 0, 0), 1.570796)),
         ((0, -1, 0), (0, -0.195, 0), 0, (0, -0.316, 0), ((1, 0, 0), 1.570796)),
         ((0, -1, 0), (0.0825, 0, 0), -1.7708, (0.0825, 0, 0),
          ((0.5661098628752397, 0.5828891661867001, -0.5828892202619214), 2.1113368158463413)),
         ((0, 1, 0), (-0.0825, 0.125, 0), -1.6, (-0.0825, 0.384, 0), ((-1, 0, 0), 1.570796)),
         ((0, -1, 0), (0, 0, 0), 1.6, (0, 0, 0),
          ((0.566110229574146, -0.5828891103953294, 0.582888919910174), 2.111336936951227)),
         ((0, -1, 0), (0.088, -0.058, 0), 0.79, (0.088, 0, 0),
          ((0.8614190923211578, -0.3591359294777342, 0.3591358121139644), 1.7194199439154274))]
SLOT = (0, 0, 0.107)
DEFAULT = [joint[2] for joint in CHAIN]
# Webots' link masses: base (link 0), links 1-7, then the hand and its two fingers.
MASSES = [0.629769, 4.970684, 0.646926, 3.228604, 3.587895, 1.225946, 1.666555, 0.735522]
HAND_MASSES = [0.73, 0.015, 0.015]


def _rotation(axis, angle: float) -> np.ndarray:
    x, y, z = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def _slot(angles) -> tuple[np.ndarray, np.ndarray]:
    """The end-effector slot's origin and frame, forward kinematics of Webots' numbers (base at the origin).

    A joint at angle q turns its endPoint, written at `position`, by q - position about the axis through
    the anchor."""
    position, frame = np.zeros(3), np.eye(3)
    for (axis, anchor, written, translation, (r_axis, r_angle)), angle in zip(CHAIN, angles, strict=True):
        turn = _rotation(axis, angle - written)
        anchor, translation = np.array(anchor), np.array(translation)
        position = position + frame @ (anchor + turn @ (translation - anchor))
        frame = frame @ turn @ _rotation(r_axis, r_angle)
    return position + frame @ np.array(SLOT), frame


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "panda.wbt")
    yield simulation
    simulation.close()


def test_devices_in_webots_order_and_limits(sim):
    entry = sim.table.robots[0]
    assert [(d.name, d.type) for d in entry.devices] == [
        *[(n, t) for j in JOINTS for n, t in ((j, "RotationalMotor"), (f"{j}_sensor", "PositionSensor"))],
        *[(n, t) for f in FINGERS for n, t in ((f, "LinearMotor"), (f"{f}_sensor", "PositionSensor"))]]
    devices = {d.name: d for d in entry.devices}
    for joint, limits in zip(JOINTS, LIMITS, strict=True):
        fields = devices[joint].fields
        assert (fields["minPosition"], fields["maxPosition"], fields["maxVelocity"], fields["maxTorque"]) == limits
    for finger in FINGERS:
        fields = devices[finger].fields
        assert (fields.get("minPosition", 0), fields["maxPosition"], fields["maxVelocity"], fields["maxForce"]) == (
            0, 0.04, 0.2, 100)
    # Webots' joint positions are the first readings (joints 4-7 start away from zero).
    model = sim.model
    for joint, written in zip(JOINTS, DEFAULT, strict=True):
        assert sim.data.qpos[model.joint(devices[joint].joint).qposadr[0]] == pytest.approx(written)


def test_link_masses(sim):
    model = sim.model
    names = ["panda/solid", *[f"panda/panda_link{i}" for i in range(1, 8)],
             "panda/panda hand", "panda/panda_leftfinger", "panda/panda_rightfinger"]
    assert [model.body_mass[model.body(n).id] for n in names] == pytest.approx(MASSES + HAND_MASSES)
    # Link 1's inertia matrix is Webots' (Ixx, Iyy, Izz, Ixy, Ixz, Iyz) about its centre of mass.
    body = model.body("panda/panda_link1").id
    rot = np.zeros(9)
    mujoco.mju_quat2Mat(rot, model.body_iquat[body])
    rot = rot.reshape(3, 3)
    inertia = rot @ np.diag(model.body_inertia[body]) @ rot.T
    assert inertia[[0, 1, 2, 0, 0, 1], [0, 1, 2, 1, 2, 2]] == pytest.approx(
        [0.70337, 0.70661, 9.117e-3, -1.39e-4, 6.772e-3, 1.9169e-2], abs=1e-9)
    assert model.body_ipos[body] == pytest.approx([0.003875, 0.002081, -0.04762])


def test_the_end_effector_slot_follows_webots_kinematics(sim):
    model, data = sim.model, sim.data
    hand = model.body("panda/panda hand").id
    # Default pose (joints 4-7 at -1.7708, -1.6, 1.6, 0.79): the hand hangs over +x, its +z down.
    assert data.xpos[hand] == pytest.approx([0.556745, 0, 0.613252], abs=1e-6)
    assert data.xpos[hand] == pytest.approx(_slot(DEFAULT)[0], abs=1e-6)
    assert data.xmat[hand].reshape(3, 3)[:, 2] == pytest.approx([0, 0, -1], abs=1e-5)
    entry = sim.table.robots[0]
    motors = [d for d in entry.devices if d.name in JOINTS]
    # Zero angles (Webots' zeros: joint 4 and 5 turned back by 1.7708 and 1.6 rad from the written links)
    # put the slot at (-0.048413, 0.087963, 0.907510); then one more configuration.
    assert _slot([0] * 7)[0] == pytest.approx([-0.048413, 0.087963, 0.90751], abs=1e-6)
    for angles in ([0] * 7, [0.5, -0.4, 0.6, -1.2, 0.7, 1.1, -0.8]):
        for device, angle in zip(motors, angles, strict=True):
            data.qpos[model.joint(device.joint).qposadr[0]] = angle
        mujoco.mj_forward(model, data)
        position, frame = _slot(angles)
        assert data.xpos[hand] == pytest.approx(position, abs=1e-6)
        assert data.xmat[hand].reshape(3, 3) == pytest.approx(frame, abs=1e-5)


def test_motors_hold_the_default_pose_and_the_fingers_open(sim):
    model, data = sim.model, sim.data
    hand = model.body("panda/panda hand").id
    start = data.xpos[hand].copy()
    while sim.time < 1.0:  # untouched motors hold their joints against gravity
        sim.step()
    assert np.linalg.norm(data.xpos[hand] - start) < 1e-3
    robot = sim.robots[0]
    tags = {d.name: i for i, d in enumerate(robot.entry.devices)}
    for joint, written in zip(JOINTS, DEFAULT, strict=True):
        assert data.qpos[model.joint(robot.entry.devices[tags[joint]].joint).qposadr[0]] == pytest.approx(
            written, abs=1e-3)
    for finger in FINGERS:
        robot.motors[tags[finger]].apply("setPosition", (0.04,), sim.time_ms)
    while sim.time < 1.5:  # 4 cm at 0.2 m/s
        sim.step()
    left, right = (data.xpos[model.body(f"panda/panda_{side}finger").id] for side in ("left", "right"))
    # Each finger slides 4 cm away from the middle, along the hand's (x + y) / sqrt(2) direction.
    across = data.xmat[hand].reshape(3, 3) @ np.array([1, 1, 0]) / np.sqrt(2)
    assert left - right == pytest.approx(0.08 * across, abs=1e-3)
