"""Wille, Hassani & Sprenger (2016a) §4, Figs. 4-5 and Table 2: heading vs course controller.

Close-hauled: U10 = 5 m/s, wind beta_w = 130 deg (Wille's angle, where the wind blows *to*: it
comes from 310 deg, 50 deg off the port bow), no current, desired course 0 deg (north), 200 s.
Rudder: the feedback-linearising heading law (eqs. 46-51, K_p = 3e5, K_d = 1e6) or the course
law (eqs. 52-59) that adds the drift correction beta_b; sail: the lambda_100 law of Wille
(2016b) with the true wind (``wille_heading`` / ``wille_course``). Gusts (NORSOK) and direction
wander on, as in the paper. The seed draws the gusts' phases and frequencies, the wander and the
start heading (within +-5 deg of north, at 2 m/s); every run of one seed, in both worlds and with
either law, sails the same realisation, so the laws and the worlds are compared seed by seed.
Table 2's error is |atan(x/y)|; the paper calls x the distance north and y east, but its x is
the small one (32.9 m): x is the cross-track (east) distance, y the distance sailed north.

Control rate: the paper's laws are continuous (no rate given). At the suite's 10 Hz the
K_d = 1e6 yaw-rate loop (time constant (I_zz - N_rdot)/K_d ~ 0.01 s, twenty times faster than
the 0.2 s rudder lag) sits in a +-20 deg rudder limit cycle; at 50 Hz it is quiet in the paper
world. The headline runs use 50 Hz; 10 Hz is a switch in the report.

Seeds: the four headline runs (two laws, two worlds) run on each of the study's N seeds; the
switches, which show the causes of the differences, run on seed 0 alone (the budget: a 6-DOF
switch costs as much as a 6-DOF headline run).
"""

from __future__ import annotations

import math

from sailmujoco.controllers.base import Composite
from sailmujoco.controllers.wille import WilleHeading
from sailmujoco.controllers.wille_roll import WilleRollSail

from sailmujoco import suite, sweep
from sailmujoco.study import Runs

from ..kit.wille import make_env

NAME = "wille_course_table2"
TITLE = "Wille (2016a) §4, Table 2 and Figs. 4-5: heading vs course controller, close-hauled"
WORLDS = {"paper": "paper (4-DOF)", "mujoco": "MuJoCo (6-DOF)"}
CONTROL_TIMESTEP = 0.02  # s, 50 Hz (see the module docstring)
# the scenario `sailmujoco study wille_course_table2 --video` films
VIDEO = {"boat": "wille_yacht", "task": "course_hold", "controller": "wille_course",
         "seconds": 60.0, "camera": "top", "control_timestep": CONTROL_TIMESTEP}
DURATION = 200.0  # s, §4
PAPER_WIND = (5.0, 130.0)  # §4: U10 [m/s] and beta_w [deg], the direction the wind blows to
SMOKE_DURATION = 30.0  # s
PAPER_TABLE2 = {  # Table 2: x = east (cross-track, m), y = north (m), error (deg)
    "heading": {"east": 32.9, "north": 583.1, "error_deg": 3.23},
    "course": {"east": -2.15, "north": 543.7, "error_deg": 0.22},
}
PAPER_REDUCTION = 0.93  # §4: "reducing the error of roughly 93%"
PAPER_SPEED = 2.7  # m/s, the paper's boat speed on this course (543.7 m north in 200 s)
SAIL_FACTOR = 1.5  # the sail-force switch (see wille_roll_table1: our sim-1 surge = the paper's)
SEEDS = 6  # N: the most the study's budget (2.5 x one seed of every run) affords, see simulated_seconds
SWITCH_SEEDS = (0,)  # the seeds the switches run on
COST = {"mujoco": 1.0, "paper": 0.2}  # the budget's weight of a simulated second, per world
LAWS = {"heading": "heading controller", "course": "course controller",
        "course_sail_only": "course controller, F_U = -S_y' only"}
# the four differences of the boat as built switched back to the papers' forms
PAPER_FORMS = {"resistance": "friction", "foils": "paper", "keel_downwash": False, "windage": False}


class CourseSailForceOnly(WilleHeading):
    """The course law with eq. 57's F_U = -S_y' only (the rudder's side force R_y' left out):
    the switch for the rudder-force feedback of the course correction (see the report)."""

    def correction(self, s: dict) -> float:
        """The drift correction beta_b (rad) with the rudder's side force set to zero.

        Parameters
        ----------
        s : dict
            The state the course law reads (:meth:`WilleHeading.correction`).

        Returns
        -------
        float
            beta_b (rad).
        """
        return super().correction({**s, "Y_rudder": 0.0})


def _controller(env, law: str):
    if law in ("heading", "course"):
        return sweep.make_controller("wille_heading" if law == "heading" else "wille_course", env)
    params = env.physics.params
    return Composite(CourseSailForceOnly(params, course=True), WilleRollSail(params, roll_control=False))


