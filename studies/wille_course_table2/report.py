"""The report: Table 2 over the seeds against the paper (means with 95 % intervals, verdicts), the
6-DOF world against the paper world paired by seed, the switches and the causes they show."""

from __future__ import annotations

from ..kit import Report, verdict
from ..kit import seeds as over
from .analysis import HEADLINE_LAWS, QUANTITIES, REDUCTION_BOUND, Analysis
from .figures import FIG4, FIG5, FIG_INTERVALS
from .scenario import (
    CONTROL_TIMESTEP,
    COST,
    LAWS,
    PAPER_REDUCTION,
    PAPER_SPEED,
    PAPER_TABLE2,
    SAIL_FACTOR,
    SWITCH_SEEDS,
    TITLE,
    WORLDS,
)
from .scenario import __doc__ as SCENARIO

OURS = "ours: mean [95 % interval]"
PAIRED = "6-DOF − paper world, paired by seed"
COLUMNS = ["quantity", "world", "paper", OURS, "difference of the mean", "verdict", PAIRED, "cause"]
NAMES = {"east": ("x, east (cross-track) [m]", "m"), "north": ("y, north [m]", "m"),
         "error_deg": ("error |atan(x/y)| [deg]", "deg")}
SWITCH_SEED = SWITCH_SEEDS[0]
SINGLE_SEED = (f"seed {SWITCH_SEED} alone, an illustration of the mechanism beside the headline run of the "
               "same seed: no interval and no verdict is drawn from it")
