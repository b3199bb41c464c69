"""Assumption validation, the sea's analysis: each series in a sea against calm water, metric by
metric and seed by seed, and what each difference beyond ``DIFFERENCE`` comes from.

Every case in a sea runs on the study's seeds (:attr:`sailmujoco.study.Results.seeds`; the seed
draws the sea, and in Table 1's runs the gusts too), each paired with the calm run of its seed
(the wind plane's and Saoud's calm runs are deterministic: one run for every seed). A
difference is relative to the calm value or, where that is smaller than the metric's floor
(the boat as good as upright, still or level), to the floor: (sea - calm) / max(|calm|, floor),
seed by seed; a case's difference is the mean over its seeds with its 95 % interval
(:mod:`sailmujoco.stats`), and its verdict (:func:`sailmujoco.stats.verdict`, the band
±``DIFFERENCE`` about 0): *holds* (the calm value stands: the whole interval within 10 %),
*breaks* (the sea changes it: the whole interval beyond) or *undecided at N seeds*. The roll of
a run is the heel's standard deviation over its window (in a random sea the peak-to-peak is an
extreme value that grows with the window). A run whose heading error RMS over the window
exceeds ``HEADING_LOST_DEG`` has lost its heading (it turned head to wind and stalled, or bore
away): such a seed's difference is not the sea's effect on a boat that holds its course, and a
case's numbers are over the seeds on which both runs keep their heading.

Every difference that breaks is rerun on the case's first :data:`.sea.MECHANISM_SEEDS` seeds
(those on which both runs kept their heading) with each of the sea's two paths into the boat
switched off in turn (:data:`.sea.PATHS`; both off, the calm boat to the bit): the share of the
difference a switch removes is 1 - (switched - calm)/(sea - calm), seed by seed, and its mean
with its interval. The path whose share's interval lies wholly above ``EXPLAINS``, the more of
the two, is the one the difference takes; where both lie wholly below, either path alone makes
more than half of it; otherwise it is undecided at those seeds (:func:`attribute`). The largest
difference of each series and metric is rerun with the hull's refinements off too, as far as the
sea's budget (:data:`.sea.BUDGET`) allows, and the refinement named the same way. A switched run
that loses its heading is reported as stalled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

from sailmujoco import constants, stats
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.design.check import natural_periods
from sailmujoco.forces.wave_spectra import pierson_moskowitz
from sailmujoco.forces.waves import components
from sailmujoco.options import WaveConfig
from sailmujoco.study import Results, Runs
from sailmujoco.suite import TASKS

from ..kit import seeds as kit_seeds
from ..kit.verdict import TOLERANCE
from . import sea
from .scenario import HEEL_HOLDS_DEG, SPEED_FLOOR

DIFFERENCE = TOLERANCE  # -, a sea changes a metric where |sea - calm| > 10 % of max(|calm|, floor)
EXPLAINS = 0.5  # -, a switch explains a difference when it removes more than half of it
ANGLE_FLOOR_DEG = 1.0  # deg, the floor of the angles' differences (roll, drift, pitch)
HEADING_LOST_DEG = 10.0  # deg, a run whose heading error RMS over its window exceeds it lost its heading
LOST = "lost its heading"  # the verdict of a case with no seed on which both runs keep their heading
# the metrics of a run holding its heading: name -> (what it is, unit, floor); heel and drift
# angle as magnitudes
SAILING = {"speed": ("steady speed", "m/s", SPEED_FLOOR),
           "heel": ("steady heel", "deg", HEEL_HOLDS_DEG),
           "roll_sd": ("roll σ (the heel's standard deviation)", "deg", ANGLE_FLOOR_DEG),
           "drift": ("drift angle (leeway)", "deg", ANGLE_FLOOR_DEG),
           "pitch_sd": ("pitch σ (the pitch's standard deviation)", "deg", ANGLE_FLOOR_DEG)}
# the metrics of a Table 1 run (over its last 50 s)
TABLE1 = {"roll_sd": ("roll σ (the heel's standard deviation)", "deg", ANGLE_FLOOR_DEG),
          "surge": ("mean surge", "m/s", SPEED_FLOOR),
          "heel": ("mean heel", "deg", HEEL_HOLDS_DEG)}
SERIES = {"saoud_robot": "saoud_robot, wind plane", "wille_yacht": "wille_yacht, wind plane",
          "table1": "Wille's roll controller, Table 1", "saoud": "Saoud's optimal sail"}
CASE_KEYS = ("case", "boat", "sim", "tws", "twa", "hs", "tp", "wave_from_deg", "n_components")


@dataclass(frozen=True, eq=False)
class SeaAnalysis:
    """What a sea does to the boats.

    Parameters
    ----------
    runs : dict
        Series (a key of ``SERIES``) -> one row per case and seed (:func:`compare`): its sea,
        ``seed``, ``case_index``, status, the reason it stopped, per metric ``<m>_calm``,
        ``<m>_sea``, ``<m>_change`` (sea - calm) and ``<m>_rel`` (the change over
        max(|calm|, floor)), the heading error RMS ``heading_rms_calm``, ``heading_rms_sea``
        (deg), the heel's period in the sea ``roll_period_sea`` (s) and ``lost_heading`` (the
        runs that lost it: "", "calm", "sea" or "calm, sea").
    tables : dict
        Series -> one row per case (:func:`summarise`): its keys, ``n`` (seeds), ``n_kept``
        (seeds on which both runs keep their heading), ``lost_calm``, ``lost_sea``, ``stopped``
        (seeds), and per metric the mean over the kept seeds with its interval (``<m>_calm``,
        ``<m>_sea``, ``<m>_change``, ``<m>_rel``, each with ``_low`` and ``_high``) and
        ``<m>_verdict``.
    mechanisms : pandas.DataFrame
        One row per series, metric and case whose difference breaks (:func:`attribution`).
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


