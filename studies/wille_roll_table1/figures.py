"""Figs. 3 and 5-8 reproduced, Table 1 over the seeds with 95 % intervals, sim 3 over the gust
realisations, and the study's CSV data."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
from sailmujoco.controllers.wille_roll import PHI_D

from sailmujoco.figures import legend_below, moment_unit

from ..kit import save_figure, setup_matplotlib
from ..kit import seeds as over
from ..kit.wille import MOMENT_TERMS, TABLE1_DURATION, TABLE1_WIND, TABLE1_WINDOW
from .analysis import BASES, LAW_SIMS, REDUCTION_BOUND, Analysis
from .run_table import RunTable
from .scenario import (
    FIG8_LABELS,
    FIG8_WINDS,
    LAG_SEEDS,
    PAPER_OPTIMUM_DEG,
    PAPER_REDUCTION,
    PAPER_SAIL_LAG_S,
    PAPER_TABLE1,
    QUANTITIES,
    SAIL_FACTOR,
    SHARES_WIND,
    SIM_LABELS,
    SIMS,
    WITHIN,
    WORLDS,
    paper_sim,
    realisation_seeds,
)

SIM_STYLE = {"sim1": ("tab:blue", "-"), "sim1_mean": ("tab:blue", ":"), "sim2": ("tab:orange", "-"),
             "sim2_mean": ("tab:orange", ":"), "sim3": ("tab:green", "-")}


FIGURES = {  # the figures' files, by name
    "5": "fig5_heel.png", "6": "fig6_p.png", "7": "fig7_p.png", "3": "fig3_moments.png",
    "8": "fig8_speed_vs_heel.png", "seeds": "fig5_seeds.png", "realisations": "sim3_realisations.png",
    "intervals": "table1_intervals.png",
}
WORLD_STYLE = {"paper": ("tab:blue", "o"), "mujoco": ("tab:red", "s")}


def figure_series(r: RunTable, out, plt, column, sims, number, title, ylabel) -> Path:
    """Figs. 5-7: one column of the median seed's trajectories over the window, per world.

    Parameters
    ----------
    r : RunTable
        The runs.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).
    column : str
        The trajectory's column (``heel_deg``, ``p_deg_s``).
    sims : sequence of str
        The simulations shown.
    number : int
        The paper's figure number.
    title : str
        What the figure shows.
    ylabel : str
        The y axis' label.

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    seed = r.median_seed()
    panels = [(world, label) for world, label in WORLDS.items()]
    fig, axes = plt.subplots(len(panels), 1, figsize=(9, 2.8 * len(panels) + 0.8), sharex=True)
    for ax, (world, label) in zip(axes, panels, strict=True):
        for sim in sims:
            traj = r.raw[("main", world, sim, seed)]["trajectory"]
            late = traj[traj["t"] >= traj["t"].iloc[-1] - TABLE1_WINDOW]
            colour, style = SIM_STYLE[sim]
            ax.plot(late["t"], late[column], color=colour, ls=style, label=SIM_LABELS[sim])
        if column == "heel_deg":
            ax.axhline(10.0, color="k", lw=0.7, ls="--", label="φ_d = 10°")
        ax.set_ylabel(ylabel)
        ax.set_title(f"{label}, seed {seed}", fontsize=10)
    legend_below(fig, axes[0], ncol=2, fontsize=7)
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(f"Fig. {number} (reproduced): {title}\nbeam reach, U10 = {TABLE1_WIND:g} m/s, last {TABLE1_WINDOW:g} s "
                 f"of {TABLE1_DURATION:g} s", fontsize=11)
    return save_figure(fig, out / FIGURES[str(number)])


