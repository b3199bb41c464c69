"""Assumption validation, sensors and actuators as fitted: what they do to each paper's claim.

From the runs of :mod:`.fitted`: each scenario's figure of merit in the three arms, each arm's
change against the perfect one seed by seed (``(arm - perfect) / max(|perfect|, floor)``) with
its 95 % interval and verdict (within ±10 %: *holds*), the switches that trace each change over
10 % to one instrument or servo, the two rows of the assumption table ("perfect sensors",
"ideal actuators") and the report's section.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco import stats
from sailmujoco.study import Results, Runs

from ..kit import seeds as over
from ..kit.verdict import TOLERANCE
from .fitted import (
    ARMS,
    ATTRIBUTION_JOB,
    FITTED_JOB,
    SCENARIOS,
    attribution_jobs,
    fitted_jobs,
    relative,
)

ROW_TITLES = {"sensors": "Perfect sensors: the controller reads the true state (every paper)",
              "actuators": "Ideal actuators: the command reaches the rudder and sail through a first-order "
                           "lag only (every paper)"}
ARM_WORDS = {"sensors": "typical sensors", "actuators": "typical actuators"}


@dataclass(frozen=True)
class FittedAnalysis:
    """The numbers of the fitted arms.

    Parameters
    ----------
    runs : pandas.DataFrame
        One row per run: scenario, arm, switch ("" for the arm itself), seed, value (SI),
        stopped.
    effects : pandas.DataFrame
        One row per scenario, arm and switch: the change against the perfect arm
        (``change``, ``change_low``, ``change_high``, ``n``: a fraction) and its verdict.
    seeds : tuple
        The seeds run.
    """

    runs: pd.DataFrame
    effects: pd.DataFrame
    seeds: tuple

    def change(self, scenario: str, arm: str, switch: str = "") -> stats.Interval:
        """The change of a scenario's figure of merit in ``arm`` (with ``switch`` perfect).

        Parameters
        ----------
        scenario, arm, switch : str
            The scenario, the arm and the switch ("" for none).
        """
        row = self.effects[(self.effects["scenario"] == scenario) & (self.effects["arm"] == arm)
                           & (self.effects["switch"] == switch)].iloc[0]
        return over.row_interval(row, "change")

    def value(self, scenario: str, arm: str) -> stats.Interval:
        """A scenario's figure of merit in ``arm`` over seeds, in its report unit.

        Parameters
        ----------
        scenario, arm : str
            The scenario and the arm.
        """
        runs = self.runs[(self.runs["scenario"] == scenario) & (self.runs["arm"] == arm)
                         & (self.runs["switch"] == "")]
        return over.interval(runs["value"].to_numpy(dtype=float)).scaled(SCENARIOS[scenario]["scale"])


def _frame(items: list[dict], results: list[dict]) -> pd.DataFrame:
    return pd.DataFrame([{"scenario": job["scenario"], "arm": job["arm"], "switch": job["switch"],
                          "seed": job["seed"], "value": float(result["value"]),
                          "stopped": result.get("stopped")}
                         for job, result in zip(items, results, strict=True)])


def _effects(runs: pd.DataFrame) -> pd.DataFrame:
    """Each (scenario, arm, switch)'s per-seed change against the perfect arm, over seeds."""
    perfect = runs[runs["arm"] == "perfect"].set_index(["scenario", "seed"])["value"]
    out = []
    for (scenario, arm, switch), group in runs[runs["arm"] != "perfect"].groupby(
            ["scenario", "arm", "switch"], sort=False):
        floor = SCENARIOS[scenario]["floor"]
        changes = [relative(v, perfect[(scenario, s)], floor)
                   for v, s in zip(group["value"], group["seed"], strict=True)]
        got = over.interval(np.asarray(changes, dtype=float))
        out.append({"scenario": scenario, "arm": arm, "switch": switch, "change": got.mean,
                    "change_low": got.low, "change_high": got.high, "n": got.n,
                    "verdict": over.decide(got, 0.0, "within", TOLERANCE)})
    return pd.DataFrame(out)


def flagged(effects: pd.DataFrame) -> list[tuple[str, str]]:
    """The (scenario, arm) pairs whose mean change exceeds ``TOLERANCE``.

    Parameters
    ----------
    effects : pandas.DataFrame
        :func:`analyse_fitted`'s effects (or the first pass's).
    """
    arms = effects[effects["switch"] == ""]
    return [(r.scenario, r.arm) for r in arms.itertuples() if abs(r.change) > TOLERANCE]


def first_pass_effects(results: Results, smoke: bool) -> pd.DataFrame:
    """The arms' changes from the first pass alone (what the second pass is chosen from).

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass (``results.seeds``: the seeds).
    smoke : bool
        The study's short pass.
    """
    items = fitted_jobs(smoke, results.seeds)
    return _effects(_frame(items, results.jobs[FITTED_JOB]))


def attribution_runs(results: Results, smoke: bool) -> Runs:
    """The second pass's switch runs for every flagged (scenario, arm).

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass.
    smoke : bool
        The study's short pass.
    """
    jobs = attribution_jobs(flagged(first_pass_effects(results, smoke)), smoke, results.seeds)
    if not jobs:
        return Runs()
    return Runs(jobs={ATTRIBUTION_JOB: (f"{__package__}.fitted:fitted_run", jobs)},
                label="the instruments' and servos' switches")


def analyse_fitted(results: Results, smoke: bool) -> FittedAnalysis:
    """The fitted arms' numbers from both passes.

    Parameters
    ----------
    results : sailmujoco.study.Results
        Both passes' runs.
    smoke : bool
        The study's short pass.
    """
    seeds = tuple(int(s) for s in results.seeds)
    items = fitted_jobs(smoke, seeds)
    runs = _frame(items, results.jobs[FITTED_JOB])
    switched = attribution_jobs(flagged(_effects(runs)), smoke, seeds)
    if switched:
        runs = pd.concat([runs, _frame(switched, results.jobs[ATTRIBUTION_JOB])], ignore_index=True)
    return FittedAnalysis(runs, _effects(runs), seeds)


