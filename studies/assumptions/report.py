"""Assumption validation, the report: the table of assumptions, the figures, the time constants
and the cross-check's finding on Wille's eq. 4, as report.md.
"""

from __future__ import annotations

from ..kit import Report
from .analysis import Analysis
from .figures import FIGURES
from .scenario import ABOUT, TITLE
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
    r = Report(TITLE)
    r.paragraph(ABOUT)
    r.table(rows(analysis), COLUMNS)
    r.figure(FIGURES["wind_plane"], "The metrics over true wind angle × true wind speed")
    r.figure(FIGURES["phi_star"], "Saoud's φ* against the heel the 6-DOF robot reaches")
    r.paragraph("Time constants: " + "; ".join(
        f"{b}: roll period {v['roll_period']:.2f} s, yaw time constant after a 10° rudder step "
        f"{v['yaw_time_constant']:.1f} s" for b, v in analysis.time_constants.items()) + ".")
    r.paragraph(
        "A finding of the cross-check (tests/test_reference_wille.py): Wille's eq. 4 as printed "
        "(Fossen's q = 0 form) leaves out tan φ times the pitch moment from the yaw equation. A "
        "heeled sail's drive, acting high up, turns a boat whose pitch is held to windward; with a "
        "fixed rudder the printed model's heading drifts 33° from the rigid boat's in 60 s of 6 m/s "
        "wind, while the rigid form agrees within 1°.")
    return r.text()
