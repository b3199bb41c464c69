"""Assumption validation, the table: one row per assumption (its scenarios, metric, range,
threshold, verdict and effect), filled from the analysis; and the headline numbers.

Every stochastic number is printed as ``mean [low, high]`` over its seeds; every verdict is
*holds*, *breaks* or *undecided at N seeds*, the interval against the threshold (an assumption
over the wind plane: :func:`.analysis.tally` of its points). The papers' own values quoted in a
row come from the ``PAPER_*`` constants.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat

from ..kit import seeds as over
from .analysis import (
    KEEL_AOA_LINEAR_DEG,
    LATERAL_HOLDS,
    PHI_STAR_HOLDS_DEG,
    Analysis,
    combined,
    judge_points,
    tally,
)
from .fitted_analysis import table_row
from .headline_numbers import (
    course_numbers,
    lateral_numbers,
    numbers,
    roll_over_yaw,
    sailing,
    steady_cases,
    switch_points,
)
from .scenario import BOATS, BUILT, HEEL_HOLDS_DEG, SPEED_FLOOR, SPEED_HOLDS

PAPER_KEEL_ROLL_SHARE = 0.08  # Wille (2016b) Fig. 3: the keel's share of the roll moment
PAPER_LINEAR_LIFT_DEG = (10.0, 15.0)  # Wille (2016a) eqs. 53-59: lift linear below this angle of attack
CT_CN_HOLDS = 0.1  # |C_T|/|C_N| "much smaller" below this
PITCH_HOLDS_DEG = 2.0  # deg: pitch "small" below this amplitude
OMEGA3_HOLDS = 0.1  # the neglected ω3² tan φ term below this share of the restoring moment
ROLL_SHARE_HOLDS = 0.1  # keel + rudder + hull below this share of the roll moment
ROLL_OVER_YAW_HOLDS = 5.0  # ω_roll τ_yaw above this: roll "much faster" than yaw
RESTORING_HOLDS = 0.1  # eq. 20's largest relative error below this
COLUMNS = ["assumption", "scenarios", "metric", "range", "threshold", "verdict", "effect"]


def rows(analysis: Analysis) -> list[dict]:
    """The table's rows: nine of the papers' assumptions, then each difference of the boat as
    built from the papers' boat (``BUILT``), then perfect sensors and ideal actuators
    (:func:`.fitted_analysis.table_row`, where they ran).

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    out = _sail_and_motion_rows(analysis) + _roll_rows(analysis) + _drift_and_balance_rows(analysis)
    out += [built_row(analysis, config, title, paper_form) for config, _, title, paper_form in BUILT]
    _add_resistance_notes(analysis, next(r for r in out if r["assumption"].startswith("Friction-only")))
    if analysis.fitted is not None:
        out += [table_row(analysis.fitted, arm) for arm in FITTED_ROWS]
    return out


FITTED_ROWS = ("sensors", "actuators")  # the fitted arms' rows, last
VERDICT_KEYS = ("ct", "four_dof", "roll_speed", "roll_moments", "sheeted", "small_drift", "restoring",
                "phi_star", "lateral", *(config for config, _, _, _ in BUILT),
                "perfect_sensors", "ideal_actuators")  # the rows' headline names


