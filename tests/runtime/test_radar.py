"""Radar: targets with a radarCrossSection in the frustum, Webots' radar equation, azimuth, occlusion, merging."""

import math
from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.radar import Radar
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 32
}
Robot {
  children [
    Radar {
      maxRange 10
      horizontalFieldOfView 1
      verticalFieldOfView 0.5
      occlusion OCCLUSION
    }
  ]
  controller "<none>"
}
DEF AHEAD Solid {
  translation 3 -1 0
  children [ Shape { geometry DEF BALL Sphere { radius 0.1 } } ]
  boundingObject USE BALL
  radarCrossSection 2
}
DEF BEHIND Solid {
  translation -3 0 0
  children [ Shape { geometry USE BALL } ]
  boundingObject USE BALL
  radarCrossSection 2
}
DEF SILENT Solid {
  translation 4 0.5 0
  children [ Shape { geometry USE BALL } ]
  boundingObject USE BALL
}
DEF WALL Solid {
  translation 2 -0.67 0
  children [ Shape { geometry DEF PANEL Box { size 0.1 0.4 0.4 } } ]
  boundingObject USE PANEL
}
"""


def targets(tmp_path: Path, occlusion: str) -> list[tuple]:
    world = tmp_path / "radar.wbt"
    world.write_text(WORLD.replace("OCCLUSION", occlusion))
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    radar = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Radar))
    return radar.sample(sim)


def test_a_target_ahead_right_with_the_radar_equation(tmp_path):
    seen = targets(tmp_path, "FALSE")
    assert len(seen) == 1  # the one behind and the one without a cross section are not targets
    distance, power, speed, azimuth = seen[0]
    assert distance == pytest.approx(math.hypot(3, 1), abs=1e-6)
    # Pt G² λ² σ / ((4π)³ d⁴): 20 dBm, 20 dBi, 24 GHz, σ = 2 m², in dBm.
    wavelength = 299792458.0 / 24e9
    watts = 0.1 * 100.0**2 * wavelength**2 * 2 / (4 * math.pi) ** 3 / distance**4
    assert power == pytest.approx(10 * math.log10(watts / 0.001), abs=1e-9)
    assert speed == 0.0
    assert azimuth == pytest.approx(math.atan2(1, 3), abs=1e-9)  # on the right: positive


def test_occlusion_hides_a_target_behind_a_wall(tmp_path):
    assert targets(tmp_path, "TRUE") == []
