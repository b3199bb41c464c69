"""The observation every world hands a task, built from measured values.

The observation is the dict of :func:`sailmujoco.tasks.base.measure` (the definition, from a
world's named accessors): the keys the controllers read (``controllers/base.py``) and the
``true_state`` of the full-state controllers. A world measures itself once per control step
(:meth:`sailmujoco.tasks.world.World.measure`); the MuJoCo boat and Wille's paper world build
the dict here, from one rotation matrix and the arrays they hold, with the same operations on
the same numbers as the accessors (the same numpy and MuJoCo functions where a library
computes a value, since numpy's SIMD transcendental functions need not agree with ``math``'s
to the last bit), so the observation is identical bit for bit (``tests/test_measurement.py``).

A task hands its ``true_state`` out as a :class:`TrueState`: read by name like a dict, and one
float64 array to numpy and to dm_control (``dm_control.rl.control.flatten_observation``).
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

# force term of a world -> key of the observation's "<key>_wrench" (true_state)
WRENCH_KEYS = {"sail": "sail", "keel": "keel", "rudder": "rudder", "damping": "damping",
               "added_mass": "added_mass", "hydrostatics": "restoring", "restoring": "restoring"}
WRENCH_NAMES = ("sail", "keel", "rudder", "damping", "added_mass", "restoring")

PI = math.pi
TWO_PI = 2.0 * math.pi


class TrueState(dict):
    """The full state of a task's observation: a dict of named float64 arrays that is also one
    flat float64 array, its entries' numbers in its key order.

    Full-state controllers read it by name (``true_state["u"]``); numpy (``np.asarray``) and
    dm_control (``flatten_observation``, ``flat_observation=True``) see the flat array, so an
    observation holding it flattens like any dm_control observation. :meth:`layout` says which
    slice of the flat array holds which entry.

    Parameters
    ----------
    entries : mapping
        Name -> array (or number), in the order the flat array takes them.
    """

    def ravel(self) -> np.ndarray:
        """The numbers of every entry, in key order, as one float64 array (a copy)."""
        return np.concatenate([np.ravel(np.asarray(value, dtype=np.float64)) for value in self.values()])

    def __array__(self, dtype=None, copy=None):
        flat = self.ravel()
        return flat if dtype is None else flat.astype(dtype, copy=False)

    @property
    def shape(self) -> tuple[int]:
        """The flat array's shape, ``(n,)``."""
        return (sum(int(np.size(value)) for value in self.values()),)

    @property
    def dtype(self) -> np.dtype:
        """float64, the flat array's dtype."""
        return np.dtype(np.float64)

    def layout(self) -> dict[str, slice]:
        """Name -> the slice of the flat array that holds it."""
        out, start = {}, 0
        for key, value in self.items():
            size = int(np.size(value))
            out[key] = slice(start, start + size)
            start += size
        return out


def wrench_rows(terms: tuple[str, ...]) -> tuple[tuple[str, ...], np.ndarray]:
    """The observation's wrench keys and where each comes from in a world's force terms.

    Parameters
    ----------
    terms : tuple of str
        The names of the world's force terms, in the order of its terms array.

    Returns
    -------
    keys : tuple of str
        The ``"<key>_wrench"`` keys in the order measure() inserts them (a later name for a key
        overwrites an earlier one in place, then any of the six the world lacks).
    rows : numpy.ndarray
        The row of each in the terms array (``len(terms)``: a row of zeros).
    """
    rows: dict[str, int] = {}
    for name, key in WRENCH_KEYS.items():
        if name in terms:
            rows[f"{key}_wrench"] = terms.index(name)
    for key in WRENCH_NAMES:
        rows.setdefault(f"{key}_wrench", len(terms))
    return tuple(rows), np.array(list(rows.values()), dtype=np.int64)


def wrap(angle: float) -> float:
    """frames.wrap_angle on a float: the same operations (fmod-based remainder) as numpy's.

    Parameters
    ----------
    angle : float
        Angle, rad.

    Returns
    -------
    float
        The angle in [-pi, pi), rad.
    """
    return (angle + PI) % TWO_PI - PI


