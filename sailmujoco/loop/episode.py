"""Episodes run by a compiled closed loop where one exists, the Python path everywhere else.

:func:`run_compiled` takes an environment just reset (``suite.load(...).reset()``) and its
controller, finds whether a compiled loop covers them (:func:`compiled_loop`), runs it and puts
every object back in the state the Python path would have left it in: the world's state, time
and action, the controller's memory and ``info``, the task's records, the environment's step
count. It stops one half step short, before the record, reward and observation of the last
state (or, where the physics stopped in the last step, before the stop's TimeStep), and hands
that half step to the environment, so the TimeStep the caller continues from, and everything
after it, is the Python path's own. The trajectory is the same to the last bit
(``tests/test_closed_loop.py``).

Covered today: Viel's position keeping under the suite's ``viel`` controller, in Viel's 3-DOF
paper world (:mod:`sailmujoco.loop.viel_world`) and on a 6-DOF MuJoCo boat stepped by RK4 with
an actuated sail (:mod:`sailmujoco.loop.mujoco_world`), with perfect instruments and actuators
and the built-in measurement tables. Anything else (another task, controller or world, 4 DOF,
instruments or servos as fitted, a measurement added at run time) returns None, and the caller
steps in Python as before.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ..jit.kernel import entry_point

MIN_STEPS = 2  # a compiled call for fewer steps than this saves nothing


def compiled_loop(env, controller):
    """The compiled loop that runs ``controller`` on ``env``, or None (the Python path).

    Parameters
    ----------
    env : sailmujoco.tasks.environment.SailEnvironment
        The environment (``suite.load``).
    controller : callable
        Its controller, as the sweep's controller factories build it.

    Returns
    -------
    callable or None
        ``loop(env, controller, n_steps) -> (taken, rows, rewards, actions, finish)``:
        ``finish()`` gives the TimeStep of the last step taken.
    """
    import numba

    if numba.config.DISABLE_JIT:
        return None
    from ..controllers.factories import Bounded
    from ..controllers.viel import VielController
    from ..forces.wind import WindField
    from ..measurement import observation
    from ..physics import RK4, BoatPhysics
    from ..reference.viel import VielWorld
    from ..tasks.base import SailTask
    from ..tasks.position import PositionKeeping
    from ..tasks.world import VielPhysics

    physics, task = env.physics, env.task
    # the task's hooks the loop writes out must be PositionKeeping's own (a subclass may place
    # the boat otherwise: the loop starts after the reset)
    hooks = ("reward_terms", "references", "record", "before_step", "after_step", "get_reward",
             "get_observation", "measurement", "get_termination", "reward_floor")
    if not (isinstance(task, PositionKeeping) and type(controller) is Bounded
            and type(controller.controller) is VielController
            and all(getattr(type(task), h) is getattr(PositionKeeping, h, getattr(SailTask, h, None))
                    for h in hooks)):
        return None
    if (not task.sensors.perfect or not task.actuators.perfect or task._servos is not None
            or task._instruments is not None or not task.include_true_state or env._flat_observation
            or not observation.builtin_tables()
            or getattr(physics, "stop_reason", None)):
        return None
    if type(physics) is VielPhysics:
        world = physics.world
        if type(world) is VielWorld and world.integrator == "rk4" and type(world.wind) is WindField:
            return _viel_world
        return None
    if (type(physics) is BoatPhysics and physics.dofs == 6 and physics.compiled_loop
            and physics.model.ptr.opt.integrator == RK4 and physics.model.nu == 2
            and physics.sail_mode == "actuated" and type(physics.wind) is WindField):
        return _mujoco_world
    return None


class CompiledEpisode(NamedTuple):
    """What :func:`run_compiled` hands back.

    Parameters
    ----------
    steps : int
        The control steps taken.
    rows : numpy.ndarray, shape (steps - 1, truth.SIZE)
        The truth (:mod:`sailmujoco.loop.truth`) of the state after each step but the last.
    rewards : numpy.ndarray, shape (steps - 1,)
        The reward of each of those states.
    actions : numpy.ndarray, shape (steps, 3)
        The command of every step (rudder, sail; ours, rad) and the controller's mode code
        (:data:`sailmujoco.loop.viel_control.MODES`).
    timestep : dm_env.TimeStep
        The TimeStep of the last step (the Python path's own), from which the caller goes on.
    """

    steps: int
    rows: np.ndarray
    rewards: np.ndarray
    actions: np.ndarray
    timestep: object


def run_compiled(env, controller) -> CompiledEpisode | None:
    """Run the episode of ``env`` (just reset) under ``controller`` by its compiled loop.

    Parameters
    ----------
    env : sailmujoco.tasks.environment.SailEnvironment
        The environment, reset, before its first step.
    controller : callable
        Its controller, reset.

    Returns
    -------
    CompiledEpisode or None
        None when no compiled loop covers the pair or it could not take a step (nothing has
        been touched: the caller steps in Python).
    """
    loop = compiled_loop(env, controller)
    if loop is None or env._reset_next_step or math.isinf(env._step_limit) or env.steps_left() < MIN_STEPS:
        return None
    taken, rows, rewards, actions, finish = loop(env, controller, env.steps_left())
    if taken == 0:
        return None
    return CompiledEpisode(taken, rows[:taken - 1], rewards[:taken - 1], actions[:taken], finish())


def trajectory_sample(row) -> dict:
    """The sweep runner's trajectory sample (``sweep.runs._trajectory_sample``) of a truth row."""
    from . import truth as T

    return {"t": float(row[T.TIME]), "x": float(row[T.X]), "y": float(row[T.Y]),
            "heading": float(row[T.HEADING]), "heel": float(row[T.HEEL]), "pitch": float(row[T.PITCH]),
            "u": float(row[T.U])}


def rollout_row(row) -> dict:
    """``suite.rollout``'s default row of a truth row: the same values by the same operations."""
    from . import truth as T

    heel = float(row[T.HEEL])
    return {"t": float(row[T.TIME]), "x": float(row[T.X]), "y": float(row[T.Y]),
            "heading": float(row[T.HEADING]), "heel": heel, "heel_deg": math.degrees(heel),
            "roll_rate": float(row[T.P]), "yaw_rate": float(row[T.R]), "u": float(row[T.U]),
            "v": float(row[T.V]), "speed": math.hypot(row[T.EAST], row[T.NORTH]),
            "rudder": float(row[T.RUDDER]), "sail": float(row[T.SAIL]), "awa": float(row[T.AWA]),
            "aws": float(row[T.AWS])}


def record(row: list) -> dict:
    """:func:`sailmujoco.measurement.observation.record` of a truth row (as a list of floats):
    the same values by the same operations."""
    from . import truth as T

    east, north = row[T.EAST], row[T.NORTH]
    return {"t": row[T.TIME], "position": np.array([row[T.X], row[T.Y]]), "heading": row[T.HEADING],
            "heel": row[T.HEEL], "roll_rate": row[T.P], "surge": row[T.U], "course": math.atan2(north, east),
            "speed": math.hypot(east, north)}


def _numbers(env, controller, wind):
    """The arrays the Viel loops take: wind numbers and tables, law, bounds, task, memory."""
    from ..forces.wind import WANDER_DT
    from ..tasks.position import FAR

    law, task = controller.controller, env.task
    c = wind.config
    numbers = np.array([c.speed, c.direction_from, c.direction_oscillation, c.oscillation_frequency, WANDER_DT],
                       dtype=np.float64)
    tables = (wind.oscillation, wind.gust_frequency, wind.gust_phase, wind.gust_amplitude, wind.log_z, wind.wander)
    target = (0.0, 0.0, 0.0) if law.target is None else (1.0, *law.target.tolist())
    law_numbers = np.array([*target, law.d_M, law.d_T, law.k_s, law.k_p, law.k_v, law.epsilon_sail,
                            law.epsilon_theta, law.delta, law.rudder_max, law.sail_max, law.dt])
    bounds = np.concatenate([controller.low, controller.high]).astype(np.float64)
    task_numbers = np.array([task.target[0], task.target[1], task.d_target, FAR], dtype=np.float64)
    memory = np.array([law.sail, 0.0 if law.v_previous is None else 1.0,
                       0.0 if law.v_previous is None else law.v_previous, float(law.q)])
    return numbers, tables, law_numbers, bounds, task_numbers, memory


def _sync_controller_and_task(env, controller, taken: int, rows, memory, info) -> None:
    """The controller's memory and info, the task's records and the step count after ``taken``
    steps, less the last half step."""
    from .viel_control import MODES

    law, task = controller.controller, env.task
    law.sail, law.q = float(memory[0]), int(memory[3])
    law.v_previous = float(memory[2]) if memory[1] else None
    mode, theta_bar, vdot_star, vdot, distance = info.tolist()
    law.info = dict(mode=MODES[int(mode)], theta_bar=theta_bar, vdot_star=vdot_star, vdot=vdot, q=law.q,
                    distance=distance)
    task._records.extend(record(row) for row in rows[:taken - 1].tolist())
    task._measured = None
    env._step_count += taken - 1


def _viel_world(env, controller, n_steps: int):
    """:func:`sailmujoco.loop.viel_world.episode` on ``env``; every object synced after it."""
    from ..reference.integrators import steps_for
    from . import truth as T
    from .viel_world import episode

    physics = env.physics
    world = physics.world
    dt = env._n_sub_steps * physics._dt  # VielPhysics.step's
    p = world.params
    world.wind.ensure(world.time + (n_steps + 2) * dt + 1.0)  # the wander the run reads, drawn up front
    packed = np.concatenate([world._packed(), [float(dt), float(steps_for(dt, world.max_step)), p.rudder_max,
                                               p.sail_max, world.wind_height]])
    numbers, tables, law, bounds, task, memory = _numbers(env, controller, world.wind)
    state, action, time = np.empty(6), np.empty(4), np.empty(1)
    rows, rewards, actions, info = _buffers(n_steps)
    taken = _call(episode)(n_steps, float(world.time), world._state.copy(), world._action.copy(), packed,
                           numbers, tables, law, bounds, task, memory, state, action, time, rows, rewards, actions,
                           info)
    if taken:
        world._state, world._time, world._action = state, float(time[0]), action[:2].copy()
        physics._control = action[2:].copy()
        _sync_controller_and_task(env, controller, taken, rows, memory, info)
    return taken, rows, rewards, actions, env.after_physics


def _mujoco_world(env, controller, n_steps: int):
    """:func:`sailmujoco.loop.mujoco_world.episode` on ``env``; every object synced after it."""
    import mujoco

    from ..forces import boat as kernels
    from ..step import native, registry
    from . import truth as T
    from .mujoco_world import episode

    physics = env.physics
    m, d = physics.model.ptr, physics.data.ptr
    n_sub = env._n_sub_steps
    physics._prepare((n_steps + 2) * n_sub * m.opt.timestep)  # the wander drawn up front, arrays bound
    numbers, tables, law, bounds, task, memory = _numbers(env, controller, physics.wind)
    rudder_at, _, sail_at, _ = physics._idx.tolist()
    site = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_SITE, "masthead")
    rows, rewards, actions, info = _buffers(n_steps)
    outcome = np.zeros(3, dtype=np.int64)
    with native.Stepping(d._address, physics._row) as slots:
        taken = _call(episode)(n_steps, m._address, d._address, n_sub, d.qpos, d.qvel, d.ctrl, d.site_xpos, site,
                               rudder_at, sail_at, registry.REGISTRY[slots[0]], physics._diag, physics._saved,
                               physics._warnings, physics._warnings_before, bool(physics._warnings_cause_exception),
                               numbers, tables, physics.wind.current, law, bounds, task, memory, rows, rewards,
                               actions, info, outcome)
    if not taken:
        return taken, rows, rewards, actions, None
    physics._status = int(outcome[2])
    _sync_controller_and_task(env, controller, taken, rows, memory, info)
    status, warned = int(outcome[0]), bool(outcome[1])
    if status != kernels.STATUS_OK:  # BoatPhysics._stop, then SailEnvironment.step's stopped step
        physics._record_stop(status)
    elif warned:  # BoatPhysics.step's PhysicsError
        physics._record_stop(kernels.STATUS_NONFINITE,
                             f"non-finite or out-of-range state ({physics._warnings_message()})")
    if physics.stop_reason is not None:
        physics._fresh = True  # the stop left it as the truth before the step made it
        return taken, rows, rewards, actions, lambda: env.stopped_step(physics.stop_reason)
    physics._fresh = False
    return taken, rows, rewards, actions, env.after_physics


def _buffers(n_steps: int) -> tuple:
    """What a loop fills: the truth rows, rewards, actions (with modes) and the law's info."""
    from . import truth as T

    return np.empty((n_steps, T.SIZE)), np.empty(n_steps), np.empty((n_steps, 3)), np.empty(5)


_ENTRIES: dict = {}


def _call(kernel):
    """A kernel's compiled entry point, built on first use (its first call compiles or loads it)."""
    if kernel not in _ENTRIES:
        _ENTRIES[kernel] = entry_point(kernel)
    return _ENTRIES[kernel]
