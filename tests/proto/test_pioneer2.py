"""wbtc's Pioneer 2: Webots' devices in order, no Physics (driven kinematically), its wheels and its ring sensors."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

# A white wall whose face is 0.5 m ahead of the robot's origin, 1 m wide and 0.4 m high.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 10 10
}
Pioneer2 {
  controller "<none>"
}
Solid {
  translation %s 0 0.2
  children [
    Shape {
      appearance PBRAppearance {
        baseColor 1 1 1
        metalness 0
      }
      geometry Box {
        size 0.02 1 0.4
      }
    }
  ]
  boundingObject Box {
    size 0.02 1 0.4
  }
}
"""


def compiled(tmp_path: Path, wall_x: float = 0.51):
    """The test world compiled, with the wall's centre at `wall_x` (its face 0.01 m nearer)."""
    world = tmp_path / "pioneer2.wbt"
    world.write_text(WORLD % wall_x)
    result, _ = compile_world(world)
    return result


def lookup(distance: float) -> float:
    """Webots' Pioneer 2 table: 1024 up to 0.2 m, down to 0 at 0.4 m."""
    return float(np.interp(distance, [0, 0.2, 0.4], [1024, 1024, 0]))


def test_devices_in_webots_order_and_a_kinematic_drive(tmp_path: Path) -> None:
    result = compiled(tmp_path)
    robot = result.table.robots[0]
    assert [d.name for d in robot.devices] == [
        "left wheel motor", "left wheel sensor", "right wheel motor", "right wheel sensor",
        *[f"ds{i}" for i in range(16)]]
    assert robot.name == "Pioneer 2"
    # No Physics, as in Webots: the two wheels (radius 0.0825 m) slide the robot kinematically.
    assert robot.drive is not None
    assert robot.drive.motors == ("left wheel motor", "right wheel motor")
    assert robot.drive.radius == pytest.approx(0.0825)


def _wheel_angle(speed: float, steps: int, ts: float = 0.016) -> float:
    """A wheel's turn in `steps` steps from rest under Webots' kinematic motor rule: without Physics the
    default motor (10 N·m) speeds up at 10 rad/s² (its torque read as an acceleration) to `speed`."""
    return sum(min(10.0 * ts * k, speed) for k in range(1, steps + 1)) * ts


def _run(result, left: float, right: float, seconds: float) -> Simulation:
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {d.name: tag for tag, d in enumerate(robot.entry.devices)}
    for name, speed in (("left wheel motor", left), ("right wheel motor", right)):
        robot.motors[tags[name]].apply("setPosition", (math.inf,), sim.time_ms)
        robot.motors[tags[name]].apply("setVelocity", (speed,), sim.time_ms)
    for _ in range(round(seconds * 1000 / 16)):
        sim.step()
    mujoco.mj_forward(result.model, sim.data)
    return sim


def test_it_drives_straight_and_turns_on_the_spot(tmp_path: Path) -> None:
    result = compiled(tmp_path, wall_x=5.0)
    body = result.model.body(result.table.robots[0].body).id
    sim = _run(result, 2.0, 2.0, 1.0)
    x, y, _ = sim.data.xpos[body]
    assert x == pytest.approx(_wheel_angle(2.0, 62) * 0.0825, abs=1e-9) and abs(y) < 1e-6
    result = compiled(tmp_path, wall_x=5.0)  # afresh: the kinematic drive moves the model's root body
    sim = _run(result, -1.0, 1.0, 1.0)
    heading = math.atan2(sim.data.xmat[body][3], sim.data.xmat[body][0])
    assert heading == pytest.approx(2 * _wheel_angle(1.0, 62) * 0.0825 / (2 * 0.1603), abs=1e-6)  # 0.49 rad left
    assert np.linalg.norm(sim.data.xpos[body][:2]) < 1e-3


def test_the_front_sensors_read_the_wall(tmp_path: Path) -> None:
    sim = Simulation(compiled(tmp_path), noise=False)
    robot = sim.robots[0]
    tags = {d.name: tag for tag, d in enumerate(robot.entry.devices)}
    sensors = {i: robot.sensors[tags[f"ds{i}"]] for i in range(16)}
    for sensor in sensors.values():
        sensor.enable(16, sim.time_ms)
    sim.step()
    # ds0 and ds15 are 0.164 m ahead and look 10 degrees aside: 0.341 m to the wall's face at 0.5 m.
    expected = lookup((0.5 - 0.164) / math.cos(math.radians(10)))
    assert 250 < expected < 350
    assert sensors[0].value == pytest.approx(expected, abs=2)
    assert sensors[15].value == pytest.approx(expected, abs=2)
    # ds1 and ds14 (30 degrees) see the wall 0.41 m away, beyond the table; the sides and the back see nothing.
    assert all(sensors[i].value == 0 for i in range(1, 15))


def test_a_near_wall_saturates_and_stops_the_robot(tmp_path: Path) -> None:
    result = compiled(tmp_path, wall_x=0.3)  # face at 0.29 m: 0.128 m from ds0 along its ray
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    ds0 = robot.sensors[[d.name for d in robot.entry.devices].index("ds0")]
    ds0.enable(16, sim.time_ms)
    sim.step()
    assert ds0.value == pytest.approx(1024)
    result = compiled(tmp_path, wall_x=0.3)
    sim = _run(result, 5.0, 5.0, 1.0)  # would go 0.41 m; the 0.219 m cylinder stops at the wall
    x = sim.data.xpos[result.model.body(result.table.robots[0].body).id][0]
    assert x == pytest.approx(0.29 - 0.219 + 0.0447, abs=0.01)