def rotation_of(qpos) -> np.ndarray:
    """The hull's body->world rotation (3x3) from its free-joint qpos: MuJoCo's mju_quat2Mat.

    Parameters
    ----------
    qpos : numpy.ndarray
        Free-joint layout: position (3), then the quaternion (w, x, y, z).

    Returns
    -------
    numpy.ndarray
        The rotation matrix, as ``BoatPhysics.rotation()`` gives it.
    """
    out = np.empty(9)
    mujoco.mju_quat2Mat(out, qpos[3:7])
    return out.reshape(3, 3)


def euler_of(rot) -> tuple[float, float, float]:
    """frames.euler_from_matrix as floats, without its array handling.

    The same numpy functions on the same numbers (np.clip keeps a NaN, as this does).

    Parameters
    ----------
    rot : numpy.ndarray
        Body->world rotation matrix (3x3).

    Returns
    -------
    tuple of float
        (heel, pitch, yaw), rad.
    """
    heel = float(np.arctan2(rot[2, 1], rot[2, 2]))
    sin_pitch = rot[2, 0]
    if sin_pitch > 1.0:
        sin_pitch = 1.0
    elif sin_pitch < -1.0:
        sin_pitch = -1.0
    return heel, float(np.arcsin(sin_pitch)), float(np.arctan2(rot[1, 0], rot[0, 0]))


def observation_dict(body, current_body, rates, angles, wind, t, true_wind, apparent_wind_ce,
                     wrenches, position, velocity) -> dict:
    """The observation dict of measure(), keys in its order, from the measured values.

    Parameters
    ----------
    body : numpy.ndarray
        Body-frame velocity of CO (u, v, w), m/s.
    current_body : numpy.ndarray
        The water current in body axes, m/s.
    rates : numpy.ndarray
        Body angular velocity (p, q, r), rad/s.
    angles : tuple of float
        (yaw, heel, pitch, rudder, sail, heading, apparent wind angle, apparent wind speed),
        rad (the speed in m/s).
    wind : sailmujoco.forces.wind.WindField
        The world's wind (its configured speed, direction and current).
    t : float
        Simulated time, s.
    true_wind : numpy.ndarray
        World wind at the sail (east, north), m/s.
    apparent_wind_ce : numpy.ndarray
        Air velocity relative to the sail CE, body x-y, m/s.
    wrenches : dict
        ``"<key>_wrench"`` -> body-frame wrench (6,), in the order of :func:`wrench_rows`.
    position : numpy.ndarray
        World position (east, north) of CO, m.
    velocity : numpy.ndarray
        World velocity (east, north) of CO, m/s.

    Returns
    -------
    dict
        The observation, ``true_state`` nested.
    """
    yaw, heel, pitch, rudder, sail, heading, awa, aws = angles
    # every scalar a 0-d float64 array of its own (views into one array: one allocation)
    scalars = np.array([
        body[0], body[1], body[2], body[0] - current_body[0], body[1] - current_body[1],
        yaw, heel, pitch, rates[0], rates[1], rates[2], rudder, sail,
        wind.config.speed, wrap(wind.direction_from(t)), t,
        heading, heel, rates[0], rates[2], awa, aws])
    (u, v, w, u_r, v_r, yaw_, heel_, pitch_, p, q, r, rudder_, sail_, speed_10, direction, time_,
     heading_, heel_top, p_top, r_top, awa_, aws_) = [scalars[i, ...] for i in range(22)]
    true_state = {
        "u": u, "v": v, "w": w, "u_r": u_r, "v_r": v_r, "yaw": yaw_, "heel": heel_,
        "pitch": pitch_, "roll_rate": p, "pitch_rate": q, "yaw_rate": r, "rudder": rudder_,
        "sail": sail_, "true_wind": true_wind, "wind_speed_10": speed_10,
        "wind_direction": direction, "apparent_wind_ce": apparent_wind_ce,
        "current": np.array(wind.current[:2], dtype=np.float64), "time": time_}
    true_state.update(wrenches)
    return {
        "position": position, "velocity": velocity, "heading": heading_,
        "heel": heel_top, "roll_rate": p_top, "yaw_rate": r_top, "apparent_wind_angle": awa_,
        "apparent_wind_speed": aws_, "true_state": true_state}
