"""Motors of robots without Physics move their joints by Webots' kinematic rule (WbMotor's kinematic control)."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 32 }
Robot {
  children [
    SliderJoint {
      jointParameters JointParameters { axis 0 0 1 }
      device [ LinearMotor { name "slider" maxPosition 0.05 } ]
      endPoint Solid { translation 0 0 0.1 children [ Shape { geometry Box { size 0.01 0.01 0.01 } } ] }
    }
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 0 1 anchor 0.2 0 0 }
      device [ RotationalMotor { name "hinge" acceleration 2 maxVelocity 3 } ]
      endPoint Solid { translation 0.3 0 0 children [ Shape { geometry Box { size 0.01 0.01 0.01 } } ] name "arm" }
    }
  ]
  controller "<none>"
}
"""


@pytest.fixture
def sim(tmp_path: Path):
    world = tmp_path / "kinematic_motors.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    simulation = Simulation(result, noise=False)
    yield simulation
    simulation.close()


def _motor(sim: Simulation, name: str):
    return next(m for m in sim.robots[0].motors.values() if m.entry.name == name)


def _position(sim: Simulation, motor) -> float:
    return float(sim.data.qpos[motor.qpos_adr] - sim.model.qpos0[motor.qpos_adr])


def test_position_control_speeds_up_at_the_max_force_and_stops_on_the_target(sim):
    slider = _motor(sim, "slider")
    slider.apply("setPosition", (0.02,))
    # acceleration -1: maxForce 10 N read as 10 m/s^2, 0.32 m/s more each 32 ms step.
    sim.step()
    assert _position(sim, slider) == pytest.approx(0.32 * 0.032, abs=1e-12)
    sim.step()  # 0.64 m/s would pass the target: it stops on it
    assert _position(sim, slider) == pytest.approx(0.02, abs=1e-12)
    for _ in range(5):
        sim.step()
    assert _position(sim, slider) == pytest.approx(0.02, abs=1e-12)
    assert slider.kinematic_velocity == 0.0  # at the target, the motor is at rest


def test_velocity_control_ramps_at_the_acceleration_and_stops_at_the_limit(sim):
    hinge, slider = _motor(sim, "hinge"), _motor(sim, "slider")
    hinge.apply("setPosition", (float("inf"),))
    hinge.apply("setVelocity", (1.0,))
    expected, speed = 0.0, 0.0
    for _ in range(20):
        sim.step()
        speed = min(speed + 2 * 0.032, 1.0)  # acceleration 2 rad/s^2, up to the requested 1 rad/s
        expected += speed * 0.032
    assert _position(sim, hinge) == pytest.approx(expected, abs=1e-9)
    # The slider in velocity control goes one step past its maxPosition 0.05, then stays (Webots' rule).
    slider.apply("setPosition", (float("inf"),))
    slider.apply("setVelocity", (0.5,))
    positions = []
    for _ in range(12):
        sim.step()
        positions.append(_position(sim, slider))
    assert positions[0] == pytest.approx(0.32 * 0.032)
    assert positions[-1] == positions[-2] >= 0.05
    assert positions[-1] < 0.05 + 0.5 * 0.032 + 1e-12


def test_the_available_force_caps_the_acceleration(sim):
    slider = _motor(sim, "slider")
    slider.apply("setAvailableForce", (2.0,))
    slider.apply("setPosition", (0.04,))
    sim.step()
    assert _position(sim, slider) == pytest.approx(2 * 0.032 * 0.032, abs=1e-12)
