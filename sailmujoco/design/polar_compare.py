"""Sail laws side by side: the steady speed of several controllers over one polar's points, and
each one's ratio to the best fixed sail (``best``), paired by seed, as a table, a summary by
true-wind-angle band, Markdown and a figure (``sailmujoco polar --compare``)."""

from __future__ import annotations

import math

import numpy as np

from .polar import BEST_SAIL_DEG, STEADY_WINDOW_S, speed_bars


def plot_comparison(frames: dict, path, title: str) -> None:
    """Speed against TWA for several sail laws (one panel per TWS).

    Parameters
    ----------
    frames : dict
        Controller name -> its polar (:func:`compute`).
    path : path
        The PNG written.
    title : str
        The figure's title.
    """
    from .. import figures

    plt = figures.pyplot()
    tws_values = sorted(next(iter(frames.values()))["tws"].unique())
    fig, axes = plt.subplots(1, len(tws_values), figsize=(4.2 * len(tws_values), 3.8),
                             squeeze=False, sharey=False)
    styles = {"best": dict(color="k", ls="--", label="best fixed sail (vel_max)")}
    for ax, tws in zip(axes[0], tws_values, strict=True):
        for name, frame in frames.items():
            group = frame[frame["tws"] == tws]
            style = styles.get(name, {"label": name})
            (line,) = ax.plot(group["twa"], group["speed"], marker="o", ms=3, **style)
            speed_bars(ax, group["twa"], group, line.get_color())
        ax.set_title(f"TWS {tws:g} m/s")
        ax.set_xlabel("true wind angle [deg]")
        ax.set_ylabel("steady speed [m/s]")
    figures.legend_below(fig, axes[0][0], ncol=len(frames))
    fig.suptitle(title)
    figures.save(fig, path, dpi=120)


# TWA bands of the comparison's summary: label, from TWA (included) to TWA (excluded), deg.
TWA_BANDS = (("close-hauled", 0.0, 60.0), ("close reach", 60.0, 90.0), ("beam to broad reach", 90.0, 135.0),
             ("running", 135.0, math.inf))


def comparison_table(frames: dict):
    """One row per (TWS, TWA): each controller's steady speed [m/s] and the ratios to ``best``.

    When ``best`` is among ``frames``, each other controller's ratio to it (``<name>/best``: speed /
    best speed, a plain ratio; 0.9 is 10 % slower than the best fixed sail). Frames with a ``seed``
    column (:func:`finished_points`) are compared seed by seed: a speed is the mean over the
    point's seeds and the ratio the mean per-seed ratio, with its 95 % interval
    (``<name>/best_low``, ``<name>/best_high``; :func:`sailmujoco.stats.paired_ratio`). A point a
    controller did not finish is missing (NaN) in its columns.

    Parameters
    ----------
    frames : dict
        Controller name -> its points (:func:`finished_points`, or a polar without seeds).

    Returns
    -------
    pandas.DataFrame
    """
    from .. import stats

    per_seed = {name: (frame if "seed" in frame else frame.assign(seed=0)) for name, frame in frames.items()}
    table = None
    for name, frame in per_seed.items():
        part = frame.groupby(["tws", "twa"], as_index=False)["speed"].mean().rename(columns={"speed": name})
        table = part if table is None else table.merge(part, on=["tws", "twa"], how="outer")
    table = table.sort_values(["tws", "twa"]).reset_index(drop=True)
    if "best" in frames:
        best = per_seed["best"][["tws", "twa", "seed", "speed"]]
        for name, frame in per_seed.items():
            if name == "best":
                continue
            both = frame[["tws", "twa", "seed", "speed"]].merge(best, on=["tws", "twa", "seed"],
                                                                 suffixes=("", "_best"))
            ratios = {}
            for key, group in both.groupby(["tws", "twa"]):
                ratios[key] = stats.paired_ratio(group["speed"], group["speed_best"])
            keys = list(zip(table["tws"], table["twa"], strict=True))
            nan = stats.Interval(np.nan, np.nan, np.nan, 0)
            got = [ratios.get(k, nan) for k in keys]
            table[f"{name}/best"] = [g.mean for g in got]
            table[f"{name}/best_low"] = [g.low for g in got]
            table[f"{name}/best_high"] = [g.high for g in got]
    return table


