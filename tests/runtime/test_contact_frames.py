"""Webots' ContactProperties rolling friction and asymmetric friction, simulated (wbtc.compile.contact,
wbtc.runtime.contact_frames)."""

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

_ROLLING = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 8
  contactProperties [
    ContactProperties { material1 "floor" material2 "free" bounce 0 }
    ContactProperties { material1 "floor" material2 "braked" rollingFriction 0.02 0 0 bounce 0 }
  ]
}
Solid { name "floor" contactMaterial "floor" boundingObject Plane { size 20 20 } }
DEF FREE Solid {
  translation 0 -1 0.1 name "free" contactMaterial "free" linearVelocity 1 0 0 angularVelocity 0 10 0
  boundingObject Sphere { radius 0.1 } physics Physics { density -1 mass 1 }
}
DEF BRAKED Solid {
  translation 0 1 0.1 name "braked" contactMaterial "braked" linearVelocity 1 0 0 angularVelocity 0 10 0
  boundingObject Sphere { radius 0.1 } physics Physics { density -1 mass 1 }
}
"""

_ASYMMETRIC = """#VRML_SIM R2023b utf8
WorldInfo {
  basicTimeStep 8
  contactProperties [
    ContactProperties { coulombFriction [ 0.01 0.5 ] frictionRotation ROTATION bounce 0 }
  ]
}
Solid { name "floor" boundingObject Plane { size 20 20 } }
DEF ALONG_X Solid {
  translation 0 -1 0.05 name "along x" linearVelocity 1 0 0
  boundingObject Box { size 0.1 0.1 0.1 } physics Physics { density -1 mass 1 }
}
DEF ALONG_Y Solid {
  translation 0 1 0.05 name "along y" linearVelocity 0 1 0
  boundingObject Box { size 0.1 0.1 0.1 } physics Physics { density -1 mass 1 }
}
"""


def _simulation(tmp_path: Path, text: str) -> Simulation:
    world = tmp_path / "contact.wbt"
    world.write_text(text, encoding="utf-8")
    result, _ = compile_world(world)
    return Simulation(result, noise=False)


def _velocity(sim: Simulation, name: str) -> np.ndarray:
    """The linear velocity of a DEF-named Solid's centre of mass, world axes."""
    body = sim.model.body(sim.table.bodies[name]).id
    twist = np.zeros(6)
    mujoco.mj_objectVelocity(sim.model, sim.data, mujoco.mjtObj.mjOBJ_BODY, body, twist, 0)
    return twist[3:]


def test_a_ball_with_rolling_friction_slows_down_and_one_without_keeps_rolling(tmp_path) -> None:
    sim = _simulation(tmp_path, _ROLLING)
    for _ in range(40):  # 0.32 s
        sim.step()
    free, braked = _velocity(sim, "FREE"), _velocity(sim, "BRAKED")
    assert free[0] == pytest.approx(1.0, abs=0.005)
    # Rolling without slipping against a torque rho·N: a = rho·g / r / (1 + I/(m r²)) = 1.401 m/s²,
    # 0.552 m/s left after 0.32 s (ODE bounds the rolling torque on its own; MuJoCo's elliptic
    # cone shares the bound with sliding, so the ball slips a little and keeps slightly more).
    assert braked[0] == pytest.approx(1.0 - 0.02 * 9.81 / 0.1 / 1.4 * 0.32, abs=0.03)
    for _ in range(60):  # 0.8 s in all: it has stopped (at 0.71 s) and stays
        sim.step()
    assert abs(_velocity(sim, "BRAKED")[0]) < 0.01
    assert _velocity(sim, "FREE")[0] == pytest.approx(1.0, abs=0.01)


#: A box sliding against μ = 0.02 for 0.512 s from 1 m/s.
_SLID = 1.0 - 0.02 * 9.81 * 0.512


@pytest.mark.parametrize(("rotation", "x", "y"), [
    # Floor and boxes give their x axes (angle 0): μ(t1) = 0.01 + 0.01 = 0.02 along x, μ(t2) = 0.5 + 0.5.
    ("0 0", _SLID, 0.0),
    # Both directions turned by -90° about the normal: t1 is -y, the low friction is along y.
    ("1.5707963 1.5707963", 0.0, _SLID),
    # Only the floor's turned: 90° between the directions, μ(t1) = 0.01 + 0.5 = μ(t2): both stop.
    ("1.5707963 0", 0.0, 0.0),
])
def test_a_box_slides_on_along_the_low_friction_direction(tmp_path, rotation, x, y) -> None:
    sim = _simulation(tmp_path, _ASYMMETRIC.replace("ROTATION", rotation))
    for _ in range(64):  # 0.512 s
        sim.step()
    assert _velocity(sim, "ALONG_X")[0] == pytest.approx(x, abs=0.005)
    assert _velocity(sim, "ALONG_Y")[1] == pytest.approx(y, abs=0.005)
