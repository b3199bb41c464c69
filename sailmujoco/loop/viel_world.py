"""Viel's position keeping in Viel's 3-DOF world, the whole closed loop in one compiled call.

:func:`episode` runs control steps of ``suite.load(boat, "position_keeping", world="paper")``
under the suite's ``viel`` controller, each step what the Python path does, in its order:

1. the truth of the state (:func:`sailmujoco.loop.truth.viel_truth`), kept as the state's row,
   and the task's reward of it (:func:`sailmujoco.loop.position_task.position_reward`);
2. the controller's command (:func:`sailmujoco.loop.viel_control.viel_command`);
3. :meth:`sailmujoco.reference.viel.VielWorld.step`: the world's saturation, eqs. 1-9 by the
   world's own RK4 kernel (:func:`sailmujoco.reference.viel_model.advance`), the heading wrapped.

Where the Python path would raise or stop (the truth's domain check, a non-finite observation
or command, an integration that runs away), the kernel stops *before* that step's action and
hands back: the caller (:mod:`sailmujoco.loop.episode`) lets the Python path take that step, so a
failure is reported in Python's own words.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.kernel import kernel
from ..reference.integrators import STATUS_OK
from ..reference.viel_model import advance
from . import truth as T
from .position_task import position_reward
from .viel_control import OK, viel_command


@kernel
def episode(n_steps, t0, state0, action0, world, wind, tables, law, bounds, task, memory, state_out,
            action_out, time_out, rows, rewards, actions, info):
    """Up to ``n_steps`` control steps of the closed loop from (t0, state0); see the module.

    Parameters
    ----------
    n_steps : int
        Control steps to run at most.
    t0 : float
        Time of the start state, s.
    state0 : numpy.ndarray, shape (6,)
        Viel's state (x, y, theta, v, u, omega) now.
    action0 : numpy.ndarray, shape (2,)
        The world's applied action now (ours, rad): the forces of the first truth use it.
    world : numpy.ndarray
        The world's packed parameters (``pack_parameters``), then the control step (s), the
        RK4 steps in it, the saturations delta_r,max and delta_s,max (rad) and the wind's
        height (m).
    wind : numpy.ndarray, shape (5,)
        The WindField's U_m10 (m/s), mean bearing the wind comes from (rad), direction
        oscillation (rad) and its frequency (Hz), and the wander's time step (s).
    tables : tuple of numpy.ndarray
        The WindField's oscillation (3,), gust frequency, phase, amplitude and log_z tables, and
        its wander (rad), covering the whole run.
    law : numpy.ndarray, shape (LAW_SIZE,)
        The controller's numbers (:data:`sailmujoco.loop.viel_control.LAW_SIZE`).
    bounds : numpy.ndarray, shape (4,)
        The suite's clip: low rudder, low sail, high rudder, high sail (rad).
    task : numpy.ndarray, shape (TASK_SIZE,)
        The task's numbers (:data:`sailmujoco.loop.position_task.TASK_SIZE`).
    memory : numpy.ndarray, shape (4,)
        The controller's memory (:data:`sailmujoco.loop.viel_control.MEMORY`), updated in place.
    state_out : numpy.ndarray, shape (6,)
        Receives the world's state after the last step taken.
    action_out : numpy.ndarray, shape (4,)
        Receives the world's applied action and the clipped command of the last step taken.
    time_out : numpy.ndarray, shape (1,)
        Receives the world's time after the last step taken.
    rows : numpy.ndarray, shape (n_steps, truth.SIZE)
        Row k: the truth of the state after step k.
    rewards : numpy.ndarray, shape (n_steps,)
        Entry k: the reward of the state after step k.
    actions : numpy.ndarray, shape (n_steps, 3)
        Row k: the command of step k (rudder, sail; ours, rad) and the controller's mode code.
    info : numpy.ndarray, shape (5,)
        Receives the controller's info of its last call (:data:`sailmujoco.loop.viel_control.INFO`).

    Returns
    -------
    int
        The control steps taken. Rows 0 .. taken - 2 of ``rows`` and ``rewards`` are those of
        the states after steps 0 .. taken - 2; the state after the last step taken is left to
        the caller to measure (the Python path's last half step).
    """
    P = world[:-5]
    dt, n_rk4 = world[-5], int(world[-4])
    rudder_max, sail_max, z = world[-3], world[-2], world[-1]
    oscillation, frequency, phase, amplitude, log_z, wander = tables
    state = state0.copy()
    applied0, applied1 = action0[0], action0[1]
    t = t0
    w = np.zeros(3)
    work = np.empty((7, 9))
    forces = np.empty(9)
    truth = np.empty(T.SIZE)
    command = np.empty(2)
    taken = 0
    for k in range(n_steps):
        if not T.viel_truth(state, t, applied0, applied1, P, z, wind, tables, w, forces, truth):
            break  # the truth's domain check: Python raises
        if k > 0:  # the state after step k - 1: its row and reward
            rows[k - 1, :] = truth
            rewards[k - 1] = position_reward(truth, task)
        kept0, kept1, kept2, kept3 = memory[0], memory[1], memory[2], memory[3]
        if viel_command(truth, task[0], task[1], law, bounds, memory, info, command) != OK:
            break
        actions[k, 0], actions[k, 1], actions[k, 2] = command[0], command[1], info[0]
        a0 = min(max(command[0], -rudder_max), rudder_max)  # VielWorld._checked_action
        a1 = min(max(command[1], -sail_max), sail_max)
        new = state.copy()
        status = advance(t, new, dt, n_rk4, P, -a0, -a1, z, wind[0], wind[1], oscillation, frequency, phase,
                         amplitude, log_z, wind[4], wander, work)
        if status != STATUS_OK:
            memory[0], memory[1], memory[2], memory[3] = kept0, kept1, kept2, kept3
            break  # the world stops: Python's words for it
        new[2] = (new[2] + math.pi) % (2.0 * math.pi) - math.pi
        state[:] = new
        t = t + dt
        applied0, applied1 = a0, a1
        action_out[0], action_out[1], action_out[2], action_out[3] = a0, a1, command[0], command[1]
        taken = k + 1
    state_out[:] = state
    time_out[0] = t
    return taken
