"""Joint stops act from the basic step after a joint reaches them, and hold a light link against its motor.

wbtc.runtime.joint_stops decides the stops per basic step as ODE does; wbtc.runtime.motors gives a motor
pushing through a stop the gain for what it then moves; the rows are ODE's (wbtc.compile.joint_stops).
"""

import math
from pathlib import Path

import mujoco
import pytest

from tests.conftest import simulation_of
from wbtc.runtime.simulation import Simulation

#: A motor turning a 4e-8 kg m² gear that carries a 0.16 kg pendulum on a hinge free within +-0.1 rad
#: (stopERP 0): Webots' HingeJointWithBacklash, written out.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 16 gravity 0 }
Robot {
  children [
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 0 1 }
      device [ RotationalMotor { name "motor" } ]
      endPoint Solid {
        name "gear"
        children [
          HingeJoint {
            jointParameters HingeJointParameters { axis 0 0 1 minStop -0.1 maxStop 0.1 stopERP 0 }
            endPoint Solid {
              translation 0 -0.2 0
              name "pendulum"
              boundingObject Box { size 0.02 0.4 0.02 }
              physics Physics { }
            }
          }
        ]
        physics Physics { density -1 mass 0.1 centerOfMass [ 0 0 0 ] inertiaMatrix [ 4e-8 4e-8 4e-8, 0 0 0 ] }
      }
    }
  ]
  name "rig"
  controller "<none>"
}
"""
#: The pendulum's inertia about the axis: a 0.16 kg box 0.02 x 0.4 x 0.02 m, centred 0.2 m from it.
PENDULUM_INERTIA = 0.16 * (0.02**2 + 0.4**2) / 12 + 0.16 * 0.2**2


@pytest.fixture
def rig(tmp_path: Path):
    sim = simulation_of(tmp_path, WORLD, "backlash.wbt")
    (motor,) = sim.robots[0].motors.values()
    motor.apply("setPosition", (math.inf,))
    motor.apply("setVelocity", (0.2,))
    return sim, motor


def _angles(sim: Simulation) -> tuple[float, float, float]:
    """The gear's angle, the pendulum's (absolute) and its velocity."""
    model, data = sim.model, sim.data
    gear, inner = (model.joint(name) for name in ("rig/gear", "rig/pendulum"))
    q = data.qpos[model.jnt_qposadr[gear.id]], data.qpos[model.jnt_qposadr[inner.id]]
    v = data.qvel[model.jnt_dofadr[gear.id]] + data.qvel[model.jnt_dofadr[inner.id]]
    return float(q[0]), float(q[0] + q[1]), float(v)


def test_the_gear_passes_its_stop_within_a_step_and_pushes_the_pendulum_from_the_next(rig) -> None:
    sim, motor = rig
    for _ in range(32):  # 32 x 3.2 mrad: the gear ends the 32nd step past its stop at 0.1
        sim.step()
    gear, pendulum, _ = _angles(sim)
    assert gear == pytest.approx(0.1024, abs=1e-5)
    # The stop was not there while the gear crossed it: ODE decides it at the step's start.
    assert pendulum == pytest.approx(0.0, abs=1e-12)
    assert sim.model.jnt_limited[sim.model.joint("rig/pendulum").id] == 0
    sim.step()
    # The stop acts: the motor moves gear and pendulum together, with a gain for both (kv × (I_gear + I_p) / I_gear).
    assert motor.stiffness / motor.kv == pytest.approx((4e-8 + PENDULUM_INERTIA) / 4e-8, rel=1e-6)
    gear, pendulum, velocity = _angles(sim)
    assert velocity == pytest.approx(0.2, rel=1e-6)
    penetration = gear - pendulum - 0.1
    assert penetration == pytest.approx(0.0024, abs=1e-5)
    for _ in range(20):
        sim.step()
    gear, pendulum, velocity = _angles(sim)
    assert velocity == pytest.approx(0.2, rel=1e-6)
    # stopERP 0: the penetration stays (as ODE's), and does not grow against the motor.
    assert gear - pendulum - 0.1 == pytest.approx(penetration, abs=1e-8)


def test_a_motor_reversing_at_the_stop_leaves_the_pendulum_where_it_is(rig) -> None:
    sim, motor = rig
    for _ in range(32):
        sim.step()
    motor.apply("setVelocity", (-0.2,))  # past the stop by 2.4 mrad, and away from it
    for _ in range(40):
        sim.step()
    gear, pendulum, velocity = _angles(sim)
    assert gear == pytest.approx(0.1024 - 40 * 0.0032, abs=2e-5)
    assert pendulum == pytest.approx(0.0, abs=1e-12)  # Webots checks it to 1e-7 m (protos/hinge_joint_with_backlash)
    assert velocity == pytest.approx(0.0, abs=1e-12)
    assert motor.stiffness == motor.kv  # the stop it leaves does not count


def test_a_stop_is_on_only_in_steps_that_start_at_or_past_it(rig) -> None:
    sim, _ = rig
    model, data = sim.model, sim.data
    inner = model.joint("rig/pendulum").id
    sim.step()
    assert model.jnt_limited[inner] == 0
    data.qpos[model.jnt_qposadr[inner]] = -0.1  # at the lower stop
    mujoco.mj_forward(model, data)
    sim.step()
    assert model.jnt_limited[inner] == 1