def figure_seeds(r: RunTable, out, plt) -> Path:
    """Roll angle of sims 1 and 3 for every seed (paper world): the lulls explain the spread.

    Parameters
    ----------
    r : RunTable
        The runs.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, axes = plt.subplots(len(r.seeds), 1, figsize=(9, 1.6 * len(r.seeds) + 0.9), sharex=True,
                             sharey=True)
    axes = np.atleast_1d(axes)
    for ax, seed in zip(axes, r.seeds, strict=True):
        for sim in ("sim1", "sim2", "sim3"):
            traj = r.raw[("main", "paper", sim, seed)]["trajectory"]
            late = traj[traj["t"] >= traj["t"].iloc[-1] - TABLE1_WINDOW]
            colour, style = SIM_STYLE[sim]
            ax.plot(late["t"], late["heel_deg"], color=colour, ls=style, label=SIM_LABELS[sim])
        ax.axhline(10.0, color="k", lw=0.7, ls="--")
        n1 = r.get("main", "paper", "sim1", seed)
        ax.set_title(f"seed {seed}: wind at the sail {n1['wind_ce']:.1f} m/s (window mean), "
                     f"sim 1 mean heel {n1['mean_heel']:.1f}°", fontsize=8)
        ax.set_ylabel("φ [deg]")
    legend_below(fig, axes[0], ncol=3, fontsize=7)
    axes[-1].set_xlabel("time [s]")
    fig.suptitle("Roll angle by gust realisation, paper world (last 50 s)", fontsize=11)
    return save_figure(fig, out / FIGURES["seeds"])


def figure_realisations(r: RunTable, out, plt) -> Path:
    """Sim 3's roll amplitude against how far sim 1 heels, over every gust realisation, and
    against the sail actuator's lag: where the paper's sim-3 amplitude lies for our model.

    Parameters
    ----------
    r : RunTable
        The runs.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    paper = PAPER_TABLE1["sim3"]["roll_amplitude"]
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": [3, 2]})
    for axis in (ax, bx):
        axis.axhspan(paper * (1 - WITHIN), paper * (1 + WITHIN), color="tab:green", alpha=0.15,
                     label=f"paper {paper:g}° ± {100 * WITHIN:.0f} %")
        axis.axhline(paper, color="tab:green", lw=1.0)
    reals = r.realisations()
    more = realisation_seeds(r.seeds)
    for headline, marker, label in ((True, "o", f"seeds 0-{r.seeds[-1]} (Table 1)"),
                                    (False, "x", f"seeds {more[0]}-{more[-1]}" if more else "")):
        pts = [(n1["mean_heel"], n3["roll_amplitude"]) for seed, n1, n3 in reals
               if (seed in r.seeds) == headline]
        if pts:
            ax.scatter(*zip(*pts, strict=True), marker=marker, color="tab:blue", label=label, zorder=3)
    if r.has("sail", "paper", "sim3", 0):
        x1, x3 = r.get("sail", "paper", "sim1", 0), r.get("sail", "paper", "sim3", 0)
        ax.scatter([x1["mean_heel"]], [x3["roll_amplitude"]], marker="^", color="tab:red", zorder=3,
                   label=f"seed 0, sail force x{SAIL_FACTOR:g}")
    ax.axvline(math.degrees(PHI_D), color="k", lw=0.7, ls="--", label="φ_d = 10°")
    ax.set_xlabel("sim 1 (roll control off): mean heel over the window [deg]")
    ax.set_ylabel("sim 3 (perfect wind): roll amplitude [deg]")
    ax.set_title(f"one point per gust realisation (paper world, U10 = {TABLE1_WIND:g} m/s)", fontsize=10)
    ax.legend(fontsize=7, loc="upper right")
    for seed, colour in zip(LAG_SEEDS, ("tab:blue", "tab:orange"), strict=True):
        for fast, style in ((False, "-"), (True, "--")):
            pts = r.lag(seed, fast)
            if len(pts) > 1:
                bx.plot([t for t, _ in pts], [n["roll_amplitude"] for _, n in pts], marker="o", ls=style,
                        color=colour, label=f"seed {seed} alone, control at {50 if fast else 10} Hz")
    bx.set_xlim(left=0.0)
    bx.set_ylim(bottom=0.0)
    bx.set_xlabel(f"sail actuator lag T_λ [s] (paper {PAPER_SAIL_LAG_S:g} s)")
    bx.set_ylabel("sim 3: roll amplitude [deg]")
    bx.set_title("sim 3's residual against the sail actuator's lag\n(one seed per line: an illustration)",
                 fontsize=10)
    bx.legend(fontsize=7, loc="upper left")
    fig.suptitle("Table 1, sim 3: what sets the remaining roll with perfect wind", fontsize=11)
    return save_figure(fig, out / FIGURES["realisations"])


