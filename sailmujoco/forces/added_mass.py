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

What we keep (``coupling="impulse"``, the default) and why
-----------------------------------------------------------
The first two triples are kept whole: the horizontal-plane triple is manoeuvring theory's
added-mass Coriolis term, Wille (2016a) eqs. 10-11, yaw Munk moment included as the paper has
it; the rotational triple needs no forward speed (it is the gyroscopic term of the added
inertia).

Of the (u, w, q) triple the *forces* are kept, for the hull's pitching, and the *moment* left
out. The force part of Kirchhoff's equations is exactly minus the rate of change of the fluid's
impulse A1 v_r (Newman 1977, Marine Hydrodynamics, §4.13; Lamb 1932, §§ 117-121):

    F_world = -d/dt (R A1 v_r),

so over any periodic motion its mean is zero: added mass cannot push a hull through the water
on average. The mass matrix's part, -R A1 R^T a (:mod:`sailmujoco.physics`), turns with the hull:
pitched by theta, its heave added mass gives a surge force a33 theta z_ddot, whose mean over a
heave and pitch is -a33 <theta_dot z_dot>; the surge term -a33 w q cancels it. Without it (the
``"manoeuvring"`` form) a hull heaving and pitching in head waves is pushed by the mean
a33 <w q>: a third of the yacht's added resistance at its peak (measured with
:mod:`sailmujoco.design.added_resistance`; the reason this form is the default). Its partner
a11 u q, the heave force of pitching at speed, is kept with it.

q in these two forces is the rate of the hull's pitch angle
(:func:`sailmujoco.forces.damping.pitch_angle_rate`, as the pitch damping takes it), not the
body rate: upright they are the same, but in a steady heeled turn body q = r sin(phi) and body
w = -v_h sin(phi) (the leeway seen in heeled axes) are steady, and -a33 w q would be a steady
surge force a33 v_h r sin^2(phi) of the high-frequency heave added mass in a motion that is
horizontal. On the 300 kg viel_boat, whose a33 is 3.2 times its mass, that force slowed the
position-keeping runs of Viel's controller, which turns all the time, from a mean 1.43 to
1.01 m/s; with the pitch angle's rate it is zero in any steady turn, and in head waves it is the
upright form's.

