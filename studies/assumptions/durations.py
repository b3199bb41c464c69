"""Assumption validation, the single scenarios' lengths: how long each of :mod:`.episodes`'
runs sails (smoke, full) and what a job of them costs in simulated seconds (:func:`part_seconds`,
for the budget of :func:`.scenario.simulated_seconds`).

The runs (:mod:`.episodes`) and the budget (:mod:`.scenario`) both read these; neither imports
the other for them.
"""

from __future__ import annotations

COURSE_SECONDS = (60.0, 200.0)  # s: Wille's course hold (smoke, full)
STEADY_SECONDS = 40.0  # s: each of Saoud's steady states
STEADY_CASES = ([(4.0, 90.0)], [(w, a) for w in (3.0, 5.0, 7.0) for a in (60.0, 90.0, 120.0)])  # (smoke, full)
STEADY_L_PHI = ((0.1,), (0.1, 1.0))  # m: the robot's l_phi (smoke, full)
DRIFT_SECONDS = (60.0, 200.0)  # s: position keeping (smoke, full)
PAPER_WORLD_COST = 0.2  # the cost of a paper-world (3-DOF) second against a 6-DOF one


def part_seconds(job: dict) -> float:
    """The simulated seconds of one job of :func:`.episodes.part` (a paper-world second counting
    ``PAPER_WORLD_COST``), for the budget.

    Parameters
    ----------
    job : dict
        A job of :func:`.episodes.part`.
    """
    if job["part"] == "table1":
        return float(job["run"]["duration"])
    full = not job["smoke"]
    if job["part"] == "course":
        return COURSE_SECONDS[full]
    if job["part"] == "steady":
        return STEADY_SECONDS * len(STEADY_CASES[full]) * len(STEADY_L_PHI[full])
    return DRIFT_SECONDS[full] * (1.0 + PAPER_WORLD_COST)
