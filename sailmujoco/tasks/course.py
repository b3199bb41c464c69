"""Courses: the events autonomous sailboats compete in, laid relative to the wind and scored by
their rules.

``upwind_downwind``: the World Robotic Sailing Championship's fleet race as its 2019 rules
(WRSC 2019, "Notice of race and competition rules" v1.1, github.com/WRSC/rules, main.tex)
score it: a mark is reached when a point of the track lies within 5 m of it; the time runs from
the start to the crossing of the finish line; a boat that does not finish is ranked by the marks
it reached in order. The rules lay the marks on the day ("announced in the morning"); ours is
the windward-leeward course every regatta sails, a start and finish line across the wind and a
windward mark ``leg`` metres straight upwind of its middle (100 m by default: the 2018 course's
legs were 80-132 m, from the organisers' coordinates, github.com/WRSC/coordinates2018), rounded
``laps`` times with a leeward mark 10 m below the line between rounds.

Observation: the sailing observation (:mod:`sailmujoco.tasks.sailing`) plus ``last_mark`` and
``next_mark`` (2,) m, world x east, y north: the leg being sailed, from the last mark reached
(the start for the first leg) to the next one (after the last mark, the finish line's middle).
Reward terms: ``to_go`` = -min(D, 100 leg) / leg with D the course's distance left along its
legs (to the next mark, then mark to mark to the finish), 0 once finished: it grows as the boat
sails the course, never drops at a rounding, and pays nothing for stopping (a stop earns less
than sailing on, :mod:`sailmujoco.tasks.base`). The episode ends at the finish. Metrics:
``marks_reached``, ``finished`` (1 or 0), ``finish_time`` (s; nan without a finish),
``distance_to_go`` (m, at the end).
"""

from __future__ import annotations

import math

import numpy as np

from ..forces.wind import WindConfig
from .base import SailTask, check_number
from .registry import register_task
from .sailing import check_wind_speed

FAR = 100.0  # legs: the distance term's floor is -FAR
MARK_RADIUS = 5.0  # m, WRSC 2019: a mark is reached within 5 m
REACH = 5000.0  # m: the farthest a mark may lie from the start (the Gymnasium adapter's sailing area)
COURSE_KEYS = ("marks", "line", "radius")


def read_course(path) -> dict:
    """A course of one's own from a small TOML file, checked: each problem one line.

    The file holds one table, ``[course]``: ``marks``, a list of [across, up] pairs, metres in
    the wind's frame from the start line's middle (:func:`lay`: up is towards the wind's eye,
    across to its right); and optionally ``line`` (the start and finish line's length, m) and
    ``radius`` (a mark is reached within it, m)::

        [course]
        marks = [[0, 150], [40, 80], [0, 150]]
        line = 20
        radius = 5

    Parameters
    ----------
    path : str or os.PathLike
        The file.

    Returns
    -------
    dict
        ``marks`` (an (n, 2) array) and, where given, ``line`` and ``radius``.
    """
    from ..tomlfile import read_toml

    where = f"course file {str(path)!r}"
    data = read_toml(path, "course file")
    table = data.get("course")
    if set(data) != {"course"} or not isinstance(table, dict):
        raise ValueError(f"{where}: the file holds one table, [course], with marks = [[across, up], ...]")
    unknown = sorted(set(table) - set(COURSE_KEYS))
    if unknown:
        raise ValueError(f"{where}: unknown key {unknown[0]!r}; the keys are {', '.join(COURSE_KEYS)}")
    marks = table.get("marks")
    try:
        marks = np.asarray(marks, dtype=float)
    except (TypeError, ValueError):
        marks = None
    if marks is None or marks.ndim != 2 or marks.shape[1] != 2 or len(marks) == 0 \
            or not np.all(np.isfinite(marks)):
        raise ValueError(f"{where}: marks must be a list of [across, up] pairs in metres, "
                         f"e.g. [[0, 150], [40, 80]]")
    out = {"marks": marks}
    for key in ("line", "radius"):
        if key in table:
            out[key] = check_number(f"{where}: {key}", table[key], 0.0, low_open=True, unit="m")
    radius = out.get("radius", MARK_RADIUS)
    for i, mark in enumerate(marks):
        before = marks[i - 1] if i else np.zeros(2)
        if math.hypot(*mark) > REACH:
            raise ValueError(f"{where}: mark {i + 1} at {mark.tolist()} lies {math.hypot(*mark):.0f} m from "
                             f"the start, beyond the {REACH:g} m a boat can be sent")
        if math.hypot(*(mark - before)) <= radius:
            what = f"mark {i}" if i else "the start"
            raise ValueError(f"{where}: mark {i + 1} at {mark.tolist()} lies within the {radius:g} m radius "
                             f"of {what}: it would be reached without sailing to it")
    return out