The moment left out is the pitch Munk moment (a33 - a11) u w. It multiplies the heave added
mass a33 by the forward speed and acts as a *steady* moment: it turns a trim angle theta into a
moment -a33 U^2 theta, a negative pitch stiffness of 9 461 U^2 N m/rad on the Wille yacht
against its hydrostatic 514 900 N m/rad (118 % at 8 m/s: the towed yacht blew up, bow 36-42 deg
up; in long head waves at Froude 0.2 the yacht pitches 0.68 of the wave's slope with it). a33
here is the high-frequency strip-theory value (free surface phi = 0), right for the inertia of
heave and pitch oscillations, which stays in the mass matrix. In forward-speed strip theory
(Salvesen, Tuck & Faltinsen 1970, Table 1) the same term is the U^2/omega^2 A33 part of A55
together with the U A33 parts of B35 and B53: inertial terms of an *oscillating* hull, derived
for the high-frequency free-surface condition, whose omega -> 0 limit is not a steady moment: as
omega -> 0 the linear free-surface condition becomes the rigid-wall one (phi_z = 0), where the
2-D heave added mass diverges (Faltinsen 1990, Sea Loads, ch. 3-5) and STF's own validity ends.
The steady trim of a surface ship at forward speed is set by its wave system (sinkage and trim,
e.g. Faltinsen 2005, Hydrodynamics of High-Speed Marine Vehicles, ch. 4), a resistance-and-lift
problem, not an added-mass one; towing tanks run displacement yachts to Froude 0.75 (Delft
series) without the pitch divergence the term predicts. Without the moment the kept forces do
work, (a11 - a33) u w q: the work the moment would have taken.

The (v, w, p) triple is left out whole, forces and moment. In steady, heeled sailing the
body-frame w is the horizontal leeway seen in heeled axes (w = -v_h sin(phi)), and the roll
moment (a22 - a33) v w would be a steady (a33 - a22) v_h^2 sin(phi) cos(phi) (about 2-3 % of
the yacht's righting moment at 3 deg leeway) built from the same high-frequency a33; the hull's
steady side force and roll moment belong to its lift and cross-flow drag (eqs. 17-18), and
Wille's roll row of eq. 11 has none. Its forces, a33 w p and -a22 v p, would put that heave
added mass into large rolls, where the heeled body z is nearly horizontal (on the 15 kg robot,
whose a33 is 2.8 times its mass and whose CG lies 0.84 m below CO, a sway force a33 w p is a
roll moment about the CG). Their mean over a periodic roll and heave, a33 <w p>, is third
order in a symmetric hull's motions (w = z_dot cos(phi) - v_h sin(phi)).

The other forms, kept so that their effect can be measured:
``coupling="manoeuvring"`` leaves out both lower triples whole (energy-neutral, but its surge
force has the mean above); ``coupling="kirchhoff"`` keeps all four (the unbounded-fluid form).

MuJoCo's free joint integrates the *world* acceleration a of CO, and R^T a = v_dot + omega x v.
The step adds R A1 R^T to the translational block of the mass matrix and A2 to the rotational
one (:mod:`sailmujoco.physics`), which supplies -A1 (v_dot_r + omega x v_r) and -A2 omega_dot
implicitly (with a current constant in the world frame, Wille's dV_c/dt = 0 after eq. 6, the
implicit part and the explicit one together give exactly -A1 d(v_r)/dt). The explicit force
computed here adds back A1 (omega x v_r).
"""

from __future__ import annotations

from ..jit.kernel import kernel

IMPULSE, MANOEUVRING, KIRCHHOFF = 0, 1, 2  # the kernel's codes: indices in options' AddedMassCoupling


@kernel
def kirchhoff_terms(nu_r, a, coupling, pitch_rate, out):
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
    coupling : int
        ``IMPULSE``: the manoeuvring and rotational triples and the forces of (u, w, q), with
        the pitch angle's rate for q; ``MANOEUVRING``: the manoeuvring and rotational triples
        only; ``KIRCHHOFF``: all four (unbounded ideal fluid). Module docstring.
    pitch_rate : float
        The rate of the hull's pitch angle, rad/s, bow up (:func:`.damping.pitch_angle_rate`; read by
        ``IMPULSE`` only).
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
    if coupling == IMPULSE:
        # the forces of (u, w, q) in the pitching of the hull: the fluid impulse's rate
        pitching = -pitch_rate  # a bow-up pitch rate is a negative rate about body y
        out[0] -= a3 * w * pitching
        out[2] += a1 * u * pitching
    if coupling == KIRCHHOFF:
        # the pitch Munk moment and partners, and the sway-roll triple
        out[0] -= a3 * w * q
        out[2] += a1 * u * q
        out[4] += (a3 - a1) * u * w
        out[1] += a3 * w * p
        out[2] -= a2 * v * p
        out[3] += (a2 - a3) * v * w


@kernel
def added_mass_velocity_terms(nu_r, a, coupling, pitch_rate, out):
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
    coupling : int
        ``IMPULSE``, ``MANOEUVRING`` or ``KIRCHHOFF`` (:func:`kirchhoff_terms`).
    pitch_rate : float
        The rate of the hull's pitch angle, rad/s, bow up (:func:`.damping.pitch_angle_rate`).
    out : numpy.ndarray, shape (6,)
        Receives the wrench, body frame about CO, N and N m.
    """
    kirchhoff_terms(nu_r, a, coupling, pitch_rate, out)
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    out[0] += a[0] * (q * w - r * v)
    out[1] += a[1] * (r * u - p * w)
    out[2] += a[2] * (p * v - q * u)
