"""Figs. 4 and 5 reproduced, and the study's CSV data."""

from __future__ import annotations

from pathlib import Path

from sailmujoco.figures import legend_below, wind_arrow

from ..kit import save_figure, setup_matplotlib
from .analysis import Analysis
from .scenario import DURATION, LAWS, PAPER_WIND, WORLDS

COLOURS = {"heading": "tab:blue", "course": "tab:red", "course_sail_only": "tab:green"}
FIG4 = "fig4_position.png"
FIG5 = "fig5_course.png"


def figure_positions(results: dict, out: Path, plt) -> Path:
    """Fig. 4: the track (north against east) of each controller, per world.

    Parameters
    ----------
    results : dict
        (case, world, law) -> the run.
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
    fig, axes = plt.subplots(1, 2, figsize=(10, 5.5), sharey=True)
    for ax, world in zip(axes, WORLDS, strict=True):
        for law in ("heading", "course"):
            traj = results[("main", world, law)]["trajectory"]
            ax.plot(traj["east"], traj["north"], color=COLOURS[law], label=LAWS[law])
        switch = results.get(("F_U = -S_y'", world, "course_sail_only"))
        if switch is not None:
            traj = switch["trajectory"]
            ax.plot(traj["east"], traj["north"], color=COLOURS["course_sail_only"], ls=":",
                    label="switch: " + LAWS["course_sail_only"])
        ax.axvline(0.0, color="k", lw=0.8, ls="--", label="desired course (0°)")
        ax.set_xlabel("y, east [m]")
        ax.set_title(WORLDS[world])
        span = max(40.0, max(abs(results[("main", world, law)]["trajectory"]["east"]).max()
                             for law in ("heading", "course")) * 1.3)
        ax.set_xlim(-span, span)
        wind_arrow(ax, to_deg, f"wind {speed:g} m/s (U10)\nfrom {(to_deg + 180.0) % 360.0:g}° (NW),\n"
                               f"blowing to {to_deg:g}°")
    axes[0].set_ylabel("x, north [m]")
    legend_below(fig, axes[0], ncol=2)
    fig.suptitle("Fig. 4 (reproduced): position, heading and course controller\n"
                 f"(U10 = {speed:g} m/s, β_w = {to_deg:g}°: the wind blows towards {to_deg:g}°, {DURATION:g} s)")
    return save_figure(fig, out / FIG4)


def figure_course(results: dict, out: Path, plt) -> Path:
    """Fig. 5: the course over ground (2 s mean) of each controller, per world.

    Parameters
    ----------
    results : dict
        (case, world, law) -> the run.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, axes = plt.subplots(2, 1, figsize=(9, 6.5), sharex=True)
    for ax, world in zip(axes, WORLDS, strict=True):
        for law in ("heading", "course"):
            traj = results[("main", world, law)]["trajectory"]
            smooth = traj["course_deg"].rolling(20, center=True, min_periods=1).mean()  # 2 s mean
            ax.plot(traj["t"], smooth, color=COLOURS[law], label=LAWS[law] + " (2 s mean)")
        switch = results.get(("F_U = -S_y'", world, "course_sail_only"))
        if switch is not None:
            traj = switch["trajectory"]
            smooth = traj["course_deg"].rolling(20, center=True, min_periods=1).mean()
            ax.plot(traj["t"], smooth, color=COLOURS["course_sail_only"], ls=":",
                    label="switch: " + LAWS["course_sail_only"])
        ax.axhline(0.0, color="k", lw=0.8, ls="--", label="desired course χ_d = 0°")
        ax.set_ylabel("course over ground χ [deg]")
        ax.set_title(WORLDS[world])
        ax.set_ylim(-10, 10)
    axes[-1].set_xlabel("time [s]")
    legend_below(fig, axes[0], ncol=2)
    fig.suptitle("Fig. 5 (reproduced): course, heading and course controller")
    return save_figure(fig, out / FIG5)


def _trajectory_file(key: tuple) -> str:
    case, world, law = key
    return (f"trajectory_{case.replace(' ', '_').replace('=', '').replace(chr(39), '')}"
            f"_{world}_{law}.csv".replace("__", "_"))


def write(analysis: Analysis, out: Path) -> None:
    """Each run's trajectory, table2.csv and Figs. 4-5 into ``out``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    for key, result in analysis.results.items():
        result["trajectory"].assign(case=key[0], world=key[1], law=key[2]).to_csv(
            out / _trajectory_file(key), index=False)
    analysis.table().to_csv(out / "table2.csv", index=False)
    plt = setup_matplotlib()
    figure_positions(analysis.results, out, plt)
    figure_course(analysis.results, out, plt)
