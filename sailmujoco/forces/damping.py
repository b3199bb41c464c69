"""Hull damping, Wille (2016a) eqs. 12-19, written in the FLU body frame, plus heave and pitch.

D(nu_r) stands on the left of eq. 3, so the force on the hull is -D(nu_r). Every term is odd
in the velocity it damps, so the FRD formulas hold unchanged in FLU.

Heave and pitch damping (d33, d55) are ours: the papers hold heave and pitch. They stand for
wave-radiation damping, which is a reaction to the hull's *vertical* motion. So they act on the
motion that exists, not on body-frame w and q: a heeled and trimmed boat sailing straight has
body w = U sin(trim) ... and body q = r sin(heel) in a turn while nothing moves vertically, and
damping on those (the ``body`` form, kept to measure it) pushes the boats 2-3 % deep in steady sailing.
Here (``vertical_damping``):

    F = -d33 dz_F/dt e_z      at the centre of flotation F (world vertical, through F)
    M = -d55 dtheta/dt (-y1)  about y1 = e_z x (horizontal heading direction)

with z_F the world height of the upright waterplane's centroid and theta the pitch angle
(bow up). Both rates are exactly zero in steady sailing, straight or turning, at any heel and
trim; the power is -d33 zF_dot^2 - d55 theta_dot^2 <= 0.
"""

from __future__ import annotations

import math

from ..jit.kernel import kernel

# Below this Reynolds number eq. 16 is outside its range (it is singular at Re = 100);
# C_F is held at its value here (the hull then moves at < 2 cm/s and linear damping rules).
MIN_REYNOLDS = 1.0e5


@kernel
def ittc_friction_coefficient(reynolds):
    """ITTC-1957 friction line C_F = 0.075 / (log10 Re - 2)^2, Wille (2016a) eq. 16.

    Parameters
    ----------
    reynolds : float
        Reynolds number, -; held at ``MIN_REYNOLDS`` from below.
    """
    lr = math.log10(max(reynolds, MIN_REYNOLDS))
    return 0.075 / ((lr - 2.0) * (lr - 2.0))


@kernel
def surge_resistance(u_r, rho, wetted_surface, form_factor, length, nu):
    """ITTC surge drag force (N), Wille (2016a) eq. 15: -1/2 rho S_H (1 + k) C_F(Re) |u_r| u_r.

    Parameters
    ----------
    u_r : float
        Surge velocity relative to the water (body x), m/s.
    rho : float
        Water density, kg/m^3.
    wetted_surface : float
        Wetted surface S_H, m^2.
    form_factor : float
        Form factor k, -.
    length : float
        Waterline length (the Reynolds number's length), m.
    nu : float
        Kinematic viscosity of the water, m^2/s.
    """
    reynolds = abs(u_r) * length / nu
    cf = ittc_friction_coefficient(reynolds)
    return -0.5 * rho * wetted_surface * (1.0 + form_factor) * cf * abs(u_r) * u_r


@kernel
def crossflow_drag(v_r, r, rho, cd, strip_x, strip_w, strip_draft):
    """Cross-flow drag (sway force, yaw moment), Wille (2016a) eqs. 17-18, Gauss-Legendre strips along x.

    Parameters
    ----------
    v_r, r : float
        Sway velocity relative to the water (body y, m/s) and yaw rate (body z, rad/s).
    rho : float
        Water density, kg/m^3.
    cd : float
        Cross-flow drag coefficient, -.
    strip_x, strip_w, strip_draft : numpy.ndarray, shape (n,)
        Gauss-Legendre strips along the hull: body x of each strip (m, forward of CO), its
        quadrature weight (m) and the hull's draft there (m).

    Returns
    -------
    fy, mz : float
        Body-y force (N) and body-z moment about CO (N m).
    """
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
    """Roll damping moment about body x (N m), Wille (2016a) eq. 19 (Himeno 1981 / Kato).

    The extracted eq. 19 reads B_F0 (L_WL + 4.1 u/(omega L_WL)) p, which adds metres to a
    dimensionless term. Kato's friction damping, which Himeno quotes, is
    B_F = B_F0 (1 + 4.1 u / (omega L)); we use that. |u_r| replaces u_r so that neither
    term turns into negative damping when the boat moves astern.

    Parameters
    ----------
    p : float
        Roll rate (body x), rad/s.
    u_r : float
        Surge velocity relative to the water, m/s.
    roll_friction : float
        Friction component B_F0, N m s/rad.
    roll_lift : float
        Lift component per unit speed, N m s^2/(m rad) (times |u_r| it is N m s/rad).
    roll_frequency : float
        Roll natural frequency omega, rad/s.
    length : float
        Waterline length L_WL, m.
    """
    speed = abs(u_r)
    b = roll_friction * (1.0 + 4.1 * speed / (roll_frequency * length)) + roll_lift * speed
    return -b * p


@kernel
def pitch_angle_rate(rot, q, r):
    """The rate of the pitch angle theta = asin(R20) (bow up), rad/s: (R21 r - R22 q) / cos(theta).

    Parameters
    ----------
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    q, r : float
        Body pitch and yaw rates, rad/s.
    """
    cos_theta = math.sqrt(rot[2, 1] * rot[2, 1] + rot[2, 2] * rot[2, 2])
    if cos_theta < 1e-9:
        return 0.0
    return (rot[2, 1] * r - rot[2, 2] * q) / cos_theta


