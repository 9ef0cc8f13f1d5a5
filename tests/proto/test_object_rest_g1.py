"""Wall, ceiling and household objects collide, light and rest as Webots' files put them.

The numbers in the comments are Webots' (R2023a/R2023b files of the same name): bounding objects, default
translations and rotations, light positions.
"""

import re
from pathlib import Path

import mujoco
import numpy as np
from conftest import simulation_of

from wbtc.compile.context import COLLISION_GROUP, VISUAL_GROUP

OBJECTS = Path(__file__).resolve().parents[2] / "protos" / "objects"
HEADER = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 8 }
Floor { size 6 6 }
"""


def _open(tmp_path: Path, nodes: str):
    """A simulation of a floor and `nodes` (forwarded once); the caller closes it."""
    sim = simulation_of(tmp_path, HEADER + nodes)
    mujoco.mj_forward(sim.model, sim.data)
    return sim


def _bounds(sim, body: int, group: int = COLLISION_GROUP) -> tuple[np.ndarray, np.ndarray]:
    """World-axis bounds (low, high) of the geoms of `body` (and the bodies welded into it) in `group`."""
    model, data = sim.model, sim.data
    lows, highs = [], []
    for g in range(model.ngeom):
        if model.geom_group[g] != group or model.geom_bodyid[g] != body:
            continue
        rot = data.geom_xmat[g].reshape(3, 3)
        centre = data.geom_xpos[g] + rot @ model.geom_aabb[g][:3]
        half = np.abs(rot) @ model.geom_aabb[g][3:]
        lows.append(centre - half)
        highs.append(centre + half)
    return np.min(lows, axis=0), np.max(highs, axis=0)


def _body(sim, name: str) -> int:
    """The MuJoCo body of the DEF name `name`."""
    return sim.model.body(sim.table.bodies[name]).id


def _fields(proto: str) -> list[tuple[str, str, str]]:
    """(type, name, default) of every field of a library PROTO's interface, in order."""
    text = (OBJECTS / f"{proto}.proto").read_text(encoding="utf-8")
    head = text[text.index(f"PROTO {proto} ["):text.index("\n]")]
    return [(t, n, re.sub(r"\s*#.*", "", d).strip())
            for t, n, d in re.findall(r"^\s*field\s+(\w+)\s+(\w+)\s+(.*)$", head, re.M)]


# Webots' Blackboard: default translation 0 0 0.72; boxes 0.08 x 2.63 x 1.384 at (0, 0, -0.018) and
# 0.163 x 2.63 x 0.034 (the chalk tray) at (0.125, 0, -0.693); no physics.
def test_the_blackboard_stands_on_the_floor_with_webots_board_and_tray_boxes(tmp_path: Path):
    sim = _open(tmp_path, "DEF BOARD Blackboard { }\n")
    try:
        board = _body(sim, "BOARD")
        assert sim.model.body_jntnum[board] == 0
        boxes = sorted(sorted(2 * sim.model.geom_size[g]) for g in range(sim.model.ngeom)
                       if sim.model.geom_bodyid[g] == board and sim.model.geom_group[g] == COLLISION_GROUP)
        np.testing.assert_allclose(boxes, [[0.034, 0.163, 2.63], [0.08, 1.384, 2.63]])
        low, high = _bounds(sim, board)
        np.testing.assert_allclose(low, [-0.04, -1.315, 0.01], atol=1e-4)
        np.testing.assert_allclose(high, [0.2065, 1.315, 1.394], atol=1e-4)
        # The drawing fills the same space: frame from 1 cm above the floor to 1.394 m, tray in front.
        low, high = _bounds(sim, board, VISUAL_GROUP)
        np.testing.assert_allclose(low, [-0.04, -1.315, 0.01], atol=3e-3)
        np.testing.assert_allclose(high, [0.2065, 1.315, 1.394], atol=3e-3)
    finally:
        sim.close()


# Webots' Clock: default translation 0 0 0.17; Cylinder radius 0.165, height 0.022, its axis along x.
def test_the_clock_is_a_thin_disc_standing_on_its_rim_above_the_floor(tmp_path: Path):
    sim = _open(tmp_path, "DEF CLOCK Clock { }\n")
    try:
        clock = _body(sim, "CLOCK")
        (cylinder,) = [g for g in range(sim.model.ngeom)
                       if sim.model.geom_bodyid[g] == clock and sim.model.geom_group[g] == COLLISION_GROUP]
        np.testing.assert_allclose(sim.model.geom_size[cylinder][:2], [0.165, 0.011])
        low, high = _bounds(sim, clock)
        np.testing.assert_allclose(low, [-0.011, -0.165, 0.005], atol=1e-4)
        np.testing.assert_allclose(high, [0.011, 0.165, 0.335], atol=1e-4)
    finally:
        sim.close()


