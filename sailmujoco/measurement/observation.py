"""Where a world's measurement becomes the observation: one place, for every world.

A world supplies its true state once per control step as a :class:`Truth`, its ``truth()``
(:class:`sailmujoco.tasks.world.World`): the MuJoCo boat in
:meth:`sailmujoco.measurement.accessors.BoatAccessors.truth`, Wille's 4-DOF paper world in
:meth:`sailmujoco.reference.wille.Wille4DOF.truth`, Viel's 3-DOF world in
:meth:`sailmujoco.reference.viel.VielWorld.truth`. Everything a task reads is made from it
here, by :func:`observation_and_record`:

* each key of the observation is one function of the truth, in :data:`OBSERVATION` (the keys
  the controllers read, ``controllers/base.py``) or :data:`TRUE_STATE` (the privileged
  ``true_state`` of the full-state controllers, followed by the world's force wrenches); a
  sensor model (noise, a lag, a vane at the masthead) is the function of its key, and a new
  measurement is one more entry (docs/architecture.md, "Add a measurement");
* the task's per-step record is :func:`record`.

:func:`measure` is the definition: the observation from a world's named accessors, which each
world's faster ``truth()`` gives bit for bit (``tests/test_measurement.py``; the worlds read one
rotation matrix and the arrays they hold, with the same numpy and MuJoCo functions where a
library computes a value, since numpy's SIMD transcendental functions need not agree with
``math``'s to the last bit).

A task hands its ``true_state`` out as a :class:`TrueState`: read by name like a dict, and one
float64 array to numpy and to dm_control (``dm_control.rl.control.flatten_observation``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from operator import attrgetter
from typing import NamedTuple

import mujoco
import numpy as np

from ..frames import wrap_angle
from ..jit.ordered import mat_t_vec

# force term of a world -> key of the observation's "<key>_wrench" (true_state)
WRENCH_KEYS = {"sail": "sail", "keel": "keel", "rudder": "rudder", "damping": "damping",
               "added_mass": "added_mass", "hydrostatics": "restoring", "restoring": "restoring"}
WRENCH_NAMES = ("sail", "keel", "rudder", "damping", "added_mass", "restoring")


class Truth(NamedTuple):
    """A world's true state at one instant, as its ``truth()`` supplies it (our frames: world x
    east, y north, z up; body x forward, y port, z up; SI).

    Parameters
    ----------
    time : float
        Simulated time, s.
    position : numpy.ndarray, shape (2,)
        World position (east, north) of CO, m.
    velocity : numpy.ndarray, shape (2,)
        World velocity (east, north) of CO over ground, m/s.
    body_velocity : numpy.ndarray, shape (3,)
        Body-frame velocity of CO (u, v, w), m/s.
    current_body : numpy.ndarray, shape (3,)
        The water current in body axes, m/s.
    rates : numpy.ndarray, shape (3,)
        Body angular velocity (p, q, r), rad/s.
    yaw : float
        ENU yaw, rad, counter-clockwise from east.
    heel : float
        Heel, rad, positive starboard down.
    pitch : float
        Pitch, rad, positive bow up.
    heading : float
        Compass heading, rad, clockwise from north, in [-pi, pi).
    rudder : float
        Rudder angle, rad, positive trailing edge to port.
    sail : float
        Sail (boom) angle, rad, positive trailing edge to port.
    apparent_wind_angle : float
        Apparent wind angle at the masthead, rad, positive from starboard.
    apparent_wind_speed : float
        Apparent wind speed at the masthead, body x-y plane, m/s.
    true_wind : numpy.ndarray, shape (2,)
        World wind at the sail (east, north), m/s.
    apparent_wind_ce : numpy.ndarray, shape (2,)
        Air velocity relative to the sail CE, body x-y, m/s.
    wind_speed_10 : float
        The wind's configured mean speed at 10 m, m/s.
    wind_direction_from : float
        Compass bearing the true wind comes from now, rad (not wrapped).
    current : numpy.ndarray, shape (2,)
        The water current (east, north), m/s.
    wrenches : dict
        ``"<key>_wrench"`` -> body-frame wrench (Fx, Fy, Fz, Mx, My, Mz) about CO, N and N m, in
        the order the observation lists them.
    """

    time: float
    position: np.ndarray
    velocity: np.ndarray
    body_velocity: np.ndarray
    current_body: np.ndarray
    rates: np.ndarray
    yaw: float
    heel: float
    pitch: float
    heading: float
    rudder: float
    sail: float
    apparent_wind_angle: float
    apparent_wind_speed: float
    true_wind: np.ndarray
    apparent_wind_ce: np.ndarray
    wind_speed_10: float
    wind_direction_from: float
    current: np.ndarray
    wrenches: dict


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

    The same numpy functions on the same numbers (np.clip keeps a NaN, as this does; the
    matrix's entries are read as Python floats, which numpy takes as the same float64).

    Parameters
    ----------
    rot : numpy.ndarray
        Body->world rotation matrix (3x3).

    Returns
    -------
    tuple of float
        (heel, pitch, yaw), rad.
    """
    return euler_of_entries(rot.ravel().tolist())


