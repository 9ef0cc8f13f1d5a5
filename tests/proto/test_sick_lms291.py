"""wbtc's SickLms291: a 180-degree, single-layer, 80 m lidar with `resolution` points per scan."""

import math

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.lidar import Lidar
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/devices/sick/protos/SickLms291.proto"
WorldInfo { basicTimeStep 16 }
Solid {
  translation 2.05 0 0.5
  children [ Shape { geometry DEF WALL Box { size 0.1 8 2 } } ]
  boundingObject USE WALL
}
Robot {
  translation 0 0 0.5
  children [ SickLms291 { resolution RESOLUTION } ]
  controller "<none>"
}
"""


@pytest.mark.parametrize("resolution", [180, 360])
def test_a_half_turn_scan_of_a_wall_two_metres_ahead(tmp_path, resolution):
    world = tmp_path / "sick.wbt"
    world.write_text(WORLD.replace("RESOLUTION", str(resolution)), encoding="utf-8")
    result, _ = compile_world(world)
    entry = result.table.robots[0].device("Sick LMS 291")
    assert entry.type == "Lidar" and entry.fields["model"] == "Sick LMS291"
    assert entry.fields["horizontalResolution"] == resolution
    assert entry.fields["verticalFieldOfView"] == pytest.approx(math.pi / resolution, rel=1e-5)
    sim = Simulation(result, noise=False)
    lidar = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Lidar))
    ranges = lidar.sample(sim)["ranges"]
    assert len(ranges) == resolution
    # Column k looks (k + 0.5) steps of pi / resolution from the left end of the half turn: the wall's
    # face 2 m ahead is 2 / cos(angle) away, within 80 m up to about 88 degrees either side.
    step = math.pi / resolution
    for k in (0, resolution // 4, resolution // 2, resolution - 1):
        angle = math.pi / 2 - (k + 0.5) * step
        expected = 2 / math.cos(angle)
        assert ranges[k] == (pytest.approx(expected, rel=1e-4) if expected <= 80 else math.inf)
    sim.close()
