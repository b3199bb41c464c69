"""Assumption validation, the analysis: the wind plane as one table, each switch's effect point by
point, the restoring errors, and the headline numbers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.forces import stability
from sailmujoco.study import Results

from ..kit import verdict
from .episodes import time_constants
from .scenario import BOATS, BUILT, CONFIGS, PART_NAMES, RUNS_JOB, SPEED_FLOOR, plane_specs, table1_jobs
from .sea_analysis import SeaAnalysis, analyse_sea

SAILING_SPEED = 0.3  # m/s: the robot "sails" (has a steady apparent wind) above this steady speed


@dataclass(frozen=True, eq=False)
class Analysis:
    """The study's numbers.

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane: one row per boat, config, true wind speed (``tws``) and angle (``twa``).
    effects : dict
        ``(boat, config) -> ``:func:`speed_effects`'s table, for every config but the baseline.
    time_constants : dict
        Boat -> roll period, yaw time constant, roll natural frequency, I_xx.
    course : dict
        Wille's correction β_b against the drift sailed, the course error, the largest heel.
    steady : pandas.DataFrame
        Saoud's φ* against the steady heel, per wind, angle and l_φ.
    drift : dict
        Mean and largest |lateral speed| in position keeping, 3-DOF (``paper``) and 6-DOF.
    table1 : dict
        ``(resistance, sim) ->`` the numbers of a Wille Table 1 run.
    restoring : dict
        Boat -> the heel reached and the largest errors of eq. 20 and eq. 66.
    sea : studies.assumptions.sea_analysis.SeaAnalysis or None
        What a sea does to the boats (None: not analysed).
    """

    data: pd.DataFrame
    effects: dict
    time_constants: dict
    course: dict
    steady: pd.DataFrame
    drift: dict
    table1: dict
    restoring: dict
    sea: SeaAnalysis | None = None


def plane_table(specs: dict, tables: list) -> pd.DataFrame:
    """The wind-plane sweeps' tables as one, with the boat and config of each row.

    Parameters
    ----------
    specs : dict
        ``(boat, config) -> spec`` (:func:`.scenario.plane_specs`).
    tables : list of pandas.DataFrame
        Each sweep's table, in the order of ``specs``.
    """
    frames_ = []
    for (boat, config), table in zip(specs, tables, strict=True):
        table = table.rename(columns={"task.wind_speed": "tws", "task.wind_from_deg": "twa"})
        table["boat"], table["config"] = boat, config
        frames_.append(table)
    return pd.concat(frames_, ignore_index=True)


def pivot(data: pd.DataFrame, boat: str, config: str, value: str) -> pd.DataFrame:
    """One metric of one boat and config over the wind plane (rows tws, columns twa).

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    boat, config : str
        Which runs.
    value : str
        The metric's column.
    """
    d = data[(data["boat"] == boat) & (data["config"] == config)]
    return d.pivot_table(index="tws", columns="twa", values=value)


def delta(data: pd.DataFrame, boat: str, config: str, value: str) -> pd.DataFrame:
    """One metric with ``config`` minus as built, over the wind plane.

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    boat, config : str
        Which runs.
    value : str
        The metric's column.
    """
    base = pivot(data, boat, "baseline", value)
    other = pivot(data, boat, config, value)
    return other - base


def speed_effects(data: pd.DataFrame, boat: str, config: str) -> pd.DataFrame:
    """Point by point over the wind plane: steady speed and heel as built and with ``config``;
    the speed change as :func:`studies.kit.verdict.difference` gives it (relative, or in m/s where the
    boat as built makes less than SPEED_FLOOR). These rows are ``effects.csv``.

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    boat, config : str
        Which boat, and the config compared with the boat as built.
    """
    keys, cols = ["tws", "twa"], ["steady_speed", "steady_heel"]
    sel = data[data["boat"] == boat]
    built = sel[sel["config"] == "baseline"][keys + cols]
    other = sel[sel["config"] == config][keys + cols]
    m = built.merge(other, on=keys, suffixes=("_built", "_switched"), how="outer").sort_values(keys)
    diffs = verdict.differences(m["steady_speed_switched"], m["steady_speed_built"], floor=SPEED_FLOOR,
                                unit="m/s")
    m.insert(0, "config", config)
    m.insert(0, "boat", boat)
    m["speed_change_pct"] = [100 * d.value if d.relative else np.nan for d in diffs]
    m["speed_change_ms"] = m["steady_speed_switched"] - m["steady_speed_built"]
    m["heel_change_deg"] = np.degrees(m["steady_heel_switched"] - m["steady_heel_built"])
    m.attrs["diffs"] = diffs
    return m.reset_index(drop=True)


def restoring_errors(data: pd.DataFrame) -> dict:
    """Geometric righting moment against eq. 20 and its linearisation (eq. 66) over the heel
    range the boats reached in the wind plane.

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    """
    out = {}
    for boat in BOATS:
        p = get_boat(boat)
        reached = float(np.nanmax(np.abs(data[(data["boat"] == boat)]["steady_heel"])))
        reached = max(reached, math.radians(5.0))
        heels = np.linspace(math.radians(1.0), reached, 12)
        curve = stability.righting_curve(p, heels)
        phi_w = math.radians(10.0)
        k = p.rho_water * 9.81 * p.displaced_volume * p.gm_t
        linear = k * (1 - 2 * math.sin(phi_w) ** 2) * (heels - phi_w) + k * math.cos(phi_w) * math.sin(phi_w)
        geometric = curve["geometric"]
        model = curve["sin"] if p.paper_righting == "sin" else curve["sin_cos"]
        out[boat] = {"heel_reached_deg": math.degrees(reached),
                     "paper_formula_error": float(np.max(np.abs(model - geometric) / np.abs(geometric))),
                     "eq66_error": float(np.max(np.abs(linear - geometric) / np.abs(geometric)))}
    return out


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's numbers from its runs (and the time constants, run here).

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`.scenario.runs`.
    smoke : bool
        The study's short pass.
    """
    specs = plane_specs(smoke)
    data = plane_table(specs, [results.sweeps[f"sweeps/{spec['name']}"] for spec in specs.values()])
    tc = time_constants()
    single = results.jobs[RUNS_JOB]
    parts = dict(zip(PART_NAMES, single, strict=False))
    table1 = dict(zip(table1_jobs(smoke), single[len(PART_NAMES):], strict=True))
    restoring = restoring_errors(data)
    effects = {(b, c): speed_effects(data, b, c) for b in BOATS for c in CONFIGS
               if c != "baseline" and (data[(data["boat"] == b) & (data["config"] == c)]).size}
    return Analysis(data, effects, tc, parts["course"], parts["steady"], parts["drift"], table1, restoring,
                    analyse_sea(results, smoke))


