"""Header lines, version ordering, coordinate systems and the legacy flags of a scene."""

import pytest

from wbtc.errors import WbtSyntaxError
from wbtc.scene import build_scene
from wbtc.vrml import Version, parse_text, read_header
from wbtc.vrml.header import R2020B, R2022A, R2022B


@pytest.mark.parametrize(("line", "text", "key"), [
    ("#VRML_SIM V6.0 utf8", "V6.0", (6, 0)),
    ("#VRML_SIM V8.5 utf8", "V8.5", (8, 5)),
    ("#VRML_SIM R2018a utf8", "R2018a", (2018, 0)),
    ("#VRML_SIM R2020b utf8   ", "R2020b", (2020, 1)),
    ("#VRML_SIM R2023b revision 1 utf8", "R2023b revision 1", (2023, 1)),
    ("#VRML_SIM R2019a-rev2 utf8", "R2019a-rev2", (2019, 0)),
    ("#VRML_SIM R2025a utf8\r", "R2025a", (2025, 0)),
])
def test_headers_of_every_version(line: str, text: str, key: tuple) -> None:
    version, info = read_header(line + "\n# a comment\nSolid {}\n", "w.wbt")
    assert version.text == text and version.key() == key
    assert info == [line.strip()[1:].strip(), "a comment"]


def test_versions_order_as_webots_does() -> None:
    order = ["V6.0", "V8.5", "V8.6", "R2018a", "R2019b", "R2020a", "R2020b", "R2021b", "R2022a", "R2022b",
             "R2023a", "R2023b", "R2025a"]
    versions = [Version.parse(v) for v in order]
    assert versions == sorted(versions)
    assert Version.parse("R2023b revision 2") == Version.parse("R2023b")


@pytest.mark.parametrize("line", ["#VRML_SIM R2023b", "VRML_SIM R2023b utf8", "#VRML V2.0 utf8", ""])
def test_bad_headers(line: str) -> None:
    with pytest.raises(WbtSyntaxError) as info:
        read_header(line + "\nSolid {}\n", "w.wbt")
    assert info.value.span.line == 1


@pytest.mark.parametrize(("version", "world_info", "system", "legacy_axes", "pre_extern"), [
    ("R2019b", "", "NUE", True, True),
    ("R2019b", 'coordinateSystem "ENU"', "NUE", True, True),  # not read before R2020b
    ("R2020b", "", "ENU", True, True),
    ("R2021b", 'coordinateSystem "NUE"', "NUE", True, True),
    ("R2022a", "", "ENU", False, True),
    ("R2022b", "", "ENU", False, False),
    ("R2025a", 'coordinateSystem "EUN"', "EUN", False, False),
])
def test_scene_records_version_and_axes(version, world_info, system, legacy_axes, pre_extern) -> None:
    text = f"#VRML_SIM {version} utf8\nWorldInfo {{ {world_info} }}\n"
    scene = build_scene(parse_text(text, "w.wbt"))
    assert scene.version == Version.parse(version)
    assert (scene.coordinate_system, scene.legacy_axes, scene.pre_externproto) == (system, legacy_axes, pre_extern)
    assert (scene.version < R2020B, scene.version < R2022A, scene.version < R2022B)[1:] == (legacy_axes, pre_extern)


def test_legacy_gravity_vector_becomes_its_length() -> None:
    scene = build_scene(parse_text("#VRML_SIM R2019a utf8\nWorldInfo { gravity 0 -9.81 0 }\n", "w.wbt"))
    assert scene.world_info().fields["gravity"] == pytest.approx(9.81)
    assert [w.message for w in scene.warnings] == [
        "deprecated gravity vector (0 -9.81 0) in WorldInfo: using its length 9.81"]