def lay(layout, wind_from: float, origin=(0.0, 0.0)) -> np.ndarray:
    """A layout drawn in the wind's frame, laid in the world for a wind from ``wind_from``.

    Parameters
    ----------
    layout : array_like, shape (n, 2)
        Points as (across, up): metres to the right of the wind's eye and towards it, from the
        layout's origin (a sailor facing the wind has "up" ahead and "across" to starboard).
    wind_from : float
        The compass bearing the wind comes from, rad.
    origin : array_like, shape (2,)
        Where the layout's origin lies in the world (east, north), m.

    Returns
    -------
    numpy.ndarray, shape (n, 2)
        The points in the world (east, north), m.
    """
    points = np.asarray(layout, dtype=float).reshape(-1, 2)
    up = np.array([math.sin(wind_from), math.cos(wind_from)])  # towards the wind's eye
    across = np.array([math.cos(wind_from), -math.sin(wind_from)])  # to its right
    return np.asarray(origin, dtype=float) + points[:, :1] * across + points[:, 1:] * up


def crossed(p, q, a, b) -> bool:
    """Whether the step from ``p`` to ``q`` crosses the segment from ``a`` to ``b``.

    Parameters
    ----------
    p, q, a, b : array_like, shape (2,)
        Points (east, north), m.
    """
    def side(u, v, w):
        return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0])

    return side(a, b, p) * side(a, b, q) < 0 and side(p, q, a) * side(p, q, b) < 0


def score_race(t, xy, marks, finish, radius: float = MARK_RADIUS) -> dict:
    """A track scored as WRSC 2019 scores its fleet race.

    Parameters
    ----------
    t : array_like, shape (n,)
        The track's times, s (the start at ``t[0]``).
    xy : array_like, shape (n, 2)
        Its points (east, north), m.
    marks : array_like, shape (k, 2)
        The marks in the order they are to be reached.
    finish : array_like, shape (2, 2)
        The finish line's ends.
    radius : float
        A mark is reached when a point lies within ``radius`` of it, m.

    Returns
    -------
    dict
        ``marks_reached`` (in order), ``finished`` (1 or 0: the line crossed after the last
        mark), ``finish_time`` (s from the start, nan without a finish).
    """
    t, xy, marks = np.asarray(t, float), np.asarray(xy, float), np.asarray(marks, float)
    reached, finish_time = 0, math.nan
    for i in range(len(t)):
        if reached < len(marks) and math.hypot(*(xy[i] - marks[reached])) <= radius:
            reached += 1
        elif reached == len(marks) and i > 0 and crossed(xy[i - 1], xy[i], *finish):
            finish_time = float(t[i] - t[0])
            break
    return {"marks_reached": reached, "finished": int(not math.isnan(finish_time)),
            "finish_time": finish_time}


