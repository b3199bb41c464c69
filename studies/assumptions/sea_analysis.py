"""Assumption validation, the sea's analysis: each series in a sea against calm water, metric by
metric, and what each difference beyond ``DIFFERENCE`` comes from.

A difference is relative to the calm value or, where that is smaller than the metric's floor
(the boat as good as upright, still or level), to the floor: (sea - calm) / max(|calm|, floor).
The roll of a run is the heel's standard deviation over its window (in a random sea the
peak-to-peak is an extreme value that grows with the window). A run whose heading error RMS
over the window exceeds ``HEADING_LOST_DEG`` has lost its heading (it turned head to wind and
stalled, or bore away): its case's difference is not the sea's effect on a boat that holds its
course, and the attribution leaves it out. For every series and metric whose difference goes
beyond ``DIFFERENCE`` in a case where both runs keep their heading, the case where it is
largest is rerun with each of the sea's mechanisms off in turn (:data:`.sea.MECHANISMS`): the
share of the difference a switch removes is 1 - (switched - calm)/(sea - calm). The sea reaches
the boat by two paths, the hull and the foils (:data:`.sea.PATHS`; both off, the calm boat to
the bit): the path whose switch removes at least ``EXPLAINS`` of the difference, the more of
the two, is the one it takes, and the refinement of the hull's path whose switch removes at
least that much, the most, the part of the hull's physics it comes from (:func:`attribute`).
A switched run that loses its heading is reported as stalled.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco import constants
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.design.check import natural_periods
from sailmujoco.forces.wave_spectra import pierson_moskowitz
from sailmujoco.forces.waves import components
from sailmujoco.options import WaveConfig
from sailmujoco.study import Results, Runs
from sailmujoco.suite import TASKS

from . import sea
from .scenario import HEEL_HOLDS_DEG, SPEED_FLOOR

DIFFERENCE = 0.10  # -, a sea changes a metric where |sea - calm| > 10 % of max(|calm|, floor)
EXPLAINS = 0.5  # -, a switch explains a difference when it removes at least half of it
ANGLE_FLOOR_DEG = 1.0  # deg, the floor of the angles' differences (roll, drift, pitch)
HEADING_LOST_DEG = 10.0  # deg, a run whose heading error RMS over its window exceeds it lost its heading
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


@dataclass(frozen=True, eq=False)
class SeaAnalysis:
    """What a sea does to the boats.

    Parameters
    ----------
    tables : dict
        Series (a key of ``SERIES``) -> one row per case: its sea, status, the reason it
        stopped, per metric ``<m>_calm``, ``<m>_sea``, ``<m>_change`` (sea - calm) and
        ``<m>_rel`` (the change over max(|calm|, floor)), the heading error RMS
        ``heading_rms_calm``, ``heading_rms_sea`` (deg), the heel's period in the sea
        ``roll_period_sea`` (s) and ``lost_heading`` (the runs that lost it: "", "calm",
        "sea" or "calm, sea").
    mechanisms : pandas.DataFrame
        One row per series and metric beyond ``DIFFERENCE``: its largest case, the value with
        each mechanism off, the share each switch removes (NaN where the switched run
        stalled, ``<mechanism>_stalled``), the path named and the hull's refinement named
        (:func:`attribution`).
    resonance : dict
        :func:`roll_resonance`: each boat's roll period and the seas' slopes.
    """

    tables: dict
    mechanisms: pd.DataFrame
    resonance: dict


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
    """One row per case: its keys, the sea run's status, each metric calm, in a sea, the change
    and the relative change, the heading error RMS of both runs and which lost its heading.

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
    calm_numbers = {j["sim"]: n for j, n in zip(sea.table1_calm_jobs(smoke), results.jobs[sea.CALM_JOB],
                                                 strict=True)}
    jobs = sea.table1_sea_jobs(smoke)
    keys = [{"case": f"{j['sim']}, Hs {j['hs']:g} m", "sim": j["sim"], "hs": j["hs"],
             "tp": j["run"]["env"]["waves"]["tp"], "wave_from_deg": j["run"]["env"]["waves"]["direction_from_deg"],
             "n_components": j["run"]["env"]["waves"]["n_components"]}
            for j in jobs]
    calm = [table1_values(calm_numbers[j["sim"]]) for j in jobs]
    tables["table1"] = compare(keys, calm, [table1_values(n) for n in results.jobs[sea.SEA_JOB]], TABLE1)
    return tables


