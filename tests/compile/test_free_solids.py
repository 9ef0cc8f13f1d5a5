"""A Solid with Physics under ancestors without Physics moves on its own, as in Webots."""

from pathlib import Path

import mujoco
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Solid {
  children [
    Shape {
      geometry Plane {
        size 10 10
      }
    }
  ]
  boundingObject Plane {
    size 10 10
  }
}
DEF TABLE Solid {
  translation 1 0 0.5
  rotation 0 0 1 1.5708
  children [
    Pose {
      translation 0.2 0 0
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
    }
  ]
  name "table"
}
"""


def test_a_ball_inside_a_static_solid_falls_to_the_floor(tmp_path: Path):
    world = tmp_path / "free.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    model = result.model
    ball = model.body(result.table.bodies["BALL"]).id
    assert model.body_parentid[ball] == 0 and model.jnt_type[model.body_jntadr[ball]] == mujoco.mjtJoint.mjJNT_FREE
    sim = Simulation(result, noise=False)
    # The table turns its frame a quarter turn: its Pose's 0.2 m along x lands along world y.
    assert list(sim.data.xpos[ball]) == pytest.approx([1.0, 0.2, 1.0], abs=1e-4)
    for _ in range(100):  # 1.6 s: it has fallen 0.95 m in 0.44 s
        sim.step()
    assert list(sim.data.xpos[ball]) == pytest.approx([1.0, 0.2, 0.05], abs=2e-3)
