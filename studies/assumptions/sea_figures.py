"""Assumption validation, the sea's files: its CSV tables and figures.

:func:`write` adds ``SEA_FILES`` (the runs one row per case and seed, the cases with their
intervals and verdicts, the mechanisms and their reruns) and ``SEA_FIGURES`` (the wind plane in
a sea against calm water, and the series against the sea's height) to the study's folder, after
the study's own (:func:`.figures.write`).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from ..kit import save_figure, setup_matplotlib
from ..kit import seeds as kit_seeds
from ..kit.verdict import value_range
from .figures import heatmap
from .figures import write as write_figures
from .sea_analysis import SeaAnalysis
from .sea_cases import DIFFERENCE, HEADING_LOST_DEG, SAILING, interval_of, verdict_kind

SEA_FILES = {"saoud_robot": "sea_wind_plane.csv", "table1": "sea_table1.csv", "saoud": "sea_saoud.csv",
             "cases": "sea_cases.csv", "mechanisms": "sea_mechanisms.csv",
             "reruns": "sea_mechanism_reruns.csv"}  # the wind plane's file holds both boats
SEA_FIGURES = {"plane": "sea_wind_plane.png", "series": "sea_heights.png"}


def write(analysis, out: Path) -> None:
    """The study's figures and data (:func:`.figures.write`), then the sea's: ``SEA_FILES``
    (the runs one row per case and seed, the cases with their intervals and verdicts, the
    mechanisms and their reruns) and ``SEA_FIGURES``.

    Parameters
    ----------
    analysis : studies.assumptions.analysis.Analysis
        The study's numbers (``analysis.sea``: the sea's).
    out : pathlib.Path
        The study's folder.
    """
    write_figures(analysis, out)
    out, s = Path(out), analysis.sea
    pd.concat([s.runs["saoud_robot"], s.runs["wille_yacht"]], ignore_index=True).to_csv(
        out / SEA_FILES["saoud_robot"], index=False)
    s.runs["table1"].to_csv(out / SEA_FILES["table1"], index=False)
    s.runs["saoud"].to_csv(out / SEA_FILES["saoud"], index=False)
    pd.concat([t.assign(series=series) for series, t in s.tables.items()], ignore_index=True).to_csv(
        out / SEA_FILES["cases"], index=False)
    s.mechanisms.to_csv(out / SEA_FILES["mechanisms"], index=False)
    s.reruns.to_csv(out / SEA_FILES["reruns"], index=False)
    plt = setup_matplotlib()
    _plane_figure(plt, s, out)
    _series_figure(plt, s, out)


def _pivot(table: pd.DataFrame, column: str) -> pd.DataFrame:
    return table.pivot_table(index="tws", columns="twa", values=column, dropna=False)


def _mark_cells(plt, ax, table: pd.DataFrame, metric: str | None) -> None:
    """On each cell: a red hatched frame and "lost: calm k | sea k" where a seed's calm or sea run
    lost its heading; "?" where ``metric``'s verdict is undecided, "✓" where it holds."""
    speeds, angles = sorted(set(table["tws"])), sorted(set(table["twa"]))
    for _, row in table.iterrows():
        i, j = speeds.index(row["tws"]), angles.index(row["twa"])
        if metric is not None:
            kind = verdict_kind(row[f"{metric}_verdict"])
            mark = {"holds": "✓", "undecided": "?"}.get(kind)
            if mark:
                ax.text(j + 0.3, i + 0.28, mark, ha="center", va="center", color="white", fontsize=9,
                        fontweight="bold")
        if row["lost_calm"] or row["lost_sea"]:
            ax.add_patch(plt.Rectangle((j - 0.45, i - 0.45), 0.9, 0.9, fill=False, edgecolor="red", hatch="//",
                                       linewidth=1.5, alpha=0.6))
            ax.text(j, i - 0.3, f"lost: {row['lost_calm']} | {row['lost_sea']}", ha="center", va="center",
                    color="red", fontsize=7, bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 1.0})