def _kept_differences(table: pd.DataFrame, metric: str) -> np.ndarray:
    """|relative change| of ``metric`` per case, -1 where it is not finite or a run lost its
    heading."""
    rel = table[f"{metric}_rel"].abs().to_numpy(dtype=float)
    kept = table["lost_heading"].eq("").to_numpy() if "lost_heading" in table else True
    return np.where(np.isfinite(rel) & kept, rel, -1.0)


def largest_cases(tables: dict, smoke: bool) -> list[tuple[str, str, int]]:
    """(series, metric, case index) of every series and metric whose difference goes beyond
    ``DIFFERENCE`` in a case where calm and sea runs keep their heading: the case where it is
    largest. Smoke: only the largest of all.

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
            rel = _kept_differences(table, metric)
            if rel.size and rel.max() > DIFFERENCE:
                out.append((series, metric, int(np.argmax(rel)), float(rel.max())))
    if smoke and out:
        out = [max(out, key=lambda item: item[3])]
    return [item[:3] for item in out]


def differing_cases(tables: dict, smoke: bool) -> list[tuple[str, str, int]]:
    """(series, metric, case index) of every difference beyond ``DIFFERENCE`` in a case where
    calm and sea runs keep their heading, series by series, metric by metric. Smoke: the
    largest of all only (:func:`largest_cases`).

    Parameters
    ----------
    tables : dict
        Series -> its table (:func:`first_pass`).
    smoke : bool
        The study's short pass.
    """
    if smoke:
        return largest_cases(tables, smoke)
    return [(series, metric, int(case)) for series, table in tables.items() for metric in metrics_of(series)
            for case in np.flatnonzero(_kept_differences(table, metric) > DIFFERENCE)]


def _cases_by_series(selected: list) -> dict:
    """Series -> its cases of ``selected``, each once, in ascending order."""
    out = {}
    for series, _, case in selected:
        out.setdefault(series, set()).add(case)
    return {series: sorted(cases) for series, cases in out.items()}


def _mechanism_sources(smoke: bool) -> dict:
    """Series -> the sea spec its cases come from (the sweep series)."""
    specs = sea.plane_sea_specs(smoke)
    return {"saoud_robot": specs[("saoud_robot", "sea")], "wille_yacht": specs[("wille_yacht", "sea")],
            "saoud": sea.saoud_sea_specs(smoke)["sea"]}


def mechanism_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: each case with a difference (:func:`differing_cases`) with each
    mechanism off in turn.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass's runs.
    smoke : bool
        The study's short pass.
    """
    by_series = _cases_by_series(differing_cases(first_pass(results, smoke), smoke))
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


def lost_cases(tables: dict) -> pd.DataFrame:
    """The cases whose calm or sea run lost its heading (left out of the attribution): series,
    case, which runs, their heading error RMS (deg) and steady speed or mean surge (m/s).

    Parameters
    ----------
    tables : dict
        Series -> its table (:func:`first_pass`).
    """
    rows = []
    for series, table in tables.items():
        speed = "surge" if series == "table1" else "speed"
        for _, row in table[table["lost_heading"] != ""].iterrows():
            rows.append({"series": SERIES[series], "case": row["case"], "lost": row["lost_heading"],
                         "heading_rms_calm": row["heading_rms_calm"], "heading_rms_sea": row["heading_rms_sea"],
                         "speed_calm": row[f"{speed}_calm"], "speed_sea": row[f"{speed}_sea"]})
    return pd.DataFrame(rows, columns=["series", "case", "lost", "heading_rms_calm", "heading_rms_sea",
                                       "speed_calm", "speed_sea"])


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


def _path_alone(removed: dict, stalled: dict) -> str | None:
    """The path whose switched rerun lost its heading, where the other path's switch removes at
    most 1 - ``EXPLAINS`` of the difference: with both paths off the boat is the calm boat, so
    the stalled one alone makes at least ``EXPLAINS`` of it. None otherwise."""
    lost = [name for name in sea.PATHS if stalled[name]]
    if len(lost) != 1:
        return None
    other = next(name for name in sea.PATHS if name != lost[0])
    return lost[0] if math.isfinite(removed[other]) and removed[other] <= 1.0 - EXPLAINS else None


