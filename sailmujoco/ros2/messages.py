"""The fields of the standard ROS 2 messages a boat publishes, from its state and instruments.

Frames (REP-103, "Standard Units of Measure and Coordinate Conventions"; REP-105, "Coordinate
Frames for Mobile Platforms"): the world is ENU (x east, y north, z up), the body ``base_link``
FLU (x forward, y port, z up), the frames of :mod:`sailmujoco.frames`, so nothing is turned on
the way out. Units SI, angles in radians.

* ``sensor_msgs/Imu`` (REP-145, "Conventions for IMU Sensor Drivers"): the orientation of the
  body in the world (ENU), the angular velocity in the body, and the linear acceleration in the
  body as an accelerometer reads it, the specific force: the acceleration less gravity, so a
  boat at rest reads +g up.
* ``sensor_msgs/NavSatFix``: WGS84 latitude and longitude (deg) and the height above the
  ellipsoid (m) of the antenna's point of the world, about a stated :class:`~sailmujoco.ros2.
  geodesy.Origin`, with its covariance in ENU (m^2) when the receiver's error is known.
* ``geometry_msgs/TwistStamped`` on ``/gps/vel``: the velocity over ground in ENU.
* ``nav_msgs/Odometry`` (REP-105): the pose in the world and the twist in the body frame.
* ``rosgraph_msgs/Clock`` and every header's stamp: a time in integer nanoseconds as
  ``builtin_interfaces/Time``'s seconds and nanoseconds.
* ``geometry_msgs/Vector3Stamped`` on ``/wind/apparent``: the masthead unit's apparent wind in
  the body frame, as the velocity of the air past the boat (where it blows to): the
  convention of :func:`sailmujoco.frames.apparent_wind_angle`, so AWA = atan2(y, -x).

Each function returns a mapping keyed by the message's field names (nested mappings for nested
messages), without the header, which the publisher stamps.
"""

from __future__ import annotations

import math

import numpy as np

from ..constants import GRAVITY
from .geodesy import Origin, geodetic_from_enu

# sensor_msgs/NavSatStatus and NavSatFix constants (sensor_msgs/msg/NavSatStatus.msg, NavSatFix.msg)
STATUS_FIX = 0
SERVICE_GPS = 1
COVARIANCE_TYPE_UNKNOWN = 0
COVARIANCE_TYPE_DIAGONAL_KNOWN = 2


def _vector(v) -> dict:
    x, y, z = (float(c) for c in v)
    return {"x": x, "y": y, "z": z}


def _quaternion(q_wxyz) -> dict:
    w, x, y, z = (float(c) for c in q_wxyz)
    return {"x": x, "y": y, "z": z, "w": w}


