"""The report: Table 1, the moment shares of Fig. 3 and the optima of Fig. 8 against the paper,
and the causes of each difference, each checked by a switch."""

from __future__ import annotations

import math

from ..kit import Report, verdict
from .analysis import STALLED, Analysis, RunTable, optimum, reduction
from .causes import causes
from .figures import FIGURES
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


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of report.md.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass (seed 0 only, no switches and no causes).

    Returns
    -------
    str
        The report.
    """
    a, r = analysis, analysis.runs
    text = Report(TITLE)
    text.summary(_summary(a, smoke))
    text.comparison(_table1_rows(a, smoke))
    if smoke:
        text.paragraph(SMOKE_NOTE)
    text.section("Scenario", SCENARIO.split("\n\n", 1)[1])
    n_sweep = sum(len(t) for t in a.tables.values())
    text.paragraph(
        f"Runs: {a.n_jobs} simulations plus {n_sweep} on the sweep engine"
        f"{'; smoke mode: 60 s, seed 0 only, metrics over the last 50 s' if smoke else ''}; "
        f"wall time {a.seconds:.0f} s ({a.simulation_seconds:.0f} s of simulation, the Fig. 8 sweeps run "
        "beside the others).")
    text.section("Roll reductions and every run",
                 f"Reductions of the roll amplitude (the paper: sim 1 → sim 2 "
                 f"{100 * PAPER_REDUCTION['sim2']:.0f} %, sim 1 → sim 3 {100 * PAPER_REDUCTION['sim3']:.0f} %; "
                 "reproduced if both are at least 60 % in the paper world), from the seed means and per seed:")
    text.table(_reduction_rows(r, smoke), ["world", "case", "seed", "sim 1 mean heel [deg]",
                                           "sim 1 → sim 2", "sim 1 (mean wind) → sim 2 (mean wind)",
                                           "sim 1 → sim 3", "sim 1 (mean wind) → sim 3"])
    text.paragraph("Every run (u mean surge, ψ_min the lowest heading in the window, δ_r the mean "
                   "rudder angle, \"on\" the share of the window the roll law is on):")
    text.table(_detail_rows(r), ["case", "world", "seed", "simulation", "amplitude [deg]", "max p [deg/s]",
                                 "u [m/s]", "mean heel [deg]", "wind at sail [m/s]", "on", "δ_r [deg]",
                                 "ψ_min [deg]"])
    if not smoke:
        text.paragraph(causes(a))
        text.figure(FIGURES["seeds"], "Roll angle of sims 1-3 for each gust realisation (paper world)")
        text.figure(FIGURES["realisations"], "Sim 3's roll amplitude over 25 gust realisations and against "
                    "the sail actuator's lag (paper world)")
    text.section("Figs. 5-7: roll angle and roll rate")
    text.figure(FIGURES["5"], "Fig. 5: roll angle φ, all simulations (last 50 s)")
    text.figure(FIGURES["6"], "Fig. 6: roll rate p, simulations 1 and 2")
    text.figure(FIGURES["7"], "Fig. 7: roll rate p, simulations 2 and 3")
    text.section(f"Fig. 3: moment shares in roll (beam reach, U10 = {SHARES_WIND:g} m/s, roll control off)")
    text.comparison(_share_rows(a))
    text.figure(FIGURES["3"], "Fig. 3: roll moments of each force term")
    text.section("Fig. 8: top surge speed against φ_d")
    text.comparison(_fig8_rows(a.optima, a.tables, a.switch8))
    text.paragraph(_fig8_text(a.tables, a.switch8))
    text.figure(FIGURES["8"], "Fig. 8: mean surge speed (last 50 s) against the desired heel φ_d")
    return text.text()


def _summary(a: Analysis, smoke: bool) -> str:
    """The roll reductions per world against the paper's, sim 3's residual and the 6-DOF speed."""
    r = a.runs
    mean = {world: {s: r.mean(world, s) for s in SIMS} for world in WORLDS}

    def cut(world, sim):
        return f"{100 * reduction(mean[world]['sim1'], mean[world][sim]):.0f} %"

    def cause(n):
        return "" if smoke else f" (cause {n})"

    paper3, ours3 = PAPER_TABLE1["sim3"]["roll_amplitude"], mean["paper"]["sim3"]["roll_amplitude"]
    seeds = "" if smoke else f" (mean over seeds {', '.join(map(str, r.seeds))})"
    return (
        f"Wille's roll law eases the sail to hold the heel of a gusty beam reach at 10°. Table 1{seeds} "
        "against the paper, in the paper's 4-DOF world and the 6-DOF yacht. The law cuts the roll "
        "amplitude, sim 1 → sim 2 / sim 3, by "
        + "; ".join(f"{label} {cut(world, 'sim2')} / {cut(world, 'sim3')}" for world, label in WORLDS.items())
        + f" (paper {100 * PAPER_REDUCTION['sim2']:.0f} % / {100 * PAPER_REDUCTION['sim3']:.0f} %). "
        f"Sim 3 keeps {ours3:.2f}° of roll in the paper world against the paper's {paper3:g}°: the "
        f"residual of the sail actuator's lag, set by the sail's coefficients{cause(6)}. The 6-DOF "
        f"yacht makes {mean['mujoco']['sim1']['mean_surge']:.2f} m/s in sim 1 against the paper's "
        f"{PAPER_TABLE1['sim1']['mean_surge']:g} m/s{cause(7)}. Figs. 3 and 8 follow.")


def _table1_rows(a: Analysis, smoke) -> list[dict]:
    r, rows = a.runs, []
    for world, label in WORLDS.items():
        for sim in SIMS:
            paper = PAPER_TABLE1[paper_sim(sim)]
            mean = r.mean(world, sim)
            for key, name in QUANTITIES.items():
                lo, hi = r.span(world, sim, key)
                cause = _smoke_cause(a, world, sim, key) if smoke else _cause(a, world, sim, key)
                rows.append({"quantity": f"{SIM_LABELS[sim]}: {name}", "world": label,
                             "paper": paper[key], "ours": mean[key],
                             "cause": (f"seeds {lo:.2f}-{hi:.2f}. " if len(r.seeds) > 1 else "") + cause})
    return rows


def _flagged(a: Analysis, world, sim, key) -> bool:
    """Whether a Table 1 row misses the paper's number (the row the comparison flags ⚠)."""
    paper = PAPER_TABLE1[paper_sim(sim)][key]
    return verdict.difference(a.runs.mean(world, sim)[key], paper).beyond(verdict.TOLERANCE)