def figure_intervals(r: RunTable, out, plt) -> Path:
    """Table 1 over the seeds: each number's mean with its 95 % interval per world against the
    paper's, and the reductions paired by seed against the paper's and the 60 % bound.

    Parameters
    ----------
    r : RunTable
        The runs.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    x = np.arange(len(SIMS))
    for ax, (key, name) in zip(axes.ravel()[:3], QUANTITIES.items(), strict=True):
        for k, world in enumerate(WORLDS):
            colour, marker = WORLD_STYLE[world]
            over.errorbar(ax, x + (k - 0.5) * 0.18, [r.interval(world, sim, key) for sim in SIMS], fmt=marker,
                          color=colour, label=f"{WORLDS[world]}, N = {len(r.seeds)}")
        ax.scatter(x, [PAPER_TABLE1[paper_sim(sim)][key] for sim in SIMS], marker="_", s=400, color="k",
                   zorder=4, label="paper (one realisation)")
        ax.set_xticks(x, [SIM_LABELS[sim].split(":")[0] + ("\n(mean wind)" if "mean" in sim else "") for sim in SIMS],
                      fontsize=8)
        ax.set_ylabel(name)
    axes[0, 0].legend(fontsize=7)
    ax = axes[1, 1]
    pairs = [(b, s) for b in BASES for s in LAW_SIMS
             if not (b == "sim1" and s == "sim2_mean" or b == "sim1_mean" and s == "sim2")]
    x = np.arange(len(pairs))
    for k, world in enumerate(WORLDS):
        colour, marker = WORLD_STYLE[world]
        got = [r.reduction(world, b, s) for b, s in pairs]
        over.errorbar(ax, x + (k - 0.5) * 0.18, [type(g)(100 * g.mean, 100 * g.low, 100 * g.high, g.n) for g in got],
                      fmt=marker, color=colour, label=WORLDS[world])
    ax.scatter(x, [100 * PAPER_REDUCTION[paper_sim(s)] for _, s in pairs], marker="_", s=400, color="k", zorder=4,
               label="paper")
    ax.axhline(100 * REDUCTION_BOUND, color="k", lw=0.7, ls="--", label=f"{100 * REDUCTION_BOUND:.0f} %")
    ax.set_xticks(x, [f"{b.replace('_mean', ' (mean)')} → {s.replace('_mean', ' (mean)')}" for b, s in pairs],
                  fontsize=8)
    ax.set_ylabel("roll amplitude reduction, per seed [%]")
    ax.legend(fontsize=7)
    fig.suptitle(f"Table 1 over {len(r.seeds)} gust realisations (seeds 0-{r.seeds[-1]}): means with 95 % "
                 f"intervals, beam reach U10 = {TABLE1_WIND:g} m/s", fontsize=11)
    return save_figure(fig, out / FIGURES["intervals"])


def figure_moments(r: RunTable, out, plt) -> Path:
    """Fig. 3: the roll moment of each force term, per world.

    Parameters
    ----------
    r : RunTable
        The runs.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), sharey=True)
    largest = max(float(np.nanmax(np.abs(r.raw[("shares", world, "sim1", 0)]["trajectory"][f"K_{term}"])))
                  for world in WORLDS for term in MOMENT_TERMS)
    scale, unit = moment_unit(largest)
    for ax, world in zip(axes, WORLDS, strict=True):
        traj = r.raw[("shares", world, "sim1", 0)]["trajectory"]
        for term in MOMENT_TERMS:
            ax.plot(traj["t"], traj[f"K_{term}"] / scale, label=term.replace("_", " "))
        ax.set_xlabel("time [s]")
        ax.set_title(WORLDS[world] + (" (restoring = buoyancy + weight)" if world == "mujoco" else ""),
                     fontsize=10)
    axes[0].set_ylabel(f"roll moment about CO [{unit}]")
    legend_below(fig, axes[0], ncol=6, fontsize=7)
    fig.suptitle(f"Fig. 3 (reproduced): moments in roll while beam reaching, U10 = {SHARES_WIND:g} m/s, "
                 "roll control off")
    return save_figure(fig, out / FIGURES["3"])


