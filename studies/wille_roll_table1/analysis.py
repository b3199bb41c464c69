"""The numbers of the Table 1 runs: over the seeds as means with 95 % intervals (the runs
themselves, by case, world, sim and seed, are :class:`.run_table.RunTable`); the reductions
paired by seed (law on against law off on the same gusts) and their verdicts; the moment shares
of Fig. 3 and the optima of Fig. 8."""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np
import pandas as pd
from sailmujoco.controllers.wille import lift_slope
from sailmujoco.controllers.wille_roll import build_sail_tables

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.stats import Interval, pass_rate
from sailmujoco.study import Results

from ..kit import seeds as over
from ..kit.verdict import TOLERANCE
from ..kit.wille import BOAT, MOMENT_TERMS, TABLE1_WINDOW
from .run_table import RunTable
from .scenario import (
    FIG8_WINDS,
    LAG_SEEDS,
    NAME,
    PAPER_TABLE1,
    SIMS,
    WITHIN,
    WORLDS,
    fig8_tables,
    jobs_for,
    paper_sim,
)

REDUCTION_BOUND = 0.60  # the paper's reductions (73 %, 93 %) reproduced: each at least 60 %
LAW_SIMS = ("sim2", "sim2_mean", "sim3")  # the simulations with the roll law on
BASES = ("sim1", "sim1_mean")  # the simulations with it off


def shares(result: dict) -> dict:
    """Fig. 3's shares of the roll moments: mean |K_term| over the window / their sum.

    Parameters
    ----------
    result : dict
        A run with its roll moments (:func:`studies.kit.wille.table1_simulate`, ``moments``).

    Returns
    -------
    dict
        The shares of ``sail + restoring``, ``keel`` and ``rudder + damping``, the mean rudder
        angle (``rudder_deg``) and each term's mean moment (``<term>_Nm``, N m).
    """
    traj = result["trajectory"]
    late = traj[traj["t"] >= traj["t"].iloc[-1] - TABLE1_WINDOW]
    size = {term: float(late[f"K_{term}"].abs().mean()) for term in MOMENT_TERMS}
    total = sum(size.values())
    return {"rudder_deg": float(late["rudder_deg"].mean()),
            "sail + restoring": (size["sail"] + size["restoring"]) / total, "keel": size["keel"] / total,
            "rudder + damping": (size["rudder"] + size["damping"] + size["added_mass"]) / total,
            **{f"{term}_Nm": float(late[f"K_{term}"].mean()) for term in MOMENT_TERMS}}


STALLED = 2.0  # m/s: a run whose mean surge is below this has broached (rounded up and stopped)


def optimum(table: pd.DataFrame, wind: float) -> float:
    """phi_d of the fastest finished run at ``wind``; the vertex of the parabola through the
    best grid point and its neighbours when it lies inside the grid. Runs that broached
    (mean surge below ``STALLED``) are left out.

    Parameters
    ----------
    table : pandas.DataFrame
        A Fig. 8 table (:func:`studies.wille_roll_table1.scenario.fig8_tables`).
    wind : float
        U10 (m/s).

    Returns
    -------
    float
        phi_d (deg); NaN when no run finished.
    """
    rows = table[(table["wind_speed"] == wind) & (table["status"] == "ok")
                 & (table["mean_surge"] >= STALLED)].sort_values("heel_desired_deg")
    if rows.empty:
        return float("nan")
    x, y = rows["heel_desired_deg"].to_numpy(float), rows["mean_surge"].to_numpy(float)
    i = int(np.argmax(y))
    if 0 < i < len(x) - 1:
        a, b, _ = np.polyfit(x[i - 1:i + 2], y[i - 1:i + 2], 2)
        if a < 0:
            return float(-b / (2 * a))
    return float(x[i])


@dataclass(frozen=True)
class SailMoments:
    """The eased trims of the roll law on this reach (beta_ws = 130 deg, from the lambda
    tables): where a few degrees of sail angle are most of the roll moment.

    Parameters
    ----------
    lam33_deg, lam0_deg : float
        The sail angles of lambda_33 and lambda_0 (deg).
    moment33, moment0 : float
        Their relative roll moments (kg: N m per (m/s)^2).
    slope : float
        The moment's change per degree of sail angle between them (kg per deg).
    """

    lam33_deg: float
    lam0_deg: float
    moment33: float
    moment0: float
    slope: float


def sail_moments() -> SailMoments:
    """The roll law's eased trims at beta_ws = 130 deg (:class:`SailMoments`).

    Returns
    -------
    SailMoments
        The trims and their moments.
    """
    lams, _, moms = build_sail_tables(get_boat(BOAT)).solutions(math.radians(130.0), 1)
    lam33, lam0, mom33, mom0 = math.degrees(lams[2]), math.degrees(lams[3]), moms[2], moms[3]
    return SailMoments(lam33, lam0, mom33, mom0, (mom33 - mom0) / abs(lam33 - lam0))


