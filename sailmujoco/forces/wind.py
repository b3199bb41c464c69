"""Wind and current, Wille (2016a) eqs. 5 and 37-43.

* Mean wind: log profile, eq. 40, U_m(z) = U_m10 (5/2) sqrt(k) ln(z / z0),
  z0 = 10 exp(-2 / (5 sqrt(k))), k = 0.0026 (so U_m(10 m) = U_m10).
* Gusts: NORSOK N-003 spectrum, eqs. 37-38, as a sum of cosines, eq. 39,
  U_g(z, t) = sum_k sqrt(2 S(f_k, z) df) cos(2 pi f_k t + Y_k), f in (0, 0.4] Hz.
  The paper uses evenly spaced f_k; we draw one f_k uniformly inside each of the n bins
  (same df) so the series does not repeat every 1/df seconds. Phases Y_k and the f_k come
  from the seed, fixed for the run (the paper keeps Y fixed between simulations).
* Total speed U(z) = U_m(z) + U_g(z), eq. 41, evaluated at the sail CE's actual height
  (eq. 42 uses -h1 cos(phi) in NED; in 6-DOF the CE height comes from the full pose).
* Direction wander, eq. 43: beta_flux_dot = w (white noise), saturated at 5 deg. We integrate
  it on a 0.1 s grid (Euler-Maruyama, clipped at the limit) from the seed and interpolate
  linearly. The noise intensity is not given in the paper; the default is a guess.
* Current, eq. 5: a constant world velocity; hydrodynamic forces use nu_r = nu - J^T V_c.
* For scenario scripts: step changes of the mean direction (``direction_schedule``, Saoud
  Fig. 6) and a sinusoidal modulation of the mean speed and direction (Viel §5.1 cases 3-6).

Wind direction is where the wind comes *from* (compass bearing), see :mod:`sailmujoco.frames`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from pathlib import Path

import numpy as np

from .. import constants as c
from .._jit import kernel
from ..tomlfile import read_toml

F_MAX = 0.4  # Hz, upper end of the simulated gust band (Wille §2.1)
MAX_SPEED = 100.0  # m/s, U10: well above any hurricane's; the force models are not meant for more
WANDER_DT = 0.1  # s, grid of the direction-wander random walk
# Heights of the gust-amplitude table (log spaced); the amplitude is interpolated in ln z.
_Z_TABLE = np.geomspace(0.05, 60.0, 48)


@dataclass(frozen=True)
class WindConfig:
    """Wind and current for one simulation. Angles in radians, speeds in m/s.

    A TOML file with the same keys (angles with a ``_deg`` suffix allowed) loads through
    :meth:`from_toml`.

    Parameters
    ----------
    speed : float
        U_m10, mean wind speed at 10 m, m/s, in [0, 100].
    direction_from : float
        Compass bearing the wind comes from, rad.
    gusts, wander : bool
        NORSOK gusts, direction wander (eq. 43) on or off.
    wander_intensity, wander_limit : float
        The wander's white-noise intensity (rad/sqrt(s), a guess: not in the paper) and its
        saturation (rad, eq. 43).
    n_frequencies : int
        Number of gust components.
    current_east, current_north : float
        World current (where it flows to), m/s.
    seed : int
        Seeds the gust phases and frequencies and the wander.
    direction_schedule : tuple of (float, float)
        Step changes of the mean direction, ((t0 s, direction_from0 rad), ...), time-ordered;
        before the first t the direction is ``direction_from`` (Saoud Fig. 6 turns the wind).
    speed_oscillation, direction_oscillation, oscillation_frequency : float
        A (m/s), B (rad) and f (Hz) of the sinusoidal modulation U_m10 + A sin(2 pi f t),
        direction_from + B sin(2 pi f t) (Viel §5.1 cases 3-6).
    """

    speed: float = 0.0
    direction_from: float = 0.0
    gusts: bool = True
    wander: bool = True
    wander_intensity: float = math.radians(0.5)
    wander_limit: float = math.radians(5.0)
    n_frequencies: int = 100
    current_east: float = 0.0
    current_north: float = 0.0
    seed: int = 0
    direction_schedule: tuple = ()
    speed_oscillation: float = 0.0
    direction_oscillation: float = 0.0
    oscillation_frequency: float = 0.0

    def __post_init__(self):
        numbers = {f.name: getattr(self, f.name) for f in fields(self)}
        for name, value in numbers.items():
            if isinstance(value, bool) or name in ("seed", "direction_schedule"):
                continue
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ValueError(f"wind: {name} must be a finite number, got {value!r}")
        if not 0.0 <= self.speed <= MAX_SPEED:
            raise ValueError(f"wind: speed must be between 0 and {MAX_SPEED:g} m/s, got {self.speed}")
        if self.n_frequencies < 1:
            raise ValueError(f"wind: n_frequencies must be >= 1, got {self.n_frequencies}")
        if self.wander_intensity < 0 or self.wander_limit < 0:
            raise ValueError("wind: wander_intensity and wander_limit must be >= 0")
        try:
            schedule = tuple((float(t), float(d)) for t, d in self.direction_schedule)
        except (TypeError, ValueError):
            raise ValueError("wind: direction_schedule must be pairs (time s, direction_from rad), "
                             f"got {self.direction_schedule!r}") from None
        if any(not (math.isfinite(t) and math.isfinite(d)) for t, d in schedule) or \
                list(schedule) != sorted(schedule):
            raise ValueError("wind: direction_schedule needs finite, time-ordered pairs")
        object.__setattr__(self, "direction_schedule", schedule)

    @classmethod
    def from_dict(cls, values: dict, source: str = "wind config") -> WindConfig:
        """Build from a mapping; ``*_deg`` keys are converted to radians.

        Parameters
        ----------
        values : dict
            Field name (or ``name_deg``) -> value; an unknown key raises a ValueError.
        source : str
            Where the mapping comes from, for the error messages.
        """
        known = {f.name for f in fields(cls)}
        kwargs = {}
        for key, value in values.items():
            name = key[:-4] if key.endswith("_deg") else key
            if name not in known:
                allowed = sorted(known | {"direction_from_deg", "wander_intensity_deg",
                                          "wander_limit_deg"})
                raise ValueError(f"{source}: unknown key {key!r}; allowed: {', '.join(allowed)}")
            if key.endswith("_deg"):
                if not isinstance(value, (int, float)) or isinstance(value, bool):
                    raise ValueError(f"{source}: {key} must be a number, got {value!r}")
                value = math.radians(value)
            kwargs[name] = value
        try:
            return cls(**kwargs)
        except (TypeError, ValueError) as err:
            raise ValueError(f"{source}: {err}") from None

    @classmethod
    def from_toml(cls, path: str | Path) -> WindConfig:
        """Load a wind file (TOML, optionally under a ``[wind]`` table).

        Parameters
        ----------
        path : str or Path
            The TOML file.
        """
        data = read_toml(path, "wind file")
        return cls.from_dict(data.get("wind", data), source=f"wind file {str(Path(path))!r}")


def norsok_spectrum(f, z, mean_speed_10):
    """NORSOK wind spectrum S(f, z) in (m/s)^2/Hz, Wille (2016a) eqs. 37-38.

    Parameters
    ----------
    f, z : array_like
        Frequency (Hz) and height above the water (m).
    mean_speed_10 : float
        Mean wind speed at 10 m, m/s.
    """
    f = np.asarray(f, dtype=float)
    zr = np.maximum(np.asarray(z, dtype=float), 1e-6) / 10.0
    u = mean_speed_10 / 10.0
    if u <= 0.0:
        return np.zeros(np.broadcast(f, zr).shape)
    n = c.NORSOK_N
    x = 172.0 * f * zr ** (2.0 / 3.0) * u ** (-0.75)
    return 320.0 * u**2 * zr**0.45 / (1.0 + x**n) ** (5.0 / (3.0 * n))


def log_profile(z, mean_speed_10):
    """Mean wind at height z (m), eq. 40; zero at and below the roughness length z0.

    Parameters
    ----------
    z : array_like
        Height above the water, m.
    mean_speed_10 : float
        Mean wind speed at 10 m, m/s.
    """
    k = c.KARMAN_K
    z0 = 10.0 * math.exp(-2.0 / (5.0 * math.sqrt(k)))
    z = np.asarray(z, dtype=float)
    return np.where(z > z0, mean_speed_10 * 2.5 * math.sqrt(k) * np.log(np.maximum(z, z0) / z0), 0.0)


class WindField:
    """The seeded realisation of a :class:`WindConfig`: arrays the kernels read.

    ``gust_frequency``, ``gust_phase`` (n,), ``gust_amplitude`` (len(_Z_TABLE), n) over
    ``log_z``; the wander random walk ``wander`` on a ``WANDER_DT`` grid, grown on demand by
    :meth:`ensure` (block by block from one generator, so it does not depend on how far ahead
    it was asked for).

    Parameters
    ----------
    config : WindConfig
        The wind to realise.
    """

    def __init__(self, config: WindConfig):
        self.config = config
        rng = np.random.default_rng([config.seed, 1])
        n = config.n_frequencies
        df = F_MAX / n
        self.gust_frequency = (np.arange(n) + rng.uniform(0.0, 1.0, n)) * df
        self.gust_phase = rng.uniform(0.0, 2.0 * np.pi, n)
        self.log_z = np.log(_Z_TABLE)
        self.gust_cos = np.full(n + 1, np.nan)  # gust_cosines' cache: (time, cos_1 .. cos_n)
        if config.gusts and config.speed > 0.0:
            s = norsok_spectrum(self.gust_frequency[None, :], _Z_TABLE[:, None], config.speed)
            self.gust_amplitude = np.sqrt(2.0 * s * df)  # eq. 39
        else:
            self.gust_amplitude = np.zeros((_Z_TABLE.size, n))
        self._wander_rng = np.random.default_rng([config.seed, 2])
        self._walk = np.zeros(1)
        self.wander = np.zeros(1)
        self.current = np.array([config.current_east, config.current_north, 0.0])
        self.oscillation = np.array([config.speed_oscillation, config.direction_oscillation,
                                     config.oscillation_frequency])
        self.ensure(600.0)

    def ensure(self, t_end: float) -> None:
        """Extend the wander series so that it covers [0, t_end] s.

        Parameters
        ----------
        t_end : float
            Time, s.
        """
        need = int(math.ceil(t_end / WANDER_DT)) + 2
        if need <= self._walk.size:
            return
        block = max(need - self._walk.size, 6000)
        steps = self._wander_rng.standard_normal(block)
        out = np.empty(block)
        value = self._walk[-1]
        cfg = self.config
        sigma = cfg.wander_intensity * math.sqrt(WANDER_DT) if cfg.wander else 0.0
        for i in range(block):
            value = min(cfg.wander_limit, max(-cfg.wander_limit, value + sigma * steps[i]))
            out[i] = value
        self._walk = np.concatenate([self._walk, out])
        # the table the kernels read: the random walk plus the scheduled mean-direction steps
        times = np.arange(self._walk.size) * WANDER_DT
        offset = np.zeros(self._walk.size)
        for t0, direction in cfg.direction_schedule:
            offset[times >= t0 - 1e-9] = direction - cfg.direction_from
        self.wander = self._walk + offset

    def direction_from(self, t: float) -> float:
        """Compass bearing the wind comes from at time t: mean, schedule and wander, rad.

        Parameters
        ----------
        t : float
            Time, s.
        """
        self.ensure(t + 1.0)
        c = self.config
        return (c.direction_from + float(wander_angle(t, WANDER_DT, self.wander))
                + c.direction_oscillation * math.sin(2.0 * math.pi * c.oscillation_frequency * t))

    def velocity(self, t: float, z: float) -> np.ndarray:
        """World wind velocity (m/s, ENU) at time t and height z, anywhere in the horizontal plane.

        Parameters
        ----------
        t, z : float
            Time (s) and height above the water (m).
        """
        self.ensure(t + 1.0)
        out = np.zeros(3)
        wind_velocity(t, z, self.config.speed, self.config.direction_from, self.oscillation,
                      self.gust_frequency, self.gust_phase, self.gust_amplitude, self.log_z,
                      WANDER_DT, self.wander, out)
        return out

    def gust(self, t, z: float) -> np.ndarray:
        """Gust speed U_g(z, t) (m/s) for an array of times.

        Parameters
        ----------
        t : array_like
            Times, s.
        z : float
            Height above the water, m.
        """
        t = np.atleast_1d(np.asarray(t, dtype=float))
        return np.array([gust_speed(ti, z, self.gust_frequency, self.gust_phase,
                                    self.gust_amplitude, self.log_z) for ti in t])


@kernel
def gust_cosines(t, frequency, phase, cache):
    """cos(2 pi f_k t + Y_k) of eq. 39 for every k into ``cache[1:]``, once per time.

    ``cache[0]`` holds the time the cosines are for (NaN: none yet). They depend on t alone, so
    one force evaluation (sail, topsides, mast) and RK4's two mid-step stages share them (300 of
    a sub-step's 400 cosines); the same expression either way, so the same bits.

    Parameters
    ----------
    t : float
        Time, s.
    frequency, phase : numpy.ndarray, shape (n,)
        Gust component frequencies f_k (Hz) and phases Y_k (rad).
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    """
    if cache[0] == t:
        return
    two_pi_t = 2.0 * math.pi * t
    for k in range(frequency.shape[0]):
        cache[1 + k] = math.cos(two_pi_t * frequency[k] + phase[k])
    cache[0] = t


@kernel(inline=True)
def _gust_place(z, log_z):
    """(j, s): the interval of ``log_z`` holding ln z and the fraction s across it (clamped)."""
    lz = math.log(max(z, 1e-6))
    m = log_z.shape[0]
    if lz <= log_z[0]:
        return 0, 0.0
    if lz >= log_z[m - 1]:
        return m - 2, 1.0
    j = np.searchsorted(log_z, lz) - 1
    return j, (lz - log_z[j]) / (log_z[j + 1] - log_z[j])


@kernel(inline=True)
def _gust_amplitude(amplitude, j, s, k):
    """Component k's amplitude at the height of (j, s) (:func:`_gust_place`), linear in ln z."""
    return amplitude[j, k] + s * (amplitude[j + 1, k] - amplitude[j, k])


