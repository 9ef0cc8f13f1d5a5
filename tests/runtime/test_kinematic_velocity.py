"""Solids without Physics move at their written linearVelocity, and a GPS on them differences positions."""

import math
from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 32 }
Robot {
  translation 0 0 1
  children [ GPS { } ]
  linearVelocity 0 2 0
  controller "<none>"
}
DEF CRATE Solid {
  translation 1 0 0.5
  children [ Shape { geometry DEF B Box { size 0.1 0.1 0.1 } } ]
  boundingObject USE B
  angularVelocity 0 0 1
}
"""


def test_a_solid_without_physics_moves_at_its_written_velocity(tmp_path: Path) -> None:
    world = tmp_path / "kinematic.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    gps = next(tag for tag, entry in enumerate(robot.entry.devices) if entry.type == "GPS")
    apply_commands(sim, robot, [(gps, "enable", 32)])
    sim.step()
    # Webots differences two positions for a GPS that physics does not move: NaN at the first sample.
    assert all(math.isnan(v) for v in robot.sensors[gps].value[3:])
    for _ in range(9):
        sim.step()
    # 10 steps of 32 ms at 2 m/s along +y, without gravity acting (no Physics).
    assert robot.sensors[gps].value[:3] == pytest.approx([0.0, 0.64, 1.0], abs=1e-9)
    assert robot.sensors[gps].value[3:] == pytest.approx([0.0, 2.0, 0.0], abs=1e-9)
    crate = sim.model.body(result.table.bodies["CRATE"]).id
    assert sim.data.xpos[crate].tolist() == pytest.approx([1.0, 0.0, 0.5], abs=1e-9)
    # Turning at 1 rad/s about z for 0.32 s: cos(0.16) = w of its quaternion.
    assert float(sim.data.xquat[crate][0]) == pytest.approx(math.cos(0.16), abs=1e-9)
    sim.close()
