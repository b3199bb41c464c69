"""Assumption validation, the table: one row per assumption (its scenarios, metric, range,
threshold, verdict and effect), filled from the analysis; and the headline numbers.

The papers' own values quoted in a row come from the ``PAPER_*`` constants.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat

from ..kit import verdict
from .analysis import Analysis, effect, numbers, roll_over_yaw, sailing, yacht_froude
from .scenario import BOATS, BUILT, HEEL_HOLDS_DEG, SPEED_FLOOR, SPEED_HOLDS

PAPER_KEEL_ROLL_SHARE = 0.08  # Wille (2016b) Fig. 3: the keel's share of the roll moment
PAPER_LINEAR_LIFT_DEG = (10.0, 15.0)  # Wille (2016a) eqs. 53-59: lift linear below this angle of attack
COLUMNS = ["assumption", "scenarios", "metric", "range", "threshold", "verdict", "effect"]

rng_ = verdict.value_range


def rows(analysis: Analysis) -> list[dict]:
    """The table's rows: nine of the papers' assumptions, then each difference of the boat as
    built from the papers' boat (``BUILT``).

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    out = _sail_and_motion_rows(analysis) + _roll_rows(analysis) + _drift_and_balance_rows(analysis)
    out += [built_row(analysis.effects, config, title, paper_form) for config, _, title, paper_form in BUILT]
    _add_resistance_notes(analysis, next(r for r in out if r["assumption"].startswith("Friction-only")))
    return out


