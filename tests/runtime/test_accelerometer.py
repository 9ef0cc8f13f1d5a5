"""The Accelerometer as Webots computes it: minus gravity plus the device point's velocity change between samples."""

import math
from pathlib import Path

import pytest

from tests.conftest import simulation_of
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.sensors import Vector3Sensor

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 32 }
Robot {
  children [
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 0 1 }
      device [ RotationalMotor { name "motor" maxVelocity 10 } ]
      endPoint Solid {
        children [ Accelerometer { translation 0.1 0 0 } ]
        physics Physics { density -1 mass 1 centerOfMass [ 0 0 0 ] inertiaMatrix [ 0.001 0.001 0.001, 0 0 0 ] }
      }
    }
  ]
  physics Physics { density -1 mass 100 }
  boundingObject Box { size 1 1 0.1 }
  translation 0 0 0.05
  controller "<none>"
}
Solid { boundingObject Plane { size 10 10 } name "floor" }
"""


def _turn(folder: Path, world: str, steps: int) -> tuple[list[float], float]:
    """The accelerometer's value after `steps` samples of the arm turning at pi rad/s, and the hinge's speed."""
    sim = simulation_of(folder, world)
    try:
        robot = sim.robots[0]
        accelerometer = next(s for s in robot.sensors.values() if isinstance(s, Vector3Sensor))
        accelerometer.enable(32, sim.time_ms)
        apply_commands(sim, robot, [(0, "setPosition", math.inf), (0, "setVelocity", math.pi)])
        for _ in range(steps):
            sim.step()
            accelerometer.tick(sim, sim.time_ms)
        return list(accelerometer.value), float(sim.data.qvel[-1])  # the hinge is the last dof
    finally:
        sim.close()


def test_a_turning_arm_reads_the_chord_of_its_velocity(tmp_path: Path):
    (x, y, z), omega = _turn(tmp_path, WORLD, 5)
    assert omega == pytest.approx(math.pi, abs=1e-3)
    # Between two samples 32 ms apart the point at 0.1 m turned by d = pi x 0.032 rad: the velocity changed by
    # the chord 2 w r sin(d / 2), seen from the later frame half a step behind, so inwards by cos(d / 2) and
    # along the motion (+y here) by sin(d / 2): (-0.98531, 0.04955) per second, where the instantaneous
    # centripetal acceleration is (-0.98696, 0).
    chord = 2 * math.pi * 0.1 * math.sin(math.pi * 0.032 / 2) / 0.032
    assert x == pytest.approx(-chord * math.cos(math.pi * 0.016), abs=2e-3)
    assert y == pytest.approx(chord * math.sin(math.pi * 0.016), abs=2e-3)
    assert z == pytest.approx(9.81, abs=2e-3)


def test_without_physics_an_accelerometer_reads_gravity_alone(tmp_path: Path):
    still = WORLD.replace("  physics Physics { density -1 mass 100 }\n", "").replace(
        "physics Physics { density -1 mass 1 centerOfMass [ 0 0 0 ] inertiaMatrix [ 0.001 0.001 0.001, 0 0 0 ] }", "")
    value, omega = _turn(tmp_path, still, 2)
    # No Physics anywhere: Webots' device has no ODE body, so only gravity, however the joint turns.
    assert omega == 0.0 and value == pytest.approx([0.0, 0.0, 9.81], abs=1e-9)
