"""Wille's 4-DOF equations as compiled kernels: the force terms, the right-hand side and the RK4
of one control period (:class:`sailmujoco.reference.wille.Wille4DOF` holds the state and the
readings; its module docstring explains the model and the ``paper``/``rigid`` forms).

The kernels read the boat and the switches from one flat float64 array (:func:`pack_parameters`,
indices below) and do the arithmetic of the model written in plain Python, in its order: run
interpreted (``NUMBA_DISABLE_JIT=1``) they give the compiled results bit for bit, and they match
the plain-Python model's trajectories (``tests/data/paper_worlds_python_reference.json``) to
rounding (``tests/test_paper_world_identity.py``). The force functions
are those of the 6-DOF boat (:mod:`sailmujoco.forces`), the wind is :func:`wind_velocity`.
"""

from __future__ import annotations

import math

import numpy as np

from ..constants import GRAVITY
from ..forces.added_mass import MANOEUVRING, kirchhoff_terms
from ..forces.damping import crossflow_drag, roll_damping, surge_resistance
from ..forces.foil_geometry import foil_world_force, lift_drag_components, section_flow
from ..forces.foil_sections import hydrofoil_coefficients
from ..forces.hydrostatics import paper_righting_moment
from ..forces.sail import flat_sail_force
from ..forces.wind import wind_velocity
from ..jit.kernel import kernel
from ..jit.ordered import solve
from .integrators import STATUS_RAN_AWAY, final_status, rk4_stage, rk4_update

TERMS = ("sail", "keel", "rudder", "restoring", "damping", "added_mass", "coriolis", "external")
(SAIL, KEEL, RUDDER, RESTORING, DAMPING, ADDED_MASS, CORIOLIS, EXTERNAL) = range(len(TERMS))

# indices of the packed parameters
(MASS, A1, A2, A3, A4, A5, A6, IXX, IYY, IZZ, RIGHTING, RIGHTING_SIN,
 L1, L2, H1, L3, H2, L4, H3,
 SAIL_EFFICIENCY, SAIL_STALL, SAIL_FRICTION, RHO_AIR, SAIL_AREA, SAIL_T, RUDDER_T,
 KEEL_CHORD, KEEL_AREA, KEEL_ASPECT, KEEL_THICKNESS,
 RUDDER_CHORD, RUDDER_AREA, RUDDER_ASPECT, RUDDER_THICKNESS,
 RHO_WATER, NU_WATER, D11, D22, D66, CROSSFLOW_CD, WETTED_SURFACE, FORM_FACTOR, LENGTH,
 ROLL_FRICTION, ROLL_LIFT, ROLL_FREQUENCY,
 ON_SAIL, ON_TANGENTIAL, ON_KEEL, ON_RUDDER, ON_DAMPING, ON_ADDED_MASS, RIGID, N_PARAMETERS) = range(54)