def metrics_of(series: str) -> dict:
    """The metrics of a series (``SAILING`` or ``TABLE1``).

    Parameters
    ----------
    series : str
        A key of ``SERIES``.
    """
    return TABLE1 if series == "table1" else SAILING


def sailing_values(record: dict) -> dict:
    """A heading-hold run's metrics (``SAILING``, angles in degrees), status, cost, heading
    error RMS and heel period.

    Roll, pitch, heading error and the heel's period come from the heel, pitch and heading
    stored in the run's trajectory over its steady window (:func:`.sea.window_statistics`).

    Parameters
    ----------
    record : dict
        The run's record (:meth:`sailmujoco.study.Results.records`).
    """
    m = record.get("metrics") or {}
    options = record["task_options"]
    trajectory = record.get("trajectory") or []
    held = TASKS[record["task"]](seed=0, **options).desired_heading
    stats = sea.window_statistics([s["t"] for s in trajectory], [s["heel"] for s in trajectory],
                                  [math.remainder(s["heading"] - held, 2.0 * math.pi) for s in trajectory],
                                  options["steady_window"], [s["pitch"] for s in trajectory])
    nan = float("nan")
    return {"status": record["status"], **stats,
            "stopped": str(record.get("error") or "") if record["status"] != "ok" else "",
            "wall_time": record.get("wall_time", nan),
            "speed": m.get("steady_speed", nan),
            "heel": abs(math.degrees(m.get("steady_heel", nan))),
            "drift": abs(math.degrees(m.get("drift_angle", nan)))}


def table1_values(numbers: dict) -> dict:
    """A Table 1 run's metrics (``TABLE1``), status, heading error RMS and heel period.

    Parameters
    ----------
    numbers : dict
        :func:`.sea.table1_sea_run` of the run.
    """
    stopped = numbers.get("stopped", "")
    return {"status": "stopped" if stopped else "ok", "stopped": stopped,
            "roll_sd": numbers["roll_sd"], "heading_rms": numbers["heading_rms"],
            "roll_period": numbers["roll_period"], "surge": numbers["mean_surge"],
            "heel": abs(numbers["mean_heel"])}


def relative(change: float, calm: float, floor: float) -> float:
    """A change over max(|calm|, floor).

    Parameters
    ----------
    change : float
        Sea minus calm.
    calm : float
        The calm value.
    floor : float
        The smallest reference, in the metric's unit.
    """
    return change / max(abs(calm), floor)


