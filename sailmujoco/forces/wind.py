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
from ..jit.ordered import elementwise, geomspace, power
from ..tomlfile import read_toml
from .wind_kernels import gust_speed, wander_angle, wind_velocity

F_MAX = 0.4  # Hz, upper end of the simulated gust band (Wille §2.1)
MAX_SPEED = 100.0  # m/s, U10: well above any hurricane's; the force models are not meant for more
WANDER_DT = 0.1  # s, grid of the direction-wander random walk
# Heights of the gust-amplitude table (log spaced); the amplitude is interpolated in ln z.
_Z_TABLE = geomspace(0.05, 60.0, 48)


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
    # the powers through the C library: numpy's pick a SIMD kernel by CPU
    x = 172.0 * f * power(zr, 2.0 / 3.0) * u ** (-0.75)
    return 320.0 * u**2 * power(zr, 0.45) / power(1.0 + power(x, n), 5.0 / (3.0 * n))


def roughness_length() -> float:
    """z0 of the log profile, m: where eq. 40's U(z) = U10 (5/2) sqrt(k) ln(z / z0) vanishes, so that
    U(10 m) = U10."""
    return 10.0 * math.exp(-2.0 / (5.0 * math.sqrt(c.KARMAN_K)))


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
    z0 = roughness_length()
    z = np.asarray(z, dtype=float)
    log = elementwise(math.log, np.maximum(z, z0) / z0)  # the C library's: numpy's varies by CPU
    return np.where(z > z0, mean_speed_10 * 2.5 * math.sqrt(k) * log, 0.0)


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
        self.log_z = elementwise(math.log, _Z_TABLE)
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