class EventTask(SailTask):
    """What every event here shares: a wind of a given speed from a given bearing, the event
    laid to it, the boat started on a beam reach at 1 m/s (not in irons).

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    wind_speed : float
        Mean true wind at 10 m, m/s, in [0, 100].
    wind_from_deg : float
        Compass bearing the wind comes from, degrees; the event is laid to it.
    gusts, wander : bool
        Gusts in speed, slow wander of the direction.
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    def __init__(self, seed=None, wind_speed: float = 5.0, wind_from_deg: float = 0.0, gusts: bool = True,
                 wander: bool = True, **kwargs):
        super().__init__(seed, **kwargs)
        self.wind_speed = check_wind_speed(wind_speed)
        self.wind_from = math.radians(check_number("wind_from_deg", wind_from_deg))
        self.gusts, self.wander = gusts, wander

    def wind(self):
        return WindConfig(speed=self.wind_speed, direction_from=self.wind_from, gusts=self.gusts,
                          wander=self.wander, seed=0 if self.seed is None else self.seed)

    def initial_heading(self):
        return self.wind_from + math.pi / 2  # a beam reach on starboard tack

    def initial_speed(self):
        return 1.0


@register_task
class UpwindDownwind(EventTask):
    """A windward-leeward race: from the start line, round the windward mark ``laps`` times,
    finish across the line (the module docstring gives the rules and the sources).

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    wind_speed : float
        Mean true wind at 10 m, m/s, in [0, 100].
    wind_from_deg : float
        Compass bearing the wind comes from, degrees; the course is laid to it.
    gusts, wander : bool
        Gusts in speed, slow wander of the direction.
    leg : float
        The windward mark's distance upwind of the start line's middle, m, > 0.
    laps : int
        Times the windward mark is rounded, 1-5 (a leeward mark 10 m below the line between).
    line : float
        The start and finish line's length, m, > 0.
    radius : float
        A mark is reached within this distance, m (WRSC 2019: 5).
    course : str or os.PathLike, optional
        A course of one's own (:func:`read_course`): its marks replace the windward mark and
        the laps, its ``line`` and ``radius`` these options; ``leg`` becomes its farthest mark's
        distance.
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "upwind_downwind"
    duration = 600.0

    def __init__(self, seed=None, wind_speed: float = 5.0, wind_from_deg: float = 0.0, gusts: bool = True,
                 wander: bool = True, leg: float = 100.0, laps: int = 1, line: float = 20.0,
                 radius: float = MARK_RADIUS, course=None, **kwargs):
        super().__init__(seed, wind_speed, wind_from_deg, gusts, wander, **kwargs)
        self.leg = check_number("leg", leg, 0.0, low_open=True, unit="m")
        if laps not in range(1, 6):
            raise ValueError(f"upwind_downwind: laps must be an integer 1-5, got {laps!r}")
        self.laps = int(laps)
        self.line = check_number("line", line, 0.0, low_open=True, unit="m")
        self.radius = check_number("radius", radius, 0.0, low_open=True, unit="m")
        windward, leeward = (0.0, self.leg), (0.0, -10.0)
        layout = [windward, leeward] * (self.laps - 1) + [windward]
        if course is not None:
            own = read_course(course)
            layout = own["marks"]
            self.line, self.radius = own.get("line", self.line), own.get("radius", self.radius)
            self.leg = float(np.max(np.hypot(*layout.T)))
        self.marks = lay(layout, self.wind_from)
        self.finish = lay([(-self.line / 2, 0.0), (self.line / 2, 0.0)], self.wind_from)
        self.reached, self.finished, self._last_position = 0, False, None  # the spec asks before a reset

    def initialize_episode(self, physics):
        super().initialize_episode(physics)
        self.reached, self.finished, self._last_position = 0, False, None

    def _points(self) -> np.ndarray:
        """The course's points in order: the start, the marks, the finish line's middle."""
        return np.vstack([np.zeros((1, 2)), self.marks, self.finish.mean(axis=0, keepdims=True)])

    def advance(self, position) -> None:
        """Count the mark reached, or the finish crossed, with the boat at ``position``.

        Parameters
        ----------
        position : array_like, shape (2,)
            The boat (east, north), m.
        """
        position = np.asarray(position, dtype=float)
        left = self.reached < len(self.marks)
        if left and math.hypot(*(position - self.marks[self.reached])) <= self.radius:
            self.reached += 1
        elif (self.reached == len(self.marks) and self._last_position is not None
              and crossed(self._last_position, position, *self.finish)):
            self.finished = True
        self._last_position = position

    def references(self, physics):
        position = np.asarray(physics.truth().position, dtype=float)
        if self._last_position is None or not np.array_equal(position, self._last_position):
            self.advance(position)
        points = self._points()
        return {"last_mark": points[self.reached].copy(), "next_mark": points[self.reached + 1].copy()}

    def distance_to_go(self, position) -> float:
        """The course's distance left along its legs from ``position``, m (0 once finished).

        Parameters
        ----------
        position : array_like, shape (2,)
            The boat (east, north), m.
        """
        if self.finished:
            return 0.0
        points = self._points()[self.reached + 1:]
        legs = np.sum(np.hypot(*np.diff(points, axis=0).T)) if len(points) > 1 else 0.0
        return float(math.hypot(*(np.asarray(position, float) - points[0])) + legs)

    def reward_terms(self, physics, observation):
        to_go = self.distance_to_go(physics.truth().position)
        return {"to_go": -min(to_go, FAR * self.leg) / self.leg}

    def reward_floor(self, physics):
        return -FAR

    def get_termination(self, physics):
        """0.0 once the finish line is crossed (the race is over; sailing on would earn 0 a step,
        as the finish does), else the base task's (a stopped world).

        Parameters
        ----------
        physics : World
            The world the task runs on.
        """
        return 0.0 if self.finished else super().get_termination(physics)

    def summarise(self, records):
        t = np.array([r["t"] for r in records])
        xy = np.array([r["position"] for r in records])
        out = score_race(t, xy, self.marks, self.finish, self.radius)
        out["distance_to_go"] = self.distance_to_go(xy[-1]) if not out["finished"] else 0.0
        return out


