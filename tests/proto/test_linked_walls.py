"""wbtc's LinkedWalls: the wall-following course, segments joined end to end, Webots' customData."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n}\n"
# Webots' default course: six lead-in turns, then its seven wall parts.
DEFAULT_TURNS = [0, 0, -2, 0, 2, 0, -6, -2, -12, 12, 8, -6, 18, -6, -6, -6, -6, 12, 6, 2, -2, -2, -4,
                 -4, 4, -4, 10, -6, 6, 14, -14, -2, -2, -2, -2, 2, -6, 2, 4, -8, 16, -8, -6, 2, 4]


def expand_one(tmp_path: Path, node: str) -> Node:
    """The Robot a LinkedWalls node expands to."""
    text = HEADER + node + "\n"
    world = tmp_path / "walls.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.console == []
    return scene.nodes[1]


def segments(robot: Node) -> list[tuple[str, float, float, float]]:
    """(name, x, y, heading) of every segment Solid."""
    out = []
    for solid in robot.get("children"):
        t, r = solid.get("translation"), solid.get("rotation")
        out.append((solid.get("name"), t.x, t.y, r.angle * (1 if r.z >= 0 else -1)))
    return out


def test_a_supervisor_robot_with_webots_default_course(tmp_path: Path) -> None:
    robot = expand_one(tmp_path, "LinkedWalls { }")
    assert robot.type_name == "Robot" and robot.get("supervisor") is True
    assert robot.get("controller") == "wall_following_supervisor" and robot.get("window") == "wall_following"
    assert robot.get("customData") == f"{len(DEFAULT_TURNS)}," + "".join(f"{a}," for a in DEFAULT_TURNS)
    found = segments(robot)
    assert len(found) == 1 + len(DEFAULT_TURNS)
    assert [name for name, *_ in found] == ["solid"] + [f"wall {i}" for i in range(1, 46)]
    box = robot.get("children")[0].get("children")[0].get("geometry").get("size")
    assert [box.x, box.y, box.z] == pytest.approx([0.01, 1, 0.5])


def test_given_turns_join_segments_end_to_end(tmp_path: Path) -> None:
    robot = expand_one(tmp_path, "LinkedWalls { length 2 height 0.3 angles [ 0 12 -6 ] }")
    found = segments(robot)
    assert robot.get("customData") == "3,0,12,-6,"
    assert [(round(x, 9), round(y, 9)) for _, x, y, _ in found[:3]] == [(0, 0), (0, 2), (-1, 3)]
    assert [h for *_, h in found] == pytest.approx([0, 0, math.pi / 2, math.pi / 4])
    # Every segment's start is the previous segment's end.
    for (_, x0, y0, h0), (_, x1, y1, h1) in zip(found, found[1:], strict=False):
        end = np.array([x0 - math.sin(h0), y0 + math.cos(h0)])
        start = np.array([x1 + math.sin(h1), y1 - math.cos(h1)])
        assert end == pytest.approx(start, abs=1e-9)


def test_the_corpus_placement_runs_the_course_along_minus_y(tmp_path: Path) -> None:
    # As the wall-following competition places it: 5 m ahead of the robot, turned half a turn.
    world = tmp_path / "course.wbt"
    world.write_text(HEADER + "LinkedWalls {\n  translation 5 0 0.25\n  rotation 0 0 1 3.14157\n}\n")
    result, _ = compile_world(world)
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    walls = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX
             and model.geom_contype[g] | model.geom_conaffinity[g]]
    assert len(walls) == 46
    centres = data.geom_xpos[walls]
    assert centres[:, 2] == pytest.approx(np.full(46, 0.25))
    assert centres[:, 1].max() == pytest.approx(0.0, abs=1e-3) and centres[:, 1].min() < -25
    # Inside the competition's 16 x 36 m arena (x from -5 to 11, y from -34 to 2).
    assert centres[:, 0].min() > -5 and centres[:, 0].max() < 11 and centres[:, 1].min() > -34
