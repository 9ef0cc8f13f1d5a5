"""JamJar, BiscuitBox, CerealBox and Gear collide, weigh and are recognized as Webots' are.

The numbers come from Webots' PROTO files (R2023a-R2025a, ENU), quoted in the comments; Webots' device samples
camera_recognition and camera_segmentation place the kitchen objects, coupled_motors the gears.
"""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import moved, simulations

from wbtc.runtime.devices import Camera

HEADER = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 6 6 }
"""


def _half(model: mujoco.MjModel, data: mujoco.MjData, g: int) -> np.ndarray:
    """Half extents (world axes) of collision geom `g`."""
    size, kind = model.geom_size[g], model.geom_type[g]
    rot = data.geom_xmat[g].reshape(3, 3)
    axis = rot[:, 2]
    if kind == mujoco.mjtGeom.mjGEOM_BOX:
        return np.abs(rot) @ size
    if kind == mujoco.mjtGeom.mjGEOM_SPHERE:
        return np.full(3, size[0])
    if kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
        return np.abs(axis) * size[1] + size[0]
    if kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
        return np.abs(axis) * size[1] + size[0] * np.sqrt(np.clip(1 - axis**2, 0, 1))
    raise AssertionError(f"unexpected collision geom type {kind}")


def _geoms(sim, body: int) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """(type, low corner, high corner) of every collision geom of `body`."""
    model, data = sim.model, sim.data
    mujoco.mj_forward(model, data)
    found = []
    for g in range(model.ngeom):
        if int(model.geom_bodyid[g]) != body or not (model.geom_contype[g] or model.geom_conaffinity[g]):
            continue
        half = _half(model, data, g)
        found.append((int(model.geom_type[g]), data.geom_xpos[g] - half, data.geom_xpos[g] + half))
    return found


def _extent(geoms) -> tuple[np.ndarray, np.ndarray]:
    assert geoms
    return np.min([lo for _, lo, _ in geoms], axis=0), np.max([hi for _, _, hi in geoms], axis=0)



@pytest.fixture
def world(tmp_path: Path):
    make, close = simulations(tmp_path, HEADER)
    yield make
    close()


def _body(sim, name: str) -> int:
    return int(sim.model.body(sim.table.bodies[name]).id)


# Webots' JamJar: boundingObject Pose { translation 0 0 0.058 Cylinder { height 0.115 radius 0.045 } };
# Physics { density -1 mass IS mass } only when mass > 0 (default 0.5 kg); model "jam jar";
# recognitionColors [ 0.55 0.06 0.06, 0.86 0.88 0.9 ].
def test_the_jam_jar_is_webots_cylinder_of_half_a_kilo(world):
    sim = world("DEF JAR JamJar { }\nDEF STILL JamJar { translation 1 0 0 mass 0 name \"still\" }\n")
    jar, still = _body(sim, "JAR"), _body(sim, "STILL")
    ((kind, low, high),) = _geoms(sim, jar)
    assert kind == mujoco.mjtGeom.mjGEOM_CYLINDER
    np.testing.assert_allclose(low, [-0.045, -0.045, 0.0005], atol=1e-6)
    np.testing.assert_allclose(high, [0.045, 0.045, 0.1155], atol=1e-6)
    assert sim.model.body_mass[jar] == pytest.approx(0.5)
    np.testing.assert_allclose(sim.model.body_ipos[jar], [0, 0, 0.058], atol=1e-6)  # the cylinder's centre
    assert sim.model.body_mass[still] == 0 and sim.model.body_jntnum[still] == 0  # mass 0: static, as in Webots
    assert len(_geoms(sim, still)) == 1  # but it still collides


# Webots' BiscuitBox: size 0.08 0.24 0.04; boundingObject a Box of `size` at (0, 0, size.z / 2); mass 0.4 kg;
# model "biscuit box"; recognitionColors [ 0.92 0.76 0.3 ]. camera_recognition resizes one to 0.17 0.33 0.04.
# Webots' CerealBox: size 0.08 0.2 0.3, the same Box at (0, 0, size.z / 2); mass 1 kg; model "cereal box".
@pytest.mark.parametrize(("node", "size", "mass"), [
    ("BiscuitBox { }", (0.08, 0.24, 0.04), 0.4),
    ("BiscuitBox { size 0.17 0.33 0.04 mass 0.25 }", (0.17, 0.33, 0.04), 0.25),
    ("BiscuitBox { size 0.1 0 0.1 }", (0.08, 0.24, 0.04), 0.4),  # a size that is not positive: the default
    ("CerealBox { }", (0.08, 0.2, 0.3), 1.0),
    ("CerealBox { size 0.06 0.15 0.25 mass 0.6 }", (0.06, 0.15, 0.25), 0.6),
])
def test_the_breakfast_boxes_are_webots_boxes_standing_on_their_origin(world, node, size, mass):
    sim = world("DEF BOX " + node + "\n")
    box = _body(sim, "BOX")
    ((kind, low, high),) = _geoms(sim, box)
    assert kind == mujoco.mjtGeom.mjGEOM_BOX
    sx, sy, sz = size
    np.testing.assert_allclose(low, [-sx / 2, -sy / 2, 0], atol=1e-6)
    np.testing.assert_allclose(high, [sx / 2, sy / 2, sz], atol=1e-6)
    assert sim.model.body_mass[box] == pytest.approx(mass)
    np.testing.assert_allclose(sim.model.body_ipos[box], [0, 0, sz / 2], atol=1e-6)


# Webots' Gear (defaults teeth 8, width 0.01, pitchRadius 0.04, toothDepth 0.01, density 0.001, translation
# 0 0 0.045): a bounding Cylinder of radius pitchRadius + toothDepth / 2 = 0.045 and height `width` along x, so
# the default gear stands on its rim on the ground; Physics { density IS density } (pi 0.045^2 0.01 0.001 =
# 6.36e-8 kg). With teethBoundingObject, each tooth adds a shape at radius r2 - t/2 (t = 2 r2 sin(pi / (4 teeth))
# is the tip's chord), angle (k + 3/8) 360/teeth from +y towards +z: a capsule along x of radius 0.7 t and
# height width - t when t <= width, else a sphere of radius 0.7 t.
def test_the_gear_collides_as_webots_rim_cylinder_and_weighs_its_density(world):
    sim = world("DEF GEAR Gear { }\n")
    gear = _body(sim, "GEAR")
    ((kind, low, high),) = _geoms(sim, gear)
    assert kind == mujoco.mjtGeom.mjGEOM_CYLINDER
    np.testing.assert_allclose(low, [-0.005, -0.045, 0], atol=1e-6)
    np.testing.assert_allclose(high, [0.005, 0.045, 0.09], atol=1e-6)
    assert sim.model.body_mass[gear] == pytest.approx(0.001 * np.pi * 0.045**2 * 0.01, rel=1e-6)


@pytest.mark.parametrize(("width", "kind"), [(0.01, mujoco.mjtGeom.mjGEOM_CAPSULE),
                                             (0.004, mujoco.mjtGeom.mjGEOM_SPHERE)])
def test_the_gear_teeth_bounding_objects_sit_on_the_tooth_tips(world, width, kind):
    sim = world(f"DEF GEAR Gear {{ translation 0 0 0.1 width {width} teethBoundingObject TRUE }}\n")
    geoms = _geoms(sim, _body(sim, "GEAR"))
    teeth = [g for g in geoms if g[0] == kind]
    assert len(geoms) == 9 and len(teeth) == 8
    r2 = 0.045
    t = 2 * r2 * np.sin(np.pi / 32)
    radius = 0.7 * t
    along_x = (width - t) / 2 + radius if kind == mujoco.mjtGeom.mjGEOM_CAPSULE else radius
    for k, (_, low, high) in enumerate(teeth):
        angle = (k + 3 / 8) * 2 * np.pi / 8
        centre = np.array([0, (r2 - t / 2) * np.cos(angle), 0.1 + (r2 - t / 2) * np.sin(angle)])
        np.testing.assert_allclose((low + high) / 2, centre, atol=1e-6)
        np.testing.assert_allclose((high - low) / 2, [along_x, radius, radius], atol=1e-6)


# coupled_motors.wbt: Gear { teeth 12 width 0.003 innerRadius 0.0025 pitchRadius 0.0078 toothDepth 0.002
# density 0 bodyBoundingObject FALSE } inside a finger Solid: no physics and nothing to collide with.
def test_a_gear_without_density_or_bounding_object_is_only_drawn(world):
    sim = world("DEF FINGER Solid { children [ DEF GEAR Gear { teeth 12 width 0.003 innerRadius 0.0025 "
                "pitchRadius 0.0078 toothDepth 0.002 density 0 bodyBoundingObject FALSE } ] }\n")
    gear = _body(sim, "GEAR")
    assert sim.model.body_mass[gear] == 0 and sim.model.body_jntnum[gear] == 0
    assert _geoms(sim, gear) == []
    drawn = [g for g in range(sim.model.ngeom) if int(sim.model.geom_bodyid[g]) == gear]
    assert len(drawn) == 1 + 12  # the disc and one box per tooth
    mujoco.mj_forward(sim.model, sim.data)
    model, data = sim.model, sim.data
    disc = [g for g in drawn if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CYLINDER]
    assert len(disc) == 1 and model.geom_size[disc[0]][0] == pytest.approx(0.0078 - 0.001)  # the teeth's root
    corners = np.array([[sx, sy, sz] for sx in (1, -1) for sy in (1, -1) for sz in (1, -1)])
    reach = []
    for g in drawn:
        if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_BOX:
            points = data.geom_xpos[g] + (corners * model.geom_size[g]) @ data.geom_xmat[g].reshape(3, 3).T
            reach.append(np.max(np.linalg.norm(points[:, 1:] - data.xpos[gear][1:], axis=1)))
    assert max(reach) == pytest.approx(0.0078 + 0.001, abs=1e-7)  # drawn up to the outer radius, not beyond


# Each object with physics stands still on the floor. The jam jar's cylinder starts 0.5 mm above its origin
# (it would drop that far from the default translation, as in Webots): it is set on the floor here.
@pytest.mark.parametrize("node", ["JamJar { translation 0 0 -0.0005 }", "BiscuitBox { }", "CerealBox { }",
                                  "BiscuitBox { size 0.17 0.33 0.04 }", "Gear { }"])
def test_each_object_rests_on_the_floor(world, node):
    sim = world("DEF OBJ " + node + "\n")
    assert sim.model.body_mass[_body(sim, "OBJ")] > 0
    assert np.max(moved(sim)) < 3e-4


# A camera with recognition reports the jam jar and the biscuit box with their model names and recognition
# colours; Webots' CerealBox has no recognitionColors, so it is not reported (nor is the Gear, which has none).
def test_a_recognition_camera_sees_the_jar_and_the_biscuit_box_but_not_the_cereal_box(world):
    sim = world('Robot { controller "<none>" children [ Camera { translation 0 0 0.1 width 128 height 64 '
                "fieldOfView 1 recognition Recognition { } } ] }\n"
                "JamJar { translation 0.6 0.2 0 }\n"
                "BiscuitBox { translation 0.6 -0.2 0 }\n"
                "CerealBox { translation 0.7 0 0 }\n"
                "Gear { translation 0.5 0 0.045 }\n")
    (robot,) = sim.robots
    camera = next(s for s in robot.sensors.values() if isinstance(s, Camera))
    seen = {o["model"]: o for o in camera.recognize(sim)}
    assert set(seen) == {"jam jar", "biscuit box"}
    jar, box = seen["jam jar"], seen["biscuit box"]
    assert jar["colors"] == [[0.55, 0.06, 0.06], [0.86, 0.88, 0.9]]
    assert box["colors"] == [[0.92, 0.76, 0.3]]
    # positions in the camera frame (x ahead, y left, z up): the bounding objects' centres
    assert jar["position"] == pytest.approx([0.6, 0.2, 0.058 - 0.1], abs=0.01)
    assert box["position"] == pytest.approx([0.6, -0.2, 0.02 - 0.1], abs=0.01)
    assert jar["position_on_image"][0] < 64 < box["position_on_image"][0]  # the jar on the left
