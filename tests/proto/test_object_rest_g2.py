"""Valves, pipes, a manhole, an advertising board and a palm tree collide and weigh as Webots' do.

The numbers come from Webots' PROTO files (R2023b-R2025a, ENU), quoted in the comments.
"""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import moved, simulations

HEADER = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 20 20 }
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
    if kind == mujoco.mjtGeom.mjGEOM_ELLIPSOID:
        return np.sqrt((rot * size) ** 2 @ np.ones(3))
    raise AssertionError(f"unexpected collision geom type {kind}")


def _geoms(sim) -> list[tuple[int, int, np.ndarray, np.ndarray]]:
    """(body, type, low corner, high corner) of every collision geom but the floor's plane."""
    model, data = sim.model, sim.data
    mujoco.mj_forward(model, data)
    found = []
    for g in range(model.ngeom):
        colliding = model.geom_contype[g] or model.geom_conaffinity[g]
        if not colliding or model.geom_type[g] == mujoco.mjtGeom.mjGEOM_PLANE:
            continue
        half = _half(model, data, g)
        found.append((int(model.geom_bodyid[g]), int(model.geom_type[g]), data.geom_xpos[g] - half,
                      data.geom_xpos[g] + half))
    return found


def _extent(geoms, body: int | None = None) -> tuple[np.ndarray, np.ndarray]:
    chosen = [(lo, hi) for b, _, lo, hi in geoms if body is None or b == body]
    assert chosen
    return np.min([lo for lo, _ in chosen], axis=0), np.max([hi for _, hi in chosen], axis=0)



@pytest.fixture
def world(tmp_path: Path):
    make, close = simulations(tmp_path, HEADER)
    yield make
    close()


# Webots' LargeValve: static body box 0.15 m at (-0.02, 0, -0.0085); the wheel (default Physics, density 1000)
# collides as capsules (r 0.008: heights 0.045, 0.05, 0.025, 0.045, 0.025, 0.05; r 0.0065: 0.05, 0.045, 0.05,
# 0.045), hub discs r 0.025 and 0.016 (h 0.005), boxes 0.009 x 0.01 x 0.0345 (3) and x 0.028 (5), and a boss
# 0.009 x 0.07 x 0.0525 at x = 0.102: 0.1598 kg, from x = 0.102 - 0.0045 to 0.117 + 0.008 (robot frame).
def test_the_large_valve_wheel_weighs_and_spans_as_webots_and_holds_still(world):
    sim = world('LargeValve { controller "<none>" }\n')
    model = sim.model
    wheel = int(model.jnt_bodyid[0])
    def capsule(r: float, h: float) -> float:
        return np.pi * r**2 * h + 4 / 3 * np.pi * r**3

    webots = 1000 * (0.009 * 0.07 * 0.0525
                     + sum(capsule(0.008, h) for h in (0.045, 0.05, 0.025, 0.045, 0.025, 0.05))
                     + sum(capsule(0.0065, h) for h in (0.05, 0.045, 0.05, 0.045))
                     + np.pi * 0.005 * (0.025**2 + 0.016**2) + 0.009 * 0.01 * (3 * 0.0345 + 5 * 0.028))
    assert webots == pytest.approx(0.1598, abs=1e-4)
    assert model.body_mass[wheel] == pytest.approx(webots, rel=0.01)
    geoms = _geoms(sim)
    body_low, body_high = _extent(geoms, int(model.body(sim.table.robots[0].body).id))
    np.testing.assert_allclose(body_low, [-0.095, -0.075, 0.106 - 0.0835], atol=1e-4)
    np.testing.assert_allclose(body_high, [0.055, 0.075, 0.106 + 0.0665], atol=1e-4)
    low, high = _extent(geoms, wheel)
    assert [low[0], high[0]] == pytest.approx([0.0975, 0.125], abs=0.002)
    assert -low[1] == pytest.approx(0.098, abs=0.004) and high[1] == pytest.approx(0.098, abs=0.004)
    assert np.max(moved(sim)) < 3e-4


