"""Assumption validation, the sea's analysis: each series in a sea against calm water, metric by
metric, and what each difference beyond ``DIFFERENCE`` comes from.

A difference is relative to the calm value or, where that is smaller than the metric's floor
(the boat as good as upright, still or level), to the floor: (sea - calm) / max(|calm|, floor).
For every series and metric whose difference goes beyond ``DIFFERENCE`` somewhere, the case
where it is largest is rerun with each of the sea's mechanisms off in turn
(:data:`.sea.MECHANISMS`): the share of the difference a switch removes is
1 - (switched - calm)/(sea - calm), and the mechanism whose switch removes at least
``EXPLAINS`` of it, the most of them, explains it (:func:`attribute`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.study import Results, Runs

from . import sea
from .scenario import HEEL_HOLDS_DEG, PART_NAMES, RUNS_JOB, SPEED_FLOOR, table1_jobs

DIFFERENCE = 0.10  # -, a sea changes a metric where |sea - calm| > 10 % of max(|calm|, floor)
EXPLAINS = 0.5  # -, a switch explains a difference when it removes at least half of it
ANGLE_FLOOR_DEG = 1.0  # deg, the floor of the angles' differences (roll amplitude, drift, pitch)
# the metrics of a run holding its heading: name -> (what it is, unit, floor); heel and drift
# angle as magnitudes
SAILING = {"speed": ("steady speed", "m/s", SPEED_FLOOR),
           "heel": ("steady heel", "deg", HEEL_HOLDS_DEG),
           "roll": ("roll amplitude", "deg", ANGLE_FLOOR_DEG),
           "drift": ("drift angle (leeway)", "deg", ANGLE_FLOOR_DEG),
           "pitch": ("pitch amplitude", "deg", ANGLE_FLOOR_DEG)}
# the metrics of a Table 1 run (over its last 50 s)
TABLE1 = {"roll": ("roll amplitude", "deg", ANGLE_FLOOR_DEG),
          "surge": ("mean surge", "m/s", SPEED_FLOOR),
          "heel": ("mean heel", "deg", HEEL_HOLDS_DEG)}
SERIES = {"saoud_robot": "saoud_robot, wind plane", "wille_yacht": "wille_yacht, wind plane",
          "table1": "Wille's roll controller, Table 1", "saoud": "Saoud's optimal sail"}


@dataclass(frozen=True, eq=False)
class SeaAnalysis:
    """What a sea does to the boats.

    Parameters
    ----------
    tables : dict
        Series (a key of ``SERIES``) -> one row per case: its sea, status, the reason it
        stopped, and per metric ``<m>_calm``, ``<m>_sea``, ``<m>_change`` (sea - calm) and
        ``<m>_rel`` (the change over max(|calm|, floor)).
    mechanisms : pandas.DataFrame
        One row per series and metric beyond ``DIFFERENCE``: its largest case, the value with
        each mechanism off, the share each switch removes and the mechanism named.
    """

    tables: dict
    mechanisms: pd.DataFrame


def metrics_of(series: str) -> dict:
    """The metrics of a series (``SAILING`` or ``TABLE1``).

    Parameters
    ----------
    series : str
        A key of ``SERIES``.
    """
    return TABLE1 if series == "table1" else SAILING


def sailing_values(record: dict) -> dict:
    """A heading-hold run's metrics (``SAILING``, angles in degrees), status and cost.

    The roll amplitude is half the peak-to-peak of the heel stored in the run's trajectory
    over its steady window.

    Parameters
    ----------
    record : dict
        The run's record (:meth:`sailmujoco.study.Results.records`).
    """
    m = record.get("metrics") or {}
    window = record["task_options"]["steady_window"]
    trajectory = record.get("trajectory") or []
    heel = [s["heel"] for s in trajectory if s["t"] >= trajectory[-1]["t"] - window] if trajectory else []
    nan = float("nan")
    return {"status": record["status"],
            "stopped": str(record.get("error") or "") if record["status"] != "ok" else "",
            "wall_time": record.get("wall_time", nan),
            "speed": m.get("steady_speed", nan),
            "heel": abs(math.degrees(m.get("steady_heel", nan))),
            "roll": math.degrees(0.5 * (max(heel) - min(heel))) if heel else nan,
            "drift": abs(math.degrees(m.get("drift_angle", nan))),
            "pitch": math.degrees(m.get("pitch_amplitude", nan))}


def table1_values(numbers: dict) -> dict:
    """A Table 1 run's metrics (``TABLE1``) and status.

    Parameters
    ----------
    numbers : dict
        :func:`studies.kit.wille.table1_numbers` of the run (with ``stopped`` where it stopped).
    """
    stopped = numbers.get("stopped", "")
    return {"status": "stopped" if stopped else "ok", "stopped": stopped,
            "roll": numbers["roll_amplitude"], "surge": numbers["mean_surge"],
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


def compare(keys: list[dict], calm: list[dict], seas: list[dict], metrics: dict) -> pd.DataFrame:
    """One row per case: its keys, the sea run's status, each metric calm, in a sea, the change
    and the relative change.

    Parameters
    ----------
    keys : list of dict
        Each case's description (``case``: its label, and its sea).
    calm, seas : list of dict
        Each case's values in calm water and in the sea (:func:`sailing_values`,
        :func:`table1_values`).
    metrics : dict
        ``SAILING`` or ``TABLE1``.
    """
    rows = []
    for key, c, s in zip(keys, calm, seas, strict=True):
        row = {**key, "status": s["status"], "stopped": s["stopped"],
               "calm_status": c["status"]}
        if "wall_time" in s:
            row["wall_time_calm"], row["wall_time_sea"] = c["wall_time"], s["wall_time"]
        for name, (_, _, floor) in metrics.items():
            change = s[name] - c[name]
            row.update({f"{name}_calm": c[name], f"{name}_sea": s[name], f"{name}_change": change,
                        f"{name}_rel": relative(change, c[name], floor)})
        rows.append(row)
    return pd.DataFrame(rows)


def _sweep_values(results: Results, spec: dict) -> list[dict]:
    return [sailing_values(r) for r in results.records(f"sweeps/{spec['name']}")]


def first_pass(results: Results, smoke: bool) -> dict:
    """Every series' table (:func:`compare`) from the first pass's runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The study's runs.
    smoke : bool
        The study's short pass.
    """
    tables = {}
    for (boat, kind), spec in sea.plane_sea_specs(smoke).items():
        if kind == "sea":
            z = spec["zip"]
            keys = [{"case": f"{u:g} m/s, {a:g}°", "boat": boat, "tws": u, "twa": a, "hs": h, "tp": t,
                     "wave_from_deg": d, "n_components": spec["options"]["waves.n_components"]}
                    for u, a, h, t, d in
                    zip(z["task.wind_speed"], z["task.wind_from_deg"], z["waves.hs"], z["waves.tp"],
                        z["waves.direction_from_deg"], strict=True)]
            calm = _sweep_values(results, sea.plane_sea_specs(smoke)[(boat, "calm")])
            tables[boat] = compare(keys, calm, _sweep_values(results, spec), SAILING)
    saoud = sea.saoud_sea_specs(smoke)
    z, options = saoud["sea"]["zip"], saoud["sea"]["options"]
    keys = [{"case": f"Hs {h:g} m", "hs": h, "tp": t, "wave_from_deg": options["waves.direction_from_deg"],
             "n_components": options["waves.n_components"]}
            for h, t in zip(z["waves.hs"], z["waves.tp"], strict=True)]
    calm = _sweep_values(results, saoud["calm"]) * len(keys)
    tables["saoud"] = compare(keys, calm, _sweep_values(results, saoud["sea"]), SAILING)
    calm_numbers = dict(zip(table1_jobs(smoke), results.jobs[RUNS_JOB][len(PART_NAMES):], strict=True))
    jobs = sea.table1_sea_jobs(smoke)
    keys = [{"case": f"{j['sim']}, Hs {j['hs']:g} m", "sim": j["sim"], "hs": j["hs"],
             "tp": j["run"]["env"]["waves"]["tp"], "wave_from_deg": j["run"]["env"]["waves"]["direction_from_deg"],
             "n_components": j["run"]["env"]["waves"]["n_components"]}
            for j in jobs]
    calm = [table1_values(calm_numbers[("dsyhs", j["sim"])]) for j in jobs]
    tables["table1"] = compare(keys, calm, [table1_values(n) for n in results.jobs[sea.SEA_JOB]], TABLE1)
    return tables


def largest_cases(tables: dict, smoke: bool) -> list[tuple[str, str, int]]:
    """(series, metric, case index) of every series and metric whose difference goes beyond
    ``DIFFERENCE``: the case where it is largest. Smoke: only the largest of all.

    Parameters
    ----------
    tables : dict
        Series -> its table (:func:`first_pass`).
    smoke : bool
        The study's short pass.
    """
    out = []
    for series, table in tables.items():
        for metric in metrics_of(series):
            rel = table[f"{metric}_rel"].abs().to_numpy(dtype=float)
            rel = np.where(np.isfinite(rel), rel, -1.0)
            if rel.size and rel.max() > DIFFERENCE:
                out.append((series, metric, int(np.argmax(rel)), float(rel.max())))
    if smoke and out:
        out = [max(out, key=lambda item: item[3])]
    return [item[:3] for item in out]


def _cases_by_series(selected: list) -> dict:
    out = {}
    for series, _, case in selected:
        out.setdefault(series, [])
        if case not in out[series]:
            out[series].append(case)
    return out


def _mechanism_sources(smoke: bool) -> dict:
    """Series -> the sea spec its cases come from (the sweep series)."""
    specs = sea.plane_sea_specs(smoke)
    return {"saoud_robot": specs[("saoud_robot", "sea")], "wille_yacht": specs[("wille_yacht", "sea")],
            "saoud": sea.saoud_sea_specs(smoke)["sea"]}


def mechanism_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: each largest case (:func:`largest_cases`) with each mechanism off in turn.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass's runs.
    smoke : bool
        The study's short pass.
    """
    by_series = _cases_by_series(largest_cases(first_pass(results, smoke), smoke))
    sources = _mechanism_sources(smoke)
    sweeps = tuple((spec, f"sweeps/{spec['name']}") for spec in
                   (sea.mechanism_spec(sources[s], cases) for s, cases in by_series.items() if s in sources))
    jobs = {}
    if "table1" in by_series:
        jobs[sea.MECHANISM_JOB] = (f"{__package__}.sea:table1_sea_run",
                                   sea.mechanism_jobs(sea.table1_sea_jobs(smoke), by_series["table1"]))
    return Runs(sweeps=sweeps, jobs=jobs, label="the sea's mechanisms")


