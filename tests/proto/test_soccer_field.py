"""wbtc's RobotstadiumSoccerField and RobotstadiumGoal: Webots' carpet, walls and goals, and a ball that
bounces off a goal post but enters the goal mouth and stops at the net."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

BALL = """DEF {name} Solid {{
  translation {x} {y} 0.1
  children [
    Shape {{
      geometry DEF BALL_SPHERE_{name} Sphere {{
        radius 0.1
      }}
    }}
  ]
  name "{name}"
  boundingObject USE BALL_SPHERE_{name}
  physics Physics {{
    density -1
    mass 0.4
  }}
  linearVelocity {vx} 0 0
}}
"""


def _compile(tmp_path: Path, body: str):
    world = tmp_path / "field.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 16\n}\n" + body)
    result, _ = compile_world(world)
    return result


def _collision_geoms(model: mujoco.MjModel, body: int) -> list[tuple[int, list[float], list[float]]]:
    """(type, position, size) of the colliding geoms of one body, in the body's frame."""
    return [(int(model.geom_type[g]), [round(float(v), 4) for v in model.geom_pos[g]],
             [round(float(v), 4) for v in model.geom_size[g]])
            for g in range(model.ngeom) if model.geom_bodyid[g] == body and model.geom_contype[g]]


def test_carpet_walls_and_two_goals_as_webots(tmp_path: Path) -> None:
    result = _compile(tmp_path, "DEF FIELD RobotstadiumSoccerField {\n  postRadius 0.06\n}\n")
    model = result.model
    field = model.body(result.table.bodies["FIELD"]).id
    box, plane, capsule, cylinder = (int(t) for t in (mujoco.mjtGeom.mjGEOM_BOX, mujoco.mjtGeom.mjGEOM_PLANE,
                                                      mujoco.mjtGeom.mjGEOM_CAPSULE, mujoco.mjtGeom.mjGEOM_CYLINDER))
    assert _collision_geoms(model, field) == [
        (plane, [0, 0, 0], [5.2, 3.7, 0.1]),
        (box, [5.2, 0, 0.15], [0.01, 3.7, 0.15]), (box, [-5.2, 0, 0.15], [0.01, 3.7, 0.15]),
        (box, [0, 3.7, 0.15], [5.2, 0.01, 0.15]), (box, [0, -3.7, 0.15], [5.2, 0.01, 0.15]),
    ]
    goal1, goal2 = model.body("goal 1").id, model.body("goal 2").id
    assert list(model.body_pos[goal1]) == pytest.approx([4.55, 0, 0])
    assert list(model.body_pos[goal2]) == pytest.approx([-4.55, 0, 0])
    assert model.body_parentid[goal1] == field and model.body_mass[goal1] == 0  # static
    goal = _collision_geoms(model, goal1)
    assert goal == _collision_geoms(model, goal2)
    assert goal == [
        (capsule, [0, 0, 0.85], [0.06, 0.8, 0]),                               # crossbar, 1.6 m
        (cylinder, [0, 0.8, 0.425], [0.06, 0.425, 0]),                         # posts, 0.85 m
        (cylinder, [0, -0.8, 0.425], [0.06, 0.425, 0]),
        (box, [0.275, 0.8, 0.425], [0.225, 0.02, 0.425]),                      # net sides
        (box, [0.275, -0.8, 0.425], [0.225, 0.02, 0.425]),
        (box, [0.6, 0, 0.425], [0.1, 0.82, 0.425]),                            # behind the net
    ]
    # Goal 2 faces goal 1: its net lies beyond x = -4.55.
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    back = [g for g in range(model.ngeom) if model.geom_bodyid[g] == goal2 and model.geom_contype[g]][-1]
    assert list(data.geom_xpos[back]) == pytest.approx([-5.15, 0, 0.425], abs=1e-4)


def test_the_lines_lie_on_the_carpet_within_the_walls(tmp_path: Path) -> None:
    result = _compile(tmp_path, "RobotstadiumSoccerField {\n}\n")
    model = result.model
    meshes = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH]
    assert len(meshes) == 1 and not model.geom_contype[meshes[0]]  # drawn only
    mesh = model.geom_dataid[meshes[0]]
    start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    # MuJoCo keeps mesh vertices about the mesh's centre: back to the field's frame.
    local = model.mesh_vert[start:start + count]
    points = data.geom_xpos[meshes[0]] + local @ data.geom_xmat[meshes[0]].reshape(3, 3).T
    assert points[:, 2] == pytest.approx(np.full(count, 0.001), abs=1e-6)
    # Outer edges of the touch and goal lines: 9 x 6 m inside 5 cm lines.
    assert points[:, 0].max() == pytest.approx(4.55, abs=1e-6)
    assert points[:, 1].max() == pytest.approx(3.05, abs=1e-6)
    assert points[:, 1].min() == pytest.approx(-3.05, abs=1e-6)


def test_a_ball_bounces_off_a_post_and_enters_the_goal_mouth(tmp_path: Path) -> None:
    # Both balls roll towards goal 1 at 3 m/s: one at the left post, one at the middle of the goal.
    result = _compile(tmp_path, "RobotstadiumSoccerField {\n}\n"
                      + BALL.format(name="POST", x=3.6, y=0.8, vx=3)
                      + BALL.format(name="MOUTH", x=3.6, y=0, vx=3))
    sim = Simulation(result, noise=False)
    post = result.model.body(result.table.bodies["POST"]).id
    mouth = result.model.body(result.table.bodies["MOUTH"]).id
    max_post = max_mouth = 0.0
    for _ in range(75):  # 1.2 s
        sim.step()
        max_post = max(max_post, float(sim.data.xpos[post][0]))
        max_mouth = max(max_mouth, float(sim.data.xpos[mouth][0]))
    # The post's front is at 4.5 m: the ball's centre never passes 4.4 m and it comes back.
    assert max_post < 4.4 + 0.015  # MuJoCo's soft contact lets it in by a few mm
    assert sim.data.xpos[post][0] < 4.35
    assert sim.data.cvel[post][3] < 0
    # The open mouth lets the other ball past the goal line; the net's back block (from 5.05 m) stops it.
    assert max_mouth > 4.6
    assert max_mouth < 4.95 + 0.015
    assert sim.data.xpos[post][2] == pytest.approx(0.1, abs=2e-3)  # on the carpet
