"""A Robot's battery drains by its cpuConsumption and its motors' effort, and its motors stop when it is empty."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands, reply
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 32 gravity 0 }
Robot {
  children [
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 0 1 }
      device [ RotationalMotor { name "m" consumptionFactor 2 maxTorque 1 } PositionSensor { name "p" } ]
      endPoint Solid {
        children [ Shape { geometry DEF ARM Box { size 0.2 0.02 0.02 } } ]
        boundingObject USE ARM
        physics Physics { density -1 mass 100 }
      }
    }
  ]
  name "eater"
  controller "<none>"
  battery [ 10 10 0 ]
  cpuConsumption 50
}
Robot { name "mains" controller "<none>" }
"""


def test_battery_drains_and_an_empty_battery_stops_the_motors(tmp_path: Path) -> None:
    world = tmp_path / "battery.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    eater, mains = sim.robots
    apply_commands(sim, eater, [(-1, "batterySensorEnable", 32)])
    apply_commands(sim, mains, [(-1, "batterySensorEnable", 32)])
    tag, sensor = next(iter(eater.sensors.items()))
    apply_commands(sim, eater, [(tag, "enable", 32)])
    sim.step()
    # The CPU alone (the motor holds still at no effort): 50 W for 32 ms.
    assert reply(sim, eater, 0)["battery"] == pytest.approx(10 - 50 * 0.032, abs=1e-9)
    assert reply(sim, mains, 0)["battery"] == -1.0  # no battery field: Webots' sensor reads -1
    motor = next(iter(eater.motors.values()))
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (10.0,))
    sim.step()
    # The 100 kg arm is far from its 10 rad/s: the motor pushes at its full 1 N·m, 2 W per N·m on top of 50 W.
    assert reply(sim, eater, 0)["battery"] == pytest.approx(8.4 - (50 + 2 * 1.0) * 0.032, abs=0.01)
    # 6.7356 J left at 52 W (1.664 J a step): four more steps leave 0.08 J, the fifth empties it.
    readings = []
    for _ in range(5):
        sim.step()
        readings.append(sensor.value)
    assert reply(sim, eater, 0)["battery"] == 0.0
    assert motor.available == 0.0  # switched off: the arm coasts
    # Webots powers the robot off in the step that empties the battery, before its sensors are read: the
    # position sensor keeps the value of the step before, though the arm goes on turning.
    assert readings[-1] == readings[-2]
    assert readings[-2] > readings[-3]
    moving = sim.data.qpos[0]
    sim.step()
    assert sim.data.qpos[0] > moving and sensor.value == readings[-1]
    sim.close()
