"""The Fig. 7 study's report: the per-angle table over seeds, paper vs ours, the checks, and the
prose that reads them, filled from the numbers of the run."""

from __future__ import annotations

import math

import numpy as np

from ..kit import Report
from ..kit import seeds as over
from ..kit.saoud import PHI_MAX_DEG, SEED_DRAWS, TRUE_WIND, WORLDS, ratio_cell, wind_speed_10
from . import scenario
from .analysis import CLOSE, HELD_DEG, NO_GO_FRACTION, TIE, Analysis, overall
from .scenario import CHECKS, STEADY, TITLE

# the paper's sentence about Fig. 7 (it prints no number), as the 'paper' column
PAPER_TEXT = {"close": "curve only; text: close to 1", "mean_Bm": "curve only; text: below S",
              "beats": "curve only; text: S better ('better results')"}
SUMMARY_WORLDS = {"paper": "paper world", "mujoco": "6-DOF robot"}
CHECK_NAMES = {"S_no_limit": "S, no roll limit (problem 5)", "S_masthead": "S, masthead wind",
               "S_ce": "S, sail-CE wind", "S_eq4": "S, eq. 4 righting", "Bm_eq4": "Bm, eq. 4 righting"}


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of ``report.md``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass (said in the report; its findings leave the checks out).
    """
    a, n = analysis, len(analysis.seeds)
    text = Report(TITLE)
    text.summary(_summary(a))
    text.comparison(_comparison_rows(a))
    text.section("Method", over.method_line(a.seeds, what="every speed and ratio", extra=(
        f"{SEED_DRAWS} The claims: S close to vel_max at an angle when S/vel_max, paired by seed, is "
        f"above {CLOSE:g}; S better than Bm when S/Bm, paired by seed, is above {1 - TIE:g} (a law "
        "that capsizes on every seed loses to one that sails); Bm below S on average when the "
        "per-seed mean S/vel_max less mean Bm/vel_max over the sailable angles is above 0. A claim "
        "made for every angle holds when it holds at each angle, breaks when it breaks at one, and "
        "is undecided otherwise. 'vel_max, φ ≤ 30°' is seed 0's full grid only (a check: no "
        "interval and no verdict from it).")))
    text.section("Scenario", scenario.__doc__.split("\n\n", 1)[1])
    text.section("Runs", _runs_paragraph(a))
    text.section(f"S/vel_max and Bm/vel_max per angle, N = {n} seeds")
    text.table(_angle_rows(a))
    text.section("Checks: the switches, l_φ = 0.1 m",
                 f"Steady speed [m/s] over the {n} seeds of S with one thing changed, against the runs "
                 "above. '—': capsized on every seed; '(ψ)': off heading 0 on some seed.")
    for world, names in CHECKS.items():
        text.table(_check_rows(a, world, names))
    text.section("What the runs show", findings(a, smoke))
    text.paragraph(NOTES.format(phi_max=PHI_MAX_DEG, refine=a.settings.refine))
    text.section("Figure and data")
    text.figure("fig7.png", f"Fig. 7 reproduced: steady speed of S, Bm and the best fixed sail (vel_max) "
                f"against ∠v_w^B, the mean over {n} seeds with its 95 % interval; grey: no-go zone")
    text.paragraph(f"Data: `fig7.csv` (per angle, the means over the seeds), `fig7_seeds.csv` (per angle "
                   f"and seed, every law and check and that seed's vel_max), `vel_max_grid.csv` (every "
                   f"fixed-sail run, with its seed), `sweep-velmax-*/` (the sweep engine's store). "
                   f"{'Smoke run: reduced grid.' if smoke else ''}")
    return text.text()


def _summary(a: Analysis) -> str:
    """What the comparison table says, world by world, as verdicts."""
    numbers, parts = a.numbers, []
    for l_phi in a.settings.l_phis:
        for world in WORLDS:
            key = f"{world}_lphi{l_phi:g}"
            parts.append(f"{SUMMARY_WORLDS[world]}, l_φ = {l_phi:g} m: close {numbers[f'verdict_S_close_{key}']}, "
                         f"better {numbers[f'verdict_S_at_least_Bm_{key}']}")
    return (f"Steady speed of S, Bm and the best fixed sail (vel_max) per wind angle, {TRUE_WIND:g} m/s at "
            f"the sail, N = {len(a.seeds)} seeds. Paper vs ours: the paper gives curves only; its sentence 'trimming the "
            "sail with δ_s* gives better results than with [3] and ... it is close to the maximum "
            "theoretical value' is the 'paper' column; ours are over the sailable angles, paired by "
            "seed. S close to vel_max (within 10 % at every angle) and better than Bm (to 1 %): "
            + "; ".join(parts) + ".")


def _runs_paragraph(a: Analysis) -> str:
    angles, sails, refine, duration, l_phis = a.settings
    return (
        f"Angles ∠v_w^B = {', '.join(f'{x:g}' for x in angles)}°. vel_max: the sweep engine "
        f"sails every fixed sail angle {sails[0]:g}-{sails[-1]:g}° by {sails[1] - sails[0]:g}° "
        f"(set to leeward) at every angle on seed 0, then the best one and it ± {refine:g}° on every seed, "
        f"so the best sail is found to {refine:g}°. {duration:g} s per run from 1 m/s near heading 0 (the "
        f"speed settles in 10-15 s); the steady speed is the mean speed over ground in the last {STEADY:g} s. "
        f"l_φ = {', '.join(f'{x:g}' for x in l_phis)} m; true wind {TRUE_WIND:g} m/s at the sail's CE "
        f"({wind_speed_10():.2f} m/s at 10 m, log profile: see the Fig. 6 report); S with "
        f"φ_max = {PHI_MAX_DEG:g}°; S and Bm are fed Saoud's V (Fig. 6 report, choice 3). "
        f"{a.runs} simulations. vel_max is not roll-limited (the paper does not say it is); "
        f"'vel_max, φ ≤ {PHI_MAX_DEG:g}°' is the best fixed sail that heels at most {PHI_MAX_DEG + 1:g}°. The "
        f"no-go zone: angles where even the best fixed sail makes less than {NO_GO_FRACTION:g} |v_w| "
        f"= {NO_GO_FRACTION * TRUE_WIND:.1f} m/s on average over the seeds; ratios are not scored there. "
        f"A run 'off heading' has an rms heading error above {HELD_DEG:g}° (it rounded up).")


def _deg_cell(a: Analysis, world, l_phi, angle, column, digits: int = 0) -> str:
    return over.interval(np.degrees(a.values(world, l_phi, angle, column))).fixed(digits)


def _angle_rows(a: Analysis) -> list[dict]:
    rows = []
    for _, r in a.table.sort_values(["l_phi", "world", "angle"]).iterrows():
        w, lp, x = r["world"], r["l_phi"], r["angle"]
        sailable = not r["no_go"]
        rows.append({"l_φ (m)": f"{lp:g}", "world": w, "∠v_w^B": f"{x:g}°",
                     "vel_max (m/s)": over.cell(a.interval(w, lp, x, "vel_max")),
                     "its sail / φ (deg)": f"{a.interval(w, lp, x, 'sail_vel_max').fixed(0)} / "
                                           f"{_deg_cell(a, w, lp, x, 'heel_vel_max')}",
                     f"vel_max, φ ≤ {PHI_MAX_DEG:g}° (seed 0)": r["vel_max_30"],
                     "S (m/s)": over.cell(a.interval(w, lp, x, "S")),
                     "Bm (m/s)": over.cell(a.interval(w, lp, x, "Bm")),
                     "sail S / Bm (deg)": f"{a.interval(w, lp, x, 'sail_S').fixed(0)} / "
                                          f"{a.interval(w, lp, x, 'sail_Bm').fixed(0)}",
                     "S/vel_max": ratio_cell(a.ratio(w, lp, x, "S", "vel_max")),
                     "Bm/vel_max": ratio_cell(a.ratio(w, lp, x, "Bm", "vel_max")),
                     "S/Bm": ratio_cell(a.ratio(w, lp, x, "S", "Bm")),
                     "close / better": f"{a.close(w, lp, x)} / {a.beats(w, lp, x)}" if sailable else "—",
                     "φ S (deg)": _deg_cell(a, w, lp, x, "heel_S", 1), "note": _note(a, r)})
    return rows


def _comparison_rows(a: Analysis) -> list[dict]:
    numbers, rows = a.numbers, []
    for l_phi in a.settings.l_phis:
        for world in WORLDS:
            key = f"{world}_lphi{l_phi:g}"
            angles = a.sailable(world, l_phi)
            close = [a.close(world, l_phi, x) for x in angles]
            beats = [a.beats(world, l_phi, x) for x in angles]
            worst = _worst(a, world, l_phi)
            gap = a.mean_gap(world, l_phi)
            rows += [
                {"quantity": f"S/vel_max at the worst angle, l_φ = {l_phi:g} m", "world": world,
                 "paper": PAPER_TEXT["close"],
                 "ours": ratio_cell(a.ratio(world, l_phi, worst, "S", "vel_max")) if worst is not None else "—",
                 "cause": f"close: {numbers[f'verdict_S_close_{key}']} ({_count(close)}); "
                          + _cause_s(a, world, l_phi)},
                {"quantity": f"mean S/vel_max − mean Bm/vel_max, l_φ = {l_phi:g} m", "world": world,
                 "paper": PAPER_TEXT["mean_Bm"], "ours": over.cell(gap),
                 "cause": f"Bm below S: {numbers[f'verdict_mean_Bm_below_S_{key}']} (means over the angles: "
                          f"S {numbers[f'mean_S_over_vel_max_{key}']:.3g}, Bm "
                          f"{numbers[f'mean_Bm_over_vel_max_{key}']:.3g})"},
                {"quantity": f"share of angles with S ≥ Bm (to 1 %), l_φ = {l_phi:g} m", "world": world,
                 "paper": PAPER_TEXT["beats"], "ours": numbers[f"share_S_at_least_Bm_{key}"],
                 "cause": f"better: {numbers[f'verdict_S_at_least_Bm_{key}']} ({_count(beats)})"},
            ]
    return rows


def _count(verdicts: list[str]) -> str:
    words = [v.split(" ", 1)[0] for v in verdicts]
    held, broke = words.count("holds"), words.count("breaks")
    return f"holds at {held}, breaks at {broke}, undecided at {len(words) - held - broke} of {len(words)} angles"


def _worst(a: Analysis, world: str, l_phi: float):
    """The sailable angle with the lowest mean S/vel_max (None without one)."""
    angles = a.sailable(world, l_phi)
    means = [a.ratio(world, l_phi, x, "S", "vel_max").mean for x in angles]
    finite = [(m, x) for m, x in zip(means, angles, strict=True) if math.isfinite(m)]
    return min(finite)[1] if finite else None


def _check_rows(a: Analysis, world: str, names) -> list[dict]:
    rows = []
    g = a.table[(a.table["world"] == world) & (a.table["l_phi"] == 0.1)].sort_values("angle")
    for _, r in g.iterrows():
        x = r["angle"]
        row = {"world": world, "∠v_w^B": f"{x:g}°", "vel_max": over.cell(a.interval(world, 0.1, x, "vel_max")),
               f"vel_max, φ ≤ {PHI_MAX_DEG:g}° (seed 0)": r["vel_max_30"],
               "S": _speed(a, world, x, "S"), "Bm": _speed(a, world, x, "Bm")}
        for name in names:
            row[CHECK_NAMES[name]] = _speed(a, world, x, name)
        row["note"] = "no-go" if r["no_go"] else ""
        rows.append(row)
    return rows


def _off(a: Analysis, world, l_phi, angle, law) -> int:
    """The seeds on which ``law`` ran off heading 0 at one point."""
    return int(np.sum(np.degrees(a.values(world, l_phi, angle, f"psi_{law}")) > HELD_DEG))


def _lost(a: Analysis, world, l_phi, angle, law) -> int:
    """The seeds on which ``law`` capsized at one point."""
    return int(np.sum(~np.isfinite(a.values(world, l_phi, angle, law))))


def _note(a: Analysis, r) -> str:
    if r["no_go"]:
        return "no-go"
    notes, n = [], len(a.seeds)
    for law in ("S", "Bm"):
        lost = _lost(a, r["world"], r["l_phi"], r["angle"], law)
        off = _off(a, r["world"], r["l_phi"], r["angle"], law)
        if lost:
            notes.append(f"{law} capsizes on {lost} of {n} seeds")
        elif off:
            notes.append(f"{law} off heading on {off} of {n} seeds")
    return "; ".join(notes)


def _speed(a: Analysis, world: str, angle: float, law: str) -> str:
    """A steady speed over the seeds with '(ψ)' when off heading 0 on some seed, '—' when it
    capsized on every seed."""
    got = a.interval(world, 0.1, angle, law)
    if not math.isfinite(got.mean):
        return "—"
    lost = _lost(a, world, 0.1, angle, law)
    return (over.cell(got) + (f" (capsized {lost})" if lost else "")
            + (" (ψ)" if _off(a, world, 0.1, angle, law) else ""))


def _cause_s(a: Analysis, world: str, l_phi: float) -> str:
    x = _worst(a, world, l_phi)
    if x is None:
        return "no sailable angle"
    if _off(a, world, l_phi, x, "S") or _lost(a, world, l_phi, x, "S"):
        return (f"worst at {x:g}°: S does not hold heading 0 (rounds up or capsizes) with the geometric "
                "hull; eq. 4 righting switched in: see the checks and the Fig. 6 report")
    if a.close(world, l_phi, x) == "holds":
        return f"worst at {x:g}°"
    heel = abs(float(np.degrees(np.nanmean(a.values(world, l_phi, x, "heel_vel_max")))))
    r = a.table[(a.table["world"] == world) & (a.table["l_phi"] == l_phi) & (a.table["angle"] == x)].iloc[0]
    if heel > PHI_MAX_DEG + 1.0:
        return (f"worst at {x:g}°, where vel_max heels {heel:.0f}° > φ_max = {PHI_MAX_DEG:g}°; the best fixed "
                f"sail within {PHI_MAX_DEG:g}° makes {r['vel_max_30']:.3g} m/s on seed 0; see checks")
    return f"worst at {x:g}°" + (": see checks" if l_phi == 0.1 else "")


def findings(a: Analysis, smoke: bool) -> str:
    """What the tables say, with this run's numbers over its seeds.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    smoke : bool
        The short pass (its runs have no checks).
    """
    lines = []  # paragraphs separated by blank lines
    for l_phi in a.settings.l_phis:
        if a.sailable("paper", l_phi):
            lines += [_paper_world(a, l_phi), ""]
    if not smoke and "S_no_limit" in a.per_seed:
        lines += [_paper_checks(a), ""]
    if not smoke and "S_eq4" in a.per_seed:
        lines += [_mujoco_checks(a), ""]
    for l_phi in a.settings.l_phis:
        angles = a.sailable("mujoco", l_phi)
        if l_phi == 0.1 or not angles:
            continue
        key = f"mujoco_lphi{l_phi:g}"
        reach = [x for x in angles if x <= 150.0]
        worst_b = min(reach, key=lambda x: a.ratio("mujoco", l_phi, x, "Bm", "vel_max").mean)
        worst_s = _worst(a, "mujoco", l_phi)
        lines += [(
            f"*6-DOF, l_φ = {l_phi:g} m.* The robot barely heels (S's steady roll at most "
            f"{_extreme_heel(a, 'mujoco', l_phi)}°). S/vel_max is lowest at {worst_s:g}°, "
            f"{ratio_cell(a.ratio('mujoco', l_phi, worst_s, 'S', 'vel_max'))}; Bm/vel_max falls to "
            f"{ratio_cell(a.ratio('mujoco', l_phi, worst_b, 'Bm', 'vel_max'))} at {worst_b:g}°. S close to "
            f"vel_max {a.numbers[f'verdict_S_close_{key}']}, S better than Bm "
            f"{a.numbers[f'verdict_S_at_least_Bm_{key}']}."), ""]
    return "\n".join(lines)


def _extreme_heel(a: Analysis, world: str, l_phi: float, law: str = "S") -> str:
    """The interval of the steady roll of ``law`` [deg] at the angle where its mean is largest in size."""
    cells = [over.interval(np.degrees(a.values(world, l_phi, x, f"heel_{law}")))
             for x in a.sailable(world, l_phi)]
    cells = [c for c in cells if math.isfinite(c.mean)]
    return max(cells, key=lambda c: abs(c.mean)).fixed(1) if cells else "—"


def _paper_world(a: Analysis, l_phi: float) -> str:
    angles = a.sailable("paper", l_phi)
    key = f"paper_lphi{l_phi:g}"
    reach = [x for x in angles if x <= 150.0]
    worst_b = min(reach, key=lambda x: a.ratio("paper", l_phi, x, "Bm", "vel_max").mean)
    worst_s = _worst(a, "paper", l_phi)
    low = [x for x in angles if x <= 30.0]
    sail = {k: a.interval("paper", l_phi, worst_b, k).fixed(0) for k in ("sail_Bm", "sail_S", "sail_vel_max")}
    text = (
        f"*Paper world, l_φ = {l_phi:g} m.* S close to vel_max {a.numbers[f'verdict_S_close_{key}']} "
        f"({_count([a.close('paper', l_phi, x) for x in angles])}); its lowest S/vel_max is "
        f"{ratio_cell(a.ratio('paper', l_phi, worst_s, 'S', 'vel_max'))} at {worst_s:g}°. Up to 150° Bm falls "
        f"to {ratio_cell(a.ratio('paper', l_phi, worst_b, 'Bm', 'vel_max'))} of vel_max, at {worst_b:g}°, where "
        f"its Fig. 5 ramp sets the sail at {sail['sail_Bm']}° against {sail['sail_S']}° for S and "
        f"{sail['sail_vel_max']}° for the best fixed sail.")
    if low:
        far = max(low, key=lambda x: abs(a.ratio("paper", l_phi, x, "S", "Bm").mean - 1.0))
        r = a.ratio("paper", l_phi, far, "S", "Bm")
        text += (f" Downwind (0-30°) S/Bm is furthest from 1 at {far:g}°, {ratio_cell(r)}: equal within "
                 f"{100 * TIE_BAND:.0f} % {over.decide(r, 1.0, 'within', TIE_BAND)}, as in Fig. 6's first segment.")
    else:
        text += " Downwind (0-30°) this run sails no angle to set beside Fig. 6's first segment."
    text += f" The largest steady roll of S is {_extreme_heel(a, 'paper', l_phi)}°."
    close = [float(x) for x in a.table[(a.table["world"] == "paper") & (a.table["l_phi"] == l_phi)]["angle"]
             if x > 150.0 and x in angles]
    if close:
        slowest = min(close, key=lambda x: a.interval("paper", l_phi, x, "vel_max").mean)
        bm = min(close, key=lambda x: a.ratio("paper", l_phi, x, "Bm", "vel_max").mean)
        text += (f" At {', '.join(f'{x:g}' for x in close)}° the boat still makes "
                 f"{over.cell(a.interval('paper', l_phi, slowest, 'vel_max'))} m/s with a nearly feathered "
                 "fixed sail; Bm feathers it completely (Fig. 5: δ_s = Θ_V below 15°, its no-go zone) and "
                 f"stops (Bm/vel_max {ratio_cell(a.ratio('paper', l_phi, bm, 'Bm', 'vel_max'))}).")
    return text


TIE_BAND = 0.10  # "perform equally" downwind, as the Fig. 6 study decides it: S/Bm within 10 % of 1


def _ratio_extreme(a: Analysis, world: str, angles, num: str, den: str, pick=max):
    """The (angle, interval) of num/den (paired) whose mean departs most from 1 (``pick=max``)."""
    got = {x: a.ratio(world, 0.1, x, num, den) for x in angles}
    got = {x: r for x, r in got.items() if math.isfinite(r.mean)}
    x = pick(got, key=lambda k: abs(got[k].mean - 1.0))
    return x, got[x]


def _paper_checks(a: Analysis) -> str:
    angles = a.sailable("paper", 0.1)
    gx, gain = _ratio_extreme(a, "paper", angles, "S_no_limit", "S")
    t = a.table[(a.table["world"] == "paper") & (a.table["l_phi"] == 0.1) & ~a.table["no_go"]]
    g0 = a.grid[(a.grid["world"] == "paper") & (a.grid["l_phi"] == 0.1) & (a.grid["seed"] == 0)]
    vel0 = g0[g0["status"] == "ok"].groupby("angle")["speed"].max()
    over30 = float(np.nanmax(vel0.reindex(t["angle"]).to_numpy() / t["vel_max_30"].to_numpy() - 1.0))
    collapse = {name: [x for x in angles if a.ratio("paper", 0.1, x, name, "S").mean < 0.5]
                for name in ("S_masthead", "S_ce")}
    return (
        f"*Checks (paper world, l_φ = 0.1 m).* Lifting the roll limit (problem 5) changes S by at most "
        f"{100 * abs(gain.mean - 1.0):.1f} % (at {gx:g}°, S without the limit / S with it "
        f"{ratio_cell(gain, 4)}): without the limit S commands the same sail, i.e. the optimum of "
        f"problem 5 stays within {PHI_MAX_DEG:g}° of heel at steady state (the world's steady roll of S, "
        f"up to {_extreme_heel(a, 'paper', 0.1)}°, includes roll moments that Saoud's eq. 5 leaves "
        "out, e.g. the keel's side force below the CG and a 0.86 m sail arm). vel_max is not "
        f"roll-limited, but on seed 0's full grid the best fixed sail within {PHI_MAX_DEG:g}° of heel is at "
        f"most {100 * over30:.0f} % slower. The sensor matters more than the limit: read at the masthead, the "
        f"apparent wind makes S collapse (below half its speed with Saoud's V, paired by seed) at "
        f"{', '.join(f'{x:g}' for x in collapse['S_masthead']) or 'no'}° (the roll rate times the 2.3 m "
        "mast feeds the sail law, which drives the roll: a limit cycle); read at the sail CE it collapses "
        f"at {', '.join(f'{x:g}' for x in collapse['S_ce']) or 'no'}° (on the run the boom's own swing "
        "flips the measured wind side, and the law gybes every step). Saoud's V, which the study feeds "
        "both laws, has neither.")


def _mujoco_checks(a: Analysis) -> str:
    angles = a.sailable("mujoco", 0.1)
    off = sum(_off(a, "mujoco", 0.1, x, "S") > 0 or _lost(a, "mujoco", 0.1, x, "S") > 0 for x in angles)
    off_b = sum(_off(a, "mujoco", 0.1, x, "Bm") > 0 or _lost(a, "mujoco", 0.1, x, "Bm") > 0 for x in angles)
    held4 = sum(_off(a, "mujoco", 0.1, x, "S_eq4") == 0 and _lost(a, "mujoco", 0.1, x, "S_eq4") == 0
                for x in angles)
    psi_fixed = max((over.interval(np.degrees(a.values("mujoco", 0.1, x, "psi_vel_max"))) for x in angles),
                    key=lambda c: c.mean)
    fixed = (f"while the best fixed sail holds it (rms heading error at most {psi_fixed.fixed(0)}°)"
             if psi_fixed.mean <= HELD_DEG else
             f"and the best fixed sail too at some angles (rms heading error up to {psi_fixed.fixed(0)}°)")
    if held4 >= len(angles) - 1:  # Saoud's righting moment alone puts the robot back on heading
        cause = ("Cause, checked by switching: the geometric hull's righting moment, which falls "
                 "below Saoud's m g l_φ sin φ at large heel, with the heeled sail's weather "
                 "helm (Fig. 6 report).")
    else:
        cause = ("Cause, checked by switching: the heeled sail's weather helm, the yaw moment the "
                 "4-DOF equations drop (Fig. 6 report), not the geometric hull's smaller righting "
                 "moment at large heel.")
    capsize_b = [x for x in angles if _lost(a, "mujoco", 0.1, x, "Bm")]
    if off or off_b:
        held = (f"With the geometric hull S goes off heading 0 (or capsizes) at {off} of {len(angles)} sailable "
                f"angles and Bm at {off_b} on some seed"
                + (f" (Bm capsizes at {', '.join(f'{x:g}' for x in capsize_b)}°)" if capsize_b else "")
                + f", {fixed}. {cause}")
    else:
        psi = max((over.interval(np.degrees(a.values("mujoco", 0.1, x, f"psi_{law}")))
                   for x in angles for law in ("S", "Bm")), key=lambda c: c.mean)
        held = (f"With the geometric hull both laws hold heading 0 at all {len(angles)} sailable angles on "
                f"every seed (rms heading error at most {psi.fixed(1)}°).")
    eq4 = [a.interval("mujoco", 0.1, x, "S_eq4") for x in angles]
    eq4 = [c for c in eq4 if math.isfinite(c.mean)]
    slow, fast = min(eq4, key=lambda c: c.mean), max(eq4, key=lambda c: c.mean)
    beats = [a.beats("mujoco", 0.1, x, "S_eq4", "Bm_eq4") for x in angles]
    return (
        f"*6-DOF, l_φ = 0.1 m.* {held} With eq. 4 in the 6-DOF world S holds heading at {held4} of "
        f"{len(angles)} angles on every seed and makes from {over.cell(slow)} to {over.cell(fast)} m/s; S at "
        f"least as fast as Bm (to 1 %) there: {overall(beats)} ({_count(beats)}).")


NOTES = """\
**Reading the ratios.** vel_max is an upper bound only to the grid's resolution ({refine:g}°): S can beat
it slightly (ratios just above 1). S maximises the *sail's* longitudinal force at the roll
equilibrium of its reduced model with the roll limited to {phi_max:g}°; vel_max is not roll-limited, and
the hull, keel and rudder drag and the heading controller's rudder are outside S's cost, so a
fixed sail can beat it where more heel is allowed or where a smaller sail angle lowers the
rudder's load (the boom's drive acts to leeward of the centreline and must be held by the rudder).
"""
