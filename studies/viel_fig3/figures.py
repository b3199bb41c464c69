"""Viel et al. (2019) Fig. 3, the figures and the data files: what :func:`write` puts in the folder."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco.figures import legend_below, wind_arrow
from sailmujoco.jit.ordered import elementwise
from sailmujoco.tasks.position import CASES as WIND_CASES

from ..kit import save_figure, setup_matplotlib
from ..kit.seeds import band, errorbar
from .analysis import Analysis, write_tables
from .scenario import (
    DEFAULT_START,
    LABELS,
    PAPER_D_M,
    PAPER_D_T,
    PAPER_DT,
    PAPER_MAX_M,
    SWITCH_SEED,
    VARIANT_LABELS,
    WORLDS,
)

FIGURES = {"paper": "fig3_paper.png", "viel_boat": "fig3_viel_boat.png", "wille_yacht": "fig3_wille_yacht.png",
           "saoud_robot": "fig3_saoud_robot.png", "summary": "max_distance.png", "six_dof": "six_dof_switches.png"}
SIX_DOF_SHOWN = (("saoud_robot", "baseline"), ("saoud_robot", "under_way"), ("wille_yacht", "baseline"),
                 ("wille_yacht", "under_way"), ("wille_yacht", "under_way_scaled"))


def _wind_arrow(ax, case: int):
    """Red arrow: where the wind blows (towards north, psi_tw = pi/2), its speed and the
    direction swing, in the corner the trajectory leaves free."""
    speed, speed_osc, dir_osc = WIND_CASES[case]
    text = "wind " + f"{speed:g}" + (f"±{speed_osc:g}" if speed_osc else "") + " m/s"
    text += "\nfrom S, blowing N" + (f"\n±{math.degrees(dir_osc):.0f}° swing" if dir_osc else "")
    wind_arrow(ax, 0.0, text, swing_deg=math.degrees(dir_osc))


def _trajectory_panel(ax, runs, case: int, start, title: str | None = None):
    """The target area, the pre-arrival ring and every run of ``runs`` (one per seed, or one run)."""
    from matplotlib.patches import Circle

    runs = runs if isinstance(runs, list) else [runs]
    d_t, d_m = runs[0].get("d_T", PAPER_D_T), runs[0].get("d_M", PAPER_D_M)
    ax.add_patch(Circle((0, 0), d_t, facecolor="tab:green", alpha=0.25, edgecolor="green", lw=1.2,
                        label=f"target area, d_T = {d_t:.3g} m"))
    for radius in (d_t, d_m):
        ax.add_patch(Circle((0, 0), radius, fill=False, edgecolor="red", lw=1.0, ls="--"))
    ax.plot([], [], color="red", ls="--", lw=1.0, label=f"pre-arrival area, {d_t:.3g}-{d_m:.3g} m")
    span = 25.0
    for i, run in enumerate(runs):
        traj = run["trajectory"]
        x = np.concatenate([[start[0]], traj["x"]])
        y = np.concatenate([[start[1]], traj["y"]])
        seed = f"seed {int(run['seed'])}" if "seed" in run else "boat"
        line, = ax.plot(x, y, lw=1.0, alpha=0.85, color=f"C{i}", label=seed)
        ax.plot(x[-1], y[-1], "s", color=line.get_color(), ms=4)
        span = max(span, float(np.max(np.abs(np.concatenate([x, y])))) + 5.0)
    ax.plot(start[0], start[1], "o", color="black", ms=5, label="start")
    ax.plot([], [], "s", color="gray", ms=4, label="end")
    ax.plot(0, 0, "+", color="black", ms=8)
    span *= 1.3  # room in the corners for the wind's arrow and words (figures.wind_arrow)
    ax.set_xlim(-span, span)
    ax.set_ylim(-span, span)
    ax.set_aspect("equal")
    ax.set_xlabel("x east [m]")
    ax.set_ylabel("y north [m]")
    if title is None:
        entered = sum(math.isfinite(r["entered_at"]) for r in runs)
        title = f"case {case}: in on {entered} of {len(runs)} seeds"
    ax.set_title(title, fontsize=9)
    _wind_arrow(ax, case)


def _distances(runs: list) -> tuple[np.ndarray, np.ndarray]:
    """The runs' distances to the target on their common times (up to the shortest run)."""
    n = min(len(r["trajectory"]["t"]) for r in runs)
    t = np.asarray(runs[0]["trajectory"]["t"][:n], dtype=float)
    d = np.array([elementwise(math.hypot, np.asarray(r["trajectory"]["x"][:n]), np.asarray(r["trajectory"]["y"][:n]))
                  for r in runs])
    return t, d


