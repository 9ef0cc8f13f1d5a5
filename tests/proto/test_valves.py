"""wbtc's SmallValve and LargeValve: Robots whose hand wheel turns on a hinge, with Webots' devices and boxes."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 8
}
SmallValve {
  controller "<none>"
  absoluteStop "3.14"
}
LargeValve {
  translation 1 0 0.106
  controller "<none>"
}
DEF SMALL_TOP Solid {
  translation -0.03 0 0.2
  children [ Shape { geometry Sphere { radius 0.01 } } ]
  boundingObject Sphere { radius 0.01 }
  physics Physics { }
}
DEF LARGE_TOP Solid {
  translation 0.95 0 0.3
  children [ Shape { geometry Sphere { radius 0.01 } } ]
  boundingObject Sphere { radius 0.01 }
  physics Physics { }
}
"""


@pytest.fixture()
def compiled(tmp_path: Path):
    world = tmp_path / "valves.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    return result


def test_devices_controller_arguments_and_the_wheels_mass(compiled) -> None:
    small, large = compiled.table.robots
    assert (small.name, large.name) == ("small valve", "large valve")
    for robot in (small, large):
        assert [(d.name, d.type) for d in robot.devices] == [
            ("position sensor", "PositionSensor"), ("rotational motor", "RotationalMotor")]
    assert small.controller_args == ["3.14"] and large.controller_args == ["15.7079632679"]
    model = compiled.model
    # The small wheel: Webots' cylinder of radius 0.027 m and 0.0138 m at density 1000; the body is static.
    wheel = model.jnt_bodyid[model.joint(compiled.table.robots[0].devices[1].joint).id]
    assert model.body_mass[wheel] == pytest.approx(1000 * math.pi * 0.027 ** 2 * 0.0138, rel=1e-3)
    assert model.body_subtreemass[model.body(small.body).id] == pytest.approx(model.body_mass[wheel])


def test_the_wheels_turn_about_x_from_minus_five_half_turns(compiled) -> None:
    sim = Simulation(compiled, noise=False)
    readings = {}
    for robot in sim.robots:
        tags = {d.name: tag for tag, d in enumerate(robot.entry.devices)}
        sensor = robot.sensors[tags["position sensor"]]
        sensor.enable(8, sim.time_ms)
        motor = robot.motors[tags["rotational motor"]]
        motor.apply("setPosition", (math.inf,), sim.time_ms)
        motor.apply("setVelocity", (2.0,), sim.time_ms)
        readings[robot.entry.name] = sensor
    sim.step()
    start = {name: s.value for name, s in readings.items()}
    assert start["small valve"] == pytest.approx(-15.706, abs=0.02)
    assert start["large valve"] == pytest.approx(-5 * math.pi, abs=0.02)
    for _ in range(125):  # 1 s
        sim.step()
    for name, sensor in readings.items():
        assert sensor.value - start[name] == pytest.approx(2.0, abs=0.05), name
    # The wheels' axes are the valves' +x axes.
    model = compiled.model
    for robot in compiled.table.robots:
        axis = sim.data.xaxis[model.joint(robot.devices[1].joint).id]
        assert axis == pytest.approx([1, 0, 0], abs=1e-9)
    sim.close()


def test_balls_rest_on_the_bodies_collision_boxes(compiled) -> None:
    sim = Simulation(compiled, noise=False)
    for _ in range(120):
        sim.step()
    mujoco.mj_forward(compiled.model, sim.data)
    bodies = compiled.table.bodies
    small = sim.data.xpos[compiled.model.body(bodies["SMALL_TOP"]).id]
    large = sim.data.xpos[compiled.model.body(bodies["LARGE_TOP"]).id]
    assert small[2] == pytest.approx(0.077 - 0.0102 + 0.0429 + 0.01, abs=2e-3)
    assert large[2] == pytest.approx(0.106 - 0.0085 + 0.075 + 0.01, abs=2e-3)
    sim.close()
