"""Residuary (wave-making) resistance of the canoe body from the Delft Systematic Yacht Hull Series.

The papers' hull resistance is friction only (ITTC-57, Wille 2016a eqs. 15-16,
:func:`sailmujoco.forces.damping.surge_resistance`). A displacement yacht also makes waves, and
their resistance climbs steeply near Fn = u / sqrt(g L_WL) ~ 0.4-0.45. With
``ForceSwitches(resistance="dsyhs")`` this module adds it.

Upright: the DSYHS regression extended to high speed, Keuning & Katgert (2008), "A bare hull
resistance prediction method derived from the results of the Delft Systematic Yacht Hull
Series extended to higher speeds", Int. Conf. Innovation in High Performance Sailing Yachts,
Lorient; as printed in Fossati (2009), Aero-hydrodynamics and the performance of sailing
yachts, Table 2.5 (Fn 0.15-0.75; the same table as Python-VPP's dat/wr.dat)::

    R_r / (rho g V_c) = a0 + (a1 LCB/L + a2 C_p + a3 V_c^(2/3)/A_w + a4 B/L
                              + a5 LCB/LCF + a6 B/T_c + a7 C_m) V_c^(1/3) / L

with LCB and LCF measured from the forward perpendicular. (The 1998 Keuning & Sonnenberg
polynomial of the same authors stops at Fn 0.60, which the Wille yacht passes; the 2008 table
is the one that covers the wave-making wall and what lies beyond it.)

Heel increment: Keuning & Sonnenberg (1998), "Approximation of the hydrodynamic forces on a
sailing yacht based on the 'Delft Systematic Yacht Hull Series'", HISWA symposium, Amsterdam;
also Larsson & Eliasson, Principles of Yacht Design, ch. 5 (Fn 0.25-0.55)::

    dR_rh(20 deg) / (rho g V_c) = 1e-3 (u0 + u1 L/B + u2 B/T_c + u3 (B/T_c)^2
                                        + u4 LCB + u5 LCB^2)
    dR_rh(phi) = dR_rh(20 deg) 6 phi^1.7   (phi in rad)

with LCB in per cent of L_WL from midship, positive forward (the series' parent at -2.3 has
its LCB 2.3 % aft). 6 (20 deg)^1.7 = 1.003, so the scaling returns the table at 20 deg. (The
equation and table numbers of KS98 are not at hand; the forms and coefficients are the ones
Larsson & Eliasson and Fossati reprint.)

Choices (none of them is in the source, which gives tables on its Froude range only):

* Each table is evaluated at its own Froude numbers and linearly interpolated between them
  (as the tables are meant to be read; the polynomial is linear in its coefficients, so
  interpolating coefficients or resistances is the same). Every tabulated value is clipped
  at 0: a regression that dips below zero at the lowest Froude numbers would push the boat.
* Below the first Froude number of a table (0.15 upright, 0.25 heeled) R_r / (rho g V)
  scales with (Fn / Fn_first)^2, i.e. the residuary resistance coefficient
  C_R = R_r / (1/2 rho u^2 S) is held at its first tabulated value. Wave making then fades to
  zero with u^2 as friction does, smoothly (R ~ |u| u, no kink at u = 0). This is the
  low-speed form of Froude's decomposition that the ITTC-57 method uses for the residual part.
* Above the last Froude number (0.75 upright, 0.55 heeled) R_r / (rho g V) is held at its last
  value, not extrapolated: past the hump a light displacement hull's R_r / W levels off
  (Keuning & Katgert 2008 Fig. 1), while a linear extrapolation of the table's last slope
  (a7, a5 change sign between 0.70 and 0.75) has no data under it.
* Astern the same resistance acts with the opposite sign (R odd in u_r): the series was towed
  bow first only; an odd force keeps the term dissipative (power -R |u_r| <= 0) and the
  boat does not go astern fast enough for the difference to matter.
* Point of action: along body x at CO, like eq. 15's friction. The regression gives a
  resistance, no trim moment (the models were free to sink and trim, and their trim is not
  part of the fit); a line of action through a lower point (say T_c / 3 down, 6 cm on the
  Wille yacht) would add a bow-down moment of under 1 % of the restoring moment of 1 deg trim.
* Heel is the roll angle of the hull, atan2(R21, R22) of the body->world rotation
  (:func:`sailmujoco.frames.euler_from_matrix`), taken in absolute value (port or starboard
  heel is the same hull shape), capped at 90 deg (the kernel stops at capsize anyway).

The canoe body's parameters come from :mod:`sailmujoco.boat.hull` (:func:`delft_hull`), so a new
hull shape carries over. Its sections are half-ellipses and its section area (1 - (2x/L)^2)^2
along x, hence C_p = V / (A_m L) = 8/15 and C_m = A_m / (B T_c) = pi/4; LCB = LCF = midship.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..boat import hull as hull_geometry
from ..constants import GRAVITY
from ..jit.kernel import kernel
from ..jit.ordered import mat_t_vec

# ---- Keuning & Katgert (2008), Fossati (2009) Table 2.5: upright residuary resistance -------
UPRIGHT_FROUDE = np.array([0.15, 0.20, 0.25, 0.30, 0.35, 0.40, 0.45, 0.50, 0.55, 0.60, 0.65,
                           0.70, 0.75])
UPRIGHT_COEFFICIENTS = np.array([  # rows a0..a7, columns UPRIGHT_FROUDE
    [-0.0005, -0.0003, -0.0002, -0.0009, -0.0026, -0.0064, -0.0218, -0.0388, -0.0347, -0.0361,
     0.0008, 0.0108, 0.1023],  # a0
    [0.0023, 0.0059, -0.0156, 0.0016, -0.0567, -0.4034, -0.5261, -0.5986, -0.4764, 0.0037,
     0.3728, -0.1238, 0.7726],  # a1: LCB_fpp / L_WL
    [-0.0086, -0.0064, 0.0031, 0.0337, 0.0446, -0.1250, -0.2945, -0.3038, -0.2361, -0.2960,
     -0.3667, -0.2026, 0.5040],  # a2: C_p
    [-0.0015, 0.0070, -0.0021, -0.0285, -0.1091, 0.0273, 0.2485, 0.6033, 0.8726, 0.9661,
     1.3957, 1.1282, 1.7867],  # a3: V_c^(2/3) / A_w
    [0.0061, 0.0014, -0.0070, -0.0367, -0.0707, -0.1341, -0.2428, -0.0430, 0.4219, 0.6123,
     1.0343, 1.1836, 2.1934],  # a4: B_WL / L_WL
    [0.0010, 0.0013, 0.0148, 0.0218, 0.0914, 0.3578, 0.6293, 0.8332, 0.8990, 0.7534, 0.3230,
     0.4973, -1.5479],  # a5: LCB_fpp / LCF_fpp
    [0.0001, 0.0005, 0.0010, 0.0015, 0.0021, 0.0045, 0.0081, 0.0106, 0.0096, 0.0100, 0.0072,
     0.0038, -0.0115],  # a6: B_WL / T_c
    [0.0052, -0.0020, -0.0043, -0.0172, -0.0078, 0.1115, 0.2086, 0.1336, -0.2272, -0.3352,
     -0.4632, -0.4477, -0.0977],  # a7: C_m
])

# ---- Keuning & Sonnenberg (1998): residuary resistance increment at 20 deg heel -----------
HEEL_FROUDE = np.array([0.25, 0.30, 0.35, 0.40, 0.45, 0.50, 0.55])
HEEL_COEFFICIENTS = np.array([  # rows u0..u5, columns HEEL_FROUDE; the result is x 1e-3
    [-0.0268, 0.6628, 1.6433, -0.8659, -3.2715, -0.1976, 1.5873],  # u0
    [-0.0014, -0.0632, -0.2144, -0.0354, 0.1372, -0.1480, -0.3749],  # u1: L_WL / B_WL
    [-0.0057, -0.0699, -0.1640, 0.2226, 0.5547, -0.6593, -0.7105],  # u2: B_WL / T_c
    [0.0016, 0.0069, 0.0199, 0.0188, 0.0268, 0.1862, 0.2146],  # u3: (B_WL / T_c)^2
    [-0.0070, 0.0459, -0.0540, -0.5800, -1.0064, -0.7489, -0.4818],  # u4: LCB, % L from midship
    [-0.0017, -0.0004, -0.0268, -0.1133, -0.2026, -0.1648, -0.1174],  # u5: LCB^2
])
HEEL_REFERENCE = math.radians(20.0)  # rad, the heel of the KS98 table
HEEL_EXPONENT = 1.7  # KS98 heel scaling 6 phi^1.7
HEEL_FACTOR = 6.0  # KS98 heel scaling 6 phi^1.7
MAX_HEEL = 0.5 * math.pi  # rad

# ---- layout of the resistance block of P (forces/boat.py P_RESISTANCE_BLOCK) -------------
R_WEIGHT, R_SQRT_GL = 0, 1  # rho g V_c (N), sqrt(g L_WL) (m/s)
R_UP_FN0, R_UP_DFN, R_UP_N = 2, 3, 4  # upright grid: first Fn, step, count
R_HEEL_FN0, R_HEEL_DFN, R_HEEL_N = 5, 6, 7  # heel grid
R_UP_VALUES = 8  # R_r / (rho g V_c) at the upright grid
R_HEEL_VALUES = R_UP_VALUES + UPRIGHT_FROUDE.size  # dR_rh(20 deg) / (rho g V_c) at the heel grid
R_USED = R_HEEL_VALUES + HEEL_FROUDE.size


@dataclass(frozen=True)
class DelftHull:
    """The canoe-body parameters of the DSYHS regressions (SI; LCB, LCF from the forward
    perpendicular).

    Parameters
    ----------
    length, beam : float
        L_WL and B_WL, m.
    draft : float
        T_c, canoe body draft, m.
    volume : float
        V_c, displaced volume of the canoe body, m^3.
    lcb, lcf : float
        LCB_fpp and LCF_fpp, aft of the forward perpendicular, m.
    prismatic, midship : float
        C_p and C_m, dimensionless.
    waterplane_area : float
        A_w, m^2.
    """

    length: float
    beam: float
    draft: float
    volume: float
    lcb: float
    lcf: float
    prismatic: float
    midship: float
    waterplane_area: float

    @property
    def lcb_percent(self) -> float:
        """LCB in per cent of L_WL from midship, positive forward (Keuning & Sonnenberg 1998)."""
        return 100.0 * (0.5 - self.lcb / self.length)


def delft_hull(h: hull_geometry.HullShape) -> DelftHull:
    """The DSYHS parameters of a :class:`~sailmujoco.boat.hull.HullShape` canoe body (module docstring).

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    volume = hull_geometry.volume(h)
    beam, draft = 2.0 * h.half_beam, h.canoe_draft
    prismatic = 8.0 / 15.0  # section area (1 - (2x/L)^2)^2 A_m along x (hull.py)
    midship = volume / (prismatic * h.length * beam * draft)  # A_m / (B T_c) = pi/4
    mid = 0.5 * h.length  # CO is midship; both centroids lie there
    return DelftHull(length=h.length, beam=beam, draft=draft, volume=volume,
                     lcb=mid - 0.0, lcf=mid - hull_geometry.centre_of_flotation_x(h),
                     prismatic=prismatic, midship=midship,
                     waterplane_area=hull_geometry.waterplane_area(h))


