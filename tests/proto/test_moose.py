"""wbtc's Clearpath Moose: Webots' eight wheel motors in order, its 1590 kg, skid-steer driving."""

from pathlib import Path

import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/clearpath/moose/protos/Moose.proto"
WorldInfo { basicTimeStep 16 }
Floor { size 40 40 }
Moose { translation 0 0 0.4 }
"""
MOTORS = [f"{side} motor {i}" for side in ("right", "left") for i in range(1, 5)]


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "moose.wbt")
    yield simulation
    simulation.close()


def _drive(sim: Simulation, right: float, left: float, steps: int) -> None:
    robot = sim.robots[0]
    for tag, device in enumerate(robot.entry.devices):
        robot.motors[tag].apply("setPosition", (float("inf"),), sim.time_ms)
        robot.motors[tag].apply("setVelocity", (right if device.name.startswith("right") else left,), sim.time_ms)
    for _ in range(steps):
        sim.step()


def test_devices_wheels_and_the_mass(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == MOTORS
    assert all(d.fields["maxVelocity"] == 26 and d.fields["maxTorque"] == 1000 for d in entry.devices)
    model = sim.model
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(1430 + 8 * 20)
    wheel = model.body("moose/left wheel 4").id
    assert model.body_pos[wheel] == pytest.approx([-1.1, 0.6, -0.06])


def test_it_rests_on_its_wheels_and_drives_straight(sim):
    body = sim.model.body(sim.table.robots[0].body).id
    for _ in range(30):
        sim.step()
    start = sim.data.xpos[body].copy()
    assert start[2] == pytest.approx(0.32 + 0.06, abs=0.005)  # wheel radius plus the axles' 0.06 m drop
    _drive(sim, 2.0, 2.0, 125)  # 2 s at 2 rad/s: 0.64 m/s on 0.32 m wheels
    moved = sim.data.xpos[body] - start
    assert moved[0] == pytest.approx(1.28, abs=0.06)
    assert abs(moved[1]) < 0.01


def test_opposite_sides_turn_it_on_the_spot(sim):
    body = sim.model.body(sim.table.robots[0].body).id
    for _ in range(30):
        sim.step()
    start = sim.data.xpos[body].copy()
    _drive(sim, -2.0, 2.0, 125)  # left forwards, right backwards: it turns right (clockwise from above)
    heading = np.arctan2(sim.data.xmat[body][3], sim.data.xmat[body][0])
    assert heading < -0.2
    assert np.linalg.norm(sim.data.xpos[body][:2] - start[:2]) < 0.2
