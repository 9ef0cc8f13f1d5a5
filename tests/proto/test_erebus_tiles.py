"""The library's Erebus rescue-maze PROTOs (worldTile, halfTile, Victim, HazardMap) follow Erebus' layout."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import CORPUS

from wbtc.proto.expand import expand_scene
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_file, parse_text

SCALE = 0.4  # what the corpus worlds use


def expand(tmp_path, nodes: str) -> list[Node]:
    world = tmp_path / "maze.wbt"
    text = f'#VRML_SIM R2022b utf8\nWorldInfo {{\n  coordinateSystem "NUE"\n}}\n{nodes}\n'
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert not expansion.console
    return scene.nodes[1:]


def boxes(tile: Node) -> list[tuple[np.ndarray, np.ndarray]]:
    """(centre, size) of every box of a tile, in the tile's frame."""
    group = tile.get("children")[0]
    found = []
    for pose in group.get("children"):
        t = pose.get("translation")
        size = pose.get("children")[0].get("geometry").get("size")
        found.append((np.array([t.x, t.y, t.z]), np.array([size.x, size.y, size.z])))
    return found


def vec(value) -> np.ndarray:
    return np.array([value.x, value.y, value.z])


def test_tile_position_floor_and_walls(tmp_path) -> None:
    [tile] = expand(tmp_path, f"""worldTile {{
      xPos 1 zPos 2 width 3 height 6 floor TRUE topWall 3 leftWall 1 rightWall 2
      topExternal TRUE leftExternal TRUE id "7" xScale {SCALE} yScale {SCALE} zScale {SCALE}
      tileColor 0.635 0.635 0.635
    }}""")
    pitch, t = 0.3 * SCALE, 0.025 * SCALE
    # Tiles are laid out from the field's centre: x = (xPos - width / 2) * pitch.
    assert np.allclose(vec(tile.get("translation")), [(1 - 1.5) * pitch, 0, (2 - 3) * pitch])
    assert tile.get("name") == "solid7"
    assert tile.get("boundingObject") is tile.get("children")[0]
    floor, right, top, left = boxes(tile)
    # The floor stops at the inner faces of the two external walls.
    assert np.allclose(floor[1], [pitch - t / 2, 0.02 * SCALE, pitch - t / 2])
    assert np.allclose(floor[0], [t / 4, -0.085 * SCALE, t / 4])
    # rightWall 2: shortened by half a thickness at its -z end.
    assert np.allclose(right[1], [t, 0.15 * SCALE, pitch - t / 2])
    assert np.allclose(right[0], [pitch / 2, 0, t / 4])
    # topWall 3 is lengthened, and leftWall 1 makes the top wall close the corner: (0.3 + 0.025) long.
    assert np.allclose(top[1], [pitch + t, (0.15 + 0.02) * SCALE, t])
    assert np.allclose(top[0], [0, -0.01 * SCALE, -pitch / 2])
    # ... so the left wall stops short of it.
    assert np.allclose(left[1], [t, (0.15 + 0.02) * SCALE, pitch - t / 2])


def test_special_floors_and_trap(tmp_path) -> None:
    start, swamp, trap = expand(tmp_path, """
      worldTile { floor TRUE start TRUE }
      worldTile { floor TRUE swamp TRUE }
      worldTile { trap TRUE }
    """)
    look = start.get("children")[0].get("children")[0].get("children")[0].get("appearance")
    assert np.allclose(look.get("emissiveColor"), [0.0313, 0.835, 0.0313])
    look = swamp.get("children")[0].get("children")[0].get("children")[0].get("appearance")
    assert np.allclose(look.get("baseColor"), [0.517647, 0.392157, 0.192157])
    pit = boxes(trap)
    assert len(pit) == 5 and np.allclose(pit[0][0], [0, -0.205, 0])


def test_tile_without_walls_or_floor_has_no_bounding_object(tmp_path) -> None:
    [tile] = expand(tmp_path, "worldTile { }")
    assert tile.get("boundingObject") is None
    assert boxes(tile) == []


