"""Viel et al. (2019) Fig. 3, the analysis: the runs as tables, the headline numbers, the CSV data.

:func:`analyse` turns the runs into four tables (:class:`Analysis`): per world and case from the
task's start (``main``), every switch next to its baseline (``variants``), the paper world over
starts and headings (``grid``) and the PID heading-hold check (``capability``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco import stats
from sailmujoco.jit.ordered import elementwise
from sailmujoco.study import Results

from ..kit.seeds import decide, paired
from .causes import viel_boat_cause
from .measures import after_entry
from .scenario import (
    DEFAULT_START,
    PAPER_D_M,
    PAPER_D_T,
    PAPER_MAX_M,
    RATE_BOUND,
    SWEPT,
    SWITCH_SEED,
    SWITCHES_JOB,
    WORLDS,
    cases,
    duration,
    is_start,
    simulated_seconds,
    sweep_folder,
)

COLUMNS = ["variant", "world", "case", "start", "seed", "d_T", "entered_at", "max_distance_after_entry",
           "mean_distance_after_entry", "stopped_at", "stop_distance", "max_after_stop", "min_distance",
           "final_distance", "to_paper_bound_s", "to_first_exit_s", "exits", "drift_speed",
           "drift_downwind", "wall_time"]  # of summary.csv, switches.csv and start_grid.csv
# the numbers stated over seeds per world and case (means with their intervals; a run that never
# enters has none of the after-entry ones, so those rest on the seeds that entered)
OVER_SEEDS = ("entered_at", "max_distance_after_entry", "mean_distance_after_entry", "stopped_at",
              "stop_distance", "max_after_stop", "min_distance", "final_distance", "exits",
              "drift_speed", "drift_downwind", "surge_after_stop", "sway_after_stop", "sail_after_stop_deg",
              "irons_fraction", "rudder_stop_fraction", "surge_mean", "heel_max_deg")
# the claims made for every run, counted per world: column -> what it says
CLAIMS = {"entered": "enters the target area",
          "inside_after_entry": f"stays within d_T = {PAPER_D_T:g} m after entry (task metric)",
          "below_bound_after_stop": f"stays within {PAPER_MAX_M:g} m after the stop"}


@dataclass(frozen=True, eq=False)
class Analysis:
    """The study's numbers.

    Parameters
    ----------
    main : pandas.DataFrame
        One row per world, case and seed: the task's start, the paper's setup.
    per_case : pandas.DataFrame
        One row per world and case: ``n`` (seeds), ``entered`` (how many entered), and for each of
        :data:`OVER_SEEDS` its :class:`~sailmujoco.stats.Interval` over the seeds; the paired
        differences from the paper world (``*_minus_paper``) and the verdicts (``after_stop_verdict``
        against the paper's 6.4 m, ``after_entry_verdict`` against d_T).
    worlds : pandas.DataFrame
        One row per world (and the paper world over all starts, ``grid``) and claim of
        :data:`CLAIMS`: ``passed`` of ``n`` runs, the Wilson interval ``rate`` and the verdict.
    variants : pandas.DataFrame
        ``main``'s rows on :data:`SWITCH_SEED` (variant "baseline") and every switching
        experiment's row (on that seed alone).
    grid : pandas.DataFrame
        The paper world over every start and seed, in the order of its sweep's runs
        (:func:`sailmujoco.sweep.expand`).
    capability : pandas.DataFrame
        The PID heading-hold check (boat, wind speed, steady speed, rudder).
    seeds : tuple of int
        The seeds run.
    smoke : bool
        Whether these are the smoke run's numbers.
    seconds : float
        Wall time of the simulations [s].
    """

    main: pd.DataFrame
    per_case: pd.DataFrame
    worlds: pd.DataFrame
    variants: pd.DataFrame
    grid: pd.DataFrame
    capability: pd.DataFrame
    seeds: tuple
    smoke: bool
    seconds: float

    @property
    def duration(self) -> float:
        """One position-keeping run's length [s]."""
        return duration(self.smoke)

    @property
    def cases(self) -> tuple:
        """The wind cases run."""
        return cases(self.smoke)

    @property
    def cost(self) -> dict:
        """The runs' simulated seconds, weighted (:func:`.scenario.simulated_seconds`)."""
        return simulated_seconds(self.smoke, self.seeds)

    def case_row(self, world: str, case: int):
        """The ``per_case`` row of ``world`` in ``case`` (None if not run).

        Parameters
        ----------
        world : str
            A key of ``WORLDS``.
        case : int
            A wind case.
        """
        sel = self.per_case[(self.per_case["world"] == world) & (self.per_case["case"] == case)]
        return None if sel.empty else sel.iloc[0]

    def claim(self, world: str, claim: str):
        """The ``worlds`` row of ``world`` (or ``"grid"``) and ``claim`` (a key of :data:`CLAIMS`).

        Parameters
        ----------
        world : str
            A key of ``WORLDS``, or ``"grid"``.
        claim : str
            A key of :data:`CLAIMS`.
        """
        sel = self.worlds[(self.worlds["world"] == world) & (self.worlds["claim"] == claim)]
        return sel.iloc[0]


def sweep_rows(key: str, records: list[dict]) -> list[dict]:
    """The rows of one swept world's runs, with the entry-based measures computed from the samples.

    Parameters
    ----------
    key : str
        The world (a key of ``WORLDS``).
    records : list of dict
        Its runs' stored records (metrics and trajectory), in the sweep's run order.
    """
    rows = []
    for record in records:
        m = record.get("metrics", {})
        traj = record.get("trajectory", [])
        t = np.array([p["t"] for p in traj])
        x = np.array([p["x"] for p in traj])
        y = np.array([p["y"] for p in traj])
        row = {"variant": "baseline", "world": key, "case": record["task_options"]["case"],
               "start": tuple(record["task_options"]["start"]), "seed": record["seed"],
               "status": record["status"], "wall_time": record.get("wall_time", float("nan")),
               "trajectory": {"t": t.tolist(), "x": x.tolist(), "y": y.tolist()}, "d_T": PAPER_D_T,
               "d_M": PAPER_D_M}
        for k in ("entered_at", "max_distance_after_entry", "mean_distance_after_entry", "final_distance",
                  "min_distance"):
            value = m.get(k)
            row[k] = float(value) if isinstance(value, (int, float)) else float("nan")
        row.update(after_entry(t, elementwise(math.hypot, x, y), row["entered_at"]))
        rows.append(row)
    return rows


def passes(frame: pd.DataFrame) -> pd.DataFrame:
    """Each run's pass or fail on the claims of :data:`CLAIMS` (a run that never enters fails all).

    Parameters
    ----------
    frame : pandas.DataFrame
        Runs (``entered_at``, ``max_distance_after_entry``, ``max_after_stop``).
    """
    entered = frame["entered_at"].notna()
    return pd.DataFrame({"entered": entered,
                         "inside_after_entry": entered & (frame["max_distance_after_entry"] < PAPER_D_T),
                         "below_bound_after_stop": entered & (frame["max_after_stop"] < PAPER_MAX_M)},
                        index=frame.index)


def by_seed(frame: pd.DataFrame, column: str, seeds) -> np.ndarray:
    """``column`` of one world and case, one value per seed in the order of ``seeds`` (nan where
    missing).

    Parameters
    ----------
    frame : pandas.DataFrame
        The runs of one world and case.
    column : str
        The number.
    seeds : sequence of int
        The seeds, in order.
    """
    values = dict(zip(frame["seed"], frame[column].astype(float), strict=True))
    return np.array([values.get(s, math.nan) for s in seeds], dtype=float)


def over_seeds(main: pd.DataFrame, seeds) -> pd.DataFrame:
    """One row per world and case of ``main``: the numbers of :data:`OVER_SEEDS` as intervals over
    the seeds, the paired differences from the paper world and the verdicts.

    Parameters
    ----------
    main : pandas.DataFrame
        One row per world, case and seed.
    seeds : sequence of int
        The seeds, in order.
    """
    rows = []
    for key in WORLDS:
        for case in sorted(set(main["case"])):
            runs = main[(main["world"] == key) & (main["case"] == case)]
            if runs.empty:
                continue
            row = {"world": key, "case": int(case), "n": len(runs), "entered": int(runs["entered_at"].notna().sum())}
            for c in OVER_SEEDS:
                row[c] = (stats.mean_interval(runs[c].to_numpy(dtype=float)) if c in runs
                          else stats.Interval(math.nan, math.nan, math.nan, 0))
            modes = [m for m in runs.get("main_mode", pd.Series(dtype=object)) if isinstance(m, str) and m]
            row["main_mode"] = max(sorted(set(modes)), key=modes.count) if modes else ""
            paper = main[(main["world"] == "paper") & (main["case"] == case)]
            for c in ("max_after_stop", "max_distance_after_entry"):
                row[f"{c}_minus_paper"] = (paired(by_seed(runs, c, seeds), by_seed(paper, c, seeds))
                                           if key != "paper" and not paper.empty
                                           else stats.Interval(math.nan, math.nan, math.nan, 0))
            row["after_stop_verdict"] = decide(row["max_after_stop"], PAPER_MAX_M) if row["entered"] else ""
            row["after_entry_verdict"] = (decide(row["max_distance_after_entry"], PAPER_D_T)
                                          if row["entered"] else "")
            rows.append(row)
    return pd.DataFrame(rows)


def claims(main: pd.DataFrame, grid: pd.DataFrame) -> pd.DataFrame:
    """Per world (and the paper world over all starts, ``"grid"``): each claim of :data:`CLAIMS`
    as ``passed`` of ``n`` runs (cases x seeds), its Wilson interval and its verdict against
    :data:`RATE_BOUND`.

    Parameters
    ----------
    main : pandas.DataFrame
        The task-start runs of every world.
    grid : pandas.DataFrame
        The paper world's runs over every start.
    """
    rows = []
    groups = [(key, main[main["world"] == key]) for key in WORLDS] + [("grid", grid)]
    for key, frame in groups:
        if frame.empty:
            continue
        got = passes(frame)
        for claim in CLAIMS:
            rate = stats.pass_rate(int(got[claim].sum()), len(got))
            rows.append({"world": key, "claim": claim, "passed": int(got[claim].sum()), "n": len(got),
                         "rate": rate, "verdict": decide(rate, RATE_BOUND, "above")})
    return pd.DataFrame(rows)


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's tables from its runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`.scenario.runs`.
    smoke : bool
        The study's short pass.
    """
    seeds = tuple(results.seeds)
    rows = [row for key in SWEPT for row in sweep_rows(key, results.records(sweep_folder(key)))]
    switches = results.jobs[SWITCHES_JOB]
    rows += [r for r in switches if r.get("variant") == "baseline"]  # viel_boat's Fig. 3 column
    switches = [r for r in switches if r.get("variant") != "baseline"]
    base = pd.DataFrame(rows)
    main = base[is_start(base["start"], DEFAULT_START)].sort_values(["world", "case", "seed"], kind="stable")
    grid = base[base["world"] == "paper"].copy()
    capability = pd.DataFrame([r for r in switches if r.get("kind") == "heading_hold"])
    variants = pd.concat([main[main["seed"] == SWITCH_SEED].assign(variant="baseline"),
                          pd.DataFrame([r for r in switches if r.get("kind", "position") == "position"])],
                         ignore_index=True)
    return Analysis(main, over_seeds(main, seeds), claims(main, grid), variants, grid, capability, seeds,
                    smoke, results.seconds)


def interval_table(frame: pd.DataFrame) -> pd.DataFrame:
    """``frame`` with each :class:`~sailmujoco.stats.Interval` column spread into its mean,
    ``<column>_low``, ``<column>_high`` and ``<column>_n`` (for a CSV).

    Parameters
    ----------
    frame : pandas.DataFrame
        A table whose cells may be intervals.
    """
    out = {}
    for c in frame.columns:
        values = list(frame[c])
        if values and all(isinstance(v, stats.Interval) for v in values):
            out[c] = [v.mean for v in values]
            out[f"{c}_low"] = [v.low for v in values]
            out[f"{c}_high"] = [v.high for v in values]
            out[f"{c}_n"] = [v.n for v in values]
        else:
            out[c] = values
    return pd.DataFrame(out)


def write_tables(analysis: Analysis, out: Path) -> None:
    """``summary.csv`` (every world, case and seed), ``per_case.csv`` (over seeds), ``claims.csv``
    (pass counts), ``switches.csv``, ``start_grid.csv``, ``heading_hold_check.csv`` and
    ``trajectories.csv`` (2 Hz) into ``out``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    main, capability = analysis.main, analysis.capability
    main[COLUMNS[1:]].to_csv(out / "summary.csv", index=False, float_format="%.4g")
    interval_table(analysis.per_case).to_csv(out / "per_case.csv", index=False, float_format="%.4g")
    interval_table(analysis.worlds).to_csv(out / "claims.csv", index=False, float_format="%.4g")
    analysis.variants[COLUMNS].to_csv(out / "switches.csv", index=False, float_format="%.4g")
    analysis.grid[COLUMNS[1:]].to_csv(out / "start_grid.csv", index=False, float_format="%.4g")
    if not capability.empty:
        capability.drop(columns=["kind"]).to_csv(out / "heading_hold_check.csv", index=False, float_format="%.4g")
    traj = [pd.DataFrame({"world": r["world"], "case": r["case"], "seed": r["seed"], "t": r["trajectory"]["t"],
                          "x": r["trajectory"]["x"], "y": r["trajectory"]["y"],
                          "distance": elementwise(math.hypot, r["trajectory"]["x"], r["trajectory"]["y"])})
            for _, r in main.iterrows()]
    pd.concat(traj).to_csv(out / "trajectories.csv", index=False, float_format="%.3f")


def _paper_world_numbers(analysis: Analysis) -> dict:
    main, variants, per_case = analysis.main, analysis.variants, analysis.per_case
    paper = main[main["world"] == "paper"]
    cases = per_case[per_case["world"] == "paper"]
    printed = variants[variants["variant"] == "printed_rudder"]
    grid_inside, grid_below = analysis.claim("grid", "inside_after_entry"), analysis.claim("grid", "below_bound_after_stop")
    return {
        "paper_all_entered": bool(paper["entered_at"].notna().all()),
        "paper_max_after_entry_m": float(max(i.mean for i in cases["max_distance_after_entry"])),
        "paper_max_after_stop_m": float(max(i.mean for i in cases["max_after_stop"])),
        "paper_all_below_7m": bool((paper["max_distance_after_entry"] < PAPER_D_T).all()),
        "paper_cases_holding_6_4m": int((cases["after_stop_verdict"] == "holds").sum()),
        "grid_runs": int(len(analysis.grid)),
        "grid_fraction_below_7m": float(grid_inside["rate"].mean),
        "grid_below_7m_verdict": str(grid_inside["verdict"]),
        "grid_fraction_below_6_4m": float(grid_below["rate"].mean),
        "grid_below_6_4m_verdict": str(grid_below["verdict"]),
        "printed_rudder_runs": int(len(printed)),
        "printed_rudder_fraction_below_6_4m": float((printed["max_after_stop"] < PAPER_MAX_M).mean()),
        "printed_rudder_fraction_below_7m": float((printed["max_distance_after_entry"] < PAPER_D_T).mean()),
        "seeds": len(analysis.seeds), "wall_time_s": analysis.seconds, "smoke": analysis.smoke}


def headline(analysis: Analysis) -> dict:
    """The headline numbers (the tests assert on them), each a mean over the seeds (a pass
    fraction for a count) with its verdict where it has one: per world, the claims of
    :data:`CLAIMS`; per world and case, the max distance after entry and after the stop and the
    6-DOF boats' paired difference from the paper world; the paper world over the grid; each
    switch's max distance after the stop (seed :data:`.scenario.SWITCH_SEED`), viel_boat's measured
    cause, the PID check's steady speeds.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    variants = analysis.variants
    out = _paper_world_numbers(analysis)
    for key in WORLDS:
        entered = analysis.claim(key, "entered")
        out[f"{key}_runs"] = int(entered["n"])
        out[f"{key}_runs_entered"] = int(entered["passed"])
        for claim, name in (("entered", "entered"), ("inside_after_entry", "inside_after_entry"),
                            ("below_bound_after_stop", "below_6_4m_after_stop")):
            row = analysis.claim(key, claim)
            out[f"{key}_{name}_fraction"] = float(row["rate"].mean)
            out[f"{key}_{name}_verdict"] = str(row["verdict"])
        for _, r in analysis.per_case[analysis.per_case["world"] == key].iterrows():
            c = int(r["case"])
            out[f"{key}_case{c}_entered_seeds"] = int(r["entered"])
            out[f"{key}_case{c}_max_after_stop_m"] = float(r["max_after_stop"].mean)
            out[f"{key}_case{c}_max_after_entry_m"] = float(r["max_distance_after_entry"].mean)
            out[f"{key}_case{c}_after_stop_verdict"] = str(r["after_stop_verdict"])
            if key != "paper":
                out[f"{key}_case{c}_after_stop_minus_paper_m"] = float(r["max_after_stop_minus_paper"].mean)
    for v in ("dt_0.1", "no_hull_wind", "printed_rudder"):
        sel = variants[(variants["variant"] == v) & is_start(variants["start"], DEFAULT_START)]
        for _, r in sel.iterrows():
            out[f"{v}_case{int(r['case'])}_max_after_stop_m"] = float(r["max_after_stop"])
    for _, r in analysis.per_case[analysis.per_case["world"] == "viel_boat"].iterrows():
        out[f"viel_boat_case{int(r['case'])}_irons_fraction"] = float(r["irons_fraction"].mean)
        out[f"viel_boat_case{int(r['case'])}_cause"] = viel_boat_cause(r, variants)
    for boat in ("viel_boat", "wille_yacht", "saoud_robot"):
        for v in ("under_way", "under_way_scaled"):
            sel = variants[(variants["variant"] == v) & (variants["world"] == boat)]
            for _, r in sel.iterrows():
                out[f"{boat}_{v}_case{int(r['case'])}_max_after_stop_m"] = float(r["max_after_stop"])
    for _, r in analysis.capability.iterrows():
        out[f"{r['world']}_pid_135deg_{r['wind_speed']:g}ms_speed"] = float(r["steady_speed"])
    return out
