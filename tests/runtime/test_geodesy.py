"""WGS84 GPS values through Webots' UTM grid: the reference projected, offsets added in grid metres, projected back."""

import math

import pytest

from wbtc.runtime.geodesy import from_grid, to_grid, to_wgs84, zone_meridian


def test_zones_and_grid_coordinates_match_an_independent_utm():
    # Zone central meridians: 18 (New York) -75°, 31 (0° E) 3°, 56 (Sydney) 153°.
    assert [round(math.degrees(zone_meridian(lon)), 9) for lon in (-73.94, 0.0, 151.2)] == [-75.0, 3.0, 153.0]
    # PROJ (pyproj 3, EPSG:32618 and EPSG:32631) gives (easting, northing) (589591.5469, 4502665.1097) and
    # (166021.4431, 0.0); Webots' series and flattening agree within a millimetre.
    north, east = to_grid(40.67, -73.94, zone_meridian(-73.94), 0.0)
    assert east == pytest.approx(589591.5469, abs=1e-3) and north == pytest.approx(4502665.1097, abs=1e-3)
    north, east = to_grid(0.0, 0.0, zone_meridian(0.0), 0.0)
    assert east == pytest.approx(166021.4431, abs=1e-3) and north == pytest.approx(0.0, abs=1e-9)
    assert from_grid(4502665.1097, 589591.5469, zone_meridian(-73.94), 0.0) == pytest.approx((40.67, -73.94), abs=1e-8)


def test_webots_test_world_values():
    # tests/api gps_coordinates_north_direction: 4999.95 m north, 2000 m east of 0 0 0, expected to 1e-7 degree.
    latitude, longitude, altitude = to_wgs84([2000.0, 4999.95, 0.0], [0.0, 0.0, 0.0])
    assert latitude == pytest.approx(0.0451744, abs=1e-7) and longitude == pytest.approx(0.0179479, abs=1e-7)
    assert altitude == 0.0


def test_offsets_are_grid_metres_and_resolution_applies_to_them():
    reference = [40.67, -73.94, 10.0]
    assert to_wgs84([0.0, 0.0, 0.0], reference) == pytest.approx([40.67, -73.94, 10.0], abs=1e-9)
    latitude, longitude, altitude = to_wgs84([0.0, 1000.0, 5.0], reference)
    assert (latitude, longitude, altitude) == pytest.approx((40.6790072, -73.9398573, 15.0), abs=1e-7)
    # South of the equator the grid counts from 10,000 km.
    assert to_wgs84([0.0, 1000.0, 0.0], [-33.9, 151.2, 0.0])[:2] == pytest.approx([-33.8909854, 151.2001894], abs=1e-7)
    # A 1 m resolution rounds the grid coordinates (166021.44 + 2000.4 -> 168022) and the altitude.
    coarse = to_wgs84([2000.4, 4999.95, 0.26], [0.0, 0.0, 0.0], 1.0)
    north, east = to_grid(coarse[0], coarse[1], zone_meridian(0.0), 0.0)
    # (back through the truncated series, to 0.1 mm)
    assert (north, east, coarse[2]) == pytest.approx((5000.0, 168022.0, 0.0), abs=1e-4)
