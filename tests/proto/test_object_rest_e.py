"""Rocks, animals, a watering can and a stair rail collide through Webots' bounding objects, at Webots' sizes."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

HEADER = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 6 6 }
"""


def _cube(name: str, x: float, z: float, edge: float) -> str:
    return (
        f'DEF {name} SolidBox {{ translation {x} 0 {z} size {edge} {edge} {edge} '
        f'physics Physics {{ density -1 mass 0.05 }} name "{name}" }}\n'
    )


def _ball(name: str, x: float, z: float, radius: float) -> str:
    return (
        f"DEF {name} Solid {{ translation {x} 0 {z} children [ DEF {name}_SHAPE Shape {{ geometry Sphere {{ "
        f"radius {radius} }} }} ] boundingObject USE {name}_SHAPE physics Physics {{ density -1 mass 0.05 }} "
        f'name "{name}" }}\n'
    )


def _after_one_second(tmp_path: Path, world: str, bodies: list[str]) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Where each of `bodies` (DEF names) starts and where it is after 1 s of `world`."""
    sim = simulation_of(tmp_path, world)
    try:
        mujoco.mj_forward(sim.model, sim.data)
        ids = {b: sim.model.body(sim.table.bodies[b]).id for b in bodies}
        start = {b: sim.data.xpos[i].copy() for b, i in ids.items()}
        while sim.time < 1.0:
            sim.step()
        return {b: (start[b], sim.data.xpos[i].copy()) for b, i in ids.items()}
    finally:
        sim.close()


def _collision_boxes(tmp_path: Path, world: str) -> list[tuple[int, np.ndarray, np.ndarray]]:
    """The world-frame bounds (lowest and highest corner) and type of every colliding geom but the floor's."""
    sim = simulation_of(tmp_path, world)
    try:
        model, data = sim.model, sim.data
        mujoco.mj_forward(model, data)
        out = []
        for g in range(model.ngeom):
            kind = int(model.geom_type[g])
            if not (model.geom_contype[g] or model.geom_conaffinity[g]) or kind == mujoco.mjtGeom.mjGEOM_PLANE:
                continue
            turn, centre, size = data.geom_xmat[g].reshape(3, 3), data.geom_xpos[g], model.geom_size[g]
            if kind == mujoco.mjtGeom.mjGEOM_MESH:
                first, count = model.mesh_vertadr[model.geom_dataid[g]], model.mesh_vertnum[model.geom_dataid[g]]
                points = model.mesh_vert[first : first + count] @ turn.T + centre
                out.append((kind, points.min(0), points.max(0)))
                continue
            if kind == mujoco.mjtGeom.mjGEOM_BOX:
                half = np.abs(turn) @ size
            elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
                half = np.full(3, size[0])
            elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
                half = np.abs(turn[:, 2]) * size[1] + size[0]
            else:  # a cylinder
                axis = turn[:, 2]
                half = np.abs(axis) * size[1] + size[0] * np.sqrt(np.clip(1 - axis**2, 0, 1))
            out.append((kind, centre - half, centre + half))
        return out
    finally:
        sim.close()