@kernel
def gust_sum(z, cache, amplitude, log_z):
    """U_g(z, t), eq. 39, from the cosines of :func:`gust_cosines`, amplitudes linear in ln z.

    Parameters
    ----------
    z : float
        Height above the water, m.
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    amplitude, log_z : numpy.ndarray, shapes (m, n) and (m,)
        Component amplitudes sqrt(2 S df) (m/s) at the heights whose ln (m) is ``log_z``.
    """
    j, s = _gust_place(z, log_z)
    total = 0.0
    for k in range(amplitude.shape[1]):
        total += _gust_amplitude(amplitude, j, s, k) * cache[1 + k]
    return total


@kernel
def gust_sums3(z0, z1, z2, cache, amplitude, log_z):
    """:func:`gust_sum` at three heights in one pass over the components.

    Each height's sum adds the same terms in the same order as :func:`gust_sum`, so each is
    bit for bit that sum; the three chains of additions run side by side instead of one after
    the other (the sum is bound by the latency of its additions).

    Parameters
    ----------
    z0, z1, z2 : float
        Heights above the water, m.
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    amplitude, log_z : numpy.ndarray, shapes (m, n) and (m,)
        Component amplitudes sqrt(2 S df) (m/s) at the heights whose ln (m) is ``log_z``.
    """
    j0, s0 = _gust_place(z0, log_z)
    j1, s1 = _gust_place(z1, log_z)
    j2, s2 = _gust_place(z2, log_z)
    t0 = 0.0
    t1 = 0.0
    t2 = 0.0
    for k in range(amplitude.shape[1]):
        c = cache[1 + k]
        t0 += _gust_amplitude(amplitude, j0, s0, k) * c
        t1 += _gust_amplitude(amplitude, j1, s1, k) * c
        t2 += _gust_amplitude(amplitude, j2, s2, k) * c
    return t0, t1, t2


