"""Viel et al. (2019) Fig. 3, the report: the prose of report.md, filled from the analysis.

The summary (the paper's claims per world as pass counts with Wilson intervals and verdicts),
the method line and the table per case and world (means over seeds with their intervals, the
6-DOF boats paired by seed with the paper world); then the scenario, viel_boat case by case, the
measure (from the stop), the trajectories, the paper world's switches and start grid, why the
6-DOF boats miss, the choices, what the runs cost. The paper's values come from the ``PAPER_*``
constants of :mod:`.scenario`.
"""

from __future__ import annotations

import math

import pandas as pd

from sailmujoco import stats
from sailmujoco.boat.catalogue import get_boat

from ..kit import Report
from ..kit.seeds import method_line
from .analysis import CLAIMS, Analysis, passes
from .causes import boat_cause, fmt, iv, paper_cause, ten_metres_a_second, viel_boat_cause
from .figures import FIGURES
from .scenario import (
    ABOUT,
    CASES,
    DEFAULT_START,
    LABELS,
    PAPER_D_T,
    PAPER_DT,
    PAPER_MAX_M,
    PAPER_P5,
    RATE_BOUND,
    SWITCH_CASES_6DOF,
    SWITCH_SEED,
    TITLE,
    TRAJECTORY_RATE,
    VARIANT_LABELS,
    VIEL_LENGTH,
    WEIGHTS,
    WORLDS,
    is_start,
)