def _smoke_cause(a: Analysis, world, sim, key) -> str:
    """A flagged row of the smoke run: why it names no cause."""
    return SMOKE_CAUSE if _flagged(a, world, sim, key) else ""


def _cause(a: Analysis, world, sim, key) -> str:
    """The modelling difference behind a Table 1 miss, with the switch that shows it."""
    r = a.runs
    if not _flagged(a, world, sim, key):
        return ""
    switched = sim if sim in SWITCH_SIMS else paper_sim(sim)  # the switches rerun SWITCH_SIMS only
    s0, sail0 = r.get("main", world, sim, 0), r.get("sail", world, switched, 0)
    if key == "mean_surge":
        text = (f"our flat AR 5 sail drives less than Marchaj's: sail x{SAIL_FACTOR:g}, seed 0: "
                f"{s0[key]:.2f} → {sail0[key]:.2f} m/s")
        if world == "mujoco":
            d4, fr = r.get("dofs4", world, switched, 0), r.get("friction", world, switched, 0)
            froude = a.froude_speed
            text = (f"the wave-making wall (Froude {s0[key] / froude:.2f}): friction-only resistance, "
                    f"seed 0: {s0[key]:.2f} → {fr[key]:.2f} m/s (Froude {fr[key] / froude:.2f}); " + text
                    + f"; heave and pitch held: {d4[key]:.2f} m/s")
            if sail0[key] < 2.0:
                text += " (with the stronger sail the 6-DOF boat broaches, see causes)"
        return text
    if sim in ("sim1", "sim1_mean"):
        mean, mm = r.mean(world, "sim1"), r.mean(world, "sim1_mean")
        return (f"sim 1's wind estimate (true vs mean wind: {mean[key]:.2f} vs {mm[key]:.2f}); "
                f"the gust realisation; sail x{SAIL_FACTOR:g}, seed 0: {s0[key]:.2f} → {sail0[key]:.2f}")
    if sim == "sim2_mean":
        return (f"the mean wind direction: with the measured direction (sim 2) {r.mean(world, 'sim2')[key]:.2f}; "
                f"the gust realisation (seed 0: {s0[key]:.2f}, seed 1: {r.get('main', world, sim, 1)[key]:.2f})")
    return (f"the gust realisation: how far past 10° sim 1 heels sets what the law can take away (seed 0: sim-1 heel "
            f"{r.get('main', world, 'sim1', 0)['mean_heel']:.1f}°, {s0[key]:.2f}; seed 1: "
            f"{r.get('main', world, 'sim1', 1)['mean_heel']:.1f}°, {r.get('main', world, sim, 1)[key]:.2f}); "
            f"sail x{SAIL_FACTOR:g}, seed 0: {sail0[key]:.2f}")