def pack_parameters(p, switches, model: str) -> np.ndarray:
    """The flat float64 array the kernels read, laid out by the indices of this module.

    Parameters
    ----------
    p : BoatParams
        The boat (SI; positions body FLU, converted here to the paper's lever arms l1..l4,
        h1..h3).
    switches : ForceSwitches
        Which force terms are on (1.0 on).
    model : str
        ``"paper"`` or ``"rigid"`` (the ``RIGID`` entry 1.0).
    """
    d11, d22, _, _, d66 = p.linear_damping
    values = {
        MASS: p.mass, IXX: p.inertia[0], IYY: p.inertia[1], IZZ: p.inertia[2],
        RIGHTING: p.rho_water * GRAVITY * p.displaced_volume * p.gm_t,
        RIGHTING_SIN: p.paper_righting == "sin",
        L1: -p.sail.mast_x, L2: p.sail.ce_aft, H1: p.sail.ce_height,
        L3: -p.keel.x, H2: -p.keel.z, L4: -p.rudder.x, H3: -p.rudder.z,
        SAIL_EFFICIENCY: p.sail.suction_efficiency, SAIL_STALL: p.sail.suction_stall,
        SAIL_FRICTION: p.sail.friction_coefficient, RHO_AIR: p.rho_air, SAIL_AREA: p.sail.area,
        SAIL_T: p.sail.time_constant, RUDDER_T: p.rudder.time_constant,
        KEEL_CHORD: p.keel.chord, KEEL_AREA: p.keel.area, KEEL_ASPECT: p.keel.aspect_ratio,
        KEEL_THICKNESS: p.keel.thickness_ratio,
        RUDDER_CHORD: p.rudder.chord, RUDDER_AREA: p.rudder.area, RUDDER_ASPECT: p.rudder.aspect_ratio,
        RUDDER_THICKNESS: p.rudder.thickness_ratio,
        RHO_WATER: p.rho_water, NU_WATER: p.nu_water, D11: d11, D22: d22, D66: d66,
        CROSSFLOW_CD: p.crossflow_cd, WETTED_SURFACE: p.wetted_surface, FORM_FACTOR: p.form_factor,
        LENGTH: p.hull.length, ROLL_FRICTION: p.roll_friction, ROLL_LIFT: p.roll_lift,
        ROLL_FREQUENCY: p.roll_frequency,
        ON_SAIL: switches.sail, ON_TANGENTIAL: switches.sail_tangential, ON_KEEL: switches.keel,
        ON_RUDDER: switches.rudder, ON_DAMPING: switches.damping, ON_ADDED_MASS: switches.added_mass,
        RIGID: model == "rigid",
    }
    for i, a in enumerate(p.added_mass_diagonal):
        values[A1 + i] = a
    packed = np.zeros(N_PARAMETERS)
    for index, value in values.items():
        packed[index] = float(value)
    return packed


@kernel
def ran_away(state, P):
    """True where the Python model raised ValueError.

    That is: math.cos or math.sin of an infinite angle (heel, heading, and the rudder and sail
    angles where those forces act).

    Parameters
    ----------
    state : numpy.ndarray, shape (10,)
        The paper's state (x, y, phi, psi, u, v, p, r, sigma, lam): NED position (m), heel and
        heading (rad), FRD velocities (m/s, rad/s), rudder and sail angles (rad)
        (:data:`sailmujoco.reference.wille.STATE`).
    P : numpy.ndarray, shape (N_PARAMETERS,)
        The boat and switches as packed by :func:`pack_parameters`, laid out by its indices.
    """
    return (math.isinf(state[2]) or math.isinf(state[3]) or (P[ON_SAIL] != 0.0 and math.isinf(state[9]))
            or (P[ON_RUDDER] != 0.0 and math.isinf(state[8])))


