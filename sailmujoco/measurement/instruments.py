"""A boat's instruments as one set: their figures (:class:`SensorOptions`, presets ``perfect`` and
``typical``) and the readings they make of a world's truth each control step (:class:`Instruments`).

``perfect`` is the observation as it has always been: every reading the true value, bit for bit.
``typical`` is a small autonomous sailboat's fit, each figure with its source or marked as ours:

* GNSS position: 2.5 m CEP (per-axis sigma 2.5 / 1.1774 m), a Gauss-Markov error with a
  correlation time of 60 s (u-blox M8 class for the CEP; the correlation time is ours, a guess);
* GNSS velocity: 0.05 m/s per axis, white (u-blox M8 class);
* GNSS timing: 5 fixes a second (the M8 class runs at 1-10 Hz), 0.1 s late (ours);
* compass: tilt-compensated, 2 deg of noise (compasses of this class quote 1 deg, the
  Honeywell HMR3300, to 3-4 deg, CMPS-class), the field's dip 66 deg (the English Channel);
* inclinometer: 0.5 deg of noise, for the heel and the compass's tilt (ours, a guess);
* gyro: 0.005 rad/s of noise and a bias walk of 1e-4 rad/s per square-root second (MEMS class,
  ours);
* vane and anemometer: 0.2 m/s of noise on each flow component, filtered at 0.5 Hz
  (ArduPilot's vane filter, ``WNDVN_DIR_FILT``);
* speed log: reads 5 % high, 0.05 m/s of noise (ours, a guess).

Each instrument draws from a stream of its own, seeded from the run's seed, the episode and the
instrument's index (``numpy.random.SeedSequence([seed, STREAM, episode, index])``), so the wind's
and the sea's streams are untouched and one instrument's figures do not move another's noise.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from ..errors import check_figures, preset_figures
from .sensors import CEP_PER_SIGMA, Compass, Gnss, Gyro, MastheadVane, SpeedLog
from .true_wind import TrueWindEstimate

STREAM = 41_000  # the instruments' entropy word, beside the run's seed (the wind and sea use others)
INSTRUMENTS = ("gnss", "compass", "gyro", "inclinometer", "vane", "log")  # stream indices, in order


@dataclass(frozen=True)
class SensorOptions:
    """The figures of a boat's instruments (SI and radians, but ``*_deg`` and ``*_hz``).

    Parameters
    ----------
    perfect : bool
        True: every reading is the true value (the other figures are ignored).
    gnss_cep : float
        GNSS horizontal accuracy, CEP, m.
    gnss_tau : float
        Correlation time of the GNSS position error, s.
    gnss_velocity_sigma : float
        GNSS velocity error per axis, m/s.
    gnss_rate_hz : float
        GNSS fixes per second.
    gnss_latency : float
        Age of a GNSS fix when reported, s.
    compass_noise_deg, compass_deviation_deg : float
        Compass white noise (standard deviation) and fixed deviation, deg.
    compass_tilt_compensated : bool
        A tilt-compensated compass (True) or one fixed to the hull (False).
    dip_deg : float
        The magnetic field's dip, deg.
    inclinometer_noise_deg : float
        The inclinometer's noise (heel, and the compass's tilt), deg.
    gyro_noise : float
        Gyro white noise, rad/s.
    gyro_bias_walk : float
        Gyro bias random walk, rad/s per square-root second.
    vane_noise : float
        Noise on each component of the masthead flow, m/s.
    vane_filter_hz : float
        Cut-off of the vane's first-order filter, Hz (0: none).
    log_scale_error : float
        Speed log calibration error, a fraction.
    log_noise : float
        Speed log noise, m/s.
    """

    perfect: bool = True
    gnss_cep: float = 0.0
    gnss_tau: float = 60.0
    gnss_velocity_sigma: float = 0.0
    gnss_rate_hz: float = 10.0
    gnss_latency: float = 0.0
    compass_noise_deg: float = 0.0
    compass_deviation_deg: float = 0.0
    compass_tilt_compensated: bool = True
    dip_deg: float = 66.0
    inclinometer_noise_deg: float = 0.0
    gyro_noise: float = 0.0
    gyro_bias_walk: float = 0.0
    vane_noise: float = 0.0
    vane_filter_hz: float = 0.0
    log_scale_error: float = 0.0
    log_noise: float = 0.0

    def __post_init__(self):
        check_figures(self, "sensors", LIMITS)
        if abs(self.dip_deg) > 90.0:
            raise ValueError(f"sensors.dip_deg must be within -90 to 90, got {self.dip_deg!r}")


# the lowest value of each figure (strict: the bound itself refused); the others are >= 0
LIMITS = {"gnss_tau": (0.0, True), "gnss_rate_hz": (0.0, True), "dip_deg": (-90.0, False),
          "log_scale_error": (-1.0, True)}

PRESETS = {
    "perfect": SensorOptions(),
    "typical": SensorOptions(perfect=False, gnss_cep=2.5, gnss_tau=60.0, gnss_velocity_sigma=0.05,
                             gnss_rate_hz=5.0, gnss_latency=0.1, compass_noise_deg=2.0,
                             compass_tilt_compensated=True, dip_deg=66.0, inclinometer_noise_deg=0.5,
                             gyro_noise=0.005, gyro_bias_walk=1e-4, vane_noise=0.2, vane_filter_hz=0.5,
                             log_scale_error=0.05, log_noise=0.05),
}


def sensor_options(value=None) -> SensorOptions:
    """:class:`SensorOptions` from a preset's name, a dict of fields over ``perfect`` (or over
    the preset its ``"preset"`` key names), an options object, or None (``perfect``).

    Parameters
    ----------
    value : str, dict, SensorOptions or None
        What the caller gave.
    """
    return preset_figures(value, PRESETS, "sensors", "a sensor figure")


class Instruments:
    """The readings a set of instruments makes of a world, once per control step.

    Parameters
    ----------
    options : SensorOptions
        The instruments' figures (not ``perfect``: a perfect set reads nothing).
    dt : float
        Control period, s.
    seed : int or None
        The run's seed (the instruments' streams are derived from it).
    episode : int
        The episode's index in its environment (each episode its own noise).
    """

    def __init__(self, options: SensorOptions, dt: float, seed: int | None, episode: int = 0):
        o = options
        entropy = [int(seed or 0), STREAM, int(episode)]
        rngs = {name: np.random.default_rng(np.random.SeedSequence([*entropy, i]))
                for i, name in enumerate(INSTRUMENTS)}
        self.gnss = Gnss(dt, rngs["gnss"], rate=o.gnss_rate_hz, latency=o.gnss_latency,
                         position_sigma=o.gnss_cep / CEP_PER_SIGMA, position_tau=o.gnss_tau,
                         velocity_sigma=o.gnss_velocity_sigma)
        self.compass = Compass(rngs["compass"], dip=math.radians(o.dip_deg),
                               tilt_compensated=o.compass_tilt_compensated,
                               noise=math.radians(o.compass_noise_deg),
                               deviation=math.radians(o.compass_deviation_deg),
                               inclinometer_noise=math.radians(o.inclinometer_noise_deg))
        self.gyro = Gyro(dt, rngs["gyro"], noise=o.gyro_noise, bias_walk=o.gyro_bias_walk)
        self.inclinometer_rng = rngs["inclinometer"]
        self.inclinometer_noise = math.radians(o.inclinometer_noise_deg)
        tau = 0.0 if o.vane_filter_hz == 0 else 1.0 / (2.0 * math.pi * o.vane_filter_hz)
        self.vane = MastheadVane(dt, rngs["vane"], noise=o.vane_noise, tau=tau)
        self.log = SpeedLog(rngs["log"], scale_error=o.log_scale_error, noise=o.log_noise)
        self.true_wind = TrueWindEstimate(dt)

    def read(self, truth) -> dict:
        """What the instruments report of ``truth`` now: the observation's measured keys
        (``position``, ``velocity``, ``heading``, ``heel``, ``roll_rate``, ``yaw_rate``,
        ``apparent_wind_angle``, ``apparent_wind_speed``), the log's ``speed_through_water`` and
        the ``true_wind_estimate`` (speed m/s, direction it comes from rad).

        Parameters
        ----------
        truth : sailmujoco.measurement.observation.Truth
            The world's true state now.
        """
        position, velocity = self.gnss.measure(truth.position, truth.velocity)
        heading = self.compass.measure(truth.heel, truth.pitch, truth.yaw)
        rates = self.gyro.measure(truth.rates)
        heel = truth.heel + self.inclinometer_noise * float(self.inclinometer_rng.standard_normal())
        flow = (-truth.apparent_wind_speed * math.cos(truth.apparent_wind_angle),
                truth.apparent_wind_speed * math.sin(truth.apparent_wind_angle))
        awa, aws = self.vane.measure(flow)
        through_water = float(truth.body_velocity[0] - truth.current_body[0])
        wind = self.true_wind.update(awa, aws, heading, velocity)
        return {"position": position, "velocity": velocity, "heading": heading, "heel": heel,
                "roll_rate": float(rates[0]), "yaw_rate": float(rates[2]), "apparent_wind_angle": awa,
                "apparent_wind_speed": aws, "speed_through_water": self.log.measure(through_water),
                "true_wind_estimate": np.array(wind)}


def figures_table(options: SensorOptions) -> dict:
    """The options as a plain dict (for a boat file, a record or a report).

    Parameters
    ----------
    options : SensorOptions
        The instruments' figures.
    """
    return asdict(options)
