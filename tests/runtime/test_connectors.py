"""Connector: presence of a compatible peer in position, lock snaps and holds it, unlock lets it go."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import Simulation

# A static robot's connector looks along -x at a free box whose connector looks along +x, 4 mm off in x
# and 3 mm off in y (within distanceTolerance 0.01), turned 0.1 rad about the docking axis (within 0.2).
WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Robot {
  translation 0.3 0 0.5
  children [
    Connector {
      rotation 0 0 1 3.14159265
      type "%s"
    }
  ]
  controller "<none>"
}
DEF BOX Solid {
  translation 0.246 0.003 0.5
  rotation 1 0 0 0.1
  children [
    Connector {
      translation 0.05 0 0
      type "%s"
    }
    DEF SHAPE Shape {
      geometry Box {
        size 0.1 0.1 0.1
      }
    }
  ]
  boundingObject USE SHAPE
  physics Physics {
    mass 0.5
  }
}
"""


def _world(tmp_path: Path, mine: str = "symmetric", theirs: str = "symmetric"):
    world = tmp_path / "dock.wbt"
    world.write_text(WORLD % (mine, theirs))
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    return sim, sim.robots[0], sim.model.body(result.table.bodies["BOX"]).id


def test_a_locked_connector_snaps_and_holds_its_peer_then_lets_it_go(tmp_path: Path):
    sim, robot, box = _world(tmp_path)
    connector = 0
    apply_commands(sim, robot, [(connector, "enablePresence", 16)])
    sim.step()
    assert robot.sensors[connector].value == 1
    apply_commands(sim, robot, [(connector, "lock")])
    for _ in range(60):
        sim.step()
    # Snapped: the two connector origins coincide (box centre 0.05 m behind its connector), rotation 0.
    assert sim.data.xpos[box] == pytest.approx([0.25, 0.0, 0.5], abs=2e-3)
    assert sim.data.xquat[box] == pytest.approx([1.0, 0.0, 0.0, 0.0], abs=2e-3)
    apply_commands(sim, robot, [(connector, "unlock")])
    for _ in range(30):
        sim.step()
    assert sim.data.xpos[box][2] < 0.2  # falling


@pytest.mark.parametrize(("mine", "theirs", "presence"), [("active", "passive", 1), ("active", "active", 0),
                                                           ("passive", "active", -1)])
def test_presence_follows_the_connector_types(tmp_path: Path, mine: str, theirs: str, presence: int):
    sim, robot, _ = _world(tmp_path, mine, theirs)
    apply_commands(sim, robot, [(0, "enablePresence", 16)])
    sim.step()
    assert robot.sensors[0].value == presence