def test_only_walls_or_a_floor_make_a_tile_collide_but_a_curved_wall_always_does(tmp_path) -> None:
    # Erebus gives a tile its boxes as bounding object only when a wall code or the floor is set; its
    # curved wall is a Solid of its own, 0.05 thick and 0.3 high in tile units from 0.075 below the origin.
    trap, obstacle, curve = expand(tmp_path, f"""
      worldTile {{ trap TRUE }}
      worldTile {{ obstacle TRUE }}
      worldTile {{ curveDir 2 xScale {SCALE} yScale {SCALE} zScale {SCALE} }}
    """)
    assert len(boxes(trap)) == 5 and trap.get("boundingObject") is None  # the pit collided before
    assert obstacle.get("boundingObject") is None
    segments = boxes(curve)
    assert len(segments) == 6
    for centre, size in segments:
        assert size[1:] == pytest.approx([0.3 * SCALE, 0.05 * SCALE])  # 0.15 high and 0.025 thick before
        assert centre[1] == pytest.approx(0.075 * SCALE)  # centred on the origin before
    bounds = curve.get("boundingObject")
    assert bounds is not None and len(bounds.get("children")) == 6


@pytest.mark.parametrize("curve", [1, 2, 3, 4])
def test_half_tile_quarters_and_curves(tmp_path, curve: int) -> None:
    [half] = expand(tmp_path, f"""halfTile {{
      floor TRUE width 3 height 3 xScale {SCALE} yScale {SCALE} zScale {SCALE}
      tile4Walls [0, 0, 1, 0] curve [{curve}, 0, 0, 0]
    }}""")
    pitch = 0.3 * SCALE
    assert np.allclose(vec(half.get("translation")), [-1.5 * pitch, 0, -1.5 * pitch])
    big, *quarters = half.get("children")
    assert len(boxes(big)) == 1  # the floor
    centres = [vec(q.get("translation")) for q in quarters]
    assert np.allclose(centres, [[-pitch / 4, 0, -pitch / 4], [pitch / 4, 0, -pitch / 4],
                                 [-pitch / 4, 0, pitch / 4], [pitch / 4, 0, pitch / 4]])
    # Quarter 4's bottom wall is as thick and high as a full tile's wall.
    [(_centre, size)] = boxes(quarters[3])
    assert np.allclose(size, [pitch / 2, 0.15 * SCALE, 0.025 * SCALE])
    # Quarter 1's curve: six segments at one quarter-tile from the corner named by `curve`.
    corner = {1: (-1, 1), 2: (-1, -1), 3: (1, -1), 4: (1, 1)}[curve]
    segments = boxes(quarters[0])
    assert len(segments) == 6
    for centre, _size in segments:
        distance = math.hypot(centre[0] - corner[0] * pitch / 4, centre[2] - corner[1] * pitch / 4)
        assert distance == pytest.approx(pitch / 2, rel=1e-3)


def test_victim_and_hazard_map(tmp_path) -> None:
    victim, hazard = expand(tmp_path, """
      Victim { translation 0.1 0 0.2 rotation 0 1 0 1.57 name "Victim0" type "stable" }
      HazardMap { name "Hazard0" type "C" }
    """)
    assert np.allclose(vec(victim.get("translation")), [0.1, 0, 0.2])
    [plate] = victim.get("children")
    assert plate.get("name") == "Victim0"
    assert np.allclose(vec(plate.get("children")[0].get("geometry").get("size")), [0.016, 0.016, 0.001])
    assert plate.get("boundingObject") is plate.get("children")[0]
    [placard] = hazard.get("children")
    assert placard.get("name") == "Hazard0" and placard.get("boundingObject") is None


def test_corpus_maze_tiles_have_unique_names() -> None:
    world = CORPUS / "projects" / "RichoM__rescuesim" / "05" / "02_Captura" / "Camara.wbt"
    scene, expansion = expand_scene(build_scene(parse_file(world)))
    assert expansion.counts["worldTile"] == 25
    names = [n.get("name") for n in scene.walk() if n.base_type == "Solid" and str(n.get("name")).startswith("solid")]
    assert len(names) == 25 == len(set(names))
