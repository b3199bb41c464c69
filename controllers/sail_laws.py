"""Simple sail laws: the baselines every comparison needs.

Both put the boom to leeward (our sign: positive angle = trailing edge to port, the leeward
side when the apparent wind comes from starboard, i.e. AWA > 0).
"""

from __future__ import annotations

import math

from .base import scalar

DEAD_RUN_BAND = math.radians(10.0)


def keep_side_at_dead_run(angle: float, last: float, wind_angle: float,
                          band: float = DEAD_RUN_BAND) -> float:
    """Hold the boom on its side while the apparent wind is within ``band`` of dead astern.

    With the wind from astern both sides are leeward; a law that picks the side from the sign
    of the wind angle gybes at every flicker of it and loses the drive. None of the papers
    specifies this; every sail law here applies it (``wind_angle`` is AWA or Theta_V, rad).

    Parameters
    ----------
    angle : float
        The law's sail angle [rad].
    last : float
        The last command [rad]; 0 before the first.
    wind_angle : float
        AWA or Theta_V [rad]; +-pi is dead astern.
    band : float
        Half-width of the dead-run band [rad].

    Returns
    -------
    float
        ``angle``, or its magnitude on the side of ``last`` within the band [rad].
    """
    if last != 0.0 and math.pi - abs(wind_angle) < band:
        return math.copysign(abs(angle), last)
    return angle


class LeewardSail:
    """Sail angle = ``fraction`` of the apparent wind angle, clipped to [min, max], to leeward.

    The sailor's rule of thumb (an angle of attack that grows with the wind angle). In irons
    (|AWA| < ``irons``) the sail is centred.

    Parameters
    ----------
    fraction : float
        Sail angle per radian of |AWA| [-].
    min_deg, max_deg : float
        Clip of the sail angle's magnitude [deg].
    irons_deg : float
        Below this |AWA| [deg] the sail is centred.
    """

    def __init__(self, fraction: float = 0.5, min_deg: float = 10.0, max_deg: float = 80.0,
                 irons_deg: float = 11.0):
        self.fraction = fraction
        self.low, self.high = math.radians(min_deg), math.radians(max_deg)
        self.irons = math.radians(irons_deg)

    def __call__(self, observation: dict) -> float:
        """The sail angle for this observation (0 in irons).

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Sail angle, rad, to leeward (the sign of the apparent wind angle).
        """
        awa = scalar(observation, "apparent_wind_angle")
        if abs(awa) < self.irons:
            return 0.0
        return math.copysign(min(max(self.fraction * abs(awa), self.low), self.high), awa)


class FixedSail:
    """A fixed sail angle (rad, magnitude) set to leeward: one point of a brute-force search.

    Parameters
    ----------
    angle : float
        Sail angle [rad]; its magnitude is used, to leeward.
    """

    def __init__(self, angle: float):
        self.angle = abs(angle)
        self.last = 0.0

    def reset(self, seed: int | None = None) -> None:
        """Clear the internal state.

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.last = 0.0

    def __call__(self, observation: dict) -> float:
        """The fixed sail angle, to leeward of this observation's apparent wind.

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Sail angle, rad.
        """
        awa = scalar(observation, "apparent_wind_angle")
        self.last = keep_side_at_dead_run(math.copysign(self.angle, awa), self.last, awa)
        return self.last
