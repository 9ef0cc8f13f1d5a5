"""wbtc's SoccerField, Walls and Goal: the Webots 7 DARwIn-OP soccer sample's PROTOs in an old world and a new one."""

from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

from wbtc.runtime.simulation import Simulation

# A world written as the Webots 7 DARwIn-OP soccer sample uses these PROTOs (NUE axes: y up; the field's
# length along x). wbtc's model frame of such a world has old x along model y and old y (up) along model z.
OLD_WORLD = """#VRML_SIM V7.4.1 utf8
WorldInfo {
  basicTimeStep 16
}
Viewpoint {
  orientation 0 1 0 0
  position 0 1 5
}
Background {
  skyColor [
    0.6 0.8 0.9
  ]
}
DirectionalLight {
  direction -0.5 -2 -0.5
}
DEF FIELD SoccerField {
}
DEF WALLS Walls {
}
DEF YELLOW_GOAL Goal {
  translation 3 0 0
  postColor 0.99 0.85 0.22
}
DEF BLUE_GOAL Goal {
  translation -3 0 0
  rotation 0 1 0 3.14159
  postColor 0.15 0.5 0.73
}
DEF BALL Ball {
  translation 0 0.2 0
}
"""

NEW_WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 8
}
DEF FIELD SoccerField {
  contactMaterial "carpet"
}
DEF WALLS Walls {
  color 0.2 0.2 0.8
  locked FALSE
  name "walls"
}
DEF GOAL Goal {
  translation 3 0 0
  name "white goal"
  postRadius 0.06
  frameColor 0.9 0.9 0.9
}
DEF SHOT Solid {
  translation 2.5 0.2 0.0325
  children [
    DEF SHOT_BALL Shape {
      geometry Sphere {
        radius 0.0325
      }
    }
  ]
  name "shot"
  boundingObject USE SHOT_BALL
  physics Physics {
    density -1
    mass 0.055
  }
  linearVelocity 3 0 0
}
DEF OUT Solid {
  translation 0 2.5 0.0325
  children [
    DEF OUT_BALL Shape {
      geometry Sphere {
        radius 0.0325
      }
    }
  ]
  name "out"
  boundingObject USE OUT_BALL
  physics Physics {
    density -1
    mass 0.055
  }
  linearVelocity 0 2 0
}
"""


def _geoms(sim: Simulation, body: int, colliding: bool) -> list[int]:
    """The collision (or visual) geoms of `body`, in model order."""
    model = sim.model
    return [
        g
        for g in range(model.ngeom)
        if model.geom_bodyid[g] == body and bool(model.geom_contype[g] or model.geom_conaffinity[g]) == colliding
    ]


def _steps(sim: Simulation, seconds: float) -> None:
    """Advance `sim` by `seconds` of simulated time."""
    for _ in range(round(seconds * 1000 / sim.step_ms)):
        sim.step()


@pytest.fixture
def old(tmp_path: Path) -> Iterator[Simulation]:
    simulation = simulation_of(tmp_path, OLD_WORLD, "soccer.wbt")
    yield simulation
    simulation.close()


def test_the_old_sample_gets_coloured_goals_on_its_goal_lines_with_their_nets_outside(old: Simulation) -> None:
    model, data = old.model, old.data
    mujoco.mj_forward(model, data)
    for name, side, colour in (("YELLOW_GOAL", 1, [0.99, 0.85, 0.22]), ("BLUE_GOAL", -1, [0.15, 0.5, 0.73])):
        goal = model.body(old.table.bodies[name]).id
        assert model.body_weldid[goal] == 0  # static
        solid = _geoms(old, goal, colliding=True)
        posts = [
            g for g in solid if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CYLINDER and data.geom_xpos[g][2] < 0.5
        ]
        # Old x (the field's length) is model y, old z is model x: posts 1.4 m apart (inside) on the goal line.
        assert sorted(data.geom_xpos[g][0] for g in posts) == pytest.approx([-0.75, 0.75])
        assert all(data.geom_xpos[g][1] == pytest.approx(3 * side) for g in posts)
        assert all(model.geom_size[g][0] == pytest.approx(0.05) for g in posts)
        back = max(solid, key=lambda g: abs(data.geom_xpos[g][1]))  # the back net, beyond the goal line
        assert data.geom_xpos[back][1] == pytest.approx(side * 3.41)
        visible = _geoms(old, goal, colliding=False)
        assert any(list(model.geom_rgba[g][:3]) == pytest.approx(colour, abs=1e-3) for g in visible)


def test_the_old_sample_field_holds_the_ball_and_its_walls_enclose_the_carpet(old: Simulation) -> None:
    model, data = old.model, old.data
    ball = model.body(old.table.bodies["BALL"]).id
    mujoco.mj_forward(model, data)
    walls = model.body(old.table.bodies["WALLS"]).id
    boxes = _geoms(old, walls, colliding=True)
    assert len(boxes) == 4 and all(model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX for g in boxes)
    inner = []
    for g in boxes:
        centre = data.geom_xpos[g]
        half = np.abs(data.geom_xmat[g].reshape(3, 3)) @ model.geom_size[g]  # world-frame half extents
        across = int(np.argmax(np.abs(centre[:2])))
        inner.append(abs(centre[across]) - half[across])
        assert centre[2] + half[2] == pytest.approx(0.3)  # 0.3 m high
    # Old x (the field's length) is model y: inner faces on the 7.4 x 5.4 m carpet's edges.
    assert sorted(inner) == pytest.approx([2.7, 2.7, 3.7, 3.7])
    field = model.body(old.table.bodies["FIELD"]).id
    (ground,) = _geoms(old, field, colliding=True)
    assert model.geom_type[ground] == mujoco.mjtGeom.mjGEOM_PLANE
    _steps(old, 1.5)
    assert data.xpos[ball][2] == pytest.approx(0.0325, abs=1e-3)  # on the field's ground plane


def test_a_shot_ends_in_the_net_and_a_ball_out_of_play_stops_at_the_wall(tmp_path: Path) -> None:
    sim = simulation_of(tmp_path, NEW_WORLD, "soccer_new.wbt")
    try:
        model, data = sim.model, sim.data
        goal = model.body(sim.table.bodies["GOAL"]).id
        posts = [g for g in _geoms(sim, goal, colliding=True) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CYLINDER]
        assert all(model.geom_size[g][0] == pytest.approx(0.06) for g in posts)
        visible = _geoms(sim, goal, colliding=False)
        assert any(list(model.geom_rgba[g][:3]) == pytest.approx([0.9, 0.9, 0.9]) for g in visible)  # white posts
        shot, out = (model.body(sim.table.bodies[name]).id for name in ("SHOT", "OUT"))
        crossed, reach = False, 0.0
        for _ in range(250):  # 2 s
            sim.step()
            crossed = crossed or data.xpos[shot][0] > 3.1
            reach = max(reach, data.xpos[out][1])
        assert crossed  # through the open mouth...
        assert 3.0 < data.xpos[shot][0] < 3.4 - 0.0325 + 1e-3  # ...and held by the back net
        assert abs(data.xpos[shot][1]) < 0.7
        assert reach == pytest.approx(2.7 - 0.0325, abs=5e-3)  # stopped by the wall's inner face
        assert data.xpos[out][1] < reach  # and sent back
        assert data.xpos[shot][2] == pytest.approx(0.0325, abs=2e-3)
    finally:
        sim.close()