@kernel
def sail_flow(t, state, P, lam_d, wind, speed10, direction_from, oscillation, frequency, phase, amplitude,
              log_z, wander_dt, wander):
    """V_ws, the air velocity relative to the sail CE in FRD, Wille (2016a) eq. 26.

    The wind is taken at eq. 42's height, h1 cos(phi).

    Parameters
    ----------
    t : float
        Time, s.
    state : numpy.ndarray, shape (10,)
        The paper's state (x, y, phi, psi, u, v, p, r, sigma, lam): NED position (m), heel and
        heading (rad), FRD velocities (m/s, rad/s), rudder and sail angles (rad)
        (:data:`sailmujoco.reference.wille.STATE`).
    P : numpy.ndarray, shape (N_PARAMETERS,)
        The boat and switches as packed by :func:`pack_parameters`, laid out by its indices.
    lam_d : float
        Commanded sail angle, rad (the sail's rate is its lag toward it).
    wind : numpy.ndarray, shape (3,)
        Receives the world wind at the CE, ENU, m/s.
    speed10, direction_from : float
        Mean wind speed at 10 m (m/s) and the compass bearing it comes from (rad).
    oscillation : numpy.ndarray, shape (3,)
        The wind's modulation: speed (m/s), direction (rad), frequency (Hz).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`~sailmujoco.forces.wind.WindField`: f_k (Hz), Y_k (rad), the
        amplitudes sqrt(2 S df) (m/s), shape (m, n), at the heights whose ln (m) is ``log_z`` (m,).
    wander_dt : float
        Time step of ``wander``, s.
    wander : numpy.ndarray
        The direction wander (rad) at ``k wander_dt`` seconds (Wille (2016a) eq. 43).

    Returns
    -------
    vws_u, vws_v : float
        The FRD (x, y) components, m/s.
    """
    phi, psi, u, v, pr, r, lam = state[2], state[3], state[4], state[5], state[6], state[7], state[9]
    cphi, cpsi, spsi = math.cos(phi), math.cos(psi), math.sin(psi)
    wind_velocity(t, P[H1] * cphi, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z,
                  wander_dt, wander, wind)  # ENU; eq. 42: CE at h1 cos(phi)
    wu = cpsi * wind[1] + spsi * wind[0]  # J_2D^T V_w, eq. 6
    wv = -spsi * cphi * wind[1] + cpsi * cphi * wind[0]
    lam_dot = (lam_d - lam) / P[SAIL_T]
    l1, l2, h1 = P[L1], P[L2], P[H1]
    cl, sl = math.cos(lam), math.sin(lam)
    vws_u = wu - u - r * l2 * sl - lam_dot * l2 * sl  # eq. 26
    vws_v = wv - v - (-r * (l1 + l2 * cl) + pr * h1) - (-lam_dot * l2 * cl)
    return vws_u, vws_v