@register_task
class PrecisionNavigation(UpwindDownwind):
    """SailBot's precision navigation: from between the two start buoys, round two buoys, and
    come back between the start buoys.

    SailBot 2022's event sheet ("SailBot-2022-Events.pdf", sailbot.org; quoted from a team's
    copy, github.com/PittSailbot/Sailbot, events/precisionNavigation.py) scores it out of 10: 2
    points for each of the first two buoys rounded, 6 more for finishing between the start
    buoys, or 4 for crossing the line outside them. Its diagram, which places the buoys, could
    not be read here; ours lays the two buoys ``distance`` m downwind of the gate and ``gap`` m
    apart across the wind (the teams' reading: the buoys lie downwind, the way back is the hard
    part), and counts a buoy rounded when the track passes within ``radius`` of it (WRSC's 5 m).
    The gate is ``line`` m wide.

    Metrics: those of :class:`UpwindDownwind` and ``points`` (0-10, the sheet's). Parameters as
    :class:`UpwindDownwind`'s, without ``leg`` and ``laps``, and:

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    distance : float
        The buoys' distance downwind of the gate, m, > 0.
    gap : float
        Their distance apart, across the wind, m, >= 0.
    line : float
        The gate's width, m, > 0.
    **kwargs
        Passed to :class:`UpwindDownwind`: ``wind_speed``, ``wind_from_deg``, ``gusts``,
        ``wander``, ``radius``, ``heading_jitter_deg``.
    """

    name = "precision_navigation"
    duration = 600.0
    fixed_options = ("leg", "laps", "course")  # the race's, which this event lays itself

    def __init__(self, seed=None, distance: float = 50.0, gap: float = 20.0, line: float = 10.0, **kwargs):
        given = [name for name in self.fixed_options if name in kwargs]
        if given:
            raise ValueError(f"precision_navigation lays its own buoys (distance, gap, line): {given[0]} "
                             "is upwind_downwind's option")
        super().__init__(seed, leg=distance, line=line, **kwargs)
        self.gap = check_number("gap", gap, 0.0, unit="m")
        self.marks = lay([(-self.gap / 2, -self.leg), (self.gap / 2, -self.leg)], self.wind_from)

    def summarise(self, records):
        out = super().summarise(records)
        points = 2 * out["marks_reached"]
        if out["finished"]:
            points += 6
        elif out["marks_reached"] == len(self.marks):
            xy = np.array([r["position"] for r in records])
            centre, half = self.finish.mean(axis=0), self.finish - self.finish.mean(axis=0)
            wide = centre + 1e3 * half  # the gate's line carried far out on both sides
            first = int(np.argmax([math.hypot(*(p - self.marks[-1])) <= self.radius for p in xy]))
            if any(crossed(xy[i - 1], xy[i], *wide) for i in range(first + 1, len(xy))):
                points += 4
        out["points"] = points
        return out