def lost_heading(values: dict) -> bool:
    """Whether a run lost its heading: its heading error RMS beyond ``HEADING_LOST_DEG``.

    Parameters
    ----------
    values : dict
        The run's values (:func:`sailing_values`, :func:`table1_values`; no ``heading_rms``:
        kept).
    """
    return bool(values.get("heading_rms", 0.0) > HEADING_LOST_DEG)


def compare(keys: list[dict], calm: list[dict], seas: list[dict], metrics: dict) -> pd.DataFrame:
    """One row per run in a sea: its keys, the sea run's status, each metric calm, in a sea, the
    change and the relative change, the heading error RMS of both runs and which lost its heading.

    Parameters
    ----------
    keys : list of dict
        Each run's description (``case``: its label, its sea and seed).
    calm, seas : list of dict
        Each run's values in calm water (the calm run of its seed) and in the sea
        (:func:`sailing_values`, :func:`table1_values`).
    metrics : dict
        ``SAILING`` or ``TABLE1``.
    """
    rows = []
    for key, c, s in zip(keys, calm, seas, strict=True):
        nan = float("nan")
        row = {**key, "status": s["status"], "stopped": s["stopped"], "calm_status": c["status"],
               "heading_rms_calm": c.get("heading_rms", nan), "heading_rms_sea": s.get("heading_rms", nan),
               "roll_period_sea": s.get("roll_period", nan),
               "lost_heading": ", ".join(k for k, v in (("calm", c), ("sea", s)) if lost_heading(v))}
        if "wall_time" in s:
            row["wall_time_calm"], row["wall_time_sea"] = c["wall_time"], s["wall_time"]
        for name, (_, _, floor) in metrics.items():
            change = s[name] - c[name]
            row.update({f"{name}_calm": c[name], f"{name}_sea": s[name], f"{name}_change": change,
                        f"{name}_rel": relative(change, c[name], floor)})
        rows.append(row)
    return pd.DataFrame(rows)


def _put(row: dict, name: str, got: stats.Interval) -> None:
    row.update({name: got.mean, f"{name}_low": got.low, f"{name}_high": got.high})


def summarise(runs: pd.DataFrame, metrics: dict) -> pd.DataFrame:
    """One row per case of :func:`compare`'s rows: each metric over the seeds on which both runs
    keep their heading, calm and in the sea, the change paired by seed and the relative change,
    each the mean with its 95 % interval, and the relative change's verdict against the band
    ±``DIFFERENCE`` (*holds*: the calm value stands; *breaks*: the sea changes it; ``LOST``
    where no seed keeps its heading).

    Parameters
    ----------
    runs : pandas.DataFrame
        :func:`compare`'s rows, with ``case_index`` and ``seed``.
    metrics : dict
        ``SAILING`` or ``TABLE1``.
    """
    rows = []
    for _, group in runs.groupby("case_index", sort=True):
        first = group.iloc[0]
        kept = group[group["lost_heading"] == ""]
        row = {k: first[k] for k in CASE_KEYS if k in group}
        row.update({"case_index": int(first["case_index"]), "n": len(group), "n_kept": len(kept),
                    "lost_calm": int(group["lost_heading"].str.contains("calm").sum()),
                    "lost_sea": int(group["lost_heading"].str.contains("sea").sum()),
                    "stopped": int((group["status"] != "ok").sum())})
        for column in ("heading_rms_calm", "heading_rms_sea", "roll_period_sea"):
            _put(row, column, kit_seeds.interval(group[column]))
        for name in metrics:
            _put(row, f"{name}_calm", kit_seeds.interval(kept[f"{name}_calm"]))
            _put(row, f"{name}_sea", kit_seeds.interval(kept[f"{name}_sea"]))
            _put(row, f"{name}_change", kit_seeds.paired(kept[f"{name}_sea"], kept[f"{name}_calm"]))
            rel = kit_seeds.interval(kept[f"{name}_rel"])
            _put(row, f"{name}_rel", rel)
            row[f"{name}_verdict"] = (kit_seeds.decide(rel, 0.0, "within", band=DIFFERENCE)
                                      if len(kept) else LOST)
        rows.append(row)
    return pd.DataFrame(rows)