def rudder_keel_ratio() -> float:
    """Roll-moment ratio of rudder to keel at the same angle of attack (linear lift).

    Returns
    -------
    float
        A_r C_L0r h3 / (A_k C_L0k h2).
    """
    p = get_boat(BOAT)
    return (p.rudder.area * lift_slope(p.rudder) * -p.rudder.z) / (p.keel.area * lift_slope(p.keel) * -p.keel.z)


@dataclass(frozen=True)
class Analysis:
    """The study's numbers.

    Parameters
    ----------
    smoke : bool
        The short pass.
    runs : RunTable
        Every run of the job list and its numbers.
    n_jobs : int
        How many runs of the job list.
    tables : dict of str to pandas.DataFrame
        Fig. 8 by variant (:func:`studies.wille_roll_table1.scenario.fig8_tables`).
    switch8 : pandas.DataFrame or None
        Fig. 8 with the sail force switched (full mode).
    shares : dict
        world -> the Fig. 3 shares (:func:`shares`).
    sail_shares : dict or None
        The paper world's shares with the sail force switched (full mode).
    optima : dict
        (variant, U10) -> phi_d of the top surge speed (:func:`optimum`).
    simulation_seconds : float
        Wall time of the simulations (s).
    seconds : float
        Wall time of the simulations and the analysis (s).
    trims : SailMoments or None
        The roll law's eased trims (full mode).
    rudder_keel : float
        :func:`rudder_keel_ratio`.
    froude_speed : float
        sqrt(g L) of the hull (m/s): a speed over it is the Froude number.
    """

    smoke: bool
    runs: RunTable
    n_jobs: int
    tables: dict
    switch8: pd.DataFrame | None
    shares: dict
    sail_shares: dict | None
    optima: dict
    simulation_seconds: float
    seconds: float
    trims: SailMoments | None
    rudder_keel: float
    froude_speed: float


