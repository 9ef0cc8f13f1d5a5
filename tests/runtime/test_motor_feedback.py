"""Torque feedback under torque control: only what the joint's stops give, as Webots' joint feedback."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
  gravity 0
}
Robot {
  children [
    HingeJoint {
      jointParameters HingeJointParameters {
        axis 0 0 1
        maxStop 0.2
      }
      device [
        RotationalMotor {
          maxTorque 10
        }
      ]
      endPoint Solid {
        translation 0.1 0 0
        physics Physics {
          density -1
          mass 1
          centerOfMass [ 0 0 0 ]
          inertiaMatrix [ 1 1 1, 0 0 0 ]
        }
      }
    }
  ]
  controller "<none>"
}
"""


@pytest.fixture
def sim(tmp_path: Path):
    world = tmp_path / "arm.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    simulation = Simulation(result, noise=False)
    yield simulation
    simulation.close()


def _feedback(sim: Simulation, steps: int) -> list[float]:
    motor = sim.robots[0].motors[0]
    values = []
    for _ in range(steps):
        sim.step()
        motor.sample_feedback(sim.data, sim.time_ms)
        values.append(motor.feedback_value)
    return values


def test_under_torque_control_a_free_joint_reads_no_torque_then_its_stop(sim):
    robot = sim.robots[0]
    apply_commands(sim, robot, [(0, "enableTorqueFeedback", 16), (0, "setTorque", 0.5)])
    # 0.5 N m on 1 kg m^2: 0.5 rad/s^2, the stop at 0.2 rad reached after about 0.9 s (56 steps).
    free = _feedback(sim, 40)
    assert max(abs(v) for v in free) == 0.0  # Webots: about 1e-7, the command is not joint feedback
    held = _feedback(sim, 60)[-10:]
    assert sim.data.qpos[0] == pytest.approx(0.2, abs=2e-3)
    # Resting on its stop, the joint holds the motor's torque back: the stop pushes down, -0.5 N m.
    assert [round(v, 3) for v in held] == [-0.5] * 10

