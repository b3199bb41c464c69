"""Published estimates of the added resistance in regular head waves, to set a measured curve
(:mod:`sailmujoco.design.added_resistance`) against.

* :func:`stawave2`: the ITTC's empirical formula STAwave-2 (ITTC recommended procedure
  7.5-04-01-01.1, "Preparation, conduct and analysis of speed/power trials", its annex on
  STAwave-2; Sakamoto, Kuroda and Tsujimoto's fit to ship model tests). Its motion part is a
  fit over ships of L 75-350 m, L/B 4-9, B/T 2.2-5.5, C_B 0.5-0.9, Fr 0.1-0.3; a yacht's canoe
  body (C_B about 0.42, B/T about 10) lies outside it, so it is a scale, not a target. The
  constants are as two independent transcriptions of the 2014-2017 text give them (they agree
  term by term); the 2017 text's d1 above omega_bar = 1 is -566 (L/B)^-2.66.
* :func:`gerritsma_beukelman`: the radiated-energy method (Gerritsma & Beukelman 1972,
  "Analysis of the resistance increase in waves of a fast cargo ship", ISP 19): the added
  resistance is the energy the hull's heave and pitch radiate per encounter period, divided by
  the distance the wave travels relative to the hull in it,

      R_aw = k / (2 omega_e) integral over L of b'_33(x) V_za(x)^2 dx,
      b'_33 = N'(x) - U dm'/dx,

  with x toward the bow, N' and m' the sections' damping and added mass at the encounter
  frequency and V_za the amplitude of each section's vertical velocity relative to the water
  (its wave elevation's rate, Smith-corrected to the section's mean depth by e^(-k T_m)).
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from ..constants import GRAVITY


def stawave2(length: float, beam: float, draft: float, block: float, gyradius: float,
             speed: float, wavelength_ratio, g: float = GRAVITY):
    """STAwave-2's sigma_aw = R_aw / (rho g zeta_a^2 B^2 / L) in regular head waves.

    sigma_aw = 4 rbar(omega) + (L / 2B) alpha_1(omega): the motion part and the reflection part.

    Parameters
    ----------
    length, beam, draft : float
        Waterline length L, beam B and draft T, m.
    block : float
        Block coefficient C_B = V / (L B T), -.
    gyradius : float
        Pitch radius of gyration over L, k_yy, -.
    speed : float
        Speed U, m/s.
    wavelength_ratio : float or numpy.ndarray
        lambda / L, -.
    g : float
        Gravity, m/s^2.
    """
    lam = np.asarray(wavelength_ratio, dtype=float) * length
    k = 2.0 * math.pi / lam
    omega = np.sqrt(g * k)
    fr = speed / math.sqrt(g * length)
    omega_bar = math.sqrt(length / g) * gyradius ** (1.0 / 3.0) / (1.17 * fr ** -0.143) * omega
    low = omega_bar < 1.0
    b1 = np.where(low, 11.0, -8.50)
    d1 = np.where(low, 14.0, -566.0 * (length / beam) ** -2.66)
    a1 = 60.3 * block**1.34
    rbar = omega_bar**b1 * np.exp(b1 / d1 * (1.0 - omega_bar**d1)) * a1 * fr**1.50 * math.exp(-3.50 * fr)
    x = 1.5 * k * draft
    bessel = math.pi**2 * special.i1(x) ** 2
    f1 = 0.692 * (speed / math.sqrt(draft * g)) ** 0.769 + 1.81 * block**6.95
    alpha1 = bessel / (bessel + special.k1(x) ** 2) * f1
    return 4.0 * rbar + 0.5 * length / beam * alpha1


def gerritsma_beukelman(x, relative_velocity, damping, added_mass_slope, speed: float, k: float,
                        omega_e: float) -> float:
    """Added resistance (N) by the radiated-energy method (module docstring).

    Parameters
    ----------
    x : numpy.ndarray, shape (n,)
        Stations along the hull, m, toward the bow, evenly spaced.
    relative_velocity : numpy.ndarray, shape (n,)
        Amplitude of each station's vertical velocity relative to the water, V_za, m/s.
    damping : numpy.ndarray, shape (n,)
        Sectional heave damping N'(x) at the encounter frequency, N s/m^2.
    added_mass_slope : numpy.ndarray, shape (n,)
        dm'/dx of the sectional heave added mass, kg/m^2.
    speed : float
        Forward speed U, m/s.
    k, omega_e : float
        Wavenumber (rad/m) and encounter frequency (rad/s).
    """
    b33 = np.asarray(damping) - speed * np.asarray(added_mass_slope)
    dx = float(x[1] - x[0])
    return float(k / (2.0 * omega_e) * np.sum(b33 * np.asarray(relative_velocity) ** 2) * dx)
