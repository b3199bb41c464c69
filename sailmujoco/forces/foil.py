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
    cs = math.cos(alpha)
    c_normal = saoud_normal_coefficient(s)
    if not tangential:
        return c_normal, 0.0
    fade = math.exp(-((s / math.sin(suction_stall)) ** 2))
    c_tangential = suction_efficiency * fade * c_normal * s * cs - 2.0 * friction * cs
    return c_normal, c_tangential


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
    (speed, alpha, C_N, C_T). The one place the sail's force is built: the physics kernel, the
    Wille 4-DOF world and the roll controller's sail tables all call it.
    """
    c, s = math.cos(angle), math.sin(angle)
    chord[0], chord[1], chord[2] = c, -s, 0.0
    normal[0], normal[1], normal[2] = s, c, 0.0
    _, _, speed, alpha = section_flow(flow, chord, normal)
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
