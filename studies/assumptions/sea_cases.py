"""Assumption validation, the sea's cases: each series in a sea against calm water, metric by
metric and seed by seed.

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

A run's values (:func:`sailing_values`, :func:`table1_values`), the rows of a series one per
case and seed (:func:`compare`, :func:`first_pass`), its cases over their seeds
(:func:`summarise`, :func:`summaries`) and the cases with a seed that lost its heading
(:func:`lost_cases`).
"""

from __future__ import annotations

import math

import pandas as pd

from sailmujoco import stats
from sailmujoco.study import Results
from sailmujoco.suite import TASKS

from ..kit import seeds as kit_seeds
from ..kit.verdict import TOLERANCE
from . import sea
from .scenario import HEEL_HOLDS_DEG, SPEED_FLOOR

DIFFERENCE = TOLERANCE  # -, a sea changes a metric where |sea - calm| > 10 % of max(|calm|, floor)
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



def put_interval(row: dict, name: str, got: stats.Interval) -> None:
    """Put an interval into a row: ``name`` (its mean), ``name_low`` and ``name_high``.

    Parameters
    ----------
    row : dict
        The row, changed in place.
    name : str
        The column of the mean.
    got : sailmujoco.stats.Interval
        The interval.
    """
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
            put_interval(row, column, kit_seeds.interval(group[column]))
        for name in metrics:
            put_interval(row, f"{name}_calm", kit_seeds.interval(kept[f"{name}_calm"]))
            put_interval(row, f"{name}_sea", kit_seeds.interval(kept[f"{name}_sea"]))
            put_interval(row, f"{name}_change", kit_seeds.paired(kept[f"{name}_sea"], kept[f"{name}_calm"]))
            rel = kit_seeds.interval(kept[f"{name}_rel"])
            put_interval(row, f"{name}_rel", rel)
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



def sweep_values(results: Results, spec: dict) -> list[dict]:
    """Every run of a sweep's values (:func:`sailing_values`), in the sweep's order.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The study's runs.
    spec : dict
        The sweep's spec (its ``name`` names its folder).
    """
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
            calm = sweep_values(results, specs[(boat, "calm")])
            tables[boat] = compare(_seeded(keys, seeds), [c for c in calm for _ in seeds],
                                   sweep_values(results, spec), SAILING)
    saoud = sea.saoud_sea_specs(smoke, seeds)
    z, options = saoud["sea"]["zip"], saoud["sea"]["options"]
    keys = [{"case": f"Hs {h:g} m", "hs": h, "tp": t, "wave_from_deg": options["waves.direction_from_deg"],
             "n_components": options["waves.n_components"]}
            for h, t in zip(z["waves.hs"][::n], z["waves.tp"][::n], strict=True)]
    calm = sweep_values(results, saoud["calm"]) * (len(keys) * n)
    tables["saoud"] = compare(_seeded(keys, seeds), calm, sweep_values(results, saoud["sea"]), SAILING)
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



def verdict_kind(verdict: str) -> str:
    """A verdict's kind: "breaks", "holds" or "undecided" (*undecided at N seeds*).

    Parameters
    ----------
    verdict : str
        A case's verdict (:func:`summarise`).
    """
    return "undecided" if verdict.startswith("undecided") else verdict
