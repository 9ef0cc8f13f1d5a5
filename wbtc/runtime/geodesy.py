"""WGS84 coordinates of a point given in a world's local east-north-up frame (GPS `coordinateSystem` WGS84).

A world with `WorldInfo.gpsCoordinateSystem "WGS84"` places its origin at `gpsReference` (latitude and
longitude in degrees, altitude in metres) with the world's east, north and up axes tangent to the
WGS84 ellipsoid there. A point's local (east, north) offset is turned into Earth-centred coordinates
and back into latitude and longitude on the ellipsoid (Bowring's method); its altitude is the
reference altitude plus its up coordinate, as Webots reports it (the tangent plane's rise above the
curved Earth, 2.3 m at 5.4 km, is not counted: Webots' test expects an altitude of exactly 0 there).
"""

from __future__ import annotations

import math

import numpy as np

_A = 6378137.0  # WGS84 semi-major axis (m)
_F = 1 / 298.257223563  # flattening
_E2 = _F * (2 - _F)  # first eccentricity squared


def _ecef(lat: float, lon: float, alt: float) -> np.ndarray:
    """Earth-centred, Earth-fixed coordinates of a geodetic point (radians, metres)."""
    n = _A / math.sqrt(1 - _E2 * math.sin(lat) ** 2)
    return np.array([(n + alt) * math.cos(lat) * math.cos(lon), (n + alt) * math.cos(lat) * math.sin(lon),
                     (n * (1 - _E2) + alt) * math.sin(lat)])


def to_wgs84(enu: np.ndarray, reference: list[float]) -> list[float]:
    """[latitude°, longitude°, altitude m] of a point at local east-north-up offset `enu` from `reference`."""
    lat0, lon0 = math.radians(reference[0]), math.radians(reference[1])
    # The local axes in Earth-centred coordinates (columns: east, north, up).
    sl, cl, so, co = math.sin(lat0), math.cos(lat0), math.sin(lon0), math.cos(lon0)
    axes = np.array([[-so, -sl * co, cl * co], [co, -sl * so, cl * so], [0.0, cl, sl]])
    east, north, up = (float(v) for v in enu)
    x, y, z = _ecef(lat0, lon0, float(reference[2])) + axes @ np.array([east, north, 0.0])
    lon = math.atan2(y, x)
    p = math.hypot(x, y)
    lat = math.atan2(z, p * (1 - _E2))
    for _ in range(5):
        n = _A / math.sqrt(1 - _E2 * math.sin(lat) ** 2)
        lat = math.atan2(z + _E2 * n * math.sin(lat), p)
    return [math.degrees(lat), math.degrees(lon), float(reference[2]) + up]
