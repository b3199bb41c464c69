"""The report: Table 1 over the gust realisations (means with 95 % intervals and verdicts against
the paper), the roll reductions paired by seed, the moment shares of Fig. 3 and the optima of
Fig. 8 against the paper, and the causes of each difference, each illustrated by a switch."""

from __future__ import annotations

import math

from ..kit import Report, verdict
from ..kit import seeds as over
from .analysis import (
    BASES,
    LAW_SIMS,
    REDUCTION_BOUND,
    STALLED,
    Analysis,
    optimum,
    roll_cut,
    table1_verdict,
)
from .causes import causes
from .figures import FIGURES
from .run_table import RunTable, reduction
from .scenario import (
    CASES,
    FIG8_LABELS,
    FIG8_WINDS,
    PAPER_OPTIMUM_DEG,
    PAPER_REDUCTION,
    PAPER_SHARES,
    PAPER_TABLE1,
    QUANTITIES,
    SAIL_FACTOR,
    SHARES_WIND,
    SIM_LABELS,
    SIMS,
    SWITCH_SIMS,
    TITLE,
    WORLDS,
    paper_sim,
)
from .scenario import __doc__ as SCENARIO

SMOKE_CAUSE = "not checked in smoke mode (below the table)"
SMOKE_NOTE = ("Smoke mode names no causes: each is checked by a switch (a rerun with one modelling choice "
              "changed) that only the full study runs; run it without --smoke.")
SINGLE_SEED = ("one fixed seed (or two), an illustration of the mechanism: no interval and no verdict "
               "is drawn from it")
OURS = "ours: mean [95 % interval]"
TABLE1_COLUMNS = ["quantity", "world", "paper", OURS, "difference of the mean", "verdict (±10 %)", "cause"]