def euler_of_entries(entries: list) -> tuple[float, float, float]:
    """:func:`euler_of` of the rotation's 9 entries in row order, as Python floats (numpy takes
    them as the same float64 numbers).

    Parameters
    ----------
    entries : list of float
        R00, R01, R02, R10, ..., R22.

    Returns
    -------
    tuple of float
        (heel, pitch, yaw), rad.
    """
    r00, _, _, r10, _, _, sin_pitch, r21, r22 = entries
    heel = math.atan2(r21, r22)
    if sin_pitch > 1.0:
        sin_pitch = 1.0
    elif sin_pitch < -1.0:
        sin_pitch = -1.0
    return heel, math.asin(sin_pitch), math.atan2(r10, r00)


# key -> its value from the truth: a number (handed out as a 0-d float64 array) or a float64 array
Reading = Callable[[Truth], object]

OBSERVATION: dict[str, Reading] = {  # the keys the controllers read, in this order
    "position": attrgetter("position"),  # (2,) m, world east, north
    "velocity": attrgetter("velocity"),  # (2,) m/s over ground, world east, north
    "heading": attrgetter("heading"),  # rad, compass
    "heel": attrgetter("heel"),  # rad, starboard down
    "roll_rate": lambda truth: truth.rates[0],  # rad/s, body x
    "yaw_rate": lambda truth: truth.rates[2],  # rad/s, body z
    "apparent_wind_angle": attrgetter("apparent_wind_angle"),  # rad, from starboard positive
    "apparent_wind_speed": attrgetter("apparent_wind_speed"),  # m/s
}

TRUE_STATE: dict[str, Reading] = {  # the privileged true_state, then the world's wrenches
    "u": lambda truth: truth.body_velocity[0],
    "v": lambda truth: truth.body_velocity[1],
    "w": lambda truth: truth.body_velocity[2],
    "u_r": lambda truth: truth.body_velocity[0] - truth.current_body[0],  # through the water
    "v_r": lambda truth: truth.body_velocity[1] - truth.current_body[1],
    "yaw": attrgetter("yaw"),
    "heel": attrgetter("heel"),
    "pitch": attrgetter("pitch"),
    "roll_rate": lambda truth: truth.rates[0],
    "pitch_rate": lambda truth: truth.rates[1],
    "yaw_rate": lambda truth: truth.rates[2],
    "rudder": attrgetter("rudder"),
    "sail": attrgetter("sail"),
    "true_wind": attrgetter("true_wind"),
    "wind_speed_10": attrgetter("wind_speed_10"),
    "wind_direction": lambda truth: wrap_angle(truth.wind_direction_from),
    "apparent_wind_ce": attrgetter("apparent_wind_ce"),
    "current": attrgetter("current"),
    "time": attrgetter("time"),
}


# the built-in tables as this module defines them: observe() reads a truth by the fast path
# while the tables hold just these (a measurement added at run time takes the general one)
_BUILTIN_STATE, _BUILTIN_OBSERVATION = dict(TRUE_STATE), dict(OBSERVATION)
_STATE_KEYS, _OBSERVATION_KEYS = tuple(TRUE_STATE), tuple(OBSERVATION)  # the literals of _observe_builtin
_VIEWS = tuple((i, ...) for i in range(22))  # the 0-d views of the fast path's 22 numbers
_NUMBERS = frozenset((float, np.float64))  # what the fast path takes for a Truth's number


