"""Geometry of a foil section: the flow in the section plane, lift and drag on its axes.

The conventions (chord axis c, normal axis n, angle of attack alpha, F = q A (C_T c - C_N n))
are those of :mod:`sailmujoco.forces.foil`, which describes them for all three foils.
"""

from __future__ import annotations

import math

from .._jit import kernel


@kernel
def section_flow(flow, chord_axis, normal_axis):
    """Section-plane components (w_c, w_n) of a flow velocity, its speed and angle of attack."""
    wc = flow[0] * chord_axis[0] + flow[1] * chord_axis[1] + flow[2] * chord_axis[2]
    wn = flow[0] * normal_axis[0] + flow[1] * normal_axis[1] + flow[2] * normal_axis[2]
    speed = math.sqrt(wc * wc + wn * wn)
    alpha = math.atan2(-wn, -wc)
    return wc, wn, speed, alpha


@kernel
def lift_drag_components(wc, wn, speed, q_area, c_lift, c_drag):
    """Force (F_c, F_n) on the chord and normal axes from C_L, C_D (Wille eqs. 21-22)."""
    if speed <= 0.0:
        return 0.0, 0.0
    uc, un = wc / speed, wn / speed
    # lift along span x w_hat = (-w_n, w_c) in (chord, normal); drag along w_hat
    return q_area * (-c_lift * un + c_drag * uc), q_area * (c_lift * uc + c_drag * un)


@kernel
def foil_world_force(fc, fn, chord_axis, normal_axis, out):
    """out = F_c c + F_n n (world frame)."""
    for k in range(3):
        out[k] = fc * chord_axis[k] + fn * normal_axis[k]
