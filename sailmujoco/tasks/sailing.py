"""Sailing tasks: hold a heading, hold a course, beam reach in a blow, a speed trial.

Observation (all tasks): the dict of :mod:`sailmujoco.measurement.observation`,

======================  =====  ===================================================
key                     unit   frame / meaning
======================  =====  ===================================================
position                m      world x east, y north (GPS)
velocity                m/s    world east, north (GPS)
heading                 rad    compass, clockwise from north
heel                    rad    positive starboard down
roll_rate, yaw_rate     rad/s  body x, body z (yaw_rate positive turning to port)
apparent_wind_angle     rad    masthead, positive from starboard
apparent_wind_speed     m/s    masthead, body x-y plane
true_state              -      full state for full-state controllers (controllers/base.py)
======================  =====  ===================================================

plus each task's references below. Action: ``[rudder, sail]`` in rad, positive trailing edge
to port (a positive rudder turns the boat to port), bounded by the actuator saturations.
"""

from __future__ import annotations

import math

import numpy as np

from .. import frames
from ..forces.wind import MAX_SPEED, WindConfig
from .base import SailTask, amplitude, check_number, wrap
from .registry import register_task

# the least a hinge angle can be: |rudder| <= pi (rad) bounds the rudder term of heading_hold
_RUDDER_LIMIT = math.pi


def check_wind_speed(value) -> float:
    """A task's ``wind_speed`` (U10, m/s) if it is within the wind's accepted range
    [0, :data:`sailmujoco.forces.wind.MAX_SPEED`]; otherwise a one-line ValueError.

    Parameters
    ----------
    value : float
        The mean true wind at 10 m, m/s.
    """
    return check_number("wind_speed", value, 0.0, MAX_SPEED, unit="m/s")


