"""A servo's departures from an ideal one, each a small stateful map stepped every ``dt``.

Applied in this order to a command (:class:`FittedServo`): quantisation (the command a PWM
channel or a servo's potentiometer can resolve), deadband (a change smaller than it leaves the
servo where it is), rate limit (the rated speed: an RC servo turns 60 degrees in 0.07-0.2 s), and
backlash (the output shaft follows the motor only once the gear play is taken up). With every
parameter zero the command passes unchanged, bit for bit. :func:`fitted_servos` makes a boat's
rudder and sail servos from its figures (:class:`sailmujoco.boat.fitted.ActuatorOptions`).
"""

from __future__ import annotations

import math

from ..boat.fitted import ActuatorOptions
from ..errors import check_number
from .winch import SheetWinch


def quantise(command: float, step: float) -> float:
    """``command`` rounded to the nearest multiple of ``step`` (unchanged for step 0).

    Parameters
    ----------
    command : float
        The command (rad or m).
    step : float
        The resolution, >= 0.
    """
    return command if step == 0.0 else step * round(command / step)


class Deadband:
    """A servo that holds its target until the command moves more than ``width`` from it.

    Parameters
    ----------
    width : float
        The deadband, >= 0 (0: every command is followed).
    """

    def __init__(self, width: float):
        self.width = check_number("deadband", width, 0.0)
        self.held = None

    def step(self, command: float) -> float:
        """The target the servo drives to after ``command``.

        Parameters
        ----------
        command : float
            The command (rad or m).
        """
        if self.held is None or abs(command - self.held) > self.width:
            self.held = command
        return self.held


class RateLimit:
    """A position that moves towards the command no faster than ``rate``.

    Parameters
    ----------
    rate : float
        The rated speed, per second (rad/s or m/s); 0: no limit.
    dt : float
        The step, s.
    """

    def __init__(self, rate: float, dt: float):
        self.max_step = check_number("rate_limit", rate, 0.0) * check_number("dt", dt, 0.0)
        self.limited = self.max_step > 0.0
        self.position = None

    def step(self, command: float) -> float:
        """The position after one step towards ``command``.

        Parameters
        ----------
        command : float
            The command (rad or m).
        """
        if self.position is None or not self.limited:
            self.position = command
        else:
            self.position += min(max(command - self.position, -self.max_step), self.max_step)
        return self.position


class Backlash:
    """Gear play of total width ``width``: the output moves only when the input pushes it,
    staying within ``width / 2`` of the input.

    Parameters
    ----------
    width : float
        The play, >= 0 (rad or m).
    """

    def __init__(self, width: float):
        self.half = check_number("backlash", width, 0.0) / 2.0
        self.output = None

    def step(self, position: float) -> float:
        """The output after the input moves to ``position``.

        Parameters
        ----------
        position : float
            The input side's position (rad or m).
        """
        if self.output is None or self.half == 0.0:
            self.output = position
        else:
            self.output = min(max(self.output, position - self.half), position + self.half)
        return self.output


class FittedServo:
    """Quantisation, deadband, rate limit and backlash, in that order (see the module docstring).

    Parameters
    ----------
    dt : float
        The step, s.
    rate_limit : float
        Rated speed, per s (0: none).
    deadband, backlash, resolution : float
        Widths in the command's unit (0: none).
    """

    def __init__(self, dt: float, rate_limit: float = 0.0, deadband: float = 0.0, backlash: float = 0.0,
                 resolution: float = 0.0):
        self.resolution = check_number("resolution", resolution, 0.0)
        self.deadband = Deadband(deadband)
        self.rate = RateLimit(rate_limit, dt)
        self.backlash = Backlash(backlash)

    def step(self, command: float) -> float:
        """The position the servo sets after ``command``.

        Parameters
        ----------
        command : float
            The controller's command (rad or m).
        """
        return self.backlash.step(self.rate.step(self.deadband.step(quantise(command, self.resolution))))


def fitted_servos(options: ActuatorOptions, low, high, dt: float, sheeted: bool = False) -> tuple:
    """The rudder's and the sail's fitted servos for commands within ``[low, high]`` (the world's
    action bounds: rudder rad, sail rad or sheet m), stepped every ``dt``, and a sheeted sail's
    winch.

    With ``sheeted`` and a ``winch_stall_pull``, the sail's rate is the winch's: it eases out at
    its free speed (the range in ``sail_full_range_s``) and hauls in the slower the nearer the
    sheet's load comes to its stall pull (:class:`~sailmujoco.actuation.winch.SheetWinch`).

    Parameters
    ----------
    options : ActuatorOptions
        The figures.
    low, high : sequence of float
        The two commands' bounds.
    dt : float
        Control period, s.
    sheeted : bool
        The sail's command is a sheet's length (the sheeted sail).

    Returns
    -------
    tuple
        (rudder servo, sail servo, the winch or None); the winch steps the sail servo's output
        against the sheet's load.
    """
    o = options
    rudder_rate = 0.0 if o.rudder_60deg_s == 0 else math.radians(60.0) / o.rudder_60deg_s
    rudder = FittedServo(dt, rate_limit=rudder_rate, deadband=math.radians(o.rudder_deadband_deg),
                         backlash=math.radians(o.rudder_backlash_deg),
                         resolution=math.radians(o.rudder_resolution_deg))
    span = float(high[1]) - float(low[1])
    sail_rate = 0.0 if o.sail_full_range_s == 0 else span / o.sail_full_range_s
    winch = None
    if sheeted and o.winch_stall_pull > 0:  # the winch sets the rate, against the sheet's load
        free_speed = sail_rate if sail_rate > 0 else span / dt  # no rated speed: the range in a step
        winch = SheetWinch(free_speed, stall_torque=o.winch_stall_pull, drum_radius=1.0, dt=dt)
        sail_rate = 0.0
    sail = FittedServo(dt, rate_limit=sail_rate, deadband=o.sail_deadband * span,
                       backlash=o.sail_backlash * span, resolution=o.sail_resolution * span)
    return rudder, sail, winch