def _switch8(raw: dict) -> pd.DataFrame:
    return pd.DataFrame([{"wind_speed": key[2], "heel_desired_deg": key[3],
                          "mean_surge": res["metrics"]["mean_surge"],
                          "mean_heel_deg": math.degrees(res["metrics"]["mean_heel"]),
                          "status": "stopped" if res["metrics"].get("stopped") else "ok"}
                         for key, res in raw.items() if key[0] == "fig8 sail"])


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's numbers from its runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`studies.wille_roll_table1.scenario.runs`.
    smoke : bool
        The short pass.

    Returns
    -------
    Analysis
        The numbers.
    """
    start = time.perf_counter()
    jobs = jobs_for(smoke, results.seeds)
    raw = dict(zip([job["key"] for job in jobs], results.jobs[NAME], strict=True))
    tables = {}
    for world in WORLDS:
        tables.update(fig8_tables(world, results.sweeps[f"fig8_sweep_{world}"]))
    runs = RunTable(raw, results.seeds)
    return Analysis(
        smoke=smoke, runs=runs, n_jobs=len(jobs), tables=tables,
        switch8=None if smoke else _switch8(raw),
        shares={w: shares(raw[("shares", w, "sim1", 0)]) for w in WORLDS},
        sail_shares=None if smoke else shares(raw[("shares", "paper", "sail", 0)]),
        optima={(v, wind): optimum(tables[v], wind) for v in tables for wind in FIG8_WINDS},
        simulation_seconds=results.seconds, seconds=results.seconds + time.perf_counter() - start,
        trims=None if smoke else sail_moments(), rudder_keel=rudder_keel_ratio(),
        froude_speed=math.sqrt(9.81 * get_boat(BOAT).hull.length))


def table1_verdict(got: Interval, sim: str, key: str) -> str:
    """A Table 1 number over seeds against the paper's: *holds* when its interval lies within
    :data:`studies.kit.verdict.TOLERANCE` (10 %) of the paper's number, *breaks* when it lies
    wholly outside that band, else *undecided at N seeds*.

    Parameters
    ----------
    got : sailmujoco.stats.Interval
        Ours over the seeds.
    sim : str
        A key of :data:`SIMS`.
    key : str
        A key of :data:`PAPER_TABLE1`'s entries.

    Returns
    -------
    str
        The verdict.
    """
    paper = PAPER_TABLE1[paper_sim(sim)][key]
    return over.decide(got, paper, "within", band=TOLERANCE * abs(paper))


@dataclass(frozen=True)
class RollCut:
    """What the roll law takes away in one world, law on against law off on the same gusts.

    Parameters
    ----------
    cut : sailmujoco.stats.Interval
        Roll amplitude off minus on (deg), paired by seed.
    cut_verdict : str
        Whether the law cuts the roll at all (the cut above 0).
    reduction : sailmujoco.stats.Interval
        The per-seed reduction 1 - on / off.
    reduction_verdict : str
        Whether it reaches :data:`REDUCTION_BOUND` (the paper's 73 % and 93 % reproduced).
    """

    cut: Interval
    cut_verdict: str
    reduction: Interval
    reduction_verdict: str


def roll_cut(r: RunTable, world: str, base: str, sim: str) -> RollCut:
    """:class:`RollCut` of ``sim`` against ``base`` in ``world``.

    Parameters
    ----------
    r : RunTable
        The runs.
    world : str
        A key of :data:`WORLDS`.
    base, sim : str
        The law-off and the law-on simulation.

    Returns
    -------
    RollCut
        The cut, the reduction and their verdicts.
    """
    cut, red = r.cut(world, base, sim), r.reduction(world, base, sim)
    return RollCut(cut, over.decide(cut, 0.0, "above"), red, over.decide(red, REDUCTION_BOUND, "above"))


def headline(analysis: Analysis) -> dict:
    """The headline numbers: Table 1's seed means (with the roll amplitude's interval) and the
    reductions paired by seed with their verdicts, the Fig. 3 shares, the Fig. 8 optima per
    world, and (full mode) sim 3 over the gust realisations and the lag switch.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.

    Returns
    -------
    dict
        ``{world}_{sim}_{quantity}`` (seed means; ``_low`` / ``_high`` the interval's ends for
        the roll amplitude; ``_verdict`` each Table 1 number's against the paper's within
        10 %), ``{world}_reduction_{base}_{sim}`` (the mean per-seed reduction,
        with ``_low``, ``_high`` and ``_verdict`` against :data:`REDUCTION_BOUND`),
        ``{world}_roll_cut_{base}_{sim}_deg`` (law off minus on, with ``_verdict``: the law
        cuts the roll), ``{world}_share_...``, ``{world}_fig8_optimum_deg_{U10}``,
        ``paper_sim3_...``, ``seeds``, ``simulation_wall_time_s`` and ``wall_time_s``.
    """
    r, numbers = analysis.runs, {"seeds": len(analysis.runs.seeds)}
    for w in WORLDS:
        for s in SIMS:
            for k in ("roll_amplitude", "max_roll_rate", "mean_surge", "mean_heel"):
                numbers[f"{w}_{s}_{k}"] = r.interval(w, s, k).mean
            amp = r.interval(w, s, "roll_amplitude")
            numbers[f"{w}_{s}_roll_amplitude_low"], numbers[f"{w}_{s}_roll_amplitude_high"] = amp.low, amp.high
            for k in ("roll_amplitude", "max_roll_rate", "mean_surge"):
                numbers[f"{w}_{s}_{k}_verdict"] = table1_verdict(r.interval(w, s, k), s, k)
        for base in BASES:
            for s in LAW_SIMS:
                c = roll_cut(r, w, base, s)
                key = f"{w}_reduction_{base}_{s}"
                numbers.update({key: c.reduction.mean, f"{key}_low": c.reduction.low,
                                f"{key}_high": c.reduction.high, f"{key}_verdict": c.reduction_verdict})
                numbers[f"{w}_roll_cut_{base}_{s}_deg"] = c.cut.mean
                numbers[f"{w}_roll_cut_{base}_{s}_verdict"] = c.cut_verdict
        for k in ("sail + restoring", "keel", "rudder + damping"):
            numbers[f"{w}_share_{k.replace(' + ', '_')}"] = analysis.shares[w][k]
        for wind in FIG8_WINDS:
            numbers[f"{w}_fig8_optimum_deg_{wind:g}"] = analysis.optima[(w, wind)]
    if not analysis.smoke:
        amps = [n3["roll_amplitude"] for _, _, n3 in r.realisations()]
        paper3 = PAPER_TABLE1["sim3"]["roll_amplitude"]
        numbers["paper_sim3_realisations"] = len(amps)
        numbers["paper_sim3_realisations_min"] = min(amps)
        numbers["paper_sim3_realisations_within"] = sum(a <= paper3 * (1 + WITHIN) for a in amps)
        numbers["paper_sim3_realisations_within_high"] = realisations_within(r).high
        for seed in LAG_SEEDS:
            for t, n in r.lag(seed)[1:]:
                numbers[f"paper_sim3_lag_{t:g}_seed{seed}_roll_amplitude"] = n["roll_amplitude"]
    numbers["simulation_wall_time_s"] = analysis.simulation_seconds
    numbers["wall_time_s"] = analysis.seconds
    return numbers


def realisations_within(r: RunTable) -> Interval:
    """The share of the paper world's gust realisations whose sim-3 roll amplitude lies within
    :data:`WITHIN` of the paper's (at most 1 + WITHIN times it), with Wilson's interval.

    Parameters
    ----------
    r : RunTable
        The runs.

    Returns
    -------
    sailmujoco.stats.Interval
        k of n with its interval.
    """
    paper3 = PAPER_TABLE1["sim3"]["roll_amplitude"]
    amps = [n3["roll_amplitude"] for _, _, n3 in r.realisations()]
    return pass_rate(sum(a <= paper3 * (1 + WITHIN) for a in amps), len(amps))
