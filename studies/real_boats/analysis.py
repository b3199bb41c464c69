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

from .scenario import CASES, folder, reference, tank_comparison

BAND = 0.10  # the and the project's tolerance: a point more than 10 % from ORC misses
BEAT_BAND_DEG = 3.0  # deg, the beat angle's tolerance
# ORC's speed guides: heel near 0 at 6 kn TWS, about 15 deg at 10 kn, 22-26 deg from about 14 kn
ORC_HEEL_DEG = {6.0: (0.0, 5.0), 10.0: (12.0, 18.0), 16.0: (22.0, 26.0)}


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
        Per case, TWS and TWA of the switches: the speed and its ratio to ORC and to as built.
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
    heel: pd.DataFrame
    tank: pd.DataFrame
    numbers: dict
    runs: int
    wall_s: float


def case_polar(table: pd.DataFrame) -> pd.DataFrame:
    """A sweep's table as a polar: the fastest sail angle at each point.

    Parameters
    ----------
    table : pandas.DataFrame
        The sweep's table (columns of :func:`sailmujoco.design.polar.polar_spec`'s sweep).
    """
    named = table.rename(columns={"task.wind_speed": "tws", "task.wind_from_deg": "twa",
                                  "steady_speed": "speed", "steady_heel": "heel"})
    best = polar.over_seeds(polar.finished_points(named, "best"))
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
    polars = {case: case_polar(results.sweeps[folder(case)]) for case in CASES if folder(case) in results.sweeps}
    orc = reference()
    ours = reference_table(polars["as built"], orc)
    ours["tws_kn"] = ours["tws_file"]
    checks = _checks(polars, orc)
    heel = _heel(polars["as built"])
    tank = tank_comparison()
    runs = sum(len(results.sweeps[folder(c)]) for c in polars)
    a = Analysis(polars, ours, checks, heel, tank, {}, runs, results.seconds)
    a.numbers.update(_numbers(a))
    return a


def _checks(polars: dict, orc) -> pd.DataFrame:
    fixed = orc.fixed()
    built = polars["as built"].set_index(["tws_kn", "twa"])["speed"]
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


def _heel(frame: pd.DataFrame) -> pd.DataFrame:
    rows = []
    for tws, group in frame.groupby("tws_kn"):
        at = group[np.isclose(group["twa"], 52.0)]
        low, high = ORC_HEEL_DEG.get(float(tws), (np.nan, np.nan))
        rows.append({"tws_kn": tws, "heel_deg": float(at["heel_deg"].iloc[0]) if not at.empty else np.nan,
                     "orc_low": low, "orc_high": high})
    return pd.DataFrame(rows)


def _numbers(a: Analysis) -> dict:
    fixed = a.orc[a.orc["point"] == "fixed"]
    beat = a.orc[a.orc["point"] == "beat"]
    miss = (np.abs(fixed["ratio"] - 1.0) > BAND).sum() + (np.abs(beat["ratio"] - 1.0) > BAND).sum()
    numbers = {"points": int(len(a.orc)), "points_outside_10pct": int(miss),
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
