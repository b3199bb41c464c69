"""Assumption validation, the headline numbers: what the table and the report read off the
analysis (:class:`.analysis.Analysis`).

A switch's points on every boat (:func:`switch_points`) and their largest effect
(:func:`largest`), the largest point mean of a baseline metric over the plane
(:func:`plane_max`), roll against yaw (:func:`roll_over_yaw`), the yacht's Froude number
(:func:`yacht_froude`), Saoud's steady states (:func:`steady_cases`, :func:`sailing`), Wille's
course hold (:func:`course_numbers`), Viel's position keeping (:func:`lateral_numbers`), and the
headline numbers in the order of the table's rows (:func:`numbers`). Every stochastic number is
a mean over seeds with its 95 % interval (:mod:`studies.kit.seeds`).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat

from ..kit import seeds as over
from .analysis import Analysis
from .scenario import BOATS, BUILT

SAILING_SPEED = 0.3  # m/s: the robot "sails" (has a steady apparent wind) above this steady speed


def switch_points(analysis: Analysis, config: str, boats=None) -> pd.DataFrame:
    """The points of ``config`` on ``boats`` (all that ran it), one table with a ``boat`` column.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    config : str
        The switch.
    boats : list of str, optional
        Which boats.
    """
    keys = [k for k in analysis.points if k[1] == config and (boats is None or k[0] in boats)]
    return pd.concat([analysis.points[k].assign(boat=k[0]) for k in keys], ignore_index=True)


def largest(points: pd.DataFrame, column: str = "speed_rel") -> float:
    """The largest |mean| of ``column`` over the points (nan if none).

    Parameters
    ----------
    points : pandas.DataFrame
        A table of points.
    column : str
        The number.
    """
    v = np.abs(points[column].to_numpy(dtype=float))
    return float(np.nanmax(v)) if np.isfinite(v).any() else float("nan")


def plane_max(analysis: Analysis, column: str, boats=None) -> float:
    """The largest point mean of a baseline metric over ``boats`` (all if None).

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    column : str
        A column of ``BASELINE_METRICS``.
    boats : list of str, optional
        Which boats.
    """
    v = np.concatenate([analysis.plane[b][column].to_numpy(dtype=float) for b in (boats or BOATS)])
    return float(np.nanmax(v)) if np.isfinite(v).any() else float("nan")


def roll_over_yaw(analysis: Analysis) -> dict:
    """Boat -> ω_roll τ_yaw: how much faster roll settles than yaw.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {b: v["roll_natural"] * v["yaw_time_constant"] for b, v in analysis.time_constants.items()}


def yacht_froude(analysis: Analysis) -> dict:
    """The yacht's largest Froude number over the wind plane (point means over seeds), as built
    and friction only.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    length = math.sqrt(9.81 * get_boat("wille_yacht").hull.length)
    pts = analysis.points[("wille_yacht", "friction_only")]
    return {"baseline": plane_max(analysis, "steady_speed", ["wille_yacht"]) / length,
            "friction_only": float(np.nanmax(pts["steady_speed_paper"].to_numpy(dtype=float))) / length}


def steady_cases(analysis: Analysis) -> pd.DataFrame:
    """Saoud's steady states per case (l_φ, wind, angle) over seeds: φ*, the heel, the error
    heel − φ* and the speed (means, intervals, ``n``), and whether the robot sails (steady speed
    above ``SAILING_SPEED``) on every seed (``sailing``).

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    s = analysis.steady
    cases = over.over_seeds(s, ["l_phi", "tws", "twa"], ["phi_star_deg", "heel_deg", "error_deg", "speed"])
    sails = s.groupby(["l_phi", "tws", "twa"], sort=False)["speed"].apply(lambda v: bool((v > SAILING_SPEED).all()))
    cases["sailing"] = sails.to_numpy()
    return cases


def sailing(analysis: Analysis) -> pd.DataFrame:
    """The steady-state cases (:func:`steady_cases`) where the robot sails on every seed: a
    stalled boat has no steady apparent wind.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    cases = steady_cases(analysis)
    return cases[cases["sailing"]].reset_index(drop=True)


def course_numbers(analysis: Analysis) -> dict:
    """Wille's course hold over seeds (deg): β_b, the drift sailed, β_b − drift (paired by
    seed), the course error and the largest heel.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    c = analysis.course
    deg = {k: np.degrees(c[k].to_numpy(dtype=float)) for k in ("beta_b", "drift", "drift_error", "heel_max")}
    return {"beta_b": over.interval(deg["beta_b"]), "drift": over.interval(deg["drift"]),
            "gap": over.paired(deg["beta_b"], deg["drift"]), "error": over.interval(deg["drift_error"]),
            "heel_max": over.interval(deg["heel_max"])}


def lateral_numbers(analysis: Analysis) -> dict:
    """Position keeping over seeds (m/s): the mean |lateral speed| of the 3-DOF model and of the
    6-DOF robot, their difference (paired by seed) and the 6-DOF's largest.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    d = analysis.drift
    paper, ours = d["paper"].to_numpy(dtype=float), d["mujoco"].to_numpy(dtype=float)
    return {"paper": over.interval(paper), "mujoco": over.interval(ours), "difference": over.paired(ours, paper),
            "mujoco_max": over.interval(d["mujoco_max"].to_numpy(dtype=float))}


def numbers(analysis: Analysis) -> dict:
    """The headline numbers (interval means: the largest point mean over the plane where a
    number varies over it), in the order of the table's rows.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    err = sailing(analysis)["error_deg"].to_numpy(dtype=float)
    sheet = analysis.points[("saoud_robot", "sheeted")]["speed_rel"].to_numpy(dtype=float)
    out = {"ct_cn_max": plane_max(analysis, "ct_cn_ratio", ["saoud_robot"]),
           "ct_speed_effect_max": largest(analysis.points[("saoud_robot", "ct_off")]),
           "pitch_amplitude_max_deg": plane_max(analysis, "pitch_amplitude_deg"),
           "four_dof_speed_effect_max": largest(switch_points(analysis, "four_dof")),
           "omega3_ratio_max": plane_max(analysis, "omega3_ratio"),
           "roll_over_yaw_speed_min": min(roll_over_yaw(analysis).values()),
           "keel_roll_share_max": plane_max(analysis, "roll_share_keel"),
           "sheeted_speed_effect_min": float(np.nanmin(sheet)) if np.isfinite(sheet).any() else float("nan"),
           "keel_aoa_max_deg": plane_max(analysis, "keel_aoa_deg", ["wille_yacht"])}
    out.update({f"{b}_restoring_error": v["paper_formula_error"] for b, v in analysis.restoring.items()})
    out["phi_star_error_max_deg"] = float(np.nanmax(np.abs(err))) if np.isfinite(err).any() else float("nan")
    out["lateral_speed_6dof"] = lateral_numbers(analysis)["mujoco"].mean
    for config, _, _, _ in BUILT:
        out[f"{config}_speed_effect_max"] = largest(switch_points(analysis, config))
    froude = yacht_froude(analysis)
    out["yacht_froude_max"] = froude["baseline"]
    out["yacht_froude_max_friction"] = froude["friction_only"]
    for key, value in analysis.table1.items():
        out[f"table1_{key[1]}_{key[0]}_roll_deg"] = value["roll_amplitude"]
        out[f"table1_{key[1]}_{key[0]}_surge"] = value["mean_surge"]
    return out
