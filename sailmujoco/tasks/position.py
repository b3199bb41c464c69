"""Position keeping around a buoy: Viel, Vautier, Wan & Jaulin, §5 (cases 1-6).

Reach the target p_T = (0, 0) and stay near it for 200 s. The target area is the circle of
radius d_T = 7 m, the pre-arrival area the ring out to d_M = 14 m (§4.1, §5.1).

Observation: the sailing observation (:mod:`sailmujoco.tasks.sailing`) plus
``target_position`` (2,) m, world x east, y north. Action: ``[rudder, sail]`` rad (ours).
Reward terms: ``distance`` = -min(d, 100 d_T) / d_T (so a step earns at least -100: beyond
100 target radii the boat is lost anyway, and a bounded floor keeps a stop from paying, see
:mod:`sailmujoco.tasks.base`). Metrics: ``entered_at`` (s, first time d < d_T; nan if
never), ``max_distance_after_entry`` and ``mean_distance_after_entry`` (m; the paper: stays
below 6.4 m), ``final_distance`` (m).

Wind cases (§5.1; psi_tw = pi/2 in Viel's x east / y north frame: the wind blows towards the
north, i.e. comes from compass 180 deg):

====  ========================  ==============================
case  a_tw (m/s)                psi_tw (rad)
====  ========================  ==============================
1     10                        pi/2
2     5                         pi/2
3     5 sin(2 pi t) + 10        pi/2
4     10                        pi/12 sin(2 pi t) + pi/2
5     5 sin(2 pi t) + 10        pi/12 sin(2 pi t) + pi/2
6     5 sin(2 pi t) + 10        pi/6 sin(2 pi t) + pi/2
====  ========================  ==============================

Viel's a_tw carries no height; we give it as the mean wind at 10 m of our log profile. The
oscillations are the paper's, at 1 Hz (t in seconds), including their sign: psi_tw grows
counter-clockwise, so a compass bearing it *comes from* shrinks by the same amount.
"""

from __future__ import annotations

import math

import numpy as np

from .. import frames
from ..forces.wind import WindConfig
from .base import SailTask, check_number
from .registry import register_task

# case: (mean a_tw m/s, speed oscillation m/s, direction oscillation rad)
FAR = 100.0  # target radii d_T: the distance term's floor, -FAR
CASES = {1: (10.0, 0.0, 0.0), 2: (5.0, 0.0, 0.0), 3: (10.0, 5.0, 0.0),
         4: (10.0, 0.0, math.pi / 12), 5: (10.0, 5.0, math.pi / 12), 6: (10.0, 5.0, math.pi / 6)}


@register_task
class PositionKeeping(SailTask):
    """Viel's position keeping, wind ``case`` 1-6; the boat starts at ``start`` (m).

    Parameters
    ----------
    seed : int, optional
        Seeds the random initial heading (uniform over the compass).
    case : int
        Viel's wind case, 1-6 (:data:`CASES`).
    start : tuple of float
        Initial world position (east, north), m.
    target : tuple of float
        Target position p_T, world (east, north), m.
    d_target : float
        Radius d_T of the target area, m, > 0.
    d_prearrival : float
        Outer radius d_M of the pre-arrival ring, m, > ``d_target``.
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "position_keeping"
    duration = 200.0

    def __init__(self, seed=None, case: int = 1, start=(-30.0, 40.0), target=(0.0, 0.0),
                 d_target: float = 7.0, d_prearrival: float = 14.0, **kwargs):
        super().__init__(seed, **kwargs)
        if case not in CASES:
            raise ValueError(f"position_keeping: case must be one of {sorted(CASES)}, got {case!r}")
        self.case = case
        self.start = np.asarray(start, dtype=float)
        self.target = np.asarray(target, dtype=float)
        self.d_target = check_number("d_target", d_target, 0.0, low_open=True, unit="m")
        self.d_prearrival = check_number("d_prearrival", d_prearrival, self.d_target, low_open=True,
                                         unit="m (more than d_target)")

    def wind(self):
        speed, speed_osc, dir_osc = CASES[self.case]
        return WindConfig(speed=speed, direction_from=math.pi, gusts=False, wander=False,
                          speed_oscillation=speed_osc, direction_oscillation=-dir_osc,
                          oscillation_frequency=1.0 if (speed_osc or dir_osc) else 0.0,
                          seed=0 if self.seed is None else self.seed)

    def initialize_episode(self, physics):
        super().initialize_episode(physics)
        heading = self.random.uniform(-math.pi, math.pi)
        physics.place(tuple(self.start), float(frames.yaw_from_heading(heading)), 0.5)

    def references(self, physics):
        return {"target_position": self.target}

    def reward_terms(self, physics, observation):
        d = math.hypot(*(observation["position"] - self.target))
        return {"distance": -min(d, FAR * self.d_target) / self.d_target}

    def reward_floor(self, physics):
        return -FAR

    def summarise(self, records):
        t = np.array([r["t"] for r in records])
        d = np.array([math.hypot(*(r["position"] - self.target)) for r in records])
        inside = np.nonzero(d < self.d_target)[0]
        out = {"final_distance": float(d[-1]), "min_distance": float(d.min())}
        if inside.size:
            after = d[inside[0]:]
            out.update(entered_at=float(t[inside[0]]),
                       max_distance_after_entry=float(after.max()),
                       mean_distance_after_entry=float(after.mean()))
        else:
            out.update(entered_at=float("nan"), max_distance_after_entry=float("nan"),
                       mean_distance_after_entry=float("nan"))
        return out
