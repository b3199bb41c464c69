"""The numbers of the Fig. 6 study: the segment means of every trial, the S/Bm ratios."""

from __future__ import annotations

from dataclasses import dataclass

import pandas as pd

from sailmujoco.study import Results

from ..kit.saoud import WORLDS
from .scenario import ANGLES_DEG, JOBS, SEGMENTS, Case, cases, l_phis_for

WINDOW = 10.0  # s, the end of each segment over which the means are taken
HELD_DEG = 20.0  # deg, a segment whose mean |heading| exceeds this did not hold heading 0
SERIES_COLUMNS = list(Case._fields) + ["t", "speed", "u", "heel_deg", "heading_deg", "sail_deg",
                                       "rudder_deg", "awa_deg"]


@dataclass(frozen=True)
class Analysis:
    """What the trials gave.

    Parameters
    ----------
    l_phis : tuple of float
        The metacentric heights of the main runs [m].
    checks : list of Case
        The check runs (one switch each).
    stats : dict
        :func:`segment_stats` of every :class:`~.scenario.Case` run.
    series : pandas.DataFrame
        Every run's time series (10 Hz), its case's fields in the first columns.
    numbers : dict
        The headline numbers (speeds, S/Bm ratios, heading held, checks' speeds).
    wall_s : float
        Wall time of the simulations [s].
    """

    l_phis: tuple
    checks: list
    stats: dict
    series: pd.DataFrame
    numbers: dict
    wall_s: float


def segment_stats(series: pd.DataFrame) -> dict:
    """Means over the last ``WINDOW`` s of each segment (nan where the run stopped before).

    Parameters
    ----------
    series : pandas.DataFrame
        One trial's time series (:func:`~.scenario.episode`).
    """
    out = {"stopped": series.attrs.get("stopped"), "end": float(series["t"].iloc[-1])}
    for _, angle, end in SEGMENTS:
        w = series[(series["t"] >= end - WINDOW - 1e-9) & (series["t"] <= end + 1e-9)]
        finished = out["end"] >= end - 1e-6
        for name, column in (("speed", "speed"), ("heel", "heel_deg"), ("heading", "heading_deg")):
            out[f"{name}_{angle:g}"] = float(w[column].mean()) if finished else float("nan")
        out[f"rudder_{angle:g}"] = float(w["rudder_deg"].abs().mean()) if finished else float("nan")
        out[f"max_heading_{angle:g}"] = float(series[(series["t"] <= end)]["heading_deg"].abs().max())
        out[f"held_{angle:g}"] = bool(finished and abs(out[f"heading_{angle:g}"]) <= HELD_DEG)
    return out


def variant(case: Case) -> str:
    """The switches of a case that differ from the main runs, as 'name=value' joined by ','.

    Parameters
    ----------
    case : Case
        A run.
    """
    base = Case(case.world, case.l_phi, case.law)
    diff = [f"{f}={getattr(case, f)}" for f in Case._fields[3:] if getattr(case, f) != getattr(base, f)]
    return ",".join(diff) or "as run"


def _numbers(stats: dict, l_phis, checks) -> dict:
    numbers = {}
    for world in WORLDS:
        for l_phi in l_phis:
            s, b = stats[Case(world, l_phi, "S")], stats[Case(world, l_phi, "Bm")]
            for a in ANGLES_DEG:
                key = f"{world}_lphi{l_phi:g}_{a:g}"
                numbers[f"speed_S_{key}"] = s[f"speed_{a:g}"]
                numbers[f"speed_Bm_{key}"] = b[f"speed_{a:g}"]
                numbers[f"ratio_{key}"] = s[f"speed_{a:g}"] / b[f"speed_{a:g}"]
                numbers[f"held_{key}"] = s[f"held_{a:g}"] and b[f"held_{a:g}"]
    for case in checks:
        tag = f"{case.world}_{variant(case)}_{case.law}"
        for a in ANGLES_DEG:
            numbers[f"check_{tag}_{a:g}"] = stats[case][f"speed_{a:g}"]
            numbers[f"check_held_{tag}_{a:g}"] = stats[case][f"held_{a:g}"]
    return numbers


def analyse(results: Results, smoke: bool) -> Analysis:
    """The segment means of every trial and the headline numbers.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The trials' results (the job list of :func:`~.scenario.runs`).
    smoke : bool
        The short pass.
    """
    l_phis = l_phis_for(smoke)
    main, checks = cases(l_phis)
    stats, frames = {}, []
    for case, result in zip(main + checks, results.jobs[JOBS], strict=True):
        series = result["series"]
        series.attrs["stopped"] = result["stopped"]
        stats[case] = segment_stats(series)
        frames.append(series.assign(**case._asdict()))
    series = pd.concat(frames, ignore_index=True)[SERIES_COLUMNS]
    return Analysis(l_phis, checks, stats, series, _numbers(stats, l_phis, checks), results.seconds)


def headline(analysis: Analysis) -> dict:
    """The headline numbers, and the simulations' wall time.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {**analysis.numbers, "wall_s": analysis.wall_s}
