"""An infra-red DistanceSensor over ink reads Webots' mix of the ink and the surface, on an untextured shape too.

The board, pen and sensor are those of the untextured half of Webots' distance_sensor_infra-red test (tests/api),
whose newest C controller expects the readings pinned here.
"""

from pathlib import Path

import pytest

from tests.conftest import simulation_of
from wbtc.runtime.commands import apply_commands

WORLD = """#VRML_SIM R2022b utf8
WorldInfo { coordinateSystem "NUE" }
Solid {
  translation 0 0.005 0.075
  children [
    Transform {
      rotation 1 0 0 -1.57079632679
      children [
        Shape {
          appearance PBRAppearance { baseColor 0.729412 0.741176 0.713725 roughness 0.5 metalness 0 }
          geometry Plane { size 0.15 0.15 }
        }
      ]
    }
  ]
  locked TRUE
}
Solid {
  translation 0 0.07 0
  children [ PointLight { ambientIntensity 1 intensity 0 } ]
  name "lamp"
}
Robot {
  translation 0 0.09 0
  children [
    Pen {
      translation 0 -0.02 0.08
      rotation 1 0 0 -1.57
      name "pen"
      inkColor 0 1 0
      inkDensity 0.298039
      leadSize 0.01
      write FALSE
    }
    DistanceSensor {
      translation 0 -0.02 0.08
      rotation 0 0 1 -1.5708
      name "ds"
      lookupTable [ 0 0 0, 0.2 2000 0 ]
      type "infra-red"
    }
  ]
  controller "<none>"
}
"""


def test_ink_on_an_untextured_board_reads_as_webots(tmp_path: Path):
    sim = simulation_of(tmp_path, WORLD)
    try:
        robot = sim.robots[0]
        tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
        sensor = robot.sensors[tags["ds"]]
        apply_commands(sim, robot, [(tags["ds"], "enable", 32)])

        def reading(*commands: tuple) -> float:
            apply_commands(sim, robot, [(tags["pen"], *command) for command in commands])
            sim.step()
            sensor.tick(sim, sim.time_ms)
            return float(sensor.value)

        readings = [reading(("setInkColor", 0x00FF00, 0.3)), reading(("write", True)),
                    reading(("setInkColor", 0xCC33FF, 0.3)), reading(("setInkColor", 0xFF0000, 0.7))]
        # Webots' values: the board, then green, violet and red ink mixed over it by coverage, as written.
        assert readings == pytest.approx([1019.3725, 1283.6893, 1252.266, 1025.485], abs=1e-3)
    finally:
        sim.close()