def headline(analysis: Analysis) -> dict:
    """The headline numbers (:func:`.headline_numbers.numbers`), each row's verdict (``verdict_<row>``:
    *holds*, *breaks* or *undecided at N seeds*) and the number of rows of the table.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    table = rows(analysis)
    verdicts = {f"verdict_{key}": row["verdict"].split(" (")[0]
                for key, row in zip(VERDICT_KEYS, table, strict=False)}  # the fitted rows: where they ran
    return {**numbers(analysis), **verdicts, "rows": len(table)}


def where(row) -> str:
    """``"(tws m/s, twa°)"`` of a point's row.

    Parameters
    ----------
    row : mapping or pandas.Series
        A wind-plane point, with ``tws`` [m/s] and ``twa`` [deg].
    """
    return f"({row['tws']:g} m/s, {row['twa']:g}°)"


def extremes(points: pd.DataFrame, column: str, scale: float = 1.0, digits: int = 3, signed: bool = False,
             unit: str = "") -> str:
    """The lowest and the highest point mean of ``column`` with their intervals and points,
    ``"low [..] (point) … high [..] (point)"`` (times ``scale``); "—" when none is a number.

    Parameters
    ----------
    points : pandas.DataFrame
        A table of points (:func:`.analysis.effect_points` or :func:`.analysis.baseline_points`).
    column : str
        The number.
    scale : float
        Factor of the printed numbers (100: per cent).
    digits : int
        Significant digits.
    signed : bool
        Print the sign of a positive mean.
    unit : str
        After each interval.
    """
    v = points[column].to_numpy(dtype=float)
    if not np.isfinite(v).any():
        return "—"

    def one(i):
        row = points.iloc[int(i)]
        text = over.cell(over.row_interval(row, column).scaled(scale), digits, unit)
        return f"{'+' if signed and row[column] > 0 else ''}{text} {where(row)}"

    low, high = np.nanargmin(v), np.nanargmax(v)
    return one(low) if low == high else f"{one(low)} … {one(high)}"


def _speed_text(points: pd.DataFrame) -> str:
    """A switch's speed differences over its points, in per cent of the paper's arm."""
    return f"speed {extremes(points, 'speed_rel', 100, signed=True, unit='%')}"


def _sail_and_motion_rows(a: Analysis) -> list[dict]:
    """Rows 1-2: C_T ≪ C_N; pitch and heave small."""
    n = len(a.plane_seeds)
    robot = a.plane["saoud_robot"]
    ct_points = a.points[("saoud_robot", "ct_off")]
    ct_ratio = tally(judge_points(robot, "ct_cn_ratio", CT_CN_HOLDS), n)
    ct_speed = tally(ct_points["speed_verdict"], n)
    both = pd.concat([a.plane[b] for b in BOATS], ignore_index=True)
    pitch = tally(judge_points(both, "pitch_amplitude_deg", PITCH_HOLDS_DEG), n)
    four = switch_points(a, "four_dof")
    four_speed = tally(four["speed_verdict"], n)
    return [
        {"assumption": "Tangential sail force negligible, C_T ≪ C_N (Saoud Assumption 4)",
         "scenarios": "robot, wind plane", "metric": "|C_T|/|C_N| at steady state",
         "range": extremes(robot, "ct_cn_ratio"),
         "threshold": f"< {CT_CN_HOLDS:g}; speed with C_T on within ±{100 * SPEED_HOLDS:g} % of C_T off",
         "verdict": f"{combined([ct_ratio[0], ct_speed[0]], n)} (ratio: {ct_ratio[0]}, {ct_ratio[1]}; "
                    f"speed: {ct_speed[0]}, {ct_speed[1]})",
         "effect": f"steady {_speed_text(ct_points)}, C_T on against off"},
        {"assumption": "Pitch and heave small: 4 DOF suffice (Saoud Assumption 1; Wille §2.1)",
         "scenarios": "both boats, wind plane",
         "metric": "pitch / heave amplitude at steady state",
         "range": "; ".join(f"{b}: pitch amplitude {extremes(a.plane[b], 'pitch_amplitude_deg')} deg, "
                            f"heave amplitude {extremes(a.plane[b], 'heave_amplitude_cm')} cm" for b in BOATS),
         "threshold": f"pitch < {PITCH_HOLDS_DEG:g} deg; speed of 6-DOF within ±{100 * SPEED_HOLDS:g} % of "
                      "heave and pitch held",
         "verdict": f"{combined([pitch[0], four_speed[0]], n)} (pitch: {pitch[0]}, {pitch[1]}; "
                    f"speed: {four_speed[0]}, {four_speed[1]})",
         "effect": "6-DOF against heave and pitch held: " + "; ".join(
             f"{b}: {_speed_text(a.points[(b, 'four_dof')])}, heel "
             f"{extremes(a.points[(b, 'four_dof')], 'heel_diff_deg', signed=True)} deg" for b in BOATS)},
    ]


def _roll_rows(a: Analysis) -> list[dict]:
    """Rows 3-5: roll faster than yaw; roll moments of keel, rudder, hull; actuated vs sheeted."""
    n = len(a.plane_seeds)
    both = pd.concat([a.plane[b] for b in BOATS], ignore_index=True)
    speed_ratio = roll_over_yaw(a)
    term = tally(judge_points(both, "omega3_ratio", OMEGA3_HOLDS), n)
    fast = ["holds" if r > ROLL_OVER_YAW_HOLDS else "breaks" for r in speed_ratio.values()]
    fast_word = "breaks" if "breaks" in fast else "holds"
    shares = tally(judge_points(both, "roll_share_others", ROLL_SHARE_HOLDS), n)
    sheet = a.points[("saoud_robot", "sheeted")]
    sheet_speed = tally(sheet["speed_verdict"], n)
    return [
        {"assumption": "Roll much faster than yaw; ω3² tan φ negligible (Saoud §III)",
         "scenarios": "free decay, rudder step (deterministic: calm water, exact start); wind plane",
         "metric": "ω_roll × τ_yaw (roll natural frequency over yaw bandwidth); "
                   "|(J33−J22) ω3² tan φ| / |restoring|",
         "range": "; ".join(f"{b}: T_roll {v['roll_period']:.2f} s, τ_yaw {v['yaw_time_constant']:.2f} s, "
                            f"ω_roll τ_yaw = {speed_ratio[b]:.1f}" for b, v in a.time_constants.items())
                  + f"; term ratio {extremes(both, 'omega3_ratio')}",
         "threshold": f"ω_roll τ_yaw > {ROLL_OVER_YAW_HOLDS:g} (much faster); term ratio < {OMEGA3_HOLDS:g}",
         "verdict": (f"{combined([term[0], fast_word], n)} (term ratio: {term[0]}, {term[1]}; ω_roll τ_yaw: "
                     f"{fast_word}, {fast.count('breaks')} of {len(fast)} boats below "
                     f"{ROLL_OVER_YAW_HOLDS:g}: roll only "
                     + ", ".join(f"{r:.1f}×" for r in speed_ratio.values()) + " faster than yaw)"),
         "effect": "the neglected term's largest share of the restoring moment: "
                   + extremes(both, "omega3_ratio").split(" … ")[-1]},
        {"assumption": "Rudder, keel, hull roll moments negligible at roll equilibrium (Saoud eq. 4)",
         "scenarios": "both boats, wind plane",
         "metric": "share of |roll moment|: keel; keel + rudder + hull",
         "range": f"keel {extremes(both, 'roll_share_keel', 100)} %; keel + rudder + hull "
                  f"{extremes(both, 'roll_share_others', 100)} % (Wille 2016b Fig. 3: keel ≈ "
                  f"{100 * PAPER_KEEL_ROLL_SHARE:g} %)",
         "threshold": f"keel + rudder + hull < {100 * ROLL_SHARE_HOLDS:g} %",
         "verdict": f"{shares[0]} ({shares[1]})",
         "effect": "enters φ* (row 8)"},
        {"assumption": "Sail fully actuated, δs free (Saoud Assumption 5) vs sheeted (Wille 2016b §2.1)",
         "scenarios": "robot with Saoud's optimum, wind plane",
         "metric": "steady speed and heel, sheeted against actuated (the paper's)",
         "range": f"{_speed_text(sheet)}, heel {extremes(sheet, 'heel_diff_deg', signed=True)} deg",
         "threshold": f"speed loss < {100 * SPEED_HOLDS:g} % (one-sided)",
         "verdict": f"{sheet_speed[0]} ({sheet_speed[1]})",
         "effect": "speed, as the range"},
    ]


def _drift_and_balance_rows(a: Analysis) -> list[dict]:
    """Rows 6-9: small drift; restoring; Saoud's steady state; lateral drift in position keeping."""
    n, ns = len(a.plane_seeds), len(a.single_seeds)
    yacht = a.plane["wille_yacht"]
    aoa = tally(judge_points(yacht, "keel_aoa_deg", KEEL_AOA_LINEAR_DEG), n)
    course = course_numbers(a)
    restoring = a.restoring
    restoring_breaks = sum(v["paper_formula_error"] >= RESTORING_HOLDS for v in restoring.values())
    cases = steady_cases(a)
    sailing_cases = sailing(a)
    phi = tally(judge_points(sailing_cases, "error_deg", 0.0, "within", PHI_STAR_HOLDS_DEG), ns, "cases")
    lateral = lateral_numbers(a)
    lateral_word = over.decide(lateral["difference"], 0.0, "within", LATERAL_HOLDS)
    low, high = PAPER_LINEAR_LIFT_DEG
    return [
        {"assumption": f"Small drift, v ≪ u, cos φ ≈ 1, linear lift below {low:g}-{high:g}° (Wille eqs. 53-59)",
         "scenarios": "yacht, wind plane; close-hauled course hold",
         "metric": "drift angle; keel |angle of attack|; β_b vs the drift sailed",
         "range": f"drift {extremes(yacht, 'drift_angle_deg')} deg; keel |α| {extremes(yacht, 'keel_aoa_deg')} "
                  f"deg; course hold: β_b {over.cell(course['beta_b'])} vs drift {over.cell(course['drift'])} deg",
         "threshold": f"keel |α| < {KEEL_AOA_LINEAR_DEG:g} deg",
         "verdict": f"{aoa[0]} ({aoa[1]})",
         "effect": f"course error left by the correction: {over.cell(course['error'])} deg "
                   f"(β_b − drift, paired by seed: {over.cell(course['gap'])} deg)"},
        {"assumption": "Restoring ρ g ∇ GM sin φ cos φ and its linearisation about φ_w (Wille eq. 20, 2016b eq. 66)",
         "scenarios": "geometric hull over the heel range reached (deterministic: the hull's geometry)",
         "metric": "max relative error vs the geometric righting moment: eq. 20 (or Saoud eq. 4); eq. 66",
         "range": "; ".join(f"{b}: {v['paper_formula_error'] * 100:.0f} %, {v['eq66_error'] * 100:.0f} % "
                            f"(to {v['heel_reached_deg']:.0f} deg)" for b, v in restoring.items()),
         "threshold": f"< {100 * RESTORING_HOLDS:g} %",
         "verdict": ("breaks" if restoring_breaks else "holds")
                    + f" (eq. 20 / Saoud eq. 4: {restoring_breaks} of {len(restoring)} boats beyond)",
         "effect": "heel and heading in 6-DOF, geometric vs Saoud eq. 4 (saoud_fig6 and saoud_fig7 checks)"},
        {"assumption": "Steady state: Saoud's static optimum φ* is the heel reached (Saoud §V)",
         "scenarios": "robot, 3-7 m/s, 60-120 deg, l_φ 0.1 and 1 m",
         "metric": f"steady heel − φ* (deg), {len(sailing_cases)} of {len(cases)} cases sailing on every seed",
         "range": _case_extremes(sailing_cases), "threshold": f"|heel − φ*| < {PHI_STAR_HOLDS_DEG:g} deg",
         "verdict": f"{phi[0]} ({phi[1]})",
         "effect": "the roll limit φ_max is not what the boat sails at"},
        {"assumption": "Wind on the sail balanced by the keel; hull windage p1 only (Viel eq. 5)",
         "scenarios": "position keeping, case 2, robot 6-DOF vs 3-DOF",
         "metric": "mean |lateral speed| (m/s)",
         "range": f"3-DOF {over.cell(lateral['paper'])}, 6-DOF {over.cell(lateral['mujoco'])} "
                  f"(largest {over.cell(lateral['mujoco_max'])})",
         "threshold": f"6-DOF within {LATERAL_HOLDS:g} m/s of 3-DOF (paired by seed)",
         "verdict": f"{lateral_word} (6-DOF − 3-DOF {over.cell(lateral['difference'])} m/s)",
         "effect": "see viel_fig3 for the distance to target"},
    ]


