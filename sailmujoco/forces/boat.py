"""All forces on the boat at one instant: one compiled kernel over the force models.

:func:`boat_forces` is a pure function of (time, generalised position and velocity, packed
parameters, wind arrays). It calls the force models of this package and returns each term's
wrench, the hinge moments and the generalised forces MuJoCo needs. The packing of
:class:`~sailmujoco.boat.params.BoatParams` and the force switches into the flat array ``P`` is
defined in :mod:`sailmujoco.forces.boat_parameters`; the kernel's arguments are declared, in
order, in :mod:`sailmujoco.forces.kernel_arguments`.

Term order (rows of ``terms``), each a body-frame wrench about CO:
``TERMS = ("sail", "keel", "rudder", "hydrostatics", "damping", "added_mass", "external",
"windage")``.
"""

from __future__ import annotations

import math

from ..jit.kernel import kernel
from .added_mass import added_mass_velocity_terms
from .boat_parameters import (
    P_A1,
    P_A2,
    P_A3,
    P_A4,
    P_A5,
    P_A6,
    P_ADDED_COUPLING,
    P_BF0,
    P_BL,
    P_BODY_DAMPING,
    P_BODY_RESTORING,
    P_CE_AFT,
    P_CE_HEIGHT,
    P_CF_SAIL,
    P_CG_X,
    P_CG_Z,
    P_CREW_BLOCK,
    P_CROSSFLOW_CD,
    P_CURRENT_E,
    P_CURRENT_N,
    P_D11,
    P_D66,
    P_FINITE_FOILS,
    P_FLOTATION_X,
    P_FOIL_BLOCK,
    P_FORM_K,
    P_G,
    P_HEADSAIL_BLOCK,
    P_HYDRO_MODE,
    P_K_HEAVE,
    P_K_PITCH,
    P_KEEL_AR,
    P_KEEL_AREA,
    P_KEEL_CHORD,
    P_KEEL_DOWNWASH,
    P_KEEL_TC,
    P_KEEL_X,
    P_KEEL_Z,
    P_LENGTH,
    P_MASS,
    P_MAST_X,
    P_NU_W,
    P_OMEGA_ROLL,
    P_ON_ADDED,
    P_ON_DAMPING,
    P_ON_KEEL,
    P_ON_RUDDER,
    P_ON_SAIL,
    P_ON_WINDAGE,
    P_RESISTANCE_BLOCK,
    P_RESISTANCE_DSYHS,
    P_RHO_A,
    P_RHO_W,
    P_RIGHTING_K,
    P_RIGHTING_SIN,
    P_RUD_AR,
    P_RUD_AREA,
    P_RUD_CHORD,
    P_RUD_TC,
    P_RUD_X,
    P_RUD_Z,
    P_SAIL_AREA,
    P_SEA_BLOCK,
    P_SEA_RAMP,
    P_STALL,
    P_SUCTION,
    P_TANGENTIAL,
    P_WANDER_DT,
    P_WETTED,
    P_WIND_FROM,
    P_WIND_SPEED,
    P_WINDAGE_BLOCK,
    RESISTANCE_BLOCK_SIZE,
    switch_slot,
)
from .crew import CB_ARM, CB_MASS, CB_SPEED, crew_drive, crew_target
from .damping import hull_damping, pitch_angle_rate
from .finite_wing import (
    FB_DOWNWASH_GAIN,
    FB_KEEL_AR,
    FB_KEEL_CD_MAX,
    FB_KEEL_RATIO,
    FB_MATCH_ANGLE,
    FB_RUDDER_AR,
    FB_RUDDER_CD_MAX,
    FB_RUDDER_RATIO,
    FB_SAIL_CD_MAX,
    FB_SAIL_SLOPE,
)
from .headsail import (
    HB_AREA,
    HB_CAMBER,
    HB_CD_MAX,
    HB_CE_AFT,
    HB_CE_HEIGHT,
    HB_INTERACTION,
    HB_MAIN_SLOPE,
    HB_MAX,
    HB_MIN,
    HB_SLOPE,
    HB_TACK_X,
    HEADSAIL_BLOCK_SIZE,
    headsail_angle,
    interact,
)
from .hull_foils import hull_foil_force, point_flow
from .hydrostatics import hull_buoyancy, paper_restoring
from .kernel_arguments import with_parameters
from .resistance import residuary_surge_force
from .sail import sail_force
from .sail_camber import add_camber_lift
from .sea_hull import SMALL_SIZE as SEA_SMALL_SIZE
from .sea_hull import hull_sea_wrench
from .sea_kernels import (
    SB_DIFFRACTION,
    SB_DX,
    SB_DY,
    SB_FOIL_FLOW,
    SB_HULL,
    SB_NX,
    SB_NY,
    SB_PRESSURE_DECAY,
    SB_RELATIVE_DAMPING,
    SEA_ROWS,
    foil_water_velocity,
    sea_stage,
)
from .wave_reflection import reflection_wrench
from .wind_kernels import wind_velocities
from .windage import (
    W_AREA_FRONT,
    W_AREA_SIDE,
    W_CX,
    W_CY,
    W_HULL_X,
    W_HULL_Z,
    W_MAST_AREA,
    W_MAST_CD,
    W_MAST_X,
    W_MAST_Z,
    mast_force,
    topsides_force,
)

