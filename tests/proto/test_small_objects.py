"""wbtc's LegoWheel and Cat: Webots' interfaces, sizes and masses, a wheel that rolls, a cat that blocks."""

from pathlib import Path

import mujoco
import numpy as np
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/objects/lego/protos/LegoWheel.proto"
EXTERNPROTO "webots://projects/objects/animals/protos/Cat.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 10 10
}
DEF WHEEL LegoWheel {
}
DEF DROPPED LegoWheel {
  translation 1 0 0.1
  name "dropped wheel"
}
DEF CAT Cat {
  translation 0 2 0
}
DEF BIG_CAT Cat {
  translation 3 0 0
  scale 2
  color 0.5 0.5 0.5
  name "big cat"
}
DEF BALL Solid {
  translation 3.2 0 1
  children [
    DEF BALL_SHAPE Shape {
      geometry Sphere {
        radius 0.02
      }
    }
  ]
  boundingObject USE BALL_SHAPE
  physics Physics {
    density -1
    mass 0.01
  }
}
"""


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "small_objects.wbt")
    yield simulation
    simulation.close()


def _extent(sim, body: int) -> tuple[np.ndarray, np.ndarray]:
    """The lowest and highest corners (world frame) of `body`'s collision geoms (boxes, spheres, capsules,
    cylinders exactly; other geoms by their bounding spheres)."""
    model, data = sim.model, sim.data
    mujoco.mj_forward(model, data)
    low, high = np.full(3, np.inf), np.full(3, -np.inf)
    for g in range(model.ngeom):
        b = model.geom_bodyid[g]
        if b != body or not (model.geom_contype[g] or model.geom_conaffinity[g]):
            continue
        centre, size, kind = data.geom_xpos[g], model.geom_size[g], model.geom_type[g]
        axis = data.geom_xmat[g].reshape(3, 3)[:, 2]
        if kind == mujoco.mjtGeom.mjGEOM_BOX:
            half = np.abs(data.geom_xmat[g].reshape(3, 3)) @ size
        elif kind == mujoco.mjtGeom.mjGEOM_SPHERE:
            half = np.full(3, size[0])
        elif kind == mujoco.mjtGeom.mjGEOM_CAPSULE:
            half = np.abs(axis) * size[1] + size[0]
        elif kind == mujoco.mjtGeom.mjGEOM_CYLINDER:
            half = np.abs(axis) * size[1] + size[0] * np.sqrt(np.clip(1 - axis**2, 0, 1))
        else:
            half = model.geom_rbound[g]
        low, high = np.minimum(low, centre - half), np.maximum(high, centre + half)
    return low, high


def test_the_lego_wheel_weighs_27_grams_and_rests_on_its_22_mm_radius(sim):
    model, data = sim.model, sim.data
    wheel = model.body(sim.table.bodies["WHEEL"]).id
    dropped = model.body(sim.table.bodies["DROPPED"]).id
    assert model.body_mass[wheel] == pytest.approx(0.027)
    (geom,) = [g for g in range(model.ngeom) if model.geom_bodyid[g] == wheel and model.geom_contype[g]]
    assert model.geom_type[geom] == mujoco.mjtGeom.mjGEOM_CYLINDER
    assert list(model.geom_size[geom][:2]) == pytest.approx([0.022, 0.0135])
    mujoco.mj_forward(model, data)
    axis = data.geom_xmat[geom].reshape(3, 3)[:, 2]
    assert abs(axis[1]) == pytest.approx(1.0, abs=1e-6)  # the axle along y
    for _ in range(125):  # 1 s
        sim.step()
    mujoco.mj_forward(model, data)
    assert data.xpos[wheel][2] == pytest.approx(0.022, abs=5e-4)
    assert data.xpos[dropped][2] == pytest.approx(0.022, abs=5e-4)  # it landed on its tyre, not on its side


def test_the_cat_is_static_half_a_metre_long_and_scales(sim):
    model = sim.model
    cat = model.body(sim.table.bodies["CAT"]).id
    big = model.body(sim.table.bodies["BIG_CAT"]).id
    assert model.body_mass[cat] == 0 or model.body_weldid[cat] == 0  # no physics: part of the static world
    low, high = _extent(sim, cat)
    assert high[0] - low[0] == pytest.approx(0.55, abs=0.01)  # muzzle to tail tip (Webots' bounding object)
    assert high[2] == pytest.approx(0.342, abs=0.005)  # tips of the ears
    assert low[2] == pytest.approx(0.0, abs=3e-3)  # paws on the ground
    big_low, big_high = _extent(sim, big)
    assert big_high[2] == pytest.approx(2 * 0.342, abs=0.01)
    assert big_high[0] - big_low[0] == pytest.approx(2 * 0.55, abs=0.02)
    recognized = {r.model: r.colors for r in sim.table.recognizable}
    assert recognized["cat"] == [[0.87, 0.58, 0.0]]


def test_a_ball_dropped_on_the_big_cats_back_stays_on_it(sim):
    ball = sim.model.body(sim.table.bodies["BALL"]).id
    for _ in range(125):  # 1 s
        sim.step()
    mujoco.mj_forward(sim.model, sim.data)
    # The big cat's back (the top of its upper-body capsule) is 2 x (0.205 + 0.045) = 0.5 m up.
    assert sim.data.xpos[ball][2] > 0.4
