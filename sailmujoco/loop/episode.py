"""Episodes run by a compiled closed loop where one exists, the Python path everywhere else.

:func:`run_compiled` takes an environment just reset (``suite.load(...).reset()``) and its
controller, finds whether a compiled loop covers them (:func:`compiled_loop`), runs it and
puts every object back in the state the Python path would have left it in: the world's state,
time and action, the controller's memory and ``info``, the task's records, the environment's
step count. It stops one half step short, before the record, reward and observation of the last
state, and hands that half step to the environment (``after_physics``), so the TimeStep the
caller continues from, and anything after it, is the Python path's own. The trajectory is the
same to the last bit (``tests/test_closed_loop.py``).

Covered today: Viel's position keeping in Viel's 3-DOF paper world
(:mod:`sailmujoco.loop.viel_paper`), with the boat's perfect instruments and actuators, the
built-in measurement tables and the suite's ``viel`` controller. Anything else (another task,
controller, world, instruments or a measurement added at run time) returns None, and the
caller steps in Python as before.
"""

from __future__ import annotations

import math

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
        ``loop(env, controller, n_steps) -> (taken, records, rewards)``.
    """
    import numba

    if numba.config.DISABLE_JIT:
        return None
    from ..forces.wind import WindField
    from ..measurement import observation
    from ..reference.viel import VielWorld
    from ..tasks.position import PositionKeeping
    from ..tasks.world import VielPhysics
    from ..controllers.factories import Bounded
    from ..controllers.viel import VielController

    physics, task = env.physics, env.task
    if not (type(physics) is VielPhysics and type(physics.world) is VielWorld and type(task) is PositionKeeping
            and type(controller) is Bounded and type(controller.controller) is VielController):
        return None
    world = physics.world
    if (world.integrator != "rk4" or type(world.wind) is not WindField or physics.stop_reason
            or not task.sensors.perfect or not task.actuators.perfect or task._servos is not None
            or task._instruments is not None or not task.include_true_state or env._flat_observation
            or env._reset_next_step or not observation.builtin_tables()):
        return None
    return _viel_paper


def run_compiled(env, controller, every: int = 0):
    """Run the episode of ``env`` (just reset) under ``controller`` by its compiled loop.

    Parameters
    ----------
    env : sailmujoco.tasks.environment.SailEnvironment
        The environment, reset, before its first step.
    controller : callable
        Its controller, reset.
    every : int
        Keep the trajectory sample of every ``every``-th step (0: none), as
        :func:`sailmujoco.sweep.runs.execute` keeps them.

    Returns
    -------
    tuple or None
        None when no compiled loop covers the pair (nothing has been touched); else (steps,
        samples, timestep): the control steps taken, the trajectory samples of steps 1 ..
        steps - 1, and the TimeStep of the last step taken (the Python path's own), from which
        the caller goes on.
    """
    loop = compiled_loop(env, controller)
    steps = env.steps_left()
    if loop is None or math.isinf(env._step_limit) or steps < MIN_STEPS:
        return None
    taken, records, _ = loop(env, controller, steps)
    if taken == 0:
        return None
    samples = []
    if every:
        for step in range(every, taken, every):
            t, x, y, heading, heel, _, surge, _, _ = records[step - 1].tolist()
            samples.append({"t": t, "x": x, "y": y, "heading": heading, "heel": heel, "pitch": 0.0, "u": surge})
    return taken, samples, env.after_physics()


def _viel_paper(env, controller, n_steps: int):
    """:func:`sailmujoco.loop.viel_paper.episode` on ``env``; every object synced after it."""
    from ..forces.wind import WANDER_DT
    from ..reference.integrators import steps_for
    from ..tasks.position import FAR
    from . import viel_paper

    physics, task = env.physics, env.task
    world, law, wind = physics.world, controller.controller, physics.world.wind
    dt = env._n_sub_steps * physics._dt  # VielPhysics.step's
    p = world.params
    wind.ensure(world.time + (n_steps + 2) * dt + 1.0)  # the wander the run reads, drawn up front
    packed = np.concatenate([world._packed(), [float(dt), float(steps_for(dt, world.max_step)), p.rudder_max,
                                               p.sail_max, world.wind_height]])
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
    state, action, time = np.empty(6), np.empty(4), np.empty(1)
    records, rewards, info = np.empty((n_steps, len(viel_paper.RECORD))), np.empty(n_steps), np.empty(5)
    taken = _EPISODE(n_steps, float(world.time), world._state.copy(), world._action.copy(), packed, numbers,
                     tables, law_numbers, bounds, task_numbers, memory, state, action, time, records, rewards,
                     info)
    if taken == 0:
        return 0, records, rewards
    # the objects as the Python path leaves them after `taken` steps, less the last half step
    world._state, world._time, world._action = state, float(time[0]), action[:2].copy()
    physics._control = action[2:].copy()
    law.sail, law.q = float(memory[0]), int(memory[3])
    law.v_previous = float(memory[2]) if memory[1] else None
    mode, theta_bar, vdot_star, vdot, distance = info.tolist()
    law.info = dict(mode=viel_paper.MODES[int(mode)], theta_bar=theta_bar, vdot_star=vdot_star, vdot=vdot,
                    q=law.q, distance=distance)
    task._records.extend(_record(row) for row in records[:taken - 1].tolist())
    task._measured = None
    env._step_count += taken - 1
    return taken, records, rewards


def _record(row: list) -> dict:
    """A record row (:data:`sailmujoco.loop.viel_paper.RECORD`) as ``SailTask.record`` gives it."""
    t, x, y, heading, heel, roll_rate, surge, course, speed = row
    return {"t": t, "position": np.array([x, y]), "heading": heading, "heel": heel, "roll_rate": roll_rate,
            "surge": surge, "course": course, "speed": speed}


class _Lazy:
    """The kernel's compiled entry point, built on first use (importing it compiles or loads it)."""

    def __init__(self):
        self._call = None

    def __call__(self, *args):
        if self._call is None:
            from . import viel_paper
            self._call = entry_point(viel_paper.episode)
        return self._call(*args)


_EPISODE = _Lazy()
