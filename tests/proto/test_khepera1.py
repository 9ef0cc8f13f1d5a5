"""wbtc's Khepera I: Webots' device names and order, its mass, an infra-red reading, and driving straight."""

import math
from pathlib import Path

import mujoco
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/k-team/khepera1/protos/Khepera1.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 4 4
}
Khepera1 {
  controller "<none>"
}
PointLight {
  attenuation 0 0 100
  location 0.527 0 0.0144
  castShadows FALSE
}
Solid {
  translation -0.046 0 0.05
  children [
    Shape {
      geometry Box {
        size 0.02 1 0.1
      }
    }
  ]
  boundingObject Box {
    size 0.02 1 0.1
  }
}
"""
#: Webots' body (cylinder r 28.5 mm, 2 cm) and two wheels (r 7.5 mm, 3 mm), density 1000 kg/m³.
BODY = 1000 * math.pi * 0.0285**2 * 0.02
WHEEL = 1000 * math.pi * 0.0075**2 * 0.003


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "khepera1.wbt")
    yield simulation
    simulation.close()


def _tags(sim: Simulation) -> dict[str, int]:
    return {d.name: i for i, d in enumerate(sim.robots[0].entry.devices)}


def test_devices_in_webots_order_and_the_mass(sim):
    entry = sim.table.robots[0]
    assert [d.name for d in entry.devices] == [
        "left wheel motor", "left wheel sensor", "right wheel motor", "right wheel sensor",
        *[f"ds{i}" for i in range(8)], *[f"ls{i}" for i in range(8)], "led0", "led1", "rs232_out", "rs232_in"]
    kinds = {d.name: d.type for d in entry.devices}
    assert kinds["ds3"] == "DistanceSensor" and kinds["ls3"] == "LightSensor" and kinds["rs232_in"] == "Receiver"
    model = sim.model
    assert model.body_subtreemass[model.body(entry.body).id] == pytest.approx(BODY + 2 * WHEEL, rel=1e-3)


def test_the_rear_sensors_read_a_wall_behind(sim):
    tags = _tags(sim)
    robot = sim.robots[0]
    for name in ("ds6", "ds7", "ds2"):
        robot.sensors[tags[name]].enable(8, sim.time_ms)
    sim.step()
    # ds6/ds7 sit 26 mm behind the centre, the wall's face is at -36 mm: 1 cm, read 1023 - 1 cm x 1023/5 cm.
    assert robot.sensors[tags["ds6"]].value == pytest.approx(1023 * 0.8, abs=2)
    assert robot.sensors[tags["ds7"]].value == pytest.approx(1023 * 0.8, abs=2)
    assert robot.sensors[tags["ds2"]].value == pytest.approx(0)  # nothing ahead


def test_the_light_sensors_read_a_lamp_ahead_through_webots_table(sim):
    tags = _tags(sim)
    robot = sim.robots[0]
    for name in ("ls2", "ls3", "ls6"):
        robot.sensors[tags[name]].enable(8, sim.time_ms)
    sim.step()
    # ls2/ls3 face the lamp 0.5 m ahead: 1 / (100 x 0.25) = 0.04 W/m², read 500 - 0.04 x 490 / 0.2.
    for name in ("ls2", "ls3"):
        assert robot.sensors[tags[name]].value == pytest.approx(402, abs=1)
    assert robot.sensors[tags["ls6"]].value == pytest.approx(500)  # facing away: dark


def test_both_wheels_at_ten_radians_a_second_drive_it_straight(sim):
    tags = _tags(sim)
    robot = sim.robots[0]
    for side in ("left", "right"):
        motor = robot.motors[tags[f"{side} wheel motor"]]
        motor.apply("setPosition", (float("inf"),), sim.time_ms)
        motor.apply("setVelocity", (10.0,), sim.time_ms)
    for _ in range(250):  # 2 s
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)
    body = sim.model.body(sim.table.robots[0].body).id
    x, y, z = sim.data.xpos[body]
    assert x == pytest.approx(10.0 * 0.0075 * 2.0, rel=0.05)  # 15 cm
    assert abs(y) < 2e-3
    assert z == pytest.approx(0.0, abs=1e-3)