def upright_table(d: DelftHull) -> np.ndarray:
    """R_r / (rho g V_c) at :data:`UPRIGHT_FROUDE`, Keuning & Katgert (2008), clipped at 0.

    Parameters
    ----------
    d : DelftHull
        The canoe body's DSYHS parameters.
    """
    slender = d.volume ** (1.0 / 3.0) / d.length
    terms = np.array([1.0 / slender, d.lcb / d.length, d.prismatic,
                      d.volume ** (2.0 / 3.0) / d.waterplane_area, d.beam / d.length,
                      d.lcb / d.lcf, d.beam / d.draft, d.midship])
    return np.maximum(slender * mat_t_vec(UPRIGHT_COEFFICIENTS, terms), 0.0)  # terms @ C, summed in order


def heel_table(d: DelftHull) -> np.ndarray:
    """dR_rh(20 deg) / (rho g V_c) at :data:`HEEL_FROUDE`, Keuning & Sonnenberg (1998), clipped at 0.

    Parameters
    ----------
    d : DelftHull
        The canoe body's DSYHS parameters.
    """
    bt, lcb = d.beam / d.draft, d.lcb_percent
    terms = np.array([1.0, d.length / d.beam, bt, bt * bt, lcb, lcb * lcb])
    return np.maximum(1e-3 * mat_t_vec(HEEL_COEFFICIENTS, terms), 0.0)