def interval_of(row, column: str) -> stats.Interval:
    """The interval a row of :func:`summarise` (N: its kept seeds) or of :func:`attribution`
    (N: ``n``) holds for ``column``.

    Parameters
    ----------
    row : mapping
        The row.
    column : str
        The number.
    """
    n = row["n_kept"] if "n_kept" in row else row["n"]
    return kit_seeds.row_interval(row, column, n=int(n))


def _sweep_values(results: Results, spec: dict) -> list[dict]:
    return [sailing_values(r) for r in results.records(f"sweeps/{spec['name']}")]


def _seeded(keys: list[dict], seeds) -> list[dict]:
    """Each case's keys once per seed (case by case, seed by seed), with ``case_index`` and ``seed``."""
    return [{**key, "case_index": i, "seed": int(seed)} for i, key in enumerate(keys) for seed in seeds]


def first_pass(results: Results, smoke: bool) -> dict:
    """Every series' rows, one per case and seed (:func:`compare`), from the first pass's runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The study's runs (``results.seeds``: the seeds).
    smoke : bool
        The study's short pass.
    """
    seeds = tuple(results.seeds)
    n = len(seeds)
    tables = {}
    specs = sea.plane_sea_specs(smoke, seeds)
    for (boat, kind), spec in specs.items():
        if kind == "sea":
            z = specs[(boat, "calm")]["zip"]
            sea_zip = spec["zip"]
            keys = [{"case": f"{u:g} m/s, {a:g}°", "boat": boat, "tws": u, "twa": a, "hs": h, "tp": t,
                     "wave_from_deg": d, "n_components": spec["options"]["waves.n_components"]}
                    for u, a, h, t, d in
                    zip(z["task.wind_speed"], z["task.wind_from_deg"], sea_zip["waves.hs"][::n],
                        sea_zip["waves.tp"][::n], sea_zip["waves.direction_from_deg"][::n], strict=True)]
            calm = _sweep_values(results, specs[(boat, "calm")])
            tables[boat] = compare(_seeded(keys, seeds), [c for c in calm for _ in seeds],
                                   _sweep_values(results, spec), SAILING)
    saoud = sea.saoud_sea_specs(smoke, seeds)
    z, options = saoud["sea"]["zip"], saoud["sea"]["options"]
    keys = [{"case": f"Hs {h:g} m", "hs": h, "tp": t, "wave_from_deg": options["waves.direction_from_deg"],
             "n_components": options["waves.n_components"]}
            for h, t in zip(z["waves.hs"][::n], z["waves.tp"][::n], strict=True)]
    calm = _sweep_values(results, saoud["calm"]) * (len(keys) * n)
    tables["saoud"] = compare(_seeded(keys, seeds), calm, _sweep_values(results, saoud["sea"]), SAILING)
    calm_numbers = {(j["sim"], j["seed"]): n for j, n in
                    zip(sea.table1_calm_jobs(smoke, seeds), results.jobs[sea.CALM_JOB], strict=True)}
    jobs = sea.table1_sea_jobs(smoke, seeds)
    keys = [{"case": f"{j['sim']}, Hs {j['hs']:g} m", "sim": j["sim"], "hs": j["hs"],
             "tp": j["run"]["env"]["waves"]["tp"], "wave_from_deg": j["run"]["env"]["waves"]["direction_from_deg"],
             "n_components": j["run"]["env"]["waves"]["n_components"]}
            for j in jobs[::n]]
    calm = [table1_values(calm_numbers[(j["sim"], j["seed"])]) for j in jobs]
    tables["table1"] = compare(_seeded(keys, seeds), calm, [table1_values(v) for v in results.jobs[sea.SEA_JOB]],
                               TABLE1)
    return tables


def summaries(runs: dict) -> dict:
    """Every series' cases (:func:`summarise`) from its rows (:func:`first_pass`).

    Parameters
    ----------
    runs : dict
        Series -> its rows.
    """
    return {series: summarise(table, metrics_of(series)) for series, table in runs.items()}


