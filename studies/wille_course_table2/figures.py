"""Figs. 4 and 5 reproduced over the seeds, Table 2's intervals against the paper, and the study's
CSV data."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco.figures import legend_below, wind_arrow

from ..kit import save_figure, setup_matplotlib
from ..kit import seeds as over
from ..kit.verdict import TOLERANCE
from .analysis import HEADLINE_LAWS, QUANTITIES, REDUCTION_BOUND, Analysis
from .scenario import LAWS, PAPER_REDUCTION, PAPER_TABLE2, PAPER_WIND, WORLDS

COLOURS = {"heading": "tab:blue", "course": "tab:red", "course_sail_only": "tab:green"}
FIG4 = "fig4_position.png"
FIG5 = "fig5_course.png"
FIG_INTERVALS = "table2_intervals.png"
SWITCH = ("F_U = -S_y'", "course_sail_only")  # the switch the figures show beside the headline
LABELS = {"east": "x, east (cross-track) [m]", "north": "y, north [m]", "error_deg": "error |atan(x/y)| [deg]"}


def _seed_runs(results: dict, case: str, world: str, law: str) -> list[tuple[int, dict]]:
    """(seed, run) of one case, by seed."""
    return sorted((key[3], run) for key, run in results.items() if key[:3] == (case, world, law))


def figure_positions(a: Analysis, out: Path, plt) -> Path:
    """Fig. 4: the track (north against east) of each controller on every seed, per world, with
    the end position's mean and 95 % intervals (east and north) over the seeds.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    speed, to_deg = PAPER_WIND
    fig, axes = plt.subplots(1, 2, figsize=(10, 5.8), sharey=True)
    for ax, world in zip(axes, WORLDS, strict=True):
        span = 40.0
        for law in HEADLINE_LAWS:
            for i, (_, run) in enumerate(_seed_runs(a.results, "main", world, law)):
                traj = run["trajectory"]
                ax.plot(traj["east"], traj["north"], color=COLOURS[law], lw=0.8, alpha=0.45,
                        label=f"{LAWS[law]}, each seed" if i == 0 else None)
                span = max(span, 1.3 * float(np.abs(traj["east"]).max()))
            end = a.main(world, law)
            east, north = end["east"], end["north"]
            ax.errorbar([east.mean], [north.mean], fmt="o", color=COLOURS[law], mec="k", capsize=4, zorder=5,
                        xerr=[[east.mean - (east.low if east.decided else east.mean)],
                              [(east.high if east.decided else east.mean) - east.mean]],
                        yerr=[[north.mean - (north.low if north.decided else north.mean)],
                              [(north.high if north.decided else north.mean) - north.mean]],
                        label=f"end position: mean, 95 % interval (N={len(a.seeds)})")
        for seed, run in _seed_runs(a.results, SWITCH[0], world, SWITCH[1]):
            traj = run["trajectory"]
            ax.plot(traj["east"], traj["north"], color=COLOURS[SWITCH[1]], ls=":",
                    label=f"switch: {LAWS[SWITCH[1]]} (seed {seed})")
        ax.axvline(0.0, color="k", lw=0.8, ls="--", label="desired course (0°)")
        ax.set_xlabel("y, east [m]")
        ax.set_title(WORLDS[world])
        ax.set_xlim(-span, span)
        wind_arrow(ax, to_deg, f"wind {speed:g} m/s (U10)\nfrom {(to_deg + 180.0) % 360.0:g}° (NW),\n"
                               f"blowing to {to_deg:g}°")
    axes[0].set_ylabel("x, north [m]")
    legend_below(fig, axes, ncol=2)
    fig.suptitle(f"Fig. 4 (reproduced): position, heading and course controller, {len(a.seeds)} seeds\n"
                 f"(U10 = {speed:g} m/s, β_w = {to_deg:g}°: the wind blows towards {to_deg:g}°, "
                 f"{a.duration:g} s)")
    return save_figure(fig, out / FIG4)


def _smoothed_course(traj: pd.DataFrame) -> pd.Series:
    return traj["course_deg"].rolling(20, center=True, min_periods=1).mean()  # a 2 s mean at 10 Hz


