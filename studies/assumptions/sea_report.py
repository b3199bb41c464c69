"""Assumption validation, the sea's part of the report: its CSV files, figures and sections.

:func:`write` adds ``SEA_FILES`` and ``SEA_FIGURES`` to the study's folder, :func:`sections`
the sections after the study's own, :func:`summary_sentence` one sentence of the summary.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd

from sailmujoco import constants
from sailmujoco.forces.waves import BAND
from sailmujoco.options import PM_HS, PM_PEAK, U19_5_PER_U10, fully_developed_sea

from ..kit import save_figure, setup_matplotlib
from ..kit.saoud import TRUE_WIND
from ..kit.verdict import value_range
from ..kit.wille import TABLE1_WIND, TABLE1_WINDOW
from . import sea
from .figures import heatmap
from .figures import write as write_figures
from .sea_analysis import (
    DIFFERENCE,
    HEADING_LOST_DEG,
    SAILING,
    TABLE1,
    SeaAnalysis,
    metrics_of,
)
from .sea_mechanisms import PATH_WORDS, mechanism_text, mechanisms_section, paths
from .table import headline as table_headline

SEA_FILES = {"saoud_robot": "sea_wind_plane.csv", "table1": "sea_table1.csv", "saoud": "sea_saoud.csv",
             "mechanisms": "sea_mechanisms.csv"}  # the wind plane's file holds both boats
SEA_FIGURES = {"plane": "sea_wind_plane.png", "series": "sea_heights.png"}


def write(analysis, out: Path) -> None:
    """The study's figures and data (:func:`.figures.write`), then the sea's: ``SEA_FILES``
    and ``SEA_FIGURES``.

    Parameters
    ----------
    analysis : studies.assumptions.analysis.Analysis
        The study's numbers (``analysis.sea``: the sea's).
    out : pathlib.Path
        The study's folder.
    """
    write_figures(analysis, out)
    out, s = Path(out), analysis.sea
    pd.concat([s.tables["saoud_robot"], s.tables["wille_yacht"]], ignore_index=True).to_csv(
        out / SEA_FILES["saoud_robot"], index=False)
    s.tables["table1"].to_csv(out / SEA_FILES["table1"], index=False)
    s.tables["saoud"].to_csv(out / SEA_FILES["saoud"], index=False)
    s.mechanisms.to_csv(out / SEA_FILES["mechanisms"], index=False)
    plt = setup_matplotlib()
    _plane_figure(plt, s, out)
    _series_figure(plt, s, out)


def headline(analysis) -> dict:
    """The study's headline numbers (:func:`.table.headline`) and the sea's: the largest
    relative change of each metric per series over the cases that keep their heading, the
    number of sea runs that stopped early and of cases that lost their heading.

    Parameters
    ----------
    analysis : studies.assumptions.analysis.Analysis
        The study's numbers.
    """
    out = table_headline(analysis)
    for series, table in analysis.sea.tables.items():
        for metric in metrics_of(series):
            rel = _kept(table)[f"{metric}_rel"].abs().to_numpy(dtype=float)
            out[f"sea_{series}_{metric}_change_max"] = float(np.nanmax(rel)) if np.isfinite(rel).any() else math.nan
        out[f"sea_{series}_stopped"] = int((table["status"] != "ok").sum())
        out[f"sea_{series}_lost_heading"] = int((table["lost_heading"] != "").sum())
    out["sea_mechanism_rows"] = len(analysis.sea.mechanisms)
    taken = paths(analysis.sea)
    for path in PATH_WORDS:
        out[f"sea_differences_by_{path}"] = taken.count(path)
    return out


def _span(values, fmt: str = "{:.2f}", scale: float = 1.0) -> str:
    """:func:`.kit.verdict.value_range`, one value where both ends read the same."""
    text = value_range(values, scale, fmt)
    low, _, high = text.partition(" … ")
    return low if low == high else text


def _kept(table: pd.DataFrame) -> pd.DataFrame:
    """The cases where calm and sea runs keep their heading."""
    return table[table["lost_heading"] == ""]


def _pivot(table: pd.DataFrame, column: str) -> pd.DataFrame:
    return table.pivot_table(index="tws", columns="twa", values=column, dropna=False)


def _mark_lost(plt, ax, table: pd.DataFrame) -> None:
    """A red hatched frame and "lost: calm | sea | both" on each cell whose calm or sea run lost
    its heading."""
    speeds, angles = sorted(set(table["tws"])), sorted(set(table["twa"]))
    for _, row in table[table["lost_heading"] != ""].iterrows():
        i, j = speeds.index(row["tws"]), angles.index(row["twa"])
        ax.add_patch(plt.Rectangle((j - 0.45, i - 0.45), 0.9, 0.9, fill=False, edgecolor="red", hatch="//",
                                   linewidth=1.5, alpha=0.6))
        which = "both" if row["lost_heading"] == "calm, sea" else row["lost_heading"]
        ax.text(j, i - 0.3, f"lost: {which}", ha="center", va="center", color="red", fontsize=7,
                bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8, "pad": 1.0})


def _plane_figure(plt, s: SeaAnalysis, out: Path) -> None:
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    for row, boat in enumerate(("saoud_robot", "wille_yacht")):
        table = s.tables[boat]
        heatmap(plt, 100 * _pivot(table, "speed_rel"), axes[row, 0],
                f"{boat}: steady speed in the sea vs calm (✓ |Δ| < {100 * DIFFERENCE:g} %)", "%",
                lambda v: abs(v) < 100 * DIFFERENCE)
        heatmap(plt, _pivot(table, "roll_sd_sea"), axes[row, 1],
                f"{boat}: roll (heel's SD) in the sea (calm: {value_range(table['roll_sd_calm'], fmt='{:.2f}')}°)",
                "deg")
        for ax in axes[row]:
            _mark_lost(plt, ax, table)
    fig.suptitle("What the sea a wind raises does over the wind plane (× = no data)\nred hatch: the calm or "
                 f"sea run lost its heading (heading error RMS > {HEADING_LOST_DEG:g}°)")
    save_figure(fig, out / SEA_FIGURES["plane"])


def _series_figure(plt, s: SeaAnalysis, out: Path) -> None:
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    t1 = s.tables["table1"]
    for sim, group in t1.groupby("sim"):
        calm = float(group["roll_sd_calm"].iloc[0])
        axes[0].plot([0.0, *group["hs"]], [calm, *group["roll_sd_sea"]], "o-", label=sim)
    _mark_stops(axes[0], t1)
    axes[0].set_title("Wille's roll controller (Table 1): roll, the heel's SD", fontsize=9)
    sa = s.tables["saoud"]
    for metric in ("roll_sd", "heel", "pitch_sd"):
        axes[1].plot([0.0, *sa["hs"]], [float(sa[f"{metric}_calm"].iloc[0]), *sa[f"{metric}_sea"]], "o-",
                     label=SAILING[metric][0].split(" (")[0])
    _mark_stops(axes[1], sa)
    axes[1].set_title("Saoud's optimal sail (robot, beam reach)", fontsize=9)
    for ax in axes:
        ax.set_xlabel("significant wave height Hs [m] (0: calm water)")
        ax.set_ylabel("[deg]")
    axes[0].legend(fontsize=8)
    # below the axes: the three lines and the marks leave no corner free
    axes[1].legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=4)
    fig.suptitle("Fully developed seas of height Hs, from the wind's bearing")
    save_figure(fig, out / SEA_FIGURES["series"])


def _mark_stops(ax, table: pd.DataFrame) -> None:
    """A red cross on the roll of each run in a sea that stopped early, a red circle where it
    lost its heading."""
    stopped = table[table["status"] != "ok"]
    if len(stopped):
        ax.scatter(stopped["hs"], stopped["roll_sd_sea"], marker="x", s=80, color="red", label="stopped early",
                   zorder=3)
    lost = table[table["lost_heading"].str.contains("sea")]
    if len(lost):
        ax.scatter(lost["hs"], lost["roll_sd_sea"], marker="o", s=120, facecolors="none", edgecolors="red",
                   label="lost its heading", zorder=3)


def summary_sentence(s: SeaAnalysis) -> str:
    """One sentence for the summary: the speed change over the wind plane, the roll, the stops,
    the cases that lost their heading and the paths the differences take.

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    """
    plane = pd.concat([s.tables["saoud_robot"], s.tables["wille_yacht"]])
    kept = _kept(plane)
    stopped = sum(int((t["status"] != "ok").sum()) for t in s.tables.values())
    lost = sum(int((t["lost_heading"] != "").sum()) for t in s.tables.values())
    runs = sum(len(t) for t in s.tables.values())
    taken = paths(s)
    stops = f"{stopped} of {runs} runs in a sea stopped early, " if stopped else ""
    return (f"In a sea, where the boat keeps its heading, the steady speed changes by "
            f"{value_range(kept['speed_rel'], 100, '{:+.0f}')} % and the roll σ reaches "
            f"{value_range(kept['roll_sd_sea'], fmt='{:.1f}').split(' … ')[-1]}°; {stops}"
            f"{lost} of {runs} cases lost their heading; of {len(taken)} differences beyond "
            f"{100 * DIFFERENCE:g} %, " + ", ".join(
                f"{taken.count(p)} come by {PATH_WORDS[p]}" if p != "stalled"
                else f"{taken.count(p)} not attributed (a rerun lost its heading)"
                for p in PATH_WORDS if taken.count(p))
            + " (sections \"The sea against calm water\", \"Where each difference comes from\").")


def _stops(table: pd.DataFrame) -> str:
    stopped = table[table["status"] != "ok"]
    if stopped.empty:
        return "Every run in a sea sailed to its end."
    return f"{len(stopped)} of {len(table)} runs in a sea stopped early: " + "; ".join(
        f"{row['case']}: {row['stopped'].splitlines()[0] if row['stopped'] else row['status']}"
        for _, row in stopped.iterrows()) + "."


def _plane_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for boat in ("saoud_robot", "wille_yacht"):
        t = _kept(s.tables[boat])
        for metric, (label, unit, _) in SAILING.items():
            rel = t[f"{metric}_rel"].to_numpy(dtype=float)
            top = t.iloc[np.nanargmax(np.abs(rel))] if np.isfinite(rel).any() else None
            rows.append({
                "boat": boat, "metric": f"{label} [{unit}]",
                "calm": value_range(t[f"{metric}_calm"], fmt="{:.2f}"),
                "in the sea": value_range(t[f"{metric}_sea"], fmt="{:.2f}"),
                "change": value_range(t[f"{metric}_change"], fmt="{:+.2f}") + f" {unit}",
                f"beyond ±{100 * DIFFERENCE:g} %": f"{int((np.abs(rel) > DIFFERENCE).sum())} of {len(t)}"
                + f" ({len(s.tables[boat]) - len(t)} lost their heading)",
                "largest": "—" if top is None else f"{100 * top[f'{metric}_rel']:+.0f} % at {top['case']}",
                "the sea's path, each difference": mechanism_text(s, boat, metric)})
    return rows


def _sea_state_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    robot, yacht = s.tables["saoud_robot"], s.tables["wille_yacht"]
    for tws in sorted(set(robot["tws"])):
        r, y = robot[robot["tws"] == tws].iloc[0], yacht[yacht["tws"] == tws].iloc[0]
        rows.append({"true wind U10 [m/s]": f"{tws:g}", "robot Hs [m]": r["hs"], "robot Tp [s]": r["tp"],
                     "yacht Hs [m]": y["hs"], "yacht Tp [s]": y["tp"]})
    return rows


def _plane_section(r, s: SeaAnalysis) -> None:
    components = int(s.tables["saoud_robot"]["n_components"].iloc[0])
    r.section("The sea against calm water: the wind plane", (
        "Each boat sails the study's wind plane (heading held, steady wind) in the sea that point's "
        "wind raises, against the same run in calm water. The sea is fetch-limited JONSWAP (γ 3.3; "
        "Hs = 1.6e-3 χ^½ U10²/g, Tp = 0.2857 χ^⅓ U10/g, χ = g F/U10², each at most its fully "
        "developed value; Hasselmann et al. 1973, Shore Protection Manual 1984 eqs. 3-33, 3-34), "
        "long-crested, the waves from the wind's bearing, seed 0, "
        + f"{components} components"
        + ". The fetch F: " + "; ".join(f"{b} {sea.FETCH[b] / 1000:g} km ({sea.FETCH_REASON[b]})"
                                         for b in sea.FETCH) + "."))
    r.table(_sea_state_rows(s))
    r.paragraph(
        f"Each metric over the steady window (the last third of the run): a difference counts where "
        f"|sea − calm| exceeds {100 * DIFFERENCE:g} % of the calm value, or of the floor where the calm "
        "value is smaller (" + ", ".join(f"{label} {floor:g} {unit}" for label, unit, floor in SAILING.values())
        + "; heel and drift angle as magnitudes). " + ROLL_TEXT + " " + _lost_text() + " The table's "
        "ranges and counts are over the cases where both runs keep their heading. The last "
        "column: how many of those differences the waves' forces on the hull explain, how many the "
        "orbital flow at the foils, and how many either path makes alone (section \"Where each "
        "difference comes from\").")
    r.table(_plane_rows(s))
    r.paragraph(" ".join(f"{boat}: {_stops(s.tables[boat])} {_lost_list(s.tables[boat])}"
                         for boat in ("saoud_robot", "wille_yacht")))
    r.figure(SEA_FIGURES["plane"], "Steady speed in the sea against calm water, and the roll (the heel's "
                                   "standard deviation) in the sea, over true wind angle × true wind speed; "
                                   "hatched: a case that lost its heading")


ROLL_TEXT = (
    "The roll is the heel's standard deviation σ about its mean over the window (the significant roll "
    "amplitude is 2σ): in a random sea the heel's half peak-to-peak is an extreme value, which grows "
    "with the number of roll cycles in the window (about σ (2 ln N)^½ for N cycles), so it says as much "
    "about the window's length as about the sea; σ does not. Calm water gets the same statistic.")


def _lost_text() -> str:
    return (f"A run whose heading error RMS over the window exceeds {HEADING_LOST_DEG:g}° lost its heading "
            "(it turned head to wind and stalled, bore away, or yawed that far about its course): the "
            "difference of such a case compares a boat sailing its course with one that is not, and is "
            "marked, not counted.")


def _lost_list(table: pd.DataFrame) -> str:
    lost = table[table["lost_heading"] != ""]
    if lost.empty:
        return "Every case keeps its heading."
    return (f"{len(lost)} of {len(table)} cases lost their heading: " + "; ".join(
        f"{row['case']} ({row['lost_heading']}: heading error RMS {row['heading_rms_calm']:.0f}° calm, "
        f"{row['heading_rms_sea']:.0f}° in the sea)" for _, row in lost.iterrows()) + ".")


def _series_rows(table: pd.DataFrame, metrics: dict, first: list[str]) -> list[dict]:
    rows = []
    for _, row in table.iterrows():
        out = {c: row[c] for c in first}
        out["Hs [m]"], out["Tp [s]"] = row["hs"], row["tp"]
        for metric, (label, unit, _) in metrics.items():
            out[f"{label} [{unit}]"] = f"{row[f'{metric}_calm']:.2f} → {row[f'{metric}_sea']:.2f}"
        out["heel's period in the sea [s]"] = f"{row['roll_period_sea']:.2f}"
        stop = row["stopped"].splitlines()[0] if row["stopped"] else ""
        out["run in the sea"] = "sailed to the end" if row["status"] == "ok" else f"stopped: {stop}"
        if row["lost_heading"]:
            out["run in the sea"] += f"; lost its heading ({row['lost_heading']})"
        rows.append(out)
    return rows


def _heights_text() -> str:
    g = constants.GRAVITY
    seas = ", ".join(f"Hs {hs:g} m: Tp {sea.developed_sea(hs)[1]:.2f} s (U10 "
                     f"{math.sqrt(g * hs / PM_HS) / U19_5_PER_U10:.1f} m/s)" for hs in sea.SEA_HS)
    per_root = 2.0 * math.pi / (PM_PEAK * math.sqrt(g * PM_HS))
    return (f"fully developed Pierson-Moskowitz seas: the wind that raises a sea of height Hs blows "
            f"U19.5 = (g Hs/{PM_HS:g})^½, its peak period Tp = 2π U19.5/({PM_PEAK:g} g) = {per_root:.2f} Hs^½ s "
            f"(Stewart 2008 eqs. 16.29-16.33): {seas}; long-crested, seed 0")


def _series_sections(r, s: SeaAnalysis) -> None:
    table1_hs, _ = fully_developed_sea(TABLE1_WIND)
    t1 = s.tables["table1"]
    r.section("Wille's roll controller in a sea (Table 1)", (
        f"Table 1's three simulations (6-DOF, seed 0, as built) in {_heights_text()}; the waves from "
        f"the wind's bearing ({float(t1['wave_from_deg'].iloc[0]):g}°, beam seas from the windward side). "
        f"Table 1's own wind (U10 {TABLE1_WIND:g} m/s) would raise a fully developed sea of Hs {table1_hs:.2f} m. "
        f"Calm: the Table 1 runs of the table above, run again with their heel and heading kept; each "
        f"value calm → in the sea, over the last {TABLE1_WINDOW:g} s. The roll is the heel's standard "
        "deviation (section \"The sea against calm water: the wind plane\"), not Table 1's roll "
        "amplitude; the heel's period is its mean zero-up-crossing period in the sea."))
    r.table(_series_rows(t1, TABLE1, ["sim"]))
    sa = s.tables["saoud"]
    r.section("Saoud's optimal sail in a sea", (
        f"The robot with Saoud's optimal sail (controller ``saoud``) holds its heading north, the wind "
        f"from {sea.SAOUD_WIND_FROM_DEG:g}° (a beam reach) at Saoud's {TRUE_WIND:g} m/s at the sail, in the same seas "
        f"from the wind's bearing. Each value calm → in the sea, over the last third of the run. "
        + _stops(sa)))
    r.table(_series_rows(sa, SAILING, []))
    r.figure(SEA_FIGURES["series"], "Roll (the heel's standard deviation) of Table 1's runs, and the robot's "
                                    "heel, roll and pitch, against the sea's height")


def _resonance_section(r, s: SeaAnalysis) -> None:
    g, res = constants.GRAVITY, s.resonance
    boats, seas = res["boats"].set_index("boat"), res["seas"]
    robot, yacht = boats.loc["saoud_robot"], boats.loc["wille_yacht"]
    sa, t1 = s.tables["saoud"], s.tables["table1"]
    waves = g * sa["roll_period_sea"] ** 2 / (2.0 * math.pi)
    r.section("Why a sea rolls the boats", (
        "Each boat's roll is a resonance the waves' slope drives. Its undamped period with sway free, "
        "T4 = 2π ((I_xx,G + A44 + z_G² m A22/(m + A22))/(ρ g V GM))^½ (z_G the CG's height above the "
        "waterline, A22 and A44 the sway and roll added mass, GM the hull's), is "
        f"{robot['t4']:.2f} s for the robot and {yacht['t4']:.2f} s for the yacht; deep-water waves of that "
        f"period, g T4²/2π, are {robot['wavelength']:.1f} m long for the robot "
        f"({robot['wavelength'] / robot['length']:.1f} hull lengths) and {yacht['wavelength']:.1f} m for the "
        f"yacht ({yacht['wavelength'] / yacht['length']:.1f} hull lengths). Sailing Saoud's beam reach in the seas, the "
        f"robot's heel swings at a mean zero-up-crossing period of {_span(sa['roll_period_sea'])} s, "
        f"{_span(sa['roll_period_sea'] / robot['t4'])} T4 (the sailing boat's roll is damped by keel, rudder and "
        "sail, and the slope spectrum falls with frequency: both move the response below the undamped "
        f"resonance): waves {_span(waves, '{:.1f}')} m long, "
        f"{_span(waves / robot['length'], '{:.1f}')} hull lengths, the short waves of the spectrum's "
        "tail, where the long-wave model (a hull short against the wave it rides) is at the edge of its "
        "validity. A Pierson-Moskowitz sea has S(ω) = (5/16) Hs² ωp⁴ ω⁻⁵ exp(−1.25 (ωp/ω)⁴); with "
        "Tp = 4.99 Hs^½ the product Hs² ωp⁴ is the same for every height, so above the peak the spectrum "
        "and the slope spectrum (ω²/g)² S(ω) do not depend on Hs, and each of these seas is as steep as the "
        f"others. At the robot's roll frequency the slope spectrum is "
        f"({_span(seas['slope_density'], scale=1e3)}) × 10⁻³ rad² s in the three seas and the RMS slope of the "
        f"simulated components ({BAND[0]:g}-{BAND[1]:g} ωp) {_span(seas['rms_slope'], '{:.1f}')}°; the robot's "
        f"roll σ is {_span(sa['roll_sd_sea'], '{:.1f}')}° in the seas run (" + ", ".join(
            f"Hs {row['hs']:g} m: {row['roll_sd_sea']:.1f}°" for _, row in sa.iterrows()) + "). The yacht's resonance lies near the "
        "smallest sea's peak: Tp/T4 = " + ", ".join(f"{row['tp_over_t4']:.2f} at Hs {row['hs']:g} m"
                                                    for _, row in seas.iterrows())
        + f"; the heel of Table 1's runs in the seas swings at {_span(t1['roll_period_sea'])} s, "
        f"{_span(t1['roll_period_sea'] / yacht['t4'])} T4, and their roll σ is " + ", ".join(
            f"{row['sim']} Hs {row['hs']:g} m: {row['roll_sd_sea']:.1f}° ({row['roll_sd_calm']:.1f}° calm)"
            for _, row in t1.iterrows()) + "."))
    r.table([{"Hs [m]": f"{row['hs']:g}", "Tp [s]": f"{row['tp']:.2f}", "yacht Tp/T4": f"{row['tp_over_t4']:.2f}",
              "robot ω4/ωp": f"{row['omega4_over_omegap']:.2f}",
              "slope spectrum at the robot's ω4 [rad² s]": f"{row['slope_density']:.2e}",
              "RMS slope [deg]": f"{row['rms_slope']:.2f}"} for _, row in seas.iterrows()])


def sections(r, s: SeaAnalysis) -> None:
    """The sea's sections, after the study's own: the wind plane, Table 1, Saoud's sail, why a
    sea rolls the boats, and where each difference comes from.

    Parameters
    ----------
    r : studies.kit.Report
        The report being written.
    s : SeaAnalysis
        The sea's numbers.
    """
    _plane_section(r, s)
    _series_sections(r, s)
    _resonance_section(r, s)
    mechanisms_section(r, s)