def effect(analysis: Analysis, boat: str, config: str) -> list:
    """The speed changes of ``config`` against the boat as built, point by point (the rows of
    effects.csv), as :class:`studies.kit.verdict.Difference`.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    boat, config : str
        Which boat and config.
    """
    return analysis.effects[(boat, config)].attrs["diffs"]


def largest(diffs: list) -> float:
    """The largest relative |change| of ``diffs`` (nan if none is relative).

    Parameters
    ----------
    diffs : list of studies.kit.verdict.Difference
        Speed changes.
    """
    rel = [abs(d.value) for d in diffs if d.finite and d.relative]
    return max(rel) if rel else float("nan")


def roll_over_yaw(analysis: Analysis) -> dict:
    """Boat -> ω_roll τ_yaw: how much faster roll settles than yaw.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {b: v["roll_natural"] * v["yaw_time_constant"] for b, v in analysis.time_constants.items()}


def yacht_froude(analysis: Analysis) -> dict:
    """The yacht's Froude numbers over the wind plane, as built and friction only.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    length = get_boat("wille_yacht").hull.length
    return {c: pivot(analysis.data, "wille_yacht", c, "steady_speed").to_numpy(dtype=float)
            / math.sqrt(9.81 * length) for c in ("baseline", "friction_only")}


def sailing(analysis: Analysis) -> pd.DataFrame:
    """The steady-state runs (φ* against the heel) where the robot sails: a stalled boat has no
    steady apparent wind.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return analysis.steady[analysis.steady["speed"] > SAILING_SPEED]


def numbers(analysis: Analysis) -> dict:
    """The headline numbers, in the order of the table's rows.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    base = analysis.data[analysis.data["config"] == "baseline"]
    ct = base[base["boat"] == "saoud_robot"]["ct_cn_ratio"].to_numpy(dtype=float)
    sheet_rel = [d.value for d in effect(analysis, "saoud_robot", "sheeted") if d.finite and d.relative]
    aoa_deg = np.degrees(base[base["boat"] == "wille_yacht"]["keel_aoa"].to_numpy(dtype=float))
    err = sailing(analysis)["error_deg"].to_numpy(dtype=float)
    out = {"ct_cn_max": float(np.nanmax(ct)) if np.isfinite(ct).any() else float("nan"),
           "ct_speed_effect_max": largest(effect(analysis, "saoud_robot", "ct_off")),
           "pitch_amplitude_max_deg": float(np.degrees(np.nanmax(base["pitch_amplitude"].to_numpy(dtype=float)))),
           "four_dof_speed_effect_max": largest(sum((effect(analysis, b, "four_dof") for b in BOATS), [])),
           "omega3_ratio_max": float(np.nanmax(base["omega3_ratio"].to_numpy(dtype=float))),
           "roll_over_yaw_speed_min": min(roll_over_yaw(analysis).values()),
           "keel_roll_share_max": float(np.nanmax(base["roll_share_keel"].to_numpy(dtype=float))),
           "sheeted_speed_effect_min": min(sheet_rel) if sheet_rel else float("nan"),
           "keel_aoa_max_deg": float(np.nanmax(aoa_deg))}
    out.update({f"{b}_restoring_error": v["paper_formula_error"] for b, v in analysis.restoring.items()})
    out["phi_star_error_max_deg"] = float(np.nanmax(np.abs(err))) if err.size else float("nan")
    out["lateral_speed_6dof"] = analysis.drift["mujoco"]
    for config, _, _, _ in BUILT:
        out[f"{config}_speed_effect_max"] = largest(sum((effect(analysis, b, config) for b in BOATS), []))
    froude = yacht_froude(analysis)
    out["yacht_froude_max"] = float(np.nanmax(froude["baseline"]))
    out["yacht_froude_max_friction"] = float(np.nanmax(froude["friction_only"]))
    for key, value in analysis.table1.items():
        out[f"table1_{key[1]}_{key[0]}_roll_deg"] = value["roll_amplitude"]
        out[f"table1_{key[1]}_{key[0]}_surge"] = value["mean_surge"]
    return out
