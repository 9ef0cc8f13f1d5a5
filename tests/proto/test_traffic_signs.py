"""wbtc's traffic objects: Webots' sizes, panels on their poles, static or not, the traffic light's LEDs."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.runtime.simulation import Simulation
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 8\n}\n"


def compiled(tmp_path: Path, nodes: str):
    """The compile result of a world holding `nodes`."""
    world = tmp_path / "traffic.wbt"
    world.write_text(HEADER + nodes, encoding="utf-8")
    result, _ = compile_world(world)
    return result


def collision_geoms(model: mujoco.MjModel, data: mujoco.MjData, body: str) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """(type, size, world position) of every colliding geom of the body named `body`, after kinematics."""
    mujoco.mj_kinematics(model, data)
    b = model.body(body).id
    return [(int(model.geom_type[g]), model.geom_size[g].copy(), data.geom_xpos[g].copy())
            for g in range(model.ngeom)
            if model.geom_bodyid[g] == b and (model.geom_contype[g] or model.geom_conaffinity[g])]


def boxes(model: mujoco.MjModel, data: mujoco.MjData, body: str) -> list[tuple[list[float], list[float]]]:
    """(full size, world centre) of the body's colliding boxes, rounded to the mm."""
    return [(list(np.round(2 * size, 3)), list(np.round(pos, 3)))
            for kind, size, pos in collision_geoms(model, data, body) if kind == mujoco.mjtGeom.mjGEOM_BOX]


def protos_of(tmp_path: Path, sign: str) -> set[str]:
    """The PROTOs a default instance of `sign` expands through (itself, its pole, its default panels)."""
    text = HEADER + f"{sign} {{\n}}\n"
    world = tmp_path / "sign.wbt"
    world.write_text(text, encoding="utf-8")
    _, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert expansion.console == []
    return set(expansion.sources)


def test_direction_panel_is_a_static_arrow_board_of_webots_size(tmp_path: Path):
    result = compiled(tmp_path, "DEF P DirectionPanel {\n  translation 0 0 1\n}\n"
                                "DEF WIDE DirectionPanel {\n  translation 5 0 1\n  width 2\n  height 0.5\n"
                                "  thickness 0.05\n  name \"wide\"\n}\n")
    model, data = result.model, mujoco.MjData(result.model)
    assert model.nv == 0  # nothing moves
    assert boxes(model, data, "P") == [([0.04, 1.3, 0.4], [0.0, 0.52, 1.0])]
    assert boxes(model, data, "WIDE") == [([0.05, 2.0, 0.5], [5.0, 0.8, 1.0])]
    # The arrow reaches from 0.1 x width behind the origin to its point 0.9 x width ahead.
    board = [g for g in range(model.ngeom) if model.geom_bodyid[g] == model.body("P").id
             and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH][0]
    mesh = model.geom_dataid[board]
    verts = model.mesh_vert[model.mesh_vertadr[mesh]:model.mesh_vertadr[mesh] + model.mesh_vertnum[mesh]]
    mujoco.mj_kinematics(model, data)
    world = data.geom_xpos[board] + verts @ data.geom_xmat[board].reshape(3, 3).T
    assert world[:, 1].min() == pytest.approx(-0.13, abs=1e-3)
    assert world[:, 1].max() == pytest.approx(1.17, abs=1e-3)