def headline(analysis: Analysis) -> dict:
    """The headline numbers (:func:`.analysis.numbers`) and the number of rows of the table.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {**numbers(analysis), "rows": len(rows(analysis))}


def _pitch_summary(g: pd.DataFrame) -> str:
    """One boat's pitch amplitude (with where it is largest), trim (mean pitch, bow up +) and
    heave amplitude over the wind plane, as built."""
    if g.empty or not np.isfinite(g["pitch_amplitude"]).any():
        return "—"
    top = g.loc[g["pitch_amplitude"].idxmax()]
    return (f"{g['boat'].iloc[0]}: pitch amplitude up to {math.degrees(top['pitch_amplitude']):.1f}° "
            f"({top['tws']:g} m/s, {top['twa']:g}°, at {top['steady_speed']:.1f} m/s), trim (bow up +) "
            f"{verdict.value_range(g['mean_pitch'], 180 / math.pi, '{:+.1f}')}°, heave amplitude up to "
            f"{100 * np.nanmax(g['heave_amplitude']):.1f} cm")


def _sail_and_motion_rows(a: Analysis) -> list[dict]:
    """Rows 1-2: C_T ≪ C_N; pitch and heave small."""
    base = a.data[a.data["config"] == "baseline"]
    ct = base[base["boat"] == "saoud_robot"]["ct_cn_ratio"].to_numpy(dtype=float)
    ct_effect = effect(a, "saoud_robot", "ct_off")
    pitch = base["pitch_amplitude"].to_numpy(dtype=float)
    heave = base["heave_amplitude"].to_numpy(dtype=float)
    four = sum((effect(a, b, "four_dof") for b in BOATS), [])
    heel4 = np.concatenate([a.effects[(b, "four_dof")]["heel_change_deg"].to_numpy(dtype=float) for b in BOATS])
    return [
        {"assumption": "Tangential sail force negligible, C_T ≪ C_N (Saoud Assumption 4)",
         "scenarios": "robot, wind plane", "metric": "|C_T|/|C_N| at steady state",
         "range": rng_(ct), "threshold": f"< 0.10; speed with C_T off within {100 * SPEED_HOLDS:g} %",
         "verdict": verdict.combined({"ratio": verdict.judge(ct, below=0.1),
                                      "speed": verdict.judge_differences(ct_effect, SPEED_HOLDS)}),
         "effect": f"steady speed with C_T off vs on: {verdict.range_of(ct_effect)}"},
        {"assumption": "Pitch and heave small: 4 DOF suffice (Saoud Assumption 1; Wille §2.1)",
         "scenarios": "both boats, wind plane",
         "metric": "pitch / heave amplitude at steady state",
         "range": f"{rng_(pitch, 180 / math.pi)} deg / {rng_(heave, 100)} cm; "
                  + "; ".join(_pitch_summary(base[base["boat"] == b]) for b in BOATS),
         "threshold": f"pitch < 2 deg; speed with heave and pitch held within {100 * SPEED_HOLDS:g} %",
         "verdict": verdict.combined({"pitch": verdict.judge(np.degrees(pitch), below=2.0),
                                      "speed": verdict.judge_differences(four, SPEED_HOLDS)}),
         "effect": f"speed, heave+pitch held vs free: {verdict.range_of(four)}; "
                   f"heel {rng_(heel4, 1.0, '{:+.2f}')} deg"},
    ]


def _roll_rows(a: Analysis) -> list[dict]:
    """Rows 3-5: roll faster than yaw; roll moments of keel, rudder, hull; actuated vs sheeted."""
    base = a.data[a.data["config"] == "baseline"]
    om = base["omega3_ratio"].to_numpy(dtype=float)
    speed_ratio = roll_over_yaw(a)
    keel = base["roll_share_keel"].to_numpy(dtype=float)
    others = (base["roll_share_keel"] + base["roll_share_rudder"] + base["roll_share_damping"]
              + base["roll_share_added_mass"]).to_numpy(dtype=float)
    sheet = effect(a, "saoud_robot", "sheeted")
    sheet_heel = a.effects[("saoud_robot", "sheeted")]["heel_change_deg"].to_numpy(dtype=float)
    # a loss beyond 5 %: judged as a change beyond -5 % of max(speed as built, SPEED_FLOOR)
    sheet_loss = [d.value if d.relative else d.value / max(abs(d.reference), SPEED_FLOOR) for d in sheet]
    return [
        {"assumption": "Roll much faster than yaw; ω3² tan φ negligible (Saoud §III)",
         "scenarios": "free decay, rudder step, wind plane",
         "metric": "ω_roll × τ_yaw (roll natural frequency over yaw bandwidth); "
                   "|(J33−J22) ω3² tan φ| / |restoring|",
         "range": "; ".join(f"{b}: T_roll {v['roll_period']:.2f} s, τ_yaw {v['yaw_time_constant']:.2f} s, "
                            f"ω_roll τ_yaw = {speed_ratio[b]:.1f}" for b, v in a.time_constants.items())
                  + f"; term ratio {rng_(om)}",
         "threshold": "ω_roll τ_yaw > 5 (much faster); term ratio < 0.10",
         "verdict": (f"term ratio < 0.10: {verdict.judge(om, below=0.1).text()}; ω_roll τ_yaw > 5: "
                     + verdict.judge(list(speed_ratio.values()), above=5.0).text("boats")
                     + " (roll only " + ", ".join(f"{r:.1f}×" for r in speed_ratio.values())
                     + " faster than yaw)"),
         "effect": "the neglected term changes the roll balance by < "
                   f"{100 * np.nanmax(om):.1f} %"},
        {"assumption": "Rudder, keel, hull roll moments negligible at roll equilibrium (Saoud eq. 4)",
         "scenarios": "both boats, wind plane",
         "metric": "share of |roll moment|: keel; keel + rudder + hull",
         "range": f"{rng_(keel, 100)} %; {rng_(others, 100)} % (Wille 2016b Fig. 3: keel ≈ "
                  f"{100 * PAPER_KEEL_ROLL_SHARE:g} %)",
         "threshold": "keel + rudder + hull < 10 %", "verdict": verdict.judge(others, below=0.1).text(),
         "effect": "enters φ* (row 8)"},
        {"assumption": "Sail fully actuated, δs free (Saoud Assumption 5) vs sheeted (Wille 2016b §2.1)",
         "scenarios": "robot with Saoud's optimum, wind plane",
         "metric": "steady speed and heel, sheeted minus actuated",
         "range": f"speed {verdict.range_of(sheet)}, heel {rng_(sheet_heel, 1.0, '{:+.2f}')} deg",
         "threshold": "speed loss < 5 %",
         "verdict": verdict.judge(sheet_loss, above=-SPEED_HOLDS).text(),
         "effect": "speed, as the range"},
    ]


def _drift_and_balance_rows(a: Analysis) -> list[dict]:
    """Rows 6-9: small drift; restoring; Saoud's steady state; lateral drift in position keeping."""
    base = a.data[a.data["config"] == "baseline"]
    yacht = base[base["boat"] == "wille_yacht"]
    drift_deg = np.degrees(yacht["drift_angle"].to_numpy(dtype=float))
    aoa_deg = np.degrees(yacht["keel_aoa"].to_numpy(dtype=float))
    course, restoring, drift = a.course, a.restoring, a.drift
    sailing_runs = sailing(a)
    err = sailing_runs["error_deg"].to_numpy(dtype=float)
    low, high = PAPER_LINEAR_LIFT_DEG
    return [
        {"assumption": f"Small drift, v ≪ u, cos φ ≈ 1, linear lift below {low:g}-{high:g}° (Wille eqs. 53-59)",
         "scenarios": "yacht, wind plane; close-hauled course hold",
         "metric": "drift angle; keel angle of attack; β_b vs the drift sailed",
         "range": f"drift {rng_(drift_deg)} deg; keel α {rng_(aoa_deg)} deg; "
                  f"β_b {math.degrees(course['beta_b']):.2f} vs drift {math.degrees(course['drift']):.2f} deg",
         "threshold": "keel |α| < 10 deg",
         "verdict": verdict.judge(aoa_deg, below=10.0, magnitude=True).text(),
         "effect": f"course error left by the correction: {math.degrees(course['drift_error']):.2f} deg "
                   f"(β_b − drift = {math.degrees(course['beta_b'] - course['drift']):+.2f} deg)"},
        {"assumption": "Restoring ρ g ∇ GM sin φ cos φ and its linearisation about φ_w (Wille eq. 20, 2016b eq. 66)",
         "scenarios": "geometric hull over the heel range reached",
         "metric": "max relative error vs the geometric righting moment: eq. 20 (or Saoud eq. 4); eq. 66",
         "range": "; ".join(f"{b}: {v['paper_formula_error'] * 100:.0f} %, {v['eq66_error'] * 100:.0f} % "
                            f"(to {v['heel_reached_deg']:.0f} deg)" for b, v in restoring.items()),
         "threshold": "< 10 %",
         "verdict": "eq. 20 / Saoud eq. 4: " + verdict.judge(
             [v["paper_formula_error"] for v in restoring.values()], below=0.1).text("boats"),
         "effect": "heel and heading in 6-DOF, geometric vs Saoud eq. 4 (saoud_fig6 and saoud_fig7 checks)"},
        {"assumption": "Steady state: Saoud's static optimum φ* is the heel reached (Saoud §V)",
         "scenarios": "robot, 3-7 m/s, 60-120 deg, l_φ 0.1 and 1 m",
         "metric": f"steady heel − φ* (deg), {len(sailing_runs)} of {len(a.steady)} runs sailing",
         "range": rng_(err), "threshold": "< 2 deg",
         "verdict": verdict.judge(err, below=2.0, magnitude=True).text("runs"),
         "effect": "the roll limit φ_max is not what the boat sails at"},
        {"assumption": "Wind on the sail balanced by the keel; hull windage p1 only (Viel eq. 5)",
         "scenarios": "position keeping, case 2, robot 6-DOF vs 3-DOF",
         "metric": "mean |lateral speed| (m/s)",
         "range": f"3-DOF {drift['paper']:.3f}, 6-DOF {drift['mujoco']:.3f} (max {drift['mujoco_max']:.2f})",
         "threshold": "6-DOF within 0.05 m/s of 3-DOF",
         "verdict": verdict.judge([drift["mujoco"] - drift["paper"]], below=0.05, magnitude=True).text("runs"),
         "effect": "see viel_fig3 for the distance to target"},
    ]


