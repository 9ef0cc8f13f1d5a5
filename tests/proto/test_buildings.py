"""wbtc's SimpleBuilding and SmallResidentialTower: footprints, heights, roofs and what collides."""

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


def expand(tmp_path: Path, nodes: str, console: list[str] | None = None) -> list[Node]:
    """The top-level nodes after the world `nodes` is expanded (WorldInfo left out); `console`: the messages."""
    text = f"#VRML_SIM R2025a utf8\nWorldInfo {{\n}}\n{nodes}\n"
    world = tmp_path / "buildings.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.console == (console or [])
    return scene.nodes[1:]


def faces(face_set: Node) -> list[np.ndarray]:
    """Every face of an IndexedFaceSet as an array of its corners."""
    points = np.asarray(face_set.get("coord").get("point"), dtype=float).reshape(-1, 3)
    out, face = [], []
    for i in face_set.get("coordIndex"):
        if i < 0:
            out.append(points[face])
            face = []
        else:
            face.append(i)
    return out


def shapes(building: Node) -> tuple[list[np.ndarray], list[np.ndarray]]:
    """The wall faces and the roof faces of a SimpleBuilding."""
    walls, roof = building.get("children")
    return faces(walls.get("geometry")), faces(roof.get("geometry"))


def flat_area(corners: np.ndarray) -> float:
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def settle(tmp_path: Path, world_text: str, balls: dict[str, tuple[float, float, float]],
           steps: int = 200) -> dict[str, np.ndarray]:
    """Drop balls of radius 0.1 from the given positions; their positions after `steps` steps of 8 ms."""
    for name, (x, y, z) in balls.items():
        world_text += (f"DEF {name} Solid {{\n  translation {x} {y} {z}\n  children [ Shape {{ geometry Sphere "
                       "{ radius 0.1 } } ]\n  boundingObject Sphere { radius 0.1 }\n  physics Physics { }\n}\n")
    world = tmp_path / "drop.wbt"
    world.write_text(world_text)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    for _ in range(steps):
        sim.step()
    mujoco.mj_forward(result.model, sim.data)
    return {name: sim.data.xpos[result.model.body(result.table.bodies[name]).id].copy() for name in balls}


HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 8\n}\n"


def test_default_building_is_20_m_square_9_m_high_with_a_3_m_pyramid(tmp_path: Path) -> None:
    [building] = expand(tmp_path, "SimpleBuilding { }")
    walls, roof = shapes(building)
    assert len(walls) == 4
    corners = np.vstack(walls)
    assert corners[:, :2].min(axis=0) == pytest.approx([-10, -10])
    assert corners[:, :2].max(axis=0) == pytest.approx([10, 10])
    assert sorted(set(corners[:, 2])) == [0, 9]  # 3 floors of 3 m
    assert len(roof) == 4
    apex = {tuple(p) for f in roof for p in f if p[2] > 9}
    assert apex == {(0.0, 0.0, 12.0)}
    assert building.get("model") == "windowed building building"  # as Webots names it
    assert np.allclose(building.get("recognitionColors"), [[0.76, 0.79, 0.84]])
    assert building.get("children")[0].get("appearance").get("baseColor") == pytest.approx([0.76, 0.79, 0.84])
    [hull] = building.get("boundingObject").get("children")  # convex footprint: one hull


# A 30 x 30 m square without its upper right 20 x 20 m (an L of 500 m²), listed clockwise; the mean of
# its corners, (13.3, 13.3), is outside it.
L_CORNERS = "0 0, 0 30, 10 30, 10 10, 30 10, 30 0"


def test_l_footprint_flat_roof_and_starting_floor(tmp_path: Path) -> None:
    [building] = expand(tmp_path, f"SimpleBuilding {{ corners [ {L_CORNERS} ] floorHeight 2.5 floorNumber 4 "
                                  "startingFloor 1 roofShape \"pyramidal roof\" wallColor [ 0.1 0.2 0.3 ] }",
                        ["SimpleBuilding: The geometry of this building is too complex for a pyramidal roof, "
                         "a flat roof will be used instead."])
    walls, roof = shapes(building)
    assert len(walls) == 6
    assert sorted({p[2] for f in walls for p in f}) == [2.5, 10]  # from floor 1 to the top of floor 4
    # The pyramid's apex would see corners across the notch: Webots falls back to a flat roof.
    assert all(np.allclose(f[:, 2], 10) for f in roof)
    areas = [flat_area(f) for f in roof]
    assert all(a > 0 for a in areas) and sum(areas) == pytest.approx(500.0)
    assert building.get("children")[0].get("appearance").get("baseColor") == pytest.approx([0.1, 0.2, 0.3])
    assert len(building.get("boundingObject").get("children")) == 4  # one prism per footprint triangle


