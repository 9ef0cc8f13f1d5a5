"""A LightSensor takes SpotLight and DirectionalLight directions as written, as Webots' WbLightSensor does."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.sensors import LightSensor
from wbtc.runtime.simulation import Simulation

# A spot light written pointing down (-z) inside a Solid turned a quarter turn about x: drawn, it
# points along +y. The sensor, 1 m below it, looks up (+x turned to +z).
WORLD = """#VRML_SIM R2025a utf8
WorldInfo {{ }}
Solid {{
  translation 0 0 1
  rotation 1 0 0 {turn}
  children [ SpotLight {{ direction 0 0 -1 cutOffAngle 0.3 beamWidth 0.2 intensity 0.5 attenuation 1 0 0 }} ]
}}
Robot {{
  children [ LightSensor {{ rotation 0 1 0 -1.5708 lookupTable [ 0 0 0, 1 1000 0 ] }} ]
  controller "<none>"
}}
"""


def _reading(tmp_path: Path, turn: float) -> float:
    (tmp_path / "light.wbt").write_text(WORLD.format(turn=turn), encoding="utf-8")
    result, _ = compile_world(tmp_path / "light.wbt")
    sim = Simulation(result, noise=False)
    sensor = next(s for s in sim.robots[0].sensors.values() if isinstance(s, LightSensor))
    value = sensor.sample(sim)
    sim.close()
    return value


def test_a_turned_spot_lights_the_sensor_as_its_written_direction_says(tmp_path):
    straight = _reading(tmp_path, 0.0)
    assert straight == pytest.approx(500.0, abs=0.5)  # 0.5 x cos 0 x spot 1, white (r + g + b) / 3, no ambient
    # Turned sideways, the drawn beam misses the sensor; Webots' sensor still reads the written -z.
    assert _reading(tmp_path, 1.5708) == pytest.approx(straight, abs=1e-6)