@kernel
def gust_speed(t, z, frequency, phase, amplitude, log_z):
    """U_g(z, t), eq. 39, with amplitudes interpolated linearly in ln z.

    Parameters
    ----------
    t, z : float
        Time (s) and height above the water (m).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`WindField`: f_k (Hz), Y_k (rad), the amplitudes sqrt(2 S df)
        (m/s), shape (m, n), at the heights whose ln (m) is ``log_z``.
    """
    cache = np.full(frequency.shape[0] + 1, np.nan)
    gust_cosines(t, frequency, phase, cache)
    return gust_sum(z, cache, amplitude, log_z)


@kernel
def mean_speed(z, mean_speed_10):
    """Log profile, eq. 40 (kernel twin of :func:`log_profile`).

    Parameters
    ----------
    z : float
        Height above the water, m.
    mean_speed_10 : float
        Mean wind speed at 10 m, m/s.
    """
    k = 0.0026
    z0 = 10.0 * math.exp(-2.0 / (5.0 * math.sqrt(k)))
    if z <= z0:
        return 0.0
    return mean_speed_10 * 2.5 * math.sqrt(k) * math.log(z / z0)


@kernel
def wander_angle(t, dt, series):
    """beta_flux(t), eq. 43, linear interpolation of the random walk.

    Parameters
    ----------
    t, dt : float
        Time and the time step of ``series``, s.
    series : numpy.ndarray
        The wander at ``k dt``, rad.
    """
    x = t / dt
    if x <= 0.0:
        return series[0]
    i = int(x)
    n = series.shape[0]
    if i >= n - 1:
        return series[n - 1]
    s = x - i
    return series[i] + s * (series[i + 1] - series[i])