def _reduction_rows(r: RunTable, smoke) -> list[dict]:
    rows = []

    def _row(world, case, seed_label, n):
        return {"world": WORLDS[world], "case": CASES[case], "seed": seed_label,
                "sim 1 mean heel [deg]": f"{n['sim1']['mean_heel']:.1f}",
                "sim 1 → sim 2": f"{100 * reduction(n['sim1'], n['sim2']):.0f} %",
                "sim 1 (mean wind) → sim 2 (mean wind)": (
                    f"{100 * reduction(n['sim1_mean'], n['sim2_mean']):.0f} %" if "sim2_mean" in n else "—"),
                "sim 1 → sim 3": f"{100 * reduction(n['sim1'], n['sim3']):.0f} %",
                "sim 1 (mean wind) → sim 3": f"{100 * reduction(n['sim1_mean'], n['sim3']):.0f} %"}

    for world in WORLDS:
        rows.append(_row(world, "main", "mean", {s: r.mean(world, s) for s in SIMS}))
        if len(r.seeds) > 1:
            for seed in r.seeds:
                rows.append(_row(world, "main", str(seed), {s: r.get("main", world, s, seed) for s in SIMS}))
    if not smoke:
        for case in ("sail", "dofs4", "friction"):
            for world in WORLDS:
                for seed in (0, 1):
                    if r.has(case, world, "sim1", seed):
                        rows.append(_row(world, case, str(seed),
                                        {s: r.get(case, world, s, seed) for s in SWITCH_SIMS}))
        rows.append(_row("mujoco", "sail dofs4", "0",
                        {s: r.get("sail dofs4", "mujoco", s, 0) for s in SWITCH_SIMS}))
        n = {s: r.get("main", "paper", s, 1) for s in ("sim1", "sim1_mean")}
        n.update({s: r.get("gain", "paper", s, 1) for s in ("sim2", "sim3")})
        rows.append(_row("paper", "gain", "1", n))
        n = {s: r.get("main", "paper", s, 0) for s in ("sim1", "sim1_mean")}
        n.update({s: r.get("band", "paper", s, 0) for s in ("sim2", "sim3")})
        rows.append(_row("paper", "band", "0", n))
    return rows


def _detail_rows(r: RunTable) -> list[dict]:
    rows = []
    order = list(CASES)
    for (case, world, sim, seed), n in sorted(r.n.items(), key=lambda kv: (
            kv[0][1], order.index(kv[0][0]) if kv[0][0] in order else 99, kv[0][3], kv[0][2])):
        if case in ("shares", "realisations"):  # the realisations: runs.csv and their figure
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