@kernel
def vertical_damping(rot, nu, flotation_x, d33, d55, water_dz, water_dpitch, out):
    """Heave and pitch damping on the vertical motion (module docstring); adds to ``out``.

    The hull's body velocity is used for the vertical motion: the current is horizontal, so
    relative and absolute vertical motion agree in calm water; in a sea the water's own heave
    and pitch rates at the waterplane are subtracted (the damping acts on the motion relative
    to the water: a hull carried by a long wave is not damped).

    Parameters
    ----------
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    nu : numpy.ndarray, shape (6,)
        (u, v, w, p, q, r) of the hull, body frame, m/s and rad/s.
    flotation_x : float
        Centre of flotation forward of CO along body x, m (on the waterline, z = 0).
    d33 : float
        Heave damping on dz_F/dt, N s/m.
    d55 : float
        Pitch damping on dtheta/dt, N m s/rad.
    water_dz, water_dpitch : float
        The water's vertical velocity at F (m/s) and its surface's pitch rate (rad/s, bow up
        positive); 0 in calm water.
    out : numpy.ndarray, shape (6,)
        The body-frame wrench about CO (N, N m) the damping is added to.
    """
    u, v, w, q, r = nu[0], nu[1], nu[2], nu[4], nu[5]
    r20, r21, r22 = rot[2, 0], rot[2, 1], rot[2, 2]
    # velocity of F = (x_F, 0, 0) in the body frame: v + omega x r_F = (u, v + r x_F, w - q x_F)
    zf_dot = r20 * u + r21 * (v + r * flotation_x) + r22 * (w - q * flotation_x) - water_dz
    fz = -d33 * zf_dot  # world vertical, at F
    out[0] += fz * r20
    out[1] += fz * r21
    out[2] += fz * r22
    # moment of that force about CO: r_F x F_body = (0, -x_F F_bz, x_F F_by)
    out[4] += -flotation_x * fz * r22
    out[5] += flotation_x * fz * r21
    if r21 * r21 + r22 * r22 < 1e-18:  # bow straight up or down: no pitch angle to damp
        return
    theta_dot = pitch_angle_rate(rot, q, r) - water_dpitch
    # y1 = e_z x (R00, R10, 0)/|.| (world, horizontal, to port); its body components R^T y1
    hx, hy = rot[0, 0], rot[1, 0]
    hn = math.sqrt(hx * hx + hy * hy)
    if hn < 1e-12:  # bow straight up or down: the check above would have caught it
        return
    y1x, y1y = -hy / hn, hx / hn
    m = d55 * theta_dot  # moment along +y1 (pushes the bow down when theta_dot > 0)
    out[3] += m * (rot[0, 0] * y1x + rot[1, 0] * y1y)
    out[4] += m * (rot[0, 1] * y1x + rot[1, 1] * y1y)
    out[5] += m * (rot[0, 2] * y1x + rot[1, 2] * y1y)


@kernel
def hull_damping(rot, nu_r, rho, linear, wetted_surface, form_factor, length, nu, crossflow_cd,
                 strip_x, strip_w, strip_draft, roll_friction, roll_lift, roll_frequency,
                 flotation_x, body_frame_vertical, water_dz, water_dpitch, out):
    """Total hull damping wrench (body frame, about CO) into ``out``.

    Linear damping (eq. 13) plus ITTC surge resistance (eqs. 15-16), cross-flow drag (eqs.
    17-18) and roll damping (eq. 19) of Wille (2016a); heave and pitch (d33, d55) are ours (the
    papers hold them), acting on the vertical motion (:func:`vertical_damping`), or, with
    ``body_frame_vertical``, on body w and q (kept to measure the difference).

    Parameters
    ----------
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    nu_r : numpy.ndarray, shape (6,)
        (u, v, w, p, q, r) relative to the water, body frame, m/s and rad/s.
    rho : float
        Water density, kg/m^3.
    linear : numpy.ndarray, shape (5,)
        (d11, d22, d33, d55, d66): surge and sway (N s/m), heave (N s/m), pitch and yaw
        (N m s/rad) linear damping; eq. 13 gives d11, d22, d66.
    wetted_surface, form_factor, length, nu : float
        S_H (m^2), k (-), waterline length (m) and the water's kinematic viscosity (m^2/s), as
        for :func:`surge_resistance`.
    crossflow_cd : float
        Cross-flow drag coefficient, -.
    strip_x, strip_w, strip_draft : numpy.ndarray, shape (n,)
        Gauss-Legendre strips along the hull: body x of each strip (m, forward of CO), its
        quadrature weight (m) and the hull's draft there (m).
    roll_friction, roll_lift, roll_frequency : float
        B_F0 (N m s/rad), the lift component per unit speed (N m s^2/(m rad)) and the roll
        natural frequency (rad/s), as for :func:`roll_damping`.
    flotation_x : float
        Centre of flotation forward of CO, m.
    body_frame_vertical : bool
        Heave and pitch damping on body w and q instead of the vertical motion.
    water_dz, water_dpitch : float
        The water's vertical velocity at the centre of flotation (m/s) and its surface's pitch
        rate (rad/s) in a sea (:func:`sailmujoco.forces.sea_hull.hull_sea_wrench`), which the
        vertical damping acts relative to; 0 in calm water.
    out : numpy.ndarray, shape (6,)
        Receives the wrench, N and N m.
    """
    u, v, w, p, q, r = nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5]
    fy_cf, mz_cf = crossflow_drag(v, r, rho, crossflow_cd, strip_x, strip_w, strip_draft)
    out[0] = -linear[0] * u + surge_resistance(u, rho, wetted_surface, form_factor, length, nu)
    out[1] = -linear[1] * v + fy_cf
    out[2] = 0.0
    out[3] = roll_damping(p, u, roll_friction, roll_lift, roll_frequency, length)
    out[4] = 0.0
    out[5] = -linear[4] * r + mz_cf
    if body_frame_vertical:
        out[2] = -linear[2] * w
        out[4] = -linear[3] * q
    else:
        vertical_damping(rot, nu_r, flotation_x, linear[2], linear[3], water_dz, water_dpitch, out)
