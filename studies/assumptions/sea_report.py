"""Assumption validation, the sea's part of the report: its sections and headline numbers.

:func:`sections` writes the sections after the study's own, :func:`summary_sentence` one
sentence of the summary, :func:`headline` the sea's headline numbers; the sea's CSV files and
figures are :mod:`.sea_figures`.
Every number of a run in a sea is the mean over the study's seeds with its 95 % interval
(:mod:`sailmujoco.stats`); each case's difference has its verdict against the ±10 % band.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from sailmujoco import constants, stats
from sailmujoco.forces.waves import BAND
from sailmujoco.options import PM_HS, PM_PEAK, U19_5_PER_U10, fully_developed_sea

from ..kit import seeds as kit_seeds
from ..kit.saoud import TRUE_WIND
from ..kit.verdict import value_range
from ..kit.wille import TABLE1_WIND, TABLE1_WINDOW
from . import sea
from .sea_analysis import SeaAnalysis
from .sea_cases import (
    DIFFERENCE,
    HEADING_LOST_DEG,
    LOST,
    SAILING,
    TABLE1,
    interval_of,
    metrics_of,
    verdict_kind,
)
from .sea_figures import SEA_FIGURES
from .sea_mechanisms import PATH_WORDS, mechanism_text, mechanisms_section, paths
from .table import headline as table_headline

VERDICTS = ("breaks", "holds", "undecided")  # a difference's verdicts, in the order the report counts them


def _verdicts(s: SeaAnalysis) -> dict:
    """Every case's and metric's verdict, counted: breaks, holds, undecided (cases with no seed
    that kept its heading have none)."""
    found = [verdict_kind(v) for series, t in s.tables.items() for m in metrics_of(series)
             for v in t[f"{m}_verdict"] if v != LOST]
    return {k: found.count(k) for k in VERDICTS}


def lost_rate(s: SeaAnalysis, which: str = "any") -> stats.Interval:
    """The share of the runs in a sea (cases x seeds) that lost their heading (``which="sea"``)
    or sailed beside a calm run that lost it too (``"any"``), with Wilson's interval.

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    which : {"any", "sea"}
        Which runs count.
    """
    rows = pd.concat(list(s.runs.values()), ignore_index=True)
    lost = rows["lost_heading"] != "" if which == "any" else rows["lost_heading"].str.contains("sea")
    return stats.pass_rate(int(lost.sum()), len(rows))


def _plane_cases(s: SeaAnalysis) -> pd.DataFrame:
    return pd.concat([s.tables["saoud_robot"], s.tables["wille_yacht"]], ignore_index=True)


def _extreme(table: pd.DataFrame, column: str, largest: bool) -> pd.Series | None:
    """The row of ``table`` (cases with a kept seed) whose mean ``column`` is largest (or smallest)."""
    kept = table[(table["n_kept"] > 0) & np.isfinite(table[column])]
    if kept.empty:
        return None
    return kept.loc[kept[column].idxmax() if largest else kept[column].idxmin()]


def headline(analysis) -> dict:
    """The study's headline numbers (:func:`.table.headline`) and the sea's: per series and
    metric the largest mean relative change over the cases and how many break the band, the sea
    runs that stopped early and the runs that lost their heading (cases x seeds), the share of
    them with its interval, the verdicts counted and the paths of the differences that break.

    Parameters
    ----------
    analysis : studies.assumptions.analysis.Analysis
        The study's numbers.
    """
    out = table_headline(analysis)
    s = analysis.sea
    for series, table in s.tables.items():
        kept = table[table["n_kept"] > 0]
        for metric in metrics_of(series):
            rel = kept[f"{metric}_rel"].abs().to_numpy(dtype=float)
            out[f"sea_{series}_{metric}_change_max"] = float(np.nanmax(rel)) if np.isfinite(rel).any() else math.nan
            out[f"sea_{series}_{metric}_breaks"] = int((table[f"{metric}_verdict"] == "breaks").sum())
        out[f"sea_{series}_stopped"] = int((s.runs[series]["status"] != "ok").sum())
        out[f"sea_{series}_lost_heading"] = int((s.runs[series]["lost_heading"] != "").sum())
    for which in ("any", "sea"):
        got = lost_rate(s, which)
        key = "sea_lost_heading_rate" if which == "any" else "sea_lost_heading_in_sea_rate"
        out.update({key: got.mean, f"{key}_low": got.low, f"{key}_high": got.high})
    plane = _plane_cases(s)
    for name, largest in (("min", False), ("max", True)):
        row = _extreme(plane, "speed_rel", largest)
        out[f"sea_speed_change_{name}"] = float(row["speed_rel"]) if row is not None else math.nan
    row = _extreme(plane, "roll_sd_sea", True)
    out["sea_roll_sd_max"] = float(row["roll_sd_sea"]) if row is not None else math.nan
    out.update({f"sea_differences_{k}": v for k, v in _verdicts(s).items()})
    out["sea_mechanism_rows"] = len(s.mechanisms)
    taken = paths(s)
    for path in PATH_WORDS:
        out[f"sea_differences_by_{path}"] = taken.count(path)
    out["sea_seeds"] = len(s.seeds)
    out["sea_simulated_seconds"] = float(s.cost.get("first", 0.0) + s.cost.get("mechanisms", 0.0))
    return out


def _percent(row, column: str) -> str:
    got = interval_of(row, column)
    return type(got)(100 * got.mean, 100 * got.low, 100 * got.high, got.n, got.method).fixed(0, "%")


def _at(row) -> str:
    return f"{row['boat']} {row['case']}"


def summary_sentence(s: SeaAnalysis) -> str:
    """One sentence for the summary: the speed change over the wind plane, the roll, the
    verdicts, the runs that lost their heading and the paths the differences take, each with
    its interval.

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    """
    plane = _plane_cases(s)
    low, high = _extreme(plane, "speed_rel", False), _extreme(plane, "speed_rel", True)
    roll = _extreme(plane, "roll_sd_sea", True)
    stopped = sum(int((t["status"] != "ok").sum()) for t in s.runs.values())
    runs = sum(len(t) for t in s.runs.values())
    cases = sum(len(t) for t in s.tables.values())
    lost = lost_rate(s)
    counts = _verdicts(s)
    taken = paths(s)
    stops = f"{stopped} of {runs} runs stopped early; " if stopped else ""
    speed = ("" if low is None else
             f"steady speed {_percent(low, 'speed_rel')} to {_percent(high, 'speed_rel')}, roll σ up to "
             f"{interval_of(roll, 'roll_sd_sea').fixed(1, 'deg')} (wind plane); ")
    return (f"In a sea ({cases} cases × {len(s.seeds)} seeds, means with 95 % intervals): {speed}{stops}"
            f"heading lost in {round(lost.mean * lost.n)} of {runs} runs, {lost.fixed(2)}; of the differences "
            f"beyond ±{100 * DIFFERENCE:g} %, {counts['breaks']} break, {counts['holds']} hold, "
            f"{counts['undecided']} undecided; of the {len(taken)} attributed, " + ", ".join(
                f"{taken.count(p)} by {PATH_WORDS[p]}" if p not in ("stalled", "undecided")
                else f"{taken.count(p)} {p}" for p in PATH_WORDS if taken.count(p)) + ".")


def _stops(s: SeaAnalysis, series: str) -> str:
    table = s.tables[series]
    stopped = table[table["stopped"] > 0]
    if stopped.empty:
        return "Every run in a sea sailed to its end."
    runs = s.runs[series]
    why = runs[runs["status"] != "ok"]
    return f"{int(why.shape[0])} of {len(runs)} runs in a sea stopped early: " + "; ".join(
        f"{row['case']} seed {row['seed']}: {row['stopped'].splitlines()[0] if row['stopped'] else row['status']}"
        for _, row in why.iterrows()) + "."


def _plane_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for boat in ("saoud_robot", "wille_yacht"):
        t = s.tables[boat]
        kept = t[t["n_kept"] > 0]
        for metric, (label, unit, _) in SAILING.items():
            kinds = [verdict_kind(v) for v in kept[f"{metric}_verdict"]]
            top = kept.loc[kept[f"{metric}_rel"].abs().idxmax()] if np.isfinite(kept[f"{metric}_rel"]).any() else None
            rows.append({
                "boat": boat, "metric": f"{label} [{unit}]",
                "calm (deterministic)": value_range(kept[f"{metric}_calm"], fmt="{:.2f}"),
                f"breaks / holds / undecided (of {len(kept)} cases)":
                    f"{kinds.count('breaks')} / {kinds.count('holds')} / {kinds.count('undecided')}",
                "largest mean change": "—" if top is None else f"{_percent(top, f'{metric}_rel')} at {top['case']}",
                "the sea's path, each that breaks": mechanism_text(s, boat, metric)})
    return rows


def _sea_state_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    robot, yacht = s.tables["saoud_robot"], s.tables["wille_yacht"]
    for tws in sorted(set(robot["tws"])):
        r, y = robot[robot["tws"] == tws].iloc[0], yacht[yacht["tws"] == tws].iloc[0]
        rows.append({"true wind U10 [m/s]": f"{tws:g}", "robot Hs [m]": r["hs"], "robot Tp [s]": r["tp"],
                     "yacht Hs [m]": y["hs"], "yacht Tp [s]": y["tp"]})
    return rows


def method_text(s: SeaAnalysis) -> str:
    """The sea's method line: the seeds and what they draw, the interval, the verdict rule, the
    mechanism reruns' seeds and what the seeds cost.

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    """
    cost = s.cost
    spent = cost.get("first", 0.0) + cost.get("mechanisms", 0.0)
    return kit_seeds.method_line(
        s.seeds, what="every number of a run in a sea",
        extra=(f"The seed draws the sea's phases and frequencies and, in Table 1's runs, the gusts and "
               "the wind's wander (the calm run of the same seed has the same gusts); the calm runs of the "
               "wind plane and of Saoud's sail sail a steady wind from an exact start, so they are "
               "deterministic: one run, paired with every seed. A case's difference is (sea − calm)/"
               "max(|calm|, floor) seed by seed, over the seeds on which both runs keep their heading; "
               f"its verdict: *holds* where its interval lies within ±{100 * DIFFERENCE:g} % (the calm-water "
               f"value stands), *breaks* where it lies wholly beyond. The mechanism reruns run on the "
               f"first {sea.MECHANISM_SEEDS} seeds only (section \"Where each difference comes from\"). Cost: "
               f"{spent:,.0f} simulated seconds (a second in a sea counts {sea.SEA_COST:g}), of a budget of "
               f"{cost.get('budget', sea.BUDGET):,.0f}."))


def _plane_section(r, s: SeaAnalysis) -> None:
    components = int(s.tables["saoud_robot"]["n_components"].iloc[0])
    r.section("The sea against calm water: the wind plane", (
        "Each boat sails the study's wind plane (heading held, steady wind) in the sea that point's "
        "wind raises, against the same run in calm water. The sea is fetch-limited JONSWAP (γ 3.3; "
        "Hs = 1.6e-3 χ^½ U10²/g, Tp = 0.2857 χ^⅓ U10/g, χ = g F/U10², each at most its fully "
        "developed value; Hasselmann et al. 1973, Shore Protection Manual 1984 eqs. 3-33, 3-34), "
        f"long-crested, the waves from the wind's bearing, {components} components, one realisation "
        "per seed. The fetch F: " + "; ".join(f"{b} {sea.FETCH[b] / 1000:g} km ({sea.FETCH_REASON[b]})"
                                                 for b in sea.FETCH) + "."))
    r.paragraph(method_text(s))
    r.table(_sea_state_rows(s))
    r.paragraph(
        f"Each metric over the steady window (the last third of the run): the band is ±{100 * DIFFERENCE:g} % "
        "of the calm value, or of the floor where the calm value is smaller (" + ", ".join(
            f"{label} {floor:g} {unit}" for label, unit, floor in SAILING.values())
        + "; heel and drift angle as magnitudes). " + ROLL_TEXT + " " + _lost_text() + " The table counts "
        "the cases with a seed on which both runs keep their heading; the largest change is the case "
        "mean's with its interval. The last column: how many of the differences that break the waves' "
        "forces on the hull explain, how many the orbital flow at the foils, how many either path makes "
        "alone, and how many stay undecided at the reruns' seeds (section \"Where each difference "
        "comes from\").")
    r.table(_plane_rows(s))
    lost, lost_sea = lost_rate(s), lost_rate(s, "sea")
    r.paragraph(f"Over every series (cases × seeds), {round(lost.mean * lost.n)} of {lost.n} runs in a sea lost their "
                f"heading or sailed beside a calm run that lost it: {lost.fixed(2)} (the share with Wilson's 95 % "
                f"interval); the run in the sea itself lost it in {round(lost_sea.mean * lost_sea.n)}: "
                f"{lost_sea.fixed(2)}.")
    r.paragraph(" ".join(f"{boat}: {_stops(s, boat)} {_lost_list(s.tables[boat])}"
                         for boat in ("saoud_robot", "wille_yacht")))
    r.figure(SEA_FIGURES["plane"], "Steady speed in the sea against calm water (✓ holds within the band, "
                                   "? undecided), and the roll (the heel's standard deviation) in the sea, "
                                   "each the mean over the seeds, over true wind angle × true wind speed; "
                                   "hatched: a case with a seed that lost its heading")


ROLL_TEXT = (
    "The roll is the heel's standard deviation σ about its mean over the window (the significant roll "
    "amplitude is 2σ): in a random sea the heel's half peak-to-peak is an extreme value, which grows "
    "with the number of roll cycles in the window (about σ (2 ln N)^½ for N cycles), so it says as much "
    "about the window's length as about the sea; σ does not. Calm water gets the same statistic.")


def _lost_text() -> str:
    return (f"A run whose heading error RMS over the window exceeds {HEADING_LOST_DEG:g}° lost its heading "
            "(it turned head to wind and stalled, bore away, or yawed that far about its course): the "
            "difference on such a seed compares a boat sailing its course with one that is not, and is "
            "left out of its case's numbers.")


def _lost_list(table: pd.DataFrame) -> str:
    lost = table[(table["lost_calm"] > 0) | (table["lost_sea"] > 0)]
    if lost.empty:
        return "Every case keeps its heading on every seed."
    return (f"{len(lost)} of {len(table)} cases lost their heading on a seed: " + "; ".join(
        f"{row['case']} (calm {row['lost_calm']}, sea {row['lost_sea']} of {row['n']} seeds; heading error RMS "
        f"{interval_of({**row, 'n_kept': row['n']}, 'heading_rms_calm').fixed(0)}° calm, "
        f"{interval_of({**row, 'n_kept': row['n']}, 'heading_rms_sea').fixed(0)}° in the sea)"
        for _, row in lost.iterrows()) + ".")


def _series_rows(table: pd.DataFrame, metrics: dict, first: list[str]) -> list[dict]:
    rows = []
    for _, row in table.iterrows():
        out = {c: row[c] for c in first}
        out["Hs [m]"], out["Tp [s]"] = row["hs"], f"{row['tp']:.2f}"
        for metric, (label, unit, _) in metrics.items():
            out[f"{label} [{unit}]"] = (f"{interval_of(row, f'{metric}_calm').fixed(2)} → "
                                        f"{interval_of(row, f'{metric}_sea').fixed(2)}: {row[f'{metric}_verdict']}")
        out["heel's period in the sea [s]"] = interval_of({**row, "n_kept": row["n"]}, "roll_period_sea").fixed(2)
        note = "sailed to the end" if not row["stopped"] else f"stopped early on {row['stopped']} of {row['n']} seeds"
        if row["lost_sea"] or row["lost_calm"]:
            note += f"; lost its heading on {row['lost_sea']} (sea), {row['lost_calm']} (calm) of {row['n']} seeds"
        out["runs in the sea"] = note
        rows.append(out)
    return rows


def _heights_text() -> str:
    g = constants.GRAVITY
    seas = ", ".join(f"Hs {hs:g} m: Tp {sea.developed_sea(hs)[1]:.2f} s (U10 "
                     f"{math.sqrt(g * hs / PM_HS) / U19_5_PER_U10:.1f} m/s)" for hs in sea.SEA_HS)
    per_root = 2.0 * math.pi / (PM_PEAK * math.sqrt(g * PM_HS))
    return (f"fully developed Pierson-Moskowitz seas: the wind that raises a sea of height Hs blows "
            f"U19.5 = (g Hs/{PM_HS:g})^½, its peak period Tp = 2π U19.5/({PM_PEAK:g} g) = {per_root:.2f} Hs^½ s "
            f"(Stewart 2008 eqs. 16.29-16.33): {seas}; long-crested, one realisation per seed")


def _series_sections(r, s: SeaAnalysis) -> None:
    table1_hs, _ = fully_developed_sea(TABLE1_WIND)
    t1 = s.tables["table1"]
    r.section("Wille's roll controller in a sea (Table 1)", (
        f"Table 1's three simulations (6-DOF, as built) in {_heights_text()}; the waves from "
        f"the wind's bearing ({float(t1['wave_from_deg'].iloc[0]):g}°, beam seas from the windward side). "
        f"Table 1's own wind (U10 {TABLE1_WIND:g} m/s) would raise a fully developed sea of Hs {table1_hs:.2f} m. "
        f"Calm: the Table 1 runs of the table above on the same seeds (the same gusts and wander), run again "
        f"with their heel and heading kept; each value calm → in the sea, over the last {TABLE1_WINDOW:g} s, "
        f"the mean over {len(s.seeds)} seeds with its interval, and the verdict of the change against the "
        f"±{100 * DIFFERENCE:g} % band. The roll is the heel's standard "
        "deviation (section \"The sea against calm water: the wind plane\"), not Table 1's roll "
        "amplitude; the heel's period is its mean zero-up-crossing period in the sea."))
    r.table(_series_rows(t1, TABLE1, ["sim"]))
    sa = s.tables["saoud"]
    r.section("Saoud's optimal sail in a sea", (
        f"The robot with Saoud's optimal sail (controller ``saoud``) holds its heading north, the wind "
        f"from {sea.SAOUD_WIND_FROM_DEG:g}° (a beam reach) at Saoud's {TRUE_WIND:g} m/s at the sail, in the same seas "
        f"from the wind's bearing. Each value calm (one deterministic run) → in the sea (the mean over "
        f"{len(s.seeds)} seeds with its interval), over the last third of the run, with the change's verdict. "
        + _stops(s, "saoud")))
    r.table(_series_rows(sa, SAILING, []))
    r.figure(SEA_FIGURES["series"], "Roll (the heel's standard deviation) of Table 1's runs, and the robot's "
                                    "heel, roll and pitch, against the sea's height: means over the seeds "
                                    "with their 95 % intervals")


def _each(table: pd.DataFrame, column: str, scale: float = 1.0, decimals: int = 2, n_column: str = "n_kept") -> str:
    """``column``'s mean with its interval in each row of ``table`` (times ``scale``), by its Hs."""
    out = []
    for _, row in table.iterrows():
        got = interval_of({**row, "n_kept": row[n_column]}, column)
        got = type(got)(scale * got.mean, scale * got.low, scale * got.high, got.n, got.method)
        out.append(f"Hs {row['hs']:g} m: {got.fixed(decimals)}")
    return ", ".join(out)