# Webots' paintings: Box 0.05 x 1.5 x 1 (default z 0.5) and 0.05 x 0.82 x 1.01 (default z 0.505), no physics.
def test_the_paintings_stand_on_the_floor_in_webots_boxes(tmp_path: Path):
    sim = _open(tmp_path, "DEF LAND LandscapePainting { translation 0 -1 0.5 }\n"
                          "DEF PORTRAIT PortraitPainting { translation 0 1 0.505 }\n")
    try:
        for name, size in (("LAND", [0.05, 1.5, 1.0]), ("PORTRAIT", [0.05, 0.82, 1.01])):
            low, high = _bounds(sim, _body(sim, name))
            np.testing.assert_allclose(high - low, size, atol=1e-4)
            assert abs(low[2]) < 1e-4
            vlow, vhigh = _bounds(sim, _body(sim, name), VISUAL_GROUP)
            np.testing.assert_allclose(vhigh - vlow, size, atol=1e-3)
        assert _fields("LandscapePainting")[0][2] == "0 0 0.5" and _fields("PortraitPainting")[0][2] == "0 0 0.505"
    finally:
        sim.close()


# Webots' Ceiling: default rotation 1 0 0 3.14159 (its plane faces down, y flipped); fields translation,
# rotation, name, contactMaterial, size, appearance, locked, castShadows; Plane bounding object.
def test_the_ceiling_keeps_webots_interface_and_turns_about_x(tmp_path: Path):
    assert [n for _, n, _ in _fields("Ceiling")] == [
        "translation", "rotation", "name", "contactMaterial", "size", "appearance", "locked", "castShadows"]
    sim = _open(tmp_path, "DEF TOP Ceiling { translation 0 0 1 }\n")
    try:
        top = _body(sim, "TOP")
        np.testing.assert_allclose(sim.data.xmat[top].reshape(3, 3), np.diag([1, -1, -1]), atol=1e-4)
        (plane,) = [g for g in range(sim.model.ngeom)
                    if sim.model.geom_bodyid[g] == top and sim.model.geom_group[g] == COLLISION_GROUP]
        assert sim.model.geom_type[plane] == mujoco.mjtGeom.mjGEOM_PLANE
    finally:
        sim.close()


# Webots' CeilingLight: PointLight at 0 0 -0.6 (attenuation 0 0 1); bulb Sphere radius 0.15 at z -0.55.
def test_the_ceiling_light_shines_from_webots_point_under_a_large_bulb(tmp_path: Path):
    sim = _open(tmp_path, "DEF LAMP CeilingLight { }\n")
    try:
        model, data = sim.model, sim.data
        lamp = _body(sim, "LAMP")
        (light,) = [i for i in range(model.nlight) if model.light_bodyid[i] == lamp]
        np.testing.assert_allclose(data.light_xpos[light], [0, 0, 2.4 - 0.6], atol=1e-6)
        np.testing.assert_allclose(model.light_attenuation[light], [0, 0, 1])
        spheres = [g for g in range(model.ngeom) if model.geom_bodyid[g] == lamp
                   and model.geom_type[g] == mujoco.mjtGeom.mjGEOM_SPHERE]
        assert [round(float(model.geom_size[g][0]), 4) for g in spheres] == [0.15]
        assert abs(data.geom_xpos[spheres[0]][2] - (2.4 - 0.55)) < 1e-6
        low, _ = _bounds(sim, lamp, VISUAL_GROUP)
        assert abs(low[2] - (2.4 - 0.7)) < 1e-3
        assert not any(model.geom_group[g] == COLLISION_GROUP for g in range(model.ngeom)
                       if model.geom_bodyid[g] == lamp)
    finally:
        sim.close()


# Webots' CeilingSpotLight: SpotLight at 0 0 -0.038, cutOffAngle 0.48; model "ceiling light"; a SolidPipe
# (height 0.08, radius 0.05, thickness 0.01) at SolidPipe's default translation 0 0 1, so 1 m above the light.
def test_the_ceiling_spot_light_has_webots_light_and_its_pipe_one_metre_above(tmp_path: Path):
    sim = _open(tmp_path, "DEF SPOT CeilingSpotLight { translation 0 0 2 }\n")
    try:
        model, data = sim.model, sim.data
        spot = _body(sim, "SPOT")
        (light,) = [i for i in range(model.nlight) if model.light_bodyid[i] == spot]
        np.testing.assert_allclose(data.light_xpos[light], [0, 0, 2 - 0.038], atol=1e-6)
        assert model.light_cutoff[light] == np.float32(np.degrees(0.48))
        np.testing.assert_allclose(data.light_xdir[light], [0, 0, -1], atol=1e-6)
        colliding = [g for g in range(model.ngeom) if model.geom_group[g] == COLLISION_GROUP
                     and model.body_rootid[model.geom_bodyid[g]] == model.body_rootid[spot]]
        assert len(colliding) == 24
        low, high = _bounds(sim, model.geom_bodyid[colliding[0]])
        np.testing.assert_allclose([low[2], high[2]], [2 + 1 - 0.04, 2 + 1 + 0.04], atol=1e-4)
        assert max(high[:2]) <= 0.05 + 1e-6 and min(low[:2]) >= -0.05 - 1e-6
    finally:
        sim.close()


