"""A Solid with Physics under Solid ancestors without Physics stays where it is, as Webots' docs say.

Webots attaches such a Solid to the static environment with a fixed joint ("it won't move from its
initial position"); wbtc welds its body to its static parent's.
"""

from pathlib import Path

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
DEF TABLE Solid {
  translation 1 0 0.5
  children [
    DEF BALL Solid {
      translation 0 0 0.5
      children [
        Shape {
          geometry DEF SPHERE Sphere {
            radius 0.05
          }
        }
      ]
      boundingObject USE SPHERE
      physics Physics {
      }
    }
  ]
  name "table"
}
"""


def test_a_ball_with_physics_inside_a_static_solid_does_not_fall(tmp_path: Path):
    world = tmp_path / "static.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    model = result.model
    ball = model.body(result.table.bodies["BALL"]).id
    assert model.body_dofnum[ball] == 0 and model.body_weldid[ball] == 0
    sim = Simulation(result, noise=False)
    for _ in range(50):
        sim.step()
    assert list(sim.data.xpos[ball]) == [1.0, 0.0, 1.0]
