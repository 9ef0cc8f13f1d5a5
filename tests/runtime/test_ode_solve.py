"""ODE's contact solve under `--ode-contacts` (wbtc.runtime.ode_solve): a friction force's torque is met by the
normal forces within the step, as in ODE's one solve.

Expected values: ODE 0.16 itself (`dWorldStep`, box-plane collider, `dContactApprox1 | SoftERP | SoftCFM |
Bounce`, μ 1, softERP 0.2, softCFM 0.001, bounce 0.5 above 0.01 m/s, world ERP 0.2 and CFM 1e-5, gravity
9.81): a 0.1 m, 1 kg box resting 0.4 mm deep in a plane is pushed through its centre of mass by a
horizontal force for 8 steps of 32 ms. At one 32 ms step ODE tilts it 0.00134 rad (2 N) and 0.00335 rad
(5 N) after the 8th step, and it has moved 0.068 and 0.170 mm; with 2 ms steps and the same spring and
damper (wbtc's substeps keep the 32 ms step's contact: CFM 1 / (h kp + kd), ERP h kp CFM), 0.00139 and
0.00347 rad, 0.071 and 0.177 mm. With MuJoCo's noslip pass alone (friction solved after the normal
forces) the 2 N push tilted it 0.0856 rad at one 32 ms step and 0.0112 rad at 2 ms substeps.
"""

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.runtime import lcp, ode_solve
from wbtc.runtime.launch import prepare

_WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
Solid { boundingObject Plane { size 10 10 } }
DEF BOX Solid {
  translation 0 0 0.0496
  children [ DEF BOX_SHAPE Shape { geometry Box { size 0.1 0.1 0.1 } } ]
  boundingObject USE BOX_SHAPE
  physics Physics { density -1 mass 1 }
}
"""


def _push(tmp_path: Path, force: float, physics_step: float) -> tuple[float, float]:
    """The box's tilt (rad) and x (mm) after 8 steps of `force` newtons along x."""
    world = tmp_path / "push.wbt"
    world.write_text(_WORLD)
    sim = prepare(world, physics_step=physics_step, ode_contacts=True).sim
    assert ode_solve.applies(sim.model)
    box = mujoco.mj_name2id(sim.model, mujoco.mjtObj.mjOBJ_BODY, "BOX")
    assert box >= 0
    sim.data.xfrc_applied[box, 0] = force
    for _ in range(8):
        sim.step()
    tilt = math.acos(min(1.0, float(sim.data.xmat[box][8])))
    return tilt, float(sim.data.xpos[box][0]) * 1000


@pytest.mark.parametrize(("force", "physics_step", "ode_tilt", "ode_x"), [
    (2.0, 1000.0, 0.00134, 0.068),
    (5.0, 1000.0, 0.00335, 0.170),
    (2.0, 2.0, 0.00139, 0.071),
    (5.0, 2.0, 0.00347, 0.177),
])
def test_a_pushed_box_tilts_as_in_ode(tmp_path, force, physics_step, ode_tilt, ode_x):
    tilt, x = _push(tmp_path, force, physics_step)
    # Within 10 % of ODE's (0.00126 and 0.00328 rad, 0.066 and 0.171 mm at one step; 0.00138 and
    # 0.00346 rad, 0.069 and 0.173 mm at 2 ms substeps), where the noslip pass alone was 8 to 70 times off.
    assert tilt == pytest.approx(ode_tilt, rel=0.10)
    assert x == pytest.approx(ode_x, rel=0.10)


def test_friction_is_bounded_by_the_normal_force_found():
    # One contact, one body of unit inverse mass: a 3 N pull along the first friction direction with
    # 1 N of normal force (μ 0.5) slides: the friction row stops at μ N = 0.5; the second stays at 0.
    a_mat = np.eye(3)
    accel = np.array([-1.0, 3.0, 0.0])  # gravity into the contact, a pull along t1
    no_other_rows = (np.zeros(0), np.zeros(0))
    forces = lcp.solve(a_mat, accel, np.zeros(3), np.zeros(3), np.array([0.5, 0.5]), no_other_rows, np.zeros(3), 1)
    assert forces.tolist() == pytest.approx([1.0, -0.5, 0.0])


def test_pivoting_finishes_what_the_sweeps_leave():
    # A contact whose normal and first friction row are almost the same direction for the bodies (a light
    # wheel on a heavy robot couples its rows so): Gauss-Seidel crawls, 20 sweeps leave it far from the
    # solution; pivoting then gives the exact one, here inside the friction box (μ 10).
    a_mat = np.array([[1.0, 0.9999, 0.0], [0.9999, 1.0, 0.0], [0.0, 0.0, 1.0]])
    accel = np.array([-2.0, -1.0, 0.5])
    mu, no_other_rows = np.array([10.0, 10.0]), (np.zeros(0), np.zeros(0))
    exact = np.linalg.solve(a_mat, -accel)
    assert exact[0] > 0 and abs(exact[1]) < 10 * exact[0] and abs(exact[2]) < 10 * exact[0]
    problem = lcp._Problem(mu, *no_other_rows, 1)
    swept, settled = lcp.sweeps(a_mat, accel, np.zeros(3), np.zeros(3), problem, np.zeros(3), np.ones(3, bool))
    assert not settled and np.abs(swept - exact).max() > 1.0
    forces = lcp.solve(a_mat, accel, np.zeros(3), np.zeros(3), mu, no_other_rows, np.zeros(3), 1)
    assert forces == pytest.approx(exact, abs=1e-6)


def test_longer_substeps_solve_larger_islands():
    # The Python solve's cost goes with the contacts solved per simulated second.
    assert [ode_solve.island_limit(h) for h in (0.001, 0.002, 0.016, 0.032)] == [8, 8, 64, 128]