# Webots' SmallValve: the wheel collides as a cylinder r 0.027, h 0.0138 along x centred at (0.0552, 0, -0.0102).
def test_the_small_valve_wheel_is_webots_cylinder(world):
    sim = world('SmallValve { controller "<none>" }\n')
    wheel = int(sim.model.jnt_bodyid[0])
    low, high = _extent(_geoms(sim), wheel)
    np.testing.assert_allclose(low, [0.0552 - 0.0069, -0.027, 0.077 - 0.0102 - 0.027], atol=1e-4)
    np.testing.assert_allclose(high, [0.0552 + 0.0069, 0.027, 0.077 - 0.0102 + 0.027], atol=1e-4)
    assert np.max(moved(sim)) < 3e-4


# Webots' LeverValve (scale 0.7): static body box (0.35, 0.29, 0.3) x scale at (-0.04, 0, -0.02) x scale; the lever
# turns on a HingeJoint about x through (0, 0, -0.02), stops 0..1.5708; its Physics (density 1000) holds a box
# (0.007, 0.028, 0.27) x scale, a sphere r 0.0262 x 0.7 and a disc r 0.05 x 0.7, 0.01 x 0.7 thick.
def test_the_lever_valve_body_box_and_its_turning_lever(world):
    sim = world("LeverValve { }\n")
    model = sim.model
    assert model.njnt == 1 and model.jnt_type[0] == mujoco.mjtJoint.mjJNT_HINGE
    np.testing.assert_allclose(model.jnt_range[0], [0, 1.5708])
    mujoco.mj_forward(model, sim.data)
    np.testing.assert_allclose(sim.data.xaxis[0], [1, 0, 0], atol=1e-9)
    np.testing.assert_allclose(sim.data.xanchor[0], [0, 0, 0.142 - 0.02], atol=1e-9)
    lever = int(model.jnt_bodyid[0])
    s = 0.7
    volume = (0.007 * 0.028 * 0.27 + 4 / 3 * np.pi * 0.0262**3 + np.pi * 0.05**2 * 0.01) * s**3
    assert model.body_mass[lever] == pytest.approx(1000 * volume, rel=1e-3)  # 0.0709 kg
    geoms = _geoms(sim)
    low, high = _extent([g for g in geoms if g[0] != lever])
    np.testing.assert_allclose(low, [-0.04 * s - 0.175 * s, -0.145 * s, 0.142 - 0.02 * s - 0.15 * s], atol=1e-4)
    np.testing.assert_allclose(high, [-0.04 * s + 0.175 * s, 0.145 * s, 0.142 - 0.02 * s + 0.15 * s], atol=1e-4)
    lever_low, lever_high = _extent(geoms, lever)
    assert lever_high[2] == pytest.approx(0.142 + 0.3561 * s + 0.0262 * s, abs=1e-4)  # top of the ball
    assert lever_low[2] == pytest.approx(0.142 - 0.0194 * s - 0.05 * s, abs=1e-4)  # bottom of the disc
    assert np.max(moved(sim)) < 3e-4


# Webots' SquareManhole: boundingObject USE of the Shape's Box (size 1 1 0.1) centred on the origin.
def test_the_manhole_is_a_centred_box_and_carries_a_box(world):
    sim = world("SquareManhole { }\n"
                "DEF CUBE Solid { translation 0.2 0.1 0.3\n"
                "  children [ DEF C Shape { geometry Box { size 0.05 0.05 0.05 } } ]\n"
                "  boundingObject USE C physics Physics { } }\n")
    cube = int(sim.model.body(sim.table.bodies["CUBE"]).id)
    low, high = _extent([g for g in _geoms(sim) if g[0] != cube])
    np.testing.assert_allclose(low, [-0.5, -0.5, -0.05], atol=1e-6)
    np.testing.assert_allclose(high, [0.5, 0.5, 0.05], atol=1e-6)
    moved(sim)
    assert sim.data.xpos[cube][2] == pytest.approx(0.05 + 0.025, abs=1e-3)


