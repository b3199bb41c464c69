"""ArduPilot's sailboat outputs as the boat's commands.

ArduPilot Rover in sailboat mode (``SAIL_ENABLE 1``) drives:

* ground steering (``SERVOn_FUNCTION 26``, channel 1 by default): a pulse from ``pwm_min`` to
  ``pwm_max``, its middle straight ahead; above the middle steers to starboard. Our rudder angle
  is positive with the trailing edge to port, which turns the boat to port, so steering to
  starboard is a negative rudder angle: ``rudder = -max_rudder (pwm - mid) / half_range``;
* the mainsail (``SERVOn_FUNCTION 89``, channel 4 in ArduPilot's sailboat.parm): 0 to 100 %
  from ``pwm_min`` (sheeted in) to ``pwm_max`` (let out), the boom let out from
  ``SAIL_ANGLE_MIN`` to ``SAIL_ANGLE_MAX`` (ArduPilot's defaults 0 and 90 degrees). The boat's
  sheeted sail (``sail_mode="sheeted"``) takes the sheet's length that lets the boom out that far
  (:func:`sailmujoco.boat.geometry.sheet_length`);
* the throttle (channel 3): ArduPilot's motor, which it runs to finish a tack that takes longer
  than 5 s (for up to 10 s more), from ``pwm_min`` (full astern) through the middle (stopped) to
  ``pwm_max`` (full ahead). Our boats carry no motor; a run may give one
  (:class:`~sailmujoco.sitl.backend.JsonBackend`'s ``motor_thrust``).

A reversed channel (``SERVOn_REVERSED 1``) swaps the ends.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import check_number


@dataclass(frozen=True)
class ServoMap:
    """Which channel drives what, and its range (ArduPilot's sailboat defaults).

    Parameters
    ----------
    steering_channel, mainsail_channel, throttle_channel : int
        The channels (1-based) of ground steering, the mainsail and the throttle.
    steering_reversed, mainsail_reversed, throttle_reversed : bool
        ``SERVOn_REVERSED`` of each.
    pwm_min, pwm_max : int
        The channels' pulse range, us (``SERVOn_MIN``, ``SERVOn_MAX``).
    sail_angle_min_deg, sail_angle_max_deg : float
        ``SAIL_ANGLE_MIN`` and ``SAIL_ANGLE_MAX``: the boom's angle at the mainsail's ends, deg.
    """

    steering_channel: int = 1
    mainsail_channel: int = 4
    throttle_channel: int = 3
    steering_reversed: bool = False
    mainsail_reversed: bool = False
    throttle_reversed: bool = False
    pwm_min: int = 1000
    pwm_max: int = 2000
    sail_angle_min_deg: float = 0.0
    sail_angle_max_deg: float = 90.0

    def __post_init__(self):
        for name in ("steering_channel", "mainsail_channel", "throttle_channel"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 32:
                raise ValueError(f"servos.{name} must be a channel from 1 to 32, got {value!r}")
        if not (isinstance(self.pwm_min, int) and isinstance(self.pwm_max, int)
                and 500 <= self.pwm_min < self.pwm_max <= 2500):
            raise ValueError(f"servos.pwm_min and pwm_max must be whole us with 500 <= min < max <= 2500, "
                             f"got {self.pwm_min!r} and {self.pwm_max!r}")
        check_number("servos.sail_angle_min_deg", self.sail_angle_min_deg, 0.0, 180.0)
        check_number("servos.sail_angle_max_deg", self.sail_angle_max_deg, self.sail_angle_min_deg, 180.0)

    def fraction(self, pwm: int, reversed_: bool) -> float:
        """Where ``pwm`` lies in the range: 0 at ``pwm_min``, 1 at ``pwm_max`` (clipped; swapped
        for a reversed channel).

        Parameters
        ----------
        pwm : int
            The pulse, us.
        reversed_ : bool
            The channel is reversed.
        """
        f = min(1.0, max(0.0, (pwm - self.pwm_min) / (self.pwm_max - self.pwm_min)))
        return 1.0 - f if reversed_ else f

    def rudder(self, pwm: int, max_rudder: float) -> float:
        """The rudder angle for the steering pulse, rad (positive: trailing edge to port).

        Parameters
        ----------
        pwm : int
            The steering channel's pulse, us.
        max_rudder : float
            The rudder's largest angle, rad.
        """
        steer = 2.0 * self.fraction(pwm, self.steering_reversed) - 1.0  # +1: full to starboard
        return -max_rudder * steer

    def throttle(self, pwm: int) -> float:
        """The throttle for the pulse: -1 full astern, 0 stopped (the middle), +1 full ahead.

        Parameters
        ----------
        pwm : int
            The throttle channel's pulse, us.
        """
        return 2.0 * self.fraction(pwm, self.throttle_reversed) - 1.0

    def sail_angle(self, pwm: int) -> float:
        """The boom angle the mainsail pulse lets the sail out to, rad (>= 0).

        Parameters
        ----------
        pwm : int
            The mainsail channel's pulse, us.
        """
        lo, hi = math.radians(self.sail_angle_min_deg), math.radians(self.sail_angle_max_deg)
        return lo + self.fraction(pwm, self.mainsail_reversed) * (hi - lo)
