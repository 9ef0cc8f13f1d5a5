"""VacuumGripper: it holds what it touches only while on, lifts it with its arm, and lets it fall when off."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
}
Robot {
  children [
    SliderJoint {
      device [
        LinearMotor {
          maxForce 1000
        }
      ]
      endPoint Solid {
        translation 0 0 0.3
        children [
          VacuumGripper {
            translation 0 0 -0.1935
            children [
              DEF CUP Shape {
                geometry Cylinder {
                  height 0.015
                  radius 0.03
                }
              }
            ]
            boundingObject USE CUP
          }
        ]
        boundingObject Box {
          size 0.02 0.02 0.2
        }
        physics Physics {
          mass 0.2
        }
      }
    }
  ]
  controller "<none>"
}
DEF BOX Solid {
  translation 0 0 0.05
  children [
    DEF SHAPE Shape {
      geometry Box {
        size 0.1 0.1 0.1
      }
    }
  ]
  boundingObject USE SHAPE
  physics Physics {
    mass 0.5
  }
}
"""


def test_a_vacuum_gripper_lifts_a_box_only_while_on(tmp_path: Path):
    world = tmp_path / "gripper.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    gripper, motor = tags["vacuum gripper"], tags["linear motor"]
    box = sim.model.body(result.table.bodies["BOX"]).id
    apply_commands(sim, robot, [(gripper, "enablePresence", 16), (motor, "setPosition", 0.1)])
    for _ in range(60):  # off: the arm rises alone
        sim.step()
    assert sim.data.xpos[box][2] == pytest.approx(0.05, abs=1e-3)
    assert robot.sensors[gripper].value == 0
    apply_commands(sim, robot, [(motor, "setPosition", 0.0)])
    for _ in range(60):  # back down onto the box
        sim.step()
    apply_commands(sim, robot, [(gripper, "turnOn", ), (motor, "setPosition", 0.1)])
    for _ in range(60):
        sim.step()
    assert robot.sensors[gripper].value == 1
    # Lifted with the arm: 0.149, the 0.1 m rise less the cup's 1 mm overlap (the 0.2 kg arm's servo, tuned
    # to its mass, hardly sags under the 0.5 kg load).
    assert sim.data.xpos[box][2] == pytest.approx(0.149, abs=5e-4)
    apply_commands(sim, robot, [(gripper, "turnOff")])
    for _ in range(60):
        sim.step()
    assert robot.sensors[gripper].value == 0
    assert sim.data.xpos[box][2] == pytest.approx(0.05, abs=1e-3)  # dropped back onto the floor
