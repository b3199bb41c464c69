"""Viel's position keeping as a compiled closed loop (``sailmujoco.loop``): the whole episode in
one native call, step for step the Python path (:class:`controllers.viel.VielController` on
``position_keeping``), equal to it to the last bit (``tests/test_closed_loop.py``).

* :func:`viel_command`: the controller's view of the observation (``viel_view``), its call
  (``VielController.__call__``) and the suite's clip (``Bounded``), read from the truth vector of
  :mod:`sailmujoco.loop.truth`. The law's functions are :mod:`controllers.viel_law`'s own, compiled
  from the same source (``numba.extending.register_jitable``); Python's ``math.hypot`` is
  :func:`sailmujoco.reference.hypot.hypot`, CPython's to the bit.
* :func:`paper_episode` (Viel's 3-DOF world) and :func:`boat_episode` (a 6-DOF MuJoCo boat): the
  loop: the truth of the state, its record row and reward, the command, the world's step.
* :func:`compiled_episode`: what ``VielController.compiled_episode`` runs: which pairs it covers,
  the arguments, and every object brought up to date afterwards (:func:`sailmujoco.loop.episode.finish`).

Where the Python path would raise (a non-finite observation or command, the paper world's domain
check or an integration that runs away) the loop stops *before* that step's action; where the
boat stops in a step (capsize, a non-finite state, MuJoCo's warnings) it stops *after* it; the
Python path then takes over, in its own words.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from sailmujoco.forces.boat import STATUS_OK as BOAT_OK
from sailmujoco.frames import wrap_angle
from sailmujoco.jit.kernel import clear_stale_cache, kernel
from sailmujoco.loop import truth as T
from sailmujoco.loop.episode import buffers, finish, wind_arguments
from sailmujoco.loop.position_task import covers, position_reward, task_numbers
from sailmujoco.loop.worlds import mujoco_step, viel_step
from sailmujoco.reference.hypot import hypot
from sailmujoco.reference.integrators import STATUS_OK as WORLD_OK
from sailmujoco.step.closed_loop import closed_loop, closed_loop_ended, closed_loop_ready
from sailmujoco.step.mujoco_calls import pointer

from . import viel_law
from .viel_law import (
    adaptive_sail,
    desired_acceleration,
    go_round,
    optimal_sail,
    rudder_law,
    sail_limit,
    sign,
    tack,
)

# the kernels below inline the Viel law's module: their cache is emptied when it changes too
clear_stale_cache(__file__, Path(viel_law.__file__))

MODES = (viel_law.GO_DIRECT, viel_law.GO_ROUND, viel_law.TACK, viel_law.UPWIND_STOP,  # by code
         viel_law.UPWIND_DRIVE)
_DIRECT, _ROUND, _TACK, _STOP, _DRIVE = range(5)
OK, REJECTED, NON_FINITE_COMMAND = 0, 1, 2  # viel_command's outcomes


@kernel(inline=True)
def viel_command(truth, target_x, target_y, law, bounds, memory, info, command):
    """The clipped command [rudder, sail] (ours, rad) for the state of ``truth`` into ``command``.

    Parameters
    ----------
    truth : numpy.ndarray
        The truth of the state (:mod:`sailmujoco.loop.truth`).
    target_x, target_y : float
        The task's target (``target_position``), m.
    law : numpy.ndarray, shape (14,)
        The controller's numbers: own target or not (1/0), x_T, y_T (m), d_M, d_T (m), k_s, k_p,
        k_v, epsilon_sail, epsilon_theta, delta, rudder_max, sail_max (rad), dt (s).
    bounds : numpy.ndarray, shape (4,)
        The clip of the command: low rudder, low sail, high rudder, high sail (rad).
    memory : numpy.ndarray, shape (4,)
        The controller's memory, updated: last sail (Viel sign), previous speed known (1/0),
        the previous speed, the tack q.
    info : numpy.ndarray, shape (5,)
        Receives the controller's ``info`` of its last call: mode code (:data:`MODES`),
        theta_bar, vdot*, vdot, distance.
    command : numpy.ndarray, shape (2,)
        Receives the command.

    Returns
    -------
    int
        OK; REJECTED where ``viel_view`` raises (nothing changed); NON_FINITE_COMMAND where the
        task's action check raises (``memory`` put back).
    """
    own_target, x_T, y_T, d_M, d_T = law[0] != 0.0, law[1], law[2], law[3], law[4]
    k_s, k_p, k_v, epsilon_sail, epsilon_theta, delta = law[5], law[6], law[7], law[8], law[9], law[10]
    rudder_max, sail_max, dt = law[11], law[12], law[13]
    x, y, east, north = truth[T.X], truth[T.Y], truth[T.EAST], truth[T.NORTH]  # viel_view
    tx, ty = (x_T, y_T) if own_target else (target_x, target_y)
    theta = wrap_angle(math.pi / 2.0 - truth[T.HEADING])
    c, s = math.cos(theta), math.sin(theta)
    phi, v, u = math.atan2(north, east), east * c + north * s, -east * s + north * c
    omega, a_aw = truth[T.R], truth[T.AWS]
    psi_aw = wrap_angle(math.pi - truth[T.AWA])
    psi_tw = wrap_angle(-0.5 * math.pi - wrap_angle(truth[T.DIRECTION_FROM]))
    for value in (x, y, theta, phi, v, u, omega, a_aw, psi_aw, psi_tw, tx, ty):
        if not math.isfinite(value):
            return REJECTED
    kept = memory.copy()  # VielController.__call__
    vdot = 0.0 if memory[1] == 0.0 else (v - memory[2]) / dt
    memory[1], memory[2] = 1.0, v
    dx, dy = tx - x, ty - y
    distance = hypot(dx, dy)
    vdot_star, q = math.nan, int(memory[3])
    if distance < d_T:  # Viel §4.3 step 4: upwind strategy in the target area
        if v > 0.0:
            mode, theta_bar = _STOP, psi_tw + math.pi  # Viel eq. 19
            sail = -sign(psi_aw) * sail_limit(psi_aw, sail_max)  # Viel eq. 20 (bounded)
        else:
            mode, theta_bar = _DRIVE, psi_tw + math.pi - delta * sign(u)  # Viel eq. 21
            lim = max(sail_limit(psi_aw, sail_max) - epsilon_sail, 0.0)
            sail = -sign(psi_aw) * min(abs(optimal_sail(psi_tw, theta_bar)), lim)  # Viel eq. 22
    else:
        theta_star = math.atan2(dy, dx)  # Viel step 1: direct path
        alpha = math.atan2(-dy, -dx)
        theta_star, turned = go_round(theta_star, alpha, psi_tw, distance, d_T, d_M)
        theta_bar, q, dead = tack(theta_star, psi_tw, delta, q)
        mode = _ROUND if turned else (_TACK if dead else _DIRECT)
        vdot_star = desired_acceleration(v, u, theta, alpha, distance, k_v, k_p)
        sail = adaptive_sail(memory[0], vdot_star, vdot, psi_aw, psi_tw, theta_bar, k_s, dt, epsilon_sail,
                             sail_max)
    theta_bar = wrap_angle(theta_bar)
    rudder = rudder_law(theta, phi, theta_bar, rudder_max, epsilon_theta)
    memory[0], memory[3] = sail, float(q)
    command[0] = min(max(-rudder, bounds[0]), bounds[2])  # action_from_viel, then Bounded's clip
    command[1] = min(max(-sail, bounds[1]), bounds[3])
    if not (math.isfinite(command[0]) and math.isfinite(command[1])):
        memory[:] = kept
        return NON_FINITE_COMMAND
    info[0], info[1], info[2], info[3], info[4] = mode, theta_bar, vdot_star, vdot, distance
    return OK


@kernel
def paper_episode(n_steps, t0, state, applied, world, wind, tables, law, bounds, task, memory, command,
                  time_out, rows, rewards, actions, info):
    """Up to ``n_steps`` control steps in Viel's world.

    Parameters
    ----------
    n_steps : int
        Control steps to take at most.
    t0 : float
        Time of the start, s.
    state : numpy.ndarray, shape (6,)
        Viel's state at the start; the last step's on return.
    applied : numpy.ndarray, shape (2,)
        The world's applied action at the start; the last step's on return (ours, rad).
    world : numpy.ndarray
        :meth:`sailmujoco.reference.viel.VielWorld.loop_arguments`' numbers.
    wind : numpy.ndarray, shape (5,)
        The loops' wind numbers (:func:`sailmujoco.loop.episode.wind_arguments`).
    tables : tuple of numpy.ndarray
        The wind's tables (the same).
    law : numpy.ndarray, shape (14,)
        The controller's numbers: own target or not (1/0), x_T, y_T (m), d_M, d_T (m), k_s, k_p,
        k_v, epsilon_sail, epsilon_theta, delta, rudder_max, sail_max (rad), dt (s).
    bounds : numpy.ndarray, shape (4,)
        The clip of the command: low rudder, low sail, high rudder, high sail (rad).
    memory : numpy.ndarray, shape (4,)
        The controller's memory, updated: last sail (Viel sign), previous speed known (1/0),
        the previous speed, the tack q.
    info : numpy.ndarray, shape (5,)
        Receives the controller's ``info`` of its last call: mode code (:data:`MODES`),
        theta_bar, vdot*, vdot, distance.
    task : numpy.ndarray, shape (4,)
        The task's numbers (:func:`sailmujoco.loop.position_task.task_numbers`).
    rows : numpy.ndarray, shape (n_steps, truth.SIZE)
        Row k: the truth of the state after step k.
    rewards : numpy.ndarray, shape (n_steps,)
        Entry k: the reward of the state after step k.
    actions : numpy.ndarray, shape (n_steps, 3)
        Row k: step k's command (ours, rad) and mode code.
    command : numpy.ndarray, shape (2,)
        Receives the last step's command.
    time_out : numpy.ndarray, shape (1,)
        Receives the time after the last step, s.

    Returns
    -------
    int
        The steps taken: it stops before a step the Python path would refuse (the module).
    """
    w, forces, work, truth = np.zeros(3), np.empty(9), np.empty((7, 9)), np.empty(T.SIZE)
    next_command, z, taken, t = np.empty(2), world[world.shape[0] - 1], 0, t0
    for k in range(n_steps):
        if not T.viel_truth(state, t, applied[0], applied[1], world[:world.shape[0] - 5], z, wind, tables, w,
                            forces, truth):
            break  # the truth's domain check: Python raises
        if k > 0:
            rows[k - 1, :] = truth
            rewards[k - 1] = position_reward(truth, task)
        kept = memory.copy()
        if viel_command(truth, task[0], task[1], law, bounds, memory, info, next_command) != OK:
            break
        if viel_step(state, t, next_command, world, wind, tables, work, applied) != WORLD_OK:
            memory[:] = kept
            break  # the world stops: Python's words for it
        t = t + world[world.shape[0] - 5]
        command[:] = next_command
        actions[k, 0], actions[k, 1], actions[k, 2] = command[0], command[1], info[0]
        taken = k + 1
    time_out[0] = t
    return taken


@kernel
def boat_episode(n_steps, h, n_sub, wind, tables, law, bounds, task, memory, rows, rewards, actions, info,
                 outcome):
    """Up to ``n_steps`` control steps of a 6-DOF boat.

    Parameters
    ----------
    n_steps : int
        Control steps to take at most.
    h : sailmujoco.step.closed_loop.LoopHandles
        The boat's arrays, while it is in the step registry.
    n_sub : int
        Physics sub-steps per control step.
    wind : numpy.ndarray, shape (5,)
        The loops' wind numbers (:func:`sailmujoco.loop.episode.wind_arguments`).
    tables : tuple of numpy.ndarray
        The wind's tables (the same).
    law : numpy.ndarray, shape (14,)
        The controller's numbers: own target or not (1/0), x_T, y_T (m), d_M, d_T (m), k_s, k_p,
        k_v, epsilon_sail, epsilon_theta, delta, rudder_max, sail_max (rad), dt (s).
    bounds : numpy.ndarray, shape (4,)
        The clip of the command: low rudder, low sail, high rudder, high sail (rad).
    memory : numpy.ndarray, shape (4,)
        The controller's memory, updated: last sail (Viel sign), previous speed known (1/0),
        the previous speed, the tack q.
    info : numpy.ndarray, shape (5,)
        Receives the controller's ``info`` of its last call: mode code (:data:`MODES`),
        theta_bar, vdot*, vdot, distance.
    task : numpy.ndarray, shape (4,)
        The task's numbers (:func:`sailmujoco.loop.position_task.task_numbers`).
    rows : numpy.ndarray, shape (n_steps, truth.SIZE)
        Row k: the truth of the state after step k.
    rewards : numpy.ndarray, shape (n_steps,)
        Entry k: the reward of the state after step k.
    actions : numpy.ndarray, shape (n_steps, 3)
        Row k: step k's command (ours, rad) and mode code.
    outcome : numpy.ndarray of int64, shape (3,)
        Receives the stop status of the last step taken, whether a new warning stopped it (1/0),
        and the force kernel's status at the last measurement.

    Returns
    -------
    int
        The steps taken, the last one possibly stopped (``outcome``).
    """
    m, d = pointer(h.m_address), pointer(h.d_address)
    scratch, truth, command = np.empty((4, 9)), np.empty(T.SIZE), np.empty(2)
    outcome[0], outcome[1], taken = BOAT_OK, 0, 0
    for k in range(n_steps):
        outcome[2] = T.mujoco_truth(m, d, h.qpos, h.qvel, h.site_xpos, h.site, h.rudder_at, h.sail_at, h.row,
                                    h.diag, wind, tables, h.current, scratch, truth)
        if k > 0:
            rows[k - 1, :] = truth
            rewards[k - 1] = position_reward(truth, task)
        if viel_command(truth, task[0], task[1], law, bounds, memory, info, command) != OK:
            break
        actions[k, 0], actions[k, 1], actions[k, 2] = command[0], command[1], info[0]
        status, warned = mujoco_step(h.m_address, h.d_address, n_sub, h.ctrl, h.row, h.saved, h.warnings,
                                     h.warnings_before, command)
        taken = k + 1
        if status != BOAT_OK:
            outcome[0] = status
            break
        if warned and h.warnings_stop:
            outcome[1] = 1
            break
    return taken


def compiled_episode(controller, env, low, high, steps: int | None = None):
    """The episode of ``env`` under ``controller`` (a :class:`~controllers.viel.VielController`
    whose command is clipped to [low, high]) by :func:`paper_episode` or :func:`boat_episode`;
    None where neither covers the pair (nothing touched).

    Parameters
    ----------
    controller : VielController
        The controller, reset.
    env : sailmujoco.tasks.environment.SailEnvironment
        Its environment, reset.
    low, high : array_like, shape (2,)
        The clip of its command (``Bounded``'s), or None for none.
    steps : int, optional
        Take at most this many control steps (default: all the episode has left).
    """
    physics, n_steps = env.physics, env.compiled_steps()
    if steps is not None:
        n_steps = min(steps, n_steps)
    paper = hasattr(physics, "closed_loop_arguments")
    if not covers(env.task) or not (physics.closed_loop_ready() if paper else closed_loop_ready(physics)):
        return None
    clip = np.array([-math.inf, -math.inf, math.inf, math.inf]) if low is None else np.concatenate(
        [np.asarray(low, dtype=float), np.asarray(high, dtype=float)])
    target = (0.0, 0.0, 0.0) if controller.target is None else (1.0, *controller.target.tolist())
    c = controller
    law = np.array([*target, c.d_M, c.d_T, c.k_s, c.k_p, c.k_v, c.epsilon_sail, c.epsilon_theta, c.delta,
                    c.rudder_max, c.sail_max, c.dt])
    memory = np.array([controller.sail, 0.0 if controller.v_previous is None else 1.0,
                       controller.v_previous or 0.0, float(controller.q)])
    rows, rewards, actions, info = buffers(n_steps)
    task, seconds = task_numbers(env.task), (n_steps + 2) * env.control_timestep()
    stop = None
    if paper:
        t0, state, applied, world = physics.closed_loop_arguments(env.sub_steps(), seconds)
        wind, tables = wind_arguments(physics.world.wind)
        command, time = np.empty(2), np.empty(1)
        taken = paper_episode(n_steps, t0, state, applied, world, wind, tables, law, clip, task, memory,
                              command, time, rows, rewards, actions, info)
        if taken:
            physics.closed_loop_ended(state, time[0], applied, command)
    else:
        outcome = np.zeros(3, dtype=np.int64)
        with closed_loop(physics, seconds) as handles:
            wind, tables = wind_arguments(physics.wind)
            taken = boat_episode(n_steps, handles, env.sub_steps(), wind, tables, law, clip, task, memory,
                                 rows, rewards, actions, info, outcome)
        if taken:
            stop = closed_loop_ended(physics, int(outcome[0]), bool(outcome[1]), int(outcome[2]))
    if not taken:
        return None
    controller.sail, controller.q = float(memory[0]), int(memory[3])
    controller.v_previous = float(memory[2]) if memory[1] else None
    mode, theta_bar, vdot_star, vdot, distance = info.tolist()
    controller.info = dict(mode=MODES[int(mode)], theta_bar=theta_bar, vdot_star=vdot_star, vdot=vdot,
                           q=controller.q, distance=distance)
    return finish(env, taken, rows, rewards, actions, stop)
