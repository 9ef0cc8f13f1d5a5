"""The Viewpoint's fields follow a Solid as Webots moves them (Tracking Shot rigid or smooth, Mounted Shot)."""

from pathlib import Path

import numpy as np
import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.scene_tree import SceneTree
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.viewpoint_follow import ViewpointFollow, find_solid

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 16 }}
Viewpoint {{ position 3 0 1 follow "group:ball" followType "{kind}" followSmoothness {smoothness} }}
Solid {{
  translation 0 0 2
  name "group"
  children [ Solid {{ name "ball" }} ]
  boundingObject Sphere {{ radius 0.1 }}
  physics Physics {{ }}
}}
"""


def _follow(tmp_path: Path, kind: str, smoothness: float) -> tuple[Simulation, ViewpointFollow]:
    world = tmp_path / "follow.wbt"
    world.write_text(WORLD.format(kind=kind, smoothness=smoothness), encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    return sim, ViewpointFollow(SceneTree(scene), sim)


def _ball_z(sim: Simulation) -> float:
    return float(sim.data.xpos[sim.model.body("group").id][2])  # the ball is fixed at the group's origin


def test_unique_names_join_the_solid_names_from_the_top(tmp_path):
    sim, follow = _follow(tmp_path, "Tracking Shot", 0)
    assert follow.solid is not None and str(follow.solid.get("name")) == "ball"
    assert find_solid(follow.tree, "ball") is None and find_solid(follow.tree, "group:nothing") is None
    sim.close()


def test_a_rigid_tracking_shot_moves_with_the_solid(tmp_path):
    sim, follow = _follow(tmp_path, "Tracking Shot", 0)
    for _ in range(20):
        sim.step()
        follow.step(sim, 0.016)
    position = np.asarray(follow.viewpoint.get("position"), dtype=float)
    assert _ball_z(sim) < 1.5  # it fell
    assert position == pytest.approx([3.0, 0.0, 1.0 + _ball_z(sim) - 2.0], abs=1e-12)
    sim.close()


def test_a_smooth_tracking_shot_lags_behind_then_catches_up(tmp_path):
    sim, follow = _follow(tmp_path, "Tracking Shot", 0.5)
    for _ in range(20):
        sim.step()
        follow.step(sim, 0.016)
    lag = float(follow.viewpoint.get("position")[2]) - (1.0 + _ball_z(sim) - 2.0)
    assert lag > 0.05  # Webots' spring: the viewpoint is still above where a rigid follow would be
    for _ in range(1500):  # the ball held still: Webots' spring (mass 0.5, braked by 0.1 a step) settles on it
        follow.step(sim, 0.016)
    assert float(follow.viewpoint.get("position")[2]) == pytest.approx(1.0 + _ball_z(sim) - 2.0, abs=1e-3)
    sim.close()


def test_a_mounted_shot_keeps_its_pose_relative_to_the_solid(tmp_path):
    sim, follow = _follow(tmp_path, "Mounted Shot", 0)
    sim.data.qvel[3:6] = [0.0, 0.0, 2.0]  # the ball spins about z while it falls
    for _ in range(10):
        sim.step()
        follow.step(sim, 0.016)
    ball = sim.data.xpos[sim.model.body("group").id]
    turn = sim.data.xmat[sim.model.body("group").id].reshape(3, 3)
    position = np.asarray(follow.viewpoint.get("position"), dtype=float)
    assert position == pytest.approx(ball + turn @ np.array([3.0, 0.0, -1.0]), abs=1e-9)
    axis_angle = [float(v) for v in follow.viewpoint.get("orientation")]
    assert axis_angle[3] == pytest.approx(10 * 0.016 * 2.0, abs=0.02) and abs(axis_angle[2]) == pytest.approx(1.0)
    sim.close()