def _read_table(fn: float, grid: np.ndarray, values: np.ndarray) -> float:
    """Interpolate a table in Fn with the range choices of the module docstring."""
    if fn <= grid[0]:
        return float(values[0] * (fn / grid[0]) ** 2)
    return float(np.interp(fn, grid, values))  # np.interp holds the last value above the grid


def heel_factor(heel: float) -> float:
    """dR_rh(phi) / dR_rh(20 deg) = 6 |phi|^1.7, Keuning & Sonnenberg (1998) (|phi| capped at 90 deg).

    Parameters
    ----------
    heel : float
        Heel phi, rad.
    """
    return HEEL_FACTOR * min(abs(heel), MAX_HEEL) ** HEEL_EXPONENT


def residuary_coefficient(d: DelftHull, froude: float, heel: float = 0.0) -> float:
    """R_r / (rho g V_c) of the hull at Froude number ``froude`` (>= 0) and ``heel`` [rad].

    Parameters
    ----------
    d : DelftHull
        The canoe body's DSYHS parameters.
    froude : float
        Fn = |u_r| / sqrt(g L_WL), >= 0.
    heel : float
        Heel, rad.
    """
    upright = _read_table(froude, UPRIGHT_FROUDE, upright_table(d))
    increment = _read_table(froude, HEEL_FROUDE, heel_table(d))
    return upright + increment * heel_factor(heel)


