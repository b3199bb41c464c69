"""Assumption validation, the figures and the data files: what :func:`write` puts in the folder."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco.figures import robust_limits

from ..kit import save_figure, setup_matplotlib
from .analysis import Analysis, delta, pivot
from .scenario import SPEED_HOLDS

FIGURES = {"wind_plane": "wind_plane.png", "phi_star": "phi_star_vs_heel.png"}


def write(analysis: Analysis, out: Path) -> None:
    """``wind_plane.csv``, ``saoud_steady_heel.csv``, ``effects.csv`` and the figures
    (``FIGURES``) into ``out``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    analysis.data.to_csv(out / "wind_plane.csv", index=False)
    analysis.steady.to_csv(out / "saoud_steady_heel.csv", index=False)
    pd.concat(analysis.effects.values(), ignore_index=True).to_csv(out / "effects.csv", index=False)
    plt = setup_matplotlib()
    _wind_plane_figure(plt, analysis.data, out)
    _phi_star_figure(plt, analysis.steady, out)


def heatmap(plt, grid: pd.DataFrame, ax, title: str, unit: str, holds=None) -> None:
    """The metric over TWA x TWS, ✓ where the assumption holds (``holds(values)``). The colour
    scale is robust (2nd-98th percentile when one cell would take it over): cells beyond it
    take the end colour, print their value, and the colorbar's end is an arrow.

    Parameters
    ----------
    plt : module
        matplotlib.pyplot (:func:`studies.kit.setup_matplotlib`).
    grid : pandas.DataFrame
        The metric, rows true wind speed, columns true wind angle.
    ax : matplotlib.axes.Axes
        Where to draw.
    title : str
        The panel's title.
    unit : str
        The colour bar's unit.
    holds : callable, optional
        ``holds(value) -> bool``: where to put a ✓.
    """
    values = grid.to_numpy(dtype=float)
    vmin, vmax, extend = robust_limits(values)
    image = ax.imshow(values, origin="lower", aspect="auto", cmap="viridis", vmin=vmin, vmax=vmax)
    ax.grid(False)
    ax.set_xticks(range(len(grid.columns)), [f"{c:g}" for c in grid.columns])
    ax.set_yticks(range(len(grid.index)), [f"{i:g}" for i in grid.index])
    ax.set_xlabel("true wind angle [deg]")
    ax.set_ylabel("true wind speed [m/s]")
    ax.set_title(title, fontsize=9)
    label = f"[{unit}]" + ("" if extend == "neither" else "\n(2nd-98th percentile; beyond: value printed)")
    plt.colorbar(image, ax=ax, label=label, extend=extend)
    for (i, j), v in np.ndenumerate(values):
        if not np.isfinite(v):
            ax.text(j, i, "×", ha="center", va="center", color="red")  # capsized / no data
            continue
        mark = "✓" if holds is not None and holds(v) else ""
        if v < vmin or v > vmax:
            mark += f"{v:.3g}"
        if mark:
            ax.text(j, i, mark, ha="center", va="center", color="white" if v < vmax else "black",
                    fontsize=8 if len(mark) < 2 else 7)


def _wind_plane_figure(plt, data: pd.DataFrame, out: Path) -> None:
    fig, axes = plt.subplots(2, 3, figsize=(15, 8))
    heatmap(plt, pivot(data, "saoud_robot", "baseline", "ct_cn_ratio"), axes[0, 0],
            "robot: |C_T|/|C_N| (✓ < 0.1)", "-", lambda v: v < 0.1)
    heatmap(plt, 100 * delta(data, "saoud_robot", "ct_off", "steady_speed")
            / pivot(data, "saoud_robot", "baseline", "steady_speed"), axes[0, 1],
            f"robot: speed change with C_T off (✓ |Δ| < {100 * SPEED_HOLDS:g} %)", "%",
            lambda v: abs(v) < 100 * SPEED_HOLDS)
    heatmap(plt, 100 * delta(data, "saoud_robot", "sheeted", "steady_speed")
            / pivot(data, "saoud_robot", "baseline", "steady_speed"), axes[0, 2],
            f"robot: speed, sheeted vs actuated (✓ > −{100 * SPEED_HOLDS:g} %)", "%",
            lambda v: v > -100 * SPEED_HOLDS)
    heatmap(plt, np.degrees(pivot(data, "wille_yacht", "baseline", "pitch_amplitude")), axes[1, 0],
            "yacht: pitch amplitude (✓ < 2°)", "deg", lambda v: v < 2)
    heatmap(plt, 100 * delta(data, "wille_yacht", "four_dof", "steady_speed")
            / pivot(data, "wille_yacht", "baseline", "steady_speed"), axes[1, 1],
            f"yacht: speed, heave+pitch held vs free (✓ |Δ| < {100 * SPEED_HOLDS:g} %)", "%",
            lambda v: abs(v) < 100 * SPEED_HOLDS)
    heatmap(plt, np.degrees(pivot(data, "wille_yacht", "baseline", "keel_aoa")), axes[1, 2],
            "yacht: keel |α| (✓ < 10°, linear lift)", "deg", lambda v: v < 10)
    fig.suptitle("Where the assumptions hold over the wind plane (× = capsized / no data)")
    save_figure(fig, out / FIGURES["wind_plane"])


def _phi_star_figure(plt, steady: pd.DataFrame, out: Path) -> None:
    fig, ax = plt.subplots(figsize=(5, 4))
    for l_phi, group in steady.groupby("l_phi"):
        ax.scatter(group["phi_star_deg"], group["heel_deg"], label=f"l_φ = {l_phi:g} m")
    lim = max(5.0, float(np.nanmax(np.abs(steady[["phi_star_deg", "heel_deg"]].to_numpy()))) * 1.1)
    ax.plot([-lim, lim], [-lim, lim], "k--", lw=1, label="heel = φ*")
    ax.set_xlabel("Saoud's predicted φ* [deg]")
    ax.set_ylabel("6-DOF steady heel [deg]")
    ax.set_title("Static optimum vs heel reached (robot)")
