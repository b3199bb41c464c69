"""Wave spectra and directional spreading.

The spectra are one-sided densities in angular frequency, S(omega) in m^2 s/rad, with
m0 = integral of S d omega = Hs^2 / 16 (Hs the significant wave height, 4 sqrt(m0)), as in
DNV-RP-C205 (2010) §3.5.5:

* Pierson-Moskowitz in its Hs/Tp form (DNV-RP-C205 eq. 3.5.5.1, Pierson & Moskowitz 1964),
  S_PM(omega) = (5/16) Hs^2 omega_p^4 omega^-5 exp(-(5/4) (omega/omega_p)^-4), omega_p = 2 pi/Tp.
* JONSWAP (Hasselmann et al. 1973; DNV-RP-C205 eqs. 3.5.5.2-3.5.5.4),
  S_J(omega) = A_gamma S_PM(omega) gamma^exp(-(omega - omega_p)^2 / (2 sigma^2 omega_p^2)),
  A_gamma = 1 - 0.287 ln(gamma), sigma = 0.07 for omega <= omega_p and 0.09 above.
  A_gamma keeps m0 = Hs^2/16 to 0.3 % for 1 <= gamma <= 5 and 1.8 % at gamma = 7
  (DNV's stated range is 1 to 7); gamma = 1 is Pierson-Moskowitz.

Directional spreading: the cos-2s distribution (Longuet-Higgins, Cartwright & Smith 1963),
D(theta) proportional to cos^(2s)((theta - theta_0)/2) on (-pi, pi], sampled by its inverse
cumulative distribution on a grid.

The sea a wind raises (:meth:`sailmujoco.options.WaveConfig.from_wind`, whose formulas
:func:`~sailmujoco.options.fully_developed_sea` and :func:`~sailmujoco.options.fetch_limited_sea`
live beside the sea's configuration), from the wind speed at 10 m, U10:

* fully developed (Pierson & Moskowitz 1964, as Stewart 2008 §16.3 writes it):
  Hs = 0.21 U19.5^2/g (eq. 16.33), omega_p = 0.877 g/U19.5 (eq. 16.30), with
  U19.5 = 1.026 U10 (eq. 16.29: a neutral atmosphere, drag coefficient 1.3e-3);
* fetch-limited (JONSWAP growth, Hasselmann et al. 1973, in the form of the Shore Protection
  Manual 1984 eqs. 3-33 and 3-34 with U10 for its adjusted wind): chi = g F/U10^2,
  Hs = 1.6e-3 chi^(1/2) U10^2/g, Tp = 0.2857 chi^(1/3) U10/g, each at most its fully
  developed value.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.ordered import elementwise, gauss_legendre, power

JONSWAP_SIGMA_LOW = 0.07  # -, peak width below omega_p, Hasselmann et al. (1973)
JONSWAP_SIGMA_HIGH = 0.09  # -, peak width above omega_p
JONSWAP_NORMALISATION = 0.287  # -, A_gamma = 1 - 0.287 ln gamma, DNV-RP-C205 eq. 3.5.5.4
_SPREAD_GRID = 4097  # points of the cos-2s inverse-CDF grid on [-pi, pi] (odd: holds theta = 0)


def pierson_moskowitz(omega, hs: float, tp: float):
    """Pierson-Moskowitz spectrum in its Hs/Tp form, m^2 s/rad (DNV-RP-C205 eq. 3.5.5.1).

    S(omega) = (5/16) Hs^2 omega_p^4 omega^-5 exp(-(5/4) (omega/omega_p)^-4), omega_p = 2 pi/Tp;
    zero at omega <= 0.

    Parameters
    ----------
    omega : array_like
        Angular frequency, rad/s.
    hs : float
        Significant wave height, m.
    tp : float
        Peak period, s.
    """
    omega = np.asarray(omega, dtype=float)
    wp = 2.0 * math.pi / tp
    w = np.where(omega > 0.0, omega, 1.0)
    # the powers and the exponential through the C library: numpy's pick a SIMD kernel by CPU
    s = 5.0 / 16.0 * hs**2 * wp**4 * power(w, -5.0) * elementwise(math.exp, -1.25 * power(w / wp, -4.0))
    return np.where(omega > 0.0, s, 0.0)


def jonswap(omega, hs: float, tp: float, gamma: float):
    """JONSWAP spectrum, m^2 s/rad (Hasselmann et al. 1973; DNV-RP-C205 eqs. 3.5.5.2-3.5.5.4).

    S(omega) = A_gamma S_PM(omega) gamma^r, r = exp(-(omega - omega_p)^2/(2 sigma^2 omega_p^2)),
    A_gamma = 1 - 0.287 ln gamma, sigma 0.07 below omega_p and 0.09 above.

    Parameters
    ----------
    omega : array_like
        Angular frequency, rad/s.
    hs : float
        Significant wave height, m.
    tp : float
        Peak period, s.
    gamma : float
        Peak enhancement factor, in [1, 7].
    """
    omega = np.asarray(omega, dtype=float)
    wp = 2.0 * math.pi / tp
    sigma = np.where(omega <= wp, JONSWAP_SIGMA_LOW, JONSWAP_SIGMA_HIGH)
    r = elementwise(math.exp, -((omega - wp) ** 2) / (2.0 * sigma**2 * wp**2))
    a_gamma = 1.0 - JONSWAP_NORMALISATION * math.log(gamma)
    return a_gamma * pierson_moskowitz(omega, hs, tp) * power(gamma, r)


def spectrum_density(config, omega):
    """The spectrum of a sea state, S(omega) in m^2 s/rad, one-sided, m0 = Hs^2/16.

    ``"pm"``: :func:`pierson_moskowitz`; ``"jonswap"``: :func:`jonswap` with the config's
    gamma. A regular wave has no density (a line at 2 pi/T): a ValueError says so.

    Parameters
    ----------
    config : WaveConfig
        The sea state (its ``spectrum``, ``hs``, ``tp``, ``gamma``).
    omega : array_like
        Angular frequency, rad/s.
    """
    if config.spectrum == "pm":
        return pierson_moskowitz(omega, config.hs, config.tp)
    if config.spectrum == "jonswap":
        return jonswap(omega, config.hs, config.tp, config.gamma)
    raise ValueError(f"spectrum_density: a {config.spectrum!r} sea has no spectral density "
                     "(accepted: pm, jonswap)")


def bin_energies(config, edges: np.ndarray, nodes: int = 16) -> np.ndarray:
    """Integral of the spectrum over each bin [edges[i], edges[i+1]], m^2 (Gauss-Legendre).

    Parameters
    ----------
    config : WaveConfig
        The sea state.
    edges : numpy.ndarray, shape (n + 1,)
        Bin edges, rad/s, increasing.
    nodes : int
        Gauss-Legendre nodes per bin.
    """
    x, w = gauss_legendre(nodes)
    lo, hi = edges[:-1, None], edges[1:, None]
    half = 0.5 * (hi - lo)
    omega = lo + half * (x[None, :] + 1.0)
    return np.sum(spectrum_density(config, omega) * w[None, :] * half, axis=1)


def spreading_offsets(s: float, uniform: np.ndarray) -> np.ndarray:
    """Directions theta - theta_0 (rad) of the cos-2s distribution at the given quantiles.

    D(theta) proportional to cos^(2s)(theta/2) on [-pi, pi]; the cumulative distribution is
    integrated by the trapezoidal rule on a grid of 4097 points and inverted by linear
    interpolation.

    Parameters
    ----------
    s : float
        Spreading exponent, > 0 (larger: narrower).
    uniform : numpy.ndarray
        Quantiles in [0, 1).
    """
    theta = np.linspace(-math.pi, math.pi, _SPREAD_GRID)
    pdf = power(elementwise(math.cos, 0.5 * theta), 2.0 * s)
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (pdf[1:] + pdf[:-1]) * np.diff(theta))])
    return np.interp(uniform, cdf / cdf[-1], theta)
