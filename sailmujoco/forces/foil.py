"""Foil forces: the keel, the rudder and the sail. Where the keel lift is computed.

Geometry of a foil section (one convention for all three foils)
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
from functools import lru_cache
from importlib import resources

import numpy as np

from .._jit import kernel
from .damping import ittc_friction_coefficient

# Saoud et al. (2015) §VII-A: C_N of the flat AR = 5 sail as a degree-5 polynomial of
# x = sin(alpha), odd-extended to x < 0.
SAOUD_CN_COEFFS = (7.15, -23.07, 39.45, -33.79, 11.52)  # p1..p5


class SectionTable:
    """NACA 0015 section coefficients through 180 deg (Sheldahl & Klimas 1981, SAND80-2114).

    Attributes are plain arrays so they can be handed to compiled kernels:
    ``alpha`` (rad, ascending, shared by every Reynolds number), ``log_re`` (log10 Re of each
    table), ``cl`` and ``cd`` (shape (n_re, n_alpha)).
    """

    def __init__(self, alpha, log_re, cl, cd):
        self.alpha = np.ascontiguousarray(alpha, dtype=float)
        self.log_re = np.ascontiguousarray(log_re, dtype=float)
        self.cl = np.ascontiguousarray(cl, dtype=float)
        self.cd = np.ascontiguousarray(cd, dtype=float)

    @property
    def reynolds(self) -> np.ndarray:
        return 10.0**self.log_re


def parse_section_table(text: str) -> SectionTable:
    """Parse the CACTUS-format NACA 0015 file shipped in ``sailmujoco/data``."""
    blocks: list[tuple[float, list[list[float]]]] = []
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("Reynolds Number:"):
            blocks.append((float(s.split(":", 1)[1]), []))
        elif blocks and s and (s[0].isdigit() or s[0] == "-"):
            blocks[-1][1].append([float(v) for v in s.split()])
    if not blocks:
        raise ValueError("no 'Reynolds Number:' blocks in the section table")
    alpha_deg = np.array(blocks[0][1])[:, 0]
    for re_, rows in blocks:
        if not np.array_equal(np.array(rows)[:, 0], alpha_deg):
            raise ValueError(f"section table at Re={re_:g} has a different alpha grid")
    cl = np.array([np.array(rows)[:, 1] for _, rows in blocks])
    cd = np.array([np.array(rows)[:, 2] for _, rows in blocks])
    log_re = np.log10([re_ for re_, _ in blocks])
    return SectionTable(np.radians(alpha_deg), log_re, cl, cd)


@lru_cache(maxsize=1)
def naca0015() -> SectionTable:
    """The shipped Sheldahl & Klimas NACA 0015 table (11 Reynolds numbers, 1e4 to 1e7)."""
    text = resources.files("sailmujoco.data").joinpath("naca0015_sheldahl_klimas.dat").read_text()
    return parse_section_table(text)


@kernel
def wrap_pi(angle):
    """Wrap to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


@kernel
def section_coefficients(alpha, reynolds, alpha_grid, log_re_grid, cl_table, cd_table):
    """Section (2-D) c_l, c_d at ``alpha`` (rad) and Reynolds number, bilinear in (alpha, log Re).

    Re is clamped to the table's range (1e4 to 1e7): the Reynolds number is picked from the
    flow at every call.
    """
    a = wrap_pi(alpha)
    n = alpha_grid.shape[0]
    i = np.searchsorted(alpha_grid, a) - 1
    i = min(max(i, 0), n - 2)
    ta = (a - alpha_grid[i]) / (alpha_grid[i + 1] - alpha_grid[i])
    lr = math.log10(max(reynolds, 1.0))
    m = log_re_grid.shape[0]
    if lr <= log_re_grid[0]:
        j, tr = 0, 0.0
    elif lr >= log_re_grid[m - 1]:
        j, tr = m - 2, 1.0
    else:
        j = np.searchsorted(log_re_grid, lr) - 1
        j = min(max(j, 0), m - 2)
        tr = (lr - log_re_grid[j]) / (log_re_grid[j + 1] - log_re_grid[j])
    cl_lo = cl_table[j, i] + ta * (cl_table[j, i + 1] - cl_table[j, i])
    cl_hi = cl_table[j + 1, i] + ta * (cl_table[j + 1, i + 1] - cl_table[j + 1, i])
    cd_lo = cd_table[j, i] + ta * (cd_table[j, i + 1] - cd_table[j, i])
    cd_hi = cd_table[j + 1, i] + ta * (cd_table[j + 1, i + 1] - cd_table[j + 1, i])
    return cl_lo + tr * (cl_hi - cl_lo), cd_lo + tr * (cd_hi - cd_lo)