def built_row(effects: dict, config: str, title: str, paper_form: str) -> dict:
    """A row for one difference between the boat as built and the papers' boat: its effect on
    steady speed and heel over the wind plane when the papers' form is switched back on.

    Parameters
    ----------
    effects : dict
        ``(boat, config) ->`` :func:`.analysis.speed_effects`'s table.
    config : str
        The difference (a name of ``BUILT``).
    title : str
        The row's title.
    paper_form : str
        What the papers assume.
    """
    speed = {b: effects[(b, config)].attrs["diffs"] for b in BOATS}
    heel = {b: effects[(b, config)]["heel_change_deg"].to_numpy(dtype=float) for b in BOATS}
    judged_speed = verdict.judge_differences(sum(speed.values(), []), SPEED_HOLDS)
    judged_heel = verdict.judge(np.concatenate(list(heel.values())), below=HEEL_HOLDS_DEG, magnitude=True)
    holds = judged_speed.holds and judged_heel.holds

    def speed_summary(diffs):
        rel = [d.value for d in diffs if d.finite and d.relative]
        median = f"median {100 * np.median(rel):+.1f} %, " if rel else ""
        return (f"{median}{verdict.range_of(diffs)}; "
                f"{verdict.judge_differences(diffs, SPEED_HOLDS).beyond} of {len(diffs)} points beyond ±"
                f"{100 * SPEED_HOLDS:g} %")

    def heel_summary(values):
        v = verdict.finite(values)
        if not v.size:
            return "—"
        return (f"median {np.median(v):+.1f}° ({verdict.value_range(v, 1.0, '{:+.1f}')}°; "
                f"{verdict.judge(values, below=HEEL_HOLDS_DEG, magnitude=True).beyond} of {len(values)} points "
                f"beyond ±{HEEL_HOLDS_DEG:g}°)")

    return {"assumption": f"{title} ({paper_form})",
            "scenarios": "both boats, wind plane",
            "metric": "steady speed and heel, the papers' form minus as built",
            "range": "; ".join(f"{b}: speed {speed_summary(speed[b])}, heel {heel_summary(heel[b])}"
                               for b in BOATS),
            "threshold": f"|speed| < {100 * SPEED_HOLDS:.0f} % (below {SPEED_FLOOR:g} m/s as built: "
                         f"< {SPEED_HOLDS * SPEED_FLOOR:g} m/s), |heel| < {HEEL_HOLDS_DEG:g} deg",
            "verdict": ("holds" if holds else "breaks") + f" (speed: {judged_speed.text()}; heel: "
                       f"{judged_heel.text()})",
            "effect": "speed and heel, as the range (the extremes are points where one of the two "
                      "boats loses its heading or stalls)"}


def _add_resistance_notes(a: Analysis, row: dict) -> None:
    """The resistance row also reports the yacht's Froude numbers and Wille's Table 1."""
    froude = yacht_froude(a)
    table1 = a.table1
    fn = math.sqrt(9.81 * get_boat("wille_yacht").hull.length)
    row["range"] += (f"; yacht Froude number (wind plane) up to {float(np.nanmax(froude['baseline'])):.2f} "
                     f"as built, {float(np.nanmax(froude['friction_only'])):.2f} friction only")
    row["effect"] += "; Wille Table 1 (6-DOF, seed 0), as built → friction only: " + ", ".join(
        f"{sim.replace('sim', 'sim ')} roll {table1[('dsyhs', sim)]['roll_amplitude']:.2f}° → "
        f"{table1[('friction', sim)]['roll_amplitude']:.2f}°, surge {table1[('dsyhs', sim)]['mean_surge']:.2f} → "
        f"{table1[('friction', sim)]['mean_surge']:.2f} m/s (Fn "
        f"{table1[('dsyhs', sim)]['mean_surge'] / fn:.2f} → "
        f"{table1[('friction', sim)]['mean_surge'] / fn:.2f})"
        for sim in ("sim1", "sim2", "sim3"))
