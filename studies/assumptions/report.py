"""Assumption validation, the report: the table of assumptions, the figures, the time constants,
the cross-check's finding on Wille's eq. 4, what a sea does to the boats and what sensors and
actuators as fitted do to each controller, as report.md.
"""

from __future__ import annotations

from ..kit import Report
from ..kit import seeds as over
from .analysis import Analysis
from .figures import FIGURES
from .fitted_analysis import SECTION_COLUMNS, section_rows, section_text
from .fitted_figures import FITTED_FIGURE
from .scenario import (
    ABOUT,
    JITTER_DEG,
    SPEED_FLOOR,
    SPEED_HOLDS,
    SWITCH_TWS_MIN,
    TITLE,
    runs,
    simulated_seconds,
)
from .sea_report import sections, summary_sentence
from .table import COLUMNS, rows, verdict_counts


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of report.md.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The study's short pass (the numbers say it; the text is the same).
    """
    table = rows(analysis)
    r = Report(TITLE)
    r.summary(_summary(analysis, table) + " " + summary_sentence(analysis.sea))
    r.table(table, COLUMNS)
    r.section("Method", method(analysis, smoke))
    r.section("Scenarios", ABOUT)
    r.section("Figures and time constants")
    r.figure(FIGURES["wind_plane"], "The metrics over true wind angle × true wind speed (means over seeds)")
    r.figure(FIGURES["effects"], "Each switch's speed difference at every point, with its 95 % interval")
    r.figure(FIGURES["phi_star"], "Saoud's φ* against the heel the 6-DOF robot reaches")
    r.paragraph("Time constants: " + "; ".join(
        f"{b}: roll period {v['roll_period']:.2f} s, yaw time constant after a 10° rudder step "
        f"{v['yaw_time_constant']:.1f} s" for b, v in analysis.time_constants.items()) + ".")
    r.section(
        "Wille's eq. 4 as printed",
        "A finding of the cross-check (tests/test_reference_wille.py): Wille's eq. 4 as printed "
        "(Fossen's q = 0 form) leaves out tan φ times the pitch moment from the yaw equation. A "
        "heeled sail's drive, acting high up, turns a boat whose pitch is held to windward; with a "
        "fixed rudder the printed model's heading drifts 33° from the rigid boat's in 60 s of 6 m/s "
        "wind, while the rigid form agrees within 1°.")
    sections(r, analysis.sea)
    if analysis.fitted is not None:
        r.section("Sensors and actuators as fitted", section_text(analysis.fitted))
        r.table(section_rows(analysis.fitted), SECTION_COLUMNS)
        r.figure(FITTED_FIGURE, "Each controller's figure of merit with typical sensors and with typical "
                                "actuators, against perfect ones: the change seed by seed, with its 95 % interval")
    return r.text()


def method(analysis: Analysis, smoke: bool) -> str:
    """The method line: the seeds of each part, what a seed draws, how a difference and a
    verdict are made, and what the calm runs cost.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The study's short pass.
    """
    def span(seeds):
        seeds = list(seeds)
        return f"seed {seeds[0]}" if len(seeds) == 1 else f"seeds {seeds[0]}-{seeds[-1]}"

    cost = simulated_seconds(runs(smoke, analysis.seeds))
    extra = (
        f"The parts run on the first seeds the budget allows: the wind plane on {span(analysis.plane_seeds)} "
        f"(N = {len(analysis.plane_seeds)}), the course hold, Saoud's steady states and position keeping on "
        f"{span(analysis.single_seeds)} (N = {len(analysis.single_seeds)}), Wille's Table 1 with and "
        f"without residuary resistance on {span(analysis.table1_seeds)} only (a note in the friction row, "
        "no verdict); the free decay and rudder step and the restoring curves are deterministic (calm "
        "water, an exact start; the hull's geometry). What a seed draws: in the wind plane and Saoud's "
        f"steady states (a steady wind) the start heading, uniform within ±{JITTER_DEG:g}° of the "
        "heading held; in the course hold the gusts, the wind's wander and the start heading (the "
        "task's own); in position keeping the start heading (over the compass); in Table 1 the "
        "gusts and the wander. A switch is compared with the boat as built at each point seed by "
        "seed: (as built − paper's form) / max(|paper's form|, "
        f"{SPEED_FLOOR:g} m/s) for the steady speed, as built − paper's form for the heel; the "
        f"switches run where the true wind is at least {SWITCH_TWS_MIN:g} m/s. A point holds when "
        f"the interval lies within ±{100 * SPEED_HOLDS:g} % (the project's tolerance; the heel "
        "within its bound), breaks when it lies wholly outside; an assumption over the plane "
        "*breaks* where any point breaks, *holds* where every point holds, and is *undecided at N "
        f"seeds* otherwise. The calm runs simulate {cost:,.0f} s (a 3-DOF second counting 0.2).")
    return over.method_line(analysis.seeds, extra=extra)


def _summary(analysis: Analysis, table: list[dict]) -> str:
    """How many of the table's assumptions hold in 6-DOF, break or stay undecided, and which."""
    counts = verdict_counts(table)
    return (
        f"The papers' simplifications and each difference of our boats from the papers' boats, in "
        f"6-DOF on the Saoud robot and the Wille yacht, each compared with the paper's form seed by "
        f"seed: of the {len(table)} assumptions below, {counts['holds']} hold at every point of "
        f"their scenarios, {counts['breaks']} break at one point or more and {counts['undecided']} "
        f"{'stays' if counts['undecided'] == 1 else 'stay'} undecided (section \"Method\": the "
        "seeds, the intervals, the verdict rule).")