def builtin_tables() -> bool:
    """Whether :data:`OBSERVATION` and :data:`TRUE_STATE` hold just the built-in readers, in their
    order (no measurement added or replaced at run time): then the observation's fast paths, and
    the compiled closed loops (:mod:`sailmujoco.loop`), which write these readers out, apply."""
    return (TRUE_STATE == _BUILTIN_STATE and OBSERVATION == _BUILTIN_OBSERVATION
            and tuple(TRUE_STATE) == _STATE_KEYS and tuple(OBSERVATION) == _OBSERVATION_KEYS)


def observe(truth: Truth) -> dict:
    """The observation of a world's truth: each key of :data:`OBSERVATION`, then
    ``true_state`` (each key of :data:`TRUE_STATE`, then the world's wrenches).

    Every number becomes a 0-d float64 array of its own (views into one array: one allocation).

    Parameters
    ----------
    truth : Truth
        The world's true state now (its ``truth()``).

    Returns
    -------
    dict
        The observation, ``true_state`` nested.
    """
    if builtin_tables():
        observation = _observe_builtin(truth)
        if observation is not None:
            return observation
    return _observe_tables(truth)


def _observe_builtin(truth: Truth) -> dict | None:
    """:func:`_observe_tables` of the built-in tables, their readers written out: the same
    values, bit for bit, in the same order. None (the general path) for a truth of other types
    than floats and float64 arrays."""
    (t, position, velocity, body, current_body, rates, yaw, heel, pitch, heading, rudder, sail, awa,
     aws, true_wind, apparent_wind_ce, speed_10, direction_from, current, wrenches) = truth
    if not (_NUMBERS.issuperset(map(type, (t, yaw, heel, pitch, heading, rudder, sail, awa, aws, speed_10)))
            and np.ndarray is type(position) is type(velocity) is type(body) is type(current_body)
            is type(rates) is type(true_wind) is type(apparent_wind_ce) is type(current)):
        return None
    try:  # the entries as Python floats: the same float64 numbers, cheaper to pack
        (u, v, w), current_u, current_v = body.tolist(), current_body[0], current_body[1]
        roll_rate, pitch_rate, yaw_rate = rates.tolist()
        packed = np.array((u, v, w, u - current_u, v - current_v, yaw, heel, pitch, roll_rate, pitch_rate,
                           yaw_rate, rudder, sail, speed_10, wrap_angle(direction_from), t, heading, heel,
                           roll_rate, yaw_rate, awa, aws), dtype=np.float64)
    except (TypeError, ValueError):  # not a vector of 3 numbers: as the general path has it
        return None
    if packed.shape != (22,):
        return None
    n = [packed[index] for index in _VIEWS]
    true_state = {"u": n[0], "v": n[1], "w": n[2], "u_r": n[3], "v_r": n[4], "yaw": n[5], "heel": n[6],
                  "pitch": n[7], "roll_rate": n[8], "pitch_rate": n[9], "yaw_rate": n[10], "rudder": n[11],
                  "sail": n[12], "true_wind": true_wind, "wind_speed_10": n[13], "wind_direction": n[14],
                  "apparent_wind_ce": apparent_wind_ce, "current": current, "time": n[15], **wrenches}
    return {"position": position, "velocity": velocity, "heading": n[16], "heel": n[17], "roll_rate": n[18],
            "yaw_rate": n[19], "apparent_wind_angle": n[20], "apparent_wind_speed": n[21],
            "true_state": true_state}


def _observe_tables(truth: Truth) -> dict:
    """:func:`observe` by the tables: every reader of :data:`TRUE_STATE` and :data:`OBSERVATION`."""
    values = [read(truth) for read in TRUE_STATE.values()]
    n_state = len(values)
    values += [read(truth) for read in OBSERVATION.values()]
    packed = np.array([v for v in values if not isinstance(v, np.ndarray)], dtype=np.float64)
    views = iter([packed[i, ...] for i in range(len(packed))])
    values = [v if isinstance(v, np.ndarray) else next(views) for v in values]
    true_state = dict(zip(TRUE_STATE, values[:n_state], strict=True))
    true_state.update(truth.wrenches)
    observation = dict(zip(OBSERVATION, values[n_state:], strict=True))
    observation["true_state"] = true_state
    return observation


