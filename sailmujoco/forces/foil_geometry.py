"""Geometry of a foil section: the flow in the section plane, lift and drag on its axes.

One convention for all three foils (the keel, the rudder and the sail); the keel's and the
rudder's forces are assembled in :mod:`sailmujoco.forces.hull_foils`, the sail's in
:mod:`sailmujoco.forces.sail`.

Geometry of a foil section
    chord axis ``c``: in the section plane, pointing from the trailing edge to the leading edge
    (forward for the keel and for an undeflected rudder, from the clew to the mast for the sail);
    normal axis ``n`` = span x c (to port when undeflected); span axis up the mast/keel.
    ``w`` is the velocity of the fluid relative to the foil (where it flows to), projected on
    the section plane: spanwise flow is dropped (the cross-flow principle), which is how the
    force stays in the foil's own plane when the boat heels.
Angle of attack
    The fluid comes from d = -w. alpha = atan2(d.n, d.c), so alpha > 0 when the fluid comes
    from the +n side. This is Wille's alpha = -beta + pi (eqs. 28, 32, 35) written in the foil
    frame. Saoud's angle (§IV) has the opposite sign, alpha = -alpha_s, because his sail angle
    turns the other way (delta_s = -lambda, see controllers/saoud.py); the forces agree.
Lift and drag
    F = q A (C_L (span x w_hat) + C_D w_hat), q = rho |w|^2 / 2 (Wille eqs. 21-22): drag along
    the flow, lift perpendicular to it, away from the side the fluid comes from.
    In chord/normal components this is F = q A (C_T c - C_N n) with
    C_T = C_L sin(alpha) - C_D cos(alpha), C_N = C_L cos(alpha) + C_D sin(alpha) (Saoud §IV).
"""

from __future__ import annotations

import math

from ..jit.kernel import kernel


@kernel
def section_flow(flow, chord_axis, normal_axis):
    """Section-plane components (w_c, w_n) of a flow velocity, its speed and angle of attack.

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        Velocity of the fluid relative to the foil (where it flows to), m/s, in any frame.
    chord_axis, normal_axis : numpy.ndarray, shape (3,)
        The foil's unit chord axis c and normal axis n, in the frame of ``flow``.

    Returns
    -------
    wc, wn, speed, alpha : float
        w.c and w.n (m/s), the in-plane speed sqrt(w_c^2 + w_n^2) (m/s; spanwise flow dropped)
        and alpha = atan2(-w_n, -w_c) (rad).
    """
    wc = flow[0] * chord_axis[0] + flow[1] * chord_axis[1] + flow[2] * chord_axis[2]
    wn = flow[0] * normal_axis[0] + flow[1] * normal_axis[1] + flow[2] * normal_axis[2]
    speed = math.sqrt(wc * wc + wn * wn)
    alpha = math.atan2(-wn, -wc)
    return wc, wn, speed, alpha


@kernel
def lift_drag_components(wc, wn, speed, q_area, c_lift, c_drag):
    """Force (F_c, F_n) on the chord and normal axes from C_L, C_D (Wille (2016a) eqs. 21-22).

    Lift along span x w_hat, drag along w_hat; zero force when the flow is at rest.

    Parameters
    ----------
    wc, wn, speed : float
        The flow's chord and normal components and its in-plane speed, m/s
        (:func:`section_flow`).
    q_area : float
        Dynamic pressure times the foil's area, rho |w|^2 A / 2, N.
    c_lift, c_drag : float
        Lift and drag coefficients C_L, C_D, -.

    Returns
    -------
    fc, fn : float
        Force along the chord axis and along the normal axis, N.
    """
    if speed <= 0.0:
        return 0.0, 0.0
    uc, un = wc / speed, wn / speed
    # lift along span x w_hat = (-w_n, w_c) in (chord, normal); drag along w_hat
    return q_area * (-c_lift * un + c_drag * uc), q_area * (c_lift * uc + c_drag * un)


@kernel
def foil_world_force(fc, fn, chord_axis, normal_axis, out):
    """out = F_c c + F_n n: the foil force as a vector in the frame of its axes.

    Parameters
    ----------
    fc, fn : float
        Force along the chord axis and along the normal axis, N.
    chord_axis, normal_axis : numpy.ndarray, shape (3,)
        The foil's unit chord and normal axes (world or body frame).
    out : numpy.ndarray, shape (3,)
        Receives the force, N, in the frame of the axes.
    """
    for k in range(3):
        out[k] = fc * chord_axis[k] + fn * normal_axis[k]
