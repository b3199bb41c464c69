"""The Fig. 6 study's figures and data files."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco.figures import legend_below
from sailmujoco.tasks.sailing import SpeedTrial

from ..kit import save_figure, setup_matplotlib
from ..kit.saoud import TRUE_WIND, WIND_SOURCE, WORLDS
from ..kit.seeds import band
from .analysis import Analysis
from .scenario import ANGLES_DEG, LAWS, SEGMENTS, WORLD_NAMES, Case

COLORS = {"S": "tab:blue", "Bm": "tab:red"}


def write(analysis: Analysis, out: Path) -> None:
    """``timeseries.csv`` (every run on every seed, 10 Hz), ``segments.csv`` (segment means, one
    row per trial and seed) and one figure per l_φ, ``fig6_lphi<l_φ>.png``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    analysis.series.to_csv(out / "timeseries.csv", index=False)
    analysis.rows.to_csv(out / "segments.csv", index=False)
    for l_phi in analysis.l_phis:
        plot(analysis, l_phi, out / f"fig6_lphi{l_phi:g}.png")


def _runs(g: pd.DataFrame, column: str, t: np.ndarray) -> np.ndarray:
    """One row per seed of ``column`` on the times ``t`` (nan after a run stopped)."""
    return np.vstack([run.set_index("t")[column].reindex(t).to_numpy(dtype=float)
                      for _, run in g.groupby("seed", sort=True)])


def plot(analysis: Analysis, l_phi: float, path: Path) -> None:
    """Fig. 6 at one l_φ: speed and roll of S and Bm over time, in both worlds; the mean over the
    seeds with the band of its 95 % interval.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    l_phi : float
        The metacentric height shown [m].
    path : pathlib.Path
        The PNG written.
    """
    series, n = analysis.series, len(analysis.seeds)
    plt = setup_matplotlib()
    fig, axes = plt.subplots(2, 2, figsize=(11, 6.5), sharex=True)
    for col, world in enumerate(WORLDS):
        notes = []
        for law in LAWS:
            case = Case(world, l_phi, law)
            g = series[(series[list(Case._fields)] == pd.Series(case._asdict())).all(axis=1)]
            t = np.sort(g["t"].unique())
            label = f"{law}: {LAWS[law]}"
            band(axes[0, col], t, _runs(g, "speed", t), color=COLORS[law], label=label)
            band(axes[1, col], t, _runs(g, "heel_deg", t), color=COLORS[law], label=label)
            stopped = [seed for seed, end in zip(analysis.values(case, "seed"), analysis.values(case, "end"),
                                                 strict=True) if end < SpeedTrial.duration - 1e-6]
            for seed in stopped:
                run = g[g["seed"] == seed]
                for ax, column in ((axes[0, col], "speed"), (axes[1, col], "heel_deg")):
                    ax.plot(run["t"].iloc[-1], run[column].iloc[-1], "x", color=COLORS[law], ms=9)
            if stopped:
                notes.append(f"{law}: capsizes on {len(stopped)} of {n} seeds")
            lost = sum(analysis.held(case, a) < n for a in ANGLES_DEG)
            if lost and not stopped:
                worst = float(np.max([analysis.values(case, f"max_heading_{a:g}") for a in ANGLES_DEG]))
                notes.append(f"{law}: off heading 0, |ψ| up to {worst:.0f}°")
        title = f"{WORLD_NAMES[world]}, $l_\\phi$ = {l_phi:g} m"
        axes[0, col].set_title(title + ("\n" + "; ".join(notes) if notes else ""), fontsize=10)
        axes[1, col].set_xlabel("time t [s]")
        for ax in axes[:, col]:
            for start, _, _ in SEGMENTS[1:]:
                ax.axvline(start, color="0.5", ls=":", lw=1)
            ax.set_xlim(0, SpeedTrial.duration)
        for start, angle, end in SEGMENTS:
            axes[0, col].text(0.5 * (start + end), 0.03, f"$\\angle v_w^B$ = {angle:g}°", ha="center",
                              transform=axes[0, col].get_xaxis_transform(), fontsize=8, color="0.3")
    for col in range(len(WORLDS)):
        axes[0, col].set_ylabel("(a) boat speed |v| [m/s]")
        axes[1, col].set_ylabel("(b) roll angle $\\phi$ [deg]")
    main = series[(series["l_phi"] == l_phi) & (series["sensor"] == WIND_SOURCE)
                  & (series["hydrostatics"] == "geometric") & (series["paper_model"] == "paper")]
    top = max(1.0, float(np.nanmax(main["speed"])) * 1.1)
    for ax in axes[0]:
        ax.set_ylim(0, top)
    legend_below(fig, axes[0, 0], ncol=2)
    fig.suptitle(f"Saoud Fig. 6 (reproduced): true wind {TRUE_WIND:g} m/s at the sail, heading 0 held "
                 f"by a PID, $l_\\phi$ = {l_phi:g} m; mean of N = {n} seeds, band: its 95 % interval\n"
                 "$\\angle v_w^B$: the direction the wind blows towards, counter-clockwise from the bow "
                 "(10° = wind from nearly astern)", fontsize=11)
    save_figure(fig, path)