TERMS = ("sail", "keel", "rudder", "hydrostatics", "damping", "added_mass", "external", "windage")
T_SAIL, T_KEEL, T_RUDDER, T_HYDRO, T_DAMP, T_ADDED, T_EXT, T_WINDAGE = range(len(TERMS))
P_ON_REFLECTION = switch_slot("wave_reflection")
# ---- diagnostics (``diag`` output) ------------------------------------------------------
(D_ALPHA_SAIL, D_ALPHA_KEEL, D_ALPHA_RUDDER, D_SPEED_SAIL, D_SPEED_KEEL, D_SPEED_RUDDER,
 D_WIND_X, D_WIND_Y, D_WIND_Z, D_CE_HEIGHT, D_SUBMERGED, D_CN, D_CT, D_SAIL_HINGE,
 D_SAIL_FLOW_X, D_SAIL_FLOW_Y, D_SIZE) = range(17)

STATUS_OK, STATUS_NONFINITE, STATUS_CAPSIZED = 0, 1, 2
WORK_SIZE = 86 + SEA_SMALL_SIZE + 15  # scratch floats handed to boat_forces


@kernel
def rotation_from_quat(q, out):
    """Body->world rotation matrix of a quaternion into ``out``.

    Parameters
    ----------
    q : numpy.ndarray, shape (4,)
        Quaternion (w, x, y, z), body FLU -> world ENU (MuJoCo's order); normalised here.
    out : numpy.ndarray, shape (3, 3)
        Receives the rotation matrix.
    """
    w, x, y, z = q[0], q[1], q[2], q[3]
    n = w * w + x * x + y * y + z * z
    s = 2.0 / n
    out[0, 0] = 1.0 - s * (y * y + z * z)
    out[0, 1] = s * (x * y - w * z)
    out[0, 2] = s * (x * z + w * y)
    out[1, 0] = s * (x * y + w * z)
    out[1, 1] = 1.0 - s * (x * x + z * z)
    out[1, 2] = s * (y * z - w * x)
    out[2, 0] = s * (x * z - w * y)
    out[2, 1] = s * (y * z + w * x)
    out[2, 2] = 1.0 - s * (x * x + y * y)


@kernel
def _accumulate(terms, row, force, point):
    """terms[row] += wrench of a body-frame ``force`` acting at body ``point`` (about CO)."""
    terms[row, 0] += force[0]
    terms[row, 1] += force[1]
    terms[row, 2] += force[2]
    terms[row, 3] += point[1] * force[2] - point[2] * force[1]
    terms[row, 4] += point[2] * force[0] - point[0] * force[2]
    terms[row, 5] += point[0] * force[1] - point[1] * force[0]


