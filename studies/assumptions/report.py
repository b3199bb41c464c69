"""Assumption validation, the report: the table of assumptions, the figures, the time constants,
the cross-check's finding on Wille's eq. 4 and what a sea does to the boats, as report.md.
"""

from __future__ import annotations

from ..kit import Report
from .analysis import Analysis
from .figures import FIGURES
from .scenario import ABOUT, TITLE
from .sea_report import sections, summary_sentence
from .table import COLUMNS, rows


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
    r.summary(_summary(table) + " " + summary_sentence(analysis.sea))
    r.table(table, COLUMNS)
    r.section("Scenarios", ABOUT)
    r.section("Figures and time constants")
    r.figure(FIGURES["wind_plane"], "The metrics over true wind angle × true wind speed")
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
    return r.text()


def _summary(table: list[dict]) -> str:
    """How many of the table's assumptions hold in 6-DOF, and which."""
    holds = [row["assumption"].split(" (")[0] for row in table
             if "holds" in row["verdict"] and "breaks" not in row["verdict"]]
    breaks = sum("breaks" in row["verdict"] for row in table)
    other = len(table) - len(holds) - breaks
    return (
        f"The papers' simplifications, and each difference of our boats as built from the papers' "
        f"boats, measured in 6-DOF on the Saoud robot and the Wille yacht: of the {len(table)} "
        f"assumptions below, {len(holds)} hold at every point of their scenarios and {breaks} break "
        "somewhere" + (f", {other} without a verdict" if other else "") + "; the verdict column says "
        "at how many points. " + (f"Those that hold everywhere: {'; '.join(holds)}. " if holds else "")
        + "Each row gives the metric's range over its scenarios, the threshold it is judged against, "
        "and the effect on the controller's own figure of merit when the assumption is made false "
        "in the simulation.")
