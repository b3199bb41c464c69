"""Assumption validation, the sea's analysis: what a sea does to the boats, from both passes'
runs (:func:`analyse_sea`).

Each series in a sea against calm water, case by case and seed by seed, is :mod:`.sea_cases`;
where each difference that breaks comes from, :mod:`.sea_attribution`. This module plans the
mechanism reruns (:func:`rerun_plan`, the second pass :func:`mechanism_runs`) within the sea's
budget (:data:`.sea.BUDGET`), reads them back, and adds why a sea rolls the boats
(:func:`roll_resonance`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from sailmujoco import constants
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.design.check import natural_periods
from sailmujoco.forces.wave_spectra import pierson_moskowitz
from sailmujoco.forces.waves import components
from sailmujoco.options import WaveConfig
from sailmujoco.study import Results, Runs

from ..kit import seeds as kit_seeds
from . import sea
from .sea_attribution import attribution, differing_cases, largest_cases
from .sea_cases import (
    SAILING,
    TABLE1,
    first_pass,
    lost_heading,
    metrics_of,
    put_interval,
    summaries,
    sweep_values,
    table1_values,
)


@dataclass(frozen=True, eq=False)
class SeaAnalysis:
    """What a sea does to the boats.

    Parameters
    ----------
    runs : dict
        Series (a key of ``SERIES``) -> one row per case and seed (:func:`.sea_cases.compare`): its sea,
        ``seed``, ``case_index``, status, the reason it stopped, per metric ``<m>_calm``,
        ``<m>_sea``, ``<m>_change`` (sea - calm) and ``<m>_rel`` (the change over
        max(|calm|, floor)), the heading error RMS ``heading_rms_calm``, ``heading_rms_sea``
        (deg), the heel's period in the sea ``roll_period_sea`` (s) and ``lost_heading`` (the
        runs that lost it: "", "calm", "sea" or "calm, sea").
    tables : dict
        Series -> one row per case (:func:`.sea_cases.summarise`): its keys, ``n`` (seeds), ``n_kept``
        (seeds on which both runs keep their heading), ``lost_calm``, ``lost_sea``, ``stopped``
        (seeds), and per metric the mean over the kept seeds with its interval (``<m>_calm``,
        ``<m>_sea``, ``<m>_change``, ``<m>_rel``, each with ``_low`` and ``_high``) and
        ``<m>_verdict``.
    mechanisms : pandas.DataFrame
        One row per series, metric and case whose difference breaks (:func:`.sea_attribution.attribution`).
    reruns : pandas.DataFrame
        One row per mechanism rerun: series, case, seed, the mechanism off, its metrics and
        whether it lost its heading.
    resonance : dict
        :func:`roll_resonance`: each boat's roll period and the seas' slopes.
    seeds : tuple of int
        The seeds every case in a sea ran on.
    cost : dict
        ``first``, ``mechanisms``: the sea's simulated seconds in each pass
        (:func:`.sea.simulated_seconds`); ``budget``: :data:`.sea.BUDGET`.
    """

    runs: dict
    tables: dict
    mechanisms: pd.DataFrame
    reruns: pd.DataFrame
    resonance: dict
    seeds: tuple = (0,)
    cost: dict = field(default_factory=dict)



def _mechanism_sources(smoke: bool, seeds) -> dict:
    """Series -> the sea spec its cases come from (the sweep series)."""
    specs = sea.plane_sea_specs(smoke, seeds)
    return {"saoud_robot": specs[("saoud_robot", "sea")], "wille_yacht": specs[("wille_yacht", "sea")],
            "saoud": sea.saoud_sea_specs(smoke, seeds)["sea"]}


REFINEMENT_ORDER = ("saoud_robot", "wille_yacht", "saoud", "table1")  # the refinements' turn for the budget


def _rerun_cost(series: str, smoke: bool) -> float:
    """Simulated seconds of one rerun of ``series`` (in a sea)."""
    from ..kit.wille import TABLE1_DURATION, TABLE1_SMOKE_DURATION

    if series == "table1":
        duration = TABLE1_SMOKE_DURATION if smoke else TABLE1_DURATION
    elif series == "saoud":
        duration = sea.SMOKE_DURATION if smoke else sea.SAOUD_DURATION
    else:
        duration = sea.plane_sea_specs(smoke)[(series, "sea")]["duration"]
    return sea.SEA_COST * duration


def rerun_plan(runs: dict, tables: dict, smoke: bool, seeds) -> dict:
    """The mechanism reruns: series -> [(run index in its sea spec or job list, case index,
    seed, mechanism)], in that order.

    Every case with a difference (:func:`.sea_attribution.differing_cases`) on its first
    :data:`.sea.MECHANISM_SEEDS` seeds that kept their heading, each path of :data:`.sea.PATHS`
    off; the largest case of each series and metric (:func:`.sea_attribution.largest_cases`; smoke: the one
    case) with the hull's refinements off as well, series by series in ``REFINEMENT_ORDER``, as
    long as the sea's cost stays within :data:`.sea.BUDGET` (no limit in smoke).

    Parameters
    ----------
    runs : dict
        Series -> its rows (:func:`.sea_cases.first_pass`).
    tables : dict
        Series -> its cases (:func:`.sea_cases.summarise`).
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The seeds of the first pass.
    """
    seeds = tuple(seeds)
    selected = differing_cases(tables, smoke)
    refine = {(s, c) for s, _, c in (selected if smoke else largest_cases(tables, selected))}
    cases = {}
    for series, _, case in selected:
        cases.setdefault(series, set()).add(case)
    refinements = [name for name, _ in sea.MECHANISMS if name not in sea.PATHS]
    spent = sea.simulated_seconds(sea.runs(smoke, seeds))
    plan = {}
    for series in REFINEMENT_ORDER:
        rows = runs.get(series)
        for case in sorted(cases.get(series, ())):
            kept = rows[(rows["case_index"] == case) & (rows["lost_heading"] == "")]["seed"].tolist()
            for seed in kept[:sea.MECHANISM_SEEDS]:
                index = case * len(seeds) + seeds.index(seed)
                plan.setdefault(series, []).extend((index, case, seed, name) for name in sea.PATHS)
        spent += _rerun_cost(series, smoke) * len(plan.get(series, []))
    for series in REFINEMENT_ORDER:
        rows = runs.get(series)
        for case in sorted(c for s, c in refine if s == series):
            kept = rows[(rows["case_index"] == case) & (rows["lost_heading"] == "")]["seed"].tolist()
            extra = [(case * len(seeds) + seeds.index(seed), case, seed, name)
                     for seed in kept[:sea.MECHANISM_SEEDS] for name in refinements]
            cost = _rerun_cost(series, smoke) * len(extra)
            if smoke or spent + cost <= sea.BUDGET:
                plan[series].extend(extra)
                spent += cost
    return plan


def mechanism_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: the mechanism reruns of :func:`rerun_plan`.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass's runs (``results.seeds``: the seeds).
    smoke : bool
        The study's short pass.
    """
    seeds = tuple(results.seeds)
    runs = first_pass(results, smoke)
    plan = rerun_plan(runs, summaries(runs), smoke, seeds)
    sources = _mechanism_sources(smoke, seeds)
    sweeps = tuple((spec, f"sweeps/{spec['name']}") for spec in
                   (sea.mechanism_spec(sources[s], [(i, m) for i, _, _, m in entries])
                    for s, entries in plan.items() if s in sources))
    jobs = {}
    if "table1" in plan:
        jobs[sea.MECHANISM_JOB] = (f"{__package__}.sea:table1_sea_run",
                                   sea.mechanism_jobs(sea.table1_sea_jobs(smoke, seeds),
                                                      [(i, m) for i, _, _, m in plan["table1"]]))
    return Runs(sweeps=sweeps, jobs=jobs, label="the sea's mechanisms")