def residuary_resistance(d: DelftHull, u_r: float, heel: float = 0.0, rho: float = 1025.0,
                         g: float = GRAVITY) -> float:
    """Surge force (N, body x) of the residuary resistance at surge speed ``u_r`` through the water.

    -sign(u_r) rho g V_c R_r/(rho g V_c)(Fn = |u_r| / sqrt(g L_WL), heel): odd in u_r.

    Parameters
    ----------
    d : DelftHull
        The canoe body's DSYHS parameters.
    u_r : float
        Surge speed through the water, m/s.
    heel : float
        Heel, rad.
    rho, g : float
        Water density (kg/m^3) and gravity (m/s^2).
    """
    if u_r == 0.0:
        return 0.0
    froude = abs(u_r) / math.sqrt(g * d.length)
    return -math.copysign(rho * g * d.volume * residuary_coefficient(d, froude, heel), u_r)


def pack_resistance(d: DelftHull, rho: float, g: float = GRAVITY) -> np.ndarray:
    """The resistance block of P (layout R_* above): what :func:`residuary_surge_force` reads.

    Parameters
    ----------
    d : DelftHull
        The canoe body's DSYHS parameters.
    rho, g : float
        Water density (kg/m^3) and gravity (m/s^2).
    """
    block = np.zeros(R_USED)
    block[R_WEIGHT], block[R_SQRT_GL] = rho * g * d.volume, math.sqrt(g * d.length)
    for fn0, dfn, n, grid in ((R_UP_FN0, R_UP_DFN, R_UP_N, UPRIGHT_FROUDE),
                              (R_HEEL_FN0, R_HEEL_DFN, R_HEEL_N, HEEL_FROUDE)):
        steps = np.diff(grid)
        assert np.allclose(steps, steps[0]), "the kernel reads uniform Froude grids"
        block[fn0], block[dfn], block[n] = grid[0], steps[0], grid.size
    block[R_UP_VALUES:R_HEEL_VALUES] = upright_table(d)
    block[R_HEEL_VALUES:R_USED] = heel_table(d)
    return block


@kernel
def _table_value(fn, fn0, dfn, n, values):
    """Kernel twin of :func:`_read_table` on a uniform grid fn0 + k dfn, k < n."""
    if fn <= fn0:
        s = fn / fn0
        return values[0] * s * s
    x = (fn - fn0) / dfn
    k = int(x)
    if k >= n - 1:
        return values[n - 1]
    f = x - k
    return values[k] + f * (values[k + 1] - values[k])


@kernel
def residuary_surge_force(u_r, heel, block):
    """Residuary resistance (N, along body x, at CO) from the packed ``block``; odd in u_r.

    Parameters
    ----------
    u_r : float
        Surge speed through the water, m/s.
    heel : float
        Heel, rad.
    block : numpy.ndarray
        The block of :func:`pack_resistance`.
    """
    if u_r == 0.0:
        return 0.0
    fn = abs(u_r) / block[R_SQRT_GL]
    n_up = int(block[R_UP_N])
    n_heel = int(block[R_HEEL_N])
    c = _table_value(fn, block[R_UP_FN0], block[R_UP_DFN], n_up,
                     block[R_UP_VALUES:R_UP_VALUES + n_up])
    phi = min(abs(heel), MAX_HEEL)
    if phi > 0.0:
        c += _table_value(fn, block[R_HEEL_FN0], block[R_HEEL_DFN], n_heel,
                          block[R_HEEL_VALUES:R_HEEL_VALUES + n_heel]) \
            * HEEL_FACTOR * phi ** HEEL_EXPONENT
    return -math.copysign(block[R_WEIGHT] * c, u_r)