def _plane_figure(plt, s: SeaAnalysis, out: Path) -> None:
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    n = len(s.seeds)
    for row, boat in enumerate(("saoud_robot", "wille_yacht")):
        table = s.tables[boat]
        heatmap(plt, 100 * _pivot(table, "speed_rel"), axes[row, 0],
                f"{boat}: steady speed in the sea vs calm, mean of {n} seeds\n"
                f"(✓ holds within ±{100 * DIFFERENCE:g} %, ? undecided, else breaks)", "%")
        heatmap(plt, _pivot(table, "roll_sd_sea"), axes[row, 1],
                f"{boat}: roll (heel's SD) in the sea, mean of {n} seeds\n"
                f"(calm: {value_range(table['roll_sd_calm'], fmt='{:.2f}')}°; ? its change undecided)", "deg")
        _mark_cells(plt, axes[row, 0], table, "speed")
        _mark_cells(plt, axes[row, 1], table, "roll_sd")
    fig.suptitle("What the sea a wind raises does over the wind plane (× = no data); red hatch: seeds on "
                 f"which the calm | sea run lost its heading\n(heading error RMS > {HEADING_LOST_DEG:g}°); "
                 "each cell's mean over the seeds that kept it")
    save_figure(fig, out / SEA_FIGURES["plane"])


def _series_figure(plt, s: SeaAnalysis, out: Path) -> None:
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    t1 = s.tables["table1"]
    for k, (sim, group) in enumerate(t1.groupby("sim")):
        calm = interval_of(group.iloc[0], "roll_sd_calm")
        x = np.array([0.0, *group["hs"]]) + 0.03 * (k - 1)
        kit_seeds.errorbar(axes[0], x, [calm, *(interval_of(r, "roll_sd_sea") for _, r in group.iterrows())],
                           fmt="o-", label=sim)
    _mark_stops(axes[0], t1)
    axes[0].set_title(f"Wille's roll controller (Table 1): roll, the heel's SD\n(mean and 95 % interval, "
                      f"{len(s.seeds)} seeds)", fontsize=9)
    sa = s.tables["saoud"]
    for k, metric in enumerate(("roll_sd", "heel", "pitch_sd")):
        calm = interval_of(sa.iloc[0], f"{metric}_calm")
        x = np.array([0.0, *sa["hs"]]) + 0.03 * (k - 1)
        kit_seeds.errorbar(axes[1], x, [calm, *(interval_of(r, f"{metric}_sea") for _, r in sa.iterrows())],
                           fmt="o-", label=SAILING[metric][0].split(" (")[0])
    _mark_stops(axes[1], sa)
    axes[1].set_title("Saoud's optimal sail (robot, beam reach)\n(calm: one deterministic run)", fontsize=9)
    for ax in axes:
        ax.set_xlabel("significant wave height Hs [m] (0: calm water)")
        ax.set_ylabel("[deg]")
    axes[0].legend(fontsize=8)
    # below the axes: the three lines and the marks leave no corner free
    axes[1].legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=4)
    fig.suptitle("Fully developed seas of height Hs, from the wind's bearing")
    save_figure(fig, out / SEA_FIGURES["series"])


def _mark_stops(ax, table: pd.DataFrame) -> None:
    """A red cross on the roll of each case with a sea run that stopped early, a red circle where
    a sea run lost its heading."""
    stopped = table[table["stopped"] > 0]
    if len(stopped):
        ax.scatter(stopped["hs"], stopped["roll_sd_sea"], marker="x", s=80, color="red",
                   label="a seed stopped early", zorder=3)
    lost = table[table["lost_sea"] > 0]
    if len(lost):
        ax.scatter(lost["hs"], lost["roll_sd_sea"], marker="o", s=120, facecolors="none", edgecolors="red",
                   label="a seed lost its heading", zorder=3)
