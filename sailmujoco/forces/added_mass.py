"""Added mass: the velocity terms. The inertia term is solved exactly inside the MuJoCo step.

Wille (2016a) eqs. 8-11 with the diagonal M_A of §2.1, generalised to 6 DOF with heave and
pitch added mass (strip theory, :mod:`sailmujoco.boat.hull`). For a diagonal
M_A = diag(A1, A2) (A1 translational, A2 rotational, positive), Kirchhoff's equations give the
fluid force on a body in an unbounded ideal fluid (Fossen 2011, eqs. 6.43-6.54)

    F = -A1 nu_dot_r - omega x (A1 v_r)
    M = -A2 omega_dot - omega x (A2 omega) - v_r x (A1 v_r)

where nu_dot is the body-frame derivative of the body-frame components. Written out, the
velocity terms -C_A(nu_r) nu_r are four energy-neutral triples (each does no work on its own):

    (u, v, r)  surge  a22 v r,   sway -a11 u r,  yaw   (a11 - a22) u v   <- Munk moment, eq. 10
    (p, q, r)  roll (a55-a66) q r, pitch (a66-a44) r p, yaw (a44-a55) p q
    (u, w, q)  surge -a33 w q,   heave a11 u q,  pitch (a33 - a11) u w   <- pitch Munk moment
    (v, w, p)  sway   a33 w p,   heave -a22 v p, roll  (a22 - a33) v w   <- sway-roll term

What we keep (``coupling="manoeuvring"``, the default) and why
---------------------------------------------------------------
The first two triples are kept: the horizontal-plane triple is manoeuvring theory's added-mass
Coriolis term, Wille (2016a) eqs. 10-11, yaw Munk moment included as the paper has it; the
rotational triple needs no forward speed (it is the gyroscopic term of the added inertia).

The last two are left out. Both multiply the heave added mass a33 by a horizontal velocity.
a33 here is the high-frequency strip-theory value (free surface phi = 0), right for the
inertia of heave and pitch oscillations, which stays in the mass matrix (exact, as it was).
The two couplings, however, act as *steady* forces of forward or sideways speed: the pitch
Munk moment (a33 - a11) u w turns a trim angle theta into a moment -a33 U^2 theta, a negative
pitch stiffness of 9 461 U^2 N m/rad on the Wille yacht against its hydrostatic 514 900 N m/rad
(118 % at 8 m/s: the towed yacht blew up, bow 36-42 deg up). In forward-speed strip theory
(Salvesen, Tuck & Faltinsen 1970, Table 1) the same term is the U^2/omega^2 A33 part of A55
together with the U A33 parts of B35 and B53: inertial terms of an *oscillating* hull, derived
for the high-frequency free-surface condition, whose omega -> 0 limit is not a steady force:
as omega -> 0 the linear free-surface condition becomes the rigid-wall one (phi_z = 0),
where the 2-D heave added mass diverges (Faltinsen 1990, Sea Loads, ch. 3-5) and STF's own
validity ends (they require high frequency). The steady vertical force and trim of a surface
ship at forward speed are set by its wave system (sinkage and trim, e.g. Faltinsen 2005,
Hydrodynamics of High-Speed Marine Vehicles, ch. 4), which is a resistance-and-lift problem,
not an added-mass one; towing tanks run displacement yachts to Froude 0.75 (Delft series)
without the pitch divergence the term predicts. So no forward-speed term is kept in heave and
pitch. The sway-roll triple is left out for the same reason: in steady, heeled sailing the
body-frame w is the horizontal leeway seen in heeled axes (w = -v_h sin(phi)), and
(a22 - a33) v w would be a steady roll moment (a33 - a22) v_h^2 sin(phi) cos(phi) (about 2-3 %
of the yacht's righting moment at 3 deg leeway) built from the same high-frequency a33; the
hull's steady side force and roll moment belong to its lift and cross-flow drag (eqs. 17-18),
and Wille's roll row of eq. 11 has no such term either.
``coupling="kirchhoff"`` keeps all four triples (the unbounded-fluid form), so the effect of
leaving them out can be measured.

MuJoCo's free joint integrates the *world* acceleration a of CO, and R^T a = v_dot + omega x v.
The step adds R A1 R^T to the translational block of the mass matrix and A2 to the rotational
one (:mod:`sailmujoco.physics`), which supplies -A1 (v_dot_r + omega x v_r) and -A2 omega_dot
implicitly (with a current constant in the world frame, Wille's dV_c/dt = 0 after eq. 6, the
implicit part and the explicit one together give exactly -A1 d(v_r)/dt). The explicit force
computed here adds back A1 (omega x v_r).
"""

