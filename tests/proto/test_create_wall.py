"""wbtc's CreateWall: a 0.2 kg Robot whose infra-red emitter reaches a Create's receiver in its cone and range."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.devices import Emitter, Receiver
from wbtc.runtime.simulation import Simulation

# The wall at the origin beams along +x; Creates on its axis 1 m and 3 m away (its range is 2.44 m), and
# one 1 m away but 30 degrees off its 0.157 rad cone.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 10 10
}
CreateWall {
  controller "<none>"
}
Create {
  translation 1 0 0.044
  name "near"
  controller "<none>"
}
Create {
  translation 3 0 0.044
  name "far"
  controller "<none>"
}
Create {
  translation 0.866 0.5 0.044
  name "aside"
  controller "<none>"
}
"""


@pytest.fixture()
def compiled(tmp_path: Path):
    world = tmp_path / "create_wall.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    return result


def test_a_robot_with_one_infra_red_emitter_and_its_mass(compiled) -> None:
    wall = compiled.table.robots[0]
    assert wall.name == "iRobot wall"
    assert [(d.name, d.type) for d in wall.devices] == [("emitter", "Emitter")]
    emitter = wall.devices[0]
    assert emitter.fields["type"] == "infra-red" and emitter.fields["channel"] == 1
    assert emitter.fields["range"] == pytest.approx(2.4384) and emitter.fields["aperture"] == pytest.approx(0.157)
    model = compiled.model
    assert model.body_subtreemass[model.body(wall.body).id] == pytest.approx(0.2)


def test_it_stands_on_the_floor(compiled) -> None:
    sim = Simulation(compiled, noise=False)
    for _ in range(30):
        sim.step()
    mujoco.mj_forward(compiled.model, sim.data)
    body = compiled.model.body(compiled.table.robots[0].body).id
    assert sim.data.xpos[body][2] == pytest.approx(0.0, abs=2e-3)  # the frame is at the casing's bottom
    sim.close()


def test_the_beam_reaches_the_create_in_its_cone_and_range(compiled) -> None:
    sim = Simulation(compiled, noise=False)
    receivers = {}
    for robot in sim.robots:
        for sensor in robot.sensors.values():
            if isinstance(sensor, Receiver):
                sensor.enable(16, 0.0)
                receivers[robot.entry.name] = sensor
    emitter = next(e for r in sim.robots for e in r.emitters.values() if isinstance(e, Emitter))
    sim.packets.append((emitter, b"\xff", emitter.channel))
    sim.step()
    assert [len(receivers[name].value) for name in ("near", "far", "aside")] == [1, 0, 0]
    sim.close()
