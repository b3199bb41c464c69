"""The sea state: a seeded field of deep-water Airy waves (elevation, orbital velocity, pressure).

A sea is a sum of linear (Airy) components in deep water, each with amplitude a_i, angular
frequency omega_i, wavenumber k_i = omega_i^2/g, the world direction beta_i it travels toward
(x east, y north, counter-clockwise from east) and phase phi_i:

    theta_i = k_i (x cos beta_i + y sin beta_i) - omega_i t + phi_i
    eta = r(t) sum_i a_i cos theta_i                                     (elevation, m, up)
    u_h = r(t) sum_i a_i omega_i e^(k_i z_s) cos theta_i (cos beta_i, sin beta_i)   (m/s)
    w   = r(t) sum_i a_i omega_i e^(k_i z_s) sin theta_i                    (m/s, up)
    p_d = r(t) rho g sum_i a_i e^(k_i z_s) cos theta_i                    (Pa)

* Stretching: the depth is measured from the local surface, z_s = min(z - eta, 0) (Wheeler
  1970 in the deep-water limit, z_s = d (z - eta)/(d + eta) as d -> infinity), so a crest never
  evaluates e^(k z) above the water: at z = eta every component has its surface value, and a
  point above the surface gets the surface value too (whether a point is wet is the caller's
  question: compare z with :func:`elevation`). The total pressure -rho g z + p_d is then zero at
  z = eta exactly; the field is divergence-free to first order in the steepness a k.
* Components: ``"regular"`` is one component, a = H/2 with H = ``hs`` the crest-to-trough
  height, omega = 2 pi/``tp``, phase 0 (after the ramp a crest passes the origin at every
  whole period).
  ``"pm"`` and ``"jonswap"`` (:mod:`sailmujoco.forces.wave_spectra`) split the band
  0.5 omega_p .. 5 omega_p (the neglected tail: 0.2 % of m0 for Pierson-Moskowitz, 0.1 % for
  JONSWAP gamma = 3.3) into ``n_components`` equal bins; a_i = sqrt(2 E_i), E_i the spectrum's
  integral over bin i, and omega_i drawn uniformly inside its bin so the sea has no repeat
  period 2 pi/Delta omega. Each component travels toward the mean direction, or, with
  ``spreading`` = s, toward one drawn from the cos-2s distribution about it (short-crested).
* Randomness: the frequencies, then the phases (uniform in [0, 2 pi)), then the directions come
  from ``numpy.random.default_rng([seed, 3])``; the wind draws its gusts from ``[seed, 1]`` and
  its wander from ``[seed, 2]`` (:class:`~sailmujoco.forces.wind.WindField`), so a sea changes
  none of the wind's draws, and the same seed gives the same sea bit for bit.
* Ramp r(t) = (1 - cos(pi t/T_r))/2 over T_r = 3 Tp, 0 before t = 0 and 1 after T_r: a
  simulation starts from calm water without a jolt.

Conventions as :class:`~sailmujoco.forces.wind.WindConfig`: SI, radians, ``direction_from`` the
compass bearing the waves come *from* (0: from the north, travelling south). Arrays are plain
float64 so a compiled kernel can read them.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from .. import constants as c
from ..frames import yaw_from_heading
from ..options import WaveConfig
from .wave_spectra import bin_energies, spreading_offsets

BAND = (0.5, 5.0)  # -, the simulated band as multiples of omega_p
RAMP_PERIODS = 3.0  # -, the ramp lasts this many peak periods
WAVE_STREAM = 3  # the sea's random stream, default_rng([seed, 3]); the wind uses 1 and 2


@dataclass(frozen=True)
class WaveComponents:
    """The seeded components of a sea: plain float64 arrays of shape (n,), read-only.

    Attributes
    ----------
    amplitude : numpy.ndarray
        a_i, m.
    omega : numpy.ndarray
        omega_i, rad/s.
    k : numpy.ndarray
        Wavenumber k_i = omega_i^2/g, rad/m (deep water).
    direction_to : numpy.ndarray
        World angle each component travels toward, rad, counter-clockwise from east (x east,
        y north).
    phase : numpy.ndarray
        phi_i, rad.
    """

    amplitude: np.ndarray
    omega: np.ndarray
    k: np.ndarray
    direction_to: np.ndarray
    phase: np.ndarray


def _frozen(values) -> np.ndarray:
    out = np.ascontiguousarray(values, dtype=np.float64)
    out.flags.writeable = False
    return out


@functools.lru_cache(maxsize=64)
def components(config: WaveConfig) -> WaveComponents:
    """The components of a sea state, drawn once per config (cached).

    Parameters
    ----------
    config : WaveConfig
        The sea state.
    """
    mean_to = float(yaw_from_heading(config.direction_from + math.pi))
    if config.spectrum == "regular":
        omega = np.array([2.0 * math.pi / config.tp])
        return WaveComponents(_frozen([0.5 * config.hs]), _frozen(omega),
                              _frozen(omega**2 / c.GRAVITY), _frozen([mean_to]), _frozen([0.0]))
    n = config.n_components
    wp = 2.0 * math.pi / config.tp
    edges = np.linspace(BAND[0] * wp, BAND[1] * wp, n + 1)
    rng = np.random.default_rng([config.seed, WAVE_STREAM])
    omega = edges[:-1] + rng.uniform(0.0, 1.0, n) * np.diff(edges)
    phase = rng.uniform(0.0, 2.0 * math.pi, n)
    direction = np.full(n, mean_to)
    if config.spreading is not None:
        direction = direction + spreading_offsets(config.spreading, rng.uniform(0.0, 1.0, n))
    amplitude = np.sqrt(2.0 * bin_energies(config, edges))
    return WaveComponents(_frozen(amplitude), _frozen(omega), _frozen(omega**2 / c.GRAVITY),
                          _frozen(direction), _frozen(phase))


def ramp(config: WaveConfig, t):
    """The start-up ramp r(t) = (1 - cos(pi t/T_r))/2, T_r = 3 Tp; 0 for t <= 0, 1 from T_r.

    Parameters
    ----------
    config : WaveConfig
        The sea state (its ``tp``).
    t : array_like
        Time, s.
    """
    duration = RAMP_PERIODS * config.tp
    s = np.clip(np.asarray(t, dtype=float) / duration, 0.0, 1.0)
    return 0.5 * (1.0 - np.cos(math.pi * s))


def _phases(comp: WaveComponents, t, x, y):
    """(theta_i at every point, shape S + (n,), and the broadcast t of shape S)."""
    t, x, y = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (t, x, y)))
    kx = comp.k * np.cos(comp.direction_to)
    ky = comp.k * np.sin(comp.direction_to)
    theta = x[..., None] * kx + y[..., None] * ky - t[..., None] * comp.omega + comp.phase
    return theta, t


def elevation(config: WaveConfig, t, x, y):
    """Surface elevation eta (m, up from the still water) at times and world points.

    eta = r(t) sum_i a_i cos theta_i. The arguments broadcast against each other.

    Parameters
    ----------
    config : WaveConfig
        The sea state.
    t : array_like
        Time, s.
    x, y : array_like
        World east and north, m.
    """
    comp = components(config)
    theta, t = _phases(comp, t, x, y)
    return (ramp(config, t) * (np.cos(theta) @ comp.amplitude))[()]


def _stretched(config: WaveConfig, t, x, y, z):
    """(components, theta, cos theta, e^(k z_s) of shape S + (n,), r(t)) at the points."""
    comp = components(config)
    theta, t = _phases(comp, t, x, y)
    cos = np.cos(theta)
    r = ramp(config, t)
    eta = r * (cos @ comp.amplitude)
    z_s = np.minimum(np.asarray(z, dtype=float) - eta, 0.0)
    return comp, theta, cos, np.exp(z_s[..., None] * comp.k), r


def orbital_velocity(config: WaveConfig, t, x, y, z):
    """Water velocity (m/s, world east, north, up) at times and world points, stretched.

    u_h = r sum_i a_i omega_i e^(k_i z_s) cos theta_i (cos beta_i, sin beta_i),
    w = r sum_i a_i omega_i e^(k_i z_s) sin theta_i, z_s = min(z - eta, 0). The arguments
    broadcast against each other to a shape S; the result has shape S + (3,).

    Parameters
    ----------
    config : WaveConfig
        The sea state.
    t : array_like
        Time, s.
    x, y, z : array_like
        World east, north and up, m (z = 0 the still water).
    """
    comp, theta, cos, decay, r = _stretched(config, t, x, y, z)
    weight = decay * (comp.amplitude * comp.omega)
    horizontal = (weight * cos) * r[..., None]
    out = np.empty(cos.shape[:-1] + (3,))
    out[..., 0] = horizontal @ np.cos(comp.direction_to)
    out[..., 1] = horizontal @ np.sin(comp.direction_to)
    out[..., 2] = r * np.sum(weight * np.sin(theta), axis=-1)
    return out


def dynamic_pressure(config: WaveConfig, t, x, y, z, rho: float = c.RHO_WATER):
    """Dynamic pressure of the waves p_d (Pa) at times and world points, stretched.

    p_d = r rho g sum_i a_i e^(k_i z_s) cos theta_i; the total pressure below the surface is
    -rho g z + p_d (gauge, zero in the air), which vanishes at z = eta. Above the surface p_d is
    the surface value rho g eta.

    Parameters
    ----------
    config : WaveConfig
        The sea state.
    t : array_like
        Time, s.
    x, y, z : array_like
        World east, north and up, m (z = 0 the still water).
    rho : float
        Water density, kg/m^3.
    """
    comp, _, cos, decay, r = _stretched(config, t, x, y, z)
    return (rho * c.GRAVITY * r * ((decay * cos) @ comp.amplitude))[()]