def attribute(calm: float, sea_value: float, switched: dict, share: float = EXPLAINS):
    """Which mechanism a difference comes from: ``(name or None, {name: share removed})``.

    The share a switch removes is 1 - (switched - calm)/(sea - calm) (1: the switch brings
    the metric back to calm; 0: it changes nothing; negative: it makes the difference larger).
    The name is the switch that removes the most, when that is at least ``share``; None when no
    single switch removes that much.

    Parameters
    ----------
    calm : float
        The metric in calm water.
    sea_value : float
        The metric in the sea, every mechanism on.
    switched : dict
        Mechanism -> the metric in the sea with that mechanism off.
    share : float
        The least share of the difference a switch must remove to explain it.
    """
    difference = sea_value - calm
    removed = {name: (1.0 - (value - calm) / difference
                      if difference != 0.0 and math.isfinite(value) else float("nan"))
               for name, value in switched.items()}
    finite = {name: value for name, value in removed.items() if math.isfinite(value)}
    if not finite:
        return None, removed
    best = max(finite, key=finite.get)
    return (best if finite[best] >= share else None), removed


def _switched_values(results: Results, series: str, cases: list, smoke: bool) -> dict:
    """(case, mechanism) -> the case's values with that mechanism off."""
    if series == "table1":
        values = [table1_values(n) for n in results.jobs.get(sea.MECHANISM_JOB, [])]
    else:
        spec = sea.mechanism_spec(_mechanism_sources(smoke)[series], cases)
        values = _sweep_values(results, spec)
    names = [name for name, _ in sea.MECHANISMS]
    return {(case, name): values[i * len(names) + j] for i, case in enumerate(cases)
            for j, name in enumerate(names)}