def test_gabled_and_hipped_roofs_follow_the_long_sides(tmp_path: Path) -> None:
    gabled, hipped = expand(tmp_path, """
      SimpleBuilding { corners [ 6 4, 6 -4, -6 -4, -6 4 ] roofShape "gabled roof" floorNumber 1 roofHeight 2 }
      SimpleBuilding { corners [ 6 4, 6 -4, -6 -4, -6 4 ] roofShape "hipped roof" floorNumber 1 roofHeight 2 }
    """)
    walls, roof = shapes(gabled)
    ridge = sorted({tuple(p) for f in roof for p in f if p[2] > 3})
    assert ridge == [(-6.0, 0.0, 5.0), (6.0, 0.0, 5.0)]  # between the middles of the 8 m sides
    assert len(roof) == 2 and len(walls) == 6  # the two gable ends close the walls
    walls, roof = shapes(hipped)
    ridge = sorted({tuple(p) for f in roof for p in f if p[2] > 3})
    assert ridge == [(-3.0, 0.0, 5.0), (3.0, 0.0, 5.0)]
    assert len(roof) == 4 and len(walls) == 4


def test_balls_rest_on_the_l_roof_and_fall_past_the_notch(tmp_path: Path) -> None:
    world = HEADER + (f"SimpleBuilding {{ corners [ {L_CORNERS} ] floorHeight 2.5 floorNumber 4 "
                      "roofShape \"flat roof\" }\n")
    found = settle(tmp_path, world, {"ROOF": (5, 25, 11), "NOTCH": (20, 20, 11)})
    assert found["ROOF"][2] == pytest.approx(10.1, abs=2e-3)
    assert found["NOTCH"][2] < 9.0


@pytest.mark.parametrize("floors", [1, 3])
def test_small_residential_tower_box(tmp_path: Path, floors: int) -> None:
    [tower] = expand(tmp_path, f"SmallResidentialTower {{ numberOfFloors {floors} }}")
    height = 6.176 + 2.574 * (floors - 1)
    bounds = tower.get("boundingObject")
    t, size = bounds.get("translation"), bounds.get("children")[0].get("size")
    assert [t.x, t.y, t.z] == pytest.approx([-0.28, 0, height / 2])
    assert [size.x, size.y, size.z] == pytest.approx([7.2, 5.4, height])
    assert tower.get("model") == "twoer" and tower.get("name") == "residential tower"
    tops = [p.get("translation").z + p.get("children")[0].get("geometry").get("size").z / 2
            for p in tower.get("children")]
    assert max(tops) == pytest.approx(height)
    found = settle(tmp_path, HEADER + f"SmallResidentialTower {{ numberOfFloors {floors} }}\n",
                   {"TOP": (-2, 2, height + 0.5)}, steps=60)
    assert found["TOP"][2] == pytest.approx(height + 0.1, abs=2e-3)


def test_tower_without_bounding_object(tmp_path: Path) -> None:
    [tower] = expand(tmp_path, "SmallResidentialTower { enableBoundingObject FALSE }")
    assert tower.get("boundingObject") is None


def test_old_world_corners_are_x_z_pairs(tmp_path: Path) -> None:
    # Before R2022a worlds were y-up and the footprint's corners (x, z): this one covers z in [0, 5].
    world = ("#VRML_SIM V8.6 utf8\nWorldInfo {\n}\n"
             "SimpleBuilding {\n  corners [ 0 0, 10 0, 10 5, 0 5 ]\n  roofShape \"flat roof\"\n}\n")
    for name, z in (("IN", 2.5), ("OUT", -2.5)):
        world += (f"DEF {name} Solid {{\n  translation 5 12 {z}\n  children [ Shape {{ geometry Sphere "
                  "{ radius 0.1 } } ]\n  boundingObject Sphere { radius 0.1 }\n  physics Physics { }\n}\n")
    path = tmp_path / "old.wbt"
    path.write_text(world)
    result, _ = compile_world(path)
    sim = Simulation(result, noise=False)
    for _ in range(60):
        sim.step()
    mujoco.mj_forward(result.model, sim.data)
    inside, outside = (sim.data.xpos[result.model.body(result.table.bodies[n]).id] for n in ("IN", "OUT"))
    assert inside[2] == pytest.approx(9.1, abs=2e-3)  # on the roof (MuJoCo's z is the old y)
    assert outside[2] < 0.0


def test_triangle_footprints_compile(tmp_path: Path) -> None:
    # A flat roof on three corners is split around its centroid: MuJoCo wants 4 vertices a mesh.
    world = tmp_path / "triangles.wbt"
    world.write_text(HEADER + "SimpleBuilding { corners [ 0 0, 4 0, 4 3 ] roofShape \"flat roof\" }\n"
                              "SimpleBuilding { translation 10 0 0 corners [ 0 0, 4 0, 4 3 ] }\n")
    result, _ = compile_world(world)
    assert result.model.nmesh == 6  # walls, roof and hull of each building