def figure_course(a: Analysis, out: Path, plt) -> Path:
    """Fig. 5: the course over ground (2 s mean) of each controller: the mean over the seeds with
    its pointwise 95 % band, per world.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.8), sharex=True)
    for ax, world in zip(axes, WORLDS, strict=True):
        for law in HEADLINE_LAWS:
            runs = [run["trajectory"] for _, run in _seed_runs(a.results, "main", world, law)]
            t = runs[0]["t"].to_numpy()
            courses = np.vstack([np.interp(t, traj["t"], _smoothed_course(traj)) for traj in runs])
            over.band(ax, t, courses, color=COLOURS[law],
                      label=f"{LAWS[law]} (2 s mean): mean, 95 % band (N={len(runs)})")
        for seed, run in _seed_runs(a.results, SWITCH[0], world, SWITCH[1]):
            traj = run["trajectory"]
            ax.plot(traj["t"], _smoothed_course(traj), color=COLOURS[SWITCH[1]], ls=":", lw=1.0,
                    label=f"switch: {LAWS[SWITCH[1]]} (seed {seed})")
        ax.axhline(0.0, color="k", lw=0.8, ls="--", label="desired course χ_d = 0°")
        ax.set_ylabel("course over ground χ [deg]")
        ax.set_title(WORLDS[world])
        ax.set_ylim(-10, 10)
    axes[-1].set_xlabel("time [s]")
    legend_below(fig, axes, ncol=2)
    fig.suptitle("Fig. 5 (reproduced): course, heading and course controller")
    return save_figure(fig, out / FIG5)


def figure_intervals(a: Analysis, out: Path, plt) -> Path:
    """Table 2 over the seeds: each number's mean with its 95 % interval per world and law, the
    paper's number with its ±10 % band; the error reduction against the paper's and the bound.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, axes = plt.subplots(1, 4, figsize=(13, 4.6))
    markers = {"paper": "o", "mujoco": "s"}
    for ax, q in zip(axes, QUANTITIES, strict=False):
        for i, law in enumerate(HEADLINE_LAWS):
            paper = PAPER_TABLE2[law][q]
            ax.hlines(paper, i - 0.35, i + 0.35, color="k", lw=1.5, label="paper (Table 2)")
            ax.fill_between([i - 0.35, i + 0.35], paper - TOLERANCE * abs(paper), paper + TOLERANCE * abs(paper),
                            color="0.6", alpha=0.35, lw=0, label="paper ± 10 %")
            for j, world in enumerate(WORLDS):
                over.errorbar(ax, [i + (j - 0.5) * 0.3], [a.main(world, law)[q]], fmt=markers[world],
                              color=COLOURS[law], mec="k", label=f"{WORLDS[world]}: mean, 95 % interval")
        ax.set_xticks(range(len(HEADLINE_LAWS)), [LAWS[law].replace(" controller", "") for law in HEADLINE_LAWS])
        ax.set_xlim(-0.6, len(HEADLINE_LAWS) - 0.4)
        ax.set_ylabel(LABELS[q])
    ax = axes[-1]
    ax.axhline(PAPER_REDUCTION, color="k", lw=1.5, label="paper (Table 2)")
    ax.axhline(REDUCTION_BOUND, color="k", lw=1.0, ls="--", label=f"bound {REDUCTION_BOUND:g}")
    for j, world in enumerate(WORLDS):
        over.errorbar(ax, [j], [a.reduction(world)], fmt=markers[world], color="tab:purple", mec="k",
                      label=f"{WORLDS[world]}: mean, 95 % interval")
    ax.set_xticks(range(len(WORLDS)), [w.split(" ")[0] for w in WORLDS.values()])
    ax.set_xlim(-0.6, len(WORLDS) - 0.4)
    ax.set_ylim(0.0, 1.05)
    ax.set_ylabel("1 − course error / heading error [-]")
    ax.set_title("error reduction, course vs heading", fontsize=10)
    legend_below(fig, axes, ncol=4)
    fig.suptitle(f"Table 2 over {len(a.seeds)} seeds ({a.duration:g} s runs): ours against the paper")
    return save_figure(fig, out / FIG_INTERVALS)


def _trajectory_file(case: str, world: str, law: str) -> str:
    return (f"trajectory_{case.replace(' ', '_').replace('=', '').replace(chr(39), '')}"
            f"_{world}_{law}.csv".replace("__", "_"))


def write(analysis: Analysis, out: Path) -> None:
    """The trajectories (one CSV per case, every seed's rows with a ``seed`` column), table2.csv
    (one row per run and seed), table2_intervals.csv (each case over its seeds), Table 2's
    intervals and Figs. 4-5 into ``out``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    cases = {}
    for (case, world, law, seed), result in analysis.results.items():
        cases.setdefault((case, world, law), []).append(
            result["trajectory"].assign(case=case, world=world, law=law, seed=seed))
    for (case, world, law), frames in cases.items():
        pd.concat(frames, ignore_index=True).sort_values(["seed", "t"], kind="stable").to_csv(
            out / _trajectory_file(case, world, law), index=False)
    analysis.runs.to_csv(out / "table2.csv", index=False)
    analysis.intervals().to_csv(out / "table2_intervals.csv", index=False)
    plt = setup_matplotlib()
    figure_intervals(analysis, out, plt)
    figure_positions(analysis, out, plt)
    figure_course(analysis, out, plt)