ONE_SEED = (f"seed {SWITCH_SEED} alone, a diagnostic of the mechanism: these numbers are that seed's, and no "
            "verdict is drawn from them")


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of report.md.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The study's short pass (said in the title).
    """
    r = Report(TITLE + (" (smoke)" if smoke else ""))
    r.summary(_summary(analysis))
    r.table(_claim_rows(analysis))
    r.section("Method, and every case", _method(analysis))
    r.paragraph(f"Per case and world (task start (-30, 40) m, dt {PAPER_DT:g} s, N = {len(analysis.seeds)} "
                "seeds; a distance after entry rests on the seeds that entered; *vs paper world* is the "
                "6-DOF boat minus the paper world, seed by seed, over the seeds where both entered):")
    _per_case(r, analysis)
    r.paragraph(_undecided(analysis))
    r.section("Scenario", ABOUT)
    _viel_boat_cases(r, analysis)
    _measure(r)
    _figures(r, analysis)
    _paper_world(r, analysis)
    _six_dof(r, analysis)
    _choices(r, analysis)
    _durations(r, analysis)
    return r.text()


def claim_text(analysis: Analysis, world: str, claim: str) -> str:
    """"k of n (rate [low, high], verdict)" for one world and claim.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    world : str
        A key of ``WORLDS``, or ``"grid"``.
    claim : str
        A key of :data:`.analysis.CLAIMS`.
    """
    c = analysis.claim(world, claim)
    return f"{int(c['passed'])} of {int(c['n'])} ({c['rate'].fixed(2)}, *{c['verdict']}*)"


def _summary(a: Analysis) -> str:
    n = len(a.seeds)
    grid = a.grid
    paper = (
        f"**Paper world (Viel's 3-DOF, task start, {len(a.cases)} cases × N = {n} seeds): enters the target "
        f"area in {claim_text(a, 'paper', 'entered')}, stays within d_T = {PAPER_D_T:g} m after entry (the "
        f"reproduction criterion) in {claim_text(a, 'paper', 'inside_after_entry')} and within the paper's "
        f"{PAPER_MAX_M:g} m after the stop in {claim_text(a, 'paper', 'below_bound_after_stop')}.** Over "
        f"{grid['start'].nunique()} starts: {PAPER_D_T:g} m in "
        f"{claim_text(a, 'grid', 'inside_after_entry')}, {PAPER_MAX_M:g} m after the stop in "
        f"{claim_text(a, 'grid', 'below_bound_after_stop')}.")
    like = ""
    if not a.per_case[a.per_case["world"] == "viel_boat"].empty:
        like = (
            f"\n\n**Like for like in 6-DOF (viel_boat): enters in "
            f"{claim_text(a, 'viel_boat', 'entered')}, but stays within {PAPER_MAX_M:g} m after the stop in "
            f"{claim_text(a, 'viel_boat', 'below_bound_after_stop')}**; its largest excursions after the stop "
            f"exceed the paper world's by {_paired_range(a, 'viel_boat')} m (paired by seed). "
            f"wille_yacht enters in {claim_text(a, 'wille_yacht', 'entered')} and stays within "
            f"{PAPER_MAX_M:g} m in {claim_text(a, 'wille_yacht', 'below_bound_after_stop')}; saoud_robot "
            f"enters in {claim_text(a, 'saoud_robot', 'entered')}.")
    return paper + like + "\n\nPer world (a run that never enters fails all three claims):"


def _paired_range(a: Analysis, world: str) -> str:
    """The smallest and largest per-case paired mean difference from the paper world, with intervals."""
    rows = a.per_case[a.per_case["world"] == world]
    diffs = [d for d in rows["max_after_stop_minus_paper"] if math.isfinite(d.mean)]
    if not diffs:
        return "— (no case where both entered)"
    lo, hi = min(diffs, key=lambda d: d.mean), max(diffs, key=lambda d: d.mean)
    return iv(lo) if lo is hi else f"{iv(lo)} to {iv(hi)}"


def _claim_rows(a: Analysis) -> list[dict]:
    rows = []
    for key in (*WORLDS, "grid"):
        if a.worlds[a.worlds["world"] == key].empty:
            continue
        label = LABELS.get(key, "paper world over all starts")
        row = {"world": label}
        for claim, text in CLAIMS.items():
            c = a.claim(key, claim)
            row[text] = f"{int(c['passed'])}/{int(c['n'])}: {c['rate'].fixed(2)} *{c['verdict']}*"
        rows.append(row)
    return rows


def _method(a: Analysis) -> str:
    cost = a.cost
    return method_line(
        a.seeds, what="every distance and time over seeds",
        extra=(f"The seed draws the start heading, uniform over the compass (the task's own draw; the wind "
               f"has no gusts), in every world, so the worlds are compared seed by seed. A count (\"enters in "
               f"k of n\") carries Wilson's 95 % interval; a claim the paper makes for every run holds for a "
               f"world when the whole interval of its pass rate lies above {RATE_BOUND:g} (it holds in most "
               f"runs) and breaks when it lies below. Per case, the max distance after the stop is checked "
               f"against the paper's {PAPER_MAX_M:g} m and the task's max distance after entry against d_T = "
               f"{PAPER_D_T:g} m (the boat enters at 7 m, so that metric sits on its bound unless the boat "
               f"leaves again). The switches and the heading-hold check run on {ONE_SEED}. N = {len(a.seeds)} "
               f"costs {cost['total']:.0f} simulated seconds ({cost['headline']:.0f} on every seed, "
               f"{cost['switches']:.0f} for the switches; a 6-DOF second counts {WEIGHTS['mujoco']:g}, a "
               f"paper-world second {WEIGHTS['paper']:g})."))


def _per_case(r: Report, a: Analysis) -> None:
    rows = []
    for key in WORLDS:
        for _, x in a.per_case[a.per_case["world"] == key].iterrows():
            cause = (paper_cause(x, a.variants) if key == "paper" else viel_boat_cause(x, a.variants)
                     if key == "viel_boat" else boat_cause(x, a.variants, a.capability))
            entered = bool(x["entered"])
            rows.append({
                "case": int(x["case"]), "world": LABELS[key], "entered": f"{int(x['entered'])}/{int(x['n'])}",
                "entered at (s)": iv(x["entered_at"], 0) if entered else "—",
                "max after entry, task (m)": iv(x["max_distance_after_entry"], 2) if entered else "—",
                f"< {PAPER_D_T:g} m after entry": x["after_entry_verdict"] or "never enters",
                "max after stop (m)": iv(x["max_after_stop"], 2) if entered else "—",
                f"< {PAPER_MAX_M:g} m after the stop": x["after_stop_verdict"] or "never enters",
                "after stop, vs paper world (m)": (iv(x["max_after_stop_minus_paper"], 2)
                                                   if math.isfinite(x["max_after_stop_minus_paper"].mean)
                                                   else "—"),
                "cause": cause})
    r.table(rows)


def _undecided(a: Analysis) -> str:
    """Which per-case verdicts after the stop stay undecided, and what the single runs say there."""
    open_ = a.per_case[a.per_case["after_stop_verdict"].str.startswith("undecided")]
    if open_.empty:
        return (f"Every case that entered is decided against the paper's {PAPER_MAX_M:g} m after the stop at "
                f"N = {len(a.seeds)}.")
    parts, runs = [], []
    for key in WORLDS:
        cases = [int(c) for c in open_[open_["world"] == key]["case"]]
        if cases:
            parts.append(f"{key} case{'s' if len(cases) > 1 else ''} {', '.join(map(str, cases))}")
            runs.append(a.main[(a.main["world"] == key) & a.main["case"].isin(cases)]["max_after_stop"].dropna())
    values = pd.concat(runs)
    below = int((values < PAPER_MAX_M).sum())
    return (f"Undecided at N = {len(a.seeds)} against {PAPER_MAX_M:g} m after the stop: {'; '.join(parts)}. "
            f"There the max distance varies widely with the start heading, and a Student-t interval of "
            f"{len(a.seeds)} values is wide; of those cases' {len(values)} runs "
            f"{below} stay within {PAPER_MAX_M:g} m (smallest {values.min():.1f} m), so the per-world counts "
            "above decide the claim, and more seeds would decide the cases.")


def _viel_boat_cases(r: Report, a: Analysis) -> None:
    vb = a.per_case[a.per_case["world"] == "viel_boat"]
    if vb.empty:
        return
    r.section("Like for like in 6-DOF: what viel_boat does, case by case",
              "Means over the seeds with their intervals; the under-way notes are the switch's, on "
              f"seed {SWITCH_SEED} alone.")
    for _, x in vb.iterrows():
        r.paragraph(f"Case {int(x['case'])}: {viel_boat_cause(x, a.variants)}.")


def _measure(r: Report) -> None:
    r.section(
        f"The measure: {PAPER_MAX_M:g} m is about what happens after the boat has stopped",
        f"The boat enters the target area at d = d_T = {PAPER_D_T:g} m, so the task's "
        "`max_distance_after_entry` starts from the entry crossing and is never below ~6.9 m, whatever "
        f"the boat does next. The paper's {PAPER_MAX_M:g} m can only be read as the excursions once the "
        "boat has arrived; we measure them from the *stop*, the first minimum of the distance after "
        "entry (`max after stop`). The task's metric is kept next to it: "
        f"'< {PAPER_D_T:g} m' (the reproduction criterion) is the same on both. Per case its mean sits "
        f"on the bound ({PAPER_D_T:g} m, the crossing itself) whenever the boat stays in, so its verdict "
        "there stays undecided at any N; the count of runs that stay inside decides it.")


def _figures(r: Report, a: Analysis) -> None:
    n = len(a.seeds)
    r.section("Trajectories",
              f"Every seed's run from the task start (one line each, N = {n}); below them, the distance to "
              "the target as the mean over the seeds with its 95 % band.")
    r.figure(FIGURES["paper"], "Paper world: trajectories (target area green, pre-arrival area between "
                               "the red circles, wind red) and the distance to the target")
    r.figure(FIGURES["viel_boat"], "viel_boat (6-DOF): Viel's Table 1 boat, like for like")
    r.figure(FIGURES["wille_yacht"], "wille_yacht (6-DOF)")
    r.figure(FIGURES["saoud_robot"], "saoud_robot (6-DOF)")
    r.figure(FIGURES["summary"], f"(a) Max distance after the stop per world and case: mean over N = {n} "
                                 f"seeds with its 95 % interval; (b) the paper world's switches, seed "
                                 f"{SWITCH_SEED} alone; (c) every paper-world run over the starts, eqs. 7-8 "
                                 "read linear (ours) and as printed")


def _paper_world(r: Report, a: Analysis) -> None:
    r.section(
        "Paper world: the reading of eqs. 7-8, and what moves the boat out",
        "Eqs. 7-8 print the rudder forces as p5 v² sin δr and p5 u|u| cos δr, but Table 1 gives p5 = "
        f"{PAPER_P5:g} in kg/s, which is a force only when multiplied by a speed: Jaulin's rudder law p5 v "
        "sin δr, the model Table 1's p1-p11 come from. We read the squares as the misprint (both eqs.; "
        "the comment in `sailmujoco/reference/viel.py` gives the reasoning) and keep the printed law as a "
        "switch. Inside the target area the strategy (§4.3 step 4, eqs. 19-22) steers head to wind with "
        "the sail luffing while v > 0 and sails close-hauled while v ≤ 0; it has no position term, so the "
        "boat stays in only if it can keep its heading while nearly stopped. With the printed v² the "
        "rudder has no authority at v ≈ 0: the boat stalls beam-on, the two modes alternate every step, "
        "and the hull wind (p1 a_tw²) pushes it sideways out of the area; on the upwind half, step 2 "
        "(arrive from downwind) then sends it round through the pre-arrival area (14-18 m). "
        f"Max distance after the stop (m) from the task start, one switch at a time, on {ONE_SEED}:")
    r.table(_switch_rows(a.variants))
    _printed_against_linear(r, a)
    _grid(r, a)


def _switch_rows(variants: pd.DataFrame) -> list[dict]:
    rows = []
    for v in ("baseline", "printed_rudder", "dt_0.1", "no_hull_wind"):
        sel = variants[(variants["variant"] == v) & (variants["world"] == "paper")
                       & is_start(variants["start"], DEFAULT_START)].set_index("case")
        if sel.empty:
            continue
        row = {"switch": VARIANT_LABELS[v]}
        row.update({f"case {c}": fmt(sel.loc[c, "max_after_stop"], 2) for c in CASES if c in sel.index})
        row[f"cases < {PAPER_MAX_M:g} m"] = int((sel["max_after_stop"] < PAPER_MAX_M).sum())
        rows.append(row)
    return rows


def _printed_against_linear(r: Report, a: Analysis) -> None:
    grid, variants = a.grid, a.variants
    printed = variants[variants["variant"] == "printed_rudder"]
    if printed.empty:
        return
    same = grid[(grid["seed"] == SWITCH_SEED)
                & grid["start"].map(lambda s: tuple(s) in {tuple(x) for x in printed["start"]})]
    r.paragraph(
        f"Over the same {len(printed)} (start, case) pairs on seed {SWITCH_SEED}: below {PAPER_MAX_M:g} m after "
        f"the stop {int((same['max_after_stop'] < PAPER_MAX_M).sum())} of {len(same)} with eqs. 7-8 read linear, "
        f"{int((printed['max_after_stop'] < PAPER_MAX_M).sum())} of {len(printed)} as printed (v²); "
        f"below {PAPER_D_T:g} m after entry: {int((same['max_distance_after_entry'] < PAPER_D_T).sum())} vs "
        f"{int((printed['max_distance_after_entry'] < PAPER_D_T).sum())} (one seed: no verdict).")


def _grid(r: Report, a: Analysis) -> None:
    grid = a.grid
    n = len(a.seeds)
    r.paragraph(f"Start position, as the paper (dt {PAPER_DT:g} s): max distance after the stop (m), mean "
                f"over N = {n} seeds (start headings) with its interval, and how many runs stay within "
                f"{PAPER_MAX_M:g} m after the stop:")
    rows = []
    for start in dict.fromkeys(tuple(s) for s in grid["start"]):
        at = grid[is_start(grid["start"], start)]
        row = {"start (m)": f"({start[0]:g}, {start[1]:g})"}
        for c in sorted(set(at["case"])):
            row[f"case {c}"] = iv(stats.mean_interval(at[at["case"] == c]["max_after_stop"].to_numpy(float)), 2)
        ok = passes(at)["below_bound_after_stop"]
        row[f"< {PAPER_MAX_M:g} m"] = f"{int(ok.sum())}/{len(ok)}"
        rows.append(row)
    r.table(rows)
    reach = grid["to_paper_bound_s"]
    leave = stats.pass_rate(int((grid["exits"] > 0).sum()), len(grid))
    below = a.claim("grid", "below_bound_after_stop")
    r.paragraph(
        f"Of these {len(grid)} runs, {int(reach.notna().sum())} drift to {PAPER_MAX_M:g} m within the "
        f"{a.duration:g} s"
        + (f" ({iv(stats.mean_interval(reach.to_numpy(float)), 0)} s after the stop)" if reach.notna().any() else "")
        + f" and {int((grid['exits'] > 0).sum())} leave the area at least once ({leave.fixed(2)} of the runs). "
        + ("Reading: the start decides where and how fast the boat arrives; the runs that leave are those "
           "where the boat stops close to the edge on the upwind half, drifts out, and step 2 sends it round "
           "the pre-arrival ring. " if (grid["exits"] > 0).any() else "")
        + f"The paper's {PAPER_MAX_M:g} m after the stop holds in "
        f"{int(below['passed'])} of {int(below['n'])} runs ({below['rate'].fixed(2)}, *{below['verdict']}*).")


def _six_dof(r: Report, a: Analysis) -> None:
    variants, capability = a.variants, a.capability
    r.section("6-DOF boats: why they miss")
    if not capability.empty:
        r.paragraph(
            "What the boats can sail, independent of Viel's laws: a PID heading rudder with the leeward "
            "sail rule (task heading_hold, steady wind from the south, start 1 m/s) holding 135°, i.e. "
            f"45° off the wind, the tack Viel's step 3 asks for from the task's start; {ONE_SEED}:")
        r.table([{"boat": x["world"], "true wind (m/s)": fmt(x["wind_speed"], 0),
                  "steady speed (m/s)": fmt(x["steady_speed"], 2),
                  "surge / sway (m/s)": f"{x['surge_mean']:.2f} / {x['sway_mean']:.2f}",
                  "mean rudder (deg)": fmt(x["rudder_mean_deg"]),
                  "heading error rms (deg)": fmt(x["heading_error_rms_deg"])}
                 for _, x in capability.sort_values(["world", "wind_speed"]).iterrows()])
    r.paragraph(f"Max distance after the stop (m) and the entry time, one switch at a time, on {ONE_SEED}:")
    r.table(_six_dof_rows(variants))
    r.paragraph(_six_dof_reading(a))
    r.figure(FIGURES["six_dof"], f"6-DOF boats in case 2 (5 m/s), seed {SWITCH_SEED}: task start, under way, "
                                 "scaled circles")


def _six_dof_rows(variants: pd.DataFrame) -> list[dict]:
    rows = []
    for boat in ("viel_boat", "wille_yacht", "saoud_robot"):
        for v in ("baseline", "under_way", "under_way_scaled"):
            sel = variants[(variants["variant"] == v) & (variants["world"] == boat)].set_index("case")
            if sel.empty:
                continue
            row = {"boat": boat, "switch": VARIANT_LABELS[v], "d_T (m)": fmt(float(sel["d_T"].iloc[0]), 1)}
            for c in CASES:
                if c in sel.index:
                    e, m = sel.loc[c, "entered_at"], sel.loc[c, "max_after_stop"]
                    row[f"case {c}"] = "never in" if not math.isfinite(e) else f"{m:.1f} (in {e:.0f} s)"
                else:
                    row[f"case {c}"] = "not run"
            rows.append(row)
    return rows


def _six_dof_reading(a: Analysis) -> str:
    variants = a.variants

    def case2(boat, variant):
        sel = variants[(variants["variant"] == variant) & (variants["world"] == boat) & (variants["case"] == 2)]
        if sel.empty:
            return "not run"
        x = sel.iloc[0]
        return ("never enters" if not math.isfinite(x["entered_at"])
                else f"in at {x['entered_at']:.0f} s, max after the stop {x['max_after_stop']:.1f} m")

    robot = a.case_row("saoud_robot", 2)
    robot_in = (f"enters in case 2 on {int(robot['entered'])} of {int(robot['n'])} seeds"
                if robot is not None else "was not run in case 2")
    scale = get_boat("wille_yacht").hull.length / VIEL_LENGTH
    windy = variants[variants["variant"].isin(("under_way", "under_way_scaled")) & (variants["case"] != 2)]
    kept = windy["entered_at"].notna() & (windy["max_after_stop"] < PAPER_MAX_M * windy["d_T"] / PAPER_D_T)
    windy_text = (
        f"on seed {SWITCH_SEED}, started under way (and with the circles scaled), the boats stay within the "
        f"(scaled) {PAPER_MAX_M:g} m after the stop in {int(kept.sum())} of {len(windy)} runs in "
        f"case{'s' if windy['case'].nunique() > 1 else ''} {', '.join(map(str, sorted(set(windy['case']))))}" if len(windy) else "the under-way switch ran in 5 m/s only")
    return (
        f"Reading: (1) in 10 m/s (cases 1, 3-6) {ten_metres_a_second(a.capability)}, while Viel's boat "
        f"has a rudder lift p5 = {PAPER_P5:g} kg/s and no sail side force in eq. 5; {windy_text}. (2) In 5 m/s (case 2) both boats can sail the tack, but from the task's start (0.5 m/s) "
        "the first turn can go through the wind, and Viel's sail law sets eq. 15's close-hauled 13° from "
        "the first step: at 0.5 m/s the apparent wind is broad, the sail's force is mostly side force that "
        f"the keel cannot carry at that speed, and the boat ends in irons or sliding sideways: the robot "
        f"{robot_in}. Started under way on the tack (135°, 1.5 m/s, seed {SWITCH_SEED}) the 1.5 m robot: "
        f"{case2('saoud_robot', 'under_way')} (paper < {PAPER_MAX_M:g} m). (3) The 8.8 m yacht under way: "
        f"{case2('wille_yacht', 'under_way')}; with the circles scaled to its length (× {scale:.1f}, Viel's "
        f"boat taken as {VIEL_LENGTH:g} m; d_T {PAPER_D_T * scale:.1f} m, the paper's bound scaled "
        f"{PAPER_MAX_M * scale:.1f} m): {case2('wille_yacht', 'under_way_scaled')}. These are single runs: "
        "they show the mechanism, the verdicts above rest on the seeds.")


def _choices(r: Report, a: Analysis) -> None:
    r.section(
        "Choices",
        f"* Start: the task's default (-30, 40) m at 0.5 m/s on a heading the seed draws (uniform over the "
        f"compass), seeds 0-{len(a.seeds) - 1} in every world (Viel does not print the starts of Fig. 3); the "
        "paper world also runs from four more starts on the same seeds.\n"
        f"* Control period dt = {PAPER_DT:g} s (§5.1: eq. 14's dt), the same in all worlds; the "
        "suite's 0.1 s is a switch on the paper world (a tenth of the run time).\n"
        "* Wind: the task's (a_tw as the 10 m wind, the 1 Hz oscillations as printed, no gusts). Controller "
        "gains exactly §5.1; its actions clipped to each boat's limits (35° rudder on the 6-DOF boats).\n"
        "* 'Max after entry' is the task's metric over every control step; the stop, 'max after stop', "
        f"the time to {PAPER_MAX_M:g} m and the exits come from {TRAJECTORY_RATE:g} Hz samples.\n"
        f"* The switches change one thing each, on seed {SWITCH_SEED}, and are diagnostics, not the paper's "
        f"setup; the 6-DOF switches run in cases {', '.join(map(str, SWITCH_CASES_6DOF))} (the steady 10 and "
        "5 m/s winds and the widest swing) to keep the seeds within the study's time; the under-way start is "
        "defined in this study only.\n"
        "* Video: `sailmujoco study viel_fig3 --video` films the scenario in `VIDEO` (the saoud_robot, case 2).")


def _durations(r: Report, a: Analysis) -> None:
    main, variants, grid, capability = a.main, a.variants, a.grid, a.capability
    bad = int((pd.concat([grid, main[main["world"] != "paper"]])["status"] != "ok").sum())
    switches = len(variants) - int((variants["variant"] == "baseline").sum()) + len(capability)
    cost = a.cost
    r.section(
        "Durations",
        f"Simulations{' (smoke)' if a.smoke else ''}: {len(grid)} paper-world runs, "
        f"{len(main[main['world'] != 'paper'])} 6-DOF runs from the task start, {switches} switch runs: "
        f"{cost['total']:.0f} simulated seconds, weighted (the wall times are in the study's log)."
        + (f" Failed or stopped sweep runs: {bad}." if bad else ""))
    r.paragraph(
        "Files: `summary.csv` (every world, case and seed), `per_case.csv` (means over seeds with their "
        "interval ends), `claims.csv` (pass counts with Wilson intervals and verdicts), `trajectories.csv` "
        "(2 Hz, every seed), `switches.csv`, `start_grid.csv`, `heading_hold_check.csv`, `sweeps/<world>/` "
        "(the sweep engine's store).")

