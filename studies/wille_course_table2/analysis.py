"""The numbers of the Table 2 runs: each run's drift and rudder, the error reduction per world."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.study import Results

from ..kit.wille import BOAT
from .scenario import NAME, PAPER_SPEED, WORLDS, jobs_for


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
    results : dict
        (case, world, law) -> the run (metrics and trajectory), in the order of the jobs.
    summaries : dict
        (case, world, law) -> :func:`summary` of the run.
    reduction : dict
        world -> 1 - course error / heading error of the headline runs.
    loop_gain : float
        :func:`rudder_loop_gain` at the headline heading controller's surge speed (paper world).
    loop_gain_paper : float
        :func:`rudder_loop_gain` at the paper's speed.
    """

    smoke: bool
    duration: float
    seconds: float
    results: dict
    summaries: dict
    reduction: dict
    loop_gain: float
    loop_gain_paper: float

    def main(self, world: str, law: str) -> dict:
        """The headline run's summary of ``law`` in ``world``.

        Parameters
        ----------
        world : str
            A key of :data:`WORLDS`.
        law : str
            ``"heading"`` or ``"course"``.

        Returns
        -------
        dict
            Its :func:`summary`.
        """
        return self.summaries[("main", world, law)]

    def table(self) -> pd.DataFrame:
        """One row per run (case, world, law and its summary): the data of table2.csv.

        Returns
        -------
        pandas.DataFrame
            The runs, in the order of the jobs.
        """
        return pd.DataFrame([{"case": key[0], "world": key[1], "law": key[2], **s}
                             for key, s in self.summaries.items()])


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's numbers from its runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`studies.wille_course_table2.scenario.runs`.
    smoke : bool
        The short pass.

    Returns
    -------
    Analysis
        The numbers.
    """
    start = time.perf_counter()
    jobs = jobs_for(smoke)
    runs = dict(zip([job["key"] for job in jobs], results.jobs[NAME], strict=True))
    summaries = {key: summary(result) for key, result in runs.items()}
    reduction = {w: 1.0 - summaries[("main", w, "course")]["error_deg"]
                 / summaries[("main", w, "heading")]["error_deg"] for w in WORLDS}
    heading = summaries[("main", "paper", "heading")]
    return Analysis(smoke, jobs[0]["duration"], results.seconds + time.perf_counter() - start, runs,
                    summaries, reduction, rudder_loop_gain(heading["mean_surge"]),
                    rudder_loop_gain(PAPER_SPEED))


def headline(analysis: Analysis) -> dict:
    """The headline numbers: each headline run's distances, error, speed and rudder, and the
    error reduction per world.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.

    Returns
    -------
    dict
        ``{world}_{law}_{quantity}``, ``{world}_error_reduction`` and ``wall_time_s``.
    """
    main = {(w, law): analysis.main(w, law) for w in WORLDS for law in ("heading", "course")}
    numbers = {f"{w}_{law}_{k}": v for (w, law), s in main.items() for k, v in s.items()
               if k in ("north", "east", "error_deg", "mean_surge", "rudder_rms_deg")}
    numbers.update({f"{w}_error_reduction": r for w, r in analysis.reduction.items()})
    numbers["wall_time_s"] = analysis.seconds
    return numbers