@kernel
def hydrofoil_coefficients(alpha, reynolds, aspect_ratio, thickness_ratio,
                           alpha_grid, log_re_grid, cl_table, cd_table):
    """Finite-span C_L, C_D of the keel or rudder.

    * Lift: Wille (2016a) eq. 23 with Asp_0 = infinity, because the Sheldahl & Klimas data are
      2-D section data: C_L = c_l / (1 + 2/Asp).
    * Drag: eq. 24, C_D = C_Di + 2 (1 + 2 t/c) C_F(Re). The paper says the table drag is the
      "induced" drag; a 2-D table holds no induced drag, so we read C_Di as the lift-dependent
      drag: the table's pressure drag above its zero-lift value, c_d(alpha) - c_d(0), plus the
      finite-span induced drag C_L^2 / (pi Asp). Eq. 24's friction term replaces the table's
      zero-lift drag, which is also how the thinner NACA 0009 keel differs from the 0015 table
      it borrows (no NACA 0009 table through 180 deg is available; the 0015 table stands in).
    """
    cl, cd = section_coefficients(alpha, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    _, cd0 = section_coefficients(0.0, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    c_lift = cl / (1.0 + 2.0 / aspect_ratio)  # eq. 23
    c_friction = 2.0 * (1.0 + 2.0 * thickness_ratio) * ittc_friction_coefficient(reynolds)  # eq. 24
    c_drag = (cd - cd0) + c_lift * c_lift / (math.pi * aspect_ratio) + c_friction
    return c_lift, c_drag


@kernel
def saoud_normal_coefficient(x):
    """C_N(x), x = sin(alpha): Saoud (2015) §VII-A polynomial, odd in x (properties (2))."""
    ax = abs(x)
    p1, p2, p3, p4, p5 = 7.15, -23.07, 39.45, -33.79, 11.52
    value = ax * (p1 + ax * (p2 + ax * (p3 + ax * (p4 + ax * p5))))
    return value if x >= 0.0 else -value


@kernel
def sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction):
    """(C_N, C_T) of the flat AR 5 sail.

    C_N follows Saoud's polynomial. C_T (Saoud neglects it, Assumption 4) is modelled:
    a thin flat sail recovers a share ``suction_efficiency`` of the ideal leading-edge suction
    C_N tan(alpha) while the flow is attached, fading out past ``suction_stall`` as
    exp(-(sin(alpha)/sin(stall))^2), and both faces feel skin friction along the chord:

        C_T = e exp(-(sin a / sin a_s)^2) C_N sin(a) cos(a) - 2 C_f cos(a)

    (sin a cos a stands in for tan a so that C_T stays bounded at 90 deg). With e = 0.3,
    a_s = 15 deg, C_f = 0.005, |C_T| stays below 0.03 while C_N reaches 1.25, the "near zero"
    C_T of Saoud's Fig. 2b. It is even in alpha, as for any symmetric section. ``tangential``
    False sets C_T = 0 exactly, making the force exactly normal to the sail.
    """
    s = math.sin(alpha)
    c_normal = saoud_normal_coefficient(s)
    if not tangential:
        return c_normal, 0.0
    return c_normal, tangential_coefficient(c_normal, s, math.cos(alpha), suction_efficiency,
                                            suction_stall, friction)


@kernel
def tangential_coefficient(c_normal, s, cs, suction_efficiency, suction_stall, friction):
    """C_T of the flat sail for its C_N at sin(alpha) = s, cos(alpha) = cs (the model of
    :func:`sail_coefficients`' docstring: recovered suction fading past the stall, friction)."""
    fade = math.exp(-((s / math.sin(suction_stall)) ** 2))
    return suction_efficiency * fade * c_normal * s * cs - 2.0 * friction * cs


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



@kernel(inline=True)  # in the per-step physics kernel: inlined, it costs what the open block did
def flat_sail_force(flow, angle, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
                    chord, normal, out):
    """The flat sail's force at sail angle ``angle`` [rad] in ``flow`` (air velocity at the CE).

    Chord (cos l, -sin l, 0) and normal (sin l, cos l, 0) go into the work arrays ``chord`` and
    ``normal``; F = q A (C_T c - C_N n) into ``out``, in the frame of ``flow``. Returns
    (speed, alpha, C_N, C_T). The papers' sail (Saoud's C_N): the physics kernel, the Wille
    4-DOF world and the roll controller's sail tables all call it; :func:`sail_force` with a
    finite-wing slope is the ``foils = "finite"`` form.
    """
    return sail_force(flow, angle, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
                      0.0, 0.0, chord, normal, out)


@kernel(inline=True)
def sail_force(flow, angle, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
               finite_slope, cd_max, chord, normal, out):
    """:func:`flat_sail_force` with C_N from Saoud's polynomial (``finite_slope`` 0) or, for
    ``finite_slope`` > 0, the finite wing's (:func:`finite_sail_coefficients`, lift slope
    ``finite_slope`` [1/rad] at zero incidence, ``cd_max`` at 90 deg)."""
    c, s = math.cos(angle), math.sin(angle)
    chord[0], chord[1], chord[2] = c, -s, 0.0
    normal[0], normal[1], normal[2] = s, c, 0.0
    _, _, speed, alpha = section_flow(flow, chord, normal)
    if finite_slope > 0.0:
        c_n, c_t = finite_sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction,
                                            finite_slope, cd_max)
    else:
        c_n, c_t = sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction)
    q_area = 0.5 * rho_air * speed * speed * area
    foil_world_force(q_area * c_t, -q_area * c_n, chord, normal, out)
    return speed, alpha, c_n, c_t


