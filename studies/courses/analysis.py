"""The courses study's numbers: each event's score on each boat and arm over the seeds, the sea
and the instruments against calm water, paired seed by seed, and the switches that name a cause.

A race's score is the finish time of the runs that finished and how many did (a boat that does
not finish has no time); the other events' scores are their rules' points or cells, one per run.
An arm *loses* against "calm, perfect" where fewer of its runs finish, or where the paired
difference's 95 % interval lies wholly on the worse side; it *gains* where the interval lies
wholly on the better side; otherwise no change is shown at N seeds (the interval holds zero). The second pass reruns a case that
loses with each half of the change alone (:data:`.scenario.SWITCHES`); the half that loses as
well names the cause ("both" where each does, "neither alone" where only the two together do).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco import stats
from sailmujoco.study import Results, Runs

from .scenario import (
    BOATS,
    BOOK_RUDDER,
    CONDITIONS,
    JOB,
    MORE_JOB,
    NAME,
    SCORES,
    SWITCHES,
    TASKS,
    job,
    simulate,
)

BASE, HARD = tuple(CONDITIONS)  # "calm, perfect", "sea, typical"


@dataclass
class Analysis:
    """What the report and the figures read.

    Parameters
    ----------
    smoke : bool
        The short pass.
    seeds : tuple of int
        The seeds.
    runs : pandas.DataFrame
        One row per run: boat, task, arm, seed, score, finished, tacks, astern and the metrics.
    summary : pandas.DataFrame
        One row per task, boat and arm: the score over the seeds.
    changes : pandas.DataFrame
        One row per task, boat and arm other than the base: its paired change and verdict.
    causes : pandas.DataFrame
        One row per case that loses in "sea, typical": each switch's verdict and the cause.
    tracks : dict
        (task, boat, arm) -> the first seed's track ([t, x, y] rows) and scene.
    """

    smoke: bool
    seeds: tuple
    runs: pd.DataFrame
    summary: pd.DataFrame
    changes: pd.DataFrame
    causes: pd.DataFrame
    tracks: dict


def run_rows(items: list[dict]) -> pd.DataFrame:
    """One row per run.

    Parameters
    ----------
    items : list of dict
        What :func:`.scenario.simulate` returned.
    """
    rows = []
    for item in items:
        metrics = item["metrics"]
        metric = SCORES[item["task"]][0]
        score = metrics.get(metric)
        rows.append({"task": item["task"], "boat": item["boat"], "arm": item["arm"], "seed": item["seed"],
                     "score": math.nan if score is None else float(score),
                     "finished": int(metrics.get("finished", 1)), "tacks": item["tacks"],
                     "astern_s": item["astern"], "duration_s": metrics["duration"],
                     **{k: v for k, v in metrics.items() if k not in ("stopped", "duration")}})
    return pd.DataFrame(rows)


def score_of(group: pd.DataFrame) -> dict:
    """A case's score over its seeds: the mean with its interval (finishers only in a race), the
    runs that finished, N.

    Parameters
    ----------
    group : pandas.DataFrame
        The runs of one task, boat and arm.
    """
    got = stats.mean_interval(group["score"].to_numpy(float))
    return {"mean": got.mean, "low": got.low, "high": got.high, "finished": int(group["finished"].sum()),
            "n": len(group), "tacks": float(group["tacks"].mean()), "astern_s": float(group["astern_s"].mean())}


def change(base: pd.DataFrame, other: pd.DataFrame, task: str) -> dict:
    """``other`` against ``base`` seed by seed: the paired difference (worse is positive) and
    whether it loses.

    Parameters
    ----------
    base, other : pandas.DataFrame
        The runs of one case in two arms.
    task : str
        The event (its score's better direction).
    """
    both = base.merge(other, on="seed", suffixes=("_base", "_other"))
    sign = 1.0 if SCORES[task][2] == "lower" else -1.0
    worse = sign * (both["score_other"] - both["score_base"])
    got = stats.mean_interval(worse.to_numpy(float))
    fewer = int(both["finished_base"].sum() - both["finished_other"].sum())
    loses = fewer > 0 or (got.decided and got.low > 0.0)
    gains = not loses and fewer <= 0 and got.decided and got.high < 0.0
    verdict = "loses" if loses else "gains" if gains else "no change shown" if got.decided or got.n else "—"
    return {"worse": got.mean, "worse_low": got.low, "worse_high": got.high, "fewer_finished": fewer,
            "loses": bool(loses), "verdict": verdict}


def cases_that_lose(changes: pd.DataFrame) -> list[tuple[str, str]]:
    """(task, boat) of every case whose "sea, typical" arm loses.

    Parameters
    ----------
    changes : pandas.DataFrame
        :attr:`Analysis.changes`.
    """
    hard = changes[(changes["arm"] == HARD) & changes["loses"]]
    return list(zip(hard["task"], hard["boat"], strict=True))


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's numbers from its runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs (first pass and switches).
    smoke : bool
        The short pass.
    """
    items = list(results.jobs[JOB]) + list(results.jobs.get(MORE_JOB, []))
    runs = run_rows(items)
    summary, changes, causes = [], [], []
    for (task, boat, arm), group in runs.groupby(["task", "boat", "arm"], sort=False):
        summary.append({"task": task, "boat": boat, "arm": arm, **score_of(group)})
    for (task, boat), case in runs.groupby(["task", "boat"], sort=False):
        base = case[case["arm"] == BASE]
        for arm in case["arm"].unique():
            if arm != BASE:
                changes.append({"task": task, "boat": boat, "arm": arm,
                                **change(base, case[case["arm"] == arm], task)})
    changes = pd.DataFrame(changes)
    for task, boat in cases_that_lose(changes):
        mine = changes[(changes["task"] == task) & (changes["boat"] == boat)].set_index("arm")["loses"]
        losing = [arm for arm in SWITCHES if arm in mine.index and mine[arm]]
        known = all(arm in mine.index for arm in SWITCHES)
        cause = (" and ".join(losing) if len(losing) == len(SWITCHES) else losing[0] if losing
                 else "neither alone" if known else "not run")
        causes.append({"task": task, "boat": boat, **{arm: bool(mine.get(arm, False)) for arm in SWITCHES},
                       "cause": cause.replace(" alone", "").replace("sea and instruments", "both")})
    tracks = {(item["task"], item["boat"], item["arm"]): {"track": item["track"], "scene": item["scene"]}
              for item in items if item["seed"] == min(results.seeds)}
    return Analysis(smoke, tuple(results.seeds), runs, pd.DataFrame(summary), changes, pd.DataFrame(causes),
                    tracks)


def more_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: each half of "sea, typical" alone, on every seed, for the cases that lose.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass.
    smoke : bool
        The short pass.
    """
    first = analyse(results, smoke)
    jobs = [job(boat, task, arm, seed, smoke) for task, boat in cases_that_lose(first.changes)
            for arm in SWITCHES for seed in results.seeds]
    if not jobs:
        return Runs()
    return Runs(jobs={MORE_JOB: (f"{simulate.__module__}:simulate", jobs)}, label=f"{NAME} switches")


def headline(analysis: Analysis) -> dict:
    """Each event's score on each boat in calm water with perfect instruments and in the sea
    with typical ones (the race: its mean finish time, s, and the runs that finished).

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    out = {}
    for row in analysis.summary.itertuples():
        if row.arm not in CONDITIONS:
            continue
        key = f"{row.task} {row.boat} {row.arm}"
        out[key] = round(float(row.mean), 3) if np.isfinite(row.mean) else None
        if row.task == "upwind_downwind":
            out[f"{key} finished"] = f"{row.finished}/{row.n}"
    return out


def ordered(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame``'s rows in the study's order: task, boat, arm.

    Parameters
    ----------
    frame : pandas.DataFrame
        Rows with task, boat and arm.
    """
    arms = [*CONDITIONS, *SWITCHES, BOOK_RUDDER]
    key = {"task": TASKS.index, "boat": BOATS.index, "arm": arms.index}
    return frame.sort_values(list(key), key=lambda column: column.map(key[column.name])).reset_index(drop=True)
