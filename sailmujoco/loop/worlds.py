"""A world's control step inside a compiled closed loop, as its Python step takes it.

* :func:`viel_step`: :meth:`sailmujoco.tasks.world.VielPhysics.step` of Viel's 3-DOF world: the
  world's saturation (``VielWorld._checked_action``), eqs. 1-9 by its own RK4 kernel
  (:func:`sailmujoco.reference.viel_model.advance`), the heading wrapped;
* :func:`mujoco_step`: ``set_control`` and :meth:`sailmujoco.physics.BoatPhysics.step` of a 6-DOF
  boat: MuJoCo's RK4 ``mj_step`` per sub-step with the compiled stage callback
  (:func:`sailmujoco.step.native.rk4_steps`), MuJoCo's warning counts copied before it as the
  Python step copies them. The boat's arrays come from :func:`sailmujoco.step.closed_loop.closed_loop`.
"""

from __future__ import annotations

import math

from ..jit.kernel import kernel
from ..reference.integrators import STATUS_OK
from ..reference.viel_model import advance
from ..step.native import rk4_steps


@kernel(inline=True)
def viel_step(state, t, command, world, wind, tables, work, applied):
    """One control step of Viel's world from (t, state) under ``command``.

    Parameters
    ----------
    state : numpy.ndarray, shape (6,)
        Viel's state; the new one on success (untouched otherwise).
    t : float
        Time, s.
    command : numpy.ndarray, shape (2,)
        The command (ours, rad).
    world : numpy.ndarray
        :meth:`sailmujoco.reference.viel.VielWorld.loop_arguments`' numbers.
    wind : numpy.ndarray, shape (5,)
        The loops' wind numbers (:func:`sailmujoco.loop.truth.direction_from`).
    tables : tuple of numpy.ndarray
        The wind's tables (:func:`sailmujoco.loop.episode.wind_arguments`).
    work : numpy.ndarray, shape (7, 9)
        Scratch of the world's RK4 kernel.
    applied : numpy.ndarray, shape (2,)
        Receives the saturated action on success.

    Returns
    -------
    int
        The integrator's status (STATUS_OK when the step was taken).
    """
    oscillation, frequency, phase, amplitude, log_z, wander = tables
    n = world.shape[0]
    dt, n_rk4 = world[n - 5], int(world[n - 4])
    rudder_max, sail_max, z = world[n - 3], world[n - 2], world[n - 1]
    a0 = min(max(command[0], -rudder_max), rudder_max)  # VielWorld._checked_action
    a1 = min(max(command[1], -sail_max), sail_max)
    new = state.copy()
    status = advance(t, new, dt, n_rk4, world[:n - 5], -a0, -a1, z, wind[0], wind[1], oscillation, frequency,
                     phase, amplitude, log_z, wind[4], wander, work)
    if status != STATUS_OK:
        return status
    new[2] = (new[2] + math.pi) % (2.0 * math.pi) - math.pi  # VielWorld.step's wrap
    state[:] = new
    applied[0], applied[1] = a0, a1
    return status


@kernel(inline=True)
def mujoco_step(m_address, d_address, n_sub, ctrl, row, saved, warnings, warnings_before, command):
    """One control step of a 6-DOF boat under ``command``.

    Parameters
    ----------
    m_address, d_address : int
        The boat's MjModel and MjData.
    n_sub : int
        Physics sub-steps per control step.
    ctrl : numpy.ndarray
        MjData's ``ctrl``.
    row : numpy.ndarray of int64
        The boat's slot of the step registry.
    saved : numpy.ndarray
        Scratch for the state before a sub-step.
    warnings, warnings_before : numpy.ndarray
        MuJoCo's warning counts, and their copy made here before the step.
    command : numpy.ndarray, shape (2,)
        The command (ours, rad; the clipped action).

    Returns
    -------
    tuple of (int, bool)
        The stop status and whether MuJoCo counted a new warning
        (:func:`sailmujoco.step.native.rk4_steps`).
    """
    ctrl[0], ctrl[1] = command[0], command[1]
    warnings_before[:] = warnings
    status, _, warned = rk4_steps(m_address, d_address, n_sub, row, saved)
    return status, warned