def _extent(parts: list[tuple[int, np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    return np.min([p[1] for p in parts], axis=0), np.max([p[2] for p in parts], axis=0)


# StraightStairsRail (defaults: run 2, rise 0.75, width 0.04, newels 0.93 m, balusters 0.8 m of radius 0.01):
# Webots' newels, balusters, middle rail and top rail all collide. With o = (0.93 - 0.8 + 0.02) / 2 = 0.075,
# baluster k of n is centred at x = 2 k / (n + 1), z = 0.75 k / (n + 1) + 0.465 + o; the top rail's centre
# line runs 0.94 m above the stair line (z = 0.375 x), 4 cm thick vertically, 4.8 cm wide, its vertical ends
# at x = -0.0417 and 2.0417; the middle rail's centre line runs 0.14 m above it, 3.92 cm high and 2 cm wide.
def test_the_stair_rail_collides_through_its_newels_balusters_and_both_rails(tmp_path: Path):
    parts = _collision_boxes(tmp_path, HEADER + "StraightStairsRail { nBalusters 3 }\n")
    boxes = sorted((p for p in parts if p[0] == mujoco.mjtGeom.mjGEOM_BOX), key=lambda p: p[1][0])
    cylinders = sorted((p for p in parts if p[0] == mujoco.mjtGeom.mjGEOM_CYLINDER), key=lambda p: p[1][0])
    prisms = sorted((p for p in parts if p[0] == mujoco.mjtGeom.mjGEOM_MESH), key=lambda p: p[2][2])
    # was a single box: the top bar, 8.6 mm lower and 8 mm narrower than Webots' top rail
    assert (len(boxes), len(cylinders), len(prisms)) == (2, 3, 2)
    assert boxes[0][1] == pytest.approx([-0.02, -0.02, 0], abs=1e-6)  # the start newel
    assert boxes[0][2] == pytest.approx([0.02, 0.02, 0.93], abs=1e-6)
    assert boxes[1][1] == pytest.approx([1.98, -0.02, 0.75], abs=1e-6)  # the end newel
    assert boxes[1][2] == pytest.approx([2.02, 0.02, 1.68], abs=1e-6)
    for k, (_, low, high) in enumerate(cylinders, start=1):
        assert (low + high) / 2 == pytest.approx([0.5 * k, 0, 0.1875 * k + 0.54], abs=1e-6)
        assert high - low == pytest.approx([0.02, 0.02, 0.8], abs=1e-6)
    middle, top = prisms
    assert middle[1] == pytest.approx([0, -0.01, 0.14 - 0.0196], abs=1e-4)
    assert middle[2] == pytest.approx([2, 0.01, 0.14 + 0.75 + 0.0196], abs=1e-4)
    assert top[1] == pytest.approx([-0.041667, -0.024, 0.94 - 0.02 - 0.375 * 0.041667], abs=1e-4)
    assert top[2] == pytest.approx([2.041667, 0.024, 0.94 + 0.02 + 0.375 * 2.041667], abs=1e-4)


@pytest.mark.parametrize(
    ("rail", "top", "edge"),
    [("top", 0.96, 0.04), ("middle", 0.14 + 0.0196, 0.02)],  # a level rail (rise 0): its rails' upper faces
)
def test_a_cube_set_on_a_level_rail_at_webots_height_stays_there(tmp_path: Path, rail: str, top: float, edge: float):
    # The middle rail's cube sits midway between the 10th and 11th of the 20 balusters.
    world = HEADER + "StraightStairsRail { rise 0 }\n" + _cube("CUBE", 1.0, top + edge / 2, edge)
    start, end = _after_one_second(tmp_path, world, ["CUBE"])["CUBE"]
    # was: fell 1 cm from the top rail (the bar was 0.95 m high), to the floor from the middle rail (none)
    assert float(np.linalg.norm(end - start)) < 3e-4


def test_the_rocks_have_webots_extents_and_volumes(tmp_path: Path):
    # Webots' meshes: regular x -0.0668 ... 0.0659, y -0.054 ... 0.0574, z -0.0562 ... 0.0494 (706 cm3);
    # flat x -0.1737 ... 0.22, y -0.1276 ... 0.13, z 0 ... 0.1759 (8393 cm3).
    world = HEADER + (
        'DEF REGULAR Rock { translation 0 0 0.3 physics Physics { density 1000 } }\n'
        'DEF FLAT Rock { translation 1 0 0 type "flat" name "flat" physics Physics { density 1000 } }\n'
    )
    parts = _collision_boxes(tmp_path, world)
    regular = _extent([p for p in parts if p[1][0] < 0.5])
    flat = _extent([p for p in parts if p[1][0] > 0.5])
    # was 11.5 x 10.3 x 9.2 cm (9 mm less deep below its origin) and 36 x 25.5 x 17.5 cm
    assert regular[0] == pytest.approx([-0.0668, -0.054, 0.3 - 0.0562], abs=2e-4)
    assert regular[1] == pytest.approx([0.0659, 0.0574, 0.3 + 0.0494], abs=2e-4)
    assert flat[0] == pytest.approx([1 - 0.1737, -0.1276, 0], abs=2e-4)
    assert flat[1] == pytest.approx([1.22, 0.13, 0.1759], abs=2e-4)
    sim = simulation_of(tmp_path, world, "masses.wbt")
    try:
        model = sim.model
        masses = {name: float(model.body_mass[model.body(sim.table.bodies[name]).id]) for name in ("REGULAR", "FLAT")}
    finally:
        sim.close()
    # was 0.47 and 6.45 kg (a third and a quarter light)
    assert masses["REGULAR"] == pytest.approx(0.706, rel=0.1)
    assert masses["FLAT"] == pytest.approx(8.393, rel=0.1)


def test_a_flat_rock_with_physics_stays_on_its_flat_underside(tmp_path: Path):
    world = HEADER + 'DEF ROCK Rock { type "flat" physics Physics { density 2500 } }\n'
    start, end = _after_one_second(tmp_path, world, ["ROCK"])["ROCK"]
    assert float(np.linalg.norm(end - start)) < 3e-4


def test_the_cat_collides_through_webots_parts(tmp_path: Path):
    parts = _collision_boxes(tmp_path, HEADER + "Cat { }\n")
    low, high = _extent(parts)
    # Webots' 21 parts: the paws (radius 2 cm) on the ground, the muzzle 0.202 m ahead, the tail's tip
    # 0.348 m behind, the ears 0.342 m up; was 10 parts, 0.315 m behind, 0.205 ahead, 0.343 up
    assert len(parts) == 21
    assert low == pytest.approx([-0.3478, -0.0584, 0], abs=1e-3)
    assert high == pytest.approx([0.202, 0.0599, 0.3421], abs=1e-3)


def test_a_ball_dropped_on_the_cats_back_rests_on_its_upper_body(tmp_path: Path):
    # Webots' upper-body capsule (radius 0.045 m, 0.205 m up) tops the cat's back at 0.25 m.
    world = HEADER + "Cat { }\n" + _ball("BALL", 0, 0.4, 0.02)
    _, end = _after_one_second(tmp_path, world, ["BALL"])["BALL"]
    assert end[2] == pytest.approx(0.25 + 0.02, abs=3e-4)  # was 0.255 (the body alone, 5 mm lower)


def test_the_rabbit_collides_through_webots_parts(tmp_path: Path):
    sim = simulation_of(tmp_path, HEADER + "Rabbit { }\n")
    try:
        recognised = {r.model: r.colors for r in sim.table.recognizable}
    finally:
        sim.close()
    assert recognised["rabbit"] == [[0.827, 0.827, 0.827]]
    parts = _collision_boxes(tmp_path, HEADER + "Rabbit { }\n")
    kinds = sorted(int(p[0]) for p in parts)
    # Webots' slanted body capsule, paws box and two ear boxes; was two spheres 0.2 m wide
    assert kinds == sorted([int(mujoco.mjtGeom.mjGEOM_CAPSULE)] + [int(mujoco.mjtGeom.mjGEOM_BOX)] * 3)
    low, high = _extent(parts)
    assert low == pytest.approx([-0.0604, -0.0556, 0], abs=1e-3)
    assert high == pytest.approx([0.1856, 0.0492, 0.2549], abs=1e-3)


def test_the_watering_can_handle_capsules_are_at_webots_poses(tmp_path: Path):
    sim = simulation_of(tmp_path, HEADER + "WateringCan { }\n")
    try:
        model, data = sim.model, sim.data
        mujoco.mj_forward(model, data)
        capsules = [g for g in range(model.ngeom) if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_CAPSULE]
        poses = sorted(
            (round(float(data.geom_xpos[g][0]), 4), round(float(data.geom_xpos[g][2]), 4),
             round(float(np.degrees(np.arctan2(*data.geom_xmat[g].reshape(3, 3)[[0, 2], 2]))) % 180, 1))
            for g in capsules
            if model.geom_contype[g] or model.geom_conaffinity[g]
        )
    finally:
        sim.close()
    # (x, z, the axis' angle from +z towards +x, modulo 180 degrees); were up to 7 mm away
    assert poses == [(-0.3783, 0.3869, 165.0), (-0.3662, 0.5774, 15.0), (-0.2983, 0.222, 135.0),
                     (-0.2451, 0.6947, 75.0), (-0.0703, 0.7141, 90.0), (0.1034, 0.6461, 135.0)]