def differing_cases(tables: dict, smoke: bool) -> list[tuple[str, str, int]]:
    """(series, metric, case index) of every difference whose verdict is *breaks*, series by
    series, metric by metric. Smoke (two seeds decide little): the one largest mean difference
    beyond ``DIFFERENCE`` of a case with a seed on which both runs keep their heading.

    Parameters
    ----------
    tables : dict
        Series -> its cases (:func:`summarise`).
    smoke : bool
        The study's short pass.
    """
    if smoke:
        found = [(abs(row[f"{metric}_rel"]), series, metric, int(row["case_index"]))
                 for series, table in tables.items() for metric in metrics_of(series)
                 for _, row in table.iterrows()
                 if row["n_kept"] and np.isfinite(row[f"{metric}_rel"]) and abs(row[f"{metric}_rel"]) > DIFFERENCE]
        return [max(found)[1:]] if found else []
    return [(series, metric, int(row["case_index"])) for series, table in tables.items()
            for metric in metrics_of(series) for _, row in table.iterrows() if row[f"{metric}_verdict"] == "breaks"]


def largest_cases(tables: dict, selected: list) -> list[tuple[str, str, int]]:
    """Of ``selected`` (:func:`differing_cases`), the largest mean difference of each series and
    metric.

    Parameters
    ----------
    tables : dict
        Series -> its cases (:func:`summarise`).
    selected : list of (str, str, int)
        The differences.
    """
    best = {}
    for series, metric, case in selected:
        size = abs(float(tables[series].set_index("case_index").loc[case, f"{metric}_rel"]))
        if (series, metric) not in best or size > best[(series, metric)][0]:
            best[(series, metric)] = (size, case)
    return [(series, metric, case) for (series, metric), (_, case) in best.items()]


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

    Every case with a difference (:func:`differing_cases`) on its first
    :data:`.sea.MECHANISM_SEEDS` seeds that kept their heading, each path of :data:`.sea.PATHS`
    off; the largest case of each series and metric (:func:`largest_cases`; smoke: the one
    case) with the hull's refinements off as well, series by series in ``REFINEMENT_ORDER``, as
    long as the sea's cost stays within :data:`.sea.BUDGET` (no limit in smoke).

    Parameters
    ----------
    runs : dict
        Series -> its rows (:func:`first_pass`).
    tables : dict
        Series -> its cases (:func:`summarise`).
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


def shares(calm, sea_value, switched) -> np.ndarray:
    """The share of a difference a switch removes, seed by seed: 1 - (switched - calm)/(sea -
    calm) (1: the switch brings the metric back to calm; 0: it changes nothing; negative: it
    makes the difference larger); NaN where the seed's difference is 0 or its rerun has no value.

    Parameters
    ----------
    calm, sea_value, switched : array_like
        One value per seed: calm water, the sea with every mechanism on, the sea with the
        switch off.
    """
    calm, sea_value, switched = (np.asarray(v, dtype=float) for v in (calm, sea_value, switched))
    difference = sea_value - calm
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(difference != 0.0, 1.0 - (switched - calm) / difference, np.nan)


def explains(got: stats.Interval, share: float = EXPLAINS) -> str:
    """Whether a switch explains a difference: the verdict of its share's interval against
    ``share`` (*holds*: it removes more than that; *breaks*: at most that).

    Parameters
    ----------
    got : sailmujoco.stats.Interval
        The share removed, over seeds.
    share : float
        The least share of the difference a switch must remove to explain it.
    """
    return stats.verdict(got, share, "above")


def attribute(calm, sea_value, switched: dict, share: float = EXPLAINS):
    """Which mechanism a difference comes from: ``(name or None, {name: share removed})``.

    Each switch's share (:func:`shares`) is the mean over seeds with its interval. The name is
    the switch with the largest mean share among those whose interval lies wholly above
    ``share`` (:func:`explains`); None when none does.

    Parameters
    ----------
    calm : array_like
        The metric in calm water, one per seed.
    sea_value : array_like
        The metric in the sea, every mechanism on, one per seed.
    switched : dict
        Mechanism -> the metric in the sea with that mechanism off, one per seed.
    share : float
        The least share of the difference a switch must remove to explain it.
    """
    removed = {name: kit_seeds.interval(shares(calm, sea_value, value)) for name, value in switched.items()}
    holding = {name: got.mean for name, got in removed.items() if explains(got, share) == "holds"}
    return (max(holding, key=holding.get) if holding else None), removed


