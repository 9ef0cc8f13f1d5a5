"""WGS84 GPS values: latitude and longitude on the ellipsoid about gpsReference, altitude along the world's up."""

import pytest

from wbtc.runtime.geodesy import to_wgs84


def test_the_reference_point_and_offsets_along_north_and_east():
    reference = [40.67, -73.94, 10.0]
    assert to_wgs84([0.0, 0.0, 0.0], reference) == pytest.approx([40.67, -73.94, 10.0], abs=1e-9)
    # WGS84 radii of curvature at 40.67°: meridian 6 362 555 m, prime vertical 6 387 224 m.
    lat, lon, alt = to_wgs84([0.0, 1000.0, 5.0], reference)
    assert lat - 40.67 == pytest.approx(1000.0 / 6362555.0 * 57.29578, rel=1e-4)
    assert lon == pytest.approx(-73.94, abs=1e-7) and alt == pytest.approx(15.0)
    lat, lon, _ = to_wgs84([1000.0, 0.0, 0.0], reference)
    assert lon + 73.94 == pytest.approx(1000.0 / (6387224.0 * 0.758476) * 57.29578, rel=1e-4)
    assert lat == pytest.approx(40.67, abs=1e-4)  # the tangent plane leaves the parallel by a hair
