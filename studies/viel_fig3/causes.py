"""Viel et al. (2019) Fig. 3, the causes: what each world did in a case, said from its numbers.

One sentence per case and world, from the numbers over seeds (means with their 95 % intervals)
and the switches (which single difference brings the boat below the paper's bound; the switches
run on one seed, so they are named as that seed's numbers, not as verdicts). The report's table
and the headline's viel_boat causes use them.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from sailmujoco.tasks.position import CASES as WIND_CASES

from .scenario import (
    DEFAULT_START,
    IRONS_AWA_DEG,
    IRONS_SURGE,
    PAPER_D_T,
    PAPER_MAX_M,
    PAPER_P5,
    SWITCH_SEED,
    VARIANT_LABELS,
    is_start,
)


def fmt(value, digits: int = 1) -> str:
    """A number with ``digits`` decimals, "—" for nan; anything else as text.

    Parameters
    ----------
    value : float or object
        The value.
    digits : int
        Decimals of a float.
    """
    if isinstance(value, (float, np.floating)) and not math.isfinite(value):
        return "—"
    return f"{value:.{digits}f}" if isinstance(value, (float, np.floating)) else str(value)


def iv(value, digits: int = 1, unit: str = "") -> str:
    """An :class:`~sailmujoco.stats.Interval` as ``mean [low, high]`` with ``digits`` decimals.

    Parameters
    ----------
    value : sailmujoco.stats.Interval
        The number over seeds.
    digits : int
        Decimals.
    unit : str
        Appended after the bracket.
    """
    return value.fixed(digits, unit)


def seeds_entered(r) -> str:
    """"on k of N seeds" for a ``per_case`` row.

    Parameters
    ----------
    r : pandas.Series
        A row of :attr:`.analysis.Analysis.per_case`.
    """
    return f"{int(r['entered'])} of {int(r['n'])} seeds"


def _switch(variants: pd.DataFrame, variant: str, world: str, case: int):
    sel = variants[(variants["variant"] == variant) & (variants["world"] == world) & (variants["case"] == case)
                   & is_start(variants["start"], DEFAULT_START)]
    return None if sel.empty else sel.iloc[0]


def under_way_note(variants: pd.DataFrame, boat: str, case: int) -> str:
    """What the under-way switch (seed :data:`SWITCH_SEED`) did for ``boat`` in ``case``, or "".

    Parameters
    ----------
    variants : pandas.DataFrame
        The switching experiments.
    boat : str
        A 6-DOF boat.
    case : int
        The wind case.
    """
    u = _switch(variants, "under_way", boat, case)
    if u is None:
        return ""
    if not math.isfinite(u["entered_at"]):
        return f"; under way (seed {SWITCH_SEED}): never enters, closest {u['min_distance']:.1f} m"
    return f"; under way (seed {SWITCH_SEED}): in at {u['entered_at']:.0f} s, max after stop {u['max_after_stop']:.1f} m"


def paper_cause(r, variants: pd.DataFrame) -> str:
    """What the paper world does in one case, over the seeds, and which switch (seed
    :data:`SWITCH_SEED`) brings it below the paper's bound where it misses.

    Parameters
    ----------
    r : pandas.Series
        The case's row of :attr:`.analysis.Analysis.per_case`.
    variants : pandas.DataFrame
        The switching experiments (:class:`.analysis.Analysis`).
    """
    if not r["entered"]:
        return f"never enters ({seeds_entered(r)})"
    m, verdict = r["max_after_stop"], r["after_stop_verdict"]
    if verdict == "holds":
        return f"holds the paper's bound (enters on {seeds_entered(r)})"
    if m.mean < PAPER_MAX_M:
        what = (f"below the paper's bound on average, but the interval reaches past {PAPER_MAX_M:g} m "
                "(the start heading decides how close to the edge the boat stops)")
    elif m.mean < PAPER_D_T:
        what = "drifts towards the edge (no position term inside the area), stays inside on average"
    elif m.mean < PAPER_D_T + 1.0:
        what = f"drifts to the edge, crosses it and is sailed back ({iv(r['exits'])} exits)"
    else:
        what = "drifts out and loops through the pre-arrival ring (step 2: go round, arrive from downwind)"
    fixes = []
    for v in (("printed_rudder", "dt_0.1", "no_hull_wind") if m.mean >= PAPER_MAX_M else ()):
        x = _switch(variants, v, "paper", int(r["case"]))
        if x is not None and x["max_after_stop"] < PAPER_MAX_M:
            fixes.append(f"{VARIANT_LABELS[v]} ({x['max_after_stop']:.1f} m)")
    return (f"{verdict}: " + what
            + (f"; on seed {SWITCH_SEED} below {PAPER_MAX_M:g} m with " + ", ".join(fixes) if fixes else ""))


def boat_cause(r, variants: pd.DataFrame, capability: pd.DataFrame) -> str:
    """What a 6-DOF boat (wille_yacht, saoud_robot) does in one case, over the seeds.

    Parameters
    ----------
    r : pandas.Series
        The case's row of :attr:`.analysis.Analysis.per_case`.
    variants : pandas.DataFrame
        The switching experiments.
    capability : pandas.DataFrame
        The PID heading-hold check.
    """
    boat, case = r["world"], int(r["case"])
    speed = WIND_CASES[case][0]
    check = capability[(capability["world"] == boat) & (capability["wind_speed"] == speed)] \
        if not capability.empty else capability
    note = under_way_note(variants, boat, case)
    if not check.empty and check["rudder_saturated"].iloc[0] > 0.5:
        return (f"overpowered in {speed:g} m/s: a PID cannot hold 45° off the wind either (rudder at its stop, "
                f"{check['steady_speed'].iloc[0]:.2f} m/s)" + note)
    if not r["entered"]:
        return (f"never enters ({seeds_entered(r)}; closest {iv(r['min_distance'])} m): the first turn "
                "through the wind from 0.5 m/s with eq. 15's 13° sail stalls, the boat drifts" + note)
    if r["after_stop_verdict"] == "holds":
        return f"holds the paper's bound (enters on {seeds_entered(r)})"
    way = "cannot stay" if r["max_after_stop"].mean >= PAPER_MAX_M else "stays on average"
    return (f"enters on {seeds_entered(r)} but {way}: {iv(r['max_after_stop'])} m after the stop "
            f"({r['after_stop_verdict']})" + note)


def viel_boat_cause(r, variants: pd.DataFrame) -> str:
    """The measured cause for viel_boat in one case, from its samples (:func:`.measures.behaviour`)
    over the seeds.

    Parameters
    ----------
    r : pandas.Series
        The case's row of :attr:`.analysis.Analysis.per_case`.
    variants : pandas.DataFrame
        The switching experiments.
    """
    note = under_way_note(variants, "viel_boat", int(r["case"]))
    if r["entered"]:
        if r["after_stop_verdict"] == "holds":
            return f"holds the paper's bound (enters on {seeds_entered(r)}, at {iv(r['entered_at'], 0)} s)"
        drift = ""
        speed, down = r["drift_speed"], r["drift_downwind"]
        if math.isfinite(speed.mean):
            surge, sway = r["surge_after_stop"], r["sway_after_stop"]
            way = ("downwind" if down.mean > 0.5 * speed.mean else
                   "upwind" if down.mean < -0.5 * speed.mean else "across the wind")
            drift = (f": from the stop on it makes {iv(speed, 2)} m/s over ground, mostly {way} on average, "
                     f"with surge {iv(surge, 2)} m/s, sideways {iv(sway, 2)} m/s and the sail eased to "
                     f"{iv(r['sail_after_stop_deg'], 0)}°")
            if sway.mean > 0.3 * abs(surge.mean):
                leeway = math.degrees(math.atan2(sway.mean, abs(surge.mean)))
                drift += (f"; the slow boat slips sideways at about {leeway:.0f}° of leeway (from the means), "
                          "where Viel's eq. 5 has no sail side force and resists sideways motion with its "
                          f"rudder term g_ru (eq. 8, p5 = {PAPER_P5:g} kg/s), while a 6-DOF keel's lift "
                          "falls with the square of the speed")
        return (f"enters on {seeds_entered(r)} (at {iv(r['entered_at'], 0)} s) but drifts to "
                f"{iv(r['max_after_stop'])} m after the stop ({r['after_stop_verdict']}), {iv(r['exits'])} exits"
                + drift + note)
    irons, stop = r["irons_fraction"].scaled(100.0), r["rudder_stop_fraction"].scaled(100.0)
    if irons.mean > 30.0:
        what = (f"never enters ({seeds_entered(r)}): in irons {iv(irons, 0)} % of the run (|AWA| < "
                f"{IRONS_AWA_DEG:g}°, surge < {IRONS_SURGE:g} m/s; mean surge {iv(r['surge_mean'], 2)} m/s) with "
                f"the rudder on its stop {iv(stop, 0)} % of the time: the turn from the start heading to the "
                "first tack goes through the wind and the rudder, whose lift falls with v², cannot bear away")
    else:
        what = (f"never enters ({seeds_entered(r)}): sails (mean surge {iv(r['surge_mean'], 2)} m/s, heel up to "
                f"{iv(r['heel_max_deg'], 0)}°, mostly '{r['main_mode']}') but comes no closer than "
                f"{iv(r['min_distance'])} m")
    return what + note


def ten_metres_a_second(capability: pd.DataFrame) -> str:
    """What the PID heading-hold check shows of each 6-DOF boat on the 45°-off-the-wind tack in 10 m/s.

    Parameters
    ----------
    capability : pandas.DataFrame
        The PID heading-hold check.
    """
    rows = capability[capability["wind_speed"] == 10.0] if not capability.empty else capability
    if not rows.empty:  # the boats in a fixed order, whatever order the worker pool returned them in
        rows = rows.sort_values("world", kind="stable")
    if rows.empty:
        return "the boats were not checked"
    parts, overpowered = [], True
    for _, c in rows.iterrows():
        stop = c["rudder_saturated"] > 0.5
        slide = abs(c["sway_mean"]) > 0.5 * abs(c["surge_mean"])
        overpowered &= bool(stop or slide)
        parts.append(f"{c['world']} {c['steady_speed']:.2f} m/s, {abs(c['sway_mean']):.2f} m/s of it "
                     f"sideways, rudder {'on its stop' if stop else f'{c.rudder_mean_deg:.0f}° on average'}, "
                     f"heading error rms {c['heading_error_rms_deg']:.0f}°")
    verdict = ("both boats are overpowered 45° off the wind, the tack Viel's step 3 asks for"
               if overpowered else "not both boats are overpowered 45° off the wind")
    return f"{verdict} (a PID heading rudder: {'; '.join(parts)})"