@kernel
def force_terms(t, state, P, sigma_d, lam_d, external, a, strip_x, strip_w, strip_draft, alpha_grid,
                log_re_grid, cl_table, cd_table, current, speed10, direction_from, oscillation, frequency,
                phase, amplitude, log_z, wander_dt, wander, work, out):
    """Every (X, Y, K, N, M) term in FRD at (t, state) into ``out``, Wille (2016a) eqs. 3-36.

    Rows in the order of ``TERMS``, signs as on the right of eq. 3 (M, the pitch moment, is not
    in the paper's model; only ``model="rigid"`` uses it). Returns False where the Python model
    raised (:func:`ran_away`), with ``out`` untouched.

    Parameters
    ----------
    t : float
        Time, s.
    state : numpy.ndarray, shape (10,)
        The paper's state (x, y, phi, psi, u, v, p, r, sigma, lam): NED position (m), heel and
        heading (rad), FRD velocities (m/s, rad/s), rudder and sail angles (rad)
        (:data:`sailmujoco.reference.wille.STATE`).
    P : numpy.ndarray, shape (N_PARAMETERS,)
        The boat and switches as packed by :func:`pack_parameters`, laid out by its indices.
    sigma_d, lam_d : float
        Commanded rudder and sail angles, rad (the actuators lag toward them, §2.1).
    external : numpy.ndarray, shape (4,)
        External (X, Y, K, N), FRD, N and N m.
    a : numpy.ndarray, shape (6,)
        Positive diagonal added masses (-X_udot, ..., -N_rdot), kg and kg m^2.
    strip_x, strip_w, strip_draft : numpy.ndarray, shape (n,)
        Cross-flow strips: x forward of CO (m), quadrature weights (m), drafts (m)
        (:func:`sailmujoco.forces.damping.crossflow_drag`).
    alpha_grid, log_re_grid, cl_table, cd_table : numpy.ndarray
        The NACA 0015 section table (:func:`sailmujoco.forces.foil_sections.section_coefficients`).
    current : numpy.ndarray, shape (3,)
        The current, world ENU, m/s (where the water goes).
    speed10, direction_from : float
        Mean wind speed at 10 m (m/s) and the compass bearing it comes from (rad).
    oscillation : numpy.ndarray, shape (3,)
        The wind's modulation: speed (m/s), direction (rad), frequency (Hz).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`~sailmujoco.forces.wind.WindField`: f_k (Hz), Y_k (rad), the
        amplitudes sqrt(2 S df) (m/s), shape (m, n), at the heights whose ln (m) is ``log_z`` (m,).
    wander_dt : float
        Time step of ``wander``, s.
    wander : numpy.ndarray
        The direction wander (rad) at ``k wander_dt`` seconds (Wille (2016a) eq. 43).
    work : numpy.ndarray, shape (7, 6)
        Work space.
    out : numpy.ndarray, shape (len(TERMS), 5)
        Receives the terms, N and N m.
    """
    if ran_away(state, P):
        return False
    phi, psi, u, v, pr, r, sigma, lam = (state[2], state[3], state[4], state[5], state[6], state[7], state[8],
                                         state[9])
    cphi, cpsi, spsi = math.cos(phi), math.cos(psi), math.sin(psi)
    # J_2D^T(psi, phi) of eq. 6 times the current in NED
    cu = cpsi * current[1] + spsi * current[0]
    cv = -spsi * cphi * current[1] + cpsi * cphi * current[0]
    u_r, v_r = u - cu, v - cv  # eq. 5
    out[:, :] = 0.0
    l1, l2, h1 = P[L1], P[L2], P[H1]
    flow, chord, normal, force = work[0], work[1], work[2], work[3]

    if P[ON_SAIL] != 0.0:
        vws_u, vws_v = sail_flow(t, state, P, lam_d, work[6], speed10, direction_from, oscillation, frequency,
                                 phase, amplitude, log_z, wander_dt, wander)
        cl, sl = math.cos(lam), math.sin(lam)
        flow[0], flow[1], flow[2] = vws_u, -vws_v, 0.0  # FRD -> FLU
        flat_sail_force(flow, lam, P[ON_TANGENTIAL] != 0.0, P[SAIL_EFFICIENCY], P[SAIL_STALL],
                        P[SAIL_FRICTION], P[RHO_AIR], P[SAIL_AREA], chord, normal, force)
        sx, sy = force[0], -force[1]  # FLU -> FRD
        row = out[SAIL]
        row[0], row[1], row[2] = sx, sy, h1 * sy
        row[3] = sx * l2 * sl - sy * (l1 + l2 * cl)  # eq. 29
        row[4] = -h1 * sx

    for term in (KEEL, RUDDER):
        base = KEEL_CHORD if term == KEEL else RUDDER_CHORD
        if term == KEEL:
            on, x_arm, z_arm, angle = P[ON_KEEL], P[L3], P[H2], 0.0
        else:
            on, x_arm, z_arm, angle = P[ON_RUDDER], P[L4], P[H3], sigma
        if on == 0.0:
            continue
        vc_u = -u_r  # eqs. 30 and 34
        vc_v = -v_r - (-r * x_arm - pr * z_arm)
        flow[0], flow[1], flow[2] = vc_u, -vc_v, 0.0
        chord[0], chord[1], chord[2] = math.cos(angle), -math.sin(angle), 0.0
        normal[0], normal[1], normal[2] = math.sin(angle), math.cos(angle), 0.0
        wc, wn, speed, alpha = section_flow(flow, chord, normal)
        re = speed * P[base] / P[NU_WATER]  # base + 0..3: chord, area, aspect ratio, thickness ratio
        c_l, c_d = hydrofoil_coefficients(alpha, re, P[base + 2], P[base + 3], alpha_grid, log_re_grid,
                                          cl_table, cd_table)
        q_area = 0.5 * P[RHO_WATER] * speed * speed * P[base + 1]
        fc, fn = lift_drag_components(wc, wn, speed, q_area, c_l, c_d)
        foil_world_force(fc, fn, chord, normal, force)
        fx, fy = force[0], -force[1]
        row = out[term]
        row[0], row[1], row[2], row[3], row[4] = fx, fy, -z_arm * fy, -x_arm * fy, z_arm * fx  # eqs. 33, 36

    out[RESTORING, 2] = paper_righting_moment(phi, P[RIGHTING], P[RIGHTING_SIN] != 0.0)

    if P[ON_DAMPING] != 0.0:  # eqs. 12-19
        fy, mz = crossflow_drag(v_r, r, P[RHO_WATER], P[CROSSFLOW_CD], strip_x, strip_w, strip_draft)
        row = out[DAMPING]
        row[0] = -P[D11] * u_r + surge_resistance(u_r, P[RHO_WATER], P[WETTED_SURFACE], P[FORM_FACTOR],
                                                  P[LENGTH], P[NU_WATER])
        row[1] = -P[D22] * v_r + fy
        row[2] = roll_damping(pr, u_r, P[ROLL_FRICTION], P[ROLL_LIFT], P[ROLL_FREQUENCY], P[LENGTH])
        row[3] = -P[D66] * r + mz
    if P[ON_ADDED_MASS] != 0.0:  # -C_A(nu_r) nu_r, eqs. 10-11
        nu_r, kirch = work[4], work[5]
        nu_r[0], nu_r[1], nu_r[2], nu_r[3], nu_r[4], nu_r[5] = u_r, v_r, 0.0, pr, 0.0, r
        kirchhoff_terms(nu_r, a, MANOEUVRING, 0.0, kirch)  # Wille eqs. 10-11 (4 DOF)
        row = out[ADDED_MASS]
        row[0], row[1], row[2], row[3] = kirch[0], kirch[1], kirch[3], kirch[5]
    row = out[CORIOLIS]  # -C_RB nu (eq. 9, module docstring of wille.py)
    row[0], row[1] = P[MASS] * r * v, -P[MASS] * r * u
    row = out[EXTERNAL]
    row[0], row[1], row[2], row[3] = external[0], external[1], external[2], external[3]
    return True


