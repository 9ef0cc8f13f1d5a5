"""wbtc's ROSbot: Webots' device names, types and order, its masses, a range reading, and skid-steer driving."""

import math
from pathlib import Path

import mujoco
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/husarion/rosbot/protos/Rosbot.proto"
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 10 10
}
DEF ROSBOT Rosbot {
  controller "<none>"
}
Solid {
  translation 1.11 0 0.1
  children [
    Shape {
      geometry Box {
        size 0.02 2 0.2
      }
    }
  ]
  boundingObject Box {
    size 0.02 2 0.2
  }
}
"""
MOTORS = ["fl_wheel_joint", "fr_wheel_joint", "rl_wheel_joint", "rr_wheel_joint"]
DEVICES = [
    *[(n, t) for m, s in zip(MOTORS, ("front left", "front right", "rear left", "rear right"), strict=True)
      for n, t in ((m, "RotationalMotor"), (f"{s} wheel motor sensor", "PositionSensor"))],
    ("imu accelerometer", "Accelerometer"), ("imu gyro", "Gyro"), ("imu compass", "Compass"),
    ("imu inertial_unit", "InertialUnit"),
    *[(f"{c}_range", "DistanceSensor") for c in ("fl", "fr", "rl", "rr")],
    ("camera rgb", "Camera"), ("camera depth", "RangeFinder"), ("laser", "Lidar"),
]


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "rosbot.wbt")
    yield simulation
    simulation.close()


def _tags(sim: Simulation) -> dict[str, int]:
    return {d.name: i for i, d in enumerate(sim.robots[0].entry.devices)}


def _drive(sim: Simulation, left: float, right: float, steps: int) -> None:
    robot, tags = sim.robots[0], _tags(sim)
    for name, speed in zip(MOTORS, (left, right, left, right), strict=True):
        motor = robot.motors[tags[name]]
        motor.apply("setPosition", (float("inf"),), sim.time_ms)
        motor.apply("setVelocity", (speed,), sim.time_ms)
    for _ in range(steps):
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)


def test_devices_in_webots_order_and_the_masses(sim):
    entry = sim.table.robots[0]
    assert [(d.name, d.type) for d in entry.devices] == DEVICES
    devices = {d.name: d for d in entry.devices}
    assert all(devices[m].fields["maxVelocity"] == 26 and devices[m].fields["maxTorque"] == 100 for m in MOTORS)
    assert (devices["camera rgb"].fields["width"], devices["camera rgb"].fields["height"]) == (640, 480)
    assert devices["camera depth"].fields["maxRange"] == 8
    assert devices["laser"].fields["horizontalResolution"] == 400
    assert devices["laser"].fields["maxRange"] == 12
    model = sim.model
    # Body 0.45, wheels 4 x 0.5, IMU 0.01, Astra 0.19, lidar 0.2.
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(0.45 + 2.0 + 0.01 + 0.19 + 0.2)


def test_the_front_ranges_read_a_wall_in_metres(sim):
    robot, tags = sim.robots[0], _tags(sim)
    for name in ("fl_range", "fr_range", "rl_range"):
        robot.sensors[tags[name]].enable(16, sim.time_ms)
    sim.step()
    # The sensors are 0.1 m ahead and 5 cm aside, turned 0.13 rad outwards; the wall's face is at x = 1.1 m.
    expected = 1.0 / math.cos(0.13)
    assert robot.sensors[tags["fl_range"]].value == pytest.approx(expected, abs=0.01)
    assert robot.sensors[tags["fr_range"]].value == pytest.approx(expected, abs=0.01)
    assert robot.sensors[tags["rl_range"]].value == pytest.approx(2.0)  # nothing behind: the table's end


def test_the_lidar_sees_the_wall_ahead_in_its_middle_column(sim):
    robot, tags = sim.robots[0], _tags(sim)
    lidar = robot.sensors[tags["laser"]]
    lidar.enable(16, sim.time_ms)
    for _ in range(12):  # more than a turn at 12 turns a second
        sim.step()
    ranges = lidar.sample(sim)["ranges"]
    assert len(ranges) == 400
    # The lidar is 2 cm ahead of the centre: the wall's face 1.08 m ahead, column 200 of 400 looking ahead.
    assert ranges[200] == pytest.approx(1.08, abs=0.01)
    assert ranges[0] == float("inf")  # nothing behind within 12 m


def test_four_wheels_drive_it_straight_and_opposite_sides_turn_it(sim):
    body = sim.model.body(sim.table.bodies["ROSBOT"]).id
    _drive(sim, 5.0, 5.0, 125)  # 2 s at 5 rad/s
    x, y, z = sim.data.xpos[body]
    # The wheels roll without slipping: the distance is their turn times their 0.043 m radius. (wbtc's
    # velocity servo loses speed to the joints' damping of 5 N·m·s/rad: about 4 rad/s instead of 5.)
    model = sim.model
    turned = [sim.data.qpos[model.jnt_qposadr[model.joint(f"rosbot/{w} wheel").id]]
              for w in ("front left", "front right", "rear left", "rear right")]
    assert min(turned) > 0.75 * 10.0
    assert x == pytest.approx(0.043 * sum(turned) / 4, rel=0.03)
    assert abs(y) < 0.01
    assert z == pytest.approx(0.0, abs=2e-3)
    _drive(sim, -5.0, 5.0, 60)  # left wheels back, right forwards: it turns left (counter-clockwise)
    w, _, _, qz = sim.data.xquat[body]
    assert 2 * math.atan2(qz, w) > 0.3
