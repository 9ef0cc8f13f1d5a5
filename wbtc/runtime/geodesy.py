"""WGS84 coordinates of a point given in a world's local east-north-up frame (GPS `coordinateSystem` WGS84).

A world with `WorldInfo.gpsCoordinateSystem "WGS84"` places its origin at `gpsReference` (latitude and
longitude in degrees, altitude in metres). Webots (WbGps's UTM converter) does not measure the offset on
the ellipsoid: it projects the reference into its Universal Transverse Mercator zone (scale 0.9996 on the
zone's central meridian, the zone picked by the reference's longitude, false northing 10,000 km south of
the equator), adds the point's north and east offsets in metres to those grid coordinates, and projects
back. So do we, with the same series (Snyder's, to the sixth power of the eccentricity and of the
distance from the central meridian) and Webots' flattening 1 / 298.2572236. Far from the central meridian
a grid metre is more than a metre on the ground (about 0.1 % at 334 km, Webots' test world at gpsReference
0 0 0): the latitudes and longitudes are Webots' own. The altitude is the reference altitude plus the up
offset; noise and resolution apply to the grid metres, before projecting back (`to_wgs84`).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence

from wbtc.runtime.lookup import quantize

_A = 6378137.0  # WGS84 semi-major axis (m)
_F = 1.0 / 298.2572236  # flattening, as WbGps writes it
_K0 = 0.9996  # scale on the central meridian
_FALSE_EASTING = 500000.0
_B = _A * (1.0 - _F)
_E2 = 1.0 - (_B / _A) ** 2  # first eccentricity squared
_EP2 = _E2 / (1.0 - _E2)  # second eccentricity squared
#: The meridian arc's series coefficients (Snyder 3-21).
_M0 = 1.0 - _E2 * (1 / 4 + _E2 * (3 / 64 + 5 * _E2 / 256))
_M2 = _E2 * (3 / 8 + _E2 * (3 / 32 + 45 * _E2 / 1024))
_M4 = _E2 * _E2 * (15 / 256 + 45 * _E2 / 1024)
_M6 = _E2 ** 3 * 35 / 3072


def zone_meridian(longitude: float) -> float:
    """The central meridian (radians) of the UTM zone of a longitude in degrees."""
    zone = 1 + math.floor((longitude + 180.0) / 6.0)
    return math.radians(3.0 + 6.0 * (zone - 1) - 180.0)


def to_grid(latitude: float, longitude: float, meridian: float, false_northing: float) -> tuple[float, float]:
    """(north, east) grid metres of a point (degrees) in the transverse Mercator of `meridian` (radians)."""
    phi = math.radians(latitude)
    n = _A / math.sqrt(1.0 - _E2 * math.sin(phi) ** 2)
    t = math.tan(phi) ** 2
    c = _EP2 * math.cos(phi) ** 2
    a = (math.radians(longitude) - meridian) * math.cos(phi)
    m = _A * (_M0 * phi - _M2 * math.sin(2 * phi) + _M4 * math.sin(4 * phi) - _M6 * math.sin(6 * phi))
    east = _K0 * n * (a + (1 - t + c) * a ** 3 / 6 + (5 - 18 * t + t * t + 72 * c - 58 * _EP2) * a ** 5 / 120)
    north = _K0 * (m + n * math.tan(phi) * (a * a / 2 + (5 - t + 9 * c + 4 * c * c) * a ** 4 / 24
                                            + (61 - 58 * t + t * t + 600 * c - 330 * _EP2) * a ** 6 / 720))
    return north + false_northing, east + _FALSE_EASTING


def from_grid(north: float, east: float, meridian: float, false_northing: float) -> tuple[float, float]:
    """(latitude, longitude) in degrees of grid metres in the transverse Mercator of `meridian` (radians)."""
    root = math.sqrt(1.0 - _E2)
    e1 = (1.0 - root) / (1.0 + root)
    mu = (north - false_northing) / _K0 / (_A * _M0)
    # The footpoint latitude (Snyder 3-26).
    phi1 = (mu + (3 * e1 / 2 - 27 * e1 ** 3 / 32) * math.sin(2 * mu) + (21 * e1 ** 2 / 16 - 55 * e1 ** 4 / 32)
            * math.sin(4 * mu) + 151 * e1 ** 3 / 96 * math.sin(6 * mu) + 1097 * e1 ** 4 / 512 * math.sin(8 * mu))
    s = math.sin(phi1)
    c1 = _EP2 * math.cos(phi1) ** 2
    t1 = math.tan(phi1) ** 2
    n1 = _A / math.sqrt(1.0 - _E2 * s * s)
    r1 = _A * (1.0 - _E2) / (1.0 - _E2 * s * s) ** 1.5
    d = (east - _FALSE_EASTING) / (n1 * _K0)
    phi = phi1 - n1 * math.tan(phi1) / r1 * (
        d * d / 2 - (5 + 3 * t1 + 10 * c1 - 4 * c1 * c1 - 9 * _EP2) * d ** 4 / 24
        + (61 + 90 * t1 + 298 * c1 + 45 * t1 * t1 - 252 * _EP2 - 3 * c1 * c1) * d ** 6 / 720)
    lam = meridian + (d - (1 + 2 * t1 + c1) * d ** 3 / 6
                      + (5 - 2 * c1 + 28 * t1 - 3 * c1 * c1 + 8 * _EP2 + 24 * t1 * t1) * d ** 5 / 120) / math.cos(phi1)
    return math.degrees(phi), math.degrees(lam)


def to_wgs84(enu: Sequence[float], reference: Sequence[float], resolution: float = -1.0) -> list[float]:
    """[latitude°, longitude°, altitude m] of a point at local east-north-up offset `enu` from `reference`.

    Args:
        enu: east, north and up offsets in metres (noise already added, as Webots adds it in metres).
        reference: `gpsReference`: latitude and longitude in degrees, altitude in metres.
        resolution: the GPS `resolution` in metres (-1: none), applied to the grid metres and the altitude.
    """
    meridian, false_northing, north0, east0 = _reference_grid(float(reference[0]), float(reference[1]))
    north = quantize(north0 + float(enu[1]), resolution)
    east = quantize(east0 + float(enu[0]), resolution)
    latitude, longitude = from_grid(north, east, meridian, false_northing)
    return [latitude, longitude, quantize(float(reference[2]) + float(enu[2]), resolution)]


@functools.lru_cache(maxsize=8)
def _reference_grid(latitude: float, longitude: float) -> tuple[float, float, float, float]:
    """The zone's meridian, false northing and grid (north, east) of a gpsReference: fixed for a world."""
    meridian = zone_meridian(longitude)
    false_northing = 10000000.0 if latitude < 0.0 else 0.0
    north, east = to_grid(latitude, longitude, meridian, false_northing)
    return meridian, false_northing, north, east
