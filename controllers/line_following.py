"""Jaulin and Le Bars' line following with tacking: the law most robotic sailboats descend from.

L. Jaulin, F. Le Bars, "An interval approach for stability analysis: application to sailboat
robotics", IEEE Trans. Robotics 29(1), 2013; the same law as "A simple controller for line
following of sailboats" (Jaulin, Le Bars, IRSC 2012) and on VAIMOS (Le Bars, Jaulin, WRSC 2012).
The T-RO text itself could not be read here: the steps below are numbered as the IRSC 2012
listing is numbered in the implementations that cite it step by step, and the law's form was
checked against Le Bars' own VAIMOS software (ENSTA Bretagne's UxVCtrl). Its frame is Jaulin's:
x east, y north, angles counter-clockwise from east, and psi the direction the wind blows *to*.

Inputs: the boat's position m, its heading theta, the wind's direction psi, the line from a to
b; state: the tack q in {-1, 1}. Parameters: the cut-off distance r, the close-hauled angle zeta
(half the no-go cone, from the wind's eye), the incidence angle gamma_inf (the angle at which a
boat far from the line heads back to it), the largest rudder angle and the sail's beta::

    1. e = det((b - a)/|b - a|, m - a)                   (signed distance, > 0 left of a -> b)
    2. if |e| > r/2: q = sign(e)                          (the hysteresis: the tack keeps until then)
    3. phi = angle(b - a)
    4. theta* = phi - (2 gamma_inf / pi) atan(e / r)     (the heading that brings the boat to the line)
    5. if cos(psi - theta*) + cos(zeta) < 0               (theta* lies in the no-go cone)
    6.    or (|e| < r and cos(psi - phi) + cos(zeta) < 0) (or the line does, and the boat is near it)
    7.    then theta_bar = pi + psi - q zeta              (close-hauled on tack q)
    8.    else theta_bar = theta*
    9. (end if)
    10. if cos(theta - theta_bar) >= 0: delta_r = delta_r_max sin(theta - theta_bar)
    11.    else delta_r = delta_r_max sign(sin(theta - theta_bar))  (full rudder beyond 90 deg)
       A positive delta_r turns the boat clockwise in Jaulin's model, so the package's rudder
       (positive: to port) is -delta_r.
    12. delta_s_max = (pi/2) ((cos(psi - theta_bar) + 1) / 2) ** (log(pi / (2 beta)) / log 2)
       (the sheet's length as an angle: beta abeam, pi/2 before the wind, 0 head to wind); the
       package's sail angle is delta_s_max to leeward.

Steps 10-11 are the IRSC listing's. Jaulin's book writes the rudder as (delta_r_max / pi)
sawtooth(theta - theta_bar), sawtooth(x) = 2 atan(tan(x / 2)): the same sign, a third of the
gain near the heading (1/pi against 1 per rad). With it Wille's 8.8 m yacht, 0.5 m/s
close-hauled, cannot hold its heading against its weather helm and stalls in its tacks; the book's
form is the switch ``rudder="sawtooth"``.

The defaults are IRSC 2012's as its citing implementations carry them (zeta = pi/3, gamma_inf =
pi/4, the tack's threshold r/2) with beta = pi/4 (the book's, for which step 12 reduces to the
IRSC listing's (pi/4)(cos + 1)); the cut-off r is the boat's to choose (the authors' runs used 5
to 50 m): 10 m here, about a hull length of the 11:Metre, two of Wille's yacht.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

RUDDER_LAWS = ("listing", "sawtooth")  # steps 10-11 as IRSC 2012 lists them; Jaulin's book form
STATION_WINDOW = 300.0  # s: station keeping's five minutes (sailmujoco.tasks.station)


def sawtooth(x: float) -> float:
    """``x`` wrapped to (-pi, pi]: 2 atan(tan(x/2)) without its poles.

    Parameters
    ----------
    x : float
        An angle, rad.
    """
    wrapped = (x + math.pi) % (2.0 * math.pi) - math.pi
    return math.pi if wrapped == -math.pi else wrapped


@dataclass(frozen=True)
class LineFollowingGains:
    """The law's parameters (Jaulin and Le Bars' names).

    Parameters
    ----------
    r : float
        Cut-off distance, m: the corridor's half-width and the scale of the return to the line.
    zeta : float
        Close-hauled angle, rad: half the no-go cone, from the wind's eye.
    gamma_inf : float
        Incidence angle, rad: the heading's angle to the line far from it.
    delta_r_max : float
        The largest rudder angle, rad.
    beta : float
        The sail's angle with the wind abeam, rad.
    rudder : str
        "listing": steps 10-11 of the IRSC listing (sin, full rudder beyond 90 deg); "sawtooth":
        Jaulin's book form, (delta_r_max / pi) sawtooth(theta - theta_bar).
    """

    r: float = 10.0
    zeta: float = math.pi / 3.0
    gamma_inf: float = math.pi / 4.0
    delta_r_max: float = math.radians(35.0)
    beta: float = math.pi / 4.0
    rudder: str = "listing"

    def __post_init__(self):
        if self.rudder not in RUDDER_LAWS:
            raise ValueError(f"rudder must be one of {', '.join(RUDDER_LAWS)}, got {self.rudder!r}")


def line_following(m, theta: float, psi: float, a, b, q: int,
                   gains: LineFollowingGains = LineFollowingGains()) -> tuple[float, float, float, int]:
    """One step of the law in Jaulin's frame (see the module docstring for the steps).

    Parameters
    ----------
    m : array_like, shape (2,)
        The boat's position (east, north), m.
    theta : float
        Its heading, rad counter-clockwise from east.
    psi : float
        The direction the wind blows to, rad counter-clockwise from east.
    a, b : array_like, shape (2,)
        The line, from a to b (east, north), m.
    q : int
        The tack kept so far, -1 or 1.
    gains : LineFollowingGains
        The parameters.

    Returns
    -------
    tuple
        (delta_r, delta_s_max, theta_bar, q): Jaulin's rudder (positive turns clockwise), the
        sheet's largest angle, the heading steered, the tack kept.
    """
    ux, uy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(ux, uy)
    e = (ux * (m[1] - a[1]) - uy * (m[0] - a[0])) / length  # 1
    if abs(e) > gains.r / 2.0:  # 2
        q = 1 if e > 0 else -1
    phi = math.atan2(uy, ux)  # 3
    theta_star = phi - 2.0 * gains.gamma_inf / math.pi * math.atan(e / gains.r)  # 4
    no_go = math.cos(gains.zeta)
    if (math.cos(psi - theta_star) + no_go < 0.0  # 5
            or (abs(e) < gains.r and math.cos(psi - phi) + no_go < 0.0)):  # 6
        theta_bar = math.pi + psi - q * gains.zeta  # 7
    else:
        theta_bar = theta_star  # 8
    error = theta - theta_bar
    if gains.rudder == "sawtooth":
        delta_r = gains.delta_r_max / math.pi * sawtooth(error)  # the book's 10-11
    elif math.cos(error) >= 0.0:  # 10
        delta_r = gains.delta_r_max * math.sin(error)
    else:  # 11
        delta_r = math.copysign(gains.delta_r_max, math.sin(error))
    exponent = math.log(math.pi / (2.0 * gains.beta)) / math.log(2.0)
    delta_s_max = math.pi / 2.0 * ((math.cos(psi - theta_bar) + 1.0) / 2.0) ** exponent  # 12
    return delta_r, delta_s_max, theta_bar, q


def mown(center, half: float, spacing: float, wind_from: float, shift: float = 0.0) -> list:
    """A square mown as a lawn: rows across the wind ``spacing`` apart, from the upwind row down
    (each row a beam reach, each move to the next one downwind: no tack), alternate rows sailed
    either way; the rows' ends as marks. ``shift`` moves every row that far downwind (rows on or
    beyond the square's edge left out): ``spacing`` / 2 lays the rows between the first ones.

    Parameters
    ----------
    center : array_like, shape (2,)
        The square's centre (east, north), m.
    half : float
        Half its side, m.
    spacing : float
        The rows' spacing, m.
    wind_from : float
        The compass bearing the wind comes from, rad.
    shift : float
        The rows' offset downwind, m.
    """
    up = (math.sin(wind_from), math.cos(wind_from))
    across = (math.cos(wind_from), -math.sin(wind_from))
    rows = max(1, int(2.0 * half / spacing))
    marks = []
    for k in range(rows):
        height = half - (k + 0.5) * 2.0 * half / rows - shift
        if abs(height) >= half:
            continue
        ends = [-half + 0.5 * spacing, half - 0.5 * spacing][:: 1 if k % 2 == 0 else -1]
        marks += [(float(center[0]) + height * up[0] + e * across[0],
                   float(center[1]) + height * up[1] + e * across[1]) for e in ends]
    return marks


def _beyond(a, b, m) -> bool:
    """Whether ``m`` lies beyond the line through ``b`` square to a -> b (Jaulin's test)."""
    return (b[0] - a[0]) * (m[0] - b[0]) + (b[1] - a[1]) * (m[1] - b[1]) > 0


class LineFollower:
    """The law sailing a course mark by mark (the mission layer): each leg is the line from the
    last mark (the start for the first) to the next; a mark counts as passed once the boat is
    beyond the line through it square to the leg (dot(b - a, m - b) > 0), Jaulin's own test.

    Parameters
    ----------
    marks : sequence of (float, float), optional
        The marks in order (east, north from the world's origin), m. None: a windward-leeward
        course laid on the first step, a mark ``leg`` metres straight upwind of the start, then
        the start. A course task's ``last_mark`` and ``next_mark`` (in the observation) take
        their place: the task's rules say when a mark counts, and a boat past a mark it has not
        reached sails the leg turned about the mark (from its mirror image) back to it.
    leg : float
        The windward leg's length without ``marks``, m.
    gains : LineFollowingGains
        The law's parameters.

    Notes
    -----
    The package's frames turn into Jaulin's: theta = pi/2 - heading, and psi = -pi/2 -
    wind_direction (the true wind's compass direction, where it comes from, read from
    ``true_state`` as Viel's controller reads it). The rudder is -delta_r (the package's positive
    rudder turns the boat to port); the sail is delta_s_max to leeward (the side of the AWA).
    """

    def __init__(self, marks=None, leg: float = 200.0, gains: LineFollowingGains = LineFollowingGains()):
        self.given = None if marks is None else [tuple(map(float, mark)) for mark in marks]
        self.leg_length, self.gains = float(leg), gains
        self.reset()

    def reset(self, seed: int | None = None) -> None:
        """Back to the course's first leg, on tack q = 1.

        Parameters
        ----------
        seed : int, optional
            Unused (the law is deterministic).
        """
        self.marks, self.a, self.b, self.leg, self.q, self.tacks = self.given, None, None, 0, 1, 0
        self.station = None  # station keeping's two ends and its way out, once laid
        self.square, self.passes = None, 0  # area scanning's square and the passes mown over it

    def _station(self, observation, m, wind_from: float):
        """Station keeping's leg: from the start to the box's centre until the five minutes
        start; then to and fro across the wind through the centre between points ``r`` either
        side of it (a beam reach each way: the boat never stops, as a sailboat cannot); once
        they are over, out of the box 4 ``r`` straight downwind of its centre. The points are
        laid once, to the wind when the five minutes start (a wind that wanders does not move
        them). Sets ``a``; returns the leg's end."""
        c = (float(observation["box_center"][0]), float(observation["box_center"][1]))
        left = float(np.asarray(observation["box_time_left"]).reshape(-1)[0])
        r = self.gains.r
        if left >= STATION_WINDOW:
            self.b = c
            return c
        if self.station is None:
            across = (math.cos(wind_from), -math.sin(wind_from))
            self.station = ((c[0] + r * across[0], c[1] + r * across[1]),
                            (c[0] - r * across[0], c[1] - r * across[1]),
                            (c[0] - 4 * r * math.sin(wind_from), c[1] - 4 * r * math.cos(wind_from)))
            self.a, self.b = self.station[1], self.station[0]
        ends, out = self.station[:2], self.station[2]
        if left <= 0.0:
            if self.b != out:
                self.a, self.b = m, out
        elif _beyond(self.a, self.b, m):
            self.a, self.b = self.b, ends[1] if self.b == ends[0] else ends[0]
        return self.b

    def __call__(self, timestep):
        """[rudder, sail] for this step.

        Parameters
        ----------
        timestep : dm_env.TimeStep
            Its observation's ``position``, ``heading``, ``apparent_wind_angle`` and
            ``true_state["wind_direction"]``.
        """
        observation = timestep.observation
        m = (float(observation["position"][0]), float(observation["position"][1]))
        wind_from = float(observation["true_state"]["wind_direction"])
        if self.a is None:
            self.a = m
            if "area_center" in observation:  # area scanning: the square mown row by row
                self.square = ((float(observation["area_center"][0]), float(observation["area_center"][1])),
                               float(np.ravel(observation["area_half"])[0]), self.gains.r / 2.0, wind_from)
                self.marks = mown(*self.square)
            elif self.marks is None:
                self.marks = [(m[0] + self.leg_length * math.sin(wind_from),
                               m[1] + self.leg_length * math.cos(wind_from)), m]
        if "box_center" in observation:  # station keeping: to the box, across it and back, out
            b = self._station(observation, m, wind_from)
        elif "next_mark" in observation:  # a course task's legs: its rules say when a mark counts
            b = (float(observation["next_mark"][0]), float(observation["next_mark"][1]))
            if b != self.b:
                self.a, self.b = (float(observation["last_mark"][0]), float(observation["last_mark"][1])), b
            elif _beyond(self.a, b, m):  # past the mark without reaching it: the leg turned about it
                self.a = (2.0 * b[0] - self.a[0], 2.0 * b[1] - self.a[1])
        else:
            b = self.marks[self.leg]
            if _beyond(self.a, b, m) and self.leg < len(self.marks) - 1:
                self.a, self.leg = b, self.leg + 1
                b = self.marks[self.leg]
            elif _beyond(self.a, b, m) and self.square is not None:  # mown: again, the other way,
                self.passes += 1  # every other pass between the first pass's rows
                marks = mown(*self.square, shift=self.square[2] / 2.0 if self.passes % 2 else 0.0)
                self.marks = marks[::-1] if self.passes % 2 else marks
                self.a, self.leg = b, 0
                b = self.marks[0]
        theta = math.pi / 2.0 - float(observation["heading"])
        psi = -math.pi / 2.0 - wind_from
        delta_r, delta_s, _, q = line_following(m, theta, psi, self.a, b, self.q, self.gains)
        self.tacks += q != self.q
        self.q = q
        sail = math.copysign(delta_s, float(observation["apparent_wind_angle"]))
        return [-delta_r, sail]