def time(nanoseconds: int) -> dict:
    """``builtin_interfaces/Time``'s fields (a Clock's ``clock``, a header's ``stamp``).

    Parameters
    ----------
    nanoseconds : int
        The time, ns (>= 0).
    """
    return {"sec": nanoseconds // 10**9, "nanosec": nanoseconds % 10**9}


def odometry(position, orientation_wxyz, linear_velocity, angular_velocity) -> dict:
    """``nav_msgs/Odometry``'s ``pose`` and ``twist`` (REP-105: the pose in the parent frame, the
    twist in the child, the body), covariances zero: unknown.

    Parameters
    ----------
    position : array_like, shape (3,)
        In the world (ENU), m.
    orientation_wxyz : array_like, shape (4,)
        Body (FLU) to world (ENU) unit quaternion, MuJoCo's order (w, x, y, z).
    linear_velocity, angular_velocity : array_like, shape (3,)
        In the body frame, m/s and rad/s.
    """
    return {"pose": {"pose": {"position": _vector(position), "orientation": _quaternion(orientation_wxyz)},
                     "covariance": [0.0] * 36},
            "twist": {"twist": {"linear": _vector(linear_velocity), "angular": _vector(angular_velocity)},
                      "covariance": [0.0] * 36}}


def vector3(v) -> dict:
    """``geometry_msgs/Vector3``'s fields.

    Parameters
    ----------
    v : array_like, shape (3,)
        The vector.
    """
    return _vector(v)


def specific_force(acceleration_world, rotation) -> np.ndarray:
    """What an accelerometer fixed to the body reads: R^T (a - g), g = (0, 0, -9.81) in ENU.

    Parameters
    ----------
    acceleration_world : array_like, shape (3,)
        The body's acceleration in the world (ENU), m/s^2.
    rotation : array_like, shape (3, 3)
        Body (FLU) to world (ENU) rotation.

    Returns
    -------
    numpy.ndarray, shape (3,)
        m/s^2 in the body frame; at rest and level (0, 0, +g).
    """
    a = np.asarray(acceleration_world, dtype=float) - np.array([0.0, 0.0, -GRAVITY])
    return np.asarray(rotation, dtype=float).reshape(3, 3).T @ a


def imu(orientation_wxyz, angular_velocity, linear_acceleration=None) -> dict:
    """``sensor_msgs/Imu``'s fields (REP-145), the covariances all zero: "covariance unknown" in
    sensor_msgs/Imu's own convention (a first element of -1 would say the quantity is missing).

    Parameters
    ----------
    orientation_wxyz : array_like, shape (4,)
        Body (FLU) to world (ENU) unit quaternion, MuJoCo's order (w, x, y, z).
    angular_velocity : array_like, shape (3,)
        In the body frame, rad/s.
    linear_acceleration : array_like, shape (3,), optional
        The specific force in the body frame (:func:`specific_force`), m/s^2; None: not
        measured (zeros, the first element of its covariance -1).
    """
    zero = [0.0] * 9
    missing = [-1.0] + [0.0] * 8
    return {"orientation": _quaternion(orientation_wxyz), "orientation_covariance": list(zero),
            "angular_velocity": _vector(angular_velocity), "angular_velocity_covariance": list(zero),
            "linear_acceleration": _vector((0.0, 0.0, 0.0) if linear_acceleration is None
                                           else linear_acceleration),
            "linear_acceleration_covariance": list(zero) if linear_acceleration is not None else missing}


def nav_sat_fix(enu, origin: Origin, sigma_horizontal: float | None = None,
                sigma_vertical: float | None = None) -> dict:
    """``sensor_msgs/NavSatFix``'s fields for an antenna at ``enu`` in the world.

    Parameters
    ----------
    enu : array_like, shape (3,)
        The antenna's point of the world (east, north, up from the origin), m.
    origin : Origin
        Where the world's origin lies on the WGS84 ellipsoid.
    sigma_horizontal, sigma_vertical : float, optional
        The receiver's standard errors, m; None: covariance unknown.
    """
    latitude, longitude, altitude = geodetic_from_enu(enu, origin)
    covariance = [0.0] * 9
    kind = COVARIANCE_TYPE_UNKNOWN
    if sigma_horizontal is not None:
        vertical = sigma_horizontal if sigma_vertical is None else sigma_vertical
        covariance[0] = covariance[4] = float(sigma_horizontal) ** 2
        covariance[8] = float(vertical) ** 2
        kind = COVARIANCE_TYPE_DIAGONAL_KNOWN
    return {"status": {"status": STATUS_FIX, "service": SERVICE_GPS}, "latitude": latitude,
            "longitude": longitude, "altitude": altitude, "position_covariance": covariance,
            "position_covariance_type": kind}


def twist_enu(velocity_enu, angular_velocity=(0.0, 0.0, 0.0)) -> dict:
    """``geometry_msgs/Twist``'s fields (a TwistStamped's ``twist``): the velocity over ground.

    Parameters
    ----------
    velocity_enu : array_like, shape (3,)
        m/s, east, north, up.
    angular_velocity : array_like, shape (3,)
        rad/s, in the same frame (a GNSS receiver gives none: zero).
    """
    return {"linear": _vector(velocity_enu), "angular": _vector(angular_velocity)}


def apparent_wind(angle: float, speed: float) -> dict:
    """``geometry_msgs/Vector3``'s fields (a Vector3Stamped's ``vector``): the air's velocity past
    the boat in the body frame, from the vane's angle and the anemometer's speed.

    Parameters
    ----------
    angle : float
        Apparent wind angle AWA, rad, positive from starboard (:mod:`sailmujoco.frames`).
    speed : float
        Apparent wind speed, m/s.
    """
    return _vector((-speed * math.cos(angle), speed * math.sin(angle), 0.0))