def path_taken(removed: dict, stalled: dict) -> str:
    """The path a difference takes from its two paths' shares (:func:`attribute`): "hull" or
    "foils" (the switch that explains it), "either" (each switch surely removes at most
    ``EXPLAINS``: each path alone makes more than half), "hull alone" or "foils alone" (that
    path's rerun lost its heading on every seed and the other's switch surely removes at most
    1 - ``EXPLAINS``: with both off the boat is the calm boat), "stalled" (a path's rerun lost
    its heading otherwise) or "undecided".

    Parameters
    ----------
    removed : dict
        Path -> its share's interval.
    stalled : dict
        Path -> (seeds whose rerun lost its heading, seeds rerun).
    """
    words = {"wave_hull": "hull", "wave_foil_flow": "foils"}
    holding = {n: removed[n].mean for n in sea.PATHS if explains(removed[n]) == "holds"}
    if holding:
        return words[max(holding, key=holding.get)]
    lost = [n for n in sea.PATHS if stalled[n][0]]
    if len(lost) == 1 and stalled[lost[0]][0] == stalled[lost[0]][1]:
        other = next(n for n in sea.PATHS if n != lost[0])
        if explains(removed[other], 1.0 - EXPLAINS) == "breaks":
            return f"{words[lost[0]]} alone"
    if lost:
        return "stalled"
    if all(explains(removed[n]) == "breaks" for n in sea.PATHS):
        return "either"
    return "undecided"


def lost_cases(tables: dict) -> pd.DataFrame:
    """The cases with a seed on which the calm or the sea run lost its heading (that seed left out
    of the case's numbers): series, case, the seeds lost in calm water and in the sea, of N,
    their heading error RMS (deg, mean over the seeds with its interval).

    Parameters
    ----------
    tables : dict
        Series -> its cases (:func:`summarise`).
    """
    rows = []
    for series, table in tables.items():
        for _, row in table[(table["lost_calm"] > 0) | (table["lost_sea"] > 0)].iterrows():
            rows.append({"series": SERIES[series], "case": row["case"], "lost_calm": row["lost_calm"],
                         "lost_sea": row["lost_sea"], "n": row["n"],
                         "heading_rms_calm": kit_seeds.row_interval(row, "heading_rms_calm"),
                         "heading_rms_sea": kit_seeds.row_interval(row, "heading_rms_sea")})
    return pd.DataFrame(rows, columns=["series", "case", "lost_calm", "lost_sea", "n", "heading_rms_calm",
                                       "heading_rms_sea"])


def _rerun_values(results: Results, plan: dict, smoke: bool, seeds) -> pd.DataFrame:
    """One row per rerun of ``plan``: series, case index, seed, mechanism, its values."""
    sources = _mechanism_sources(smoke, seeds)
    rows = []
    for series, entries in plan.items():
        if series == "table1":
            values = [table1_values(v) for v in results.jobs.get(sea.MECHANISM_JOB, [])]
        else:
            spec = sea.mechanism_spec(sources[series], [(i, m) for i, _, _, m in entries])
            values = _sweep_values(results, spec)
        for (_, case, seed, name), v in zip(entries, values, strict=True):
            rows.append({"series": series, "case_index": case, "seed": seed, "mechanism": name,
                         "stalled": lost_heading(v), **{m: v[m] for m in metrics_of(series)}})
    return pd.DataFrame(rows, columns=["series", "case_index", "seed", "mechanism", "stalled",
                                       *dict.fromkeys([*SAILING, *TABLE1])])