def _webots_l_joint_capsules() -> tuple[np.ndarray, np.ndarray]:
    # Webots' LJoint: Capsules r 0.035, h 0.04 at (x, z) (0.031098346, -0.036), (-0.036079734, 0.029794677),
    # (-0.019555909, -0.0041774259), turned about y by 1.8325997, -0.2, -0.59269969; not scaled since R2023b.
    lows, highs = [], []
    for x, z, angle in ((0.031098346, -0.036, 1.8325997), (-0.036079734, 0.029794677, -0.2),
                        (-0.019555909, -0.0041774259, -0.59269969)):
        half = np.abs([np.sin(angle), 0, np.cos(angle)]) * 0.02 + 0.035
        lows.append(np.array([x, 0, z]) - half)
        highs.append(np.array([x, 0, z]) + half)
    return np.min(lows, axis=0), np.max(highs, axis=0)


def test_the_l_joint_capsules_do_not_scale(world):
    sim = world('DEF PLAIN LJoint { }\nDEF BIG LJoint { translation 1 0 0.2 scale 2 2 2 name "big" }\n')
    geoms = _geoms(sim)
    expected_low, expected_high = _webots_l_joint_capsules()
    for name, origin in (("PLAIN", [0, 0, 0.08]), ("BIG", [1, 0, 0.2])):
        body = int(sim.model.body(sim.table.bodies[name]).id)
        assert len([g for g in geoms if g[0] == body]) == 3
        low, high = _extent(geoms, body)
        np.testing.assert_allclose(low, expected_low + origin, atol=1e-6)
        np.testing.assert_allclose(high, expected_high + origin, atol=1e-6)


# Webots' AdvertisingBoard: a Solid "board" (box frameThickness x displayWidth + 0.2 x displayHeight + 0.2) at
# z = displayHeight / 2 + 0.1 without poles, poleHeight - 0.6 displayHeight - 0.2 with poles; two poles at
# y = +-displayWidth / 4, cylinders of radius poleThickness / 2 and height poleHeight standing on the ground.
def test_the_advertising_board_stands_on_the_ground_or_on_its_poles(world):
    sim = world('DEF PLAIN AdvertisingBoard { }\n'
                'DEF POLES AdvertisingBoard { translation 0 10 0 poleNumber 2 name "on poles" }\n')
    geoms = _geoms(sim)
    boxes = sorted((g for g in geoms if g[1] == mujoco.mjtGeom.mjGEOM_BOX), key=lambda g: g[2][1])
    cylinders = sorted((g for g in geoms if g[1] == mujoco.mjtGeom.mjGEOM_CYLINDER), key=lambda g: g[2][1])
    assert len(boxes) == 2 and len(cylinders) == 2
    np.testing.assert_allclose(boxes[0][2], [-0.3, -2.1, 0], atol=1e-6)
    np.testing.assert_allclose(boxes[0][3], [0.3, 2.1, 3.2], atol=1e-6)
    np.testing.assert_allclose(boxes[1][2], [-0.3, 10 - 2.1, 5 - 1.8 - 0.2 - 1.6], atol=1e-6)
    np.testing.assert_allclose(boxes[1][3], [0.3, 10 + 2.1, 5 - 1.8 - 0.2 + 1.6], atol=1e-6)
    for (_, _, low, high), y in zip(cylinders, (9, 11), strict=True):
        np.testing.assert_allclose(low, [-0.2, y - 0.2, 0], atol=1e-6)
        np.testing.assert_allclose(high, [0.2, y + 0.2, 5], atol=1e-6)


# Webots' PalmTree: boundingObject Pose { translation 0 0 1.125 Cylinder { height 2.25 radius 0.35 } }.
def test_the_palm_tree_trunk_collides_up_to_two_and_a_quarter_metres(world):
    sim = world("PalmTree { }\n")
    ((_, kind, low, high),) = _geoms(sim)
    assert kind == mujoco.mjtGeom.mjGEOM_CYLINDER
    np.testing.assert_allclose(low, [-0.35, -0.35, 0], atol=1e-6)
    np.testing.assert_allclose(high, [0.35, 0.35, 2.25], atol=1e-6)