@kernel
def sail_forces(flow, sail_angles, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
                out):
    """:func:`flat_sail_force` for each angle of ``sail_angles`` (n,) into ``out`` (n, 3): one
    compiled loop, for the roll controller's sail tables (some 300 000 angles)."""
    chord, normal, force = np.zeros(3), np.zeros(3), np.zeros(3)
    for i in range(sail_angles.shape[0]):
        flat_sail_force(flow, sail_angles[i], tangential, suction_efficiency, suction_stall, friction,
                        rho_air, area, chord, normal, force)
        for k in range(3):
            out[i, k] = force[k]


# ---- finite-wing forms (ForceSwitches.foils = "finite") -------------------------------------
#
# Lift slope of a finite wing: Helmbold (1942), "Der unverwundene Ellipsenflügel als tragende
# Fläche", Jahrbuch der deutschen Luftfahrtforschung, I 111-113:
#     a = a0 / (sqrt(1 + (a0 / (pi A))^2) + a0 / (pi A)).
# It tends to Prandtl's lifting line a0 / (1 + a0/(pi A)) for large A and to Jones' slender-wing
# slope pi A / 2 for small A, so one formula serves the AR 5 sail and the keel of AR 1.75 (3.5
# with its image in the hull), where lifting line overstates the slope (by 12 % at A = 3.5).
# At A = 5 it gives 4.25 /rad against lifting line's 4.49 /rad; measured rectangular wings of
# A = 5 lie between (lifting line assumes elliptic loading).
#
# Post-stall: Viterna & Corrigan (1982), "Fixed pitch rotor performance of large horizontal axis
# wind turbines", NASA CP-2230, pp. 69-85: from a matching angle alpha_s to 90 deg
#     C_D = B1 sin^2 a + B2 cos a,     C_L = A1 sin 2a + A2 cos^2 a / sin a,
#     B1 = C_D,max = 1.11 + 0.018 A (A <= 50), A1 = B1 / 2,
#     B2 = (C_D,s - C_D,max sin^2 a_s) / cos a_s, A2 = (C_L,s - C_D,max sin a_s cos a_s) sin a_s / cos^2 a_s,
# so that C_L, C_D equal (C_L,s, C_D,s) at a_s and C_N(90 deg) = C_D(90 deg) = C_D,max. For A = 5
# that is 1.20, Hoerner's flat plate of the same aspect ratio (Fluid-Dynamic Drag, 1965, ch. 3).
# Beyond 90 deg the curves are mirrored as for a flat plate: C_N(pi - a) = C_N(a),
# C_L(pi - a) = -C_L(a), C_D(pi - a) = C_D(a).
THIN_AIRFOIL_SLOPE = 2.0 * math.pi  # 1/rad, a0 of a thin section (thin-airfoil theory)
# The hull as an end plate on the keel: a foil whose root meets a wall (here the canoe body) acts
# as the foil plus its mirror image, effective span twice the geometric one, so A_e = 2 A
# (Hoerner & Borst, Fluid-Dynamic Lift, 1985, ch. 3, "wall effect"; Larsson & Eliasson,
# Principles of Yacht Design, keel chapter, who note heel and a root gap reduce it). The keel
# is fixed to the hull with no gap: factor 2. The rudder turns on its stock below the counter,
# with a gap at its root and the hull rising to the transom above it: no end plate (factor 1).
KEEL_END_PLATE = 2.0  # -, A_e / A of the keel
RUDDER_END_PLATE = 1.0  # -, A_e / A of the rudder
# Section angle past which the table's 2-D post-stall is replaced by Viterna & Corrigan: beyond
# the table's own stall at every Reynolds number it holds (12-16 deg for Re >= 7e5, ~10 deg
# below), before its 2-D flat-plate branch (c_d 1.8 at 90 deg) takes over.
HYDROFOIL_MATCH_ANGLE = math.radians(20.0)  # rad, section (effective) angle

