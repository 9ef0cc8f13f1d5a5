"""wbtc's Khepera IV: Webots' device names and order, its mass, its wheels, and its front sonar."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Floor {
  size 10 10
}
Khepera4 {
  controller "<none>"
}
Solid {
  translation 1.07 0 0.1
  children [
    Shape {
      geometry Box {
        size 0.02 1 0.2
      }
    }
  ]
  boundingObject Box {
    size 0.02 1 0.2
  }
}
"""


@pytest.fixture()
def compiled(tmp_path: Path):
    world = tmp_path / "khepera4.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    return result


def test_devices_in_webots_order_and_the_mass(compiled):
    robot = compiled.table.robots[0]
    sides = [f"{s} {kind}" for s in ("left", "front left", "front", "front right", "right")
             for kind in ("ultrasonic sensor",)]
    infrared = [f"{s} infrared sensor" for s in ("rear left", "left", "front left", "front", "front right", "right",
                                                 "rear right", "rear")]
    ground = [f"ground {s} infrared sensor" for s in ("left", "front left", "front right", "right")]
    assert [d.name for d in robot.devices] == [
        "left wheel motor", "left wheel sensor", "right wheel motor", "right wheel sensor",
        "front left led", "front right led", "rear led", *sides, *infrared, *ground,
        "camera", "receiver", "emitter", "accelerometer", "gyro", "speaker"]
    model = compiled.model
    assert model.body_subtreemass[model.body(robot.body).id] == pytest.approx(0.566 + 2 * 0.01 + 2 * 0.01)


def test_the_front_sonar_reads_the_wall_one_metre_ahead(compiled):
    sim = Simulation(compiled, noise=False)
    robot = sim.robots[0]
    tags = {d.name: tag for tag, d in enumerate(robot.entry.devices)}
    front, left = robot.sensors[tags["front ultrasonic sensor"]], robot.sensors[tags["left ultrasonic sensor"]]
    front.enable(16, sim.time_ms)
    left.enable(16, sim.time_ms)
    sim.step()
    # The sensor is 7 cm ahead of the centre, the wall's face 1.06 m: 0.99 m, read as itself (table 0.25-2 m).
    assert front.value == pytest.approx(0.99, abs=0.01)
    assert left.value == pytest.approx(2.0)  # nothing to the left: the table's last value
