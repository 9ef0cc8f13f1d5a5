"""wbtc's RoadIntersection: Webots' layout of the centre polygon and of the start roads, for 4 and 3 roads."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.runtime.simulation import Simulation
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text


def expand(tmp_path: Path, nodes: str, console: list[str] | None = None) -> list[Node]:
    """The top-level nodes after the world `nodes` is expanded (WorldInfo left out); `console`: the messages."""
    text = f"#VRML_SIM R2025a utf8\nWorldInfo {{\n}}\n{nodes}\n"
    world = tmp_path / "intersection.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.console == (console or [])
    return scene.nodes[1:]


def polygon(face_set: Node) -> np.ndarray:
    """The corners of the centre polygon, in order, after checking that its triangles face up and tile it."""
    points = np.asarray(face_set.get("coord").get("point"), dtype=float).reshape(-1, 3)
    index = np.asarray(face_set.get("coordIndex")).reshape(-1, 4)
    assert np.all(index[:, 3] == -1)
    corners = points[:-1]  # the last point is the centre of the fan
    assert np.allclose(points[-1], 0)
    areas = [area(points[face[:3]]) for face in index]
    assert all(a > 0 for a in areas) and sum(areas) == pytest.approx(area(corners))
    return corners


def area(corners: np.ndarray) -> float:
    """Signed area seen from above (positive: counter-clockwise)."""
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def roads(node: Node, prefix: str) -> list[dict]:
    """The field values of the Road instances among the children whose name starts with `prefix`."""
    return [c.proto.values for c in node.get("children")
            if c.proto is not None and c.proto.name == "Road" and str(c.get("name")).startswith(prefix)]


def surface_extent(node: Node, name: str) -> np.ndarray:
    """(min, max) of the x and y of the road surface of the Road `name`, in its own frame."""
    [road] = [c for c in node.get("children") if c.type_name == "Solid" and c.get("name") == name]
    points = np.asarray(road.get("children")[1].get("geometry").get("coord").get("point"), dtype=float)
    points = points.reshape(-1, 3)
    return np.array([points[:, :2].min(axis=0), points[:, :2].max(axis=0)])


def test_four_roads_centre_square_and_start_roads(tmp_path: Path) -> None:
    [crossing] = expand(tmp_path, "RoadIntersection { }")
    centre = polygon(crossing.get("children")[0].get("geometry"))
    outer = 7 / (2 * math.sin(math.pi / 4))
    # A square of side 7 with its corners on the axes, at 4.95 m, facing up.
    assert len(centre) == 4
    assert area(centre) == pytest.approx(49.0)
    assert np.allclose(np.linalg.norm(centre[:, :2], axis=1), outer)
    assert {tuple(np.round(p[:2], 6)) for p in centre} == {
        (0.0, round(outer, 6)), (round(outer, 6), 0.0), (0.0, round(-outer, 6)), (round(-outer, 6), 0.0)}
    surfaces = roads(crossing, "road ")
    assert [str(r["name"]) for r in surfaces] == ["road 0", "road 1", "road 2", "road 3"]
    for i, road in enumerate(surfaces):
        a = 2 * math.pi * (i + 0.5) / 4
        t = road["translation"]
        # Each road starts on the middle of a side, 3.5 m out, and runs outwards for 5 m.
        assert [t.x, t.y, t.z] == pytest.approx([3.5 * math.sin(a), 3.5 * math.cos(a), 0], abs=1e-6)
        assert road["rotation"].angle == pytest.approx(math.pi / 2 - a, abs=1e-6)
        assert [list(p) for p in road["wayPoints"]] == [[0, 0, 0], [5, 0, 0]]
        assert road["width"] == 7 and road["numberOfLanes"] == 2
        assert road["rightBorder"] is False and road["leftBorder"] is False
    assert surface_extent(crossing, "road 2") == pytest.approx(np.array([[0, -3.5], [5, 3.5]]))
    # Sidewalks along each road from the polygon, widening from 0 to 0.8 m where neighbours meet (0.8 m
    # along each road), as Webots lays them out.
    borders = roads(crossing, "border ")
    assert len(borders) == 4
    assert [list(p) for p in borders[0]["wayPoints"]] == [[0, 0, 0], pytest.approx([0.8, 0, 0]), [5, 0, 0]]
    assert list(borders[0]["roadBorderWidth"]) == pytest.approx([0, 0.8])
    assert np.linalg.norm([borders[0]["translation"].x, borders[0]["translation"].y]) == pytest.approx(3.5)


def test_road_start_edges_meet_the_centre_corners(tmp_path: Path) -> None:
    [crossing] = expand(tmp_path, "RoadIntersection { roadNumber 3 roadsWidth 6 startRoadsLength [2, 3, 4] "
                                  "startRoadBorder FALSE }")
    centre = polygon(crossing.get("children")[0].get("geometry"))
    assert len(centre) == 3
    assert area(centre) == pytest.approx(math.sqrt(3) / 4 * 36)  # equilateral, side 6
    corners = {tuple(np.round(p[:2], 5)) for p in centre}
    surfaces = roads(crossing, "road ")
    assert roads(crossing, "border ") == []
    assert [r["wayPoints"][1][0] for r in surfaces] == [2, 3, 4]
    for road in surfaces:
        t, angle = road["translation"], road["rotation"].angle
        left = np.array([t.x - 3 * math.sin(angle), t.y + 3 * math.cos(angle)])
        right = np.array([t.x + 3 * math.sin(angle), t.y - 3 * math.cos(angle)])
        assert tuple(np.round(left, 5)) in corners and tuple(np.round(right, 5)) in corners


def test_a_single_length_serves_all_roads_and_zero_draws_none(tmp_path: Path) -> None:
    [crossing] = expand(tmp_path, "RoadIntersection { roadNumber 5 startRoadsLength [0] }")
    assert roads(crossing, "") == []
    [crossing] = expand(tmp_path, "RoadIntersection { roadNumber 2 startRoadsLength [] }", [
        "RoadIntersection: 'roadNumber' must be at least 3. Value reset to 4."])
    assert len(polygon(crossing.get("children")[0].get("geometry"))) == 4  # reset to 4 roads


WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 8
}
RoadIntersection {
  translation 0 0 0.5
  boundingObject TRUE
}
DEF CENTRE Solid {
  translation 0.5 0.5 1
  children [ Shape { geometry Sphere { radius 0.1 } } ]
  boundingObject Sphere { radius 0.1 }
  physics Physics { }
}
DEF ARM Solid {
  translation 5 5 1
  children [ Shape { geometry Sphere { radius 0.1 } } ]
  boundingObject Sphere { radius 0.1 }
  physics Physics { }
}
DEF OFF Solid {
  translation 5 -10 1
  children [ Shape { geometry Sphere { radius 0.1 } } ]
  boundingObject Sphere { radius 0.1 }
  physics Physics { }
}
"""


def test_balls_rest_on_the_centre_and_on_a_road_but_not_beside(tmp_path: Path) -> None:
    world = tmp_path / "crossing.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    model = result.model
    ids = {name: model.body(result.table.bodies[name]).id for name in ("CENTRE", "ARM", "OFF")}
    sim = Simulation(result, noise=False)
    for _ in range(150):  # 1.2 s
        sim.step()
    mujoco.mj_forward(model, sim.data)
    assert sim.data.xpos[ids["CENTRE"]][2] == pytest.approx(0.6, abs=2e-3)
    assert sim.data.xpos[ids["ARM"]][2] == pytest.approx(0.6, abs=2e-3)  # on road 0, 7.07 m out
    assert sim.data.xpos[ids["OFF"]][2] < 0.0


def test_three_roads_compile(tmp_path: Path) -> None:
    world = tmp_path / "three.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo {\n}\nRoadIntersection {\n  roadNumber 3\n"
                     "  boundingObject TRUE\n  startRoadBorderboundingObject TRUE\n}\n")
    result, _ = compile_world(world)
    assert result.model.ngeom > 0