@kernel
@with_parameters
def boat_forces(t, qpos, qvel, idx, P, columns, strips, alpha_grid, log_re_grid, cl_table,
                cd_table, oscillation, gust_f, gust_phase, gust_amp, log_z, wander, gust_cos,
                external, terms, diag, qfrc, madd, mass_csr, csr_addr, work, sea, grid, waterline,
                add_mass):
    """Every force on the boat for the state (qpos, qvel) at time t.

    The arguments are declared, in order, in :mod:`sailmujoco.forces.kernel_arguments`, which
    writes the "Parameters" section below. With a sea (``sea`` of m > 0 components) the
    geometric hydrostatics gain the sea's part (:mod:`sailmujoco.forces.sea_hull`: the
    Froude-Krylov and diffraction forces, the water's heave and pitch rates for the damping)
    and the keel and rudder feel the orbital velocity averaged over their spans; m = 0: calm
    water.

    Returns
    -------
    int
        STATUS_OK, STATUS_NONFINITE or STATUS_CAPSIZED.
    """
    for k in range(qpos.shape[0]):
        if not math.isfinite(qpos[k]):
            return STATUS_NONFINITE
    for k in range(qvel.shape[0]):
        if not math.isfinite(qvel[k]):
            return STATUS_NONFINITE
    terms[:, :] = 0.0
    qfrc[:] = 0.0
    R = work[0:9].reshape((3, 3))
    v, w, current_b = work[9:12], work[12:15], work[15:18]
    nu_r = work[18:24]
    zero3, flow, point = work[24:27], work[27:30], work[30:33]
    chord, normal, force = work[33:36], work[36:39], work[39:42]
    wrench, extra = work[42:48], work[48:51]
    wind_w, wind_b, total = work[51:54], work[54:57], work[57:63]
    winds = work[63:72]  # the wind at the sail's CE, the topsides and the mast (rows of 3)
    fluid = work[72:75]  # the water at a foil in a sea: current + orbital velocity
    added, water, sea_wrench = work[75:78], work[78:80], work[80:86]  # the hull in a sea
    sea_small = work[86:86 + SEA_SMALL_SIZE]
    jib = work[86 + SEA_SMALL_SIZE:WORK_SIZE]  # the headsail: its centroid, wind, flow, force; a spare force
    jib_point, jib_wind, jib_flow = jib[0:3], jib[3:6], jib[6:9]
    jib_force, spare_force = jib[9:12], jib[12:15]
    zero3[:] = 0.0
    rotation_from_quat(qpos[3:7], R)
    if R[2, 2] < 0.0:
        return STATUS_CAPSIZED  # |heel| or |pitch| beyond 90 deg

    # body-frame velocities: v of CO, w, and v_r relative to the current (eq. 5)
    for i in range(3):
        v[i] = R[0, i] * qvel[0] + R[1, i] * qvel[1] + R[2, i] * qvel[2]
        w[i] = qvel[3 + i]
        current_b[i] = R[0, i] * P[P_CURRENT_E] + R[1, i] * P[P_CURRENT_N]
    for i in range(3):
        nu_r[i] = v[i] - current_b[i]
        nu_r[3 + i] = w[i]
    waves = sea.shape[1] > 0  # a sea: this stage's phases into its rows (forces/sea_kernels.py)
    sb = P_SEA_BLOCK
    if waves:
        sea_stage(t, P[P_SEA_RAMP], qpos[0:3], R, sea)
    water = current_b

    # ---- keel: fixed to the hull, chord +x, normal +y (Wille eqs. 30-33) ----
    finite = P[P_FINITE_FOILS] > 0.0
    fb = P_FOIL_BLOCK
    keel_lift = 0.0
    if P[P_ON_KEEL] > 0.0:
        if waves and P[sb + SB_FOIL_FLOW] > 0.0:
            foil_water_velocity(qpos[0:3], R, P[P_KEEL_X], P[P_KEEL_Z],
                                math.sqrt(P[P_KEEL_AR] * P[P_KEEL_AREA]), sea, current_b, fluid)
            water = fluid
        alpha, speed, keel_lift = hull_foil_force(
            0.0, P[P_KEEL_X], P[P_KEEL_Z], P[P_KEEL_CHORD], P[P_KEEL_AR], P[P_KEEL_TC], P[P_KEEL_AREA],
            P[P_RHO_W], P[P_NU_W], water, v, w, alpha_grid, log_re_grid, cl_table, cd_table, zero3, point,
            flow, chord, normal, force, finite, P[fb + FB_KEEL_RATIO], P[fb + FB_KEEL_AR],
            P[fb + FB_KEEL_CD_MAX], P[fb + FB_MATCH_ANGLE], 0.0)
        _accumulate(terms, T_KEEL, force, point)
        diag[D_ALPHA_KEEL], diag[D_SPEED_KEEL] = alpha, speed

    # ---- rudder: turns by sigma about -z through its CP (Wille eqs. 34-36) ----
    if P[P_ON_RUDDER] > 0.0:
        # the keel's downwash at the rudder, from the keel's C_L of this same call:
        # epsilon = k C_L,keel / (pi A_e,keel) (forces/finite_wing.py, downwash_factor); 0 when off
        downwash = P[fb + FB_DOWNWASH_GAIN] * keel_lift if P[P_KEEL_DOWNWASH] > 0.0 else 0.0
        if waves and P[sb + SB_FOIL_FLOW] > 0.0:
            foil_water_velocity(qpos[0:3], R, P[P_RUD_X], P[P_RUD_Z],
                                math.sqrt(P[P_RUD_AR] * P[P_RUD_AREA]), sea, current_b, fluid)
            water = fluid
        alpha, speed, _ = hull_foil_force(
            qpos[idx[0]], P[P_RUD_X], P[P_RUD_Z], P[P_RUD_CHORD], P[P_RUD_AR], P[P_RUD_TC], P[P_RUD_AREA],
            P[P_RHO_W], P[P_NU_W], water, v, w, alpha_grid, log_re_grid, cl_table, cd_table, zero3, point,
            flow, chord, normal, force, finite, P[fb + FB_RUDDER_RATIO], P[fb + FB_RUDDER_AR],
            P[fb + FB_RUDDER_CD_MAX], P[fb + FB_MATCH_ANGLE], downwash)
        _accumulate(terms, T_RUDDER, force, point)
        diag[D_ALPHA_RUDDER], diag[D_SPEED_RUDDER] = alpha, speed

    # ---- the wind, at every point that feels it, in one evaluation (forces/wind.py) ----
    on_sail = P[P_ON_SAIL] > 0.0
    on_windage = P[P_ON_WINDAGE] > 0.0
    wb = P_WINDAGE_BLOCK
    lam = qpos[idx[2]]
    cl_, sl_ = math.cos(lam), math.sin(lam)
    arm_x, arm_y = -P[P_CE_AFT] * cl_, P[P_CE_AFT] * sl_  # CE from the mast axis
    ce_x, ce_y, ce_z = P[P_MAST_X] + arm_x, arm_y, P[P_CE_HEIGHT]
    z_ce = qpos[2] + R[2, 0] * ce_x + R[2, 1] * ce_y + R[2, 2] * ce_z
    z_hull = qpos[2] + R[2, 0] * P[wb + W_HULL_X] + R[2, 1] * 0.0 + R[2, 2] * P[wb + W_HULL_Z]
    z_mast = qpos[2] + R[2, 0] * P[wb + W_MAST_X] + R[2, 1] * 0.0 + R[2, 2] * P[wb + W_MAST_Z]
    if on_sail or on_windage:  # sail: row 0; topsides, mast: rows 1 and 2 of ``winds``
        if on_sail:
            z0, z1, z2, count, out = z_ce, z_hull, z_mast, (3 if on_windage else 1), winds
        else:
            z0, z1, z2, count, out = z_hull, z_mast, z_mast, 2, winds[3:9]
        wind_velocities(t, z0, z1, z2, count, P[P_WIND_SPEED], P[P_WIND_FROM], oscillation, gust_f,
                        gust_phase, gust_amp, log_z, P[P_WANDER_DT], wander, gust_cos, out)
    hb = P_HEADSAIL_BLOCK
    headsail = on_sail and P[hb + HB_AREA] > 0.0
    delta, delta_rate = 0.0, 0.0
    if headsail:  # its centroid turns by delta about the tack's vertical (forces/headsail.py)
        delta, delta_rate = headsail_angle(lam, qvel[idx[3]], P[hb + HB_MIN], P[hb + HB_MAX])
        jib_point[0] = P[hb + HB_TACK_X] - P[hb + HB_CE_AFT] * math.cos(delta)
        jib_point[1], jib_point[2] = P[hb + HB_CE_AFT] * math.sin(delta), P[hb + HB_CE_HEIGHT]
        z_jib = qpos[2] + R[2, 0] * jib_point[0] + R[2, 1] * jib_point[1] + R[2, 2] * jib_point[2]
        wind_velocities(t, z_jib, z_jib, z_jib, 1, P[P_WIND_SPEED], P[P_WIND_FROM], oscillation, gust_f,
                        gust_phase, gust_amp, log_z, P[P_WANDER_DT], wander, gust_cos, jib_wind)

    # ---- sail: turns by lambda about the mast (-z); flow at its CE (Wille eqs. 25-29) ----
    sail_hinge = 0.0
    if on_sail:
        lam_rate = qvel[idx[3]]
        point[0], point[1], point[2] = ce_x, ce_y, ce_z
        # hinge-rate velocity (-lambda_dot z) x arm = lambda_dot l2 (sin, cos, 0), eq. 26
        extra[0], extra[1], extra[2] = lam_rate * P[P_CE_AFT] * sl_, lam_rate * P[P_CE_AFT] * cl_, 0.0
        wind_w[0], wind_w[1], wind_w[2] = winds[0], winds[1], winds[2]
        for i in range(3):
            wind_b[i] = R[0, i] * wind_w[0] + R[1, i] * wind_w[1] + R[2, i] * wind_w[2]
        point_flow(wind_b, v, w, point, extra, flow)
        diag[D_SAIL_FLOW_X], diag[D_SAIL_FLOW_Y] = flow[0], flow[1]
        # Saoud's C_N (slope 0 selects it) or the finite wing's (forces/finite_wing.py)
        slope = P[fb + FB_SAIL_SLOPE] if finite else 0.0
        if headsail:  # its flow, the two sails' interaction, and its force (to the hull, at its CE)
            for i in range(3):
                wind_b[i] = R[0, i] * jib_wind[0] + R[1, i] * jib_wind[1] + R[2, i] * jib_wind[2]
            extra[0] = delta_rate * P[hb + HB_CE_AFT] * math.sin(delta)
            extra[1] = delta_rate * P[hb + HB_CE_AFT] * math.cos(delta)
            point_flow(wind_b, v, w, jib_point, extra, jib_flow)
            if P[hb + HB_INTERACTION] > 0.0:
                interact(flow, jib_flow, lam, delta, point, jib_point, P[hb:hb + HEADSAIL_BLOCK_SIZE],
                         P[P_TANGENTIAL] > 0.0, P[P_SUCTION], P[P_STALL], P[P_CF_SAIL], P[P_RHO_A],
                         P[P_SAIL_AREA], slope, P[fb + FB_SAIL_CD_MAX], chord, normal, spare_force, jib_force)
            speed, alpha, _, _ = sail_force(jib_flow, delta, P[P_TANGENTIAL] > 0.0, P[P_SUCTION], P[P_STALL],
                                            P[P_CF_SAIL], P[P_RHO_A], P[hb + HB_AREA],
                                            P[hb + HB_SLOPE] if finite else 0.0, P[hb + HB_CD_MAX], chord,
                                            normal, jib_force)
            add_camber_lift(jib_flow, chord, normal, alpha, speed, P[hb + HB_CAMBER], P[hb + HB_SLOPE],
                            P[P_STALL], P[P_RHO_A], P[hb + HB_AREA], jib_force)
            _accumulate(terms, T_SAIL, jib_force, jib_point)
        speed, alpha, c_n, c_t = sail_force(flow, lam, P[P_TANGENTIAL] > 0.0, P[P_SUCTION], P[P_STALL],
                                            P[P_CF_SAIL], P[P_RHO_A], P[P_SAIL_AREA], slope,
                                            P[fb + FB_SAIL_CD_MAX], chord, normal, force)
        if P[hb + HB_CAMBER] > 0.0:  # a cambered rig (forces/sail_camber.py); flat: nothing added
            add_camber_lift(flow, chord, normal, alpha, speed, P[hb + HB_CAMBER], P[hb + HB_MAIN_SLOPE],
                            P[P_STALL], P[P_RHO_A], P[P_SAIL_AREA], force)
        _accumulate(terms, T_SAIL, force, point)
        # moment about the hinge axis (-z): -(arm x F)_z
        sail_hinge = -(arm_x * force[1] - arm_y * force[0])
        diag[D_ALPHA_SAIL], diag[D_SPEED_SAIL] = alpha, speed
        diag[D_WIND_X], diag[D_WIND_Y], diag[D_WIND_Z] = wind_w[0], wind_w[1], wind_w[2]
        diag[D_CE_HEIGHT], diag[D_CN], diag[D_CT] = z_ce, c_n, c_t
    diag[D_SAIL_HINGE] = sail_hinge

    # ---- windage of topsides and mast, each at its centroid in its own wind (forces/windage.py) ----
    if on_windage:
        for element in range(2):
            if element == 0:
                point[0], point[1], point[2] = P[wb + W_HULL_X], 0.0, P[wb + W_HULL_Z]
            else:
                point[0], point[1], point[2] = P[wb + W_MAST_X], 0.0, P[wb + W_MAST_Z]
            row = 3 + 3 * element
            wind_w[0], wind_w[1], wind_w[2] = winds[row], winds[row + 1], winds[row + 2]
            for i in range(3):
                wind_b[i] = R[0, i] * wind_w[0] + R[1, i] * wind_w[1] + R[2, i] * wind_w[2]
            point_flow(wind_b, v, w, point, zero3, flow)
            if element == 0:
                topsides_force(flow, P[P_RHO_A], P[wb + W_CX], P[wb + W_CY], P[wb + W_AREA_FRONT],
                               P[wb + W_AREA_SIDE], force)
            else:
                mast_force(flow, P[P_RHO_A], P[wb + W_MAST_CD], P[wb + W_MAST_AREA], force)
            _accumulate(terms, T_WINDAGE, force, point)

    # ---- hydrostatics ----
    mode = P[P_HYDRO_MODE]
    water_dz, water_dpitch = 0.0, 0.0  # the water's heave and pitch rates at the hull (a sea)
    if mode == 2.0:
        diag[D_SUBMERGED] = hull_buoyancy(qpos[2], R, columns, P[P_RHO_W], P[P_G], wrench)
        if waves and P[sb + SB_HULL] > 0.0:  # + the sea's part, on the coarse grid (forces/sea_hull.py)
            added[0], added[1], added[2] = P[P_A1], P[P_A2], P[P_A3]
            nx, ny = int(P[sb + SB_NX]), int(P[sb + SB_NY])
            hull_sea_wrench(qpos[0:3], R, sea, sea[SEA_ROWS:SEA_ROWS + nx], sea[SEA_ROWS + nx:], grid,
                            P[sb + SB_DX], P[sb + SB_DY], nx, ny, P[P_FLOTATION_X], added,
                            P[sb + SB_PRESSURE_DECAY] > 0.0,
                            P[sb + SB_DIFFRACTION] > 0.0 and P[P_ON_ADDED] > 0.0,
                            P[P_RHO_W], P[P_G], sea_small, sea_wrench, water)
            for i in range(6):
                wrench[i] += sea_wrench[i]
            if P[P_ON_REFLECTION] > 0.0:  # short waves' mean reflection (forces/wave_reflection.py)
                reflection_wrench(sea, waterline, nu_r[0], P[P_RHO_W], P[P_G], sea_wrench)
                for i in range(6):
                    wrench[i] += sea_wrench[i]
            if P[sb + SB_RELATIVE_DAMPING] > 0.0:
                water_dz, water_dpitch = water[0], water[1]
        terms[T_HYDRO, :] = wrench
    elif mode == 1.0:
        paper_restoring(qpos[2], R, P[P_MASS] * P[P_G], P[P_RIGHTING_K], P[P_RIGHTING_SIN] > 0.0,
                        P[P_K_HEAVE], P[P_K_PITCH], P[P_CG_X], P[P_CG_Z], P[P_BODY_RESTORING] > 0.0,
                        wrench)
        terms[T_HYDRO, :] = wrench

    # ---- hull damping, eqs. 12-19 (+ residuary resistance, forces/resistance.py) ----
    if P[P_ON_DAMPING] > 0.0:
        hull_damping(R, nu_r, P[P_RHO_W], P[P_D11:P_D66 + 1], P[P_WETTED], P[P_FORM_K], P[P_LENGTH],
                     P[P_NU_W], P[P_CROSSFLOW_CD], strips[0], strips[1], strips[2], P[P_BF0],
                     P[P_BL], P[P_OMEGA_ROLL], P[P_FLOTATION_X], P[P_BODY_DAMPING] > 0.0, water_dz,
                     water_dpitch, wrench)
        if P[P_RESISTANCE_DSYHS] > 0.0:  # + Delft residuary resistance, along body x at CO
            heel = math.atan2(R[2, 1], R[2, 2])  # frames.euler_from_matrix
            block = P[P_RESISTANCE_BLOCK:P_RESISTANCE_BLOCK + RESISTANCE_BLOCK_SIZE]
            wrench[0] += residuary_surge_force(nu_r[0], heel, block)
        terms[T_DAMP, :] = wrench

    # ---- added mass: velocity terms here, inertia via madd in the mass matrix ----
    for i in range(3):
        for j in range(3):
            madd[i, j] = 0.0
    if P[P_ON_ADDED] > 0.0:
        added_mass_velocity_terms(nu_r, P[P_A1:P_A6 + 1], int(P[P_ADDED_COUPLING]),
                                  pitch_angle_rate(R, nu_r[4], nu_r[5]), wrench)
        terms[T_ADDED, :] = wrench
        for i in range(3):
            for j in range(3):
                madd[i, j] = (R[i, 0] * P[P_A1] * R[j, 0] + R[i, 1] * P[P_A2] * R[j, 1]
                              + R[i, 2] * P[P_A3] * R[j, 2])

    terms[T_EXT, :] = external

    # ---- generalised forces: free joint (world force, body torque about CO) + sail hinge ----
    total[:] = 0.0
    for row in range(terms.shape[0]):
        for i in range(6):
            total[i] += terms[row, i]
    for i in range(3):
        qfrc[i] = R[i, 0] * total[0] + R[i, 1] * total[1] + R[i, 2] * total[2]
        qfrc[3 + i] = total[3 + i]
    qfrc[idx[1]] = 0.0  # the rudder CP is on its stock: no hinge moment
    qfrc[idx[3]] = sail_hinge
    cb = P_CREW_BLOCK
    if P[cb + CB_MASS] > 0.0:  # the crew's slide is the model's last joint (forces/crew.py)
        last = qvel.shape[0] - 1
        qfrc[last] = crew_drive(qpos[qpos.shape[0] - 1], qvel[last], crew_target(lam, P[cb + CB_ARM]),
                                P[cb + CB_MASS], P[cb + CB_SPEED], -P[P_G] * R[2, 1])

    if add_mass and P[P_ON_ADDED] > 0.0:
        k = 0
        for i in range(3):
            for j in range(i + 1):
                mass_csr[csr_addr[k]] += madd[i, j]
                k += 1
        mass_csr[csr_addr[6]] += P[P_A4]
        mass_csr[csr_addr[7]] += P[P_A5]
        mass_csr[csr_addr[8]] += P[P_A6]
    return STATUS_OK