def test_highway_pole_gantry_and_its_default_signs(tmp_path: Path):
    result = compiled(tmp_path, "DEF HP HighwayPole {\n}\n"
                                "DEF HP2 HighwayPole {\n  translation 20 0 0\n  stand 2\n  type \"H-shape\"\n"
                                "  rightVerticalSigns []\n  rightHorizontalSigns []\n  name \"two\"\n}\n")
    model, data = result.model, mujoco.MjData(result.model)
    assert model.nv == 0
    # Post 6 m + the 0.4 m bend, arm 8 + 0.4 m along -y at 6.4 m, all 0.2 m thick.
    assert boxes(model, data, "HP") == [([0.2, 0.2, 6.4], [0.0, 0.0, 3.2]), ([0.2, 8.4, 0.2], [0.0, -4.2, 6.4])]
    # Two stands: the arm reaches 8 + 2 x 0.2 + 0.4 m, where the second post stands.
    assert boxes(model, data, "HP2") == [([0.2, 0.2, 6.4], [20.0, 0.0, 3.2]), ([0.2, 8.8, 0.2], [20.0, -4.4, 6.4]),
                                         ([0.2, 0.2, 6.4], [20.0, -8.8, 3.2])]
    # Webots' default signs: a 4.5 x 3 m sign hung from the arm 3 m out, a 3.2 x 2.1 m one on the post 3 m up,
    # both standing out on the +x side from 0.95 x the half thickness.
    assert boxes(model, data, "vertical sign") == [([0.2, 4.5, 3.0], [0.195, -3.0, 6.4])]
    assert boxes(model, data, "horizontal sign") == [([0.2, 3.2, 2.1], [0.195, 0.0, 3.0])]
    assert [model.body(b).name for b in range(model.nbody) if "sign" in model.body(b).name] == [
        "vertical sign", "horizontal sign"]


def test_generic_traffic_light_is_a_static_robot_with_webots_leds(tmp_path: Path):
    result = compiled(tmp_path, "DEF TL GenericTrafficLight {\n}\n"
                                "GenericTrafficLight {\n  translation 3 0 0\n  name \"second\"\n  startGreen FALSE\n"
                                "  redTime 20.5\n  greenTime 30\n}\n")
    first, second = result.table.robots
    assert [d.name for d in first.devices] == ["red light", "orange light", "green light"]
    assert [d.type for d in first.devices] == ["LED"] * 3
    assert (first.controller, first.controller_args, first.custom_data) == (
        "generic_traffic_light", ["15", "60", "g"], "off")
    assert second.controller_args == ["20.5", "30", "r"]
    assert first.model == "generic traffic light"
    model = result.model
    assert model.nv == 0
    sim = Simulation(result, noise=False)
    try:
        state = sim.robots[0]
        data = sim.data
        mujoco.mj_kinematics(model, data)
        # The lamps: spheres of 0.09 m on a 2 m pole, 0.63, 0.39 and 0.15 m up the head, 0.12 m in front.
        heights = {}
        for led in state.leds.values():
            (geom,) = led.geoms
            assert model.geom_size[geom][0] == pytest.approx(0.09)
            heights[led.entry.name] = list(np.round(data.geom_xpos[geom], 3))
        assert heights == {"red light": [0.12, 0.0, 2.63], "orange light": [0.12, 0.0, 2.39],
                           "green light": [0.12, 0.0, 2.15]}
        # Lighting the red LED paints its lamp in the LED's colour; the others stay unlit.
        red, orange, green = (state.leds[t] for t in sorted(state.leds))
        red.set(1, model)
        assert list(model.geom_rgba[red.geoms[0]]) == [1.0, 0.0, 0.0, 1.0]
        assert list(model.geom_rgba[green.geoms[0]]) != [0.0, pytest.approx(0.709804), pytest.approx(0.129412), 1.0]
        green.set(1, model)
        assert list(model.geom_rgba[green.geoms[0]]) == pytest.approx([0.0, 0.709804, 0.129412, 1.0])
    finally:
        sim.close()
    # The pole's collision cylinder (radius 0.03 m, 2 m) and the head's 0.16 x 0.22 x 0.74 m housing.
    data = mujoco.MjData(model)
    pole = collision_geoms(model, data, "generic traffic light/pole")
    assert [(k, list(np.round(s[:2], 3))) for k, s, _ in pole] == [(mujoco.mjtGeom.mjGEOM_CYLINDER, [0.03, 1.0])]
    assert boxes(model, data, "generic traffic light/traffic light")[0] == ([0.16, 0.22, 0.74], [0.05, 0.0, 2.37])


@pytest.mark.parametrize(("sign", "panel"), [("SpeedLimitSign", "SpeedLimitPanel"), ("CautionSign", "CautionPanel"),
                                             ("StopSign", "StopPanel"), ("YieldSign", "YieldPanel"),
                                             ("SignPole", "DirectionPanel")])
def test_each_sign_holds_its_webots_panel_by_default(tmp_path: Path, sign: str, panel: str):
    assert protos_of(tmp_path, sign) == {sign, "SignPole", panel} - {None}