def percent(got: stats.Interval) -> str:
    """A change as ``"+3.1 [-0.5, 6.7] %"``.

    Parameters
    ----------
    got : sailmujoco.stats.Interval
        The change, a fraction.
    """
    text = got.scaled(100).fixed(1, "%")
    return text if text[0] in "-—" else "+" + text


def traced_to(f: FittedAnalysis, scenario: str, arm: str) -> str:
    """The switches that bring a flagged change back within ``TOLERANCE``, or what is left.

    Parameters
    ----------
    f : FittedAnalysis
        The numbers.
    scenario, arm : str
        A flagged pair.
    """
    rows = f.effects[(f.effects["scenario"] == scenario) & (f.effects["arm"] == arm)
                     & (f.effects["switch"] != "")]
    if rows.empty:
        return "—"
    removes = [r.switch for r in rows.itertuples() if abs(r.change) <= TOLERANCE]
    left = ", ".join(f"{r.switch} {100 * r.change + 0.0:+.0f} %" for r in rows.itertuples())
    found = f"the {' or the '.join(removes)}" if removes else "no single switch"
    return f"{found} (the change with each made perfect in turn: {left})"


def table_row(f: FittedAnalysis, arm: str) -> dict:
    """The assumption table's row for ``arm`` ("sensors" or "actuators").

    Parameters
    ----------
    f : FittedAnalysis
        The numbers.
    arm : {"sensors", "actuators"}
        Which assumption.
    """
    n = len(f.seeds)
    verdicts, ranges, traces = [], [], []
    for name in SCENARIOS:
        got = f.change(name, arm)
        word = f.effects[(f.effects["scenario"] == name) & (f.effects["arm"] == arm)
                         & (f.effects["switch"] == "")]["verdict"].iloc[0]
        verdicts.append(word)
        ranges.append(f"{name} {percent(got)} ({word})")
        if abs(got.mean) > TOLERANCE:
            traces.append(f"{name}: {traced_to(f, name, arm)}")
    broke = sum(v == "breaks" for v in verdicts)
    held = sum(v == "holds" for v in verdicts)
    word = "breaks" if broke else "holds" if held == len(verdicts) else f"undecided at {n} seeds"
    return {"assumption": ROW_TITLES[arm],
            "scenarios": f"each paper's controller in its own scenario ({len(SCENARIOS)}), 6-DOF",
            "metric": f"each controller's figure of merit, {ARM_WORDS[arm]} against perfect, paired by seed",
            "range": "; ".join(ranges),
            "threshold": f"within ±{100 * TOLERANCE:g} %",
            "verdict": f"{word} ({broke} of {len(verdicts)} scenarios break, {held} hold)",
            "effect": "; ".join(traces) if traces else "no change beyond 10 %"}


def section_rows(f: FittedAnalysis) -> list[dict]:
    """The report section's table: one row per scenario and arm.

    Parameters
    ----------
    f : FittedAnalysis
        The numbers.
    """
    out = []
    for name, s in SCENARIOS.items():
        for arm in ARMS:
            if arm == "perfect":
                continue
            got = f.change(name, arm)
            word = f.effects[(f.effects["scenario"] == name) & (f.effects["arm"] == arm)
                             & (f.effects["switch"] == "")]["verdict"].iloc[0]
            out.append({"scenario": s["label"], "arm": ARM_WORDS[arm],
                        "perfect": over.cell(f.value(name, "perfect"), 3, s["unit"]),
                        "fitted": over.cell(f.value(name, arm), 3, s["unit"]),
                        "change": percent(got), "verdict": word,
                        "traced to": traced_to(f, name, arm) if abs(got.mean) > TOLERANCE else "—"})
    return out


SECTION_COLUMNS = ["scenario", "arm", "perfect", "fitted", "change", "verdict", "traced to"]


def section_text(f: FittedAnalysis) -> str:
    """The report section's first paragraph: what was run and how it is decided.

    Parameters
    ----------
    f : FittedAnalysis
        The numbers.
    """
    return (
        "Each paper's controller in its own scenario, as the paper has it (perfect sensors and "
        "ideal actuators), with a small boat's instruments (`sensors=\"typical\"`: GNSS 2.5 m CEP "
        "at 5 Hz, 0.1 s late; compass 2°; gyro, inclinometer, masthead vane with ArduPilot's 0.5 Hz "
        "filter, speed log) and with its fitted servos (`actuators=\"typical\"`: rudder 60° in "
        "0.15 s, sail winch 1.3 s across its range, deadband, backlash, the 1 µs PWM step), the "
        f"other half perfect, on seeds {f.seeds[0]}-{f.seeds[-1]} (N = {len(f.seeds)}); the same "
        "wind in all three arms, and in the typical arms the instruments' own noise. The change is "
        "(arm − perfect) / max(|perfect|, floor) seed by seed (floors 0.3 m/s, 1°, 1 m), with its 95 % "
        f"Student-t interval; it *holds* within ±{100 * TOLERANCE:g} %. A change beyond 10 % is "
        "traced by rerunning the arm with one instrument (GNSS, compass, inclinometer, gyro, vane, "
        "log) or one servo (rudder, sail) made perfect at a time: the switch that brings the change "
        "back within 10 % made it. The controllers read what the instruments reach (docs/extending.md, "
        "\"Through instruments\"); what their papers assume known (the true wind in Viel and Saoud, "
        "Wille's body velocities) they still take from the true state.")