def attribution(results: Results, tables: dict, smoke: bool) -> pd.DataFrame:
    """The mechanisms' table: each difference beyond ``DIFFERENCE`` (:func:`differing_cases`;
    ``largest``: the largest of its series and metric), the metric with each mechanism off, the share each removes (NaN where the switched
    run lost its heading: ``<mechanism>_stalled``), the path it takes (``mechanism``: the one of
    :data:`.sea.PATHS` that :func:`attribute` names or, where one path's rerun lost its heading,
    :func:`_path_alone`; ``path_alone`` then) and the refinement of the hull's path
    that explains it (``refinement``: :func:`attribute` over the other switches), each "" when
    none does.

    Parameters
    ----------
    results : sailmujoco.study.Results
        Both passes' runs.
    tables : dict
        Series -> its table (:func:`first_pass`).
    smoke : bool
        The study's short pass.
    """
    selected = differing_cases(tables, smoke)
    largest = set(largest_cases(tables, smoke))
    by_series = _cases_by_series(selected)
    switched = {s: _switched_values(results, s, cases, smoke) for s, cases in by_series.items()}
    rows = []
    for series, metric, case in selected:
        row_in = tables[series].iloc[case]
        calm, sea_value = float(row_in[f"{metric}_calm"]), float(row_in[f"{metric}_sea"])
        runs = {name: switched[series][(case, name)] for name, _ in sea.MECHANISMS}
        values = {name: float(run[metric]) for name, run in runs.items()}
        stalled = {name: lost_heading(run) for name, run in runs.items()}
        kept = {n: (math.nan if stalled[n] else v) for n, v in values.items()}
        path, removed = attribute(calm, sea_value, {n: kept[n] for n in sea.PATHS})
        path, alone = path or _path_alone(removed, stalled), not path
        refinement, finer = attribute(calm, sea_value, {n: v for n, v in kept.items() if n not in sea.PATHS})
        removed.update(finer)
        label, unit, _ = metrics_of(series)[metric]
        row = {"series": SERIES[series], "case": row_in["case"], "metric": label, "unit": unit,
               "status": row_in["status"], "calm": calm, "sea": sea_value,
               "change": sea_value - calm, "rel": float(row_in[f"{metric}_rel"]),
               "largest": (series, metric, case) in largest}
        for name, _ in sea.MECHANISMS:
            row[f"{name}_off"] = values[name]
            row[f"{name}_removed"] = removed[name]
            row[f"{name}_stalled"] = stalled[name]
        row["mechanism"], row["refinement"] = path or "", refinement or ""
        row["path_alone"] = bool(path) and alone
        rows.append(row)
    return pd.DataFrame(rows)


def roll_resonance(n_components: int) -> dict:
    """Why a sea rolls the boats: each boat's roll period and the waves it meets, and the
    fully developed seas ``SEA_HS``' slopes.

    ``boats``: one row per boat, ``t4`` (the roll period with sway free, :func:`sailmujoco.design.check.natural_periods`, s), ``wavelength``
    (deep-water waves of that period, g T4^2/(2 pi), m), ``length`` (the hull's, m).
    ``seas``: one row per Hs of :data:`.sea.SEA_HS`, ``tp`` (s), ``tp_over_t4`` (the yacht's),
    ``omega4_over_omegap`` (the robot's roll frequency over the sea's peak), ``slope_density`` (the wave slope spectrum (omega^2/g)^2 S(omega) at the robot's roll
    frequency, rad^2 s) and ``rms_slope`` (the RMS slope of the sea's ``n_components``
    components, sqrt(sum (a_i k_i)^2 / 2), deg).

    Parameters
    ----------
    n_components : int
        Components of the seas, as the runs draw them (seed :data:`.sea.SEA_SEED`).
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
        comp = components(WaveConfig(spectrum="pm", hs=hs, tp=tp, n_components=n_components, seed=sea.SEA_SEED))
        rows.append({"hs": hs, "tp": tp, "tp_over_t4": tp / t4["wille_yacht"],
                     "omega4_over_omegap": omega * tp / (2.0 * math.pi),
                     "slope_density": (omega**2 / g) ** 2 * float(pierson_moskowitz(omega, hs, tp)),
                     "rms_slope": math.degrees(math.atan(math.sqrt(0.5 * float(np.sum((comp.amplitude * comp.k) ** 2)))))})
    return {"boats": boats, "seas": pd.DataFrame(rows)}


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
    return SeaAnalysis(tables, attribution(results, tables, smoke), roll_resonance(sea.SEA_COMPONENTS))
