"""The IBOAT sail trimming of Briere (2008), as Saoud et al. (2015) summarise it in Fig. 5 ("Bm").

Y. Briere, "IBOAT: An autonomous robot for long-term offshore operation", MELECON 2008 (Saoud's
ref. [3]); we have only Saoud's summary (§VII-B and Fig. 5), not Briere's paper.

Saoud (2015) Fig. 5 plots the sail angle delta_s against the apparent wind angle Theta_V for
Theta_V in [0, 180 deg], with three labelled breakpoints (15, 15), (45, 15) and (150, 90) in
degrees (kept by the second text extraction of the paper, 001_a17fd47305b41ae5.txt), and §VII-B
says: "the sail angle is limited to +-pi/2 when |Theta_V| > 5 pi/6 ... the sail angle remains
constant when |Theta_V| in [pi/12, pi/4]". So, for Theta_V >= 0:

    delta_s = Theta_V                                  0      <= Theta_V <= pi/12
            = pi/12                                    pi/12  <= Theta_V <= pi/4
            = pi/12 + (Theta_V - pi/4) (5pi/12)/(7pi/12)   pi/4  <= Theta_V <= 5pi/6
            = pi/2                                     5pi/6  <= Theta_V <= pi

and delta_s(-Theta_V) = -delta_s(Theta_V) ("Figs 3 and 4 have origin symmetry"; Fig. 5 is the
curve compared with them). Reading chosen where the figure is silent: the segment below pi/12
carries no label; odd symmetry and continuity put delta_s(0) = 0, and we join (0, 0) to
(15, 15) by a straight line. Along it delta_s = Theta_V, which in Saoud's eq. 8a at zero heel
gives sin(alpha_s) = sin(delta_s - Theta_V) = 0: the sail is feathered in the no-go zone.

Theta_V and delta_s are Saoud's (see :mod:`controllers.saoud`); the law returns our sail angle
through the same conversion as :class:`controllers.saoud.SaoudSail`.
"""

from __future__ import annotations

import math

import numpy as np

from sailmujoco.frames import wrap_angle

from .sail_laws import keep_side_at_dead_run
from .saoud import WIND_SOURCES, observed_apparent_wind, sail_angle_from_saoud

# Saoud (2015) Fig. 5: (Theta_V, delta_s) in degrees; the first point is our reading, the last
# one the extension of the pi/2 plateau to pi (§VII-B).
BREAKPOINTS_DEG = ((0.0, 0.0), (15.0, 15.0), (45.0, 15.0), (150.0, 90.0), (180.0, 90.0))
_THETA = np.radians([p[0] for p in BREAKPOINTS_DEG])
_DELTA = np.radians([p[1] for p in BREAKPOINTS_DEG])


def briere_sail_angle(theta_v: float) -> float:
    """Briere's sail angle delta_s [rad] (Saoud's convention) for Theta_V [rad].

    Piecewise linear through :data:`BREAKPOINTS_DEG` for |Theta_V|, odd in Theta_V; the
    result lies in [-pi/2, pi/2].

    Parameters
    ----------
    theta_v : float
        Theta_V [rad] (Saoud's, §IV).
    """
    theta = float(wrap_angle(theta_v))
    return math.copysign(float(np.interp(abs(theta), _THETA, _DELTA)), theta)


class BriereSail:
    """Sail law "Bm" of Saoud (2015) Fig. 5: ``law(observation) -> our sail angle`` [rad].

    Parameters
    ----------
    wind_source : {"saoud_v", "ce", "masthead"}
        Where the apparent wind comes from (:func:`controllers.saoud.observed_apparent_wind`:
        Saoud's V by default; the measured readings are un-heeled, tan AWA = cos(phi) tan(Theta_V)).
    min_speed : float
        Below this apparent speed [m/s] Theta_V is undefined and the last command is held.
    """

    def __init__(self, *, wind_source: str = "saoud_v", min_speed: float = 0.1):
        if wind_source not in WIND_SOURCES:
            raise ValueError(f"unknown wind source {wind_source!r}; known: {', '.join(WIND_SOURCES)}")
        self.wind_source, self.min_speed = wind_source, min_speed
        self.reset()

    def reset(self, seed: int | None = None) -> None:
        """Forget the last command (the law is otherwise memoryless; ``seed`` is unused).

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.last_sail_angle = 0.0

    def __call__(self, observation: dict) -> float:
        """The sail angle for this observation; held while the apparent wind is below ``min_speed``.

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Sail angle, rad, positive trailing edge to port.
        """
        theta_v, speed = observed_apparent_wind(observation, self.wind_source)
        if speed >= self.min_speed:
            self.last_sail_angle = keep_side_at_dead_run(
                sail_angle_from_saoud(briere_sail_angle(theta_v)), self.last_sail_angle, theta_v)
        return self.last_sail_angle