def record(truth: Truth) -> dict:
    """The task's per-step record of a world's truth: what the tasks' metrics read.

    Parameters
    ----------
    truth : Truth
        The world's true state now (its ``truth()``).

    Returns
    -------
    dict
        ``t`` (s), ``position`` (m, east and north), ``heading`` (rad, compass), ``heel`` (rad),
        ``roll_rate`` (rad/s), ``surge`` (m/s), ``course`` (rad, ENU) and ``speed`` (m/s, over
        ground).
    """
    velocity = truth.velocity
    east, north = velocity.tolist() if type(velocity) is np.ndarray else velocity  # the same float64s
    return {"t": truth.time, "position": truth.position.copy(), "heading": truth.heading,
            "heel": truth.heel, "roll_rate": float(truth.rates[0]), "surge": float(truth.body_velocity[0]),
            "course": float(math.atan2(north, east)), "speed": math.hypot(east, north)}


def observation_and_record(world) -> tuple[dict, dict]:
    """(observation, record) of a world now: what a task asks of it, from its ``truth()``.

    Parameters
    ----------
    world : sailmujoco.tasks.world.World
        The world (anything with a ``truth()`` that returns a :class:`Truth`).

    Returns
    -------
    observation : dict
        :func:`observe` of the truth (without the task's references).
    record : dict
        :func:`record` of the truth.
    """
    truth = world.truth()
    return observe(truth), record(truth)


def wrenches_of(terms: dict) -> dict:
    """The ``"<key>_wrench"`` entries of the observation from a world's force terms by name.

    Parameters
    ----------
    terms : dict
        Force term name -> body-frame wrench (6,) (a world's ``force_terms()``).

    Returns
    -------
    dict
        ``"<key>_wrench"`` -> float64 wrench, in the order of :func:`wrench_rows`; zeros for a
        wrench the world lacks.
    """
    out = {}
    for name, key in WRENCH_KEYS.items():
        if name in terms:
            out[f"{key}_wrench"] = np.asarray(terms[name], dtype=np.float64)
    for key in WRENCH_NAMES:
        out.setdefault(f"{key}_wrench", np.zeros(6))
    return out


def accessor_truth(world) -> Truth:
    """The truth of a world read from its named SI accessors: the definition that each world's
    faster ``truth()`` equals bit for bit.

    Parameters
    ----------
    world : object
        A world with the named accessors of :class:`sailmujoco.physics.BoatPhysics`
        (``rotation``, ``body_velocity``, ``heel``, ... ``force_terms``) and a ``wind``.

    Returns
    -------
    Truth
        The world's true state now.
    """
    rot = world.rotation()
    current = world.wind.current
    t = world.time()
    return Truth(
        time=t, position=np.asarray(world.position()[:2], dtype=np.float64),
        velocity=np.asarray(world.ground_velocity(), dtype=np.float64),
        body_velocity=world.body_velocity(), current_body=mat_t_vec(rot, current),
        rates=world.angular_velocity(), yaw=world.yaw(), heel=world.heel(), pitch=world.pitch(),
        heading=world.heading(), rudder=world.rudder_angle(), sail=world.sail_angle(),
        apparent_wind_angle=world.apparent_wind_angle(), apparent_wind_speed=world.apparent_wind_speed(),
        true_wind=np.asarray(world.sail_wind()[:2], dtype=np.float64),
        apparent_wind_ce=np.asarray(world.apparent_wind_ce()[:2], dtype=np.float64),
        wind_speed_10=world.wind.config.speed, wind_direction_from=world.wind.direction_from(t),
        current=np.array(current[:2], dtype=np.float64), wrenches=wrenches_of(world.force_terms()))


def measure(world) -> dict:
    """The observation of a world from its named accessors (:func:`accessor_truth`): the
    definition of the observation, which the worlds' own ``truth()`` gives by a faster path.

    Parameters
    ----------
    world : object
        A world with the named accessors of :class:`sailmujoco.physics.BoatPhysics` and a
        ``wind``.

    Returns
    -------
    dict
        The observation, ``true_state`` nested.
    """
    return observe(accessor_truth(world))
