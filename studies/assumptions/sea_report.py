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
from sailmujoco.forces.wave_spectra import PM_HS, PM_PEAK, U19_5_PER_U10, fully_developed_sea

from ..kit import save_figure, setup_matplotlib
from ..kit.saoud import TRUE_WIND
from ..kit.verdict import value_range
from ..kit.wille import TABLE1_WIND, TABLE1_WINDOW
from . import sea
from .figures import heatmap
from .figures import write as write_figures
from .sea_analysis import DIFFERENCE, EXPLAINS, SAILING, SERIES, TABLE1, SeaAnalysis, metrics_of
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
    relative change of each metric per series and the number of sea runs that stopped early.

    Parameters
    ----------
    analysis : studies.assumptions.analysis.Analysis
        The study's numbers.
    """
    out = table_headline(analysis)
    for series, table in analysis.sea.tables.items():
        for metric in metrics_of(series):
            rel = table[f"{metric}_rel"].abs().to_numpy(dtype=float)
            out[f"sea_{series}_{metric}_change_max"] = float(np.nanmax(rel)) if np.isfinite(rel).any() else math.nan
        out[f"sea_{series}_stopped"] = int((table["status"] != "ok").sum())
    out["sea_mechanism_rows"] = len(analysis.sea.mechanisms)
    return out


def _pivot(table: pd.DataFrame, column: str) -> pd.DataFrame:
    return table.pivot_table(index="tws", columns="twa", values=column, dropna=False)


def _plane_figure(plt, s: SeaAnalysis, out: Path) -> None:
    fig, axes = plt.subplots(2, 2, figsize=(11, 8))
    for row, boat in enumerate(("saoud_robot", "wille_yacht")):
        table = s.tables[boat]
        heatmap(plt, 100 * _pivot(table, "speed_rel"), axes[row, 0],
                f"{boat}: steady speed in the sea vs calm (✓ |Δ| < {100 * DIFFERENCE:g} %)", "%",
                lambda v: abs(v) < 100 * DIFFERENCE)
        heatmap(plt, _pivot(table, "roll_sea"), axes[row, 1],
                f"{boat}: roll amplitude in the sea (calm: {value_range(table['roll_calm'], fmt='{:.2f}')}°)",
                "deg")
    fig.suptitle("What the sea a wind raises does over the wind plane (× = no data)")
    save_figure(fig, out / SEA_FIGURES["plane"])


def _series_figure(plt, s: SeaAnalysis, out: Path) -> None:
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    t1 = s.tables["table1"]
    for sim, group in t1.groupby("sim"):
        calm = float(group["roll_calm"].iloc[0])
        axes[0].plot([0.0, *group["hs"]], [calm, *group["roll_sea"]], "o-", label=sim)
    _mark_stops(axes[0], t1)
    axes[0].set_title("Wille's roll controller (Table 1): roll amplitude", fontsize=9)
    sa = s.tables["saoud"]
    for metric in ("roll", "heel", "pitch"):
        axes[1].plot([0.0, *sa["hs"]], [float(sa[f"{metric}_calm"].iloc[0]), *sa[f"{metric}_sea"]], "o-",
                     label=SAILING[metric][0])
    _mark_stops(axes[1], sa)
    axes[1].set_title("Saoud's optimal sail (robot, beam reach)", fontsize=9)
    for ax in axes:
        ax.set_xlabel("significant wave height Hs [m] (0: calm water)")
        ax.set_ylabel("[deg]")
        ax.legend(fontsize=8)
    fig.suptitle("Fully developed seas of height Hs, from the wind's bearing")
    save_figure(fig, out / SEA_FIGURES["series"])


def _mark_stops(ax, table: pd.DataFrame) -> None:
    """A red cross on the roll amplitude of each run in a sea that stopped early."""
    stopped = table[table["status"] != "ok"]
    if len(stopped):
        ax.scatter(stopped["hs"], stopped["roll_sea"], marker="x", s=80, color="red", label="stopped early",
                   zorder=3)


def summary_sentence(s: SeaAnalysis) -> str:
    """One sentence for the summary: the speed change over the wind plane and the stops.

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    """
    plane = pd.concat([s.tables["saoud_robot"], s.tables["wille_yacht"]])
    stopped = sum(int((t["status"] != "ok").sum()) for t in s.tables.values())
    runs = sum(len(t) for t in s.tables.values())
    return (f"In a sea (section \"The sea against calm water\"), the steady speed changes by "
            f"{value_range(plane['speed_rel'], 100, '{:+.0f}')} % over the wind plane and the roll "
            f"amplitude reaches {value_range(plane['roll_sea'], fmt='{:.1f}').split(' … ')[-1]}°; "
            f"{stopped} of {runs} runs in a sea stopped early.")


def _stops(table: pd.DataFrame) -> str:
    stopped = table[table["status"] != "ok"]
    if stopped.empty:
        return "Every run in a sea sailed to its end."
    return f"{len(stopped)} of {len(table)} runs in a sea stopped early: " + "; ".join(
        f"{row['case']}: {row['stopped'].splitlines()[0] if row['stopped'] else row['status']}"
        for _, row in stopped.iterrows()) + "."


def _mechanism_text(s: SeaAnalysis, series: str, metric: str) -> str:
    m = s.mechanisms
    if m.empty:
        return "—"
    row = m[(m["series"] == SERIES[series]) & (m["metric"] == metrics_of(series)[metric][0])]
    if row.empty:
        return "—"
    return _named(row.iloc[0])


def _named(row) -> str:
    removed = {name: row[f"{name}_removed"] for name, _ in sea.MECHANISMS}
    finite = {k: v for k, v in removed.items() if np.isfinite(v)}
    if row["mechanism"]:
        name = row["mechanism"]
        return f"`env.{name} = {_off(name)}` removes {100 * removed[name]:.0f} %"
    if not finite:
        return "no rerun finished"
    best = max(finite, key=finite.get)
    if finite[best] <= 0.0:
        return "no single switch explains it (none makes it smaller)"
    return (f"no single switch explains it (the most: `env.{best} = {_off(best)}`, "
            f"{100 * finite[best]:.0f} %)")


def _off(name: str) -> str:
    value = dict(sea.MECHANISMS)[name]
    return f'"{value}"' if isinstance(value, str) else str(value).lower()


def _plane_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for boat in ("saoud_robot", "wille_yacht"):
        t = s.tables[boat]
        for metric, (label, unit, _) in SAILING.items():
            rel = t[f"{metric}_rel"].to_numpy(dtype=float)
            top = t.loc[np.nanargmax(np.abs(rel))] if np.isfinite(rel).any() else None
            rows.append({
                "boat": boat, "metric": f"{label} [{unit}]",
                "calm": value_range(t[f"{metric}_calm"], fmt="{:.2f}"),
                "in the sea": value_range(t[f"{metric}_sea"], fmt="{:.2f}"),
                "change": value_range(t[f"{metric}_change"], fmt="{:+.2f}") + f" {unit}",
                f"beyond ±{100 * DIFFERENCE:g} %": f"{int((np.abs(rel) > DIFFERENCE).sum())} of {len(t)}",
                "largest": "—" if top is None else f"{100 * top[f'{metric}_rel']:+.0f} % at {top['case']}",
                "mechanism": _mechanism_text(s, boat, metric)})
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
        + "; heel and drift angle as magnitudes). The roll amplitude is half the peak-to-peak of the heel over the window. The mechanism "
        "column: the switch that removes most of the largest difference (section \"Where each "
        "difference comes from\").")
    r.table(_plane_rows(s))
    r.paragraph(" ".join(f"{boat}: {_stops(s.tables[boat])}" for boat in ("saoud_robot", "wille_yacht")))
    r.figure(SEA_FIGURES["plane"], "Steady speed in the sea against calm water, and the roll amplitude "
                                   "in the sea, over true wind angle × true wind speed")


def _series_rows(table: pd.DataFrame, metrics: dict, first: list[str]) -> list[dict]:
    rows = []
    for _, row in table.iterrows():
        out = {c: row[c] for c in first}
        out["Hs [m]"], out["Tp [s]"] = row["hs"], row["tp"]
        for metric, (label, unit, _) in metrics.items():
            out[f"{label} [{unit}]"] = f"{row[f'{metric}_calm']:.2f} → {row[f'{metric}_sea']:.2f}"
        stop = row["stopped"].splitlines()[0] if row["stopped"] else ""
        out["run in the sea"] = "sailed to the end" if row["status"] == "ok" else f"stopped: {stop}"
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
        f"Calm: the Table 1 runs of the table above; each value calm → in the sea, over the last "
        f"{TABLE1_WINDOW:g} s."))
    r.table(_series_rows(t1, TABLE1, ["sim"]))
    sa = s.tables["saoud"]
    r.section("Saoud's optimal sail in a sea", (
        f"The robot with Saoud's optimal sail (controller ``saoud``) holds its heading north, the wind "
        f"from {sea.SAOUD_WIND_FROM_DEG:g}° (a beam reach) at Saoud's {TRUE_WIND:g} m/s at the sail, in the same seas "
        f"from the wind's bearing. Each value calm → in the sea, over the last third of the run. "
        + _stops(sa)))
    r.table(_series_rows(sa, SAILING, []))
    r.figure(SEA_FIGURES["series"], "Roll amplitude of Table 1's runs, and the robot's heel, roll and pitch, "
                                    "against the sea's height")


def _mechanisms_section(r, s: SeaAnalysis) -> None:
    names = ", ".join(f"`env.{name} = {_off(name)}`" for name, _ in sea.MECHANISMS)
    r.section("Where each difference comes from", (
        f"For every series and metric with a difference beyond {100 * DIFFERENCE:g} %, the case where it "
        f"is largest is run again with each of the sea's mechanisms off in turn ({names}). The share "
        "of the difference a switch removes is 1 − (switched − calm)/(sea − calm); the switch that "
        f"removes the most, and at least {100 * EXPLAINS:g} %, names the mechanism."))
    rows = []
    for _, m in s.mechanisms.iterrows():
        row = {"series": m["series"], "case": m["case"], "metric": f"{m['metric']} [{m['unit']}]",
               "calm → sea": f"{m['calm']:.2f} → {m['sea']:.2f}"}
        for name, _ in sea.MECHANISMS:
            row[f"`env.{name} = {_off(name)}` removes"] = f"{100 * m[f'{name}_removed']:.0f} %" \
                if np.isfinite(m[f"{name}_removed"]) else "—"
        row["explained by"] = _named(m)
        rows.append(row)
    if rows:
        r.table(rows)
        idle = [name for name, _ in sea.MECHANISMS
                if (s.mechanisms[f"{name}_off"] == s.mechanisms["sea"]).all()]
        if idle:
            r.paragraph("Switched off, " + ", ".join(f"`env.{n} = {_off(n)}`" for n in idle)
                        + " leave" + ("s" if len(idle) == 1 else "") + " every metric of these reruns "
                        "as it is with the switch on, to the bit.")
    else:
        r.paragraph(f"No metric differs by more than {100 * DIFFERENCE:g} %.")


def sections(r, s: SeaAnalysis) -> None:
    """The sea's sections, after the study's own: the wind plane, Table 1, Saoud's sail, and
    where each difference comes from.

    Parameters
    ----------
    r : studies.kit.Report
        The report being written.
    s : SeaAnalysis
        The sea's numbers.
    """
    _plane_section(r, s)
    _series_sections(r, s)
    _mechanisms_section(r, s)