# offsets inside P[P_FOIL_BLOCK : P_FOIL_BLOCK + FOIL_BLOCK_SIZE] (forces/boat.py)
(FB_SAIL_SLOPE, FB_SAIL_CD_MAX, FB_KEEL_RATIO, FB_KEEL_AR, FB_KEEL_CD_MAX, FB_RUDDER_RATIO,
 FB_RUDDER_AR, FB_RUDDER_CD_MAX, FB_MATCH_ANGLE, FB_DOWNWASH_GAIN, FB_DOWNWASH_K) = range(11)


@kernel
def helmbold_lift_slope(section_slope, aspect_ratio):
    """Helmbold (1942) lift slope [1/rad] of a wing of aspect ratio A with section slope a0."""
    k = section_slope / (math.pi * aspect_ratio)
    return section_slope / (math.sqrt(1.0 + k * k) + k)


@kernel
def viterna_corrigan_cd_max(aspect_ratio):
    """Viterna & Corrigan (1982): C_D,max = 1.11 + 0.018 A, A capped at 50."""
    return 1.11 + 0.018 * min(aspect_ratio, 50.0)


@kernel
def viterna_corrigan(alpha, alpha_s, c_lift_s, c_drag_s, cd_max):
    """Viterna & Corrigan (1982) post-stall (C_L, C_D) at alpha in [alpha_s, pi/2], matched to
    (C_L,s, C_D,s) at alpha_s (formulas in the block comment above)."""
    ss, cs = math.sin(alpha_s), math.cos(alpha_s)
    b2 = (c_drag_s - cd_max * ss * ss) / cs
    a2 = (c_lift_s - cd_max * ss * cs) * ss / (cs * cs)
    s, c = math.sin(alpha), math.cos(alpha)
    return 0.5 * cd_max * math.sin(2.0 * alpha) + a2 * c * c / s, cd_max * s * s + b2 * c


