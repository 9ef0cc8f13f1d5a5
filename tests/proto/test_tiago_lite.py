"""wbtc's TIAGo LITE (TiagoBase + TiagoBody + Astra + Hokuyo): Webots' devices, masses, wheels and joints."""

from pathlib import Path

import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.lidar import Lidar
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/pal_robotics/tiago_lite/protos/TiagoLite.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 20 20 }
TiagoLite { controller "<none>" }
"""
WALL = """Solid {
  translation 2.05 0 0.5
  children [ Shape { geometry DEF WALL Box { size 0.1 8 2 } } ]
  boundingObject USE WALL
}
"""
DEVICES = [
    "torso_lift_joint", "torso_lift_joint_sensor", "head_1_joint", "head_1_joint_sensor",
    "head_2_joint", "head_2_joint_sensor", "Astra rgb", "Astra depth", "Hokuyo URG-04LX-UG01",
    "accelerometer", "inertial unit", "gyro", "base_cover_link",
    "base_sonar_03_link", "base_sonar_02_link", "base_sonar_01_link",
    "wheel_right_joint", "wheel_right_joint_sensor", "wheel_left_joint", "wheel_left_joint_sensor",
]
BASE = 28.26649 + 0.25821 + 2 * 1.82362 + 4 * (0.051448 + 0.088558)  # body, bumper, wheels, castors
BODY = 14.0136 + 6.93198 + 0.6222 + 0.66123  # column, torso, neck, head
RADIUS = 0.0985
ACCELERATION = 5.0762  # the wheel motors' rad/s²


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "tiago_lite.wbt")
    yield simulation
    simulation.close()


def _command(sim: Simulation, name: str, command: str, value: float) -> None:
    robot = sim.robots[0]
    tag = [d.name for d in robot.entry.devices].index(name)
    robot.motors[tag].apply(command, (value,), sim.time_ms)


def _joint_value(sim: Simulation, name: str) -> float:
    device = next(d for d in sim.robots[0].entry.devices if d.name == name)
    return float(sim.data.qpos[sim.model.joint(device.joint).qposadr[0]])


def test_devices_in_webots_order_the_mass_and_the_motors(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == DEVICES
    model = sim.model
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(BASE + BODY + 0.16 + 0.19)
    fields = {d.name: d.fields for d in entry.devices}
    for wheel in ("wheel_left_joint", "wheel_right_joint"):
        assert fields[wheel]["maxVelocity"] == pytest.approx(10.1523)
        assert fields[wheel]["maxTorque"] == pytest.approx(10)
    assert fields["torso_lift_joint"]["maxPosition"] == pytest.approx(0.35)
    assert fields["torso_lift_joint"]["maxForce"] == pytest.approx(2000)
    head_2 = fields["head_2_joint"]
    assert (head_2["minPosition"], head_2["maxPosition"], head_2["maxTorque"]) == pytest.approx((-0.98, 0.79, 2.77))
    # The wheels sit 0.202 m either side of the centre.
    left = model.body("TIAGo LITE/wheel_left_link").id
    right = model.body("TIAGo LITE/wheel_right_link").id
    assert sim.data.xpos[left][1] - sim.data.xpos[right][1] == pytest.approx(0.404, abs=1e-6)


def test_it_rests_on_its_wheels_and_both_wheels_drive_it_forwards(sim):
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


def test_the_torso_and_head_reach_their_commanded_positions(sim):
    head = sim.model.body("TIAGo LITE/head_2_link").id
    for _ in range(10):
        sim.step()
    height = sim.data.xpos[head][2]
    _command(sim, "torso_lift_joint", "setPosition", 0.1)  # 1.4 s at 0.07 m/s
    _command(sim, "head_1_joint", "setPosition", 1.0)  # pan to the left
    _command(sim, "head_2_joint", "setPosition", -0.5)
    for _ in range(110):  # 1.76 s
        sim.step()
    assert _joint_value(sim, "torso_lift_joint") == pytest.approx(0.1, abs=0.003)
    assert _joint_value(sim, "head_1_joint") == pytest.approx(1.0, abs=0.01)
    assert _joint_value(sim, "head_2_joint") == pytest.approx(-0.5, abs=0.01)
    assert sim.data.xpos[head][2] - height == pytest.approx(0.1, abs=0.005)  # the lift raises the head
    # Panned by 1 rad about +z, the head's forward axis (its x) points 1 rad to the left.
    forward = sim.data.xmat[head].reshape(3, 3)[:, 0]
    assert np.arctan2(forward[1], forward[0]) == pytest.approx(1.0, abs=0.02)


def test_the_hokuyo_in_the_lidar_slot_sees_a_wall_two_metres_ahead(tmp_path: Path):
    sim = simulation_of(tmp_path, WORLD + WALL, "tiago_lite_wall.wbt")
    entry = sim.table.robots[0].device("Hokuyo URG-04LX-UG01")
    assert entry.fields["horizontalResolution"] == 667
    assert entry.fields["fieldOfView"] == pytest.approx(4.18879)
    assert (entry.fields["minRange"], entry.fields["maxRange"]) == pytest.approx((0.2, 5.6))
    lidar = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Lidar))
    for _ in range(20):
        sim.step()
    ranges = lidar.sample(sim)["ranges"]
    sim.close()
    assert len(ranges) == 667
    # The lidar is 0.202 m ahead of the centre: the middle column reads the wall's face at 1.798 m; the
    # columns a quarter of the 240 degrees to either side look 60 degrees off, twice as far.
    assert ranges[333] == pytest.approx(1.798, abs=0.003)
    for k in (166, 500):
        assert ranges[k] == pytest.approx(2 * 1.798, abs=0.02)
