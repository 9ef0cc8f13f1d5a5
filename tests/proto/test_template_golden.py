"""Golden tests of template PROTOs: the expanded node tree, printed, must match a file in golden/.

Each case writes a small world that declares the PROTO with an absolute EXTERNPROTO path (so the file under
test is used, never wbtc's library copy of the same name), expands it and prints the expanded top-level
nodes with `format_node`. The PROTOs are real ones from the corpus (Webots' Parquetry in JavaScript, a
project's UR5e in JavaScript, a project's MazeWall in Lua) and small fixtures written for these tests
(tests/proto/fixtures/protos) that use loops, conditionals, node-valued and MF fields, `wbvector3` and
`context.coordinate_system`. Every PROTO is expanded with its defaults and with non-default values.

To accept new output after an intended change, run
`WBTC_REGEN_GOLDEN=1 python -m pytest tests/proto/test_template_golden.py`, then read the diff of
tests/proto/golden/ before committing it.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

import pytest
from conftest import CORPUS

from wbtc.proto.expand import expand_scene
from wbtc.scene import build_scene
from wbtc.scene.printer import format_node
from wbtc.vrml import parse_text

GOLDEN = Path(__file__).parent / "golden"
FIXTURES = Path(__file__).parent / "fixtures" / "protos"
REGENERATE = os.environ.get("WBTC_REGEN_GOLDEN") == "1"

PARQUETRY = CORPUS / "webots" / "projects" / "appearances" / "protos" / "Parquetry.proto"
UR5E = CORPUS / "projects" / "hoanbklucky__eel4664-robotics-labs-webots-version" / "webots" / "protos" / "UR5e.proto"
MAZE_WALL = CORPUS / "projects" / "Klodivio355__Maze_webots" / "protos" / "MazeWall.proto"


@dataclass(frozen=True)
class Case:
    """One expansion: the PROTO file, the nodes written in the world, the world's axes."""

    name: str
    proto: Path
    nodes: str
    coordinate_system: str = "ENU"


CASES = [
    Case("parquetry_default", PARQUETRY, "Shape {\n  appearance Parquetry {\n  }\n  geometry Plane {\n  }\n}"),
    Case("parquetry_dark_strip", PARQUETRY,
         'Shape {\n  appearance Parquetry {\n    type "dark strip"\n    colorOverride 0.5 0.4 0.3\n'
         "    textureTransform TextureTransform {\n      scale 4 4\n    }\n    IBLStrength 0.5\n  }\n"
         "  geometry Plane {\n  }\n}"),
    Case("ur5e_default", UR5E, "UR5e {\n}"),
    Case("ur5e_free_base", UR5E,
         'UR5e {\n  name "arm"\n  controller "move"\n  staticBase FALSE\n  selfCollision FALSE\n'
         '  toolSlot [\n    DistanceSensor {\n      name "tool sensor"\n    }\n  ]\n}'),
    Case("mazewall_default", MAZE_WALL, "MazeWall {\n}"),
    Case("mazewall_long", MAZE_WALL, 'MazeWall {\n  translation 1 0.15 2\n  name "long wall"\n  length 2.5\n}'),
    Case("ring_default", FIXTURES / "WbtcRing.proto", "WbtcRing {\n}"),
    Case("ring_custom_nue", FIXTURES / "WbtcRing.proto",
         "WbtcRing {\n  posts 4\n  radius 1\n  colors [ 0 1 0 ]\n  heights [ 0.1, 0.3 ]\n"
         "  postAppearance PBRAppearance {\n    baseColor 0.2 0.4 0.6\n  }\n  lid TRUE\n}", "NUE"),
    Case("ring_no_lid", FIXTURES / "WbtcRing.proto", "WbtcRing {\n  posts 2\n  colors [ ]\n  lid FALSE\n}"),
    Case("shelf_default", FIXTURES / "WbtcShelf.proto", "WbtcShelf {\n}"),
    Case("shelf_items", FIXTURES / "WbtcShelf.proto",
         'WbtcShelf {\n  boards [ 0.9, 0.2, 0.5 ]\n  labels [ "bottom", "middle" ]\n'
         '  items [\n    Solid {\n      name "cup"\n    }\n    Pose {\n    }\n  ]\n  ring TRUE\n}'),
]


def expand_case(case: Case, folder: Path) -> str:
    """The printed expansion of the case's nodes."""
    world = folder / f"{case.name}.wbt"
    text = (f'#VRML_SIM R2025a utf8\nEXTERNPROTO "{case.proto}"\n'
            f'WorldInfo {{\n  coordinateSystem "{case.coordinate_system}"\n}}\n{case.nodes}\n')
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert not expansion.errors and not expansion.warnings, expansion.warnings
    assert not expansion.console, expansion.console
    assert all(not node.is_proto for node in scene.walk())
    return "\n".join(format_node(node) for node in scene.nodes[1:]) + "\n"


@pytest.mark.parametrize("case", CASES, ids=lambda c: c.name)
def test_template_golden(case: Case, tmp_path) -> None:
    assert case.proto.is_file(), f"{case.proto} is missing"
    printed = expand_case(case, tmp_path)
    golden = GOLDEN / f"{case.name}.wbt"
    if REGENERATE:
        golden.write_text(printed)
    assert golden.is_file(), f"no golden file {golden}: run with WBTC_REGEN_GOLDEN=1 and review it"
    assert printed == golden.read_text(), f"{case.name} differs from {golden} (WBTC_REGEN_GOLDEN=1 to accept)"


def test_defaults_and_values_differ() -> None:
    # Each PROTO is expanded at least twice, and the non-default expansions do change the tree.
    by_proto: dict[Path, list[str]] = {}
    for case in CASES:
        by_proto.setdefault(case.proto, []).append(case.name)
    for names in by_proto.values():
        texts = {(GOLDEN / f"{name}.wbt").read_text() for name in names}
        assert len(texts) == len(names) >= 2
