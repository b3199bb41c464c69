"""Simple sail laws: the baselines every comparison needs.

Both put the boom to leeward (our sign: positive angle = trailing edge to port, the leeward
side when the apparent wind comes from starboard, i.e. AWA > 0).
"""

from __future__ import annotations

import math

from .base import scalar


class LeewardSail:
    """Sail angle = ``fraction`` of the apparent wind angle, clipped to [min, max], to leeward.

    The sailor's rule of thumb (an angle of attack that grows with the wind angle). In irons
    (|AWA| < ``irons``) the sail is centred.
    """

    def __init__(self, fraction: float = 0.5, min_deg: float = 10.0, max_deg: float = 80.0,
                 irons_deg: float = 11.0):
        self.fraction = fraction
        self.low, self.high = math.radians(min_deg), math.radians(max_deg)
        self.irons = math.radians(irons_deg)

    def __call__(self, observation: dict) -> float:
        awa = scalar(observation, "apparent_wind_angle")
        if abs(awa) < self.irons:
            return 0.0
        return math.copysign(min(max(self.fraction * abs(awa), self.low), self.high), awa)


class FixedSail:
    """A fixed sail angle (rad, magnitude) set to leeward: one point of a brute-force search."""

    def __init__(self, angle: float):
        self.angle = abs(angle)

    def __call__(self, observation: dict) -> float:
        return math.copysign(self.angle, scalar(observation, "apparent_wind_angle"))
