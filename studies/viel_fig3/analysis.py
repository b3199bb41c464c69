"""Viel et al. (2019) Fig. 3, the analysis: the runs as tables, the headline numbers, the CSV data.

:func:`analyse` turns the runs into four tables (:class:`Analysis`): per world and case from the
task's start (``main``), every switch next to its baseline (``variants``), the paper world over
starts and headings (``grid``) and the PID heading-hold check (``capability``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco.study import Results

from .causes import viel_boat_cause
from .measures import after_entry
from .scenario import (
    DEFAULT_START,
    PAPER_D_M,
    PAPER_D_T,
    PAPER_MAX_M,
    SWEPT,
    SWITCHES_JOB,
    WORLDS,
    cases,
    duration,
    is_start,
    sweep_folder,
)

COLUMNS = ["variant", "world", "case", "start", "seed", "d_T", "entered_at", "max_distance_after_entry",
           "mean_distance_after_entry", "stopped_at", "stop_distance", "max_after_stop", "min_distance",
           "final_distance", "to_paper_bound_s", "to_first_exit_s", "exits", "drift_speed",
           "drift_downwind", "wall_time"]  # of summary.csv, switches.csv and start_grid.csv


@dataclass(frozen=True, eq=False)
class Analysis:
    """The study's numbers.

    Parameters
    ----------
    main : pandas.DataFrame
        One row per world and case: the task's start, seed 0, the paper's setup.
    variants : pandas.DataFrame
        ``main`` (variant "baseline") and every switching experiment's row.
    grid : pandas.DataFrame
        The paper world over every start and seed, in the order of its sweep's runs
        (:func:`sailmujoco.sweep.expand`).
    capability : pandas.DataFrame
        The PID heading-hold check (boat, wind speed, steady speed, rudder).
    smoke : bool
        Whether these are the smoke run's numbers.
    seconds : float
        Wall time of the simulations [s].
    """

    main: pd.DataFrame
    variants: pd.DataFrame
    grid: pd.DataFrame
    capability: pd.DataFrame
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
        row.update(after_entry(t, np.hypot(x, y), row["entered_at"]))
        rows.append(row)
    return rows


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's tables from its runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`.scenario.runs`.
    smoke : bool
        The study's short pass.
    """
    rows = [row for key in SWEPT for row in sweep_rows(key, results.records(sweep_folder(key)))]
    switches = results.jobs[SWITCHES_JOB]
    rows += [r for r in switches if r.get("variant") == "baseline"]  # viel_boat's Fig. 3 column
    switches = [r for r in switches if r.get("variant") != "baseline"]
    base = pd.DataFrame(rows)
    main = base[is_start(base["start"], DEFAULT_START) & (base["seed"] == 0)].sort_values(["world", "case"])
    grid = base[base["world"] == "paper"].copy()
    capability = pd.DataFrame([r for r in switches if r.get("kind") == "heading_hold"])
    variants = pd.concat([main.assign(variant="baseline"),
                          pd.DataFrame([r for r in switches if r.get("kind", "position") == "position"])],
                         ignore_index=True)
    return Analysis(main, variants, grid, capability, smoke, results.seconds)


def write_tables(analysis: Analysis, out: Path) -> None:
    """``summary.csv``, ``switches.csv``, ``start_grid.csv``, ``heading_hold_check.csv`` and
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
    analysis.variants[COLUMNS].to_csv(out / "switches.csv", index=False, float_format="%.4g")
    analysis.grid[COLUMNS[1:]].to_csv(out / "start_grid.csv", index=False, float_format="%.4g")
    if not capability.empty:
        capability.drop(columns=["kind"]).to_csv(out / "heading_hold_check.csv", index=False, float_format="%.4g")
    traj = [pd.DataFrame({"world": r["world"], "case": r["case"], "t": r["trajectory"]["t"],
                          "x": r["trajectory"]["x"], "y": r["trajectory"]["y"],
                          "distance": np.hypot(r["trajectory"]["x"], r["trajectory"]["y"])})
            for _, r in main.iterrows()]
    pd.concat(traj).to_csv(out / "trajectories.csv", index=False, float_format="%.3f")


def _paper_world_numbers(analysis: Analysis) -> dict:
    main, grid, variants = analysis.main, analysis.grid, analysis.variants
    paper = main[main["world"] == "paper"].set_index("case")
    printed = variants[variants["variant"] == "printed_rudder"]
    return {
        "paper_all_entered": bool(paper["entered_at"].notna().all()),
        "paper_max_after_entry_m": float(paper["max_distance_after_entry"].max()),
        "paper_max_after_stop_m": float(paper["max_after_stop"].max()),
        "paper_all_below_7m": bool((paper["max_distance_after_entry"] < PAPER_D_T).all()),
        "paper_cases_below_6_4m": int((paper["max_after_stop"] < PAPER_MAX_M).sum()),
        "grid_runs": int(len(grid)),
        "grid_fraction_below_7m": float((grid["max_distance_after_entry"] < PAPER_D_T).mean()),
        "grid_fraction_below_6_4m": float((grid["max_after_stop"] < PAPER_MAX_M).mean()),
        "printed_rudder_runs": int(len(printed)),
        "printed_rudder_fraction_below_6_4m": float((printed["max_after_stop"] < PAPER_MAX_M).mean()),
        "printed_rudder_fraction_below_7m": float((printed["max_distance_after_entry"] < PAPER_D_T).mean()),
        "wille_yacht_cases_entered": int(main[main["world"] == "wille_yacht"]["entered_at"].notna().sum()),
        "saoud_robot_cases_entered": int(main[main["world"] == "saoud_robot"]["entered_at"].notna().sum()),
        "viel_boat_cases_entered": int(main[main["world"] == "viel_boat"]["entered_at"].notna().sum()),
        "wall_time_s": analysis.seconds, "smoke": analysis.smoke}


def headline(analysis: Analysis) -> dict:
    """The headline numbers (the tests assert on them): the paper world's bound per case and over
    the grid, each switch's max distance after the stop, the 6-DOF boats' entries, viel_boat's
    measured cause, the PID check's steady speeds.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    main, variants = analysis.main, analysis.variants
    out = _paper_world_numbers(analysis)
    for key in WORLDS:
        for _, r in main[main["world"] == key].iterrows():
            out[f"{key}_case{int(r['case'])}_max_after_stop_m"] = float(r["max_after_stop"])
            out[f"{key}_case{int(r['case'])}_max_after_entry_m"] = float(r["max_distance_after_entry"])
    for v in ("dt_0.1", "no_hull_wind", "printed_rudder"):
        sel = variants[(variants["variant"] == v) & is_start(variants["start"], DEFAULT_START)]
        for _, r in sel.iterrows():
            out[f"{v}_case{int(r['case'])}_max_after_stop_m"] = float(r["max_after_stop"])
    for _, r in main[main["world"] == "viel_boat"].iterrows():
        out[f"viel_boat_case{int(r['case'])}_irons_fraction"] = float(r["irons_fraction"])
        out[f"viel_boat_case{int(r['case'])}_cause"] = viel_boat_cause(r, variants)
    for boat in ("viel_boat", "wille_yacht", "saoud_robot"):
        for v in ("under_way", "under_way_scaled"):
            sel = variants[(variants["variant"] == v) & (variants["world"] == boat)]
            for _, r in sel.iterrows():
                out[f"{boat}_{v}_case{int(r['case'])}_max_after_stop_m"] = float(r["max_after_stop"])
    for _, r in analysis.capability.iterrows():
        out[f"{r['world']}_pid_135deg_{r['wind_speed']:g}ms_speed"] = float(r["steady_speed"])
    return out
