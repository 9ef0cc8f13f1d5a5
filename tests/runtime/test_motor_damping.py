"""A motor reaches its velocity against its joint's damping, as ODE's motor does, within its torque."""

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
        dampingConstant 5
      }
      device [
        RotationalMotor {
          maxVelocity 26
          maxTorque %s
        }
      ]
      endPoint Solid {
        children [
          DEF WHEEL Shape {
            geometry Cylinder {
              height 0.035
              radius 0.043
            }
          }
        ]
        boundingObject USE WHEEL
        physics Physics {
          mass 0.5
        }
      }
    }
  ]
  controller "<none>"
}
"""


def _speed(tmp_path: Path, max_torque: float) -> float:
    world = tmp_path / "wheel.wbt"
    world.write_text(WORLD % max_torque)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    apply_commands(sim, robot, [(0, "setPosition", float("inf")), (0, "setVelocity", 5.0)])
    for _ in range(60):
        sim.step()
    return float(sim.data.qvel[0])


def test_a_motor_reaches_its_velocity_against_damping_within_its_torque(tmp_path: Path):
    # 5 rad/s against damping 5 takes 25 N·m: a 100 N·m motor gets there (a bare servo settled at 4.05).
    assert _speed(tmp_path, 100) == pytest.approx(5.0, abs=1e-3)
    # A 10 N·m motor cannot: the damping's torque (5 × v) meets the available torque at 2 rad/s.
    assert _speed(tmp_path, 10) == pytest.approx(2.0, abs=0.05)
