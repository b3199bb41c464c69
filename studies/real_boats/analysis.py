"""The numbers of the real-boats study: each case's polar (the best sail angle per point), the
11:Metre's ratios to ORC and the misses beyond 10 %, the heel over the wind, the switches' effect,
and the canoe body against the Delft tank per Froude number."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.design import polar
from sailmujoco.design.reference_compare import reference_table
from sailmujoco.design.reference_polar import KNOT
from sailmujoco.study import Results

from .scenario import CASES, CAUSES, FULL_SAIL, folder, reference, tank_comparison

BAND = 0.10  # the and the project's tolerance: a point more than 10 % from ORC misses
BEAT_BAND_DEG = 3.0  # deg, the beat angle's tolerance
# ORC's speed guides: heel near 0 at 6 kn TWS, about 15 deg at 10 kn, 22-26 deg from about 14 kn
ORC_HEEL_DEG = {6.0: (0.0, 5.0), 10.0: (12.0, 18.0), 16.0: (22.0, 26.0)}
TRIM_COLUMNS = {"boat.reef": "reef", "boat.flat": "flat"}  # the searched trims' sweep keys -> polar columns


@dataclass(frozen=True)
class Analysis:
    """What the runs gave.

    Parameters
    ----------
    polars : dict of str to pandas.DataFrame
        Each case's polar: tws (m/s), tws_kn, twa, speed (m/s), speed_kn, heel_deg, sail_deg.
    orc : pandas.DataFrame
        The 11:Metre as built against ORC (:func:`sailmujoco.design.reference_compare.reference_table`).
    checks : pandas.DataFrame
        Per case, TWS and TWA of the switches: the speed and its ratio to ORC and to full sail.
    outside : pandas.DataFrame
        Each as-built point more than :data:`BAND` from ORC, with its ratio in each case of
        :data:`~studies.real_boats.scenario.CAUSES` at the same point.
    heel : pandas.DataFrame
        Per TWS: our heel at 52 deg and ORC's speed-guide band.
    tank : pandas.DataFrame
        :func:`studies.real_boats.scenario.tank_comparison`.
    numbers : dict
        The headline numbers.
    runs : int
        Simulations run.
    wall_s : float
        Their wall time, s.
    """

    polars: dict
    orc: pd.DataFrame
    checks: pd.DataFrame
    outside: pd.DataFrame
    heel: pd.DataFrame
    tank: pd.DataFrame
    numbers: dict
    runs: int
    wall_s: float


def case_polar(table: pd.DataFrame, **fixed) -> pd.DataFrame:
    """A sweep's table as a polar: the fastest trim (sail angle, and reef and flat where searched)
    at each point.

    Parameters
    ----------
    table : pandas.DataFrame
        The sweep's table (columns of :func:`sailmujoco.design.polar.polar_spec`'s sweep).
    **fixed
        Sweep columns held at one value (``**{"boat.reef": 1.0}``): the best of the rest.
    """
    named = table.rename(columns={"task.wind_speed": "tws", "task.wind_from_deg": "twa",
                                  "steady_speed": "speed", "steady_heel": "heel"})
    for column, value in fixed.items():
        if column in named:  # a trim the sweep did not search is at its full value already
            named = named[named[column] == value]
    ok = named[named["status"] == "ok"]
    chosen = ok.loc[ok.groupby(["tws", "twa", "seed"])["speed"].idxmax()]
    best = polar.over_seeds(polar.finished_points(named, "best"))
    trims = [c for c in TRIM_COLUMNS if c in chosen]
    best = best.merge(chosen[["tws", "twa", *trims]].rename(columns=TRIM_COLUMNS), on=["tws", "twa"])
    best["tws_kn"] = (best["tws"] / KNOT).round(6)
    best["speed_kn"] = best["speed"] / KNOT
    best["heel_deg"] = np.degrees(np.abs(best["heel"]))
    return best


def analyse(results: Results, smoke: bool) -> Analysis:
    """The polars, ORC's ratios, the switches, the heel and the tank.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The sweeps' tables.
    smoke : bool
        The short pass.
    """
    tables = {case: _both_passes(results, case) for case in CASES if folder(case) in results.sweeps}
    polars = {case: case_polar(table) for case, table in tables.items()}
    polars["full sail"] = case_polar(tables["as built"], **FULL_SAIL)
    orc = reference()
    ours = reference_table(polars["as built"], orc)
    ours["tws_kn"] = ours["tws_file"]
    checks = _checks(polars, orc)
    heel = _heel(polars["as built"], polars["full sail"])
    tank = tank_comparison()
    runs = sum(len(table) for table in tables.values())
    outside = _outside(ours, {case: reference_table(polars[case], orc) for case in CAUSES if case in polars})
    a = Analysis(polars, ours, checks, outside, heel, tank, {}, runs, results.seconds)
    a.numbers.update(_numbers(a))
    return a


def within(ratio: float, point: str, twa: float, twa_reference: float) -> bool:
    """Whether a point holds: its ratio within :data:`BAND` and, for a beat, its angle within
    :data:`BEAT_BAND_DEG` of the reference's.

    Parameters
    ----------
    ratio : float
        Ours over the reference.
    point : {"fixed", "beat"}
        The kind of point.
    twa, twa_reference : float
        Our angle and the reference's, deg.
    """
    return abs(ratio - 1.0) <= BAND and (point != "beat" or abs(twa - twa_reference) <= BEAT_BAND_DEG)


def _outside(ours: pd.DataFrame, causes: dict) -> pd.DataFrame:
    """Each as-built point that does not hold, and in each cause's case its ratio and angle and
    whether each of the two holds there ("speed holds": the ratio within :data:`BAND`; "angle
    holds": a beat's angle within :data:`BEAT_BAND_DEG`; a fixed point's angle always holds).
    ``explained``: every criterion the point misses holds in one of the cases."""
    rows = []
    for _, r in ours.iterrows():
        if within(r["ratio"], r["point"], r["twa"], r["twa_reference"]):
            continue
        row = {"tws_kn": r["tws_kn"], "point": r["point"], "twa": r["twa"], "twa_reference": r["twa_reference"],
               "ratio": r["ratio"], "speed_off": abs(r["ratio"] - 1.0) > BAND,
               "angle_off": r["point"] == "beat" and abs(r["twa"] - r["twa_reference"]) > BEAT_BAND_DEG}
        speed_held = angle_held = False
        for case, table in causes.items():
            same = table[np.isclose(table["tws_file"], r["tws_file"]) & (table["point"] == r["point"])
                         & np.isclose(table["twa_reference"], r["twa_reference"])]
            ratio = float(same["ratio"].iloc[0]) if not same.empty else np.nan
            twa = float(same["twa"].iloc[0]) if not same.empty else np.nan
            row[case], row[f"{case} twa"] = ratio, twa
            row[f"{case} speed holds"] = bool(abs(ratio - 1.0) <= BAND)
            row[f"{case} angle holds"] = bool(r["point"] != "beat" or abs(twa - r["twa_reference"]) <= BEAT_BAND_DEG)
            speed_held |= row[f"{case} speed holds"]
            angle_held |= row[f"{case} angle holds"]
        row["explained"] = (speed_held or not row["speed_off"]) and (angle_held or not row["angle_off"])
        rows.append(row)
    return pd.DataFrame(rows)


def _both_passes(results: Results, case: str) -> pd.DataFrame:
    """A case's first and second passes in one table (full sail where a pass has no trim columns)."""
    parts = [results.sweeps[name] for name in (folder(case), f"{folder(case)}/finer") if name in results.sweeps]
    table = pd.concat(parts, ignore_index=True)
    for column, value in FULL_SAIL.items():
        table[column] = table[column].fillna(value) if column in table else value
    return table


def _checks(polars: dict, orc) -> pd.DataFrame:
    """Per case and point: its speed over ORC's and over the boat's at full sail."""
    fixed = orc.fixed()
    built = polars["full sail"].set_index(["tws_kn", "twa"])["speed"]
    rows = []
    for case, frame in polars.items():
        for _, r in frame.iterrows():
            ref = fixed[np.isclose(fixed["tws_file"], r["tws_kn"]) & np.isclose(fixed["twa"], r["twa"])]
            if ref.empty:
                continue
            key = (r["tws_kn"], r["twa"])
            rows.append({"case": case, "tws_kn": r["tws_kn"], "twa": r["twa"], "speed_kn": r["speed_kn"],
                         "orc_kn": float(ref["speed"].iloc[0]) / KNOT,
                         "to_orc": r["speed"] / float(ref["speed"].iloc[0]),
                         "to_built": r["speed"] / built[key] if key in built.index else np.nan})
    return pd.DataFrame(rows)


def _heel(best: pd.DataFrame, full: pd.DataFrame) -> pd.DataFrame:
    """Per TWS at 52 deg: the heel at the best trim (and that trim) and at full sail, and ORC's band."""
    rows = []
    for tws, group in best.groupby("tws_kn"):
        at = group[np.isclose(group["twa"], 52.0)]
        sail = full[np.isclose(full["tws_kn"], tws) & np.isclose(full["twa"], 52.0)]
        if at.empty:
            continue
        low, high = ORC_HEEL_DEG.get(float(tws), (np.nan, np.nan))
        r = at.iloc[0]
        rows.append({"tws_kn": tws, "heel_deg": float(r["heel_deg"]), "reef": r.get("reef", 1.0),
                     "flat": r.get("flat", 1.0), "sail_deg": float(r["sail_deg"]),
                     "heel_full_sail_deg": float(sail["heel_deg"].iloc[0]) if not sail.empty else np.nan,
                     "orc_low": low, "orc_high": high})
    return pd.DataFrame(rows)


def _numbers(a: Analysis) -> dict:
    fixed = a.orc[a.orc["point"] == "fixed"]
    beat = a.orc[a.orc["point"] == "beat"]
    miss = len(a.outside)
    explained = int(a.outside["explained"].sum()) if not a.outside.empty else 0
    numbers = {"points": int(len(a.orc)), "points_outside_10pct": int(miss),
               "misses_explained_by_a_switch": int(explained),
               "ratio_min": float(a.orc["ratio"].min()), "ratio_max": float(a.orc["ratio"].max())}
    for tws, group in fixed.groupby("tws_kn"):
        numbers[f"ratio_{tws:g}kn_mean"] = float(group["ratio"].mean())
    if not beat.empty:
        numbers["beat_angle_error_max_deg"] = float(np.abs(beat["twa"] - beat["twa_reference"]).max())
    tank = a.tank[(a.tank["fn"] >= 0.2) & (a.tank["tank"] > 0)]
    numbers["tank_ratio_median_fn_0.2_0.45"] = float(tank["ratio"].median())
    return numbers


def headline(analysis: Analysis) -> dict:
    """The headline numbers, the simulations run and their wall time.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {**analysis.numbers, "runs": analysis.runs, "wall_s": analysis.wall_s}
