"""Webots' cylinder-on-plane contact points under `--ode-contacts` (wbtc.runtime.ode_cylinders).

Expected points: Webots' collider (src/ode/ode/src/collision_cylinder_plane.cpp): within sin² 0.001 of
standing, the cap's centre plus its y, plus its x, minus its y, minus its x axis (times the radius);
within sin² 0.1, the deepest rim point, the two across it and the opposite one; beyond, the deepest rim
point of each cap; each only when below the plane, the +axis cap's first.
"""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.runtime import ode_cylinders
from wbtc.runtime.launch import prepare

R, HALF = 0.05, 0.025
UP = np.array([0.0, 0.0, 1.0])
ORIGIN = np.zeros(3)


def _turned(angle: float) -> np.ndarray:
    """A cylinder frame (columns x, y, axis) turned by `angle` about the x axis."""
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])


def test_a_standing_cylinder_touches_at_a_cross_of_four_rim_points():
    centre = np.array([0.0, 0.0, HALF - 0.001])  # 1 mm deep
    points = ode_cylinders.ode_points(ORIGIN, UP, centre, np.eye(3), R, HALF)
    expected = [(0, R, -0.001), (R, 0, -0.001), (0, -R, -0.001), (-R, 0, -0.001)]  # +y, +x, -y, -x
    assert np.allclose(points, expected)


def test_slightly_inclined_the_deepest_point_and_the_two_across_it():
    angle = 0.1  # sin² 0.00997: past "parallel", within "slightly inclined"
    frame = _turned(angle)
    low_cap = np.array([0.0, 0.0, -0.001])  # its centre 1 mm deep
    centre = low_cap + HALF * frame[:, 2]
    points = ode_cylinders.ode_points(ORIGIN, UP, centre, frame, R, HALF)
    # Deepest: the cap's radius that points most downwards; then across it along axis × normal (-x here),
    # then the opposite of the deepest (5 mm up: above the plane), then +x.
    deepest = low_cap + R * np.array([0.0, -math.cos(angle), -math.sin(angle)])
    assert np.allclose(points, [deepest, low_cap - (R, 0, 0), low_cap + (R, 0, 0)])


def test_tipped_further_the_deepest_rim_point_alone():
    frame = _turned(0.5)  # sin² 0.23
    low_cap = np.array([0.0, 0.0, 0.02])  # its deepest point 3.97 mm deep
    points = ode_cylinders.ode_points(ORIGIN, UP, low_cap + HALF * frame[:, 2], frame, R, HALF)
    assert len(points) == 1
    assert np.allclose(points[0], low_cap + R * np.array([0.0, -math.cos(0.5), -math.sin(0.5)]))


def test_a_lying_wheel_touches_at_each_rim():
    frame = _turned(math.pi / 2)
    points = ode_cylinders.ode_points(ORIGIN, UP, np.array([0.0, 0.0, R - 0.0005]), frame, R, HALF)
    assert np.allclose(points, [(0, -HALF, -0.0005), (0, HALF, -0.0005)])


_MODEL = """<mujoco><option timestep="0.002"/><worldbody><geom type="plane" size="1 1 1"/>
<body pos="0 0 0.0249"><freejoint/><geom type="cylinder" size="0.05 0.025" mass="1"/></body>
<body pos="1 0 0.2"><freejoint/><geom type="box" size="0.05 0.05 0.05"/></body></worldbody></mujoco>"""


def test_the_hook_gives_a_standing_cylinder_four_contacts_with_their_rows():
    model = mujoco.MjModel.from_xml_string(_MODEL)
    data = mujoco.MjData(model)
    mujoco.mj_step1(model, data)
    assert data.ncon == 3  # MuJoCo's triangle
    ode_cylinders.hook_for(model)(model, data)
    assert data.ncon == 4
    assert np.allclose(data.contact.pos[:, :2], [(0, R), (R, 0), (0, -R), (-R, 0)])
    assert np.allclose(data.contact.dist, -0.0001)
    assert data.contact.efc_address.tolist() == [0, 4, 8, 12]  # pyramidal: 4 rows per contact
    assert data.nefc == 16
    for _ in range(500):  # it rests on them: 1 s later it has not moved sideways or tipped
        mujoco.mj_step1(model, data)
        ode_cylinders.hook_for(model)(model, data)
        mujoco.mj_step2(model, data)
    assert (data.contact.geom[:, 1] == 1).sum() == 4  # (and the box that fell beside it: MuJoCo's 4 corners)
    assert np.abs(data.qpos[:2]).max() < 1e-9
    assert abs(data.qpos[3]) == pytest.approx(1.0, abs=1e-9)


def test_a_model_without_cylinders_or_planes_has_no_hook():
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><geom type="plane" size="1 1 1"/><body><freejoint/><geom type="box" size="1 1 1"/>'
        '</body></worldbody></mujoco>')
    assert ode_cylinders.hook_for(model) is None


_WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
Solid { boundingObject Plane { size 10 10 } }
DEF LEG Solid {
  translation 0 0 0.025
  children [ DEF LEG_SHAPE Shape { geometry Cylinder { height 0.05 radius 0.02 } } ]
  boundingObject USE LEG_SHAPE
  physics Physics { density -1 mass 1 }
}
"""


@pytest.mark.parametrize(("ode", "count"), [(False, 3), (True, 4)])
def test_a_supervisor_reads_webots_four_points_with_ode_contacts(tmp_path: Path, ode: bool, count: int):
    world = tmp_path / "leg.wbt"
    world.write_text(_WORLD)
    sim = prepare(world, ode_contacts=ode).sim
    for _ in range(5):
        sim.step()
    found = sim.end_contacts().collide(sim)
    assert found.ncon == count