@register_task
class HeadingHold(SailTask):
    """Hold a compass heading in a steady, gusty wind.

    Reference: ``desired_heading`` (rad, compass). Reward terms: ``heading`` = -(e/pi)^2 with e
    the heading error (in [-1, 0]), ``rudder`` = -0.01 (sigma/0.6)^2 with sigma the rudder
    angle (>= -0.01 (pi/0.6)^2); a step earns at least -1.274. Metrics: ``heading_error_rms`` (rad),
    ``mean_surge`` (m/s), ``heel_amplitude`` (rad), and over the last ``steady_window`` seconds
    ``steady_speed`` (speed over ground, m/s) and ``steady_heel`` (rad): a polar point.

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    desired_heading_deg : float
        Compass heading to hold, degrees clockwise from north.
    wind_speed : float
        Mean true wind at 10 m, U10, m/s, in [0, 100] (:data:`~sailmujoco.forces.wind.MAX_SPEED`).
    wind_from_deg : float
        Compass bearing the wind comes from, degrees.
    gusts, wander : bool
        Gusts in speed, slow wander of the direction (:class:`~sailmujoco.forces.wind.WindConfig`).
    steady_window : float
        Length of the final window the polar point is averaged over, s, > 0.
    diagnostics : bool
        Record the world's diagnostic rows and summarise them (:func:`diagnostic_summary`).
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "heading_hold"
    duration = 60.0

    def __init__(self, seed=None, desired_heading_deg: float = 0.0, wind_speed: float = 6.0,
                 wind_from_deg: float = 80.0, gusts: bool = True, wander: bool = True,
                 steady_window: float = 20.0, diagnostics: bool = False, **kwargs):
        super().__init__(seed, **kwargs)
        self.diagnostics = diagnostics
        self.desired_heading = math.radians(check_number("desired_heading_deg", desired_heading_deg))
        self.wind_speed = check_wind_speed(wind_speed)
        self.wind_from = math.radians(check_number("wind_from_deg", wind_from_deg))
        steady_window = check_number("steady_window", steady_window, 0.0, low_open=True, unit="s")
        self.gusts, self.wander = gusts, wander
        self.steady_window = steady_window

    def wind(self):
        return WindConfig(speed=self.wind_speed, direction_from=self.wind_from, gusts=self.gusts,
                          wander=self.wander, seed=0 if self.seed is None else self.seed)

    def initial_heading(self):
        return self.desired_heading

    def initial_speed(self):
        return 1.0

    def references(self, physics):
        return {"desired_heading": self.desired_heading}

    def reward_terms(self, physics, observation):
        e = wrap(float(observation["heading"]) - self.desired_heading)
        rudder = float(observation["true_state"]["rudder"])
        return {"heading": -(e / math.pi) ** 2, "rudder": -0.01 * (rudder / 0.6) ** 2}

    def reward_floor(self, physics):
        return -1.0 - 0.01 * (_RUDDER_LIMIT / 0.6) ** 2

    def summarise(self, records):
        errors = np.array([wrap(r["heading"] - self.desired_heading) for r in records])
        last = [r for r in records if r["t"] >= records[-1]["t"] - self.steady_window]
        out = {"heading_error_rms": float(np.sqrt(np.mean(errors**2))),
               "mean_surge": float(np.mean([r["surge"] for r in records])),
               "heel_amplitude": amplitude([r["heel"] for r in records]),
               "steady_speed": float(np.mean([r["speed"] for r in last])),
               "steady_heel": float(np.mean([r["heel"] for r in last]))}
        if self.diagnostics and "ct_cn" in records[-1]:
            out.update(diagnostic_summary(last))
        return out

    def record(self, physics) -> dict:
        row = super().record(physics)
        if self.diagnostics:
            row.update(physics.diagnostic_record())
        return row


def diagnostic_summary(rows: list[dict]) -> dict:
    """Steady-window statistics of the world's diagnostic records.

    Parameters
    ----------
    rows : list of dict
        :meth:`~sailmujoco.tasks.world.World.diagnostic_record` rows (with the task's record).

    Returns
    -------
    dict
        Means over the rows of the C_T/C_N ratio, pitch, heave, drift and keel angle of attack,
        amplitudes of pitch and heave, each term's share of the roll moment, and the ratio of
        Saoud's neglected omega_3 term to the restoring moment.
    """
    def mean(key):
        values = np.array([r[key] for r in rows], dtype=float)
        values = values[np.isfinite(values)]
        return float(values.mean()) if values.size else float("nan")

    names = ("sail", "keel", "rudder", "hydrostatics", "damping", "added_mass")  # hydrostatics
    # here means buoyancy + weight, the restoring moment
    magnitude = {n: float(np.mean([abs(r[f"mx_{n}"]) for r in rows])) for n in names}
    total = sum(magnitude.values()) or float("nan")
    return {
        "ct_cn_ratio": mean("ct_cn"),
        "pitch_amplitude": amplitude([r["pitch"] for r in rows]),
        "heave_amplitude": amplitude([r["heave"] for r in rows]),
        "mean_pitch": mean("pitch"), "mean_heave": mean("heave"),
        "drift_angle": mean("drift"),
        "keel_aoa": float(np.mean([abs(r["keel_aoa"]) for r in rows])),
        **{f"roll_share_{n}": magnitude[n] / total for n in names},
        "omega3_ratio": float(np.mean([abs(r["omega3_term"]) for r in rows])
                              / max(np.mean([abs(r["restoring"]) for r in rows]), 1e-9)),
    }


@register_task
class CourseHold(SailTask):
    """Wille (2016a) §4: close-hauled, U10 = 5 m/s, beta_w = 130 deg (from 310 deg), no current,
    desired course 0 (north), 200 s.

    Reference: ``desired_course`` (rad, compass). Reward terms: ``course`` = -(e/pi)^2 with e
    the course-over-ground error (in [-1, 0]). Metrics: ``drift_error`` = ``|atan(x/y)|`` (rad,
    x north, y east: Wille's Table 2 measure), ``course_error_mean`` (rad, mean absolute),
    ``mean_surge`` (m/s), ``north``, ``east`` (m).

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    desired_course_deg : float
        Compass course over ground to hold, degrees clockwise from north.
    wind_speed : float
        Mean true wind at 10 m, U10, m/s, in [0, 100] (:data:`~sailmujoco.forces.wind.MAX_SPEED`).
    beta_w_deg : float
        Wille's beta_w, degrees: the NED bearing the wind blows *towards* (Wille 2016a eq. 42).
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "course_hold"
    duration = 200.0

    def __init__(self, seed=None, desired_course_deg: float = 0.0, wind_speed: float = 5.0,
                 beta_w_deg: float = 130.0, **kwargs):
        super().__init__(seed, **kwargs)
        self.desired_course = math.radians(check_number("desired_course_deg", desired_course_deg))
        self.wind_speed = check_wind_speed(wind_speed)
        beta_w_deg = check_number("beta_w_deg", beta_w_deg)
        self.wind_from = float(frames.direction_from_wille_beta_w(math.radians(beta_w_deg)))

    def wind(self):
        return WindConfig(speed=self.wind_speed, direction_from=self.wind_from,
                          seed=0 if self.seed is None else self.seed)

    def initial_heading(self):
        return self.desired_course

    def initial_speed(self):
        return 2.0

    def references(self, physics):
        return {"desired_course": self.desired_course}

    def reward_terms(self, physics, observation):
        ve, vn = observation["velocity"]
        course = math.atan2(ve, vn)  # compass
        return {"course": -(wrap(course - self.desired_course) / math.pi) ** 2}

    def reward_floor(self, physics):
        return -1.0

    def summarise(self, records):
        east, north = records[-1]["position"] - records[0]["position"]
        along = north * math.cos(self.desired_course) + east * math.sin(self.desired_course)
        across = -north * math.sin(self.desired_course) + east * math.cos(self.desired_course)
        courses = np.array([wrap(frames.heading_from_yaw(r["course"]) - self.desired_course)
                            for r in records if r["speed"] > 0.2])
        return {"drift_error": float(abs(math.atan2(across, along))),
                "course_error_mean": float(np.mean(np.abs(courses))) if courses.size else float("nan"),
                "mean_surge": float(np.mean([r["surge"] for r in records])),
                "north": float(north), "east": float(east)}


@register_task
class BeamReachRoll(SailTask):
    """Wille (2016b) §5: beam reach, U10 = 10 m/s, 300 s, metrics over the last 50 s.

    The boat sails perpendicular to the mean wind (wind from the west, desired heading north:
    wind from port). Reference: ``desired_heading`` (rad). Reward terms: ``speed`` =
    max(u, -U10) / U10 (sternway faster than the wind earns no less than -1; 0 without wind),
    ``heel`` = -(phi / 10 deg)^2 (>= -81 while the boat runs: |phi| > 90 deg is a capsize,
    which ends the episode); a step earns at least -82. Metrics: ``roll_amplitude`` (rad, half peak-to-peak),
    ``max_roll_rate`` (rad/s), ``mean_surge`` (m/s), ``mean_heel`` (rad).

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    wind_speed : float
        Mean true wind at 10 m, U10, m/s, in [0, 100] (:data:`~sailmujoco.forces.wind.MAX_SPEED`).
    desired_heading_deg : float
        Compass heading to hold, degrees; the wind comes from 90 degrees to port of it.
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "beam_reach_roll"
    duration = 300.0
    window = 50.0

    def __init__(self, seed=None, wind_speed: float = 10.0, desired_heading_deg: float = 0.0,
                 **kwargs):
        super().__init__(seed, **kwargs)
        self.wind_speed = check_wind_speed(wind_speed)
        self.desired_heading = math.radians(check_number("desired_heading_deg", desired_heading_deg))

    def wind(self):
        return WindConfig(speed=self.wind_speed, direction_from=self.desired_heading - math.pi / 2,
                          seed=0 if self.seed is None else self.seed)

    def initial_heading(self):
        return self.desired_heading

    def initial_speed(self):
        return 3.0

    def references(self, physics):
        return {"desired_heading": self.desired_heading}

    def reward_terms(self, physics, observation):
        heel = float(observation["heel"])
        u = float(observation["true_state"]["u"])
        speed = max(u, -self.wind_speed) / self.wind_speed if self.wind_speed > 0.0 else 0.0
        return {"speed": speed, "heel": -(heel / math.radians(10.0)) ** 2}

    def reward_floor(self, physics):
        return -1.0 - 81.0

    def summarise(self, records):
        end = records[-1]["t"]
        last = [r for r in records if r["t"] >= end - self.window]
        return {"roll_amplitude": amplitude([r["heel"] for r in last]),
                "max_roll_rate": float(max(abs(r["roll_rate"]) for r in last)),
                "mean_surge": float(np.mean([r["surge"] for r in last])),
                "mean_heel": float(np.mean([r["heel"] for r in last]))}


@register_task
class SpeedTrial(SailTask):
    """Saoud (2015) Fig. 6: true wind 4 m/s whose angle in the body frame (the direction it
    blows *to*, counter-clockwise, Saoud's NWU) is 10, 45 and 80 deg over 0-20, 20-40 and
    40-60 s, heading held at zero (north).

    With the boat heading north, a wind blowing towards +a (ccw) comes from compass
    180 - a: 170, 135 and 100 deg. Reference: ``desired_heading`` = 0. Reward terms:
    ``speed`` = ``|v| / U10`` (>= 0; 0 without wind). Metrics: ``mean_speed_<a>`` (m/s) and
    ``mean_heel_<a>`` (rad) over the last 10 s of each segment, ``max_heel`` (rad).

    Parameters
    ----------
    seed : int, optional
        Seeds the initial-heading jitter and the wind's gusts.
    wind_speed : float
        True wind at 10 m, m/s, in [0, 100] (:data:`~sailmujoco.forces.wind.MAX_SPEED`).
    **kwargs
        Passed to :class:`~sailmujoco.tasks.base.SailTask`: ``heading_jitter_deg``.
    """

    name = "speed_trial"
    duration = 60.0
    segments = ((0.0, 10.0), (20.0, 45.0), (40.0, 80.0))  # (start s, wind angle deg)

    def __init__(self, seed=None, wind_speed: float = 4.0, **kwargs):
        super().__init__(seed, **kwargs)
        self.wind_speed = check_wind_speed(wind_speed)

    @staticmethod
    def wind_from(angle_deg: float) -> float:
        """The compass bearing (rad) a wind blowing towards ``angle_deg`` (ccw, heading north) comes from.

        Parameters
        ----------
        angle_deg : float
            Direction the wind blows to, degrees counter-clockwise from the bow (Saoud's NWU, heading north).
        """
        return math.radians(180.0 - angle_deg)

    def wind(self):
        (_, a0), *rest = self.segments
        return WindConfig(speed=self.wind_speed, direction_from=self.wind_from(a0),
                          gusts=False, wander=False, seed=0 if self.seed is None else self.seed,
                          direction_schedule=tuple((t, self.wind_from(a)) for t, a in rest))

    def initial_heading(self):
        return 0.0

    def initial_speed(self):
        return 0.5

    def references(self, physics):
        return {"desired_heading": 0.0}

    def reward_terms(self, physics, observation):
        speed = math.hypot(*observation["velocity"])
        return {"speed": speed / self.wind_speed if self.wind_speed > 0.0 else 0.0}

    def reward_floor(self, physics):
        return 0.0

    def summarise(self, records):
        out = {"max_heel": float(max(abs(r["heel"]) for r in records))}
        ends = [t for t, _ in self.segments[1:]] + [self.duration]
        for (_start, angle), end in zip(self.segments, ends, strict=True):
            window = [r for r in records if end - 10.0 <= r["t"] <= end + 1e-9]
            if window:
                out[f"mean_speed_{angle:g}"] = float(np.mean([r["speed"] for r in window]))
                out[f"mean_heel_{angle:g}"] = float(np.mean([r["heel"] for r in window]))
        return out
