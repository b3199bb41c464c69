"""A boat's polar held against a reference polar: the table of ratios, its markdown and its figure.

The fixed-angle points are compared where both polars have the same TWS (within
:data:`WIND_MATCH`) and TWA; the beat as
the VMG optimum (ours: the best VMG over our own upwind angles; the reference's: its ``beat`` row).
Points from ``SPINNAKER_FROM`` deg on are left out: ORC's polars assume a spinnaker there, and
no boat here carries one.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from .polar import best_vmg, half_polar
from .reference_polar import KNOT, ReferencePolar

SPINNAKER_FROM = 110.0  # deg, ORC's polars set a spinnaker from this TWA on
BEAT_TWA = (36.0, 39.0, 42.0, 45.0, 48.0)  # deg, our upwind angles for the beat beside the fixed ones
WIND_MATCH = 0.01  # m/s: our wind and the reference's are the same point within this (10 kn: 5.14)


def polar_axes(reference: ReferencePolar) -> tuple[list, list]:
    """The TWS (m/s at 10 m) and TWA (deg) a boat is sailed at to be held against ``reference``.

    Every TWS of the file; its fixed angles below :data:`SPINNAKER_FROM` and :data:`BEAT_TWA`.

    Parameters
    ----------
    reference : ReferencePolar
        The reference.
    """
    fixed = reference.fixed()
    twa = sorted({float(a) for a in fixed["twa"] if a < SPINNAKER_FROM} | set(BEAT_TWA))
    return sorted({float(s) for s in reference.table["tws"]}), twa


def reference_table(ours: pd.DataFrame, reference: ReferencePolar) -> pd.DataFrame:
    """One row per compared point: fixed angles where both polars have them, then the beats.

    Parameters
    ----------
    ours : pandas.DataFrame
        Our polar (:func:`sailmujoco.design.polar.compute`: tws in m/s at 10 m, twa, speed).
    reference : ReferencePolar
        The reference.

    Returns
    -------
    pandas.DataFrame
        Columns point ("fixed" or "beat"), tws_file (the file's own wind), tws (m/s), twa and
        twa_reference (deg; equal for fixed points), ours_kn, reference_kn (boat speed, or VMG for
        a beat), ratio (ours / reference).
    """
    rows = []
    for _, ref in reference.fixed().iterrows():
        if ref["twa"] >= SPINNAKER_FROM:
            continue
        match = ours[np.isclose(ours["tws"], ref["tws"], rtol=0.0, atol=WIND_MATCH)
                     & np.isclose(ours["twa"], ref["twa"])]
        if match.empty:
            continue
        rows.append(_row("fixed", ref, float(ref["twa"]), float(match["speed"].iloc[0]), ref["speed"]))
    vmg = best_vmg(ours)
    for _, ref in reference.optimum("beat").iterrows():
        at = [t for t in vmg if math.isclose(t, ref["tws"], abs_tol=WIND_MATCH)]
        if not at:
            continue
        angle, value = vmg[at[0]]["upwind"]
        rows.append(_row("beat", ref, float(angle), float(value), ref["vmg"]))
    return pd.DataFrame(rows, columns=["point", "tws_file", "tws", "twa", "twa_reference", "ours_kn",
                                       "reference_kn", "ratio"])


def _row(point: str, ref, twa: float, ours: float, theirs: float) -> dict:
    return {"point": point, "tws_file": float(ref["tws_file"]), "tws": float(ref["tws"]), "twa": twa,
            "twa_reference": float(ref["twa"]), "ours_kn": ours / KNOT, "reference_kn": theirs / KNOT,
            "ratio": ours / theirs if theirs > 0 else math.nan}


def reference_markdown(table: pd.DataFrame, name: str, band: float = 0.10) -> str:
    """The comparison as markdown: speeds in knots, ratios, and the points outside ``band``.

    Parameters
    ----------
    table : pandas.DataFrame
        :func:`reference_table`'s result.
    name : str
        The reference's name (its file).
    band : float
        The relative miss a point is flagged beyond.
    """
    lines = [f"| point | TWS (as in {name}) | TWA ours / ref [deg] | ours [kn] | reference [kn] "
             "| ours / ref |",
             "|---|---|---|---|---|---|"]
    for _, r in table.iterrows():
        what = "speed" if r["point"] == "fixed" else "beat VMG"
        flag = " **outside**" if abs(r["ratio"] - 1.0) > band else ""
        lines.append(f"| {what} | {r['tws_file']:g} | {r['twa']:g} / {r['twa_reference']:g} | "
                     f"{r['ours_kn']:.2f} | {r['reference_kn']:.2f} | {r['ratio']:.2f}{flag} |")
    outside = int((np.abs(table["ratio"] - 1.0) > band).sum())
    lines += ["", f"{outside} of {len(table)} points are more than {band:.0%} from the reference."]
    return "\n".join(lines) + "\n"


def plot_reference(ours: pd.DataFrame, reference: ReferencePolar, path, title: str) -> None:
    """Our polar (solid) and the reference's (dashed), one colour per TWS, speeds in knots.

    Parameters
    ----------
    ours : pandas.DataFrame
        Our polar.
    reference : ReferencePolar
        The reference.
    path : path
        The PNG written.
    title : str
        The figure's title.
    """
    from .. import figures

    fig, ax = half_polar((6.5, 6.8))
    fixed = reference.fixed()
    for tws, group in ours.groupby("tws"):
        ref = fixed[np.isclose(fixed["tws"], tws, rtol=0.0, atol=WIND_MATCH)].sort_values("twa")
        label = f"{ref['tws_file'].iloc[0]:g} kn" if not ref.empty else f"{tws:g} m/s"
        group = group.sort_values("twa")
        (line,) = ax.plot(np.radians(group["twa"]), group["speed"] / KNOT, "-o", ms=3,
                          label=f"ours, TWS {label}")
        if not ref.empty:
            ax.plot(np.radians(ref["twa"]), ref["speed"] / KNOT, "--", color=line.get_color(), lw=1.2,
                    label=f"reference, TWS {label}")
    ax.set_xlabel("true wind angle TWA [deg]; solid: ours, dashed: the reference\n"
                  f"(the reference carries a spinnaker from {SPINNAKER_FROM:g} deg)")
    ax.set_title(title + "\nradius: boat speed [kn]", fontsize=10)
    figures.legend_below(fig, ax, ncol=2)
    figures.save(fig, path, dpi=120)
