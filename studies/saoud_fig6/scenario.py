"""Saoud et al. (2015) Fig. 6: boat speed and roll over time, optimal sail S against Briere's Bm.

Scenario (§VII-B): a true wind of 4 m/s whose angle in the body frame, ∠v_w^B (Saoud's NWU:
the direction the wind blows *to*, counter-clockwise from the bow), is 10°, 45° and 80° over
0-20, 20-40 and 40-60 s, while a heading controller holds a zero heading: the ``speed_trial``
task (the boat heads north, so the wind comes *from* compass 180° - ∠v_w^B = 170°, 135°, 100°).
S is Saoud's optimal sail (problem 14, φ_max = 30°), Bm the IBOAT trimming of Fig. 5; the
rudder is the same PID for both. Each law runs in both worlds: "paper" (Wille's 4-DOF
equations with the saoud_robot numbers) and "mujoco" (the 6-DOF robot), for both metacentric
heights of the paper, l_φ = 0.1 m and 1 m.

The paper prints no number for Fig. 6, only the sentence "both methods perform equally when
sailing downwind (t ∈ [0, 20]) but the gain on velocity appears when sailing beam reach
(t ∈ [20, 40]) and even more when sailing upwind (t ∈ [40, 60])"; the axis ranges of the plot
are lost in both text extractions. The report compares that sentence with the S/Bm ratio of
the mean speeds over the last 10 s of each segment.

The paper's wind is steady and its start fixed; every trial here runs on each seed, which draws
the start heading within a few degrees of 0 (the method line gives the width), and S and Bm are
compared seed by seed.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import pandas as pd

from sailmujoco.jit.ordered import elementwise
from sailmujoco.study import Runs
from sailmujoco.tasks.sailing import SpeedTrial

from ..kit import run_episode
from ..kit.saoud import (
    BOAT,
    HEADING_JITTER_DEG,
    L_PHI,
    PHI_MAX_DEG,
    TRUE_WIND,
    WIND_SOURCE,
    WORLDS,
    briere_law,
    briere_law_ce,
    briere_law_masthead,
    saoud_law,
    saoud_law_ce,
    saoud_law_masthead,
    wind_speed_10,
)


def _wrapped(heading: float) -> float:
    """The heading in (-pi, pi], rad, from the C library (numpy's SIMD atan2 varies by CPU)."""
    return math.atan2(math.sin(heading), math.cos(heading))

NAME = "saoud_fig6"
TITLE = "Saoud (2015) Fig. 6: speed and roll over time, optimal sail S vs Briere's Bm"
# the scenario `sailmujoco study saoud_fig6 --video` films
VIDEO = {"boat": "saoud_robot", "task": "speed_trial", "controller": "saoud", "seconds": 60.0,
         "boat_options": {"l_phi": 1.0}}
WORLD_NAMES = {"paper": "paper world (4-DOF reduced model)", "mujoco": "MuJoCo 6-DOF"}
SEGMENTS = tuple((start, angle, end) for (start, angle), end in
                 zip(SpeedTrial.segments, [t for t, _ in SpeedTrial.segments[1:]] + [SpeedTrial.duration],
                     strict=True))
ANGLES_DEG = tuple(a for _, a, _ in SEGMENTS)  # ∠v_w^B of the three segments
LAWS = {"S": f"Saoud optimal sail, $\\phi_{{max}}$ = {PHI_MAX_DEG:g}°", "Bm": "Briere/IBOAT trimming (Fig. 5)"}
FACTORIES = {("S", "saoud_v"): saoud_law, ("Bm", "saoud_v"): briere_law,
             ("S", "ce"): saoud_law_ce, ("Bm", "ce"): briere_law_ce,
             ("S", "masthead"): saoud_law_masthead, ("Bm", "masthead"): briere_law_masthead}
JOBS = "fig6_trials"  # the job list's name (its store: jobs/fig6_trials)
# N: the seeds of the full pass. Every trial runs on each; five decide the paired S/Bm claims
# wherever both laws hold heading 0 (the spread over seeds is far below the gains), and cost
# 5 x 528 simulated seconds (6-DOF 1 per second, paper world 0.2).
SEEDS = 5


class Case(NamedTuple):
    """One speed trial: world, l_φ [m], law, wind sensor and the modelling switches."""

    world: str
    l_phi: float
    law: str
    sensor: str = WIND_SOURCE
    hydrostatics: str = "geometric"  # 6-DOF restoring: "geometric" hull or Saoud eq. 4 ("paper")
    paper_model: str = "paper"  # paper world: eqs. 3-4 as printed, or "rigid" (heel -> yaw)
    wind_at: str = "ce"  # where the true wind blows TRUE_WIND: at the sail's CE, or at "10m"


CHECKS = ({"sensor": "ce"}, {"sensor": "masthead"}, {"wind_at": "10m"}, {"wind_at": "10m", "sensor": "ce"},
          {"paper_model": "rigid"})  # switched in the paper world at l_φ = 0.1 m (and one 6-DOF switch)


def l_phis_for(smoke: bool) -> tuple:
    """The metacentric heights run [m]: both of the paper's, l_φ = 0.1 m alone in smoke mode.

    Parameters
    ----------
    smoke : bool
        The short pass.
    """
    return (0.1,) if smoke else L_PHI


def cases(l_phis) -> tuple[list[Case], list[Case]]:
    """The main runs (both worlds and laws at each l_φ) and the checks (one switch each).

    Parameters
    ----------
    l_phis : sequence of float
        The metacentric heights of the main runs [m].
    """
    main = [Case(world, l_phi, law) for l_phi in l_phis for world in WORLDS for law in LAWS]
    checks = [Case("paper", 0.1, law, **switch) for switch in CHECKS for law in LAWS]
    checks += [Case("mujoco", 0.1, law, hydrostatics="paper") for law in LAWS]
    return main, checks


def episode(case: Case, seed: int = 0) -> pd.DataFrame:
    """One speed trial; the time series (10 Hz) in SI and degrees, with the stop reason.

    Parameters
    ----------
    case : Case
        The trial.
    seed : int
        Draws the start heading (within ±``HEADING_JITTER_DEG``).
    """
    metrics, frame, _ = run_episode(BOAT, "speed_trial", case.world, FACTORIES[(case.law, case.sensor)],
                                    seed=seed, boat_options={"l_phi": case.l_phi},
                                    hydrostatics=case.hydrostatics, paper_model=case.paper_model,
                                    wind_speed=wind_speed_10(l_phi=case.l_phi) if case.wind_at == "ce"
                                    else TRUE_WIND, heading_jitter_deg=HEADING_JITTER_DEG)
    series = pd.DataFrame({
        "t": frame["t"], "speed": frame["speed"], "u": frame["u"],
        "heel_deg": np.degrees(frame["heel"]),
        "heading_deg": np.degrees(elementwise(_wrapped, frame["heading"])),
        "sail_deg": np.degrees(frame["sail"]), "rudder_deg": np.degrees(frame["rudder"]),
        "awa_deg": np.degrees(frame["awa"])})
    series.attrs["stopped"] = metrics.get("stopped")
    return series


def episode_job(job: dict) -> dict:
    """:func:`episode` of ``Case(**fields)`` on the job's seed (a job of the sweep engine).

    Parameters
    ----------
    job : dict
        A :class:`Case`'s fields and ``seed``.
    """
    job = dict(job)
    seed = int(job.pop("seed"))
    series = episode(Case(**job), seed)
    return {"series": series, "stopped": series.attrs.get("stopped")}


def jobs(smoke: bool, seeds) -> list[tuple[Case, int]]:
    """Every (trial, seed) run, main runs then checks, each trial on every seed.

    Parameters
    ----------
    smoke : bool
        The short pass (l_φ = 0.1 m only).
    seeds : sequence of int
        The seeds.
    """
    main, checks = cases(l_phis_for(smoke))
    return [(case, int(seed)) for case in main + checks for seed in seeds]


def runs(smoke: bool, seeds=(0,)) -> Runs:
    """Every speed trial on every seed, as one job list.

    Parameters
    ----------
    smoke : bool
        The short pass (l_φ = 0.1 m only).
    seeds : sequence of int
        The seeds every trial runs on.
    """
    items = [{**case._asdict(), "seed": seed} for case, seed in jobs(smoke, seeds)]
    return Runs(jobs={JOBS: (f"{__name__}:episode_job", items)}, label=JOBS)