@kernel
def wind_velocity(t, z, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z,
                  wander_dt, wander, out):
    """World wind velocity at (t, z) into ``out`` (3,), eqs. 40-43.

    Parameters
    ----------
    t, z : float
        Time (s) and height above the water (m).
    speed10, direction_from, oscillation, wander_dt, wander : float or numpy.ndarray
        U_m10 (m/s); the mean bearing the wind comes from (rad); the modulation (speed m/s,
        direction rad, frequency Hz); the wander series (rad) at ``k wander_dt`` seconds.
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`WindField`: f_k (Hz), Y_k (rad), the amplitudes sqrt(2 S df)
        (m/s), shape (m, n), at the heights whose ln (m) is ``log_z``.
    out : numpy.ndarray, shape (3,)
        Receives the velocity (ENU, where the air goes), m/s.
    """
    cache = np.full(frequency.shape[0] + 1, np.nan)
    wind_velocities(t, z, z, z, 1, speed10, direction_from, oscillation, frequency, phase, amplitude,
                    log_z, wander_dt, wander, cache, out)


@kernel
def wind_velocities(t, z0, z1, z2, count, speed10, direction_from, oscillation, frequency, phase,
                    amplitude, log_z, wander_dt, wander, cache, out):
    """World wind velocity at time t and ``count`` (1 to 3) heights z0, z1, z2 into
    ``out[3 i:3 i + 3]``: the boat's sail and windage points in one call.

    What depends on t alone (modulation, direction, the gust cosines) is evaluated once; each
    height's value is the same expression as for one height alone, so the same bits.

    Parameters
    ----------
    t : float
        Time, s.
    z0, z1, z2 : float
        Heights above the water, m.
    count : int
        How many of the heights to evaluate, 1 to 3.
    speed10, direction_from, oscillation, wander_dt, wander : float or numpy.ndarray
        U_m10 (m/s); the mean bearing the wind comes from (rad); the modulation (speed m/s,
        direction rad, frequency Hz); the wander series (rad) at ``k wander_dt`` seconds.
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`WindField`: f_k (Hz), Y_k (rad), the amplitudes sqrt(2 S df)
        (m/s), shape (m, n), at the heights whose ln (m) is ``log_z``.
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    out : numpy.ndarray, shape (3 count,)
        Receives the velocities (ENU, where the air goes), m/s.
    """
    s = math.sin(2.0 * math.pi * oscillation[2] * t)
    mean10 = speed10 + oscillation[0] * s
    u0 = mean_speed(z0, mean10)
    u1 = mean_speed(z1, mean10) if count > 1 else 0.0
    u2 = mean_speed(z2, mean10) if count > 2 else 0.0
    if speed10 > 0.0:
        gust_cosines(t, frequency, phase, cache)
        if count == 1:
            u0 += gust_sum(z0, cache, amplitude, log_z)
        else:
            g0, g1, g2 = gust_sums3(z0, z1, z2, cache, amplitude, log_z)
            u0 += g0
            u1 += g1
            u2 += g2
    bearing = direction_from + wander_angle(t, wander_dt, wander) + oscillation[1] * s
    sb = math.sin(bearing)
    cb = math.cos(bearing)
    out[0] = -u0 * sb
    out[1] = -u0 * cb
    out[2] = 0.0
    if count > 1:
        out[3] = -u1 * sb
        out[4] = -u1 * cb
        out[5] = 0.0
    if count > 2:
        out[6] = -u2 * sb
        out[7] = -u2 * cb
        out[8] = 0.0