def test_signs_poles_and_panels_have_webots_sizes_and_are_static(tmp_path: Path):
    result = compiled(tmp_path, "DEF SPEED SpeedLimitSign {\n}\n"
                                "DEF CAUTION CautionSign {\n  translation 2 0 0\n}\n"
                                "DEF STOP StopSign {\n  translation 4 0 0\n}\n"
                                "DEF YIELD YieldSign {\n  translation 6 0 0\n}\n"
                                "DEF TALL StopSign {\n  translation 8 0 0\n  height 3\n  radius 0.05\n"
                                "  name \"tall\"\n  signBoards [ SpeedLimitPanel { name \"limit\" } ]\n}\n")
    model, data = result.model, mujoco.MjData(result.model)
    assert model.nv == 0
    for name, x in (("SPEED", 0), ("CAUTION", 2), ("STOP", 4), ("YIELD", 6)):
        (pole,) = collision_geoms(model, data, name)
        assert pole[0] == mujoco.mjtGeom.mjGEOM_CYLINDER
        assert list(pole[1][:2]) == pytest.approx([0.03, 1.0])  # 2 m high, radius 0.03 m
        assert list(pole[2]) == pytest.approx([x, 0, 1.0])
    (tall,) = collision_geoms(model, data, "TALL")
    assert list(tall[1][:2]) == pytest.approx([0.05, 1.5])
    # The panels, 1.9 m up plus each sign's offset.
    assert boxes(model, data, "speed limit panel") == [([0.06, 0.5, 0.63], [0.053, -0.01, 1.9])]
    assert boxes(model, data, "limit") == [([0.06, 0.5, 0.63], [8.03, -0.01, 1.9])]  # same height on a 3 m post
    (diamond,) = collision_geoms(model, data, "caution panel")
    assert list(diamond[1]) == pytest.approx([0.04, 0.305, 0.305])
    assert list(diamond[2]) == pytest.approx([2.045, 0, 1.738])
    (octagon,) = collision_geoms(model, data, "stop panel")
    assert octagon[0] == mujoco.mjtGeom.mjGEOM_CYLINDER
    assert list(octagon[1][:2]) == pytest.approx([0.325, 0.019])
    assert list(octagon[2]) == pytest.approx([4.039, 0, 1.803])
    triangle = boxes(model, data, "yield panel")
    assert triangle[0] == ([0.08, 0.8, 0.1], [6.043, 0.0, 2.12])  # the top bar, the top edge 2.17 m up
    assert triangle[3] == ([0.08, 0.35, 0.35], [6.043, 0.0, 1.9])


def test_traffic_cone_is_static_by_default_and_takes_its_physics_mass(tmp_path: Path):
    world = ("Floor {\n}\nDEF STILL TrafficCone {\n}\n"
             "DEF FALLING TrafficCone {\n  translation 1 0 0.3\n  name \"falling\"\n"
             "  physics Physics {\n    density -1\n    mass 2.5\n  }\n}\n"
             "DEF BIG TrafficCone {\n  translation -1 0 0.3\n  scale 2\n  name \"big\"\n  physics Physics {\n  }\n}\n")
    result = compiled(tmp_path, world)
    model = result.model
    still, falling, big = (model.body(n).id for n in ("STILL", "FALLING", "BIG"))
    assert model.body_jntnum[still] == 0
    assert model.body_mass[falling] == pytest.approx(2.5)
    data = mujoco.MjData(model)
    assert boxes(model, data, "STILL") == [([0.5, 0.5, 0.015], [0.0, 0.0, 0.015])]
    assert boxes(model, data, "BIG") == [([1.0, 1.0, 0.03], [-1.0, 0.0, 0.33])]
    # Density 1000 over the scaled collision shapes: 8 times the unscaled cone's.
    result1 = compiled(tmp_path, "DEF ONE TrafficCone {\n  physics Physics {\n  }\n}\n")
    assert model.body_mass[big] == pytest.approx(8 * result1.model.body_mass[result1.model.body("ONE").id], rel=1e-3)
    sim = Simulation(result, noise=False)
    try:
        for _ in range(250):  # 2 s
            sim.step()
        # It rests on its lowest collision shape, the sphere of 0.157 m at 0.161 m: 4 mm deep.
        assert sim.data.xpos[falling][2] == pytest.approx(-0.004, abs=2e-3)
        assert sim.data.xpos[big][2] == pytest.approx(-0.008, abs=3e-3)
        assert sim.data.xpos[still][2] == 0.0
    finally:
        sim.close()


