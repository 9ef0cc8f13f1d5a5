"""Traffic panels and signs, two landmark buildings, RoadLine and the lamp geometry against Webots' files.

Every box below is the world-axis bounding box of one Webots collision shape, worked out from the Pose and
Box (or Cylinder) of the PROTO's boundingObject in Webots R2023b (R2023a for SpeedLimitPanel and CautionPanel).
None of these objects has Physics in Webots: they are static.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 8\n}\n"
PROTOS = Path(__file__).resolve().parents[2] / "protos" / "objects"


def compiled(tmp_path: Path, nodes: str) -> mujoco.MjModel:
    """The compiled model of a world holding `nodes`."""
    world = tmp_path / "g3.wbt"
    world.write_text(HEADER + nodes, encoding="utf-8")
    result, _ = compile_world(world)
    return result.model


def shapes(model: mujoco.MjModel, body: str, origin=(0.0, 0.0, 0.0)) -> list[tuple[list[float], list[float]]]:
    """(low, high) world-axis corners of every colliding geom of `body`, relative to `origin`, sorted."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    b = model.body(body).id
    out = []
    for g in range(model.ngeom):
        if model.geom_bodyid[g] != b or not (model.geom_contype[g] or model.geom_conaffinity[g]):
            continue
        rot, size = data.geom_xmat[g].reshape(3, 3), model.geom_size[g]
        if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
            half = np.abs(rot) @ size
        elif model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CYLINDER:
            axis = rot[:, 2]
            half = size[1] * np.abs(axis) + size[0] * np.sqrt(np.clip(1 - axis * axis, 0, 1))
        else:
            pytest.fail(f"unexpected collision geom type {model.geom_type[g]}")
        centre = data.geom_xpos[g] - np.array(origin)
        out.append((list(np.round(centre - half, 4)), list(np.round(centre + half, 4))))
    return sorted(out)


def close(found, expected, tol=1e-3) -> bool:
    """True when the lists of (low, high) corners agree within `tol`."""
    return len(found) == len(expected) and all(
        np.allclose(lo, elo, atol=tol) and np.allclose(hi, ehi, atol=tol)
        for (lo, hi), (elo, ehi) in zip(found, sorted(expected), strict=True))


PANELS = {
    # DirectionPanel: Box (width, height, thickness) = (1.3, 0.4, 0.04) at y = 0.4 x width, turned so that
    # its width runs along y, height along z, thickness along x.
    "DirectionPanel": [([-0.02, -0.13, -0.2], [0.02, 1.17, 0.2])],
    # YieldPanel: three bars 0.8 x 0.1 x 0.08 (top at z 0.22; the sides at y -+0.18, z -0.1, tilted by 60 deg)
    # and a 0.35 x 0.35 x 0.08 square, all centred at x 0.043.
    "YieldPanel": [([0.003, -0.4, 0.17], [0.083, 0.4, 0.27]),
                   ([0.003, -0.4233, -0.4714], [0.083, 0.0633, 0.2714]),
                   ([0.003, -0.0633, -0.4714], [0.083, 0.4233, 0.2714]),
                   ([0.003, -0.175, -0.175], [0.083, 0.175, 0.175])],
    # SpeedLimitPanel: Box 0.06 x 0.50 x 0.63 at (0.03, -0.01, 0).
    "SpeedLimitPanel": [([0.0, -0.26, -0.315], [0.06, 0.24, 0.315])],
    # StopPanel: Cylinder radius 0.325, height 0.038, its axis along x, at (0.039, 0, 0).
    "StopPanel": [([0.02, -0.325, -0.325], [0.058, 0.325, 0.325])],
    # CautionPanel: Box 0.61 x 0.61 x 0.08 at (0.045, 0, 0.008), a diamond (45 deg about x), 0.08 along x.
    "CautionPanel": [([0.005, -0.4313, -0.4233], [0.085, 0.4313, 0.4393])],
    # HighwaySign: Box thickness x length x height = 0.2 x 4.5 x 3 at (thickness / 2, 0, 0).
    "HighwaySign": [([0.0, -2.25, -1.5], [0.2, 2.25, 1.5])],
}


def test_panels_and_highway_sign_collide_as_webots_and_are_static(tmp_path: Path):
    nodes = "".join(f"DEF P{i} {proto} {{\n  translation {10 * i} 0 3\n}}\n" for i, proto in enumerate(PANELS))
    model = compiled(tmp_path, nodes)
    assert model.nv == 0  # no Physics anywhere: nothing moves
    for i, (proto, expected) in enumerate(PANELS.items()):
        found = shapes(model, f"P{i}", (10 * i, 0, 3))
        assert close(found, expected), (proto, found)


