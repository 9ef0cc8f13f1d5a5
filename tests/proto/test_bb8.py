"""wbtc's BB-8: Webots' device names and order, its masses, and a ball that rolls when the body pitches."""

from pathlib import Path

import mujoco
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/sphero/bb8/protos/BB-8.proto"
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 20 20
}
DEF BB8 BB-8 {
  controller "<none>"
}
"""
DEVICES = [
    ("counterweight accelerometer", "Accelerometer"), ("counterweight gyro", "Gyro"),
    ("body yaw motor", "RotationalMotor"), ("body pitch motor", "RotationalMotor"),
    ("body accelerometer", "Accelerometer"), ("body gyro", "Gyro"),
    ("head yaw motor", "RotationalMotor"), ("head accelerometer", "Accelerometer"), ("head gyro", "Gyro"),
]


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "bb8.wbt")
    yield simulation
    simulation.close()


def _ball(sim: Simulation) -> int:
    """The MuJoCo body of the rolling ball: the body holding the 0.25 m sphere."""
    model = sim.model
    (ball,) = {int(model.geom_bodyid[g]) for g in range(model.ngeom)
               if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_SPHERE and model.geom_contype[g]
               and model.geom_size[g][0] == pytest.approx(0.25)}
    return ball


def test_devices_in_webots_order_and_the_masses(sim):
    entry = sim.table.robots[0]
    assert [(d.name, d.type) for d in entry.devices] == DEVICES
    assert all(d.fields["maxVelocity"] == pytest.approx(8.72) for d in entry.devices if d.type == "RotationalMotor")
    model = sim.model
    root = model.body(entry.body).id
    assert model.body_mass[root] == pytest.approx(20.0)  # the counterweight
    assert model.body_mass[_ball(sim)] == pytest.approx(5.0)
    assert model.body_subtreemass[root] == pytest.approx(20.0 + 5.0 + 0.05 + 1.0)


def test_it_rests_on_its_ball_and_a_positive_pitch_rolls_it_forward(sim):
    tags = {d.name: i for i, d in enumerate(sim.robots[0].entry.devices)}
    ball = _ball(sim)
    for _ in range(30):
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)
    assert sim.data.xpos[ball][2] == pytest.approx(0.25, abs=2e-3)  # the ball on the floor, the head on it
    motor = sim.robots[0].motors[tags["body pitch motor"]]
    motor.apply("setPosition", (float("inf"),), sim.time_ms)
    motor.apply("setVelocity", (2.0,), sim.time_ms)
    for _ in range(188):  # 3 s
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)
    x, y, z = sim.data.xpos[ball]
    assert x > 0.8  # 2 rad/s on a 0.25 m ball: 0.5 m/s once the counterweight has swung
    assert abs(y) < 0.02
    assert z == pytest.approx(0.25, abs=2e-3)
    robot = sim.model.body(sim.table.bodies["BB8"]).id
    assert sim.data.xpos[robot][0] == pytest.approx(x, abs=0.15)  # the swinging counterweight (the robot) follows
