"""wbtc's Crossroad: the `shape` polygon, ear-clipped into an upward surface, and its collision prisms."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.runtime.simulation import Simulation
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text


def expand(tmp_path: Path, nodes: str) -> list[Node]:
    """The top-level nodes after the world `nodes` is expanded (WorldInfo left out)."""
    text = f"#VRML_SIM R2025a utf8\nWorldInfo {{\n}}\n{nodes}\n"
    world = tmp_path / "crossroad.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert not expansion.console
    return scene.nodes[1:]


def triangles(face_set: Node) -> np.ndarray:
    """The corners of every face of a triangulated IndexedFaceSet, shape (n, 3, 3)."""
    points = np.asarray(face_set.get("coord").get("point"), dtype=float).reshape(-1, 3)
    index = list(face_set.get("coordIndex"))
    faces, face = [], []
    for i in index:
        if i < 0:
            faces.append(face)
            face = []
        else:
            face.append(i)
    assert all(len(f) == 3 for f in faces)
    return points[np.asarray(faces)]


def up_areas(corners: np.ndarray) -> np.ndarray:
    """Signed areas of the triangles seen from above (positive: counter-clockwise, facing up)."""
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def shape_of(points_xy: list[tuple[float, float]], z: float = 0.0) -> str:
    """`shape` values putting the corners at `points_xy` (Webots writes (x, y, z) as (-y, -x, -z))."""
    return ", ".join(f"{-y} {-x} {-z}" for x, y in points_xy)


SQUARE = [(0, 0), (10, 0), (10, 10), (0, 10)]
# An L: the 4 x 4 square without its upper right 2 x 2 quarter (area 12); reflex corner at (2, 2).
L_SHAPE = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]


def surface(node: Node) -> Node:
    return node.get("children")[0].get("geometry")


def test_square_is_two_upward_triangles_of_100_square_metres(tmp_path: Path) -> None:
    [road] = expand(tmp_path, f"Crossroad {{ shape [ {shape_of(SQUARE, 0.02)} ] }}")
    corners = triangles(surface(road))
    assert len(corners) == 2
    areas = up_areas(corners)
    assert np.all(areas > 0)
    assert areas.sum() == pytest.approx(100.0, abs=1e-9)
    assert np.allclose(corners[:, :, 2], 0.02)  # the surface is at the height the points give
    assert road.get("boundingObject") is None
    assert road.get("model") == "crossroad"


@pytest.mark.parametrize("order", [1, -1], ids=["counter-clockwise", "clockwise"])
def test_l_shape_is_clipped_into_four_triangles_of_12_square_metres(tmp_path: Path, order: int) -> None:
    [road] = expand(tmp_path, f"Crossroad {{ shape [ {shape_of(L_SHAPE[::order])} ] }}")
    corners = triangles(surface(road))
    areas = up_areas(corners)
    assert len(corners) == 4 and np.all(areas > 0)
    assert areas.sum() == pytest.approx(12.0, abs=1e-9)
    # No triangle covers the notch: every centroid lies in the L.
    centroids = corners.mean(axis=1)
    assert not np.any((centroids[:, 0] > 2) & (centroids[:, 1] > 2))


def test_bottom_adds_the_downward_faces(tmp_path: Path) -> None:
    [road] = expand(tmp_path, f"Crossroad {{ shape [ {shape_of(L_SHAPE)} ] bottom TRUE }}")
    areas = up_areas(triangles(surface(road)))
    assert sorted(areas) == pytest.approx(sorted([*areas[:4], *(-areas[:4])]))
    assert areas[4:].sum() == pytest.approx(-12.0)


def test_default_shape_is_webots_triangle(tmp_path: Path) -> None:
    [road] = expand(tmp_path, "Crossroad { }")
    corners = triangles(surface(road))
    # [0 0 0, 0 1 0, 1 0 0] lies at (0, 0), (-1, 0), (0, -1): half a square metre, drawn as three triangles
    # around its centroid (a MuJoCo mesh needs 4 vertices).
    areas = up_areas(corners)
    assert len(corners) == 3 and np.all(areas > 0) and areas.sum() == pytest.approx(0.5)
    assert {tuple(np.round(p[:2], 6)) for p in corners.reshape(-1, 3)} == {
        (0.0, 0.0), (-1.0, 0.0), (0.0, -1.0), (round(-1 / 3, 6), round(-1 / 3, 6))}


def test_a_triangle_compiles(tmp_path: Path) -> None:
    world = tmp_path / "triangle.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo {\n}\nCrossroad {\n  boundingObject TRUE\n}\n")
    result, _ = compile_world(world)
    assert result.model.nmesh == 2  # the surface and the one collision prism


WORLD = f"""#VRML_SIM R2025a utf8
WorldInfo {{
  basicTimeStep 8
}}
Crossroad {{
  translation 1 1 0.5
  shape [ {shape_of(L_SHAPE)} ]
  boundingObject TRUE
}}
DEF ON Solid {{
  translation 2 2 1
  children [ Shape {{ geometry Sphere {{ radius 0.1 }} }} ]
  boundingObject Sphere {{ radius 0.1 }}
  physics Physics {{ }}
}}
DEF NOTCH Solid {{
  translation 4 4 1
  children [ Shape {{ geometry Sphere {{ radius 0.1 }} }} ]
  boundingObject Sphere {{ radius 0.1 }}
  physics Physics {{ }}
}}
"""


def test_balls_rest_on_the_l_and_fall_through_its_notch(tmp_path: Path) -> None:
    world = tmp_path / "l.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    model = result.model
    prisms = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH
              and model.geom_contype[g] != 0]
    assert len(prisms) == 4  # one prism per triangle
    on, notch = (model.body(result.table.bodies[name]).id for name in ("ON", "NOTCH"))
    sim = Simulation(result, noise=False)
    for _ in range(150):  # 1.2 s
        sim.step()
    mujoco.mj_forward(model, sim.data)
    assert sim.data.xpos[on][2] == pytest.approx(0.6, abs=2e-3)  # surface at 0.5, radius 0.1
    assert sim.data.xpos[notch][2] < 0.0  # (4, 4) is in the notch of the L moved by (1, 1)


OLD_WORLD = """#VRML_SIM V8.6 utf8
WorldInfo {
}
Crossroad {
  translation 0 0.5 0
  shape [ 0 0 0, 10 0 0, 10 0 10, 0 0 10 ]
  boundingObject TRUE
}
DEF ON Solid {
  translation 5 1 5
  children [ Shape { geometry Sphere { radius 0.1 } } ]
  boundingObject Sphere { radius 0.1 }
  physics Physics { }
}
DEF OFF Solid {
  translation 5 1 -5
  children [ Shape { geometry Sphere { radius 0.1 } } ]
  boundingObject Sphere { radius 0.1 }
  physics Physics { }
}
"""


def test_old_y_up_shape_in_an_old_world(tmp_path: Path) -> None:
    # Before R2022a the points were (x, height, z) in y-up worlds: the square x, z in [0, 10] at y = 0.5.
    world = tmp_path / "old.wbt"
    world.write_text(OLD_WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    for _ in range(60):
        sim.step()
    mujoco.mj_forward(result.model, sim.data)
    on, off = (sim.data.xpos[result.model.body(result.table.bodies[n]).id] for n in ("ON", "OFF"))
    assert on[2] == pytest.approx(0.6, abs=2e-3)  # MuJoCo's z is the old y
    assert off[2] < 0.0
