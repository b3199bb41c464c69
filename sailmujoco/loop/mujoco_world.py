"""Viel's position keeping on a 6-DOF MuJoCo boat, the whole closed loop in one compiled call.

:func:`episode` runs control steps of ``suite.load(boat, "position_keeping")`` under the suite's
``viel`` controller, each step what the Python path does, in its order:

1. the truth of the state (:func:`sailmujoco.loop.truth.mujoco_truth`: MuJoCo's kinematics and
   the force kernel brought up to the state, as the accessors' ``_ensure_fresh`` does), kept as
   the state's row, and the task's reward of it;
2. the controller's command (:func:`sailmujoco.loop.viel_control.viel_command`) into MjData's
   ``ctrl`` (dm_control's ``set_control``);
3. the physics' control step: MuJoCo's RK4 ``mj_step`` for each sub-step with the compiled stage
   callback (``sailmujoco.step.native``, the step ``BoatPhysics.step`` takes), its stop status
   and MuJoCo's warnings checked after it as ``BoatPhysics._step_native`` checks them.

A stop in the physics (capsize, a non-finite state, a new MuJoCo warning where warnings stop the
run) ends the kernel after that step with the outcome; a state the controller would reject ends
it before that step's action. Either way the caller (:mod:`sailmujoco.loop.episode`) finishes
the step in Python, in Python's words.
"""

from __future__ import annotations

import numpy as np

from ..forces.boat import STATUS_OK
from ..jit.kernel import kernel
from ..step.mujoco_calls import pointer
from ..step.native import _rk4_one
from . import truth as T
from .position_task import position_reward
from .viel_control import OK, viel_command


@kernel
def episode(n_steps, m_address, d_address, n_sub, qpos, qvel, ctrl, site_xpos, site, rudder_at, sail_at, row,
            diag, saved, warnings, warnings_before, warnings_stop, wind, tables, current, law, bounds, task, memory,
            rows, rewards, actions, info, outcome):
    """Up to ``n_steps`` control steps of the closed loop on a 6-DOF MuJoCo boat; see the module.

    Parameters
    ----------
    n_steps : int
        Control steps to run at most.
    m_address, d_address : int
        The boat's MjModel and MjData (C structs).
    n_sub : int
        Physics sub-steps per control step.
    qpos, qvel, ctrl, site_xpos : numpy.ndarray
        MjData's arrays.
    site, rudder_at, sail_at : int
        The masthead site's id; the rudder's and the sail's qpos addresses.
    row : numpy.ndarray of int64
        The boat's row in the step registry (its slot of ``registry.REGISTRY``, while it is
        stepping: :class:`sailmujoco.step.native.Stepping`).
    diag : numpy.ndarray
        The force kernel's diagnostics (the row's).
    saved : numpy.ndarray
        Scratch for the state before a sub-step (``BoatPhysics._saved``).
    warnings, warnings_before : numpy.ndarray of int
        MuJoCo's warning counts (``BoatPhysics._warnings``) and their copy before the last step
        taken (``BoatPhysics._warnings_before``, written here as the Python step writes it).
    warnings_stop : bool
        Whether a new MuJoCo warning stops the run (``BoatPhysics._warnings_cause_exception``).
    wind : numpy.ndarray, shape (5,)
        The WindField's U_m10 (m/s), mean bearing the wind comes from (rad), direction
        oscillation (rad) and its frequency (Hz), and the wander's time step (s).
    tables : tuple of numpy.ndarray
        The WindField's oscillation (3,), gust frequency, phase, amplitude and log_z tables, and
        its wander (rad), covering the whole run.
    current : numpy.ndarray, shape (3,)
        The water current (ENU, m/s).
    law, bounds, task, memory, info : numpy.ndarray
        As :func:`sailmujoco.loop.viel_world.episode` takes them.
    rows : numpy.ndarray, shape (n_steps, truth.SIZE)
        Row k: the truth of the state after step k.
    rewards : numpy.ndarray, shape (n_steps,)
        Entry k: the reward of the state after step k.
    actions : numpy.ndarray, shape (n_steps, 3)
        Row k: the command of step k (rudder, sail; ours, rad) and the controller's mode code.
    outcome : numpy.ndarray of int64, shape (3,)
        Receives the physics' stop status of the last step taken (STATUS_OK if none), whether a
        new warning stopped it (1/0), and the force kernel's status at the last truth.

    Returns
    -------
    int
        The control steps taken (the last one possibly stopped: ``outcome``). Rows 0 .. taken
        - 2 of ``rows`` and ``rewards`` are the states after steps 0 .. taken - 2.
    """
    m, d = pointer(m_address), pointer(d_address)
    scratch = np.empty((4, 9))
    truth = np.empty(T.SIZE)
    command = np.empty(2)
    outcome[0], outcome[1] = STATUS_OK, 0
    taken = 0
    for k in range(n_steps):
        outcome[2] = T.mujoco_truth(m, d, qpos, qvel, site_xpos, site, rudder_at, sail_at, row, diag, wind,
                                    tables, current, scratch, truth)
        if k > 0:  # the state after step k - 1: its row and reward
            rows[k - 1, :] = truth
            rewards[k - 1] = position_reward(truth, task)
        if viel_command(truth, task[0], task[1], law, bounds, memory, info, command) != OK:
            break
        actions[k, 0], actions[k, 1], actions[k, 2] = command[0], command[1], info[0]
        ctrl[0], ctrl[1] = command[0], command[1]
        warnings_before[:] = warnings
        status, _, warned = _rk4_one(m_address, d_address, n_sub, row, saved)
        taken = k + 1
        if status != STATUS_OK:
            outcome[0] = status
            break
        if warned and warnings_stop:
            outcome[1] = 1
            break
    return taken