@kernel
def finite_sail_normal_coefficient(x, slope, stall, cd_max):
    """C_N(x), x = sin(alpha), of a flat finite wing; odd in x like Saoud's (properties (2)).

    Attached (|alpha| <= stall, alpha folded to [0, 90 deg] as theta = asin|x|): C_N = a x, the
    finite-wing slope ``slope`` at zero incidence (Helmbold). The flow on a flat plate without
    leading-edge suction leaves the force normal to it, so at the stall C_L,s = C_N,s cos(stall),
    C_D,s = C_N,s sin(stall); past it Viterna & Corrigan's C_L, C_D, resolved on the normal:
    C_N = C_L cos(theta) + C_D sin(theta), which reaches C_D,max at 90 deg.
    """
    ax = min(abs(x), 1.0)
    if ax <= math.sin(stall):
        value = slope * ax
    else:
        theta = math.asin(ax)
        c_n_s = slope * math.sin(stall)
        c_l, c_d = viterna_corrigan(theta, stall, c_n_s * math.cos(stall), c_n_s * math.sin(stall), cd_max)
        value = c_l * math.cos(theta) + c_d * ax
    return value if x >= 0.0 else -value


@kernel
def finite_sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction, slope, cd_max):
    """(C_N, C_T) of the flat finite sail: :func:`finite_sail_normal_coefficient` with the sail's
    stall at ``suction_stall`` (the angle where its leading-edge suction collapses), and
    :func:`sail_coefficients`' tangential model on that C_N (suction share, fade, friction)."""
    s = math.sin(alpha)
    c_normal = finite_sail_normal_coefficient(s, slope, suction_stall, cd_max)
    if not tangential:
        return c_normal, 0.0
    return c_normal, tangential_coefficient(c_normal, s, math.cos(alpha), suction_efficiency,
                                            suction_stall, friction)


