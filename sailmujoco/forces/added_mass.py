"""Added mass: the velocity terms. The inertia term is solved exactly inside the MuJoCo step.

Wille (2016a) eqs. 8-11 with the diagonal M_A of §2.1, generalised to 6 DOF with heave and
pitch added mass (strip theory, :mod:`sailmujoco.hull`). For a diagonal
M_A = diag(A1, A2) (A1 translational, A2 rotational, positive), Kirchhoff's equations give the
fluid force on the hull (Fossen 2011, eqs. 6.43-6.54)

    F = -A1 nu_dot_r - omega x (A1 v_r)
    M = -A2 omega_dot - omega x (A2 omega) - v_r x (A1 v_r)

where nu_dot is the body-frame derivative of the body-frame components. The yaw row of
-v_r x (A1 v_r) is the Munk moment (Y_vdot - X_udot) u_r v_r of eq. 10 (it reads
(a11 - a22) u v in our FLU frame, the same quantity).

MuJoCo's free joint integrates the *world* acceleration a of CO, and R^T a = v_dot + omega x v.
The step adds R A1 R^T to the translational block of the mass matrix and A2 to the rotational
one (:mod:`sailmujoco.physics`), which supplies -A1 (v_dot_r + omega x v_r) and -A2 omega_dot
implicitly (assuming, as Wille does after eq. 6, a current that is constant in the body
frame). The explicit force computed here is what remains:

    F = A1 (omega x v_r) - omega x (A1 v_r),   M = (A2 omega) x omega + (A1 v_r) x v_r
"""

from __future__ import annotations

from .._jit import kernel


@kernel
def kirchhoff_terms(nu_r, a, out):
    """-C_A(nu_r) nu_r for a diagonal M_A (Fossen 2011 eq. 6.54) into ``out`` (6,).

    F = -omega x (A1 v_r), M = (A1 v_r) x v_r + (A2 omega) x omega. In 4 DOF (w = q = 0) its
    surge, sway and yaw rows are Wille (2016a) eq. 11: (-Y_vdot v_r r, X_udot u_r r, ...,
    (Y_vdot - X_udot) u_r v_r), the last being the Munk moment.
    """
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    a1u, a1v, a1w = a[0] * u, a[1] * v, a[2] * w
    a2p, a2q, a2r = a[3] * p, a[4] * q, a[5] * r
    out[0] = -(q * a1w - r * a1v)
    out[1] = -(r * a1u - p * a1w)
    out[2] = -(p * a1v - q * a1u)
    out[3] = (a2q * r - a2r * q) + (a1v * w - a1w * v)
    out[4] = (a2r * p - a2p * r) + (a1w * u - a1u * w)
    out[5] = (a2p * q - a2q * p) + (a1u * v - a1v * u)


@kernel
def added_mass_velocity_terms(nu_r, a, out):
    """Explicit added-mass wrench for the MuJoCo step (body frame, about CO) into ``out`` (6,).

    The Kirchhoff terms plus A1 (omega x v_r), which undoes the omega x v_r that the world-frame
    acceleration in the augmented mass matrix brings in (see the module docstring).
    ``nu_r`` = (u, v, w, p, q, r) relative to the water; ``a`` = positive diagonal added masses
    (-X_udot, -Y_vdot, -Z_wdot, -K_pdot, -M_qdot, -N_rdot).
    """
    kirchhoff_terms(nu_r, a, out)
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    out[0] += a[0] * (q * w - r * v)
    out[1] += a[1] * (r * u - p * w)
    out[2] += a[2] * (p * v - q * u)
