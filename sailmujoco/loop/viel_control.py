"""Viel's position keeping law, compiled, read from the truth vector (:mod:`sailmujoco.loop.truth`).

:func:`viel_command` is ``Bounded(VielController)(timestep)`` of the suite's ``viel``
controller: the controller's view of the observation (``controllers.viel.viel_view``), its call
(``VielController.__call__``) and the suite's clip to the action bounds, in their order. The
law's functions are the controller module's own (``rudder_law``, ``adaptive_sail``, ``tack``, ...),
compiled from the same source (``numba.extending.register_jitable``); Python's ``math.hypot``
is :func:`sailmujoco.reference.hypot.hypot`, CPython's to the bit.
"""

from __future__ import annotations

import math

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

from ..frames import wrap_angle
from ..jit.kernel import kernel
from ..reference.hypot import hypot
from . import truth as T

# modes of VielController.info["mode"], by the code the law writes into ``info``
MODES = (viel_law.GO_DIRECT, viel_law.GO_ROUND, viel_law.TACK, viel_law.UPWIND_STOP, viel_law.UPWIND_DRIVE)
_DIRECT, _ROUND, _TACK, _STOP, _DRIVE = range(5)
# the law's numbers: its own target or not (1/0), x_T, y_T (m), d_M, d_T (m), k_s, k_p, k_v,
# epsilon_sail, epsilon_theta, delta, rudder_max, sail_max (rad), dt (s)
LAW_SIZE = 14
# the controller's memory, in and out: last sail (Viel sign), previous speed known (0/1), the
# previous speed, the tack q
MEMORY = ("sail", "has_previous", "v_previous", "q")
# VielController.info of the last call: mode code, theta_bar, vdot*, vdot, distance
INFO = ("mode", "theta_bar", "vdot_star", "vdot", "distance")
OK, REJECTED, NON_FINITE_COMMAND = 0, 1, 2


@kernel(inline=True)
def viel_command(truth, target_x, target_y, law, bounds, memory, info, command):
    """The clipped command [rudder, sail] (ours, rad) for the state of ``truth`` into ``command``.

    ``target_x``, ``target_y``: the task's target (the observation's ``target_position``);
    ``bounds``: low rudder, low sail, high rudder, high sail (rad); ``memory`` and ``info`` as
    :data:`MEMORY` and :data:`INFO`, updated. Returns OK; REJECTED where ``viel_view`` raises
    (a non-finite number: nothing changed); NON_FINITE_COMMAND where the task's action check
    would raise (the memory put back as it was).
    """
    own_target, x_T, y_T, d_M, d_T = law[0] != 0.0, law[1], law[2], law[3], law[4]
    k_s, k_p, k_v, epsilon_sail, epsilon_theta, delta = law[5], law[6], law[7], law[8], law[9], law[10]
    rudder_max, sail_max, dt = law[11], law[12], law[13]
    # --- viel_view
    x, y, east, north = truth[T.X], truth[T.Y], truth[T.EAST], truth[T.NORTH]
    tx, ty = (x_T, y_T) if own_target else (target_x, target_y)
    theta = wrap_angle(math.pi / 2.0 - truth[T.HEADING])
    c, s = math.cos(theta), math.sin(theta)
    phi = math.atan2(north, east)
    v = east * c + north * s
    u = -east * s + north * c
    omega, a_aw = truth[T.R], truth[T.AWS]
    psi_aw = wrap_angle(math.pi - truth[T.AWA])
    psi_tw = wrap_angle(-0.5 * math.pi - wrap_angle(truth[T.DIRECTION_FROM]))
    if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(theta) and math.isfinite(phi)
            and math.isfinite(v) and math.isfinite(u) and math.isfinite(omega) and math.isfinite(a_aw)
            and math.isfinite(psi_aw) and math.isfinite(psi_tw) and math.isfinite(tx) and math.isfinite(ty)):
        return REJECTED
    # --- VielController.__call__
    kept0, kept1, kept2, kept3 = memory[0], memory[1], memory[2], memory[3]
    vdot = 0.0 if memory[1] == 0.0 else (v - memory[2]) / dt
    memory[1], memory[2] = 1.0, v
    dx, dy = tx - x, ty - y
    distance = hypot(dx, dy)
    vdot_star = math.nan
    q = int(memory[3])
    if distance < d_T:  # Viel §4.3 step 4: upwind strategy in the target area
        if v > 0.0:
            mode = _STOP
            theta_bar = psi_tw + math.pi  # Viel eq. 19
            sail = -_sign(psi_aw) * sail_limit(psi_aw, sail_max)  # Viel eq. 20 (bounded)
        else:
            mode = _DRIVE
            theta_bar = psi_tw + math.pi - delta * _sign(u)  # Viel eq. 21
            lim = max(sail_limit(psi_aw, sail_max) - epsilon_sail, 0.0)
            sail = -_sign(psi_aw) * min(abs(optimal_sail(psi_tw, theta_bar)), lim)  # Viel eq. 22
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
    # --- action_from_viel, then the suite's Bounded clip
    command[0] = min(max(-rudder, bounds[0]), bounds[2])
    command[1] = min(max(-sail, bounds[1]), bounds[3])
    if not (math.isfinite(command[0]) and math.isfinite(command[1])):
        memory[0], memory[1], memory[2], memory[3] = kept0, kept1, kept2, kept3
        return NON_FINITE_COMMAND
    info[0], info[1], info[2], info[3], info[4] = mode, theta_bar, vdot_star, vdot, distance
    return OK
