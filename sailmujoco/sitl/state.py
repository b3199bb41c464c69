"""The boat's state as ArduPilot's JSON backend reads it: every vector in ArduPilot's frames.

* ``timestamp``: the simulated time, s (it goes back to 0 when the boat is reset: SITL takes a
  timestamp that goes backwards for a reset of the physics);
* ``imu``: ``gyro``, the body rates in FRD (rad/s), and ``accel_body``, the specific force in
  FRD (m/s^2): the acceleration of CO less gravity, ``R^T (a - g)``, so that a boat at rest
  reads ``[0, 0, -9.81]`` (an accelerometer at rest feels the water push up);
* ``position`` from home (north, east, down, m) and ``velocity`` (north, east, down, m/s) of CO;
* ``quaternion``: the rotation from body FRD to NED, (w, x, y, z)
  (:func:`sailmujoco.frames.ned_frd_quaternion`);
* ``windvane``: the apparent wind at the masthead, ``direction`` clockwise from the bow (0 head
  to wind: our AWA, positive from starboard) and ``speed`` (m/s), as the boat's vane reads it
  (the sensor layer's :class:`~sailmujoco.measurement.sensors.MastheadVane`, or the truth with
  perfect sensors).

The acceleration is the change of CO's velocity over the last step (the step the packet asked
for), divided by its length: the mean acceleration of that step.
"""

from __future__ import annotations

import numpy as np

from .. import frames
from ..constants import GRAVITY
from ..jit.ordered import mat_t_vec, mat_vec


def boat_state(physics, previous_velocity, dt: float, vane: tuple[float, float]) -> dict:
    """The JSON backend's state of a :class:`~sailmujoco.physics.BoatPhysics` now.

    Parameters
    ----------
    physics : BoatPhysics
        The boat.
    previous_velocity : array_like, shape (3,) or None
        CO's world (ENU) velocity one step ago, m/s (None: the boat has not moved yet; no
        acceleration).
    dt : float
        That step's length, s.
    vane : tuple of float
        (direction, speed) the wind vane reports: rad clockwise from the bow, m/s.
    """
    rot = physics.rotation()
    velocity = mat_vec(rot, physics.body_velocity())  # CO's world (ENU) velocity, m/s
    acceleration = np.zeros(3) if previous_velocity is None else (velocity - previous_velocity) / dt
    specific = mat_t_vec(rot, acceleration - np.array([0.0, 0.0, -GRAVITY]))  # body FLU
    return {
        "timestamp": float(physics.data.time),
        "imu": {"gyro": frames.frd_from_flu(physics.angular_velocity()),
                "accel_body": frames.frd_from_flu(specific)},
        "position": frames.ned_from_enu(physics.position()),
        "velocity": frames.ned_from_enu(velocity),
        "quaternion": frames.ned_frd_quaternion(rot),
        "windvane": {"direction": float(vane[0]), "speed": float(vane[1])},
    }
