"""A boat's instruments as one set: the readings they make of a world's truth each control step
(:class:`Instruments`), from their figures (:class:`sailmujoco.boat.fitted.SensorOptions`, where
each typical figure's source is given).

Each instrument draws from a stream of its own, seeded from the run's seed, the episode and the
instrument's index (``numpy.random.SeedSequence([seed, STREAM, episode, index])``), so the wind's
and the sea's streams are untouched and one instrument's figures do not move another's noise.
"""

from __future__ import annotations

import math
from dataclasses import asdict

import numpy as np

from ..boat.fitted import SensorOptions
from .sensors import CEP_PER_SIGMA, Compass, Gnss, Gyro, MastheadVane, SpeedLog
from .true_wind import TrueWindEstimate

STREAM = 41_000  # the instruments' entropy word, beside the run's seed (the wind and sea use others)
INSTRUMENTS = ("gnss", "compass", "gyro", "inclinometer", "vane", "log")  # stream indices, in order


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
        self.vane = MastheadVane(dt, rngs["vane"], noise=o.vane_noise, tau=tau,
                                 upwash=math.radians(o.vane_upwash_deg))
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
