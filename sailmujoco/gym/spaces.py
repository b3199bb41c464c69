"""The Gymnasium adapter's spaces: the observation's bounds (its envelope), the observation as
Gymnasium hands it out, and the action's mapping onto the actuators.

Every quantity has its bound for a physical reason, given with it below (:data:`BOUNDS`,
:func:`wrench_bound`); the table of :mod:`sailmujoco.gym` lists them with their units. A
state outside these bounds ends the episode, as a capsize does (:func:`outside`), so every
observation an episode hands out lies in its declared space.

The layout is the one RL libraries take as it is (Stable-Baselines3's ``check_env`` and its
``MultiInputPolicy``, which read each key as a 1-D vector and refuse nested Dicts): one flat
``Dict`` of 1-D float32 ``Box`` es, a scalar as shape ``(1,)``, and the privileged true state's
keys at the top level as ``true_state_<key>``. The dm_env side keeps dm_control's own
conventions (scalars of shape ``()``, ``true_state`` nested).
"""

from __future__ import annotations

import math

import numpy as np
from gymnasium import spaces

from ..constants import RHO_WATER
from ..forces.wind import MAX_SPEED
from ..frames import wrap_angle

PI = math.pi
MAX_BOAT_SPEED = 50.0  # m/s: above the sailing speed record, 65.45 kn = 33.7 m/s (Sailrocket 2, 2012)
MAX_AIR_SPEED = 340.0  # m/s: the speed of sound at sea level; the force models are incompressible
MAX_RATE = 25.0  # rad/s, four turns a second: a capsize under an absurd heeling moment reaches 11
DEFAULT_AREA = 5000.0  # m: half-width of the default sailing area around the origin

# key path -> (low, high); "area" and "time" stand for the sailing area and the time bound
BOUNDS = {
    "position": ("-area", "area"),
    "velocity": (-MAX_BOAT_SPEED, MAX_BOAT_SPEED),
    "heading": (-PI, PI),
    "heel": (-PI, PI),
    "roll_rate": (-MAX_RATE, MAX_RATE),
    "yaw_rate": (-MAX_RATE, MAX_RATE),
    "apparent_wind_angle": (-PI, PI),
    "apparent_wind_speed": (0.0, MAX_AIR_SPEED),
    "desired_heading": (-PI, PI),
    "desired_course": (-PI, PI),
    "target_position": ("-area", "area"),
    "last_mark": ("-area", "area"),
    "next_mark": ("-area", "area"),
    "box_center": ("-area", "area"),
    "box_time_left": ("-time", "time"),
    "area_center": ("-area", "area"),
    "area_half": (0.0, "area"),
    "speed_through_water": (-MAX_BOAT_SPEED, MAX_BOAT_SPEED),  # instruments: a log's reading
    "true_wind_estimate": (-MAX_AIR_SPEED, MAX_AIR_SPEED),  # instruments: speed m/s, direction rad
    **{f"true_state.{key}": (-MAX_BOAT_SPEED, MAX_BOAT_SPEED) for key in ("u", "v", "w", "u_r", "v_r")},
    "true_state.yaw": (-PI, PI),
    "true_state.heel": (-PI, PI),
    "true_state.pitch": (-PI / 2, PI / 2),
    **{f"true_state.{key}": (-MAX_RATE, MAX_RATE) for key in ("roll_rate", "pitch_rate", "yaw_rate")},
    "true_state.rudder": (-2.0 * PI, 2.0 * PI),  # joint angles: within +-pi, soft limits pass a little
    "true_state.sail": (-2.0 * PI, 2.0 * PI),
    "true_state.true_wind": (-MAX_AIR_SPEED, MAX_AIR_SPEED),
    "true_state.wind_speed_10": (0.0, MAX_SPEED),
    "true_state.wind_direction": (-PI, PI),
    "true_state.apparent_wind_ce": (-MAX_AIR_SPEED, MAX_AIR_SPEED),
    "true_state.current": (-MAX_BOAT_SPEED, MAX_BOAT_SPEED),
    "true_state.time": (0.0, "time"),
}
# angles handed out wrapped to [-pi, pi) (the others are wrapped already, or a heel that is not)
WRAPPED = ("desired_heading", "desired_course", "true_state.yaw")


def bounds(area: float, time: float, length: float, wrenches=()) -> dict:
    """:data:`BOUNDS` with the sailing area and the time bound filled in, and the wrenches'.

    Parameters
    ----------
    area : float
        Half-width of the square sailing area around the origin, m.
    time : float
        The latest time an episode reaches, s.
    length : float
        The hull's length, m (:func:`wrench_bound`).
    wrenches : iterable of str
        The true state's ``<term>_wrench`` keys.
    """
    fill = {"area": area, "-area": -area, "time": time, "-time": -time}
    limits = {key: (fill.get(low, low), fill.get(high, high)) for key, (low, high) in BOUNDS.items()}
    high = wrench_bound(length)
    limits.update({f"true_state.{key}": (-high, high) for key in wrenches})
    return limits


