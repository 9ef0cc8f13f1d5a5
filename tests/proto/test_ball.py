"""wbtc's Ball: Webots' interface and physics (55 g, inertia 2.3e-5 kg·m², damping), dropped onto a floor."""

from pathlib import Path

import mujoco
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
}
DEF BALL Ball {
  centerOfMass [0 0 0]
}
DEF BIG Ball {
  translation 1 0 0.5
  color 0 0 1
  radius 0.1
  mass 0.5
  name "big ball"
}
"""


def test_a_ball_falls_from_its_default_height_and_rests_on_the_floor(tmp_path: Path):
    world = tmp_path / "ball.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    model = result.model
    ball = model.body(result.table.bodies["BALL"]).id
    assert model.body_mass[ball] == pytest.approx(0.055)
    assert list(model.body_inertia[ball]) == pytest.approx([2.3e-5] * 3)
    big = model.body(result.table.bodies["BIG"]).id
    assert model.body_mass[big] == pytest.approx(0.5)
    assert model.geom_size[model.body_geomadr[big]][0] == pytest.approx(0.1)
    sim = Simulation(result, noise=False)
    assert sim.data.xpos[ball][2] == pytest.approx(0.1625)
    for _ in range(200):  # 3.2 s
        sim.step()
    mujoco.mj_forward(model, sim.data)
    assert sim.data.xpos[ball][2] == pytest.approx(0.0325, abs=1e-3)
    assert sim.data.xpos[big][2] == pytest.approx(0.1, abs=1e-3)


def test_a_soccer_ball_has_webots_size_and_mass_and_rests_on_its_radius(tmp_path: Path):
    world = tmp_path / "soccer.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 16\n}\nFloor {\n}\n"
                     "DEF SOCCER SoccerBall {\n  translation 0 0 0.3\n}\n")
    result, _ = compile_world(world)
    model = result.model
    ball = model.body(result.table.bodies["SOCCER"]).id
    assert model.body_mass[ball] == pytest.approx(0.6)
    recognized = [r for r in result.table.recognizable if r.model == "soccer ball"]
    assert [r.colors for r in recognized] == [[[1.0, 1.0, 1.0], [0.0, 0.0, 0.0]]]
    sim = Simulation(result, noise=False)
    for _ in range(200):
        sim.step()
    assert sim.data.xpos[ball][2] == pytest.approx(0.113, abs=1e-3)