def figure_fig8(tables, switch, out, plt) -> Path:
    """Fig. 8: the top surge speed against phi_d, per variant and U10.

    Parameters
    ----------
    tables : dict of str to pandas.DataFrame
        Fig. 8 by variant.
    switch : pandas.DataFrame or None
        Fig. 8 with the sail force switched.
    out : pathlib.Path
        The study's folder.
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).

    Returns
    -------
    pathlib.Path
        The figure's file.
    """
    fig, ax = plt.subplots(figsize=(11.5, 5.5))
    colours = {13.0: "tab:blue", 16.0: "tab:red"}
    styles = {"paper": ("-", "o"), "mujoco": ("--", "s"), "mujoco_dofs4": ("-.", "d")}
    for variant, table in tables.items():
        style, marker = styles[variant]
        for wind in FIG8_WINDS:
            rows = table[(table["wind_speed"] == wind) & (table["status"] == "ok")].sort_values(
                "heel_desired_deg")
            ax.plot(rows["heel_desired_deg"], rows["mean_surge"], ls=style, marker=marker,
                    color=colours[wind], label=f"{FIG8_LABELS[variant]}, U10 = {wind:g} m/s")
    if switch is not None:
        for wind in FIG8_WINDS:
            rows = switch[switch["wind_speed"] == wind].sort_values("heel_desired_deg")
            ax.plot(rows["heel_desired_deg"], rows["mean_surge"], ls=":", marker="^", color=colours[wind],
                    label=f"paper world, sail x{SAIL_FACTOR:g}, U10 = {wind:g} m/s")
    for wind, heel in PAPER_OPTIMUM_DEG.items():
        ax.axvline(heel, color=colours[wind], lw=0.8, alpha=0.5)
    optima = ", ".join(f"{heel:g}° ({wind:g} m/s, {'blue' if wind == 13.0 else 'red'})"
                       for wind, heel in PAPER_OPTIMUM_DEG.items())
    ax.text(0.99, 0.02, f"vertical lines: the paper's optima,\n{optima}",
            fontsize=7, ha="right", va="bottom", transform=ax.transAxes,
            bbox=dict(facecolor="white", edgecolor="0.8", alpha=0.9))
    ax.set_xlabel("desired heel φ_d [deg]")
    ax.set_ylabel("top speed in surge u [m/s] (mean of the last 50 s)")
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    ax.set_title("Fig. 8 (reproduced): top surge speed against φ_d, beam reach")
    return save_figure(fig, out / FIGURES["8"])




def write_data(analysis: Analysis, out: Path) -> None:
    """The CSV data: Fig. 8's tables, every run's numbers (runs.csv) and the median seed's
    trajectories.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    r = analysis.runs
    for variant, table in analysis.tables.items():
        table.to_csv(out / f"fig8_{variant}.csv", index=False)
    if analysis.switch8 is not None:
        analysis.switch8.to_csv(out / "fig8_paper_sail_switch.csv", index=False)
    rows = pd.DataFrame([{"case": k[0], "world": k[1], "sim": k[2], "seed": k[3], **v} for k, v in r.n.items()]
                        ).sort_values(["case", "world", "sim", "seed"])
    rows.to_csv(out / "runs.csv", index=False)
    main = rows[rows["case"] == "main"]
    over.over_seeds(main, ["world", "sim"], ["roll_amplitude", "max_roll_rate", "mean_surge", "mean_heel",
                                             "wind_ce", "on"]).to_csv(out / "table1.csv", index=False)
    seed = r.median_seed()
    for world in WORLDS:
        for sim in SIMS:
            r.raw[("main", world, sim, seed)]["trajectory"].to_csv(
                out / f"trajectory_{world}_{sim}_seed{seed}.csv", index=False)


def write(analysis: Analysis, out: Path) -> None:
    """The CSV data (:func:`write_data`) and the figures into ``out``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    write_data(analysis, out)
    r = analysis.runs
    plt = setup_matplotlib()
    figure_series(r, out, plt, "heel_deg", ("sim1", "sim1_mean", "sim2", "sim3"), 5,
                  "roll angle φ, all simulations", "φ [deg]")
    figure_series(r, out, plt, "p_deg_s", ("sim1", "sim2"), 6, "roll rate p, simulations 1 and 2", "p [deg/s]")
    figure_series(r, out, plt, "p_deg_s", ("sim2", "sim3"), 7, "roll rate p, simulations 2 and 3", "p [deg/s]")
    figure_intervals(r, out, plt)
    figure_moments(r, out, plt)
    figure_fig8(analysis.tables, analysis.switch8, out, plt)
    if not analysis.smoke:
        figure_seeds(r, out, plt)
        figure_realisations(r, out, plt)
