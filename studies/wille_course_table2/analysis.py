"""The numbers of the Table 2 runs: each run's drift and rudder, and over the seeds each headline
number's mean with its 95 % interval, the error reduction per world, the 6-DOF world against the
paper world paired by seed, and each row's verdict against the paper."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.stats import Interval
from sailmujoco.study import Results

from ..kit import seeds as over
from ..kit.verdict import TOLERANCE
from ..kit.wille import BOAT
from .scenario import NAME, PAPER_SPEED, PAPER_TABLE2, WORLDS, jobs_for, simulated_seconds

QUANTITIES = ("east", "north", "error_deg")  # Table 2's numbers, in its order
NUMBERS = (*QUANTITIES, "mean_surge", "rudder_rms_deg", "beta_b_mean_deg")  # each run's, stated over seeds
HEADLINE_LAWS = ("heading", "course")
REDUCTION_BOUND = 0.80  # the paper's 93 % reproduced: the course law removes at least 80 % of the error


def summary(result: dict) -> dict:
    """One run's numbers (the rudder and beta_b over the second half, from 50 s at most).

    Parameters
    ----------
    result : dict
        What :func:`studies.wille_course_table2.scenario.simulate` returned.

    Returns
    -------
    dict
        ``north``, ``east`` (m), ``error_deg`` (|atan(east / north)|), ``mean_surge`` (m/s),
        ``rudder_rms_deg``, ``beta_b_mean_deg`` and ``stopped``.
    """
    m, traj = result["metrics"], result["trajectory"]
    late = traj[traj["t"] >= min(50.0, 0.5 * traj["t"].iloc[-1])]
    return {"north": m["north"], "east": m["east"], "error_deg": math.degrees(m["drift_error"]),
            "mean_surge": m["mean_surge"], "rudder_rms_deg": float(np.sqrt(np.mean(late["rudder_deg"] ** 2))),
            "beta_b_mean_deg": float(late["beta_b_deg"].mean()), "stopped": m.get("stopped")}


def rudder_loop_gain(speed: float, kp: float = 3e5) -> float:
    """Gain of the loop rudder side force -> beta_b (eqs. 57-59) -> K_p beta_b -> rudder moment:
    K_p 2 / (rho A_k C_L0k speed^2) / l_4 (dimensionless; above 1 it runs away).

    Parameters
    ----------
    speed : float
        The boat's speed (m/s).
    kp : float
        The heading law's K_p (eq. 48).

    Returns
    -------
    float
        The loop gain.
    """
    from sailmujoco.controllers.wille import lift_slope

    p = get_boat(BOAT)
    return kp * 2.0 / (p.rho_water * p.keel.area * lift_slope(p.keel) * speed**2) / -p.rudder.x


@dataclass(frozen=True)
class Analysis:
    """The study's numbers.

    Parameters
    ----------
    smoke : bool
        The short pass.
    duration : float
        Each run's length (s).
    seconds : float
        Wall time of the simulations and the analysis (s).
    seeds : tuple of int
        The seeds of the headline runs (N = len(seeds)).
    cost : float
        The runs' simulated seconds, weighted per world (:func:`~.scenario.simulated_seconds`).
    results : dict
        (case, world, law, seed) -> the run (metrics and trajectory), in the order of the jobs.
    runs : pandas.DataFrame
        One row per run: case, world, law, seed and its :func:`summary`.
    loop_gain : float
        :func:`rudder_loop_gain` at the paper world's heading controller's mean surge speed (the
        mean over the seeds).
    loop_gain_paper : float
        :func:`rudder_loop_gain` at the paper's speed.
    """

    smoke: bool
    duration: float
    seconds: float
    seeds: tuple
    cost: float
    results: dict
    runs: pd.DataFrame
    loop_gain: float
    loop_gain_paper: float

    def values(self, world: str, law: str, quantity: str, case: str = "main") -> np.ndarray:
        """One number of a case, one value per seed (in the order of :attr:`seeds`).

        Parameters
        ----------
        world : str
            A key of :data:`~.scenario.WORLDS`.
        law : str
            A key of :data:`~.scenario.LAWS`.
        quantity : str
            A key of :func:`summary`.
        case : str
            ``"main"`` (the headline) or a switch.

        Returns
        -------
        numpy.ndarray
            The values, by seed.
        """
        r = self.runs
        rows = r[(r["case"] == case) & (r["world"] == world) & (r["law"] == law)].sort_values("seed")
        return rows[quantity].to_numpy(dtype=float)

    def main(self, world: str, law: str) -> dict:
        """The headline runs of ``law`` in ``world`` over the seeds: each number's interval.

        Parameters
        ----------
        world : str
            A key of :data:`~.scenario.WORLDS`.
        law : str
            ``"heading"`` or ``"course"``.

        Returns
        -------
        dict
            quantity -> :class:`sailmujoco.stats.Interval`, for each of :data:`NUMBERS`.
        """
        return {q: over.interval(self.values(world, law, q)) for q in NUMBERS}

    def run(self, case: str, world: str, law: str, seed: int = 0) -> dict:
        """One run's :func:`summary` (a switch runs on one seed: no interval).

        Parameters
        ----------
        case : str
            ``"main"`` or a switch.
        world : str
            A key of :data:`~.scenario.WORLDS`.
        law : str
            A key of :data:`~.scenario.LAWS`.
        seed : int
            The seed.

        Returns
        -------
        dict
            The run's numbers.
        """
        r = self.runs
        row = r[(r["case"] == case) & (r["world"] == world) & (r["law"] == law) & (r["seed"] == seed)]
        return row.iloc[0].to_dict()

    def reduction_values(self, world: str, case: str = "main", laws: tuple = HEADLINE_LAWS) -> np.ndarray:
        """1 - course error / heading error, per seed (both laws on the same gusts and start).

        Parameters
        ----------
        world : str
            A key of :data:`~.scenario.WORLDS`.
        case : str
            ``"main"`` or a switch.
        laws : tuple of str
            The heading and the course law.

        Returns
        -------
        numpy.ndarray
            The reductions, by seed.
        """
        heading, course = (self.values(world, law, "error_deg", case) for law in laws)
        return 1.0 - course / heading

    def reduction(self, world: str) -> Interval:
        """The error reduction of the headline runs in ``world``: the mean of the per-seed reductions
        with its interval (the laws paired by seed).

        Parameters
        ----------
        world : str
            A key of :data:`~.scenario.WORLDS`.
        """
        return over.interval(self.reduction_values(world))

    def world_difference(self, law: str, quantity: str) -> Interval:
        """The 6-DOF world minus the paper world, paired by seed, for a headline number.

        Parameters
        ----------
        law : str
            ``"heading"`` or ``"course"``.
        quantity : str
            A key of :func:`summary`.
        """
        return over.paired(self.values("mujoco", law, quantity), self.values("paper", law, quantity))

    def reduction_difference(self) -> Interval:
        """The 6-DOF world's error reduction minus the paper world's, paired by seed."""
        return over.paired(self.reduction_values("mujoco"), self.reduction_values("paper"))

    def verdict(self, world: str, law: str, quantity: str) -> str:
        """A Table 2 number against the paper's: within ±10 % of it
        (:data:`studies.kit.verdict.TOLERANCE`) decided on its interval.

        Parameters
        ----------
        world : str
            A key of :data:`~.scenario.WORLDS`.
        law : str
            ``"heading"`` or ``"course"``.
        quantity : str
            One of :data:`QUANTITIES`.
        """
        paper = PAPER_TABLE2[law][quantity]
        return over.decide(self.main(world, law)[quantity], paper, "within", band=TOLERANCE * abs(paper))

    def reduction_verdict(self, world: str) -> str:
        """The paper's reduction (93 %) reproduced: the reduction's interval above
        :data:`REDUCTION_BOUND`.

        Parameters
        ----------
        world : str
            A key of :data:`~.scenario.WORLDS`.
        """
        return over.decide(self.reduction(world), REDUCTION_BOUND, "above")

    def intervals(self) -> pd.DataFrame:
        """Each case's numbers over its seeds (:func:`studies.kit.seeds.over_seeds`): the data of
        table2_intervals.csv.

        Returns
        -------
        pandas.DataFrame
            One row per (case, world, law): each number's mean, ``_low`` and ``_high``, and ``n``.
        """
        return over.over_seeds(self.runs, ["case", "world", "law"], list(NUMBERS))


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's numbers from its runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`studies.wille_course_table2.scenario.runs`; ``results.seeds`` the seeds.
    smoke : bool
        The short pass.

    Returns
    -------
    Analysis
        The numbers.
    """
    start = time.perf_counter()
    seeds = tuple(int(s) for s in results.seeds)
    jobs = jobs_for(smoke, seeds)
    runs = {tuple(job["key"]): result for job, result in zip(jobs, results.jobs[NAME], strict=True)}
    table = pd.DataFrame([{"case": key[0], "world": key[1], "law": key[2], "seed": key[3], **summary(result)}
                          for key, result in runs.items()])
    rank = pd.DataFrame({"_switch": table["case"] != "main", "_world": table["world"] != "paper",
                         "_law": table["law"] != "heading", "case": table["case"], "law": table["law"],
                         "seed": table["seed"]})  # the headline first, the paper world first, heading first
    table = table.loc[rank.sort_values(["_switch", "_world", "case", "_law", "law", "seed"], kind="stable").index]
    table = table.reset_index(drop=True)
    heading_surge = over.interval(table[(table["case"] == "main") & (table["world"] == "paper")
                                        & (table["law"] == "heading")]["mean_surge"]).mean
    return Analysis(smoke, jobs[0]["duration"], results.seconds + time.perf_counter() - start, seeds,
                    simulated_seconds(jobs), runs, table, rudder_loop_gain(heading_surge),
                    rudder_loop_gain(PAPER_SPEED))