def attribution(runs: dict, tables: dict, reruns: pd.DataFrame, smoke: bool) -> pd.DataFrame:
    """The mechanisms' table: each difference of :func:`differing_cases` (``largest``: the
    largest of its series and metric), with, per mechanism rerun, the metric with it off
    (``<mechanism>_off``, the mean over the seeds rerun), the share it removes
    (``<mechanism>_removed`` with ``_low`` and ``_high``: :func:`attribute`; over the seeds on
    which the rerun kept its heading), the seeds whose rerun lost it (``<mechanism>_stalled``)
    and rerun (``<mechanism>_n``); the path it takes (``path``: :func:`path_taken`;
    ``mechanism``: the path's switch where one explains it) and the refinement of the hull's
    path that explains it (``refinement``), each "" when none does.

    Parameters
    ----------
    runs : dict
        Series -> its rows (:func:`first_pass`).
    tables : dict
        Series -> its cases (:func:`summarise`).
    reruns : pandas.DataFrame
        :func:`_rerun_values`.
    smoke : bool
        The study's short pass.
    """
    selected = differing_cases(tables, smoke)
    largest = set(largest_cases(tables, selected))
    out = []
    for series, metric, case in selected:
        case_row = tables[series].set_index("case_index").loc[case]
        mine = reruns[(reruns["series"] == series) & (reruns["case_index"] == case)]
        rerun_seeds = list(dict.fromkeys(mine["seed"]))
        first = runs[series].set_index(["case_index", "seed"])
        calm = np.array([first.loc[(case, s), f"{metric}_calm"] for s in rerun_seeds], dtype=float)
        sea_value = np.array([first.loc[(case, s), f"{metric}_sea"] for s in rerun_seeds], dtype=float)
        values, stalled = {}, {}
        for name, _ in sea.MECHANISMS:
            these = mine[mine["mechanism"] == name].set_index("seed")
            if these.empty:
                continue
            got = np.array([these.loc[s, metric] if s in these.index else np.nan for s in rerun_seeds], dtype=float)
            lost = np.array([bool(these.loc[s, "stalled"]) if s in these.index else False for s in rerun_seeds])
            values[name] = np.where(lost, np.nan, got)
            stalled[name] = (int(lost.sum()), len(these))
        mechanism, removed = attribute(calm, sea_value, {n: values[n] for n in sea.PATHS if n in values})
        path = path_taken(removed, stalled) if all(n in removed for n in sea.PATHS) else "undecided"
        refinement, finer = attribute(calm, sea_value, {n: v for n, v in values.items() if n not in sea.PATHS})
        removed.update(finer)
        label, unit, _ = metrics_of(series)[metric]
        row = {"series": SERIES[series], "series_key": series, "metric_key": metric, "case": case_row["case"],
               "case_index": case, "metric": label, "unit": unit, "n": len(rerun_seeds),
               "mechanism_seeds": " ".join(str(s) for s in rerun_seeds),
               "largest": (series, metric, case) in largest, "verdict": case_row[f"{metric}_verdict"],
               "n_kept": int(case_row["n_kept"])}
        for column in ("calm", "sea", "change", "rel"):
            for end in ("", "_low", "_high"):
                row[f"{column}{end}"] = case_row[f"{metric}_{column}{end}"]
        for name, _ in sea.MECHANISMS:
            got = removed.get(name, stats.Interval(math.nan, math.nan, math.nan, 0))
            row[f"{name}_off"] = float(np.nanmean(values[name])) if name in values and np.isfinite(values[name]).any() \
                else math.nan
            row[f"{name}_removed"], row[f"{name}_removed_low"], row[f"{name}_removed_high"] = got.mean, got.low, got.high
            row[f"{name}_removed_n"] = got.n
            row[f"{name}_stalled"], row[f"{name}_n"] = stalled.get(name, (0, 0))
        row["path"], row["mechanism"], row["refinement"] = path, mechanism or "", refinement or ""
        out.append(row)
    return pd.DataFrame(out)


def removed_interval(row, name: str) -> stats.Interval:
    """The share of a difference switch ``name`` removes, from a row of :func:`attribution`.

    Parameters
    ----------
    row : mapping
        The row.
    name : str
        A mechanism of :data:`.sea.MECHANISMS`.
    """
    return stats.Interval(float(row[f"{name}_removed"]), float(row[f"{name}_removed_low"]),
                          float(row[f"{name}_removed_high"]), int(row[f"{name}_removed_n"]))


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
        _put(row, "rms_slope", kit_seeds.interval(slopes))
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