def _case_extremes(cases: pd.DataFrame) -> str:
    """The lowest and highest mean heel − φ* of the sailing cases, with their intervals."""
    v = cases["error_deg"].to_numpy(dtype=float)
    if not np.isfinite(v).any():
        return "—"

    def one(i):
        row = cases.iloc[int(i)]
        return (f"{over.cell(over.row_interval(row, 'error_deg'))} ({row['tws']:g} m/s, {row['twa']:g}°, "
                f"l_φ {row['l_phi']:g} m)")

    low, high = np.nanargmin(v), np.nanargmax(v)
    return one(low) if low == high else f"{one(low)} … {one(high)}"


def built_row(a: Analysis, config: str, title: str, paper_form: str) -> dict:
    """A row for one difference between the boat as built and the papers' boat: the boat as
    built against the papers' form over the wind plane, seed by seed (speed relative to the
    papers' form, heel in deg).

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    config : str
        The difference (a name of ``BUILT``).
    title : str
        The row's title.
    paper_form : str
        What the papers assume.
    """
    n = len(a.plane_seeds)
    pts = switch_points(a, config)
    speed, heel = tally(pts["speed_verdict"], n), tally(pts["heel_verdict"], n)

    def summary(b):
        p = a.points[(b, config)]
        beyond = tally(p["speed_verdict"], n)[1]
        return (f"{b}: {_speed_text(p)} ({beyond}), heel {extremes(p, 'heel_diff_deg', signed=True)} deg "
                f"({tally(p['heel_verdict'], n)[1]})")

    return {"assumption": f"{title} ({paper_form})",
            "scenarios": "both boats, wind plane (5-14 m/s)",
            "metric": "steady speed and heel, as built against the papers' form",
            "range": "; ".join(summary(b) for b in BOATS),
            "threshold": f"|speed| within ±{100 * SPEED_HOLDS:.0f} % of the papers' form (of {SPEED_FLOOR:g} "
                         f"m/s where it is slower), |heel| < {HEEL_HOLDS_DEG:g} deg",
            "verdict": f"{combined([speed[0], heel[0]], n)} (speed: {speed[0]}, {speed[1]}; heel: {heel[0]}, "
                       f"{heel[1]})",
            "effect": "speed and heel, as the range (the extremes are points where one of the two "
                      "boats loses its heading or stalls)"}