CITY = """DEF GENERIC GenericTrafficLight {
  translation -34.665 55.2732 0
  startGreen FALSE
  greenTime 10
  redTime 10
}
CautionSign {
  translation -91.9275 48.9391 0
  signBoards [
    CautionPanel {
      translation 0 0 -0.17
      signImage [
        "webots://projects/objects/traffic/protos/textures/signs/us/turn_left.jpg"
      ]
    }
  ]
}
StopSign {
  translation -34.6012 34.2884 0
  rotation 0 0 1 -1.5708
  signBoards [
    StopPanel {
      translation 0 0 -0.097
    }
    SpeedLimitPanel {
      translation -0.03 0 -0.11
      rotation 0 0 1 3.1415926
    }
  ]
}
YieldSign {
  translation -55.468 66.4958 0
  rotation 0 0 1 1.5708
}
SpeedLimitSign {
  translation -113.192 20.4404 0
  rotation 0 0 1 0.9163
  signBoards [
    SpeedLimitPanel {
      translation 0.023 0 0
      signImage [
        "webots://projects/objects/traffic/protos/textures/signs/us/speed_limit_55.jpg"
      ]
    }
  ]
}
DEF CONE TrafficCone {
  translation -50.8173 33.9068 0
  physics Physics {
    density -1
    mass 1
  }
}
DEF TILTED_CONE TrafficCone {
  translation -45.1042 26.3544 0
  rotation 0.9999998711276221 0 0.0005076856697149851 0.013703449
  name "traffic cone(3)"
  physics Physics {
    density -1
    mass 1
  }
}
DEF GANTRY HighwayPole {
  translation -17.67 -117.85 0
  rotation 0 0 -1 3.14159
  height 9
  length 12
  rightHorizontalSigns [
    HighwaySign {
      translation 0 -4.56 0
      name "horizontal highway sign"
      height 4
      length 5.5
      texture [
        "webots://projects/objects/traffic/protos/textures/highway_sign_bayonne.jpg"
      ]
    }
  ]
  rightVerticalSigns [
    HighwaySign {
      name "vertical highway sign"
      height 2.5
      length 3
      texture [
        "webots://projects/objects/traffic/protos/textures/highway_sign_sebastian.jpg"
      ]
    }
  ]
}
DirectionPanel {
  translation 5 5 2
  frontTextTexture [ "textures/my_town.png" ]
}
"""


def test_traffic_objects_as_webots_city_world_sets_them(tmp_path: Path):
    """The fields Webots' city world sets on its signs, cones, gantry and traffic light."""
    result = compiled(tmp_path, "Floor {\n  size 400 400\n}\n" + CITY)
    model, data = result.model, mujoco.MjData(result.model)
    (light,) = result.table.robots
    assert light.controller_args == ["10", "10", "r"]
    assert model.body_mass[model.body("CONE").id] == pytest.approx(1.0)
    assert model.body_mass[model.body("TILTED_CONE").id] == pytest.approx(1.0)
    # The gantry is turned half a turn: its 9.4 m post at its origin, its 12.4 m arm along +y at 9.4 m.
    post, arm = boxes(model, data, "GANTRY")
    assert post == ([0.2, 0.2, 9.4], [-17.67, -117.85, 4.7])
    assert arm[0] == [0.2, 12.4, 0.2] and arm[1] == pytest.approx([-17.67, -111.65, 9.4], abs=1e-3)
    # The hung sign: 3 m out along the arm plus its own -4.56 m, 0.95 x 0.1 m off the pole (on -x, turned).
    (sign,) = boxes(model, data, "horizontal highway sign")
    assert sign[0] == [0.2, 5.5, 4.0]
    assert sign[1] == pytest.approx([-17.67 - 0.195, -117.85 + 7.56, 9.4], abs=1e-3)
    assert sum(1 for b in range(model.nbody) if model.body(b).name.startswith("speed limit panel")) == 2
