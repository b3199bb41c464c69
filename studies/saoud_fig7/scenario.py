"""Saoud et al. (2015) Fig. 7, the scenario: maximum (steady) velocity against the relative wind angle, for the
optimal sail S (φ_max = 30°), Briere's Bm and the brute-force vel_max.

Fig. 7 plots "the maximum velocity that can be reached by the sailboat as function of ∠v_w^B,
the relative angle between the heading and the true wind, when |v_w| is 4 m/s"; vel_max "is
obtained by simulating the system with every possible sail configuration for each wind
condition". Here every point is a ``heading_hold`` run on heading 0 in a steady wind (no gusts,
no wander; the start heading as the seed draws it, see Seeds below); its speed is the mean speed over ground at the end of the run
(``steady_speed``). vel_max is the fastest of a grid of fixed sail angles set to leeward
(``fixed_sail``, run on the sweep engine, :func:`sailmujoco.design.polar.polar_spec`); S and Bm are the
same laws as in the Fig. 6 study (fed Saoud's V, see there).

Angle convention. ∠v_w^B is Saoud's (§VII-B, NWU body frame): the direction the true wind
blows *to*, counter-clockwise from the bow, so 0° is a dead run and 180° head to wind (Fig. 6
calls 10° "downwind" and 80° "upwind"). ``heading_hold`` takes the compass bearing the wind
comes *from*: on heading 0, ``wind_from_deg = 180° - ∠v_w^B`` (the same conversion as the
``speed_trial`` task); positive angles put the wind on the starboard side, and the laws are
symmetric. The axis range of Fig. 7 is lost in both text extractions; we plot 0-180°, the
range of the paper's other angle plots (Figs. 3-5 in 001), and mark the no-go zone.

Seeds. The wind is steady and the paper's start fixed; each seed draws the start heading within a
few degrees of 0 (the method line gives the width). S, Bm and the checks sail every angle on
every seed. vel_max is a search: the coarse grid of fixed sails runs on seed 0 and picks, per
angle, the best coarse sail c; c and c ± the refinement then sail on every seed, and a seed's
vel_max is the fastest of those three on that seed, so S/vel_max and S/Bm are compared seed by
seed.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
import pandas as pd

from sailmujoco.design import polar
from sailmujoco.study import Results, Runs

from ..kit import run_episode
from ..kit.saoud import (
    BOAT,
    HEADING_JITTER_DEG,
    L_PHI,
    WORLDS,
    briere_law,
    saoud_law,
    saoud_law_ce,
    saoud_law_masthead,
    saoud_law_unlimited,
    wind_speed_10,
)

NAME = "saoud_fig7"
TITLE = "Saoud (2015) Fig. 7: maximum velocity vs relative wind angle, S vs Bm vs vel_max"
# the scenario `sailmujoco study saoud_fig7 --video` films
VIDEO = {"boat": "saoud_robot", "task": "heading_hold", "controller": "saoud", "seconds": 40.0,
         "wind_speed": 5.82, "wind_from_deg": 100.0, "gusts": False, "wander": False}
ANGLES_DEG = tuple(float(a) for a in range(0, 181, 15))  # ∠v_w^B
COARSE_SAIL_DEG = tuple(float(s) for s in range(10, 91, 10))  # vel_max grid, first pass
REFINE_DEG = 5.0  # second pass: the best coarse sail +- this
DURATION = 30.0  # s per run
STEADY = 10.0  # s, the steady-speed window at the end of each run
SMOKE = {"angles": (45.0, 90.0), "sails": (20.0, 40.0, 60.0, 80.0), "refine": 10.0,
         "duration": 25.0, "l_phi": (0.1,)}
LAWS = {  # name: (controller factory, extra suite.load options)
    "S": (saoud_law, {}), "Bm": (briere_law, {}),
    # checks (switches): the roll limit, the wind sensor, the 6-DOF righting moment
    "S_no_limit": (saoud_law_unlimited, {}), "S_masthead": (saoud_law_masthead, {}),
    "S_ce": (saoud_law_ce, {}),
    "S_eq4": (saoud_law, {"hydrostatics": "paper"}), "Bm_eq4": (briere_law, {"hydrostatics": "paper"}),
}
CHECKS = {"paper": ("S_no_limit", "S_masthead", "S_ce"), "mujoco": ("S_eq4", "Bm_eq4")}  # l_φ = 0.1
JOBS = "fig7_laws"  # the job list of S, Bm and the checks (its store: jobs/fig7_laws)
# N: the seeds of the full pass. Three decide the paired S/vel_max and S/Bm claims at nearly
# every angle (the spread over seeds is far below the margins) within the study's budget: the
# coarse grid runs once, the three candidate sails, S, Bm and the checks on every seed.
SEEDS = 3


class Settings(NamedTuple):
    """The grid and durations of a pass: angles ∠v_w^B [deg], the coarse fixed sails [deg], the
    refinement ± [deg], seconds per run, the metacentric heights [m]."""

    angles: tuple
    sails: tuple
    refine: float
    duration: float
    l_phis: tuple


def settings(smoke: bool) -> Settings:
    """The full grid, or the reduced one of the smoke pass.

    Parameters
    ----------
    smoke : bool
        The short pass.
    """
    if smoke:
        return Settings(SMOKE["angles"], SMOKE["sails"], SMOKE["refine"], SMOKE["duration"], SMOKE["l_phi"])
    return Settings(ANGLES_DEG, COARSE_SAIL_DEG, REFINE_DEG, DURATION, L_PHI)


def wind_from_deg(angle_deg: float) -> float:
    """heading_hold's ``wind_from_deg`` (compass, where the wind comes from) on heading 0 for
    Saoud's ∠v_w^B (where it blows to, counter-clockwise from the bow), degrees.

    Parameters
    ----------
    angle_deg : float
        ∠v_w^B [deg].
    """
    return 180.0 - angle_deg


def angle_from_wind_from(wind_from: float) -> float:
    """Inverse of :func:`wind_from_deg`.

    Parameters
    ----------
    wind_from : float or array
        heading_hold's ``wind_from_deg`` [deg].
    """
    return 180.0 - wind_from


# ----------------------------------------------------------------------------- vel_max
def grid_spec(world: str, rows: list[tuple], duration: float, seeds=(0,)) -> dict:
    """A fixed-sail sweep over zipped (angle, sail_deg, l_phi) rows, on heading 0, each row on
    every seed of ``seeds``.

    Parameters
    ----------
    world : str
        "paper" or "mujoco".
    rows : list of tuple
        (∠v_w^B [deg], sail angle [deg], l_φ [m]) of each run.
    duration : float
        Seconds per run.
    seeds : sequence of int
        The seeds (each draws the start heading).
    """
    angles, sails, l_phis = (list(x) for x in zip(*rows, strict=True))
    spec = polar.polar_spec(BOAT, "fixed_sail", [wind_speed_10()], [wind_from_deg(angles[0])],
                            world=world, duration=duration, steady_window=STEADY,
                            options={"task.heading_jitter_deg": HEADING_JITTER_DEG})
    spec["seeds"] = [int(seed) for seed in seeds]
    spec["name"] = f"{NAME}-velmax-{world}"
    spec["metrics"] = ["steady_speed", "steady_heel", "heading_error_rms"]
    spec["zip"] = {"task.wind_speed": [wind_speed_10()] * len(rows),
                   "task.wind_from_deg": [wind_from_deg(a) for a in angles],
                   "controller.sail_deg": sails, "boat.l_phi": l_phis}
    return spec


def tidy(table: pd.DataFrame, world: str) -> pd.DataFrame:
    """A vel_max sweep's table with the study's column names, its angle ∠v_w^B and world.

    Parameters
    ----------
    table : pandas.DataFrame
        The sweep's table (:func:`sailmujoco.sweep.run`).
    world : str
        Its world.
    """
    table = table.rename(columns={"task.wind_from_deg": "wind_from", "boat.l_phi": "l_phi",
                                  "controller.sail_deg": "sail_deg", "steady_speed": "speed",
                                  "steady_heel": "heel"})
    table["angle"] = angle_from_wind_from(table["wind_from"])
    table["world"] = world
    if "seed" not in table:
        table["seed"] = 0
    return table


def best_of(grid: pd.DataFrame, max_heel_deg: float | None = None, by_seed: bool = False) -> pd.DataFrame:
    """The fastest finished run per (world, l_φ, angle), optionally among |heel| <= max_heel,
    on seed 0 (the search) or on every seed (``by_seed``: the fastest of each seed's runs).

    Parameters
    ----------
    grid : pandas.DataFrame
        Tidy vel_max runs (:func:`tidy`).
    max_heel_deg : float, optional
        Only runs heeling at most this [deg].
    by_seed : bool
        One row per seed; otherwise seed 0's runs alone.
    """
    ok = grid[grid["status"] == "ok"]
    if not by_seed:
        ok = ok[ok["seed"] == 0]
    if max_heel_deg is not None:
        ok = ok[np.degrees(ok["heel"].abs()) <= max_heel_deg]
    keys = ["world", "l_phi", "angle"] + (["seed"] if by_seed else [])
    idx = ok.groupby(keys)["speed"].idxmax()
    best = ok.loc[idx, keys + ["speed", "heel", "sail_deg", "heading_error_rms"]]
    return best.sort_values(keys).reset_index(drop=True)


# ----------------------------------------------------------------------------- S and Bm
def law_run(world: str, l_phi: float, law: str, angle: float, duration: float, seed: int = 0) -> dict:
    """One steady heading-hold run of a sail law of ``LAWS`` (in a worker process).

    Parameters
    ----------
    world : str
        "paper" or "mujoco".
    l_phi : float
        Metacentric height [m].
    law : str
        A name of ``LAWS``.
    angle : float
        ∠v_w^B [deg].
    duration : float
        Seconds of the run.
    seed : int
        Draws the start heading (within ±``HEADING_JITTER_DEG``).
    """
    factory, options = LAWS[law]
    metrics, frame, _ = run_episode(BOAT, "heading_hold", world, factory, seed=int(seed),
                                    boat_options={"l_phi": l_phi}, time_limit=duration,
                                    wind_speed=wind_speed_10(), wind_from_deg=wind_from_deg(angle),
                                    gusts=False, wander=False, heading_jitter_deg=HEADING_JITTER_DEG,
                                    desired_heading_deg=0.0, steady_window=STEADY, **options)
    stopped = metrics.get("stopped")
    return {"world": world, "l_phi": l_phi, "law": law, "angle": angle, "seed": int(seed),
            "speed": float("nan") if stopped else metrics["steady_speed"],
            "heel": float("nan") if stopped else metrics["steady_heel"],
            "heading_error_rms": metrics.get("heading_error_rms", float("nan")),
            "sail_deg": float(np.degrees(np.abs(frame["sail"].iloc[-int(STEADY * 10):]).mean())),
            "stopped": stopped}


def law_runs(rows: list[dict]) -> pd.DataFrame:
    """The rows of ``law_run`` as a table, sorted.

    Parameters
    ----------
    rows : list of dict
        :func:`law_run`'s results.
    """
    return pd.DataFrame(rows).sort_values(["world", "l_phi", "law", "angle", "seed"]).reset_index(drop=True)


def law_run_job(job: dict) -> dict:
    """:func:`law_run` of ``job``'s keywords (a job of the sweep engine).

    Parameters
    ----------
    job : dict
        :func:`law_run`'s keywords.
    """
    return law_run(**job)


def runs(smoke: bool, seeds=(0,)) -> Runs:
    """The first pass: the coarse vel_max grid of each world (seed 0: the search), and S, Bm and
    the checks on every seed.

    Parameters
    ----------
    smoke : bool
        The short pass (reduced grid, no checks).
    seeds : sequence of int
        The seeds every law runs on.
    """
    angles, sails, _, duration, l_phis = settings(smoke)
    jobs = [(w, lp, law, a, duration) for w in WORLDS for lp in l_phis for law in ("S", "Bm")
            for a in angles]
    if not smoke:
        jobs += [(w, 0.1, law, a, duration) for w, names in CHECKS.items() for law in names for a in angles]
    jobs = [dict(world=w, l_phi=lp, law=law, angle=a, duration=d, seed=int(seed))
            for w, lp, law, a, d in jobs for seed in seeds]
    coarse = [(a, s, lp) for lp in l_phis for a in angles for s in sails]
    return Runs(sweeps=tuple((grid_spec(w, coarse, duration), f"sweep-velmax-{w}/coarse") for w in WORLDS),
                jobs={JOBS: (f"{__name__}:law_run_job", jobs)}, label=f"{NAME} coarse grid and laws")


def more_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: in each world, per angle, the best coarse sail c ± the refinement on every
    seed, and c itself on the seeds after 0 (seed 0 ran it in the coarse grid).

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass's results (``results.seeds``: the seeds).
    smoke : bool
        The short pass.
    """
    _, sails, refine, duration, _ = settings(smoke)
    seeds = [int(s) for s in results.seeds]
    sweeps = []
    for world in WORLDS:
        first = best_of(tidy(results.sweeps[f"sweep-velmax-{world}/coarse"], world))
        finer = [(r.angle, r.sail_deg + d, r.l_phi) for r in first.itertuples()
                 for d in (-refine, refine) if 0.0 < r.sail_deg + d <= 180.0 and r.sail_deg + d not in sails]
        if finer:
            sweeps.append((grid_spec(world, finer, duration, seeds), f"sweep-velmax-{world}/finer"))
        if seeds[1:]:
            best = [(r.angle, r.sail_deg, r.l_phi) for r in first.itertuples()]
            sweeps.append((grid_spec(world, best, duration, seeds[1:]), f"sweep-velmax-{world}/best"))
    return Runs(sweeps=tuple(sweeps), label=f"{NAME} candidate sails on every seed")