@kernel
def rates(t, state, P, sigma_d, lam_d, external, a, strip_x, strip_w, strip_draft, alpha_grid, log_re_grid,
          cl_table, cd_table, current, speed10, direction_from, oscillation, frequency, phase, amplitude,
          log_z, wander_dt, wander, mass_matrix, mass_inverse, terms, work, out):
    """d/dt of the state (Wille (2016a) eqs. 3-4 and the actuator lags) into ``out``.

    Returns False where the Python model raised (:func:`ran_away`).

    Parameters
    ----------
    t : float
        Time, s.
    state : numpy.ndarray, shape (10,)
        The paper's state (x, y, phi, psi, u, v, p, r, sigma, lam): NED position (m), heel and
        heading (rad), FRD velocities (m/s, rad/s), rudder and sail angles (rad)
        (:data:`sailmujoco.reference.wille.STATE`).
    P : numpy.ndarray, shape (N_PARAMETERS,)
        The boat and switches as packed by :func:`pack_parameters`, laid out by its indices.
    sigma_d, lam_d : float
        Commanded rudder and sail angles, rad (the actuators lag toward them, §2.1).
    external : numpy.ndarray, shape (4,)
        External (X, Y, K, N), FRD, N and N m.
    a : numpy.ndarray, shape (6,)
        Positive diagonal added masses (-X_udot, ..., -N_rdot), kg and kg m^2.
    strip_x, strip_w, strip_draft : numpy.ndarray, shape (n,)
        Cross-flow strips: x forward of CO (m), quadrature weights (m), drafts (m)
        (:func:`sailmujoco.forces.damping.crossflow_drag`).
    alpha_grid, log_re_grid, cl_table, cd_table : numpy.ndarray
        The NACA 0015 section table (:func:`sailmujoco.forces.foil_sections.section_coefficients`).
    current : numpy.ndarray, shape (3,)
        The current, world ENU, m/s (where the water goes).
    speed10, direction_from : float
        Mean wind speed at 10 m (m/s) and the compass bearing it comes from (rad).
    oscillation : numpy.ndarray, shape (3,)
        The wind's modulation: speed (m/s), direction (rad), frequency (Hz).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`~sailmujoco.forces.wind.WindField`: f_k (Hz), Y_k (rad), the
        amplitudes sqrt(2 S df) (m/s), shape (m, n), at the heights whose ln (m) is ``log_z`` (m,).
    wander_dt : float
        Time step of ``wander``, s.
    wander : numpy.ndarray
        The direction wander (rad) at ``k wander_dt`` seconds (Wille (2016a) eq. 43).
    mass_matrix, mass_inverse : numpy.ndarray, shape (4, 4)
        M_RB + M_A of eq. 3 over (u, v, p, r) and its inverse.
    terms : numpy.ndarray, shape (len(TERMS), 5)
        Work space for :func:`force_terms`.
    work : numpy.ndarray, shape (7, 6)
        Work space.
    out : numpy.ndarray, shape (10,)
        Receives the rates.
    """
    if not force_terms(t, state, P, sigma_d, lam_d, external, a, strip_x, strip_w, strip_draft, alpha_grid,
                       log_re_grid, cl_table, cd_table, current, speed10, direction_from, oscillation,
                       frequency, phase, amplitude, log_z, wander_dt, wander, work, terms):
        return False
    phi, psi, u, v, pr, r, sigma, lam = (state[2], state[3], state[4], state[5], state[6], state[7], state[8],
                                         state[9])
    total = work[0]
    for k in range(5):
        total[k] = 0.0
    for i in range(terms.shape[0]):  # the sum over TERMS, in their order
        for k in range(5):
            total[k] += terms[i, k]
    tau = work[1]
    for k in range(4):
        tau[k] = total[k]
    cphi, cpsi, spsi = math.cos(phi), math.cos(psi), math.sin(psi)
    if P[RIGID] == 0.0:
        for i in range(4):  # nu_dot = M^-1 tau, as numpy's matrix-vector product sums
            s = 0.0
            for j in range(4):
                s += mass_inverse[i, j] * tau[j]
            out[4 + i] = s
        psi_dot = r * cphi
    else:  # rigid hull, heave and pitch angle held (wille.py's module docstring)
        ixx, iyy, izz = P[IXX], P[IYY], P[IZZ]
        tphi = math.tan(phi)
        q = r * tphi
        mass = mass_matrix.copy()
        mass[3, 3] += (iyy + a[4]) * tphi * tphi
        tau[2] -= q * r * (izz - iyy)  # omega x (I omega), roll row
        tau[3] += tphi * total[4]  # the pitch moment the held pitch turns into yaw
        tau[3] -= tphi * (iyy + a[4]) * r * pr / (cphi * cphi)  # d/dt(tan phi) part of q_dot
        tau[3] -= tphi * pr * r * (ixx - izz) + pr * q * (iyy - ixx)  # gyroscopic, pitch and yaw rows
        finite = True
        for i in range(4):
            finite = finite and math.isfinite(tau[i]) and math.isfinite(mass[3, i])
        if finite:
            nu_dot = solve(mass, tau[:4].copy())  # in a written order: LAPACK's varies by CPU
            for i in range(4):
                out[4 + i] = nu_dot[i]
        else:  # compiled solve refuses NaN: the state is lost either way
            for i in range(4):
                out[4 + i] = math.nan
        psi_dot = r / cphi
    out[0] = cpsi * u - spsi * cphi * v  # eq. 4
    out[1] = spsi * u + cpsi * cphi * v
    out[2] = pr
    out[3] = psi_dot
    out[8] = (sigma_d - sigma) / P[RUDDER_T]  # actuator lag, §2.1
    out[9] = (lam_d - lam) / P[SAIL_T]
    return True