def simulate(job: dict) -> dict:
    """One close-hauled run; returns the task metrics and a 10 Hz trajectory.

    Parameters
    ----------
    job : dict
        ``world``, ``law`` (a key of :data:`LAWS`), ``dt`` (the control period, s) and
        ``duration`` (s); optional ``seed`` (the gusts, wander and start heading; 0 if not
        given), ``sail_factor`` and ``env`` (more options of
        :func:`studies.kit.wille.make_env`).

    Returns
    -------
    dict
        ``metrics`` (the task's) and ``trajectory`` (a DataFrame at 10 Hz).
    """
    env = make_env("course_hold", job["world"], seed=job.get("seed", 0), control_timestep=job["dt"],
                   sail_factor=job.get("sail_factor", 1.0), time_limit=job["duration"], **job.get("env", {}))
    controller = _controller(env, job["law"])
    every = max(1, int(round(0.1 / job["dt"])))

    def row(step, timestep, action):
        if step % every:
            return None
        obs = timestep.observation
        ts = obs["true_state"]
        ve, vn = obs["velocity"]
        return {"t": float(ts["time"]), "east": float(obs["position"][0]), "north": float(obs["position"][1]),
                "course_deg": math.degrees(math.atan2(ve, vn)),
                "heading_deg": math.degrees(math.remainder(float(obs["heading"]), 2 * math.pi)),
                "rudder_deg": math.degrees(float(ts["rudder"])), "u": float(ts["u"]),
                "heel_deg": math.degrees(float(obs["heel"])),
                "beta_b_deg": math.degrees(getattr(controller.rudder, "last_beta_b", 0.0))}

    trajectory = suite.rollout(env, controller, record=row)
    return {"metrics": env.task.metrics(), "trajectory": trajectory}


def jobs_for(smoke: bool, seeds: tuple = (0,)) -> list[dict]:
    """The runs: both controllers in both worlds on every seed, and (full mode) the switches on
    the seeds of :data:`SWITCH_SEEDS` that are run.

    Parameters
    ----------
    smoke : bool
        The short pass: the four headline runs of each seed only, of :data:`SMOKE_DURATION` s.
    seeds : tuple of int
        The seeds (:attr:`sailmujoco.study.Results.seeds`).

    Returns
    -------
    list of dict
        The jobs of :func:`simulate`, each with its ``key`` (case, world, law, seed) and
        ``seed``, longest first.
    """
    duration = SMOKE_DURATION if smoke else DURATION
    seeds = tuple(int(s) for s in seeds)

    def job(case, world, law, seed, dt=CONTROL_TIMESTEP, **more):
        return dict(key=(case, world, law, seed), world=world, law=law, seed=seed, dt=dt, duration=duration,
                    **more)

    jobs = [job("main", world, law, seed) for seed in seeds for world in WORLDS for law in ("heading", "course")]
    if smoke:
        return jobs
    for seed in (s for s in SWITCH_SEEDS if s in seeds):
        for world in WORLDS:
            for law in ("heading", "course"):  # the control-rate switch
                jobs.append(job("10 Hz", world, law, seed, dt=0.1))
            jobs.append(job("F_U = -S_y'", world, "course_sail_only", seed))
        for law in ("heading", "course"):  # the boat as built switched back to the papers' forms, 6-DOF
            jobs.append(job("paper forms", "mujoco", law, seed, env=PAPER_FORMS))
        for law in ("heading", "course_sail_only"):  # the sail-force switch, paper world
            jobs.append(job(f"sail x{SAIL_FACTOR:g}", "paper", law, seed, sail_factor=SAIL_FACTOR))
    # longest first (the paper world at 50 Hz), for the worker pool
    return sorted(jobs, key=lambda j: (j["world"] != "paper", j["dt"] != CONTROL_TIMESTEP))


def simulated_seconds(jobs: list[dict]) -> float:
    """What the runs cost: their simulated seconds, weighted by :data:`COST` (a 6-DOF second 1,
    a paper-world second 0.2).

    Parameters
    ----------
    jobs : list of dict
        Jobs of :func:`jobs_for`.

    Returns
    -------
    float
        The weighted simulated seconds.
    """
    return float(sum(COST[j["world"]] * j["duration"] for j in jobs))


def runs(smoke: bool, seeds: tuple = (0,)) -> Runs:
    """The study's simulations: the jobs of :func:`jobs_for`, stored under ``jobs/<NAME>``.

    Parameters
    ----------
    smoke : bool
        The short pass.
    seeds : tuple of int
        The seeds every headline run is run on.

    Returns
    -------
    sailmujoco.study.Runs
        One job list, named :data:`NAME`.
    """
    return Runs(jobs={NAME: (f"{__name__}:simulate", jobs_for(smoke, seeds))})
