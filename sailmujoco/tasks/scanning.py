"""Area scanning: the World Robotic Sailing Championship's event, laid to the wind and scored
by its cells (:class:`AreaScanning` gives the rules and the sources)."""

from __future__ import annotations

import math

import numpy as np

from .base import check_number
from .course import EventTask, lay
from .registry import register_task


def cells_of(xy, center, half: float, cell: float, wind_from: float) -> set:
    """The grid cells a track's points fall in: (column, row) counted from the area's corner
    downwind and to port, the grid's lines along and across the wind; points outside none.

    Parameters
    ----------
    xy : array_like, shape (n, 2)
        The track's points (east, north), m.
    center : array_like, shape (2,)
        The area's centre, m.
    half : float
        Half its side, m.
    cell : float
        A cell's side, m.
    wind_from : float
        The compass bearing the wind comes from, rad.
    """
    d = np.asarray(xy, float).reshape(-1, 2) - np.asarray(center, float)
    across = d[:, 0] * math.cos(wind_from) - d[:, 1] * math.sin(wind_from)
    up = d[:, 0] * math.sin(wind_from) + d[:, 1] * math.cos(wind_from)
    n = int(round(2.0 * half / cell))
    column = np.floor((across + half) / cell).astype(int)
    row = np.floor((up + half) / cell).astype(int)
    inside = (column >= 0) & (column < n) & (row >= 0) & (row < n)
    return set(zip(column[inside].tolist(), row[inside].tolist(), strict=True))


@register_task
class AreaScanning(EventTask):
    """WRSC's area scanning: visit as many cells of a square area as the time allows.

    WRSC 2019's rules (github.com/WRSC/rules, main.tex) count a cell visited when a point of the
    track falls in it; the organisers' scoring script (github.com/WRSC/scoring) lays a 24 x 24
    grid of 2.5 m cells (a 60 m square) and counts each team's first 15 minutes, the default
    here. Ours lays the square with its sides along and across the wind, its centre
    ``distance`` m upwind of the start (the rules place it on the day).

    Observation: the sailing observation plus ``area_center`` (2,) m and ``area_half`` (1,) m.
    Reward term ``cells``: the cells first visited at this step (never negative: a stop can
    only lose the cells not yet visited). Metrics: ``cells_visited``, ``coverage`` (their share
    of the grid).

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
        The area's side, m, > 0 (WRSC 2019: 60).
    cell : float
        A cell's side, m, > 0, dividing ``side`` into whole cells (WRSC 2019: 2.5).
    distance : float
        The area's centre's distance upwind of the start, m, >= 0.
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "area_scanning"
    duration = 900.0

    def __init__(self, seed=None, wind_speed: float = 5.0, wind_from_deg: float = 0.0, gusts: bool = True,
                 wander: bool = True, side: float = 60.0, cell: float = 2.5, distance: float = 50.0,
                 **kwargs):
        super().__init__(seed, wind_speed, wind_from_deg, gusts, wander, **kwargs)
        side = check_number("side", side, 0.0, low_open=True, unit="m")
        self.cell = check_number("cell", cell, 0.0, side, low_open=True, unit="m (at most side)")
        if abs(side / self.cell - round(side / self.cell)) > 1e-9:
            raise ValueError(f"area_scanning: cell must divide side into whole cells, got side {side:g} m "
                             f"and cell {self.cell:g} m")
        self.half = 0.5 * side
        self.distance = check_number("distance", distance, 0.0, unit="m")
        self.center = lay([(0.0, self.distance)], self.wind_from)[0]
        self.cells = round(side / self.cell) ** 2
        self.visited, self.fresh = set(), 0

    def initialize_episode(self, physics):
        super().initialize_episode(physics)
        self.visited, self.fresh = self._cells(physics.truth().position), 0

    def _cells(self, position) -> set:
        return cells_of([position], self.center, self.half, self.cell, self.wind_from)

    def after_step(self, physics):
        super().after_step(physics)  # this step's record: the true position, as the score reads it
        fresh = self._cells(self._records[-1]["position"]) - self.visited
        self.visited |= fresh
        self.fresh = len(fresh)  # this step's reward: read as often as asked

    def references(self, physics):
        return {"area_center": self.center.copy(), "area_half": np.array([self.half])}

    def reward_terms(self, physics, observation):
        return {"cells": float(self.fresh)}

    def reward_floor(self, physics):
        return 0.0

    def summarise(self, records):
        xy = np.array([r["position"] for r in records])
        visited = len(cells_of(xy, self.center, self.half, self.cell, self.wind_from))
        return {"cells_visited": visited, "coverage": visited / self.cells}
