"""A WGS84 GPS after a supervisor changes WorldInfo.coordinateSystem: the letters pick the world axes anew.

Webots' WbGps (R2023) reads the world position as it is and takes its north, east and up components at
the positions of 'N', 'E' and 'U' in `coordinateSystem`; the world does not turn. The world is Webots'
gps_coordinates_north_direction test world: an NUE world, the GPS at (4999.95, 0, 2000).
"""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.geodesy import to_wgs84
from wbtc.runtime.sensors import GPS
from wbtc.runtime.simulation import Simulation

WORLD = Path(__file__).parents[1] / "conformance" / "api" / "worlds" / "gps_coordinates_north_direction.wbt"
X, Y, Z = 4999.95, 0.0, 2000.0  # the GPS in the world's axes (0.05 m behind the robot's origin along x)


@pytest.fixture(scope="module")
def sim():
    result, _ = compile_world(WORLD)
    simulation = Simulation(result)
    yield simulation
    simulation.close()


def _read(sim: Simulation, system: str) -> list[float]:
    sim.set_coordinate_system(system)
    gps = next(s for r in sim.robots for s in r.sensors.values() if isinstance(s, GPS))
    return gps.sample(sim)[:3]


@pytest.mark.parametrize(("system", "east", "north", "up"), [
    ("NUE", Z, X, Y),  # as loaded: 5 km north, 2 km east, altitude 0
    ("ENU", X, Y, Z),  # x is east now and z up: latitude 0, altitude 2000 (the robot is not moved)
    ("EUN", X, Z, Y),  # z is north: latitude from 2 km, longitude from 5 km, altitude 0 again
])
def test_the_letters_pick_north_east_and_up_from_the_unturned_world(sim, system, east, north, up):
    latitude, longitude, altitude = _read(sim, system)
    expected = to_wgs84([east, north, up], [0.0, 0.0, 0.0])
    assert latitude == pytest.approx(expected[0], abs=1e-9) and longitude == pytest.approx(expected[1], abs=1e-9)
    assert altitude == pytest.approx(up, abs=1e-6)


def test_after_enu_the_reading_is_not_the_quarter_turn_the_stored_test_expects(sim):
    # Webots' test expects latitude = old longitude, longitude = -old latitude, altitude 0: the rule of
    # WbGps's former northDirection field (0 0 1 turned the position by -pi/2 about up). No pick of world
    # axes gives a negative longitude here (every coordinate of the GPS is >= 0).
    old = _read(sim, "NUE")
    new = _read(sim, "ENU")
    assert old[2] == pytest.approx(0.0, abs=1e-9) and new[2] == pytest.approx(2000.0)
    assert new[0] == pytest.approx(0.0, abs=1e-9) and new[1] == pytest.approx(0.0448722, abs=1e-7)
    assert old[0] == pytest.approx(0.0451744, abs=1e-7) and old[1] == pytest.approx(0.0179479, abs=1e-7)