def _resonance_section(r, s: SeaAnalysis) -> None:
    res = s.resonance
    boats, seas = res["boats"].set_index("boat"), res["seas"]
    robot, yacht = boats.loc["saoud_robot"], boats.loc["wille_yacht"]
    sa, t1 = s.tables["saoud"], s.tables["table1"]
    slope = stats.Interval(float(seas["rms_slope"].mean()), float(seas["rms_slope_low"].min()),
                           float(seas["rms_slope_high"].max()), len(s.seeds))
    r.section("Why a sea rolls the boats", (
        "Each boat's roll is a resonance the waves' slope drives. Its undamped period with sway free, "
        "T4 = 2π ((I_xx,G + A44 + z_G² m A22/(m + A22))/(ρ g V GM))^½ (z_G the CG's height above the "
        "waterline, A22 and A44 the sway and roll added mass, GM the hull's), is "
        f"{robot['t4']:.2f} s for the robot and {yacht['t4']:.2f} s for the yacht; deep-water waves of that "
        f"period, g T4²/2π, are {robot['wavelength']:.1f} m long for the robot "
        f"({robot['wavelength'] / robot['length']:.1f} hull lengths) and {yacht['wavelength']:.1f} m for the "
        f"yacht ({yacht['wavelength'] / yacht['length']:.1f} hull lengths). Sailing Saoud's beam reach in the seas, the "
        f"robot's heel swings at a mean zero-up-crossing period (s; mean over the seeds with its interval) of "
        f"{_each(sa, 'roll_period_sea', n_column='n')}, in T4: "
        f"{_each(sa, 'roll_period_sea', 1.0 / robot['t4'], n_column='n')} (the sailing boat's roll is damped by "
        "keel, rudder and sail, and the slope spectrum falls with frequency: both move the response below "
        "the undamped resonance); deep-water waves of that period, g T²/2π, are "
        f"{_wavelengths(sa, robot['length'])} hull lengths long, the short waves of the spectrum's "
        "tail, where the long-wave model (a hull short against the wave it rides) is at the edge of its "
        "validity. A Pierson-Moskowitz sea has S(ω) = (5/16) Hs² ωp⁴ ω⁻⁵ exp(−1.25 (ωp/ω)⁴); with "
        "Tp = 4.99 Hs^½ the product Hs² ωp⁴ is the same for every height, so above the peak the spectrum "
        "and the slope spectrum (ω²/g)² S(ω) do not depend on Hs, and each of these seas is as steep as the "
        f"others. At the robot's roll frequency the slope spectrum is "
        f"({value_range(seas['slope_density'], 1e3, '{:.2f}')}) × 10⁻³ rad² s in the three seas and the RMS "
        f"slope of the simulated components ({BAND[0]:g}-{BAND[1]:g} ωp) {slope.fixed(1)}° over the seeds' "
        f"realisations; the robot's roll σ (deg) is {_each(sa, 'roll_sd_sea', decimals=1)}. The yacht's "
        "resonance lies near the smallest sea's peak: Tp/T4 = " + ", ".join(
            f"{row['tp_over_t4']:.2f} at Hs {row['hs']:g} m" for _, row in seas.iterrows())
        + "; the heel of Table 1's runs in the seas swings at (s) " + "; ".join(
            f"{sim}: {_each(group, 'roll_period_sea', n_column='n')}" for sim, group in t1.groupby("sim"))
        + ", and their roll σ (deg, calm → sea) is " + "; ".join(
            f"{row['sim']} Hs {row['hs']:g} m: {interval_of(row, 'roll_sd_calm').fixed(1)} → "
            f"{interval_of(row, 'roll_sd_sea').fixed(1)}" for _, row in t1.iterrows()) + "."))
    r.table([{"Hs [m]": f"{row['hs']:g}", "Tp [s]": f"{row['tp']:.2f}", "yacht Tp/T4": f"{row['tp_over_t4']:.2f}",
              "robot ω4/ωp": f"{row['omega4_over_omegap']:.2f}",
              "slope spectrum at the robot's ω4 [rad² s]": f"{row['slope_density']:.2e}",
              f"RMS slope [deg] (N={len(s.seeds)})": kit_seeds.row_interval(row, "rms_slope", len(s.seeds)).fixed(2)}
             for _, row in seas.iterrows()])


def _wavelengths(table: pd.DataFrame, length: float) -> str:
    """Per Hs: the deep-water wave of each seed's heel period, in hull lengths, mean with its interval."""
    g = constants.GRAVITY
    out = []
    for _, row in table.iterrows():
        got = interval_of({**row, "n_kept": row["n"]}, "roll_period_sea")
        waves = [g * t**2 / (2.0 * math.pi) / length for t in (got.mean, got.low, got.high)]
        out.append(f"Hs {row['hs']:g} m: {waves[0]:.1f} (period's interval: {waves[1]:.1f}-{waves[2]:.1f})")
    return ", ".join(out)


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