def figure_world(out: Path, key: str, runs: dict, start) -> Path:
    """Fig. 3 for one world: every seed's trajectory in each case, and the distance to the target
    against time (mean over seeds with its 95 % band).

    Parameters
    ----------
    out : pathlib.Path
        The study's folder.
    key : str
        The world (a key of ``WORLDS``).
    runs : dict
        Case -> its rows (a list, one per seed: trajectory, entry, stop), or one row.
    start : tuple of float
        The runs' start (m).
    """
    plt = setup_matplotlib()
    runs = {c: (r if isinstance(r, list) else [r]) for c, r in runs.items()}
    cols = min(3, len(runs))  # the paper's six cases: 2 rows of 3 (the smoke run's two: 1 row of 2)
    rows = math.ceil(len(runs) / cols)
    fig = plt.figure(figsize=(14 * cols / 3, 4.2 * rows + 3.6))  # 14 x 12 in for 2 x 3
    grid = fig.add_gridspec(rows + 1, cols, height_ratios=(1,) * rows + (0.8,))
    for i, case in enumerate(sorted(runs)):
        ax = fig.add_subplot(grid[i // cols, i % cols])
        _trajectory_panel(ax, runs[case], case, start)
        if i == 0:
            first = ax
    ax = fig.add_subplot(grid[rows, :])
    top, end, all_in = 20.0, 1.0, True
    for case, seeds in sorted(runs.items()):
        t, d = _distances(seeds)
        top = max(top, float(d.max()))
        end = max(end, float(t[-1]) if t.size else 1.0)
        all_in &= all(math.isfinite(r["entered_at"]) for r in seeds)
        line = band(ax, t, d, lw=1.2, label=f"case {case}")
        for r in seeds:
            if math.isfinite(r["stopped_at"]):
                ax.plot(r["stopped_at"], r["stop_distance"], "v", color=line.get_color(), ms=5)
    n = max(len(s) for s in runs.values())
    ax.plot([], [], "v", color="gray", label="stop of a seed (first minimum after entry)")
    ax.axhline(PAPER_D_T, color="green", ls="--", lw=1.2, label=f"d_T = {PAPER_D_T:g} m (target area)")
    ax.axhline(PAPER_MAX_M, color="black", ls="-.", lw=1.2, label=f"paper: stays below {PAPER_MAX_M:g} m")
    ax.axhline(PAPER_D_M, color="red", ls=":", lw=1.0, label=f"d_M = {PAPER_D_M:g} m")
    limit = 20.0 if all_in else min(top * 1.05, 120.0)
    ax.set_ylim(0, limit)
    ax.set_xlim(0, end)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("distance to target [m]")
    ax.set_title(f"distance to the target p_T: mean over {n} seeds, 95 % band"
                 + (f"\n(axis cut at {limit:.0f} m: the approach starts at {math.hypot(*start):.0f} m)"
                    if top > limit else ""))
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    legend_below(fig, first, ncol=6)
    fig.suptitle(f"Viel Fig. 3 reproduced, {LABELS[key]}\nstart {start} m, {n} start headings (seeds), "
                 f"dt {PAPER_DT:g} s, paper's gains")
    return save_figure(fig, out / FIGURES[key])


def figure_summary(out: Path, per_case: pd.DataFrame, variants: pd.DataFrame, grid: pd.DataFrame) -> Path:
    """Max distance after the stop: per world and case over seeds; paper world per switch (one
    seed); every paper-world run over starts and headings.

    Parameters
    ----------
    out : pathlib.Path
        The study's folder.
    per_case, variants, grid : pandas.DataFrame
        The tables of :class:`.analysis.Analysis`.
    """
    plt = setup_matplotlib()
    fig, axes = plt.subplots(1, 3, figsize=(17, 4.8))
    cases = sorted(set(per_case["case"]))
    width = 0.8 / len(WORLDS)
    for i, key in enumerate(WORLDS):
        rows = per_case[per_case["world"] == key].set_index("case")
        pos = np.arange(len(cases)) + (i - (len(WORLDS) - 1) / 2) * width
        shown = [(p, rows.loc[c]) for p, c in zip(pos, cases, strict=True) if c in rows.index]
        got = [(p, r["max_after_stop"]) for p, r in shown if int(r["entered"])]
        if got:
            errorbar(axes[0], [p for p, _ in got], [g for _, g in got], fmt="o", ms=5, color=f"C{i}",
                     label=LABELS[key])
        else:
            axes[0].plot([], [], "o", color=f"C{i}", label=LABELS[key])
        for p, r in shown:
            if not int(r["entered"]):
                axes[0].text(p, 1.1, "never in", rotation=90, ha="center", va="bottom", fontsize=7,
                             color=f"C{i}")
    n = int(per_case["n"].max())
    axes[0].set_title(f"(a) max distance after the stop, task start: mean, 95 % interval, N = {n}")
    shown = [v for v in ("baseline", "printed_rudder", "dt_0.1", "no_hull_wind") if v in set(variants["variant"])]
    for i, v in enumerate(shown):
        rows = variants[(variants["variant"] == v) & (variants["world"] == "paper")]
        rows = rows[rows["start"].map(lambda s: tuple(s) == DEFAULT_START)].set_index("case")
        values = [rows["max_after_stop"].get(c, np.nan) for c in cases]
        pos = np.arange(len(cases)) + (i - (len(shown) - 1) / 2) * 0.2
        axes[1].bar(pos, np.nan_to_num(values, nan=0.0), 0.2, label=VARIANT_LABELS[v])
        for p, c in zip(pos, cases, strict=True):  # the smoke run switches case 1 only
            if c not in rows.index:
                axes[1].text(p, 0.5, "not run", rotation=90, ha="center", va="bottom", fontsize=7)
    axes[1].set_title(f"(b) paper world, task start, seed {SWITCH_SEED}: one switch at a time")
    for ax in axes[:2]:
        ax.set_xticks(np.arange(len(cases)), [f"case {c}" for c in cases])
    printed = variants[(variants["variant"] == "printed_rudder")]
    for offset, frame, color, label in ((-0.18, grid, "tab:blue", "eqs. 7-8 linear in speed (ours)"),
                                        (0.18, printed, "tab:red", "eqs. 7-8 as printed, v² (switch)")):
        for c in cases:
            g = frame[frame["case"] == c]["max_after_stop"].to_numpy()
            if g.size == 0:
                continue
            jitter = np.linspace(-0.12, 0.12, g.size) if g.size > 1 else np.zeros(1)
            axes[2].plot(c + offset + jitter, g, "o", ms=4, alpha=0.7, color=color,
                         label=label if c == cases[0] else None)
    axes[2].set_xticks(cases, [f"case {c}" for c in cases])
    axes[2].set_title(f"(c) paper world, every start and seed ({len(grid)} + {len(printed)} runs)")
    axes[0].set_xlim(-0.5, len(cases) - 0.5)
    axes[0].set_yscale("log")  # the 6-DOF boats drift tens of metres, the paper world a few
    axes[0].set_ylim(1.0, 300.0)
    for ax in axes:
        ax.axhline(PAPER_D_T, color="green", ls="--", lw=1.2, label=f"d_T = {PAPER_D_T:g} m")
        ax.axhline(PAPER_MAX_M, color="black", ls="-.", lw=1.2, label=f"paper {PAPER_MAX_M:g} m")
        ax.set_ylabel("max distance after the stop [m]")
        if ax is not axes[0]:
            ax.set_ylim(0, 25)
        for bar in ax.patches:  # a bar beyond the axis says how far it goes
            if bar.get_height() > 25:
                ax.text(bar.get_x() + bar.get_width() / 2, 24.5, f"{bar.get_height():.0f}↑", ha="center",
                        va="top", rotation=90, fontsize=7, color="white")
        ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=2)
    return save_figure(fig, out / FIGURES["summary"])


def figure_six_dof(out: Path, runs: dict) -> Path:
    """The 6-DOF boats in one case: task start vs under way vs scaled circles (trajectories).

    Parameters
    ----------
    out : pathlib.Path
        The study's folder.
    runs : dict
        (boat, variant) -> its row, or None where not run.
    """
    plt = setup_matplotlib()
    shown = [(k, v) for k, v in runs.items() if v is not None]
    fig, axes = plt.subplots(1, len(shown), figsize=(4.2 * len(shown), 5.0), squeeze=False)
    for ax, ((boat, variant), run) in zip(axes[0], shown, strict=True):
        note = (f"max after stop {run['max_after_stop']:.1f} m (d_T {run['d_T']:.3g} m)"
                if math.isfinite(run["entered_at"]) else "never enters")
        _trajectory_panel(ax, run, int(run["case"]), DEFAULT_START,
                          title=f"{boat}, case {int(run['case'])}\n{VARIANT_LABELS[variant]}\n{note}")
    legend_below(fig, axes[0][0], ncol=5)
    return save_figure(fig, out / FIGURES["six_dof"])


def write(analysis: Analysis, out: Path) -> None:
    """The data files (:func:`.analysis.write_tables`) and the figures (``FIGURES``) into ``out``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    write_tables(analysis, out)
    main, variants = analysis.main, analysis.variants
    for key in WORLDS:
        rows = main[main["world"] == key]
        figure_world(out, key, {int(c): [r.to_dict() for _, r in g.iterrows()] for c, g in rows.groupby("case")},
                     DEFAULT_START)
    figure_summary(out, analysis.per_case, variants, analysis.grid)
    shown_case = 2 if 2 in analysis.cases else analysis.cases[0]

    def pick(boat, variant):
        frame = variants[(variants["world"] == boat) & (variants["variant"] == variant)
                         & (variants["case"] == shown_case)]
        return None if frame.empty else frame.iloc[0].to_dict()

    figure_six_dof(out, {(b, v): pick(b, v) for b, v in SIX_DOF_SHOWN})