def headline(analysis: Analysis) -> dict:
    """The headline numbers: each headline number's mean over the seeds, the error reduction per
    world, and the verdicts against the paper.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.

    Returns
    -------
    dict
        ``{world}_{law}_{quantity}`` (the mean over the seeds), ``{world}_{law}_{quantity}_verdict``
        (Table 2's numbers), ``{world}_error_reduction`` (the mean) with ``_low``, ``_high`` and
        ``_verdict``, ``seeds`` (N), ``cost_s`` (the weighted simulated seconds) and
        ``wall_time_s``.
    """
    numbers: dict = {}
    for world in WORLDS:
        for law in HEADLINE_LAWS:
            main = analysis.main(world, law)
            for q in ("north", "east", "error_deg", "mean_surge", "rudder_rms_deg"):
                numbers[f"{world}_{law}_{q}"] = main[q].mean
            for q in QUANTITIES:
                numbers[f"{world}_{law}_{q}_verdict"] = analysis.verdict(world, law, q)
    for world in WORLDS:
        r = analysis.reduction(world)
        numbers.update({f"{world}_error_reduction": r.mean, f"{world}_error_reduction_low": r.low,
                        f"{world}_error_reduction_high": r.high,
                        f"{world}_error_reduction_verdict": analysis.reduction_verdict(world)})
    numbers.update({"seeds": len(analysis.seeds), "cost_s": analysis.cost, "wall_time_s": analysis.seconds})
    return numbers
