"""Station keeping: SailBot's box, laid to the wind and scored by its 2022 event sheet
(:class:`StationKeeping` gives the rules and the sources)."""

from __future__ import annotations

import math

import numpy as np

from .base import check_number
from .course import FAR, EventTask, lay
from .registry import register_task

WINDOW = 300.0  # s, SailBot: stay inside the box for 5 minutes
GRACE = 30.0  # s, then exit within 30 seconds


def score_station(t, xy, center, half: float, wind_from: float) -> dict:
    """A track scored as SailBot 2022's station keeping: 2 points a minute inside the box during
    the 5 minutes from the first entry (at most 10), less 2 a minute inside after 5 1/2 minutes
    (held at 0: our reading of a deduction from the event's points).

    Parameters
    ----------
    t : array_like, shape (n,)
        The track's times, s.
    xy : array_like, shape (n, 2)
        Its points (east, north), m.
    center : array_like, shape (2,)
        The box's centre, m.
    half : float
        Half its side, m (its sides along and across the wind).
    wind_from : float
        The compass bearing the wind comes from, rad (the box's axes).

    Returns
    -------
    dict
        ``entered_at`` (s; nan if never), ``time_in_box`` (s inside in the 5 minutes),
        ``time_in_box_late`` (s inside after 5 1/2), ``points``.
    """
    t, xy = np.asarray(t, float), np.asarray(xy, float)
    local = (xy - np.asarray(center, float)) @ np.array(
        [[math.cos(wind_from), math.sin(wind_from)], [-math.sin(wind_from), math.cos(wind_from)]])
    inside = np.all(np.abs(local) <= half, axis=1)  # (across, up) within the half side
    if not inside.any():
        return {"entered_at": math.nan, "time_in_box": 0.0, "time_in_box_late": 0.0, "points": 0.0}
    t0 = t[np.argmax(inside)]
    dt = np.diff(t, append=t[-1])  # each point holds until the next
    window = (t >= t0) & (t < t0 + WINDOW)
    late = t >= t0 + WINDOW + GRACE
    in_window = float(np.sum(dt[inside & window]))
    in_late = float(np.sum(dt[inside & late]))
    points = max(0.0, min(10.0, 2.0 * in_window / 60.0) - 2.0 * in_late / 60.0)
    return {"entered_at": float(t0), "time_in_box": in_window, "time_in_box_late": in_late,
            "points": points}


@register_task
class StationKeeping(EventTask):
    """SailBot's station keeping: enter a 40 m x 40 m box, stay inside it for five minutes,
    then leave it within 30 seconds.

    SailBot 2022's event sheet (as a team copied it: github.com/PittSailbot/Sailbot,
    events/stationKeeping.py) scores it out of 10: 2 points a minute inside the box during the 5
    minutes (the boat may leave and come back), less 2 a minute inside after 5 1/2 minutes; the
    five minutes start when the boat first enters. Ours lays the box with its sides along and
    across the wind, its centre ``distance`` m upwind of the start (WRSC releases its boats at
    least 40 m from the point; :func:`score_station`).

    Observation: the sailing observation plus ``box_center`` (2,) m and ``box_time_left`` (s of
    the five minutes left: 300 until the boat enters, negative once they are over). Reward term
    ``box``: during the five minutes, 0 inside and -min(d, 100 half) / half outside (d the
    distance to the box); after them, -1 inside and 0 outside; before the first entry as
    outside. Metrics: ``entered_at``, ``time_in_box``, ``time_in_box_late``, ``points``.

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    wind_speed : float
        Mean true wind at 10 m, m/s, in [0, 100].
    wind_from_deg : float
        Compass bearing the wind comes from, degrees.
    gusts, wander : bool
        Gusts in speed, slow wander of the direction.
    side : float
        The box's side, m, > 0 (SailBot: 40).
    distance : float
        Its centre's distance upwind of the start, m, >= 0.
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "station_keeping"
    duration = 600.0

    def __init__(self, seed=None, wind_speed: float = 5.0, wind_from_deg: float = 0.0, gusts: bool = True,
                 wander: bool = True, side: float = 40.0, distance: float = 60.0, **kwargs):
        super().__init__(seed, wind_speed, wind_from_deg, gusts, wander, **kwargs)
        self.half = 0.5 * check_number("side", side, 0.0, low_open=True, unit="m")
        self.distance = check_number("distance", distance, 0.0, unit="m")
        self.center = lay([(0.0, self.distance)], self.wind_from)[0]
        self.entered_at = None

    def initialize_episode(self, physics):
        super().initialize_episode(physics)
        self.entered_at = None

    def _outside_by(self, position) -> float:
        """How far ``position`` lies outside the box, m (0 inside)."""
        local = np.asarray(position, float) - self.center
        c, s = math.cos(self.wind_from), math.sin(self.wind_from)
        across, up = local[0] * c - local[1] * s, local[0] * s + local[1] * c
        return float(math.hypot(max(abs(across) - self.half, 0.0), max(abs(up) - self.half, 0.0)))

    def time_left(self, t: float) -> float:
        """Seconds of the five minutes left at ``t`` (all of them before the boat enters).

        Parameters
        ----------
        t : float
            The time, s.
        """
        return WINDOW if self.entered_at is None else WINDOW - (t - self.entered_at)

    def references(self, physics):
        truth = physics.truth()
        if self.entered_at is None and self._outside_by(truth.position) == 0.0:
            self.entered_at = float(truth.time)
        return {"box_center": self.center.copy(), "box_time_left": np.array([self.time_left(truth.time)])}

    def reward_terms(self, physics, observation):
        truth = physics.truth()
        outside = self._outside_by(truth.position)
        if self.time_left(truth.time) > -GRACE or self.entered_at is None:
            return {"box": -min(outside, FAR * self.half) / self.half}
        return {"box": -1.0 if outside == 0.0 else 0.0}

    def reward_floor(self, physics):
        return -FAR

    def summarise(self, records):
        t = np.array([r["t"] for r in records])
        xy = np.array([r["position"] for r in records])
        return score_station(t, xy, self.center, self.half, self.wind_from)
