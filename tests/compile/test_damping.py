"""Damping: Webots takes the fraction `linear` of a body's speed away per second, and `angular` of its spin."""

import math

import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 16
  gravity 0
  defaultDamping Damping {
    linear 0.5
    angular 0.2
  }
}
Solid {
  translation 0 0 1
  children [
    Solid {
      translation 0.3 0 0
      boundingObject Sphere {
        radius 0.05
      }
      physics Physics {
        density -1
        mass 1
      }
    }
  ]
  boundingObject Box {
    size 0.4 0.2 0.1
  }
  physics Physics {
    density -1
    mass 2
  }
}
"""


@pytest.fixture
def sim(tmp_path):
    simulation = simulation_of(tmp_path, WORLD, "damped.wbt")
    yield simulation
    simulation.close()


def test_the_free_joint_damps_the_whole_tree_about_its_centre_of_mass(sim):
    # A 2 kg box (0.4 × 0.2 × 0.1 m) with a 1 kg ball (radius 0.05 m) welded 0.3 m along x: 3 kg,
    # centre of mass at x = 0.1 m. About it: Ixx = 2/12 (0.2² + 0.1²) + 2/5 · 0.05², and Iyy, Izz
    # add the box's and the ball's offsets (0.1 m and 0.2 m) by the parallel-axis rule.
    ball = 0.4 * 0.05 ** 2
    inertia = [2 / 12 * (0.04 + 0.01) + ball,
               2 / 12 * (0.16 + 0.01) + 2 * 0.1 ** 2 + ball + 1 * 0.2 ** 2,
               2 / 12 * (0.16 + 0.04) + 2 * 0.1 ** 2 + ball + 1 * 0.2 ** 2]
    linear, angular = -math.log(1 - 0.5), -math.log(1 - 0.2)
    assert sim.model.dof_damping[:6] == pytest.approx([0.0] * 3 + [angular * i for i in inertia])
    # The linear part is a drag on the tree's centre of mass, applied by the runtime: 3 kg × the rate.
    assert list(sim.table.linear_damping.values()) == pytest.approx([linear * 3])


def test_the_drag_acts_on_the_centre_of_mass_so_drifting_does_not_turn_the_tree(sim):
    # Drifting sideways (along y) with the centre of mass 0.1 m ahead of the box's centre: a drag on
    # the box's centre would turn the tree about z; Webots' drag on the centre of mass does not.
    sim.data.qvel[1] = 1.0
    for _ in range(62):
        sim.step()
    assert sim.data.qvel[1] == pytest.approx(0.5 ** 0.992, rel=0.01)
    assert abs(sim.data.qvel[5]) < 1e-9


def test_a_tree_loses_half_its_speed_and_a_fifth_of_its_spin_a_second(sim):
    sim.data.qvel[0] = 1.0  # 1 m/s along x
    sim.data.qvel[3] = 1.0  # 1 rad/s about x, the line through both centres of mass
    for _ in range(62):  # 0.992 s
        sim.step()
    assert sim.data.qvel[0] == pytest.approx(0.5 ** 0.992, rel=0.01)
    assert sim.data.qvel[3] == pytest.approx(0.8 ** 0.992, rel=0.01)
