"""The Gymnasium adapter's spaces: the observation's bounds (its envelope), the observation as
Gymnasium hands it out, and the action's mapping onto the actuators.

Every bounded quantity has its bound for a physical reason, given with it below
(:data:`BOUNDS`); the table of :mod:`sailmujoco.gym` lists them with their units. A state
outside these bounds ends the episode, as a capsize does (:func:`outside`), so every
observation an episode hands out lies in its declared space.
"""

from __future__ import annotations

import math

import numpy as np
from gymnasium import spaces

from .forces.wind import MAX_SPEED

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


def bounds(area: float, time: float) -> dict[str, tuple[float, float]]:
    """:data:`BOUNDS` with the sailing area and the time bound filled in.

    Parameters
    ----------
    area : float
        Half-width of the square sailing area around the origin, m.
    time : float
        The latest time an episode reaches, s.
    """
    fill = {"area": area, "-area": -area, "time": time}
    return {key: (fill.get(low, low), fill.get(high, high)) for key, (low, high) in BOUNDS.items()}


def observation_space(spec, limits: dict, path: str = "") -> spaces.Dict:
    """The float32 ``Dict`` space of an observation spec (nested for ``true_state``); a key
    without a bound (a user's task reference, a force wrench) is unbounded.

    Parameters
    ----------
    spec : dict
        The dm_env observation spec.
    limits : dict
        Key path -> (low, high), from :func:`bounds`.
    path : str
        The spec's own path (for the nested ``true_state``).
    """
    if isinstance(spec, dict):
        return spaces.Dict({key: observation_space(value, limits, f"{path}{key}.")
                            for key, value in spec.items()})
    low, high = limits.get(path[:-1], (-np.inf, np.inf))
    return spaces.Box(np.float32(low), np.float32(high), shape=spec.shape, dtype=np.float32)


def _wrap(value: np.ndarray) -> np.ndarray:
    return (value + PI) % (2.0 * PI) - PI


def gym_observation(observation, space: spaces.Dict, path: str = "") -> dict:
    """The observation as the space declares it: float32 arrays, angle references and the yaw
    wrapped, every number clipped into its bounds (which changes only the last observation of
    an episode that left them, see :func:`outside`).

    Parameters
    ----------
    observation : dict
        The dm_env observation.
    space : gymnasium.spaces.Dict
        Its space (:func:`observation_space`).
    path : str
        The observation's own path (for the nested ``true_state``).
    """
    out = {}
    for key, box in space.spaces.items():
        value = observation[key]
        if isinstance(box, spaces.Dict):
            out[key] = gym_observation(value, box, f"{path}{key}.")
            continue
        value = np.array(value, dtype=np.float64)
        if f"{path}{key}" in WRAPPED:
            value = _wrap(value)
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
            value = _wrap(value)
        if not np.all((value >= low) & (value <= high)):  # NaN is outside too
            if top in ("position", "target_position"):
                return f"left the sailing area (|x| or |y| > {high:g} m)"
            return f"left the observation bounds ({key} outside [{low:g}, {high:g}])"
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
