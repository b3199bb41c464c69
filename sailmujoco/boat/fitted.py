"""A boat's instruments and actuators as fitted: their figures (:class:`SensorOptions`,
:class:`ActuatorOptions`), each with the presets ``perfect`` and ``typical``.

``perfect`` is the papers' boat: every reading the true value and every command passed to the
world's servo (a first-order lag, as the papers have it) unchanged, bit for bit. ``typical`` is
a small autonomous sailboat's fit, each figure with its source or marked as ours.

Instruments (read by :class:`sailmujoco.measurement.instruments.Instruments`):

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

Actuators (the fitted servos of :func:`sailmujoco.actuation.servo.fitted_servos`):

* rudder: 60 deg in 0.15 s (RC servos: 0.07-0.2 s), a deadband of 0.5 deg (a servo's 4 us of a
  1000-2000 us pulse over +-60 deg, 0.12 deg per us), 0.5 deg of gear backlash (ours, a guess),
  resolution 0.12 deg (the autopilot's 1 us PWM step);
* sail (angle or sheet): full in to full out in 1.3 s (a sail winch of the RMG 280D class), a
  deadband and a backlash of 1 % of the range (ours, guesses), resolution 0.1 % of the range
  (1 us of a 1000 us pulse).

A boat holds its own (``BoatParams.sensors`` and ``.actuators``, a boat file's ``[sensors]`` and
``[actuators]`` sections: :mod:`.fitted_file`); a task's ``sensors=`` and ``actuators=`` override
them.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import check_figures, preset_figures


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
    vane_upwash_deg : float
        The sail's upwash at the masthead close-hauled, deg: the vane reads the apparent wind
        this much wider, fading as cos(AWA) to none on the beam
        (:func:`sailmujoco.measurement.sensors.upwash_shift`); 0: none.
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
    vane_upwash_deg: float = 0.0
    log_scale_error: float = 0.0
    log_noise: float = 0.0

    def __post_init__(self):
        check_figures(self, "sensors", SENSOR_LIMITS)
        if abs(self.dip_deg) > 90.0:
            raise ValueError(f"sensors.dip_deg must be within -90 to 90, got {self.dip_deg!r}")


# the lowest value of each figure (strict: the bound itself refused); the others are >= 0
SENSOR_LIMITS = {"gnss_tau": (0.0, True), "gnss_rate_hz": (0.0, True), "dip_deg": (-90.0, False),
          "log_scale_error": (-1.0, True)}

# figure -> (unit, meaning, the source of its typical value): what a boat file writes beside it
SENSOR_FIGURES = {
    "perfect": ("-", "every reading the true value (the figures below are then not used)", ""),
    "gnss_cep": ("m", "GNSS horizontal accuracy, CEP (per-axis sigma: CEP / 1.1774)",
                 "u-blox M8 class: 2.5 m CEP"),
    "gnss_tau": ("s", "correlation time of the GNSS position error (Gauss-Markov)", "ours, a guess"),
    "gnss_velocity_sigma": ("m/s", "GNSS velocity error per axis, white", "u-blox M8 class: 0.05 m/s"),
    "gnss_rate_hz": ("Hz", "GNSS fixes per second", "u-blox M8 class: 1-10 Hz"),
    "gnss_latency": ("s", "age of a GNSS fix when reported", "ours, a guess"),
    "compass_noise_deg": ("deg", "compass white noise, standard deviation",
                          "1 deg (Honeywell HMR3300) to 3-4 deg (CMPS class)"),
    "compass_deviation_deg": ("deg", "compass fixed deviation", "ours: a swung compass"),
    "compass_tilt_compensated": ("-", "tilt-compensated compass (true) or one fixed to the hull (false)",
                                 "ours"),
    "dip_deg": ("deg", "the magnetic field's dip (an untilted compass's heel error)",
                "the English Channel"),
    "inclinometer_noise_deg": ("deg", "inclinometer noise (the heel, and the compass's tilt)",
                               "ours, a guess"),
    "gyro_noise": ("rad/s", "gyro white noise", "MEMS class, ours"),
    "gyro_bias_walk": ("rad/s/sqrt(s)", "gyro bias random walk", "MEMS class, ours"),
    "vane_noise": ("m/s", "noise on each component of the masthead flow", "ours, a guess"),
    "vane_filter_hz": ("Hz", "cut-off of the vane's first-order filter (0: none)",
                       "ArduPilot's vane filter, WNDVN_DIR_FILT"),
    "vane_upwash_deg": ("deg", "the sail's upwash at the masthead close-hauled, fading as cos(AWA) "
                               "to none on the beam (0: none)", "none in the preset: no sourced size"),
    "log_scale_error": ("-", "speed log calibration error, a fraction", "ours, a guess"),
    "log_noise": ("m/s", "speed log noise", "ours, a guess"),
}

SENSOR_PRESETS = {
    "perfect": SensorOptions(),
    "typical": SensorOptions(perfect=False, gnss_cep=2.5, gnss_tau=60.0, gnss_velocity_sigma=0.05,
                             gnss_rate_hz=5.0, gnss_latency=0.1, compass_noise_deg=2.0,
                             compass_tilt_compensated=True, dip_deg=66.0, inclinometer_noise_deg=0.5,
                             gyro_noise=0.005, gyro_bias_walk=1e-4, vane_noise=0.2, vane_filter_hz=0.5,
                             log_scale_error=0.05, log_noise=0.05),
}


def sensor_options(value=None, base: SensorOptions | None = None) -> SensorOptions:
    """:class:`SensorOptions` from a preset's name, a dict of fields over ``perfect`` (or over
    the preset its ``"preset"`` key names), an options object, or None (``perfect``).

    Parameters
    ----------
    value : str, dict, SensorOptions or None
        What the caller gave.
    base : SensorOptions, optional
        What None gives and a dict without ``"preset"`` is over (default ``perfect``): a boat's
        own figures, from its boat file.
    """
    return preset_figures(value, SENSOR_PRESETS, "sensors", "a sensor figure", base)


@dataclass(frozen=True)
class ActuatorOptions:
    """The fitted actuators' figures (0: that effect off).

    Parameters
    ----------
    perfect : bool
        True: the command passes unchanged (the other figures are ignored).
    rudder_60deg_s : float
        Time the rudder servo takes to turn 60 deg, s.
    rudder_deadband_deg, rudder_backlash_deg, rudder_resolution_deg : float
        The rudder servo's deadband, gear play and position step, deg.
    sail_full_range_s : float
        Time the sail actuator takes from one end of its range to the other, s.
    sail_deadband, sail_backlash, sail_resolution : float
        The sail actuator's deadband, play and step, as fractions of its range.
    winch_stall_pull : float
        With a sheeted sail: the pull on the sheet at which the winch stalls, N (its stall torque
        over its drum's radius); it hauls in the slower the nearer the sheet's load comes to it
        (:class:`sailmujoco.actuation.winch.SheetWinch`). 0: no torque limit.
    """

    perfect: bool = True
    rudder_60deg_s: float = 0.0
    rudder_deadband_deg: float = 0.0
    rudder_backlash_deg: float = 0.0
    rudder_resolution_deg: float = 0.0
    sail_full_range_s: float = 0.0
    sail_deadband: float = 0.0
    sail_backlash: float = 0.0
    sail_resolution: float = 0.0
    winch_stall_pull: float = 0.0

    def __post_init__(self):
        check_figures(self, "actuators", {})


# figure -> (unit, meaning, the source of its typical value): what a boat file writes beside it
ACTUATOR_FIGURES = {
    "perfect": ("-", "every command passes unchanged (the figures below are then not used)", ""),
    "rudder_60deg_s": ("s", "time the rudder servo takes to turn 60 deg (0: no rate limit)",
                       "RC servos: 0.07-0.2 s"),
    "rudder_deadband_deg": ("deg", "the rudder servo's deadband", "4 us of a 1000-2000 us pulse"),
    "rudder_backlash_deg": ("deg", "the rudder's gear play", "ours, a guess"),
    "rudder_resolution_deg": ("deg", "the rudder's position step", "the autopilot's 1 us PWM step"),
    "sail_full_range_s": ("s", "time the sail actuator takes across its range (0: no rate limit)",
                          "a sail winch of the RMG 280D class: 1.3 s"),
    "sail_deadband": ("-", "the sail actuator's deadband, a fraction of its range", "ours, a guess"),
    "sail_backlash": ("-", "the sail actuator's play, a fraction of its range", "ours, a guess"),
    "sail_resolution": ("-", "the sail actuator's step, a fraction of its range",
                        "1 us of a 1000 us pulse"),
    "winch_stall_pull": ("N", "a sheeted sail's winch: the sheet's pull at stall, stall torque / drum "
                              "radius (0: no torque limit)", "none sourced: no limit (a datasheet's figure)"),
}

ACTUATOR_PRESETS = {
    "perfect": ActuatorOptions(),
    "typical": ActuatorOptions(perfect=False, rudder_60deg_s=0.15, rudder_deadband_deg=0.5,
                               rudder_backlash_deg=0.5, rudder_resolution_deg=0.12, sail_full_range_s=1.3,
                               sail_deadband=0.01, sail_backlash=0.01, sail_resolution=0.001),
}


def actuator_options(value=None, base: ActuatorOptions | None = None) -> ActuatorOptions:
    """:class:`ActuatorOptions` from a preset's name, a dict of figures over ``perfect`` (or over
    the preset its ``"preset"`` key names), an options object, or None (``perfect``).

    Parameters
    ----------
    value : str, dict, ActuatorOptions or None
        What the caller gave.
    base : ActuatorOptions, optional
        What None gives and a dict without ``"preset"`` is over (default ``perfect``): a boat's
        own figures, from its boat file.
    """
    return preset_figures(value, ACTUATOR_PRESETS, "actuators", "an actuator figure", base)
