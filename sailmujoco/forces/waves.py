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
from typing import Literal

import numpy as np

from .. import constants as c
from ..frames import yaw_from_heading
from ..names import check_known
from .wave_spectra import (  # noqa: F401 - the spectra, importable from here too
    bin_energies,
    fetch_limited_sea,
    fully_developed_sea,
    jonswap,
    pierson_moskowitz,
    spectrum_density,
    spreading_offsets,
)

Spectrum = Literal["regular", "pm", "jonswap"]
SPECTRA = ("regular", "pm", "jonswap")
SEA_KINDS = ("fully_developed", "fetch_limited")
BAND = (0.5, 5.0)  # -, the simulated band as multiples of omega_p
RAMP_PERIODS = 3.0  # -, the ramp lasts this many peak periods
WAVE_STREAM = 3  # the sea's random stream, default_rng([seed, 3]); the wind uses 1 and 2
N_COMPONENTS = 16  # -, default number of components (the cost and the error: docs/physics.md)
GAMMA_RANGE = (1.0, 7.0)  # -, JONSWAP gamma, DNV-RP-C205 §3.5.5
MAX_WIND = 100.0  # m/s, U10 for a wind-raised sea, as WindConfig.speed


def _finite(name: str, value, unit: str) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"WaveConfig.{name} must be a finite number{unit}, got {value!r}")


@dataclass(frozen=True)
class WaveConfig:
    """A sea state: spectrum, height, period, direction, spreading and seed. SI, radians.

    ``hs = 0`` is calm water.

    Parameters
    ----------
    spectrum : {"regular", "pm", "jonswap"}
        ``"regular"``: one Airy wave; ``"pm"``: Pierson-Moskowitz; ``"jonswap"``: JONSWAP.
    hs : float
        Significant wave height Hs = 4 sqrt(m0), m, >= 0; for ``"regular"`` the crest-to-trough
        height H.
    tp : float
        Peak period, s, > 0; for ``"regular"`` the period T.
    direction_from : float
        Compass bearing the waves come from, rad (0: from the north, travelling south).
    gamma : float
        JONSWAP peak enhancement factor, in [1, 7] (read by ``"jonswap"`` only).
    spreading : float or None
        None: long-crested (every component travels the mean direction); s > 0: each
        component's direction drawn from cos^(2s)((theta - theta_0)/2). Not for ``"regular"``.
    n_components : int
        Number of components of a spectral sea, >= 1.
    seed : int
        Seeds the frequencies, phases and directions, >= 0.
    """

    spectrum: Spectrum = "jonswap"
    hs: float = 0.0
    tp: float = 6.0
    direction_from: float = 0.0
    gamma: float = 3.3
    spreading: float | None = None
    n_components: int = N_COMPONENTS
    seed: int = 0

    def __post_init__(self):
        check_known([self.spectrum], SPECTRA, "WaveConfig.spectrum", kind="spectrum")
        _finite("hs", self.hs, " (m)")
        if self.hs < 0.0:
            raise ValueError(f"WaveConfig.hs must be >= 0 m, got {self.hs!r}")
        _finite("tp", self.tp, " (s)")
        if self.tp <= 0.0:
            raise ValueError(f"WaveConfig.tp must be > 0 s, got {self.tp!r}")
        _finite("direction_from", self.direction_from, " (rad)")
        _finite("gamma", self.gamma, "")
        if not GAMMA_RANGE[0] <= self.gamma <= GAMMA_RANGE[1]:
            raise ValueError(f"WaveConfig.gamma must be in [1, 7], got {self.gamma!r}")
        if self.spreading is not None:
            _finite("spreading", self.spreading, " or None")
            if self.spreading <= 0.0:
                raise ValueError(f"WaveConfig.spreading must be > 0 or None, got {self.spreading!r}")
            if self.spectrum == "regular":
                raise ValueError("WaveConfig.spreading must be None for spectrum 'regular' "
                                 f"(a regular wave is long-crested), got {self.spreading!r}")
        for name in ("n_components", "seed"):
            value = getattr(self, name)
            low = 1 if name == "n_components" else 0
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
                raise ValueError(f"WaveConfig.{name} must be an integer >= {low}, got {value!r}")

    @classmethod
    def from_wind(cls, u10: float, kind: str = "fully_developed", fetch: float | None = None,
                  direction_from: float = 0.0, *, spreading: float | None = None,
                  n_components: int = N_COMPONENTS, seed: int = 0) -> WaveConfig:
        """The sea a steady wind raises: fully developed (Pierson-Moskowitz) or fetch-limited.

        ``"fully_developed"``: a ``"pm"`` sea with Hs = 0.21 U19.5^2/g, omega_p = 0.877 g/U19.5,
        U19.5 = 1.026 U10 (Pierson & Moskowitz 1964; Stewart 2008 eqs. 16.29-16.33).
        ``"fetch_limited"``: a ``"jonswap"`` sea (gamma 3.3) with Hs = 1.6e-3 chi^(1/2) U10^2/g,
        Tp = 0.2857 chi^(1/3) U10/g, chi = g F/U10^2 (Hasselmann et al. 1973; Shore Protection
        Manual 1984 eqs. 3-33, 3-34), each at most its fully developed value. See
        :mod:`sailmujoco.forces.wave_spectra`. No wind (``u10 = 0``) is calm water.

        Parameters
        ----------
        u10 : float
            Mean wind speed at 10 m, m/s, in [0, 100] (``WindConfig.speed``).
        kind : {"fully_developed", "fetch_limited"}
            Which growth stage.
        fetch : float or None
            Fetch, m, > 0, for ``"fetch_limited"``; None for ``"fully_developed"``.
        direction_from : float
            Compass bearing the wind and the waves come from, rad.
        spreading : float or None
            As :class:`WaveConfig`.
        n_components : int
            As :class:`WaveConfig`.
        seed : int
            As :class:`WaveConfig`.
        """
        check_known([kind], SEA_KINDS, "WaveConfig.from_wind", kind="kind")
        if isinstance(u10, bool) or not isinstance(u10, (int, float)) or \
                not 0.0 <= u10 <= MAX_WIND:
            raise ValueError(f"WaveConfig.from_wind: u10 must be in [0, {MAX_WIND:g}] m/s, got {u10!r}")
        if kind == "fully_developed" and fetch is not None:
            raise ValueError(f"WaveConfig.from_wind: fetch must be None for a fully developed sea, "
                             f"got {fetch!r}")
        if kind == "fetch_limited" and (isinstance(fetch, bool) or not isinstance(fetch, (int, float))
                                        or not math.isfinite(fetch) or fetch <= 0.0):
            raise ValueError(f"WaveConfig.from_wind: fetch must be > 0 m for a fetch-limited sea, "
                             f"got {fetch!r}")
        spectrum = "pm" if kind == "fully_developed" else "jonswap"
        common = dict(spectrum=spectrum, direction_from=direction_from, spreading=spreading,
                      n_components=n_components, seed=seed)
        if u10 == 0.0:
            return cls(hs=0.0, **common)
        hs, tp = fully_developed_sea(u10) if kind == "fully_developed" else fetch_limited_sea(u10, fetch)
        return cls(hs=hs, tp=tp, **common)


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
