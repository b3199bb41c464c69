"""WGS84 geodesy: the world's local east-north-up plane about an origin, as latitude, longitude
and altitude, and back.

The world of the simulation is a local tangent plane (ENU, :mod:`sailmujoco.frames`) at a stated
origin; a GNSS receiver reports geodetic coordinates on the WGS84 ellipsoid (NIMA TR8350.2,
a = 6378137 m, f = 1/298.257223563). The conversion goes through Earth-centred Earth-fixed
(ECEF) coordinates: the origin's ECEF point plus the ENU offset turned by the origin's ENU axes,
then ECEF to geodetic by Bowring's iteration (B. R. Bowring, "Transformation from spatial to
geographical coordinates", Survey Review 23(181), 1976), which converges to below a micrometre
in two or three steps at the Earth's surface.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

WGS84_A = 6378137.0  # m, semi-major axis (NIMA TR8350.2)
WGS84_F = 1.0 / 298.257223563  # flattening
WGS84_E2 = WGS84_F * (2.0 - WGS84_F)  # first eccentricity squared


@dataclass(frozen=True)
class Origin:
    """Where the world's origin lies on the WGS84 ellipsoid.

    Parameters
    ----------
    latitude, longitude : float
        Geodetic latitude and longitude, deg (north and east positive).
    altitude : float
        Height above the ellipsoid, m.
    """

    latitude: float
    longitude: float
    altitude: float = 0.0

    def __post_init__(self):
        if not (isinstance(self.latitude, (int, float)) and -90.0 <= self.latitude <= 90.0):
            raise ValueError(f"origin latitude must be in [-90, 90] deg, got {self.latitude!r}")
        if not (isinstance(self.longitude, (int, float)) and -180.0 <= self.longitude <= 180.0):
            raise ValueError(f"origin longitude must be in [-180, 180] deg, got {self.longitude!r}")
        if not (isinstance(self.altitude, (int, float)) and math.isfinite(self.altitude)):
            raise ValueError(f"origin altitude must be a finite number (m), got {self.altitude!r}")


def ecef_from_geodetic(latitude: float, longitude: float, altitude: float) -> np.ndarray:
    """ECEF coordinates of a geodetic point, m.

    Parameters
    ----------
    latitude, longitude : float
        Degrees.
    altitude : float
        Height above the ellipsoid, m.
    """
    lat, lon = math.radians(latitude), math.radians(longitude)
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)  # prime-vertical radius
    return np.array([(n + altitude) * math.cos(lat) * math.cos(lon),
                     (n + altitude) * math.cos(lat) * math.sin(lon),
                     (n * (1.0 - WGS84_E2) + altitude) * math.sin(lat)])


def geodetic_from_ecef(point) -> tuple[float, float, float]:
    """(latitude deg, longitude deg, altitude m) of an ECEF point, by Bowring's iteration.

    Parameters
    ----------
    point : array_like, shape (3,)
        ECEF coordinates, m.
    """
    x, y, z = (float(v) for v in point)
    lon = math.atan2(y, x)
    p = math.hypot(x, y)
    lat = math.atan2(z, p * (1.0 - WGS84_E2))
    for _ in range(5):
        n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
        altitude = p / math.cos(lat) - n
        lat = math.atan2(z, p * (1.0 - WGS84_E2 * n / (n + altitude)))
    n = WGS84_A / math.sqrt(1.0 - WGS84_E2 * math.sin(lat) ** 2)
    altitude = p / math.cos(lat) - n
    return math.degrees(lat), math.degrees(lon), altitude


def enu_axes(origin: Origin) -> np.ndarray:
    """The origin's east, north and up unit vectors in ECEF, as the rows of a 3x3 matrix.

    Parameters
    ----------
    origin : Origin
        The world's origin.
    """
    lat, lon = math.radians(origin.latitude), math.radians(origin.longitude)
    return np.array([[-math.sin(lon), math.cos(lon), 0.0],
                     [-math.sin(lat) * math.cos(lon), -math.sin(lat) * math.sin(lon), math.cos(lat)],
                     [math.cos(lat) * math.cos(lon), math.cos(lat) * math.sin(lon), math.sin(lat)]])


def geodetic_from_enu(enu, origin: Origin) -> tuple[float, float, float]:
    """(latitude deg, longitude deg, altitude m) of a point of the world's ENU plane.

    Parameters
    ----------
    enu : array_like, shape (3,)
        East, north, up from the origin, m.
    origin : Origin
        The world's origin.
    """
    base = ecef_from_geodetic(origin.latitude, origin.longitude, origin.altitude)
    return geodetic_from_ecef(base + enu_axes(origin).T @ np.asarray(enu, dtype=float))


def enu_from_geodetic(latitude: float, longitude: float, altitude: float, origin: Origin) -> np.ndarray:
    """East, north, up (m) of a geodetic point from the origin: :func:`geodetic_from_enu`'s inverse.

    Parameters
    ----------
    latitude, longitude : float
        Degrees.
    altitude : float
        Height above the ellipsoid, m.
    origin : Origin
        The world's origin.
    """
    base = ecef_from_geodetic(origin.latitude, origin.longitude, origin.altitude)
    return enu_axes(origin) @ (ecef_from_geodetic(latitude, longitude, altitude) - base)
