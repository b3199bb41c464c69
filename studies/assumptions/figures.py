"""Assumption validation, the figures and the data files: what :func:`write` puts in the folder.

The heat maps show each point's mean over its seeds and mark its verdict (✓ holds, ? undecided);
the effects figure shows each switch's speed difference at every point with its 95 % interval,
and the φ* figure the heel reached with its interval over seeds.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco.figures import robust_limits

from ..kit import save_figure, setup_matplotlib
from ..kit import seeds as over
from .analysis import Analysis, judge_points
from .headline_numbers import steady_cases
from .scenario import BOATS, BUILT, SPEED_HOLDS

FIGURES = {"wind_plane": "wind_plane.png", "phi_star": "phi_star_vs_heel.png", "effects": "effects.png"}
MARKS = {"holds": "✓"}  # a point's verdict in a heat map (anything else undecided: "?"; breaks: none)


def write(analysis: Analysis, out: Path) -> None:
    """``wind_plane.csv`` (every seed's row), ``saoud_steady_heel.csv`` (every seed's),
    ``effects.csv`` (each switch against the boat as built, seed by seed),
    ``effect_points.csv`` (the same over seeds: means, intervals and verdicts per point) and
    the figures (``FIGURES``) into ``out``.

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
    pd.concat([p.assign(boat=b, config=c) for (b, c), p in analysis.points.items()],
              ignore_index=True).to_csv(out / "effect_points.csv", index=False)
    plt = setup_matplotlib()
    _wind_plane_figure(plt, analysis, out)
    _phi_star_figure(plt, analysis, out)
    _effects_figure(plt, analysis, out)


def heatmap(plt, grid: pd.DataFrame, ax, title: str, unit: str, holds=None, marks=None) -> None:
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
    marks : pandas.DataFrame, optional
        A text per cell (the same rows and columns as ``grid``), in place of ``holds``.
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
        if marks is not None:
            mark = str(marks.iloc[i, j]) if isinstance(marks.iloc[i, j], str) else ""
        else:
            mark = "✓" if holds is not None and holds(v) else ""
        if v < vmin or v > vmax:
            mark += f"{v:.3g}"
        if mark:
            ax.text(j, i, mark, ha="center", va="center", color="white" if v < vmax else "black",
                    fontsize=8 if len(mark) < 2 else 7)


def _grid(points: pd.DataFrame, column: str, scale: float = 1.0) -> pd.DataFrame:
    """A column of a table of points over the plane: rows tws, columns twa."""
    return (points.assign(value=points[column] * scale)
            .pivot_table(index="tws", columns="twa", values="value", dropna=False))


def _marks(points: pd.DataFrame, verdicts) -> pd.DataFrame:
    """Each point's verdict as its heat-map mark (``MARKS``; undecided: ``?``)."""
    text = [MARKS.get(v, "?" if v.startswith("undecided") else "") for v in verdicts]
    return points.assign(mark=text).pivot(index="tws", columns="twa", values="mark")


def _wind_plane_figure(plt, a: Analysis, out: Path) -> None:
    robot, yacht = a.plane["saoud_robot"], a.plane["wille_yacht"]
    ct, sheet, four = (a.points[("saoud_robot", "ct_off")], a.points[("saoud_robot", "sheeted")],
                       a.points[("wille_yacht", "four_dof")])
    fig, axes = plt.subplots(2, 3, figsize=(15, 8))
    heatmap(plt, _grid(robot, "ct_cn_ratio"), axes[0, 0], "robot: |C_T|/|C_N| (✓ < 0.1)", "-",
            marks=_marks(robot, judge_points(robot, "ct_cn_ratio", 0.1)))
    heatmap(plt, _grid(ct, "speed_rel", 100), axes[0, 1],
            f"robot: speed, C_T on vs off (✓ |Δ| < {100 * SPEED_HOLDS:g} %)", "%",
            marks=_marks(ct, ct["speed_verdict"]))
    heatmap(plt, _grid(sheet, "speed_rel", 100), axes[0, 2],
            f"robot: speed, sheeted vs actuated (✓ > −{100 * SPEED_HOLDS:g} %)", "%",
            marks=_marks(sheet, sheet["speed_verdict"]))
    heatmap(plt, _grid(yacht, "pitch_amplitude_deg"), axes[1, 0], "yacht: pitch amplitude (✓ < 2°)", "deg",
            marks=_marks(yacht, judge_points(yacht, "pitch_amplitude_deg", 2.0)))
    heatmap(plt, _grid(four, "speed_rel", 100), axes[1, 1],
            f"yacht: speed, 6-DOF vs heave+pitch held (✓ |Δ| < {100 * SPEED_HOLDS:g} %)", "%",
            marks=_marks(four, four["speed_verdict"]))
    heatmap(plt, _grid(yacht, "keel_aoa_deg"), axes[1, 2], "yacht: keel |α| (✓ < 10°, linear lift)", "deg",
            marks=_marks(yacht, judge_points(yacht, "keel_aoa_deg", 10.0)))
    fig.suptitle(f"Where the assumptions hold over the wind plane: means over {len(a.plane_seeds)} seeds; "
                 "✓ holds, ? undecided (95 % interval), × no data")
    save_figure(fig, out / FIGURES["wind_plane"])


