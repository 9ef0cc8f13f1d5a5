"""wbtc's BuildingUnderConstruction, TheThreeTowers and BigGlassTower: interface, sizes and what collides."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_buildings import settle

from wbtc.proto.expand import expand_scene
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 8\n}\n"


def expand_one(tmp_path: Path, node: str) -> Node:
    """The single top-level node `node` expands to."""
    text = HEADER + node + "\n"
    world = tmp_path / "building.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.console == []
    return scene.nodes[1]


def extent(bounds: Node) -> np.ndarray:
    """The axis-aligned [min, max] corners of a Group of Poses holding Boxes and z-axis Cylinders."""
    poses = bounds.get("children") if bounds.type_name == "Group" else [bounds]
    lows, highs = [], []
    for pose in poses:
        t = pose.get("translation")
        centre = np.array([t.x, t.y, t.z])
        [shape] = pose.get("children")
        if shape.type_name == "Box":
            s = shape.get("size")
            half = np.array([s.x, s.y, s.z]) / 2
        else:
            r = shape.get("radius")
            half = np.array([r, r, shape.get("height") / 2])
        lows.append(centre - half)
        highs.append(centre + half)
    return np.array([np.min(lows, axis=0), np.max(highs, axis=0)])


def drop(tmp_path: Path, building: str, balls: dict[str, tuple[float, float, float]],
         steps: int = 80) -> dict[str, np.ndarray]:
    """Drop balls of radius 0.1 on the building; their positions after `steps` steps of 8 ms."""
    return settle(tmp_path, HEADER + building + "\n", balls, steps)


@pytest.mark.parametrize(("proto", "name", "model"), [
    ("BuildingUnderConstruction", "building under construction", "building under construction"),
    ("TheThreeTowers", "three towers", "three towers"),
    ("BigGlassTower", "big glass tower", "big glass tower"),
])
def test_interface_defaults(tmp_path: Path, proto: str, name: str, model: str) -> None:
    node = expand_one(tmp_path, f"{proto} {{ translation 1 2 0 rotation 0 0 1 0.5 name \"mine\" }}")
    assert node.type_name == "Solid" and node.get("name") == "mine" and node.get("model") == model
    t = node.get("translation")
    assert [t.x, t.y, t.z] == [1, 2, 0] and node.get("rotation").angle == pytest.approx(0.5)
    assert expand_one(tmp_path, f"{proto} {{ }}").get("name") == name


def test_building_under_construction_is_a_16_m_block_38_6_m_high(tmp_path: Path) -> None:
    node = expand_one(tmp_path, "BuildingUnderConstruction { }")
    low, high = extent(node.get("boundingObject"))
    assert low == pytest.approx([-8, -8, 0]) and high == pytest.approx([8, 8, 38.6])
    assert np.allclose(node.get("recognitionColors"), [[0.38, 0.38, 0.4]])
    tops = [p.get("translation").z + p.get("children")[0].get("geometry").get("size").z / 2
            for p in node.get("children")]
    assert sorted(tops) == pytest.approx([30.8, 33.0, 38.55])
    # On the collision box's top (above the drawn step, as in Webots); beside the block (no floor: it falls).
    found = drop(tmp_path, "BuildingUnderConstruction { }", {"TOP": (-4, 0, 39.0), "SIDE": (8.2, 0, 20.0)})
    assert found["TOP"][2] == pytest.approx(38.7, abs=2e-3)
    assert found["SIDE"][2] < 19.0


def test_three_towers_boxes_and_their_overhang(tmp_path: Path) -> None:
    node = expand_one(tmp_path, "TheThreeTowers { }")
    bounds = node.get("boundingObject")
    assert len(bounds.get("children")) == 11
    low, high = extent(bounds)
    assert low == pytest.approx([-8.05, -27.032, 0.025])
    assert high == pytest.approx([8, 27.032, 41.7])
    assert len(node.get("children")) == 11  # drawn as the collision boxes
    # On the middle crown; under the middle tower's overhang (no pier below it); on a roof block.
    found = drop(tmp_path, "TheThreeTowers { }",
                 {"CROWN": (-6, 5, 40.3), "UNDER": (-6, 0, 2.0), "ROOF": (0, -19, 42.1)})
    assert found["CROWN"][2] == pytest.approx(40.05, abs=2e-3)
    assert found["UNDER"][2] < 1.5  # falls through: no floor, no building there
    assert found["ROOF"][2] == pytest.approx(41.8, abs=2e-3)


def test_big_glass_tower_stadium_footprint(tmp_path: Path) -> None:
    node = expand_one(tmp_path, "BigGlassTower { }")
    low, high = extent(node.get("boundingObject"))
    assert low == pytest.approx([-7.1, -3.9803, 0])
    assert high == pytest.approx([7.1, 4.0197, 55.8])
    assert np.allclose(node.get("recognitionColors"), [[0.37, 0.62, 0.77]])
    # On the rounded end, just past the box; beyond the round corner (outside the stadium).
    found = drop(tmp_path, "BigGlassTower { }", {"END": (6.5, 0, 56.3), "CORNER": (6.9, 3.8, 56.3)})
    assert found["END"][2] == pytest.approx(55.9, abs=2e-3)
    assert found["CORNER"][2] < 55.5