def _rerun_values(results: Results, plan: dict, smoke: bool, seeds) -> pd.DataFrame:
    """One row per rerun of ``plan``: series, case index, seed, mechanism, its values."""
    sources = _mechanism_sources(smoke, seeds)
    rows = []
    for series, entries in plan.items():
        if series == "table1":
            values = [table1_values(v) for v in results.jobs.get(sea.MECHANISM_JOB, [])]
        else:
            spec = sea.mechanism_spec(sources[series], [(i, m) for i, _, _, m in entries])
            values = sweep_values(results, spec)
        for (_, case, seed, name), v in zip(entries, values, strict=True):
            rows.append({"series": series, "case_index": case, "seed": seed, "mechanism": name,
                         "stalled": lost_heading(v), **{m: v[m] for m in metrics_of(series)}})
    return pd.DataFrame(rows, columns=["series", "case_index", "seed", "mechanism", "stalled",
                                       *dict.fromkeys([*SAILING, *TABLE1])])



def roll_resonance(n_components: int, seeds=(0,)) -> dict:
    """Why a sea rolls the boats: each boat's roll period and the waves it meets, and the
    fully developed seas ``SEA_HS``' slopes.

    ``boats``: one row per boat, ``t4`` (the roll period with sway free, :func:`sailmujoco.design.check.natural_periods`, s), ``wavelength``
    (deep-water waves of that period, g T4^2/(2 pi), m), ``length`` (the hull's, m).
    ``seas``: one row per Hs of :data:`.sea.SEA_HS`, ``tp`` (s), ``tp_over_t4`` (the yacht's),
    ``omega4_over_omegap`` (the robot's roll frequency over the sea's peak), ``slope_density`` (the wave slope spectrum (omega^2/g)^2 S(omega) at the robot's roll
    frequency, rad^2 s) and ``rms_slope`` (the RMS slope of the sea's ``n_components``
    components, sqrt(sum (a_i k_i)^2 / 2), deg: the mean over ``seeds`` with ``rms_slope_low``
    and ``rms_slope_high``, its interval).

    Parameters
    ----------
    n_components : int
        Components of the seas, as the runs draw them.
    seeds : sequence of int
        The seeds the runs draw them with.
    """
    g = constants.GRAVITY
    t4 = {b: natural_periods(get_boat(b))["roll_period"] for b in sea.FETCH}
    boats = pd.DataFrame([{"boat": b, "t4": t4[b],
                           "wavelength": g * t4[b] ** 2 / (2.0 * math.pi),
                           "length": get_boat(b).hull.length} for b in sea.FETCH])
    omega = 2.0 * math.pi / t4["saoud_robot"]
    rows = []
    for hs in sea.SEA_HS:
        _, tp = sea.developed_sea(hs)
        slopes = []
        for seed in seeds:
            comp = components(WaveConfig(spectrum="pm", hs=hs, tp=tp, n_components=n_components, seed=int(seed)))
            slopes.append(math.degrees(math.atan(math.sqrt(0.5 * float(np.sum((comp.amplitude * comp.k) ** 2))))))
        row = {"hs": hs, "tp": tp, "tp_over_t4": tp / t4["wille_yacht"],
               "omega4_over_omegap": omega * tp / (2.0 * math.pi),
               "slope_density": (omega**2 / g) ** 2 * float(pierson_moskowitz(omega, hs, tp))}
        put_interval(row, "rms_slope", kit_seeds.interval(slopes))
        rows.append(row)
    return {"boats": boats, "seas": pd.DataFrame(rows)}


def analyse_sea(results: Results, smoke: bool) -> SeaAnalysis:
    """What a sea does to the boats, from both passes' runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The study's runs (the second pass's included; ``results.seeds``: the seeds).
    smoke : bool
        The study's short pass.
    """
    seeds = tuple(results.seeds)
    runs = first_pass(results, smoke)
    tables = summaries(runs)
    plan = rerun_plan(runs, tables, smoke, seeds)
    reruns = _rerun_values(results, plan, smoke, seeds)
    cost = {"first": sea.simulated_seconds(sea.runs(smoke, seeds)),
            "mechanisms": sea.simulated_seconds(mechanism_runs(results, smoke)), "budget": sea.BUDGET}
    return SeaAnalysis(runs, tables, attribution(runs, tables, reruns, smoke), reruns,
                       roll_resonance(sea.SEA_COMPONENTS, seeds), seeds, cost)