def _add_resistance_notes(a: Analysis, row: dict) -> None:
    """The resistance row also reports the yacht's Froude numbers and Wille's Table 1 (its first
    seed only: a note, no verdict)."""
    table1 = a.table1
    fn = math.sqrt(9.81 * get_boat("wille_yacht").hull.length)
    seed = a.table1_seeds[0] if a.table1_seeds else 0
    top = extremes(a.plane["wille_yacht"], "steady_speed", 1 / fn).split(" … ")[-1]
    top_friction = extremes(a.points[("wille_yacht", "friction_only")], "steady_speed_paper", 1 / fn).split(" … ")[-1]
    row["range"] += f"; yacht Froude number at its largest: {top} as built, {top_friction} friction only"
    row["effect"] += f"; Wille Table 1 (6-DOF, seed {seed} only: no interval), as built → friction only: " + ", ".join(
        f"{sim.replace('sim', 'sim ')} roll {table1[('dsyhs', sim)]['roll_amplitude']:.2f}° → "
        f"{table1[('friction', sim)]['roll_amplitude']:.2f}°, surge {table1[('dsyhs', sim)]['mean_surge']:.2f} → "
        f"{table1[('friction', sim)]['mean_surge']:.2f} m/s (Fn "
        f"{table1[('dsyhs', sim)]['mean_surge'] / fn:.2f} → "
        f"{table1[('friction', sim)]['mean_surge'] / fn:.2f})"
        for sim in ("sim1", "sim2", "sim3"))


def verdict_counts(table: list[dict]) -> dict:
    """How many rows hold, break and are undecided.

    Parameters
    ----------
    table : list of dict
        The rows.
    """
    words = [row["verdict"].split(" (")[0] for row in table]
    return {"holds": sum(w == "holds" for w in words), "breaks": sum(w == "breaks" for w in words),
            "undecided": sum(w.startswith("undecided") for w in words)}