def attribution(results: Results, tables: dict, smoke: bool) -> pd.DataFrame:
    """The mechanisms' table: for each series and metric beyond ``DIFFERENCE``, its largest
    case, the metric with each mechanism off, the share each removes and the one named.

    Parameters
    ----------
    results : sailmujoco.study.Results
        Both passes' runs.
    tables : dict
        Series -> its table (:func:`first_pass`).
    smoke : bool
        The study's short pass.
    """
    selected = largest_cases(tables, smoke)
    by_series = _cases_by_series(selected)
    switched = {s: _switched_values(results, s, cases, smoke) for s, cases in by_series.items()}
    rows = []
    for series, metric, case in selected:
        row_in = tables[series].iloc[case]
        calm, sea_value = float(row_in[f"{metric}_calm"]), float(row_in[f"{metric}_sea"])
        values = {name: float(switched[series][(case, name)][metric]) for name, _ in sea.MECHANISMS}
        named, removed = attribute(calm, sea_value, values)
        label, unit, _ = metrics_of(series)[metric]
        row = {"series": SERIES[series], "case": row_in["case"], "metric": label, "unit": unit,
               "status": row_in["status"], "calm": calm, "sea": sea_value,
               "change": sea_value - calm, "rel": float(row_in[f"{metric}_rel"])}
        for name, _ in sea.MECHANISMS:
            row[f"{name}_off"] = values[name]
            row[f"{name}_removed"] = removed[name]
        row["mechanism"] = named or ""
        rows.append(row)
    return pd.DataFrame(rows)


def analyse_sea(results: Results, smoke: bool) -> SeaAnalysis:
    """What a sea does to the boats, from both passes' runs.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The study's runs (the second pass's included).
    smoke : bool
        The study's short pass.
    """
    tables = first_pass(results, smoke)
    return SeaAnalysis(tables, attribution(results, tables, smoke))