def ratio_summary(table, bands=TWA_BANDS):
    """Per controller and TWA band: the lowest and highest ``<name>/best`` ratio and where each is.

    Where: TWS, TWA, the controller's and the best speed, over every TWS in the band.

    Parameters
    ----------
    table : pandas.DataFrame
        From :func:`comparison_table`.
    bands : tuple of (str, float, float)
        Label, from TWA (included) to TWA (excluded), deg.

    Returns
    -------
    pandas.DataFrame
        Empty when the table has no ratio columns.
    """
    import pandas as pd

    rows = []
    for column in _ratio_columns(table):
        name = column[: -len("/best")]
        for label, low, high in bands:
            band = table[(table["twa"] >= low) & (table["twa"] < high)].dropna(subset=[column])
            if band.empty:
                continue
            lo, hi = band.loc[band[column].idxmin()], band.loc[band[column].idxmax()]
            rows.append({"controller": name, "band": label, "twa_low": float(band["twa"].min()),
                         "twa_high": float(band["twa"].max()), "ratio_min": float(lo[column]),
                         "ratio_max": float(hi[column]), "min_tws": float(lo["tws"]),
                         "min_twa": float(lo["twa"]), "min_speed": float(lo[name]),
                         "min_best": float(lo["best"]), "max_tws": float(hi["tws"]),
                         "max_twa": float(hi["twa"]), "max_speed": float(hi[name]),
                         "max_best": float(hi["best"])})
    return pd.DataFrame(rows)


def comparison_markdown(table, summary, command: str = "", settings: str = "") -> str:
    """``compare.md``: the summary by TWA band, then the full table (speeds in m/s).

    Parameters
    ----------
    table : pandas.DataFrame
        From :func:`comparison_table`.
    summary : pandas.DataFrame
        From :func:`ratio_summary`.
    command : str
        The command that made it, quoted in the text ("" for none).
    settings : str
        Its settings, after the command ("" for none).
    """
    lines = ["# Steady speed by sail law", ""]
    if command:
        lines += [f"Made by `{command}`" + (f" ({settings})" if settings else "") + ". *speed*: the "
                  f"mean speed over ground in the last {STEADY_WINDOW_S:g} s of each run, "
                  + ("in gusts." if "gusts" in settings else "wind steady, no gusts."), ""]
    if len(summary):
        lines += ["*ratio*: the controller's steady speed / the best fixed sail's (`best`, brute force "
                  f"over sail angles {BEST_SAIL_DEG[0]}-{BEST_SAIL_DEG[-1]}° in "
                  f"{BEST_SAIL_DEG[1] - BEST_SAIL_DEG[0]}° steps), a plain ratio: 0.90 is 10 % slower, "
                  "1.02 is 2 % faster.", "",
                  "| controller | TWA band | TWA [deg] | ratio min (TWS, TWA: speed / best) "
                  "| ratio max (TWS, TWA: speed / best) |", "|---|---|---|---|---|"]
        for r in summary.itertuples():
            low = f"{r.min_tws:g} m/s, {r.min_twa:g}°: {r.min_speed:.2f} / {r.min_best:.2f} m/s"
            high = f"{r.max_tws:g} m/s, {r.max_twa:g}°: {r.max_speed:.2f} / {r.max_best:.2f} m/s"
            lines.append(f"| {r.controller} | {r.band} | {r.twa_low:g}-{r.twa_high:g} "
                         f"| {r.ratio_min:.2f} ({low}) | {r.ratio_max:.2f} ({high}) |")
        lines.append("")
    ratios = _ratio_columns(table)
    speeds = [c for c in table.columns if c not in ("tws", "twa") and "/best" not in str(c)]
    seeded = any(table[f"{c}_low"].notna().any() for c in ratios)
    if seeded:
        lines += ["Speeds are means over seeds; each ratio is the mean of its per-seed ratios with its 95 % "
                  "interval, `mean [low, high]` (the same start and wind in both laws).", ""]
    lines += ["| TWS [m/s] | TWA [deg] | " + " | ".join(f"{c} [m/s]" for c in speeds)
              + "".join(f" | {c}" for c in ratios) + " |",
              "|" + "---|" * (2 + len(speeds) + len(ratios))]
    for _, row in table.iterrows():
        cells = [f"{row['tws']:g}", f"{row['twa']:g}"] + [_cell(row[c], 2) for c in speeds]
        cells += [_ratio_cell(row, c) if seeded else _cell(row[c], 2) for c in ratios]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def _cell(value, digits: int) -> str:
    return "—" if not np.isfinite(value) else f"{value:.{digits}f}"


def _ratio_columns(table) -> list[str]:
    """The ``<name>/best`` ratio columns of a comparison table (not their interval ends)."""
    return [c for c in table.columns if str(c).endswith("/best")]


def _ratio_cell(row, column: str) -> str:
    from .. import stats

    return stats.Interval(row[column], row[f"{column}_low"], row[f"{column}_high"], 0).fixed(2)
