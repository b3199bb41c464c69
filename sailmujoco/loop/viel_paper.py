"""Viel's position keeping in Viel's 3-DOF world, the whole closed loop in one compiled call.

:func:`episode` runs control steps of ``suite.load(boat, "position_keeping", world="paper")``
driven by ``controllers.viel.VielController`` (behind the suite's ``Bounded`` clip), each step
what the Python path does, in its order and with its operations:

1. the truth of the state (:meth:`sailmujoco.reference.viel.VielWorld.truth`: the wind of
   :class:`~sailmujoco.forces.wind.WindField` at the world's height, the apparent wind of
   §2.3, the force terms, whose domain check it keeps), the task's record of it and its reward
   (``tasks/position.py``);
2. the controller's view of the observation (``controllers.viel.viel_view``) and its law
   (``VielController.__call__``): the law's functions are the controller module's own, compiled
   from the same source (``numba.extending.register_jitable``);
3. the suite's clip to the action bounds, the world's saturation, then Viel's eqs. 1-9
   integrated by :func:`sailmujoco.reference.viel_model.advance` (the world's RK4 kernel) and
   the heading wrapped, as :meth:`VielWorld.step` does.

Python's ``math.hypot`` is not the C library's (one pair in about 500 differs in the last bit):
every hypot here is :func:`sailmujoco.reference.hypot.hypot`, which is CPython's to the bit.

Where the Python path would raise or stop (a non-finite observation, the world's domain check,
an integration that runs away), the kernel stops *before* that step's action and hands back:
the caller (:mod:`sailmujoco.loop.episode`) then lets the Python path take that step, so a
failure is reported in Python's own words.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import sailmujoco.controllers.viel as viel_law
from sailmujoco.controllers.viel import (
    _sign,
    adaptive_sail,
    desired_acceleration,
    go_round,
    optimal_sail,
    rudder_law,
    sail_limit,
    tack,
)

from ..forces.wind_kernels import wander_angle, wind_velocity
from ..frames import wrap_angle
from ..jit.kernel import _SOURCES, _clear_stale_cache, kernel
from ..reference.hypot import hypot
from ..reference.integrators import STATUS_OK
from ..reference.viel_model import apparent_wind, forces_kernel
from ..reference.viel_model import advance as world_advance

# the cache of this module's kernel also depends on the controller's law, outside the package's
# kernel sources: cleared when either has changed
_HERE = Path(__file__).resolve()
_clear_stale_cache((*_SOURCES, Path(viel_law.__file__).resolve(), _HERE), {_HERE.parent / "__pycache__"})

# modes of VielController.info["mode"], by the code the kernel returns
MODES = (viel_law.GO_DIRECT, viel_law.GO_ROUND, viel_law.TACK, viel_law.UPWIND_STOP, viel_law.UPWIND_DRIVE)
_DIRECT, _ROUND, _TACK, _STOP, _DRIVE = range(5)

# columns of the record rows: what tasks.base.SailTask.record keeps of a state
RECORD = ("t", "x", "y", "heading", "heel", "roll_rate", "surge", "course", "speed")
# the controller's state, in and out: last sail (Viel sign), previous speed known (0/1), the
# previous speed, the tack q
CONTROLLER_STATE = ("sail", "has_previous", "v_previous", "q")
# VielController.info of the last call: mode code, theta_bar, vdot*, vdot, distance
INFO = ("mode", "theta_bar", "vdot_star", "vdot", "distance")


@kernel
def episode(n_steps, t0, state0, action0, world, wind, tables, law, bounds, task, controller, state_out,
            action_out, time_out, records, rewards, info):
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
    law : numpy.ndarray, shape (14,)
        The controller's numbers: its own target or not (1/0), x_T, y_T (m), d_M, d_T (m), k_s,
        k_p, k_v, epsilon_sail, epsilon_theta, delta, rudder_max, sail_max (rad), dt (s).
    bounds : numpy.ndarray, shape (4,)
        The suite's clip: low rudder, low sail, high rudder, high sail (rad).
    task : numpy.ndarray, shape (4,)
        The task's target (x, y, m), d_T (m) and its floor FAR (target radii).
    controller : numpy.ndarray, shape (4,)
        The controller's state (:data:`CONTROLLER_STATE`), updated in place.
    state_out : numpy.ndarray, shape (6,)
        Receives the world's state after the last step taken.
    action_out : numpy.ndarray, shape (4,)
        Receives the world's applied action and the clipped command of the last step taken.
    time_out : numpy.ndarray, shape (1,)
        Receives the world's time after the last step taken.
    records : numpy.ndarray, shape (n_steps, 9)
        Row k: the record (:data:`RECORD`) of the state after step k.
    rewards : numpy.ndarray, shape (n_steps,)
        Entry k: the reward of the state after step k.
    info : numpy.ndarray, shape (5,)
        Receives the controller's info of its last call (:data:`INFO`).

    Returns
    -------
    int
        The control steps taken. Rows 0 .. taken - 2 of ``records`` and ``rewards`` are those
        of the states after steps 0 .. taken - 2; the state after the last step taken is left
        to the caller to record (the Python path's last half step).
    """
    P = world[:-5]
    dt, n_rk4 = world[-5], int(world[-4])
    rudder_max, sail_max, z = world[-3], world[-2], world[-1]
    speed10, direction_mean, direction_oscillation, frequency_hz = wind[0], wind[1], wind[2], wind[3]
    wander_dt = wind[4]
    oscillation, frequency, phase, amplitude, log_z, wander = tables
    own_target, x_T, y_T, d_M, d_T = law[0] != 0.0, law[1], law[2], law[3], law[4]
    k_s, k_p, k_v, epsilon_sail, epsilon_theta, delta = law[5], law[6], law[7], law[8], law[9], law[10]
    law_rudder_max, law_sail_max, law_dt = law[11], law[12], law[13]
    target_x, target_y, task_d_T, far = task[0], task[1], task[2], task[3]

    state = state0.copy()
    applied0, applied1 = action0[0], action0[1]
    t = t0
    w = np.zeros(3)
    work = np.empty((7, 9))
    forces = np.empty(9)
    taken = 0
    for k in range(n_steps):
        # --- VielWorld.truth: the wind at the world's height, the apparent wind, the forces
        x, y, theta, v, u, omega = state[0], state[1], state[2], state[3], state[4], state[5]
        wind_velocity(t, z, speed10, direction_mean, oscillation, frequency, phase, amplitude, log_z,
                      wander_dt, wander, w)
        a_tw, psi_tw = hypot(w[0], w[1]), math.atan2(w[1], w[0])
        a_aw, psi_aw = apparent_wind(a_tw, psi_tw, theta, v)
        if not forces_kernel(P, state, -applied0, -applied1, a_tw, psi_tw, forces):
            break  # the truth's domain check: Python raises
        c, s = math.cos(theta), math.sin(theta)
        east, north = v * c - u * s, v * s + u * c
        heading = wrap_angle(math.pi / 2.0 - theta)  # frames.heading_from_yaw
        awa = wrap_angle(math.pi - psi_aw)  # viel_model.awa_from_psi_aw
        direction_from = (direction_mean + wander_angle(t, wander_dt, wander)
                          + direction_oscillation * math.sin(2.0 * math.pi * frequency_hz * t))
        wind_direction = wrap_angle(direction_from)  # observation: true_state["wind_direction"]
        if k > 0:  # the record and reward of the state after step k - 1 (tasks.base, position.py)
            row = records[k - 1]
            row[0], row[1], row[2], row[3] = t, x, y, heading
            row[4], row[5], row[6] = 0.0, 0.0, v
            row[7], row[8] = math.atan2(north, east), hypot(east, north)
            d = hypot(x - target_x, y - target_y)
            rewards[k - 1] = -min(d, far * task_d_T) / task_d_T
        # --- controllers.viel.viel_view
        tx, ty = (x_T, y_T) if own_target else (target_x, target_y)
        th = wrap_angle(math.pi / 2.0 - heading)
        cc, ss = math.cos(th), math.sin(th)
        phi = math.atan2(north, east)
        sv = east * cc + north * ss
        su = -east * ss + north * cc
        s_psi_aw = wrap_angle(math.pi - awa)
        s_psi_tw = wrap_angle(-0.5 * math.pi - wind_direction)
        if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(th) and math.isfinite(phi)
                and math.isfinite(sv) and math.isfinite(su) and math.isfinite(omega) and math.isfinite(a_aw)
                and math.isfinite(s_psi_aw) and math.isfinite(s_psi_tw) and math.isfinite(tx)
                and math.isfinite(ty)):
            break  # viel_view raises
        # --- VielController.__call__
        kept = (controller[0], controller[1], controller[2], controller[3])
        vdot = 0.0 if controller[1] == 0.0 else (sv - controller[2]) / law_dt
        controller[1], controller[2] = 1.0, sv
        dx, dy = tx - x, ty - y
        distance = hypot(dx, dy)
        vdot_star = math.nan
        q = int(controller[3])
        if distance < d_T:  # Viel §4.3 step 4
            if sv > 0.0:
                mode = _STOP
                theta_bar = s_psi_tw + math.pi  # Viel eq. 19
                sail = -_sign(s_psi_aw) * sail_limit(s_psi_aw, law_sail_max)  # Viel eq. 20 (bounded)
            else:
                mode = _DRIVE
                theta_bar = s_psi_tw + math.pi - delta * _sign(su)  # Viel eq. 21
                lim = max(sail_limit(s_psi_aw, law_sail_max) - epsilon_sail, 0.0)
                sail = -_sign(s_psi_aw) * min(abs(optimal_sail(s_psi_tw, theta_bar)), lim)  # Viel eq. 22
        else:
            theta_star = math.atan2(dy, dx)  # Viel step 1
            alpha = math.atan2(-dy, -dx)
            theta_star, turned = go_round(theta_star, alpha, s_psi_tw, distance, d_T, d_M)
            theta_bar, q, dead = tack(theta_star, s_psi_tw, delta, q)
            mode = _ROUND if turned else (_TACK if dead else _DIRECT)
            vdot_star = desired_acceleration(sv, su, th, alpha, distance, k_v, k_p)
            sail = adaptive_sail(controller[0], vdot_star, vdot, s_psi_aw, s_psi_tw, theta_bar, k_s, law_dt,
                                 epsilon_sail, law_sail_max)
        theta_bar = wrap_angle(theta_bar)
        rudder = rudder_law(th, phi, theta_bar, law_rudder_max, epsilon_theta)
        controller[0], controller[3] = sail, float(q)
        # --- the suite's Bounded clip, then VielWorld.step: saturation, eqs. 1-9, the heading wrap
        command0 = min(max(-rudder, bounds[0]), bounds[2])
        command1 = min(max(-sail, bounds[1]), bounds[3])
        if not (math.isfinite(command0) and math.isfinite(command1)):
            controller[0], controller[1], controller[2], controller[3] = kept
            break  # the task's action check raises
        a0 = min(max(command0, -rudder_max), rudder_max)
        a1 = min(max(command1, -sail_max), sail_max)
        new = state.copy()
        status = world_advance(t, new, dt, n_rk4, P, -a0, -a1, z, speed10, direction_mean, oscillation,
                               frequency, phase, amplitude, log_z, wander_dt, wander, work)
        if status != STATUS_OK:
            controller[0], controller[1], controller[2], controller[3] = kept
            break  # the world stops: Python's words for it
        new[2] = (new[2] + math.pi) % (2.0 * math.pi) - math.pi
        state[:] = new
        t = t + dt
        applied0, applied1 = a0, a1
        info[0], info[1], info[2], info[3], info[4] = mode, theta_bar, vdot_star, vdot, distance
        action_out[0], action_out[1], action_out[2], action_out[3] = a0, a1, command0, command1
        taken = k + 1
    state_out[:] = state
    time_out[0] = t
    return taken