from __future__ import annotations

from ..jit.kernel import kernel


@kernel
def kirchhoff_terms(nu_r, a, full, out):
    """-C_A(nu_r) nu_r for a diagonal M_A (Fossen 2011 eq. 6.54) into ``out``.

    In 4 DOF (w = q = 0) the surge, sway and yaw rows are Wille (2016a) eq. 11:
    (-Y_vdot v_r r, X_udot u_r r, ..., (Y_vdot - X_udot) u_r v_r), the last being the Munk
    moment.

    Parameters
    ----------
    nu_r : numpy.ndarray, shape (6,)
        (u, v, w, p, q, r) relative to the water, body frame, m/s and rad/s.
    a : numpy.ndarray, shape (6,)
        Positive diagonal added masses (-X_udot, -Y_vdot, -Z_wdot, -K_pdot, -M_qdot, -N_rdot),
        kg and kg m^2.
    full : bool
        False: the manoeuvring and rotational triples only (module docstring); True: all four
        (unbounded ideal fluid, ``coupling="kirchhoff"``).
    out : numpy.ndarray, shape (6,)
        Receives the wrench, body frame about CO, N and N m.
    """
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    a1, a2, a3, a4, a5, a6 = a[0], a[1], a[2], a[3], a[4], a[5]
    # (u, v, r): manoeuvring, Wille eqs. 10-11
    out[0] = a2 * v * r
    out[1] = -a1 * u * r
    out[2] = 0.0
    out[5] = (a1 - a2) * u * v
    # (p, q, r): rotational
    out[3] = (a5 - a6) * q * r
    out[4] = (a6 - a4) * r * p
    out[5] += (a4 - a5) * p * q
    if full:
        # (u, w, q): pitch Munk moment and partners
        out[0] -= a3 * w * q
        out[2] += a1 * u * q
        out[4] += (a3 - a1) * u * w
        # (v, w, p): sway-roll term and partners
        out[1] += a3 * w * p
        out[2] -= a2 * v * p
        out[3] += (a2 - a3) * v * w


@kernel
def added_mass_velocity_terms(nu_r, a, full, out):
    """Explicit added-mass wrench for the MuJoCo step (body frame, about CO) into ``out``.

    The kept Kirchhoff terms plus A1 (omega x v_r), which undoes the omega x v_r that the
    world-frame acceleration in the augmented mass matrix brings in (module docstring).

    Parameters
    ----------
    nu_r : numpy.ndarray, shape (6,)
        (u, v, w, p, q, r) relative to the water, body frame, m/s and rad/s.
    a : numpy.ndarray, shape (6,)
        Positive diagonal added masses (-X_udot, -Y_vdot, -Z_wdot, -K_pdot, -M_qdot, -N_rdot),
        kg and kg m^2.
    full : bool
        False: the manoeuvring and rotational triples only (module docstring); True: all four
        (unbounded ideal fluid, ``coupling="kirchhoff"``).
    out : numpy.ndarray, shape (6,)
        Receives the wrench, body frame about CO, N and N m.
    """
    kirchhoff_terms(nu_r, a, full, out)
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    out[0] += a[0] * (q * w - r * v)
    out[1] += a[1] * (r * u - p * w)
    out[2] += a[2] * (p * v - q * u)
