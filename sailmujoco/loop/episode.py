"""Episodes run by a compiled closed loop where a controller offers one, the Python path elsewhere.

The protocol: a controller that can run a whole episode in compiled code has a method
``compiled_episode(env) -> CompiledEpisode or None``. :func:`run_compiled` (which
``suite.rollout``, the sweep runner and the studies call after ``env.reset()``) calls it when the
episode allows one (:meth:`~sailmujoco.tasks.environment.SailEnvironment.compiled_steps`); None
means "not this pair" and nothing has been touched, so the caller steps in Python as before.

A compiled episode takes the steps the Python path would, in its order, and then puts every
object back in the state that path leaves: the world (``closed_loop_ended`` of
:class:`~sailmujoco.tasks.world.VielPhysics` and :func:`sailmujoco.step.closed_loop.closed_loop_ended`),
the controller's memory, the task's records and the environment's step count
(:func:`finish`). It stops one half step short, before the record, reward and observation of
the last state (or before the stop's TimeStep, where the physics stopped in the last step), and
hands that half step to the environment, so the TimeStep the caller goes on from, and everything
after it, is the Python path's own. The loops' trajectories are the Python path's to the last bit
(``tests/test_closed_loop.py``).

The pieces a compiled episode is built from: :mod:`sailmujoco.loop.truth` (each world's truth),
:mod:`sailmujoco.loop.worlds` (each world's control step), :mod:`sailmujoco.loop.position_task`
(a task's reward); the controller brings its law (``controllers/viel_loop.py``: Viel's).
"""

from __future__ import annotations

import math
import os
from typing import NamedTuple

import numpy as np

from . import truth as T

MIN_STEPS = 2  # a compiled call for fewer steps than this saves nothing


class CompiledEpisode(NamedTuple):
    """What a compiled episode hands back.

    Parameters
    ----------
    steps : int
        The control steps taken.
    rows : numpy.ndarray, shape (steps - 1, truth.SIZE)
        The truth (:mod:`sailmujoco.loop.truth`) of the state after each step but the last.
    rewards : numpy.ndarray, shape (steps - 1,)
        The reward of each of those states.
    actions : numpy.ndarray, shape (steps, 3)
        The command of every step (rudder, sail; ours, rad) and the controller's mode code.
    timestep : dm_env.TimeStep
        The TimeStep of the last step (the Python path's own), from which the caller goes on.
    """

    steps: int
    rows: np.ndarray
    rewards: np.ndarray
    actions: np.ndarray
    timestep: object


def run_compiled(env, controller) -> CompiledEpisode | None:
    """Run the episode of ``env`` (just reset) under ``controller`` by its compiled loop, if the
    controller offers one for this environment.

    Parameters
    ----------
    env : sailmujoco.tasks.environment.SailEnvironment
        The environment, reset, before its first step.
    controller : callable
        Its controller, reset.

    Returns
    -------
    CompiledEpisode or None
        None when the controller offers no compiled loop for the pair, it could not take a step,
        or ``SAILMUJOCO_PYTHON_LOOP=1`` is set (nothing has been touched: the caller steps in
        Python).
    """
    if os.environ.get("SAILMUJOCO_PYTHON_LOOP") == "1":  # the Python path everywhere, to compare
        return None
    offer = getattr(controller, "compiled_episode", None)
    if offer is None or not hasattr(env, "compiled_steps") or env.compiled_steps() < MIN_STEPS:
        return None
    return offer(env)


def buffers(n_steps: int) -> tuple:
    """What a compiled episode fills: the truth rows, rewards, actions (with modes), and 5 numbers
    of the controller's last call.

    Parameters
    ----------
    n_steps : int
        The control steps the episode may take.
    """
    return np.empty((n_steps, T.SIZE)), np.empty(n_steps), np.empty((n_steps, 3)), np.empty(5)


def finish(env, taken: int, rows, rewards, actions, stop_reason: str | None = None) -> CompiledEpisode:
    """The task's records and the step count after ``taken`` compiled steps, then the last half
    step by the environment: its TimeStep after the step (or the stop's, for ``stop_reason``).

    Parameters
    ----------
    env : sailmujoco.tasks.environment.SailEnvironment
        The environment; its world already brought up to date.
    taken : int
        The control steps taken, >= 1.
    rows, rewards, actions : numpy.ndarray
        As :func:`buffers` gave them, filled.
    stop_reason : str, optional
        Why the physics stopped in the last step, if it did.
    """
    env.task.add_records(record(row) for row in rows[:taken - 1].tolist())
    env.count_steps(taken - 1)
    timestep = env.after_physics() if stop_reason is None else env.stopped_step(stop_reason)
    return CompiledEpisode(taken, rows[:taken - 1], rewards[:taken - 1], actions[:taken], timestep)


def record(row: list) -> dict:
    """:func:`sailmujoco.measurement.observation.record` of a truth row (as a list of floats):
    the same values by the same operations.

    Parameters
    ----------
    row : sequence of float
        The truth of a state (:mod:`sailmujoco.loop.truth`).
    """
    east, north = row[T.EAST], row[T.NORTH]
    return {"t": row[T.TIME], "position": np.array([row[T.X], row[T.Y]]), "heading": row[T.HEADING],
            "heel": row[T.HEEL], "roll_rate": row[T.P], "surge": row[T.U], "course": math.atan2(north, east),
            "speed": math.hypot(east, north)}


def trajectory_sample(row) -> dict:
    """The sweep runner's trajectory sample (``sweep.runs._trajectory_sample``) of a truth row.

    Parameters
    ----------
    row : sequence of float
        The truth of a state (:mod:`sailmujoco.loop.truth`).
    """
    return {"t": float(row[T.TIME]), "x": float(row[T.X]), "y": float(row[T.Y]),
            "heading": float(row[T.HEADING]), "heel": float(row[T.HEEL]), "pitch": float(row[T.PITCH]),
            "u": float(row[T.U])}


def rollout_row(row) -> dict:
    """``suite.rollout``'s default row of a truth row: the same values by the same operations.

    Parameters
    ----------
    row : sequence of float
        The truth of a state (:mod:`sailmujoco.loop.truth`).
    """
    heel = float(row[T.HEEL])
    return {"t": float(row[T.TIME]), "x": float(row[T.X]), "y": float(row[T.Y]),
            "heading": float(row[T.HEADING]), "heel": heel, "heel_deg": math.degrees(heel),
            "roll_rate": float(row[T.P]), "yaw_rate": float(row[T.R]), "u": float(row[T.U]),
            "v": float(row[T.V]), "speed": math.hypot(row[T.EAST], row[T.NORTH]),
            "rudder": float(row[T.RUDDER]), "sail": float(row[T.SAIL]), "awa": float(row[T.AWA]),
            "aws": float(row[T.AWS])}


def wind_arguments(wind) -> tuple:
    """A :class:`~sailmujoco.forces.wind.WindField` as the loops read it: (numbers, tables), the
    numbers U_m10, mean bearing, direction oscillation, its frequency, the wander's time step,
    the tables its oscillation, gust frequency, phase, amplitude, log_z and wander.

    Parameters
    ----------
    wind : sailmujoco.forces.wind.WindField
        The wind, its wander drawn for the whole run.
    """
    from ..forces.wind import WANDER_DT

    c = wind.config
    numbers = np.array([c.speed, c.direction_from, c.direction_oscillation, c.oscillation_frequency,
                        WANDER_DT], dtype=np.float64)
    return numbers, (wind.oscillation, wind.gust_frequency, wind.gust_phase, wind.gust_amplitude, wind.log_z,
                     wind.wander)