def wrench_bound(length: float) -> np.ndarray:
    """The bound of a force model's wrench (Fx, Fy, Fz, Mx, My, Mz) inside the envelope, N and N m.

    A fluid force is a coefficient times the dynamic pressure times an area. Inside the
    envelope the water meets the boat at most at :data:`MAX_BOAT_SPEED` (air, at the speed of
    sound, carries 1/1000 the pressure per unit of speed squared), every coefficient of the
    force models is below 2 and every area of the boat (wetted hull, keel, rudder, sail) below
    ``length**2``, so a force is below ``rho_w V_max**2 length**2`` (twice the dynamic pressure
    on ``length**2``) and a moment about the CO below that force times ``length``. The weight
    and the buoyancy are far below it (6e5 times less for a 1.5 m boat).

    Parameters
    ----------
    length : float
        The hull's length, m.
    """
    force = RHO_WATER * MAX_BOAT_SPEED**2 * length**2
    return np.array([force] * 3 + [force * length] * 3)


def flat_items(tree, path: str = ""):
    """``(gym key, key path, leaf)`` for every leaf of an observation or its spec: a nested key
    ``true_state.u`` becomes the top-level ``true_state_u``.

    Parameters
    ----------
    tree : dict
        The dm_env observation, or its spec.
    path : str
        The tree's own path (for the nested ``true_state``).
    """
    for key, value in tree.items():
        if isinstance(value, dict):
            yield from flat_items(value, f"{path}{key}.")
        else:
            yield f"{path}{key}".replace(".", "_"), f"{path}{key}", value


def observation_space(spec, limits: dict) -> spaces.Dict:
    """The flat float32 ``Dict`` space of an observation spec: 1-D ``Box`` es (a scalar has shape
    ``(1,)``), the true state's keys as ``true_state_<key>``; a key without a bound (a user's
    task reference) is unbounded.

    Parameters
    ----------
    spec : dict
        The dm_env observation spec.
    limits : dict
        Key path -> (low, high), from :func:`bounds`.
    """
    boxes = {}
    for key, path, leaf in flat_items(spec):
        low, high = limits.get(path, (-np.inf, np.inf))
        shape = leaf.shape if leaf.shape else (1,)
        boxes[key] = spaces.Box(np.broadcast_to(np.float32(low), shape),
                                np.broadcast_to(np.float32(high), shape), shape=shape, dtype=np.float32)
    return spaces.Dict(boxes)


def gym_observation(observation, space: spaces.Dict) -> dict:
    """The observation as the space declares it: flat, 1-D float32 arrays, angle references and
    the yaw wrapped, every number clipped into its bounds (which changes only the last
    observation of an episode that left them, see :func:`outside`).

    Parameters
    ----------
    observation : dict
        The dm_env observation.
    space : gymnasium.spaces.Dict
        Its space (:func:`observation_space`).
    """
    out = {}
    for key, path, value in flat_items(observation):
        box = space.spaces[key]
        value = np.array(value, dtype=np.float64).reshape(box.shape)
        if path in WRAPPED:
            value = wrap_angle(value)
        out[key] = np.asarray(np.clip(value.astype(np.float32), box.low, box.high), dtype=np.float32)
    return out


def outside(measured: dict, limits: dict) -> str | None:
    """Why a measurement is outside the envelope (its first quantity out of bounds), or None.

    Parameters
    ----------
    measured : dict
        The task's whole measurement (with ``true_state``), as its reward reads it.
    limits : dict
        Key path -> (low, high), from :func:`bounds`.
    """
    for key, (low, high) in limits.items():
        top, _, sub = key.partition(".")
        value = measured.get(top)
        if sub and value is not None:
            value = value.get(sub)
        if value is None:
            continue
        value = np.asarray(value, dtype=np.float64)
        if key in WRAPPED:
            value = wrap_angle(value)
        if not np.all((value >= low) & (value <= high)):  # NaN is outside too
            if top in ("position", "target_position", "last_mark", "next_mark", "box_center", "area_center"):
                return f"left the sailing area (|x| or |y| > {high:g} m)"
            low, high = (np.array2string(np.asarray(b), precision=3) if np.ndim(b) else f"{b:g}"
                         for b in (low, high))
            return f"left the observation bounds ({key} outside [{low}, {high}])"
    return None


def actuator_command(action, low: np.ndarray, high: np.ndarray, normalized: bool) -> np.ndarray:
    """The command the actuators get for ``action``: the action itself, or, normalised,
    ``low + (clip(a, -1, 1) + 1) / 2 * (high - low)``.

    Parameters
    ----------
    action : array_like
        The action, shape (2,).
    low, high : numpy.ndarray
        The actuators' ranges (rad, or m for a sheet).
    normalized : bool
        Whether ``action`` is in [-1, 1].
    """
    action = np.asarray(action, dtype=np.float64)
    if not normalized:
        return action
    return low + (np.clip(action, -1.0, 1.0) + 1.0) * 0.5 * (high - low)
