"""The numbers Viel's boat is identified from: Viel et al. (2019) Table 1, the operating point,
and the sail and rudder areas that match Viel's laws there (:func:`sailmujoco.boat.catalogue.viel_boat`).
"""

from __future__ import annotations

import math

# Viel et al. (2019) Table 1 (from Melin 2015 / Jaulin), the numbers viel_boat is identified from.
VIEL_P2 = 40.0  # kg/m, p2, tangential friction p2 v|v| (Viel eq. 4; Table 1 prints kg/s)
VIEL_P4 = 200.0  # kg/s, p4, sail lift: g_s = p4 a_aw sin(delta_s - psi_aw) (Viel eq. 9)
VIEL_P5 = 1500.0  # kg/s, p5, rudder lift: g_rv = p5 v sin(delta_r) (Viel eq. 7, read linear in v)
VIEL_P6 = 0.5  # m, p6, mast to the sail's centre of effort (Viel eq. 6)
VIEL_P7 = 0.5  # m, p7, G to the mast (Viel eq. 6)
VIEL_P8 = 2.0  # m, p8, G to the rudder (Viel eq. 6)
VIEL_P9 = 300.0  # kg, p9, mass of the boat
VIEL_P10 = 400.0  # kg m^2, p10, moment of inertia about the vertical axis
# The operating point at which p4 is identified: Viel's own 3-DOF world (reference/viel.py, Table 1,
# eqs. 7-8 linear in v) sailed by the viel controller (§5.1 gains, dt 0.01 s) in §5.1 case 1
# (10 m/s true wind, start (-30, 40) m, seed 0), medians over its steady direct leg t = 12-26 s
# (measured at viel16, /tmp script; the leg that carries it to the target area at 2.3 m/s):
VIEL_SAIL_REF_WIND = 11.7  # m/s, a_aw on that leg (measured, 11.74)
VIEL_SAIL_REF_INCIDENCE = math.radians(23.3)  # rad, |delta_s - psi_aw| taken to the flow, i.e.
# pi - |delta_s - psi_aw| of Viel's "blows towards" psi_aw (measured, 23.3 deg: eq. 16 holds the
# sail at its luffing limit minus epsilon on a close reach, AWA 38 deg)
VIEL_BOAT_REF_SPEED = 3.0  # m/s, v at which p5 is identified: Viel's boat reaches at
# 3-4.7 m/s in 10 m/s of wind (its 3-DOF model, tests/test_viel_boat.py), 2-3 m/s in 5 m/s
SAOUD_CN_POLY = (7.15, -23.07, 39.45, -33.79, 11.52)  # -, C_N(x) = sum c_k x^k (k = 1..5),
# x = sin(alpha): Saoud (2015) §VII-A's fit for the flat AR 5 sail (the force model's C_N)


def viel_identified_sail_area(rho_air: float) -> float:
    """Sail area A_s [m^2] whose normal force equals Viel's at his own operating point.

    Viel eq. 9: g_s = p4 a_aw sin(alpha), alpha = delta_s - psi_aw (linear in the wind speed
    and in sin(alpha), no stall: Jaulin's law). Ours: F_N = 1/2 rho_air A_s C_N(sin alpha)
    a_aw^2 with Saoud's C_N, which stalls at ~15 deg and levels at ~1.26. The two laws cannot
    agree everywhere; they are made equal where the controller sails them, the case 1 direct
    leg (a_ref = 11.7 m/s, alpha_ref = 23.3 deg, :data:`VIEL_SAIL_REF_INCIDENCE`):
    A_s = 2 p4 sin(alpha_ref) / (rho_air C_N(sin alpha_ref) a_ref). At small alpha our sail is
    then 2.6x stronger than Viel's; past ~30 deg weaker (xml/viel_boat/README.md step 3).

    Parameters
    ----------
    rho_air : float
        Air density, kg/m^3 (the boat's).

    Returns
    -------
    float
        A_s, m^2.
    """
    x = math.sin(VIEL_SAIL_REF_INCIDENCE)
    c_n = sum(coef * x ** (k + 1) for k, coef in enumerate(SAOUD_CN_POLY))  # Saoud §VII-A
    return 2.0 * VIEL_P4 * x / (rho_air * c_n * VIEL_SAIL_REF_WIND)


def viel_identified_rudder_area(rho_water: float, aspect_ratio: float) -> float:
    """Rudder area A_r [m^2] whose lift equals Viel's at the reference boat speed.

    Viel eq. 7 (read linear in v): g_rv = p5 v sin(delta_r). Ours (Wille eq. 23 with the thin-
    aerofoil section slope 2 pi): L = 1/2 rho_w A_r C_La delta_r v^2, C_La = 2 pi / (1 + 2/Asp).
    Equal at v = v_ref: A_r = 2 p5 / (rho_w C_La v_ref).

    Parameters
    ----------
    rho_water : float
        Water density, kg/m^3.
    aspect_ratio : float
        The rudder's effective aspect ratio Asp (Wille eq. 23).

    Returns
    -------
    float
        A_r, m^2.
    """
    c_la = 2.0 * math.pi / (1.0 + 2.0 / aspect_ratio)
    return 2.0 * VIEL_P5 / (rho_water * c_la * VIEL_BOAT_REF_SPEED)