def test_caution_sign_is_a_2_m_post_with_its_diamond_1_73_m_up(tmp_path: Path):
    # SignPole: Cylinder height 2, radius 0.03 (CautionSign's defaults) in a Solid at z = 1; the panel's
    # Pose is 1.9 m up and CautionSign puts its CautionPanel at z -0.17 in it: the diamond centred 1.738 m up.
    model = compiled(tmp_path, "DEF SIGN CautionSign {\n}\n")
    assert model.nv == 0
    assert close(shapes(model, "SIGN"), [([-0.03, -0.03, 0.0], [0.03, 0.03, 2.0])])
    assert close(shapes(model, "caution panel"), [([0.005, -0.4313, 1.3067], [0.085, 0.4313, 2.1693])])


def test_the_three_towers_and_the_building_under_construction_collide_as_webots(tmp_path: Path):
    # TheThreeTowers: 11 boxes, each turned so that Webots' (a, b, c) size runs along (y, z, x):
    # shafts 16 x 29.91 x 10.1 at (2.9, -+19.032 or 0, 14.98); piers 8 x 29.91 x 5.9 at (-5.1, -+23.032, 14.98);
    # crowns 16 x 10 x 16 at z 34.95; roof blocks 4.4 x 1.8 x 4.4 at z 40.8.
    towers = []
    for y in (-19.032, 0.0, 19.032):
        towers.append(([-2.15, y - 8, 0.025], [7.95, y + 8, 29.935]))
        towers.append(([-8, y - 8, 29.95], [8, y + 8, 39.95]))
        towers.append(([-2.2, y - 2.2, 39.9], [2.2, y + 2.2, 41.7]))
    for y in (-23.032, 23.032):
        towers.append(([-8.05, y - 4, 0.025], [-2.15, y + 4, 29.935]))
    model = compiled(tmp_path, "DEF T TheThreeTowers {\n}\nDEF B BuildingUnderConstruction {\n"
                               "  translation 100 0 0\n}\n")
    assert model.nv == 0
    assert close(shapes(model, "T"), towers, tol=2e-3)
    # BuildingUnderConstruction: one Box 16 x 38.6 x 16 (turned: 38.6 along z) at z 19.3.
    assert close(shapes(model, "B", (100, 0, 0)), [([-8, -8, 0], [8, 8, 38.6])])


def test_road_line_keeps_webots_interface_of_unconnected_fields():
    # Webots' RoadLine: unconnectedField SFColor color 1 1 1, SFString type "dashed" (one of dashed,
    # continuous, double, none), SFFloat width 0.15.
    syntax = parse_text((PROTOS / "RoadLine.proto").read_text(encoding="utf-8"), "RoadLine.proto", kind="proto")
    (proto,) = syntax.protos
    fields = {f.name: f for f in proto.fields}
    assert [(f.kind, f.type) for f in proto.fields] == [
        ("unconnectedField", "SFColor"), ("unconnectedField", "SFString"), ("unconnectedField", "SFFloat")]
    assert list(fields) == ["color", "type", "width"]
    assert fields["color"].default.runs == ["1 1 1"] and fields["width"].default.runs == ["0.15"]
    assert fields["type"].default.value == "dashed"
    assert [item.value for item in fields["type"].restriction] == ["dashed", "continuous", "double", "none"]


def test_a_road_still_reads_its_road_line_fields(tmp_path: Path):
    # A continuous yellow line 0.3 m wide between the two lanes of a 10 m road: the road's template reads the
    # RoadLine's (unconnected) fields.
    model = compiled(tmp_path, "Road {\n  wayPoints [ 0 0 0, 10 0 0 ]\n"
                               "  lines [ RoadLine { color 1 1 0 type \"continuous\" width 0.3 } ]\n}\n")
    yellow = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH
              and np.allclose(model.geom_rgba[g][:3], [1, 1, 0])]
    assert len(yellow) == 1
    m = model.geom_dataid[yellow[0]]
    verts = model.mesh_vert[model.mesh_vertadr[m]:model.mesh_vertadr[m] + model.mesh_vertnum[m]]
    assert sorted(np.round(verts.max(axis=0) - verts.min(axis=0), 3)) == pytest.approx([0, 0.3, 10], abs=0.01)


def test_an_old_world_road_may_still_set_dashed_line(tmp_path: Path):
    # Webots kept the R2018c field `dashedLine` as a hidden field; old worlds (Webots' own R2020b
    # highway_driving benchmark) still set it. It changes nothing: the default RoadLine is drawn.
    model = compiled(tmp_path, "Road {\n  wayPoints [ 0 0 0, 10 0 0 ]\n  dashedLine [ FALSE ]\n}\n")
    white = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH
             and np.allclose(model.geom_rgba[g][:3], [1, 1, 1])]
    assert len(white) == 1


def test_traffic_light_lamp_is_a_sphere_of_0_09_m(tmp_path: Path):
    # Webots' TrafficLightStandardLampGeometry: Sphere { radius 0.09 }.
    text = HEADER + "Shape {\n  geometry TrafficLightStandardLampGeometry {\n  }\n}\n"
    world = tmp_path / "lamp.wbt"
    world.write_text(text, encoding="utf-8")
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.console == []
    sphere = scene.nodes[1].get("geometry")
    assert sphere.type_name == "Sphere" and sphere.get("radius") == pytest.approx(0.09)