SMOKE_NOTE = ("Smoke mode names no causes and compares the errors only (a short run's distances are not the "
              "paper's): the switches that show the causes run in the full study only.")


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of report.md.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass (Table 2's errors only, no switches).

    Returns
    -------
    str
        The report.
    """
    a = analysis
    text = Report(TITLE)
    text.summary(_summary(a, smoke))
    text.table(_table2_rows(a, smoke), COLUMNS)
    text.section("Seeds, intervals and verdicts", _method(a) + " *difference of the mean*: "
                 + verdict.DIFFERENCE_NOTE.split(": ", 1)[1].replace("; ⚠ beyond 10 %", ""))
    text.paragraph(_undecided(a, smoke))
    if smoke:
        text.paragraph(SMOKE_NOTE)
    text.section("Scenario", SCENARIO.split("\n\n", 1)[1])
    n_main = sum(1 for key in a.results if key[0] == "main")
    text.paragraph(
        f"Runs: {len(a.results)} simulations of {a.duration:g} s{' (smoke mode)' if smoke else ''}: the "
        f"{n_main} headline runs ({len(HEADLINE_LAWS)} laws in {len(WORLDS)} worlds on each of N = {len(a.seeds)} "
        f"seeds){'' if smoke else f' and {len(a.results) - n_main} switches on seed {SWITCH_SEED}'}. They cost "
        f"{a.cost:.0f} simulated seconds (a 6-DOF second counts {COST['mujoco']:g}, a paper-world second "
        f"{COST['paper']:g}). Distances are the displacement from the start over "
        "the whole run. Every run's numbers, seed by seed, are in table2.csv; each case over its seeds in "
        "table2_intervals.csv.")
    text.figure(FIG_INTERVALS, f"Table 2 over {len(a.seeds)} seeds: means with 95 % intervals against the "
                "paper's numbers (grey: ±10 %) and the reduction against its bound")
    if not smoke:
        text.section("Switches: what moves the numbers", f"Each switch runs on {SINGLE_SEED}.")
        text.table(_switch_rows(a),
                   ["switch", "world", "controller", "seed", "north [m]", "east [m]", "error [deg]",
                    "mean surge [m/s]", "rudder rms [deg]", "mean β_b [deg]"])
        text.paragraph(_causes(a))
    text.section("Figures")
    text.figure(FIG4, f"Fig. 4: position (x north against y east), heading and course controller, every "
                f"seed's track and the end position's mean with its 95 % intervals (N = {len(a.seeds)})")
    text.figure(FIG5, f"Fig. 5: course over ground, heading and course controller, the mean over {len(a.seeds)} "
                "seeds with its pointwise 95 % band")
    return text.text()


def _method(a: Analysis) -> str:
    """The method line: the seeds, the interval, the verdict rule and what the seed draws."""
    return over.method_line(
        a.seeds, what="every number of Table 2, of the reduction and of the headline runs",
        extra=("The seed draws the NORSOK gusts' phases and frequencies, the wind's direction wander and the "
               "start heading (within ±5° of north); every run of a seed, with either law and in either world, "
               "sails that same realisation, so the laws and the worlds are compared seed by seed. A Table 2 "
               "number is checked against the paper's within ±10 % of it; the error reduction "
               f"1 − course error / heading error (per seed) against {REDUCTION_BOUND:g} (the paper's "
               f"{PAPER_REDUCTION:g} reproduced). The switches run on {SINGLE_SEED}."))


def _undecided(a: Analysis, smoke: bool) -> str:
    """Which verdicts N leaves undecided, and the edge each interval straddles."""
    rows = []
    for world, label in WORLDS.items():
        for law in HEADLINE_LAWS:
            for key in QUANTITIES if not smoke else ("error_deg",):
                got, paper = a.main(world, law)[key], PAPER_TABLE2[law][key]
                if a.verdict(world, law, key) in ("holds", "breaks"):
                    continue
                band = verdict.TOLERANCE * abs(paper)
                edge = paper - band if abs(got.mean - (paper - band)) < abs(got.mean - (paper + band)) else paper + band
                rows.append(f"{LAWS[law]}'s {NAMES[key][0].split(' [')[0]}, {label}: {over.cell(got)} across "
                            f"the band's edge {edge:.3g}")
        if a.reduction_verdict(world) not in ("holds", "breaks"):
            rows.append(f"the error reduction, {label}: {over.cell(a.reduction(world))} across {REDUCTION_BOUND:g}")
    if not rows:
        return f"Every verdict is decided at N = {len(a.seeds)}."
    return f"Undecided at N = {len(a.seeds)} (each interval straddles the edge named): {'; '.join(rows)}."


def _summary(a: Analysis, smoke: bool) -> str:
    """Table 2's claim, world by world: the course controller's cut of the heading error."""
    worlds = "; ".join(
        f"{label}: {a.main(world, 'heading')['error_deg'].text(3)}° → {a.main(world, 'course')['error_deg'].text(3)}°, "
        f"a reduction of {a.reduction(world).text(3)} ({a.reduction_verdict(world)})"
        for world, label in WORLDS.items())
    text = (f"Table 2: Wille's heading controller (eqs. 46-51) against the course controller "
            f"(eqs. 52-59) close-hauled, the error |atan(x/y)| after {a.duration:g} s, over N = {len(a.seeds)} "
            f"seeds. The paper's course controller cuts the error by a fraction {PAPER_REDUCTION:g} (the reduction "
            f"1 − course error / heading error); ours, heading → "
            f"course controller: {worlds}, each against {REDUCTION_BOUND:g}. Paired by seed, the 6-DOF "
            f"reduction differs from the paper world's by {a.reduction_difference().text(2)}.")
    if smoke:
        return text + " The smoke run compares the errors only (a short run's distances are not the paper's)."
    north = {law: a.main("paper", law)["north"] for law in HEADLINE_LAWS}
    return text + (f" The distances sailed north in the paper world, {north['heading'].fixed(0)} m and "
                   f"{north['course'].fixed(0)} m against the paper's {PAPER_TABLE2['heading']['north']:g} m and "
                   f"{PAPER_TABLE2['course']['north']:g} m, are set by our sail, the course correction's "
                   "feedback of the rudder's own side force and, in 6-DOF, the heading loop's limit "
                   "cycle: each cause is shown by a switch below.")


def _table2_rows(a: Analysis, smoke: bool) -> list[dict]:
    causes = {} if smoke else _row_causes(a)
    rows = []
    for world, label in WORLDS.items():
        for law in HEADLINE_LAWS:
            ours = a.main(world, law)
            for key in QUANTITIES:
                if smoke and key != "error_deg":  # distances of a short run: not the paper's
                    continue
                name, unit = NAMES[key]
                paper = PAPER_TABLE2[law][key]
                rows.append({"quantity": f"{LAWS[law]}: {name}", "world": label, "paper": paper,
                             OURS: over.cell(ours[key]),
                             "difference of the mean": verdict.difference(ours[key].mean, paper, unit=unit).text(),
                             "verdict": f"{a.verdict(world, law, key)} (±10 %)",
                             PAIRED: over.cell(a.world_difference(law, key)) if world == "mujoco" else "",
                             "cause": causes.get((world, law, key), "")})
        reduction = a.reduction(world)
        rows.append({"quantity": "error reduction, course vs heading controller", "world": label,
                     "paper": PAPER_REDUCTION, OURS: over.cell(reduction),
                     "difference of the mean": verdict.difference(reduction.mean, PAPER_REDUCTION).text(),
                     "verdict": f"{a.reduction_verdict(world)} (≥ {REDUCTION_BOUND:g})",
                     PAIRED: over.cell(a.reduction_difference()) if world == "mujoco" else "",
                     "cause": "" if smoke or world == "paper" else causes[("mujoco", "reduction", "")]})
    return rows


def _get(a: Analysis):
    """The switch runs and the headline runs of the switches' seed, by (case, world, law)."""
    return lambda case, world, law: a.run(case, world, law, SWITCH_SEED)


def _row_causes(a: Analysis) -> dict:
    """The modelling difference behind each Table 2 miss, with the switch that shows it."""
    get, s = _get(a), f"seed {SWITCH_SEED}"
    h, c_s = get("main", "paper", "heading"), get("F_U = -S_y'", "paper", "course_sail_only")
    h_x = get(f"sail x{SAIL_FACTOR:g}", "paper", "heading")
    c_x = get(f"sail x{SAIL_FACTOR:g}", "paper", "course_sail_only")
    cm0, cms = get("main", "mujoco", "course"), get("F_U = -S_y'", "mujoco", "course_sail_only")
    ph, pc = get("paper forms", "mujoco", "heading"), get("paper forms", "mujoco", "course")
    hm0 = get("main", "mujoco", "heading")
    c, hm, cm = a.main("paper", "course"), a.main("mujoco", "heading"), a.main("mujoco", "course")
    forms = (f"with the papers' foils, friction-only resistance, no downwash and no windage (the boat as built "
             f"switched back, {s}): {cm0['error_deg']:.2f}° → {pc['error_deg']:.2f}° (heading controller "
             f"{hm0['error_deg']:.2f}° → {ph['error_deg']:.2f}°, rudder rms {pc['rudder_rms_deg']:.0f}°), not "
             "isolated further")
    sail = (f"our flat AR 5 sail: with its force x{SAIL_FACTOR:g} (a stand-in for Marchaj's coefficients, {s}) "
            f"{h['north']:.0f} → {h_x['north']:.0f} m")
    rudder_loop = (f"the course correction feeds the rudder's own side force back (eq. 57): the rudder bangs "
                   f"(rms {c['rudder_rms_deg'].fixed(0)}°, mean surge {c['mean_surge'].fixed(2)} m/s); with "
                   f"F_U = -S_y' only ({s}): {c_s['north']:.0f} m, rudder rms {c_s['rudder_rms_deg']:.0f}°")
    six_dof = (f"6-DOF: the K_d = 1e6 heading loop limit-cycles (rudder rms {hm['rudder_rms_deg'].fixed(0)}° / "
               f"{cm['rudder_rms_deg'].fixed(0)}°) at 10 and 50 Hz; the drag slows the boat "
               f"({hm['mean_surge'].fixed(2)} / {cm['mean_surge'].fixed(2)} m/s)")
    return {
        ("paper", "heading", "north"): sail,
        ("paper", "heading", "east"): (f"less leeway than the paper's boat: partly the sail (x{SAIL_FACTOR:g}, "
                                       f"{s}: {h['east']:.1f} → {h_x['east']:.1f} m), the rest not isolated "
                                       "(our keel's lift slope, hull cross-flow drag)"),
        ("paper", "heading", "error_deg"): (f"the leeway angle, as x; sail x{SAIL_FACTOR:g} ({s}): "
                                            f"{h['error_deg']:.2f} → {h_x['error_deg']:.2f}°"),
        ("paper", "course", "north"): rudder_loop,
        ("paper", "course", "east"): (f"{'to windward of' if c['east'].high < 0.0 else 'either side of'} the "
                                      f"track; F_U = -S_y' only ({s}): "
                                      f"{c_s['east']:.1f} m, sail x{SAIL_FACTOR:g} as well: {c_x['east']:.1f} m"),
        ("paper", "course", "error_deg"): (f"tenths of a degree, set by the gusts (the interval); F_U = -S_y' "
                                           f"only ({s}): {c_s['error_deg']:.2f}°"),
        ("mujoco", "heading", "north"): six_dof,
        ("mujoco", "course", "north"): six_dof + "; and the rudder-force feedback as in the paper world",
        ("mujoco", "heading", "east"): "as in the paper world, on a shorter track",
        ("mujoco", "heading", "error_deg"): ("the slower 6-DOF boat makes more leeway than the paper world's"
                                             if a.world_difference("heading", "error_deg").low > 0.0 else
                                             "the 6-DOF boat's leeway, as x"),
        ("mujoco", "course", "east"): (f"F_U = -S_y' only ({s}): {cms['east']:.1f} m (the rudder still "
                                       f"limit-cycles, rms {cms['rudder_rms_deg']:.0f}°)"),
        ("mujoco", "course", "error_deg"): (f"the rudder limit cycle; F_U = -S_y' only ({s}): "
                                            f"{cm0['error_deg']:.2f} → {cms['error_deg']:.2f}°; {forms}"),
        ("mujoco", "reduction", ""): "the course controller's error in 6-DOF (the row above)",
    }


def _switch_rows(a: Analysis) -> list[dict]:
    names = {"main": f"none (headline, {1 / CONTROL_TIMESTEP:.0f} Hz)", "10 Hz": "control at 10 Hz",
             "F_U = -S_y'": "course law with F_U = -S_y' (no R_y')",
             f"sail x{SAIL_FACTOR:g}": f"sail force x{SAIL_FACTOR:g}",
             "paper forms": "the papers' foils, resistance, no downwash, no windage"}
    rows = []
    for _, r in a.runs[a.runs["seed"] == SWITCH_SEED].iterrows():
        rows.append({"switch": names[r["case"]], "world": WORLDS[r["world"]], "controller": LAWS[r["law"]],
                     "seed": int(r["seed"]), "north [m]": r["north"], "east [m]": r["east"],
                     "error [deg]": r["error_deg"], "mean surge [m/s]": r["mean_surge"],
                     "rudder rms [deg]": r["rudder_rms_deg"],
                     "mean β_b [deg]": r["beta_b_mean_deg"] if r["law"] != "heading" else None})
    return rows


def _causes(a: Analysis) -> str:
    get, s = _get(a), f"seed {SWITCH_SEED}"
    h, c = get("main", "paper", "heading"), get("main", "paper", "course")
    h10, c10 = get("10 Hz", "paper", "heading"), get("10 Hz", "paper", "course")
    c_s = get("F_U = -S_y'", "paper", "course_sail_only")
    h_x = get(f"sail x{SAIL_FACTOR:g}", "paper", "heading")
    c_x = get(f"sail x{SAIL_FACTOR:g}", "paper", "course_sail_only")
    hm, cm = get("main", "mujoco", "heading"), get("main", "mujoco", "course")
    hm10 = get("10 Hz", "mujoco", "heading")
    cms = get("F_U = -S_y'", "mujoco", "course_sail_only")
    ph, pc = get("paper forms", "mujoco", "heading"), get("paper forms", "mujoco", "course")
    red_x = 1.0 - c_x["error_deg"] / h_x["error_deg"]
    ph2, pc2 = PAPER_TABLE2["heading"], PAPER_TABLE2["course"]
    side = ("to windward of the track (west), as the paper's does" if c_s["east"] < 0.0
            else "to leeward of the track (east), the paper's to windward")
    hi, ci = a.main("paper", "heading"), a.main("paper", "course")
    hmi, cmi = a.main("mujoco", "heading"), a.main("mujoco", "course")
    return f"""### Causes, each shown by switching it

The headline numbers below are means with their 95 % intervals over the {len(a.seeds)} seeds; each switch
is compared with the headline run of its own seed ({s}), the only seed it runs on.

1. **Control rate (10 Hz vs 50 Hz), {s}.** Paper world, heading controller: rudder rms
   {h10['rudder_rms_deg']:.1f}° at 10 Hz against {h['rudder_rms_deg']:.1f}° at 50 Hz; the limit cycle's drag
   costs {h['north'] - h10['north']:.0f} m of the {h['north']:.0f} m ({h10['mean_surge']:.2f} vs
   {h['mean_surge']:.2f} m/s). The heading error moves {h10['error_deg']:.2f}° → {h['error_deg']:.2f}°
   and the course controller's {c10['error_deg']:.2f}° → {c['error_deg']:.2f}°. The headline uses 50 Hz
   because the paper's laws are continuous-time; there the heading controller's rudder rms over the seeds
   is {hi['rudder_rms_deg'].text(2)}°.
2. **The course correction feeds the rudder's own side force back (eq. 57, F_U = -S_y' - R_y').**
   β_b = -α_k cos φ with α_k ∝ F_U / (u² + v²) (eq. 58): a rudder side force changes β_b, hence
   the heading demand -K_p β_b, hence the rudder. The loop gain is
   K_p · 2 / (ρ A_k C_L0k (u² + v²)) / l_4 = {a.loop_gain:.0f} at the heading
   controller's mean surge, {hi['mean_surge'].text(2)} m/s ({a.loop_gain_paper:.0f} at the paper's
   {PAPER_SPEED:g} m/s, larger when slower) and the sign is positive, so the rudder runs from stop to stop
   (rms {ci['rudder_rms_deg'].fixed(0)}°), the boat slows to {ci['mean_surge'].fixed(2)} m/s and sails
   {ci['north'].fixed(0)} m against the paper's {pc2['north']:g} m. With F_U = -S_y' (the rudder's side
   force left out, switch, {s}): rudder rms {c_s['rudder_rms_deg']:.1f}°, {c_s['north']:.0f} m north,
   {c_s['east']:.1f} m east, error {c_s['error_deg']:.2f}° (β_b {c_s['beta_b_mean_deg']:.1f}°): the distance
   lost to the correction is then {100 * (1 - c_s['north'] / h['north']):.0f} % of the heading controller's
   (paper {100 * (1 - pc2['north'] / ph2['north']):.0f} %), and the boat ends {side} (it blames the
   neglected drag in eq. 56 for a correction "slightly bigger than it should be"). The paper reports a
   smooth course with R_y' in F_U; its text does not say how this loop is kept quiet.
3. **Our flat AR 5 sail in place of Marchaj's coefficients, {s}.** We do not have Marchaj's table;
   the switch multiplies our sail's force by {SAIL_FACTOR:g} (the factor at which our beam-reach
   sim 1 reaches the paper's surge speed, see wille_roll_table1), in the physics and in the λ
   tables alike. Heading controller: {h['north']:.0f} → {h_x['north']:.0f} m north (paper {ph2['north']:g}),
   {h['east']:.1f} → {h_x['east']:.1f} m east (paper {ph2['east']:g}), error {h['error_deg']:.2f}° →
   {h_x['error_deg']:.2f}° (paper {ph2['error_deg']:g}°). Course controller (F_U = -S_y'): {c_x['north']:.0f} m
   north (paper {pc2['north']:g}), {c_x['east']:.1f} m east, error {c_x['error_deg']:.2f}°; reduction
   {red_x:.2f} (paper {PAPER_REDUCTION:g}).
4. **6-DOF world.** The heading loop limit-cycles also at 50 Hz (rudder rms
   {hmi['rudder_rms_deg'].text(3)}° over the seeds; {s}: {hm['rudder_rms_deg']:.0f}° at 50 Hz,
   {hm10['rudder_rms_deg']:.0f}° at 10 Hz) and the boat makes {hmi['mean_surge'].text(3)} m/s. With the
   boat as built switched back to the papers' forms (their foils, friction-only resistance, no keel
   downwash, no windage; {s}) the errors are {ph['error_deg']:.2f}° / {pc['error_deg']:.2f}° (heading /
   course controller; as built, the same seed: {hm['error_deg']:.2f}° / {cm['error_deg']:.2f}°), reduction
   {1 - pc['error_deg'] / ph['error_deg']:.2f}, rudder rms {ph['rudder_rms_deg']:.0f}° /
   {pc['rudder_rms_deg']:.0f}°, surge {ph['mean_surge']:.2f} / {pc['mean_surge']:.2f} m/s. Exploratory runs
   (not repeated here) limit-cycle as well with the other hydrodynamic forms of the physics options
   (added-mass coupling, vertical damping, restoring axes), at 100 Hz, with heave and pitch held
   (dofs = 4), with the paper's hydrostatics, and with K_d = 3e5, while the paper world with the
   rigid-hull yaw kinematics (``paper_model="rigid"``) at 50 Hz is quiet (rudder rms < 1°). Among what is
   left, the likeliest is the MuJoCo rudder, a servo-driven body behind the 0.2 s lag (an extra ~0.07 s
   of overdamped servo lag), in a loop with almost no phase margin; we did not isolate it further. The
   course controller in 6-DOF over the seeds: {cmi['north'].text(3)} m, error {cmi['error_deg'].text(3)}°;
   with F_U = -S_y' ({s}): {cms['north']:.0f} m, {cms['error_deg']:.2f}° (the headline run of that seed:
   {cm['north']:.0f} m, {cm['error_deg']:.2f}°).
"""