def _effects_figure(plt, a: Analysis, out: Path) -> None:
    """Each switch's speed difference (as built against the paper's form, % of the paper's) at
    every point, mean over seeds with its 95 % interval, and the ±tolerance band."""
    configs = ["ct_off", "four_dof", "sheeted", *(c for c, _, _, _ in BUILT)]
    fig, axes = plt.subplots(len(BOATS), 1, figsize=(15, 8), sharey=True)
    for ax, boat in zip(axes, BOATS, strict=True):
        ticks, labels, x0 = [], [], 0
        for k, config in enumerate(c for c in configs if (boat, c) in a.points):
            pts = a.points[(boat, config)]
            x = x0 + np.arange(len(pts))
            intervals = [i.scaled(100) for i in over_intervals(pts)]
            over.errorbar(ax, x, intervals, fmt="o", ms=3, color=f"C{k}", label=config)
            ticks.append(x0 + (len(pts) - 1) / 2)
            labels.append(config)
            x0 += len(pts) + 3
        ax.axhspan(-100 * SPEED_HOLDS, 100 * SPEED_HOLDS, color="0.85", zorder=0)
        ax.set_yscale("symlog", linthresh=10)
        ax.set_yticks([-100, -50, -10, 0, 10, 50, 100, 500], ["−100", "−50", "−10", "0", "10", "50", "100", "500"])
        ax.set_xticks(ticks, labels, fontsize=8)
        ax.set_ylabel("speed, as built vs paper [%]")
        pts = pd.concat([a.points[(boat, c)] for c in configs if (boat, c) in a.points])
        ax.set_title(f"{boat}: each point of the plane ({pts['tws'].min():g}-{pts['tws'].max():g} m/s × "
                     f"{pts['twa'].min():g}-{pts['twa'].max():g}°, by speed then angle), mean over "
                     f"{len(a.plane_seeds)} seeds with its 95 % interval; grey: ±{100 * SPEED_HOLDS:g} %",
                     fontsize=9)
    save_figure(fig, out / FIGURES["effects"])


def over_intervals(points: pd.DataFrame) -> list:
    """The speed difference's interval at each point of a table of points.

    Parameters
    ----------
    points : pandas.DataFrame
        Wind-plane points over seeds, with ``speed_rel`` and its interval columns.
    """
    return [over.row_interval(r, "speed_rel") for _, r in points.iterrows()]


def _phi_star_figure(plt, a: Analysis, out: Path) -> None:
    cases = steady_cases(a)
    fig, ax = plt.subplots(figsize=(5, 4))
    for k, (l_phi, group) in enumerate(cases.groupby("l_phi")):
        over.errorbar(ax, group["phi_star_deg"].to_numpy(dtype=float),
                      [over.row_interval(r, "heel_deg") for _, r in group.iterrows()],
                      fmt="o", color=f"C{k}", label=f"l_φ = {l_phi:g} m")
    values = np.abs(cases[["phi_star_deg", "heel_deg"]].to_numpy(dtype=float))
    lim = max(5.0, float(np.nanmax(values)) * 1.1) if np.isfinite(values).any() else 5.0
    ax.plot([-lim, lim], [-lim, lim], "k--", lw=1, label="heel = φ*")
    ax.set_xlabel("Saoud's predicted φ* [deg]")
    ax.set_ylabel("6-DOF steady heel [deg]")
    ax.set_title(f"Static optimum vs heel reached (robot), {len(a.single_seeds)} seeds", fontsize=9)
    ax.legend(fontsize=8)
    save_figure(fig, out / FIGURES["phi_star"])