@kernel
def _attached_hydrofoil(alpha, reynolds, lift_ratio, aspect_ratio, cd0, c_friction,
                        alpha_grid, log_re_grid, cl_table, cd_table):
    """Table lift at the effective angle alpha_e = alpha a/a0 and the eq. 24 drag reading with
    the finite wing's induced drag C_L^2 / (pi A_e)."""
    cl, cd = section_coefficients(alpha * lift_ratio, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    return cl, (cd - cd0) + cl * cl / (math.pi * aspect_ratio) + c_friction


@kernel
def finite_hydrofoil_coefficients(alpha, reynolds, lift_ratio, aspect_ratio, cd_max, match_angle,
                                  thickness_ratio, alpha_grid, log_re_grid, cl_table, cd_table):
    """Finite-wing C_L, C_D of the keel or rudder (``foils = "finite"``).

    * Attached: lifting line's reading of a 2-D section on a finite wing: the section works at
      the effective angle alpha_e = alpha - alpha_i; for the linear range alpha_e = alpha a/a0,
      a = Helmbold(a0 = 2 pi, A_e) (``lift_ratio`` = a/a0), so C_L(alpha) = c_l(alpha a/a0):
      slope a at zero incidence, the section's own c_l,max, reached at a larger angle (finite
      wings stall later). The table's 0-2 deg slope is 6.30 /rad at Re >= 8e4, 2 pi to 0.4 %.
      Drag as :func:`hydrofoil_coefficients` reads eq. 24, with the induced drag on A_e.
    * Past the section angle ``match_angle`` (alpha > match_angle a0/a): Viterna & Corrigan
      matched there, C_D -> C_D,max(A_e) at 90 deg instead of the 2-D table's 1.8.
    * |alpha| > 90 deg: mirrored as a flat plate (C_L odd about 90 deg, C_D even).
    """
    a = wrap_pi(alpha)
    sign = 1.0 if a >= 0.0 else -1.0
    phi = abs(a)
    if phi > 0.5 * math.pi:
        phi = math.pi - phi
        sign = -sign
    _, cd0 = section_coefficients(0.0, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    c_friction = 2.0 * (1.0 + 2.0 * thickness_ratio) * ittc_friction_coefficient(reynolds)  # eq. 24
    phi_s = match_angle / lift_ratio
    if phi <= phi_s:
        c_lift, c_drag = _attached_hydrofoil(phi, reynolds, lift_ratio, aspect_ratio, cd0, c_friction,
                                             alpha_grid, log_re_grid, cl_table, cd_table)
    else:
        c_lift_s, c_drag_s = _attached_hydrofoil(phi_s, reynolds, lift_ratio, aspect_ratio, cd0, c_friction,
                                                 alpha_grid, log_re_grid, cl_table, cd_table)
        c_lift, c_drag = viterna_corrigan(phi, phi_s, c_lift_s, c_drag_s, cd_max)
    return sign * c_lift, c_drag


def downwash_factor(distance: float, keel_span: float) -> float:
    """k in epsilon = k C_L,keel / (pi A_e,keel) at ``distance`` behind the keel's CP.

    The keel and its image in the hull form one wing of span b_e = 2 ``keel_span``; the rudder
    sits near its plane of symmetry (the hull). For elliptic loading the rolled-up tip vortices
    lie s = (pi/4)(b_e/2) either side of it (same lift rho V Gamma0 (pi b_e / 4) as the elliptic
    sheet). Biot-Savart for two semi-infinite trailing vortices starting at the keel (Anderson,
    Fundamentals of Aerodynamics, §5.2, induced velocity of a semi-infinite filament) gives the
    downwash behind the centre, as a share of the far wake's 2 C_L / (pi A):
        k = 1 + x / sqrt(x^2 + s^2),
    1 at the keel (Prandtl's downwash at the lifting line) and 2 far behind. The bound vortex's
    share (it is the keel's own, and singular on its line) and the rudder's depth below the
    vortices' plane are left out; the latter makes k an upper bound.
    """
    s = 0.25 * math.pi * keel_span
    return 1.0 + distance / math.sqrt(distance * distance + s * s)


def pack_foil_block(p, end_plate_keel: float = KEEL_END_PLATE,
                    end_plate_rudder: float = RUDDER_END_PLATE) -> np.ndarray:
    """The finite-wing constants of boat ``p`` (BoatParams), FOIL_BLOCK_SIZE floats at most."""
    block = np.zeros(11)
    block[FB_SAIL_SLOPE] = helmbold_lift_slope(THIN_AIRFOIL_SLOPE, p.sail.aspect_ratio)
    block[FB_SAIL_CD_MAX] = viterna_corrigan_cd_max(p.sail.aspect_ratio)
    for base, foil, end_plate in ((FB_KEEL_RATIO, p.keel, end_plate_keel),
                                  (FB_RUDDER_RATIO, p.rudder, end_plate_rudder)):
        ar = end_plate * foil.aspect_ratio
        block[base] = helmbold_lift_slope(THIN_AIRFOIL_SLOPE, ar) / THIN_AIRFOIL_SLOPE
        block[base + 1] = ar
        block[base + 2] = viterna_corrigan_cd_max(ar)
    block[FB_MATCH_ANGLE] = HYDROFOIL_MATCH_ANGLE
    k = downwash_factor(p.keel.x - p.rudder.x, p.keel.span)
    block[FB_DOWNWASH_K] = k
    block[FB_DOWNWASH_GAIN] = k / (math.pi * end_plate_keel * p.keel.aspect_ratio)
    return block
