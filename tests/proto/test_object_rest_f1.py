"""Laptop and Book collide and weigh as Webots' do, and rest where Webots puts them."""

from pathlib import Path

import mujoco
import numpy as np
from conftest import simulation_of

HEADER = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 }
Floor { size 6 6 }
"""


def _settle(tmp_path: Path, node: str):
    """Body masses, collision-box bounds (world frame), start and end positions after 1 s, end qpos."""
    sim = simulation_of(tmp_path, HEADER + "DEF OBJ " + node + "\n")
    try:
        model, data = sim.model, sim.data
        mujoco.mj_forward(model, data)
        boxes = []
        for g in range(model.ngeom):
            colliding = model.geom_contype[g] or model.geom_conaffinity[g]
            if model.geom_type[g] != mujoco.mjtGeom.mjGEOM_BOX or not colliding:
                continue
            half = np.abs(data.geom_xmat[g].reshape(3, 3)) @ model.geom_size[g]
            boxes.append((int(model.geom_bodyid[g]), data.geom_xpos[g] - half, data.geom_xpos[g] + half))
        start = data.xpos.copy()
        while sim.time < 1.0:
            sim.step()
        return model.body_mass.copy(), boxes, start, data.xpos.copy(), data.qpos.copy(), model
    finally:
        sim.close()


# Webots' Laptop: base box 0.36 x 0.02 x 0.233 turned so that it spans x -0.0585..0.1745, y +-0.18, z 0..0.02,
# density 1200 (2.013 kg); lid Solid of 0.5 kg on a HingeJoint (stops -2.105..0.01), its box 0.359 x 0.232 x 0.011
# leaning back: x -0.1856..-0.0584, y -0.1735..0.1855, z 0.0042..0.2098.
def test_the_laptop_base_and_hinged_lid_have_webots_boxes_and_masses(tmp_path: Path):
    mass, boxes, start, end, qpos, model = _settle(tmp_path, "Laptop { }")
    assert model.njnt == 2 and model.jnt_type[1] == mujoco.mjtJoint.mjJNT_HINGE
    np.testing.assert_allclose(sorted(mass[1:])[-2:], [0.5, 1200 * 0.36 * 0.02 * 0.233], rtol=0.01)
    lows = sorted(((lo, hi) for _, lo, hi in boxes), key=lambda b: b[0][2])
    np.testing.assert_allclose(lows[0][0], [-0.0585, -0.18, 0.0], atol=0.002)
    np.testing.assert_allclose(lows[0][1], [0.1745, 0.18, 0.02], atol=0.002)
    np.testing.assert_allclose(lows[1][0], [-0.1856, -0.1735, 0.0042], atol=0.002)
    np.testing.assert_allclose(lows[1][1], [-0.0584, 0.1855, 0.2098], atol=0.002)


def test_a_laptop_rests_on_the_floor_with_its_lid_within_its_stops(tmp_path: Path):
    mass, boxes, start, end, qpos, model = _settle(tmp_path, "Laptop { }")
    base = model.jnt_bodyid[0]
    assert np.abs(end[base] - start[base]).max() < 3e-4
    assert -2.105 <= qpos[7] <= 0.0101


def test_a_book_at_its_default_translation_stands_on_the_floor(tmp_path: Path):
    mass, boxes, start, end, qpos, model = _settle(tmp_path, "Book { }")
    (_, lo, hi), = boxes
    np.testing.assert_allclose(lo, [-0.01, -0.075, 0.0], atol=0.002)
    np.testing.assert_allclose(hi, [0.01, 0.075, 0.2], atol=0.002)
    assert np.abs(end - start).max() < 3e-4
