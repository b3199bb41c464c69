"""The cameras of a frame: the follow camera that sees the sail's face, and the top view.

The follow camera rides with the boat at ``distance`` m, looking down ``elevation_deg``, on a
bearing from the bow (counter-clockwise, deg). By default (``bearing_deg=None``) the bearing
comes from the boom. A sail sets roughly across the apparent wind and its force is roughly
normal to it: seen along its normal, the sail shows its face and its force arrow points at
the camera; seen from astern with the boom out, the sail is edge-on. The camera sits instead
on the side away from the boom (windward), :data:`OFF_NORMAL` from the sail's normal towards
dead astern, and never forward of that normal::

    bearing = 180 deg + side * max(0, 90 deg - |boom angle| - OFF_NORMAL)

with ``side`` +1 (starboard) for a boom to port and -1 for a boom to starboard. With the boom
out by OFF_NORMAL or less, the line of sight meets the sail at 90 deg - OFF_NORMAL and the
sail's force at OFF_NORMAL, so both show at least cos(45 deg) = 71 % of their size (times the
cosine of the elevation); with the boom further out the camera is dead astern and sees more
of the sail. The side changes only when the boom has crossed the centre line by more than
:data:`SIDE_HYSTERESIS`, and the bearing and the heading both follow through first-order lags
of ``lag`` s: a tack or a gybe swings the camera round smoothly. A given ``bearing_deg`` fixes
the bearing instead.
"""

from __future__ import annotations

import math

import numpy as np

from ..frames import wrap_angle

OFF_NORMAL = math.radians(45.0)  # the camera's bearing from the sail's normal, towards astern
SIDE_HYSTERESIS = math.radians(4.0)  # the boom must cross the centre line by this to switch sides
ELEVATION_DEG = -24.0  # default follow camera elevation (looking down)
DISTANCE_MASTHEADS = 2.7  # default follow distance, masthead heights


def yaw_of(rotation: np.ndarray) -> float:
    """Yaw (rad, ENU, counter-clockwise from east) of a body -> world rotation matrix.

    Parameters
    ----------
    rotation : ndarray
        (3, 3) body -> world.
    """
    return math.atan2(rotation[1, 0], rotation[0, 0])


def boom_angle(rotation: np.ndarray, mast_step: np.ndarray, boom_end: np.ndarray) -> float:
    """Angle of the boom from the centre line, rad, positive to port, from world positions.

    Parameters
    ----------
    rotation : ndarray
        (3, 3) body -> world rotation of the hull.
    mast_step, boom_end : ndarray
        (3,) world positions of the boom's two ends, m.
    """
    aft = rotation.T @ (np.asarray(boom_end, float) - np.asarray(mast_step, float))
    return math.atan2(aft[1], -aft[0])


class FollowCamera:
    """The follow camera's state: smoothed heading and bearing, and the side it is on.

    Parameters
    ----------
    distance : float
        m from the point looked at.
    height : float
        m above the boat's origin of the point looked at.
    elevation_deg : float
        deg, negative looking down.
    bearing_deg : float, optional
        Fixed bearing from the bow, deg counter-clockwise; None: from the boom (module doc).
    lag : float
        s, time constant of the heading and bearing lags (0: none).
    """

    def __init__(self, distance: float, height: float, elevation_deg: float = ELEVATION_DEG,
                 bearing_deg: float | None = None, lag: float = 3.0):
        self.distance, self.height, self.elevation = float(distance), float(height), float(elevation_deg)
        self.fixed_bearing = None if bearing_deg is None else math.radians(bearing_deg)
        self.lag = float(lag)
        self.side = 1.0
        self._yaw = self._bearing = self._time = None

    def bearing_for(self, boom: float) -> float:
        """The bearing from the bow (rad, counter-clockwise) that shows the sail's face.

        Parameters
        ----------
        boom : float
            Boom angle, rad, positive to port (:func:`boom_angle`).
        """
        if self.fixed_bearing is not None:
            return self.fixed_bearing
        if boom > SIDE_HYSTERESIS:
            self.side = 1.0  # boom to port: camera to starboard
        elif boom < -SIDE_HYSTERESIS:
            self.side = -1.0
        return math.pi + self.side * max(0.0, 0.5 * math.pi - abs(boom) - OFF_NORMAL)

    def _smooth(self, previous, target: float, dt: float) -> float:
        if previous is None or self.lag <= 0.0:
            return target
        return previous + wrap_angle(target - previous) * (1.0 - math.exp(-dt / self.lag))

    def pose(self, time: float, position, rotation, boom: float) -> tuple[np.ndarray, float, float, float]:
        """(look-at point, distance, azimuth deg, elevation deg) of MuJoCo's free camera now.

        Parameters
        ----------
        time : float
            Simulated time, s (the lags run on it).
        position : ndarray
            (3,) the boat's origin in the world, m.
        rotation : ndarray
            (3, 3) body -> world rotation of the hull.
        boom : float
            Boom angle, rad, positive to port.
        """
        dt = 0.0 if self._time is None else max(time - self._time, 0.0)
        self._time = time
        self._yaw = self._smooth(self._yaw, yaw_of(rotation), dt)
        self._bearing = self._smooth(self._bearing, self.bearing_for(boom), dt)
        # the camera sits at bearing b from the bow, so it looks along yaw + b + pi
        azimuth = math.degrees(self._yaw + self._bearing + math.pi)
        lookat = np.asarray(position, float) + np.array([0.0, 0.0, self.height])
        return lookat, self.distance, azimuth, self.elevation


def top_pose(center, extent: float, fovy_deg: float) -> tuple[np.ndarray, float]:
    """(look-at point, distance) of a view straight down showing ``extent`` m each side of centre.

    Parameters
    ----------
    center : array_like
        (2,) m, world x east, y north.
    extent : float
        m, half-height of the view on the water.
    fovy_deg : float
        Vertical field of view, deg.
    """
    distance = extent / math.tan(math.radians(fovy_deg) / 2.0)
    return np.array([center[0], center[1], 0.0]), distance
