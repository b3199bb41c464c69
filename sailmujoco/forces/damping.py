"""Hull damping, Wille (2016a) eqs. 12-19, written in the FLU body frame.

D(nu_r) stands on the left of eq. 3, so the force on the hull is -D(nu_r). Every term is odd
in the velocity it damps, so the FRD formulas hold unchanged in FLU.
"""

from __future__ import annotations

import math

from .._jit import kernel

# Below this Reynolds number eq. 16 is outside its range (it is singular at Re = 100);
# C_F is held at its value here (the hull then moves at < 2 cm/s and linear damping rules).
MIN_REYNOLDS = 1.0e5


@kernel
def ittc_friction_coefficient(reynolds):
    """ITTC-1957 friction line C_F = 0.075 / (log10 Re - 2)^2, Wille (2016a) eq. 16."""
    lr = math.log10(max(reynolds, MIN_REYNOLDS))
    return 0.075 / ((lr - 2.0) * (lr - 2.0))


@kernel
def surge_resistance(u_r, rho, wetted_surface, form_factor, length, nu):
    """ITTC surge drag force (N), eq. 15: -1/2 rho S_H (1 + k) C_F(Re) |u_r| u_r."""
    reynolds = abs(u_r) * length / nu
    cf = ittc_friction_coefficient(reynolds)
    return -0.5 * rho * wetted_surface * (1.0 + form_factor) * cf * abs(u_r) * u_r


@kernel
def crossflow_drag(v_r, r, rho, cd, strip_x, strip_w, strip_draft):
    """Cross-flow drag (sway force, yaw moment), eqs. 17-18, Gauss-Legendre strips along x."""
    fy = 0.0
    mz = 0.0
    for k in range(strip_x.shape[0]):
        x = strip_x[k]
        vs = v_r + x * r
        dfy = -0.5 * rho * cd * strip_draft[k] * abs(vs) * vs * strip_w[k]
        fy += dfy
        mz += x * dfy
    return fy, mz


@kernel
def roll_damping(p, u_r, roll_friction, roll_lift, roll_frequency, length):
    """Roll damping moment, eq. 19 (Himeno 1981 / Kato friction and lift components).

    The extracted eq. 19 reads B_F0 (L_WL + 4.1 u/(omega L_WL)) p, which adds metres to a
    dimensionless term. Kato's friction damping, which Himeno quotes, is
    B_F = B_F0 (1 + 4.1 u / (omega L)); we use that. |u_r| replaces u_r so that neither
    term turns into negative damping when the boat moves astern.
    """
    speed = abs(u_r)
    b = roll_friction * (1.0 + 4.1 * speed / (roll_frequency * length)) + roll_lift * speed
    return -b * p


@kernel
def hull_damping(nu_r, rho, linear, wetted_surface, form_factor, length, nu, crossflow_cd,
                 strip_x, strip_w, strip_draft, roll_friction, roll_lift, roll_frequency, out):
    """Total hull damping wrench (body frame, about CO) into ``out`` (6,).

    ``nu_r`` = (u, v, w, p, q, r) relative to the water. ``linear`` = (d11, d22, d33, d55, d66):
    eq. 13 gives d11, d22, d66; heave and pitch (d33, d55) are ours (the papers hold them).
    """
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    fy_cf, mz_cf = crossflow_drag(v, r, rho, crossflow_cd, strip_x, strip_w, strip_draft)
    out[0] = -linear[0] * u + surge_resistance(u, rho, wetted_surface, form_factor, length, nu)
    out[1] = -linear[1] * v + fy_cf
    out[2] = -linear[2] * w
    out[3] = roll_damping(p, u, roll_friction, roll_lift, roll_frequency, length)
    out[4] = -linear[3] * q
    out[5] = -linear[4] * r + mz_cf