@kernel
def advance(t0, y, dt, n, P, sigma_d, lam_d, external, a, strip_x, strip_w, strip_draft, alpha_grid,
            log_re_grid, cl_table, cd_table, current, speed10, direction_from, oscillation, frequency, phase,
            amplitude, log_z, wander_dt, wander, mass_matrix, mass_inverse, terms, work, stages):
    """``n`` RK4 steps of ``dt / n`` from (t0, y), y in place; returns a status of :mod:`.integrators`.

    Parameters
    ----------
    t0 : float
        Start time, s.
    y : numpy.ndarray, shape (10,)
        The state, as ``state`` of :func:`rates`; advanced in place.
    dt : float
        The time to advance, s.
    n : int
        Number of RK4 steps.
    P : numpy.ndarray, shape (N_PARAMETERS,)
        The boat and switches as packed by :func:`pack_parameters`, laid out by its indices.
    sigma_d, lam_d : float
        Commanded rudder and sail angles, rad (the actuators lag toward them, §2.1).
    external : numpy.ndarray, shape (4,)
        External (X, Y, K, N), FRD, N and N m.
    a : numpy.ndarray, shape (6,)
        Positive diagonal added masses (-X_udot, ..., -N_rdot), kg and kg m^2.
    strip_x, strip_w, strip_draft : numpy.ndarray, shape (n,)
        Cross-flow strips: x forward of CO (m), quadrature weights (m), drafts (m)
        (:func:`sailmujoco.forces.damping.crossflow_drag`).
    alpha_grid, log_re_grid, cl_table, cd_table : numpy.ndarray
        The NACA 0015 section table (:func:`sailmujoco.forces.foil_sections.section_coefficients`).
    current : numpy.ndarray, shape (3,)
        The current, world ENU, m/s (where the water goes).
    speed10, direction_from : float
        Mean wind speed at 10 m (m/s) and the compass bearing it comes from (rad).
    oscillation : numpy.ndarray, shape (3,)
        The wind's modulation: speed (m/s), direction (rad), frequency (Hz).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`~sailmujoco.forces.wind.WindField`: f_k (Hz), Y_k (rad), the
        amplitudes sqrt(2 S df) (m/s), shape (m, n), at the heights whose ln (m) is ``log_z`` (m,).
    wander_dt : float
        Time step of ``wander``, s.
    wander : numpy.ndarray
        The direction wander (rad) at ``k wander_dt`` seconds (Wille (2016a) eq. 43).
    mass_matrix, mass_inverse : numpy.ndarray, shape (4, 4)
        M_RB + M_A of eq. 3 over (u, v, p, r) and its inverse.
    terms : numpy.ndarray, shape (len(TERMS), 5)
        Work space for :func:`force_terms`.
    work : numpy.ndarray, shape (7, 6)
        Work space.
    stages : numpy.ndarray, shape (5, 10)
        Work space for k1..k4 and a stage's state.
    """
    h = dt / n
    k1, k2, k3, k4, ys = stages[0], stages[1], stages[2], stages[3], stages[4]
    model = (P, sigma_d, lam_d, external, a, strip_x, strip_w, strip_draft, alpha_grid, log_re_grid, cl_table,
             cd_table, current, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z,
             wander_dt, wander, mass_matrix, mass_inverse, terms, work)
    for i in range(n):
        t = t0 + i * h
        if not rates(t, y, *model, k1):
            return STATUS_RAN_AWAY
        rk4_stage(y, 0.5 * h, k1, ys)
        if not rates(t + 0.5 * h, ys, *model, k2):
            return STATUS_RAN_AWAY
        rk4_stage(y, 0.5 * h, k2, ys)
        if not rates(t + 0.5 * h, ys, *model, k3):
            return STATUS_RAN_AWAY
        rk4_stage(y, h, k3, ys)
        if not rates(t + h, ys, *model, k4):
            return STATUS_RAN_AWAY
        rk4_update(y, h, k1, k2, k3, k4)
    return final_status(y)