def _method(r: RunTable) -> str:
    """The report's method line: the seeds, the interval, the verdict rule, what the seed draws."""
    return over.method_line(
        r.seeds, what="every number of Table 1 and of the reductions",
        extra=("The seed draws the NORSOK gusts and the wind's direction wander; all simulations of a "
               "seed, in both worlds, sail the same realisation, so law on and law off are compared "
               "seed by seed. A Table 1 number is checked against the paper's within ±10 % of it; the "
               f"reductions against {100 * REDUCTION_BOUND:.0f} % (the paper's "
               f"{100 * PAPER_REDUCTION['sim2']:.0f} % and {100 * PAPER_REDUCTION['sim3']:.0f} % reproduced), "
               "and the roll cut (law off minus law on, deg) against 0 (the law cuts the roll). The switches, "
               f"Fig. 3 and Fig. 8 run {SINGLE_SEED}."))


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of report.md.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass (short runs, no switches and no causes).

    Returns
    -------
    str
        The report.
    """
    a, r = analysis, analysis.runs
    text = Report(TITLE)
    text.summary(_summary(a, smoke))
    text.table(_table1_rows(a, smoke), TABLE1_COLUMNS)
    text.section("Method", _method(r) + " *difference of the mean*: " + verdict.DIFFERENCE_NOTE.split(": ", 1)[1]
                 .replace("; ⚠ beyond 10 %", ""))
    if smoke:
        text.paragraph(SMOKE_NOTE)
    text.section("Scenario", SCENARIO.split("\n\n", 1)[1])
    n_sweep = sum(len(t) for t in a.tables.values())
    text.paragraph(
        f"Runs: {a.n_jobs} simulations plus {n_sweep} on the sweep engine; N = {len(r.seeds)} gust "
        f"realisations for Table 1{'; smoke mode: 60 s runs, metrics over the last 50 s' if smoke else ''}.")
    text.section("Roll reductions, law on against law off on the same gusts", _reduction_text(r))
    text.table(_reduction_rows(r), ["world", "law off → law on", "roll cut [deg]", "the law cuts the roll",
                                    "reduction", f"reduction ≥ {100 * REDUCTION_BOUND:.0f} %", "paper"])
    full = not smoke and len(r.seeds) >= 3  # the switches' baselines: headline seeds 0-2
    if full:
        text.paragraph(f"The switches, each on {SINGLE_SEED} (the seed is named; law off → law on, per seed):")
        text.table(_switch_rows(r), ["world", "case", "seed", "sim 1 mean heel [deg]", "sim 1 → sim 2",
                                     "sim 1 (mean wind) → sim 2 (mean wind)", "sim 1 → sim 3",
                                     "sim 1 (mean wind) → sim 3"])
        text.paragraph("Every switch run (u mean surge, ψ_min the lowest heading in the window, δ_r the mean "
                       "rudder angle, \"on\" the share of the window the roll law is on); every run of every "
                       "seed, the headline's included, is in runs.csv:")
        text.table(_detail_rows(r), ["case", "world", "seed", "simulation", "amplitude [deg]", "max p [deg/s]",
                                     "u [m/s]", "mean heel [deg]", "wind at sail [m/s]", "on", "δ_r [deg]",
                                     "ψ_min [deg]"])
    text.figure(FIGURES["intervals"], f"Table 1 over {len(r.seeds)} gust realisations: means with 95 % "
                "intervals, against the paper")
    if full:
        text.paragraph(causes(a))
        text.figure(FIGURES["seeds"], "Roll angle of sims 1-3 for each gust realisation (paper world)")
        text.figure(FIGURES["realisations"], f"Sim 3's roll amplitude over {len(r.realisations())} gust "
                    "realisations and against the sail actuator's lag (paper world)")
    seed = r.median_seed()
    text.section("Figs. 5-7: roll angle and roll rate",
                 f"One gust realisation, as the paper shows one: seed {seed}, the median sim-1 roll amplitude "
                 f"of the paper world's {len(r.seeds)} (the spread over the seeds is in Table 1's intervals).")
    text.figure(FIGURES["5"], "Fig. 5: roll angle φ, all simulations (last 50 s)")
    text.figure(FIGURES["6"], "Fig. 6: roll rate p, simulations 1 and 2")
    text.figure(FIGURES["7"], "Fig. 7: roll rate p, simulations 2 and 3")
    text.section(f"Fig. 3: moment shares in roll (beam reach, U10 = {SHARES_WIND:g} m/s, roll control off)",
                 f"Seed 0 alone: {SINGLE_SEED}.")
    _single_seed_table(text, _share_rows(a))
    text.figure(FIGURES["3"], "Fig. 3: roll moments of each force term")
    text.section("Fig. 8: top surge speed against φ_d", f"Seed 0 alone: {SINGLE_SEED}.")
    _single_seed_table(text, _fig8_rows(a.optima, a.tables, a.switch8))
    text.paragraph(_fig8_text(a.tables, a.switch8))
    text.figure(FIGURES["8"], "Fig. 8: mean surge speed (last 50 s) against the desired heel φ_d")
    return text.text()


def _single_seed_table(text: Report, rows: list[dict]) -> None:
    """A table of single-seed numbers against the paper: the difference, and no verdict."""
    table = [{**row, "ours (seed 0)": row["ours"], "difference": verdict.difference(row["ours"], row["paper"]).text()}
             for row in rows]
    text.table(table, ["quantity", "world", "paper", "ours (seed 0)", "difference", "cause"])
    text.paragraph(verdict.DIFFERENCE_NOTE.replace("; ⚠ beyond 10 %", ""))


def _pct(got) -> str:
    """A fraction over seeds as per cent: ``"63 [45, 80] %"``."""
    scaled = type(got)(100 * got.mean, 100 * got.low, 100 * got.high, got.n, got.method)
    return scaled.fixed(0, "%")


def _summary(a: Analysis, smoke: bool) -> str:
    """The roll reductions per world against the paper's, sim 3's residual and the 6-DOF speed."""
    r = a.runs

    def cause(n):
        return "" if smoke else f" (cause {n})"

    cuts = {(w, s): roll_cut(r, w, "sim1", s) for w in WORLDS for s in ("sim2", "sim3")}
    cut_verdicts = sorted({c.cut_verdict for c in cuts.values()})
    per_world = "; ".join(
        f"{label} {_pct(cuts[(w, 'sim2')].reduction)} / {_pct(cuts[(w, 'sim3')].reduction)}, "
        f"at least {100 * REDUCTION_BOUND:.0f} %: *{cuts[(w, 'sim2')].reduction_verdict}* / "
        f"*{cuts[(w, 'sim3')].reduction_verdict}*" for w, label in WORLDS.items())
    paper3 = PAPER_TABLE1["sim3"]["roll_amplitude"]
    ours3 = r.interval("paper", "sim3", "roll_amplitude")
    surge = r.interval("mujoco", "sim1", "mean_surge")
    return (
        f"Wille's roll law eases the sail to hold the heel of a gusty beam reach at 10°. Table 1 over "
        f"N = {len(r.seeds)} gust realisations against the paper, in the paper's 4-DOF world and the 6-DOF "
        "yacht. Law on against law off on the same gusts, the law cuts sim 1's roll amplitude: "
        f"*{' / '.join(cut_verdicts)}* in both worlds for sims 2 and 3. The reduction, sim 1 → sim 2 / sim 3: "
        f"{per_world} (paper {100 * PAPER_REDUCTION['sim2']:.0f} % / {100 * PAPER_REDUCTION['sim3']:.0f} %). "
        f"Sim 3 keeps {ours3.fixed(2, '°')} of roll in the paper world against the paper's {paper3:g}° "
        f"(*{table1_verdict(ours3, 'sim3', 'roll_amplitude')}*): the residual of the sail actuator's lag, set "
        f"by the sail's coefficients{cause(6)}. The 6-DOF yacht makes {surge.fixed(2, 'm/s')} in sim 1 against "
        f"the paper's {PAPER_TABLE1['sim1']['mean_surge']:g} m/s (*{table1_verdict(surge, 'sim1', 'mean_surge')}*)"
        f"{cause(7)}.")


def _table1_rows(a: Analysis, smoke) -> list[dict]:
    r, rows = a.runs, []
    for world, label in WORLDS.items():
        for sim in SIMS:
            paper = PAPER_TABLE1[paper_sim(sim)]
            for key, name in QUANTITIES.items():
                got = r.interval(world, sim, key)
                said = table1_verdict(got, sim, key)
                cause = "" if said == "holds" else SMOKE_CAUSE if smoke else _cause(a, world, sim, key)
                rows.append({"quantity": f"{SIM_LABELS[sim]}: {name}", "world": label, "paper": paper[key],
                             OURS: got.fixed(2), "difference of the mean": verdict.difference(
                                 got.mean, paper[key]).text(),
                             "verdict (±10 %)": said, "cause": cause})
    return rows


def _illustration(text: str) -> str:
    return f"illustration, {text}"


def _cause(a: Analysis, world, sim, key) -> str:
    """The modelling difference behind a Table 1 row that does not hold, with the switch that
    illustrates it (one seed, named)."""
    r = a.runs
    switched = sim if sim in SWITCH_SIMS else paper_sim(sim)  # the switches rerun SWITCH_SIMS only
    s0, sail0 = r.get("main", world, sim, 0), r.get("sail", world, switched, 0)
    sail_text = f"sail x{SAIL_FACTOR:g}, seed 0 alone: {s0[key]:.2f} → {sail0[key]:.2f}"
    if key == "mean_surge":
        text = f"our flat AR 5 sail drives less than Marchaj's ({sail_text} m/s)"
        if world == "mujoco":
            d4, fr = r.get("dofs4", world, switched, 0), r.get("friction", world, switched, 0)
            froude = a.froude_speed
            text = (f"the wave-making wall (Froude {r.interval(world, sim, key).mean / froude:.2f} on the seed "
                    f"mean; friction-only resistance, seed 0 alone: {s0[key]:.2f} → {fr[key]:.2f} m/s, Froude "
                    f"{fr[key] / froude:.2f}); " + text + f"; heave and pitch held, seed 0 alone: {d4[key]:.2f} m/s")
            if sail0[key] < STALLED:
                text += " (with the stronger sail the 6-DOF boat broaches, see causes)"
        return text
    if sim in ("sim1", "sim1_mean"):
        return (f"sim 1's wind estimate (true vs mean wind: {r.interval(world, 'sim1', key).fixed(2)} vs "
                f"{r.interval(world, 'sim1_mean', key).fixed(2)}); our sail ({sail_text})")
    if sim == "sim2_mean":
        return (f"the mean wind direction: with the measured direction (sim 2) "
                f"{r.interval(world, 'sim2', key).fixed(2)}")
    return (f"how far past 10° sim 1 heels sets what the law can take away (sim-1 mean heel "
            f"{r.interval(world, 'sim1', 'mean_heel').fixed(1, '°')}) and the sail actuator's lag; our sail "
            f"({sail_text})")


def _reduction_text(r: RunTable) -> str:
    """The reductions' paragraph: how they are taken, and the paper's."""
    return (f"The roll amplitude law off minus law on, and the reduction 1 − on / off, each taken seed by seed "
            f"on the same gusts over N = {len(r.seeds)} (the paper: sim 1 → sim 2 "
            f"{100 * PAPER_REDUCTION['sim2']:.0f} %, sim 1 → sim 3 {100 * PAPER_REDUCTION['sim3']:.0f} %, one "
            f"realisation; reproduced where each is at least {100 * REDUCTION_BOUND:.0f} %). A reduction is a "
            "mean of per-seed ratios: a lull (sim 1 heeling little past 10°) gives a small one, a windy "
            "window a large one.")


def _reduction_rows(r: RunTable) -> list[dict]:
    rows = []
    for world, label in WORLDS.items():
        for base in BASES:
            for sim in LAW_SIMS:
                if base == "sim1" and sim == "sim2_mean" or base == "sim1_mean" and sim == "sim2":
                    continue  # compare like wind knowledge with like
                c = roll_cut(r, world, base, sim)
                paper = PAPER_REDUCTION.get(paper_sim(sim))
                rows.append({"world": label, "law off → law on": f"{SIM_LABELS[base]} → {SIM_LABELS[sim]}",
                             "roll cut [deg]": c.cut.fixed(2), "the law cuts the roll": c.cut_verdict,
                             "reduction": _pct(c.reduction),
                             f"reduction ≥ {100 * REDUCTION_BOUND:.0f} %": c.reduction_verdict,
                             "paper": f"{100 * paper:.0f} %"})
    return rows


def _switch_rows(r: RunTable) -> list[dict]:
    rows = []

    def _row(world, case, seed, n):
        return {"world": WORLDS[world], "case": CASES[case], "seed": str(seed),
                "sim 1 mean heel [deg]": f"{n['sim1']['mean_heel']:.1f}",
                "sim 1 → sim 2": f"{100 * reduction(n['sim1'], n['sim2']):.0f} %",
                "sim 1 (mean wind) → sim 2 (mean wind)": (
                    f"{100 * reduction(n['sim1_mean'], n['sim2_mean']):.0f} %" if "sim2_mean" in n else "—"),
                "sim 1 → sim 3": f"{100 * reduction(n['sim1'], n['sim3']):.0f} %",
                "sim 1 (mean wind) → sim 3": f"{100 * reduction(n['sim1_mean'], n['sim3']):.0f} %"}

    for case in ("sail", "dofs4", "friction"):
        for world in WORLDS:
            for seed in (0, 1):
                if r.has(case, world, "sim1", seed):
                    base = {s: r.get("main", world, s, seed) for s in SWITCH_SIMS}
                    rows.append(_row(world, "main", seed, base))
                    rows.append(_row(world, case, seed, {s: r.get(case, world, s, seed) for s in SWITCH_SIMS}))
    rows.append(_row("mujoco", "sail dofs4", 0, {s: r.get("sail dofs4", "mujoco", s, 0) for s in SWITCH_SIMS}))
    for case, seed in (("gain", 1), ("band", 0)):
        n = {s: r.get("main", "paper", s, seed) for s in ("sim1", "sim1_mean")}
        n.update({s: r.get(case, "paper", s, seed) for s in ("sim2", "sim3")})
        rows.append(_row("paper", "main", seed, {s: r.get("main", "paper", s, seed) for s in SWITCH_SIMS}))
        rows.append(_row("paper", case, seed, n))
    # the same headline row once only
    seen, unique = set(), []
    for row in rows:
        key = tuple(row.values())
        if key not in seen:
            seen.add(key)
            unique.append(row)
    return unique


def _detail_rows(r: RunTable) -> list[dict]:
    rows = []
    order = list(CASES)
    for (case, world, sim, seed), n in sorted(r.n.items(), key=lambda kv: (
            kv[0][1], order.index(kv[0][0]) if kv[0][0] in order else 99, kv[0][3], kv[0][2])):
        if case in ("shares", "realisations", "main"):  # these: runs.csv (and their figures)
            continue
        rows.append({"case": CASES[case], "world": WORLDS[world], "seed": seed, "simulation": SIM_LABELS[sim],
                     "amplitude [deg]": n["roll_amplitude"], "max p [deg/s]": n["max_roll_rate"],
                     "u [m/s]": n["mean_surge"], "mean heel [deg]": n["mean_heel"],
                     "wind at sail [m/s]": n["wind_ce"], "on": f"{100 * n['on']:.0f} %",
                     "δ_r [deg]": n["rudder_mean"], "ψ_min [deg]": n["heading_min"]})
    return rows


def _share_rows(a: Analysis) -> list[dict]:
    alt = a.sail_shares
    rows = []
    for world, label in WORLDS.items():
        s = a.shares[world]
        for key, paper in PAPER_SHARES.items():
            cause = ""
            if key == "keel" and abs(s[key] / paper - 1) > 0.10:
                cause = (f"the rudder, at {s['rudder_deg']:.1f}°, sees the keel's leeway (eqs. 30, 34) and carries "
                         f"side force too: rudder/keel roll moment {s['rudder_Nm'] / s['keel_Nm']:.2f}, against "
                         f"A_r C_L0r h3 / (A_k C_L0k h2) = {a.rudder_keel:.2f} from the foil data; the paper's "
                         f"{100 * PAPER_SHARES['rudder + damping']:.0f} % for rudder and drag implies a rudder that carries almost none; not isolated")
                if alt is not None and world == "paper":
                    cause += f"; not the sail: sail x{SAIL_FACTOR:g} gives keel {100 * alt['keel']:.1f} %"
            elif key == "rudder + damping" and abs(s[key] / paper - 1) > 0.10:
                cause = "as the keel row: mostly the rudder"
            rows.append({"quantity": f"share of |roll moment|: {key}", "world": label, "paper": paper,
                         "ours": s[key], "cause": cause})
    return rows


def _fig8_rows(optima, tables, switch8) -> list[dict]:
    rows = []
    for (variant, wind), heel in optima.items():
        table = tables[variant]
        ok = table[(table["wind_speed"] == wind) & (table["status"] == "ok")]
        top_heel = math.degrees(float(ok["mean_heel"].max())) if len(ok) else float("nan")
        slow = ok[ok["mean_surge"] < STALLED]
        cause = f"the boat heels at most {top_heel:.0f}° (mean of the window) with λ100 here"
        if len(slow):
            cause = (f"the MuJoCo boat broaches for φ_d ≥ {slow['heel_desired_deg'].min():g}° "
                     f"(u < {STALLED:g} m/s; left out): see Table 1 cause 7")
        rows.append({"quantity": f"φ_d of the top surge speed at U10 = {wind:g} m/s [deg]",
                     "world": FIG8_LABELS[variant], "paper": PAPER_OPTIMUM_DEG[wind], "ours": heel,
                     "cause": cause})
    if switch8 is not None and len(switch8):
        for wind in FIG8_WINDS:
            rows.append({"quantity": f"φ_d of the top surge speed at U10 = {wind:g} m/s [deg]",
                         "world": f"{WORLDS['paper']}, sail x{SAIL_FACTOR:g}", "paper": PAPER_OPTIMUM_DEG[wind],
                         "ours": optimum(switch8, wind), "cause": "switch: the sail-force level"})
    return rows


def _fig8_text(tables, switch8) -> str:
    parts = []
    for variant, t in tables.items():
        for wind in FIG8_WINDS:
            rows = t[(t["wind_speed"] == wind) & (t["status"] == "ok")].sort_values("heel_desired_deg")
            if rows.empty:
                continue
            parts.append(f"{FIG8_LABELS[variant]}, U10 = {wind:g} m/s: u = "
                         + ", ".join(f"{u:.2f}" for u in rows["mean_surge"]) + " m/s at φ_d = "
                         + ", ".join(f"{h:g}" for h in rows["heel_desired_deg"]) + "°.")
    stalled = [FIG8_LABELS[v] for v, t in tables.items()
               if ((t["status"] == "ok") & (t["mean_surge"] < STALLED)).any()]
    text = ("The curve rises while φ_d limits the heel; once φ_d exceeds the heel the boat reaches "
            "with λ100 the law is never on and the curve is flat. The paper's optimum is a maximum "
            "inside that range: heeling further turns β_ws towards head-on (eqs. 26-27)"
            + (f"; {', '.join(stalled)}: speeds below {STALLED:g} m/s are broaches (rounded up and "
               "stopped, Table 1 cause 7), not points of that curve" if stalled else "")
            + ". " + " ".join(parts))
    if switch8 is not None and len(switch8):
        text += (f" With the sail force x{SAIL_FACTOR:g} (paper world) the boat heels further and the "
                 "maximum moves to " + " and ".join(f"{optimum(switch8, w):.0f}° at {w:g} m/s"
                                                   for w in FIG8_WINDS)
                 + ": where the optimum lies depends on the sail-force level.")
    return text
