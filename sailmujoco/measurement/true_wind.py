"""The true wind as an autopilot estimates it from its own instruments.

The masthead vane and anemometer give the apparent wind in the boat's frame; the compass turns
it into the world's; adding the boat's velocity over ground (GNSS) gives the wind over ground,
the *true* wind::

    w = R_z(yaw) f + v_g,   f = AWS (-cos AWA, sin AWA)

with ``f`` the air's velocity relative to the masthead (body x-y plane) and ``v_g`` the GNSS
velocity. The estimate is filtered as a vector (a first-order filter on its east and north
components), as ArduPilot's wind vane library filters its true wind (at 0.05 Hz, tau =
1 / (2 pi 0.05) = 3.2 s; its vane and anemometer at 0.5 Hz, ``WNDVN_DIR_FILT`` and
``WNDVN_SPEED_FILT``). ArduPilot forms the same sum, the apparent wind turned to the earth frame
plus the vehicle's velocity (``update_true_wind_speed_and_direction`` of its ``AP_WindVane``).
Like ArduPilot's, it takes the mast's plane for the horizontal (no heel correction) and the
masthead's motion for the hull's: a heeling, rolling boat biases it, and that bias is part of
what it reports.
"""

from __future__ import annotations

import math

from .noise import LowPass

ARDUPILOT_TRUE_WIND_TAU = 1.0 / (2.0 * math.pi * 0.05)  # s: ArduPilot's true-wind filter, 0.05 Hz


def true_wind(awa: float, aws: float, heading: float, velocity_en) -> tuple[float, float]:
    """(speed m/s, direction it comes from, compass rad) of the wind over ground, unfiltered.

    Parameters
    ----------
    awa, aws : float
        Apparent wind angle (rad, positive from starboard) and speed (m/s) at the masthead.
    heading : float
        Compass heading, rad clockwise from north.
    velocity_en : array_like, shape (2,)
        Velocity over ground, m/s east and north.
    """
    east, north = _over_ground(awa, aws, heading, velocity_en)
    return math.hypot(east, north), math.atan2(-east, -north)


def _over_ground(awa, aws, heading, velocity_en) -> tuple[float, float]:
    fx, fy = -aws * math.cos(awa), aws * math.sin(awa)  # body axes, x forward, y port
    yaw = math.pi / 2.0 - heading  # frames.yaw_from_heading
    c, s = math.cos(yaw), math.sin(yaw)
    return c * fx - s * fy + float(velocity_en[0]), s * fx + c * fy + float(velocity_en[1])


class TrueWindEstimate:
    """The filtered true-wind estimate, stepped once per control step.

    Parameters
    ----------
    dt : float
        Control period, s.
    tau : float
        Time constant of the vector filter, s (default ArduPilot's 0.05 Hz).
    """

    def __init__(self, dt: float, tau: float = ARDUPILOT_TRUE_WIND_TAU):
        self.filter = LowPass(tau, dt)

    def update(self, awa: float, aws: float, heading: float, velocity_en) -> tuple[float, float]:
        """(speed m/s, direction it comes from, compass rad) after this step's readings.

        Parameters
        ----------
        awa, aws : float
            The vane's apparent wind angle (rad) and speed (m/s).
        heading : float
            The compass heading, rad.
        velocity_en : array_like, shape (2,)
            The GNSS velocity over ground, m/s east and north.
        """
        east, north = self.filter.step(_over_ground(awa, aws, heading, velocity_en))
        return math.hypot(east, north), math.atan2(-east, -north)


__all__ = ["ARDUPILOT_TRUE_WIND_TAU", "TrueWindEstimate", "true_wind"]