# Webots' CabinetHandle: 0.3 kg; bar Capsule radius r = 0.0055, height L = 0.065 at x = 2r along y; two feet
# Capsule radius 0.7r, height 2r along x at y = +-0.35L: the handle spans x -0.00935 ... 0.0165, y +-0.038.
def test_the_cabinet_handle_collides_through_its_bar_and_both_feet(tmp_path: Path):
    sim = _open(tmp_path, "DEF HANDLE CabinetHandle { translation 0 0 0.5 }\n")
    try:
        model = sim.model
        handle = [b for b in range(1, model.nbody) if model.body_jntnum[b] == 1][0]
        assert abs(model.body_mass[handle] - 0.3) < 1e-9
        capsules = sorted(tuple(np.round(model.geom_size[g][:2], 6)) for g in range(model.ngeom)
                          if model.geom_bodyid[g] == handle and model.geom_group[g] == COLLISION_GROUP)
        assert capsules == [(0.00385, 0.0055), (0.00385, 0.0055), (0.0055, 0.0325)]
        low, high = _bounds(sim, handle)
        np.testing.assert_allclose(low, [-0.00935, -0.038, 0.5 - 0.0055], atol=1e-5)
        np.testing.assert_allclose(high, [0.0165, 0.038, 0.5 + 0.0055], atol=1e-5)
    finally:
        sim.close()


# Webots' PottedTree: Cylinder r 0.17 h 0.27 at z 0.14, Cylinder r 0.04 h 0.46 at z 0.48, Sphere r 0.3 at
# z 1.046: the pot's bottom is 5 mm above the origin, so a tree with physics settles 5 mm down.
def test_a_potted_tree_collides_as_webots_and_settles_on_its_pot(tmp_path: Path):
    sim = _open(tmp_path, "DEF STILL PottedTree { translation 1 0 0 name \"still\" }\n"
                          "DEF TREE PottedTree { physics Physics { } }\n")
    try:
        model, data = sim.model, sim.data
        still, tree = _body(sim, "STILL"), _body(sim, "TREE")
        assert model.body_jntnum[still] == 0 and model.body_jntnum[tree] == 1
        low, high = _bounds(sim, still)
        np.testing.assert_allclose(low, [1 - 0.3, -0.3, 0.005], atol=1e-4)
        np.testing.assert_allclose(high, [1 + 0.3, 0.3, 1.346], atol=1e-4)
        shapes = sorted((int(model.geom_type[g]), *np.round(model.geom_size[g][:2], 4)) for g in range(model.ngeom)
                        if model.geom_bodyid[g] == still and model.geom_group[g] == COLLISION_GROUP)
        cylinder, sphere = int(mujoco.mjtGeom.mjGEOM_CYLINDER), int(mujoco.mjtGeom.mjGEOM_SPHERE)
        assert shapes == sorted([(cylinder, 0.17, 0.135), (cylinder, 0.04, 0.23), (sphere, 0.3, 0.0)])
        while sim.time < 1.0:
            sim.step()
        assert abs(data.xpos[tree][2] - -0.005) < 5e-4
        assert np.linalg.norm(data.xpos[tree][:2]) < 3e-4
        start = data.xpos[tree].copy()
        while sim.time < 1.5:
            sim.step()
        assert np.abs(data.xpos[tree] - start).max() < 3e-4
    finally:
        sim.close()


# Webots' drawn Keyboard case 0.1343 x 0.4094 m; drawn ComputerMouse 0.086 x 0.052 m, 0.034 m high (its collision
# box, 0.082 x 0.045 x 0.03, and the keyboard's are checked in test_office_objects.py).
def test_the_keyboard_and_mouse_are_drawn_at_webots_sizes(tmp_path: Path):
    sim = _open(tmp_path, "DEF KEYS Keyboard { translation 0 0 0.2 }\n"
                          "DEF MOUSE ComputerMouse { translation 1 0 0.2 mass 0 }\n")
    try:
        low, high = _bounds(sim, _body(sim, "KEYS"), VISUAL_GROUP)
        np.testing.assert_allclose((high - low)[:2], [0.1343, 0.4094], atol=5e-4)
        low, high = _bounds(sim, _body(sim, "MOUSE"), VISUAL_GROUP)
        np.testing.assert_allclose(high - low, [0.086, 0.052, 0.034], atol=5e-4)
    finally:
        sim.close()


# Webots' BunchOfSunFlowers (already matched): Cylinder r 0.1 h 0.648 at z 0.324, Sphere r 0.17 at z 0.78.
def test_the_bunch_of_sunflowers_keeps_webots_vase_and_crown_shapes(tmp_path: Path):
    sim = _open(tmp_path, "DEF FLOWERS BunchOfSunFlowers { }\n")
    try:
        low, high = _bounds(sim, _body(sim, "FLOWERS"))
        np.testing.assert_allclose(low, [-0.17, -0.17, 0.0], atol=1e-4)
        np.testing.assert_allclose(high, [0.17, 0.17, 0.95], atol=1e-4)
    finally:
        sim.close()
