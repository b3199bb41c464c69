"""The figures of a boat's actuators (:class:`ActuatorOptions`, presets ``perfect`` and
``typical``) and the fitted servos they make (:func:`fitted_servos`).

``perfect`` is the actuators as they have always been: the command goes to the world's servo
(a first-order lag, as the papers have it) unchanged, bit for bit. ``typical`` puts the fitted
servo of :mod:`.servo` in front of it, with a small boat's figures:

* rudder: 60 deg in 0.15 s (RC servos: 0.07-0.2 s), a deadband of 0.5 deg (a servo's 4 us of a
  1000-2000 us pulse over +-60 deg, 0.12 deg per us), 0.5 deg of gear backlash (ours, a guess),
  resolution 0.12 deg (the autopilot's 1 us PWM step);
* sail (angle or sheet): full in to full out in 1.3 s (a sail winch of the RMG 280D class), a
  deadband and a backlash of 1 % of the range (ours, guesses), resolution 0.1 % of the range
  (1 us of a 1000 us pulse).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import check_figures, preset_figures
from .servo import FittedServo


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

    def __post_init__(self):
        check_figures(self, "actuators", {})


PRESETS = {
    "perfect": ActuatorOptions(),
    "typical": ActuatorOptions(perfect=False, rudder_60deg_s=0.15, rudder_deadband_deg=0.5,
                               rudder_backlash_deg=0.5, rudder_resolution_deg=0.12, sail_full_range_s=1.3,
                               sail_deadband=0.01, sail_backlash=0.01, sail_resolution=0.001),
}


def actuator_options(value=None) -> ActuatorOptions:
    """:class:`ActuatorOptions` from a preset's name, a dict of figures over ``perfect`` (or over
    the preset its ``"preset"`` key names), an options object, or None (``perfect``).

    Parameters
    ----------
    value : str, dict, ActuatorOptions or None
        What the caller gave.
    """
    return preset_figures(value, PRESETS, "actuators", "an actuator figure")


def fitted_servos(options: ActuatorOptions, low, high, dt: float) -> tuple[FittedServo, FittedServo]:
    """The rudder's and the sail's fitted servos for commands within ``[low, high]`` (the world's
    action bounds: rudder rad, sail rad or sheet m), stepped every ``dt``.

    Parameters
    ----------
    options : ActuatorOptions
        The figures.
    low, high : sequence of float
        The two commands' bounds.
    dt : float
        Control period, s.
    """
    o = options
    rudder_rate = 0.0 if o.rudder_60deg_s == 0 else math.radians(60.0) / o.rudder_60deg_s
    rudder = FittedServo(dt, rate_limit=rudder_rate, deadband=math.radians(o.rudder_deadband_deg),
                         backlash=math.radians(o.rudder_backlash_deg),
                         resolution=math.radians(o.rudder_resolution_deg))
    span = float(high[1]) - float(low[1])
    sail_rate = 0.0 if o.sail_full_range_s == 0 else span / o.sail_full_range_s
    sail = FittedServo(dt, rate_limit=sail_rate, deadband=o.sail_deadband * span,
                       backlash=o.sail_backlash * span, resolution=o.sail_resolution * span)
    return rudder, sail
