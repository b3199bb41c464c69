"""Assumption validation, the analysis: the wind plane as one table, each switch's effect point by
point and seed by seed, the single scenarios over their seeds and the restoring errors; the
headline numbers read off them are :mod:`.headline_numbers`.

Every stochastic number is a mean over seeds with its 95 % interval (:mod:`studies.kit.seeds`).
A comparison of the boat as built (6-DOF) with a paper's simplification is made seed by seed: at
each point the per-seed difference of the two arms, relative to the paper's arm
(:func:`relative`), and its interval; a point's verdict is that interval against the tolerance
(:func:`point_verdicts`), an assumption's the tally of its points' (:func:`tally`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.forces import stability
from sailmujoco.study import Results

from ..kit import seeds as over
from .episodes import time_constants
from .fitted import FITTED_JOB
from .fitted_analysis import FittedAnalysis, analyse_fitted
from .scenario import (
    BOATS,
    CONFIGS,
    HEEL_HOLDS_DEG,
    PAPER_ARM,
    PART_NAMES,
    ROBOT_ONLY,
    RUNS_JOB,
    SPEED_FLOOR,
    SPEED_HOLDS,
    part_seeds,
    plane_specs,
)
from .sea_analysis import SeaAnalysis, analyse_sea

POINT = ["tws", "twa"]  # the columns that name a point of the wind plane
KEEL_AOA_LINEAR_DEG = 10.0  # deg: Wille's lift is linear below this keel angle of attack
PHI_STAR_HOLDS_DEG = 2.0  # deg: phi* is "the heel reached" within this
LATERAL_HOLDS = 0.05  # m/s: the 6-DOF lateral speed within this of the 3-DOF model's


@dataclass(frozen=True, eq=False)
class Analysis:
    """The study's numbers.

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane: one row per boat, config, true wind speed (``tws``), angle (``twa``)
        and seed.
    effects : dict
        ``(boat, config) -> ``:func:`paired_effects`'s per-seed table, for every switch.
    points : dict
        ``(boat, config) -> ``:func:`effect_points`'s table: one row per point, the
        differences' means, intervals and verdicts.
    plane : dict
        ``boat -> ``:func:`baseline_points`'s table: the as-built boat's metrics over seeds.
    time_constants : dict
        Boat -> roll period, yaw time constant, roll natural frequency, I_xx.
    course : pandas.DataFrame
        Wille's correction β_b against the drift sailed, the course error, the largest heel:
        one row per seed.
    steady : pandas.DataFrame
        Saoud's φ* against the steady heel, per wind, angle, l_φ and seed.
    drift : pandas.DataFrame
        Mean and largest |lateral speed| in position keeping, 3-DOF (``paper``) and 6-DOF
        (``mujoco``): one row per seed.
    table1 : dict
        ``(resistance, sim) ->`` the numbers of a Wille Table 1 run (``table1_seeds``' first).
    restoring : dict
        Boat -> the heel reached and the largest errors of eq. 20 and eq. 66.
    seeds : tuple
        The study's seeds.
    plane_seeds, single_seeds, table1_seeds : tuple
        The seeds the wind plane, the single scenarios and Table 1 ran on.
    sea : studies.assumptions.sea_analysis.SeaAnalysis or None
        What a sea does to the boats (None: not analysed).
    fitted : studies.assumptions.fitted_analysis.FittedAnalysis or None
        What sensors and actuators as fitted do to each paper's controller (None: not run).
    """

    data: pd.DataFrame
    effects: dict
    points: dict
    plane: dict
    time_constants: dict
    course: pd.DataFrame
    steady: pd.DataFrame
    drift: pd.DataFrame
    table1: dict
    restoring: dict
    seeds: tuple = (0,)
    plane_seeds: tuple = (0,)
    single_seeds: tuple = (0,)
    table1_seeds: tuple = (0,)
    sea: SeaAnalysis | None = None
    fitted: FittedAnalysis | None = None


def plane_table(specs: dict, tables: list) -> pd.DataFrame:
    """The wind-plane sweeps' tables as one, with the boat and config of each row.

    Parameters
    ----------
    specs : dict
        ``(boat, config) -> spec`` (:func:`.scenario.plane_specs`).
    tables : list of pandas.DataFrame
        Each sweep's table, in the order of ``specs``.
    """
    frames_ = []
    for (boat, config), table in zip(specs, tables, strict=True):
        table = table.rename(columns={"task.wind_speed": "tws", "task.wind_from_deg": "twa"})
        table["boat"], table["config"] = boat, config
        frames_.append(table)
    return pd.concat(frames_, ignore_index=True)


def switches(boat: str) -> list[str]:
    """The configs compared with the boat as built on ``boat``.

    Parameters
    ----------
    boat : str
        A boat of ``BOATS``.
    """
    return [c for c in CONFIGS if c != "baseline" and (boat == "saoud_robot" or c not in ROBOT_ONLY)]


def relative(ours, paper) -> np.ndarray:
    """(ours - paper) / max(|paper|, SPEED_FLOOR), value by value: a speed difference relative to
    the paper's arm, in m/s over the floor where the paper's boat is (nearly) stalled.

    Parameters
    ----------
    ours, paper : array_like
        The two arms' steady speeds, m/s.
    """
    ours, paper = np.asarray(ours, dtype=float), np.asarray(paper, dtype=float)
    return (ours - paper) / np.maximum(np.abs(paper), SPEED_FLOOR)


def paired_effects(data: pd.DataFrame, boat: str, config: str) -> pd.DataFrame:
    """Seed by seed at each point both arms run: the steady speed and heel of the boat as built
    (``_6dof``) and of the paper's simplification (``_paper``, ``PAPER_ARM``), the speed
    difference relative to the paper's arm (:func:`relative`) and the heel difference in deg.
    These rows are ``effects.csv``.

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    boat, config : str
        Which boat, and the switch.
    """
    keys, cols = [*POINT, "seed"], ["steady_speed", "steady_heel"]
    paper = PAPER_ARM[config]
    ours = config if paper == "baseline" else "baseline"
    sel = data[data["boat"] == boat]
    a, b = sel[sel["config"] == ours][keys + cols], sel[sel["config"] == paper][keys + cols]
    m = a.merge(b, on=keys, suffixes=("_6dof", "_paper")).sort_values(keys).reset_index(drop=True)
    m.insert(0, "config", config)
    m.insert(0, "boat", boat)
    m["speed_rel"] = relative(m["steady_speed_6dof"], m["steady_speed_paper"])
    m["heel_diff_deg"] = np.degrees(m["steady_heel_6dof"] - m["steady_heel_paper"])
    return m


def speed_verdict(config: str, got) -> str:
    """A point's verdict on the speed: the interval of the relative difference within
    ±``SPEED_HOLDS`` of 0; for the sheeted sail a loss below ``SPEED_HOLDS`` (one-sided: a
    sheeted sail that sails faster keeps the actuated sail's claim).

    Parameters
    ----------
    config : str
        The switch.
    got : sailmujoco.stats.Interval
        The point's relative speed difference over seeds.
    """
    if config == "sheeted":
        return over.decide(got, -SPEED_HOLDS, "above")
    return over.decide(got, 0.0, "within", band=SPEED_HOLDS)


def effect_points(effects: pd.DataFrame, config: str) -> pd.DataFrame:
    """One row per point: the speed and heel differences' means and intervals over seeds
    (:func:`studies.kit.seeds.over_seeds`) and each point's verdicts (``speed_verdict``,
    ``heel_verdict``: within ±``HEEL_HOLDS_DEG``).

    Parameters
    ----------
    effects : pandas.DataFrame
        :func:`paired_effects`'s rows.
    config : str
        The switch.
    """
    columns = ["speed_rel", "heel_diff_deg", "steady_speed_6dof", "steady_speed_paper"]
    pts = over.over_seeds(effects, POINT, columns)
    pts["speed_verdict"] = [speed_verdict(config, over.row_interval(r, "speed_rel")) for _, r in pts.iterrows()]
    pts["heel_verdict"] = [over.decide(over.row_interval(r, "heel_diff_deg"), 0.0, "within", band=HEEL_HOLDS_DEG)
                           for _, r in pts.iterrows()]
    return pts


BASELINE_METRICS = ["ct_cn_ratio", "pitch_amplitude_deg", "heave_amplitude_cm", "omega3_ratio",
                    "roll_share_keel", "roll_share_others", "keel_aoa_deg", "drift_angle_deg",
                    "steady_speed", "steady_heel_deg", "mean_pitch_deg"]


def baseline_points(data: pd.DataFrame, boat: str) -> pd.DataFrame:
    """The as-built boat's metrics at each point over its seeds (means, intervals, ``n``), in
    the units the report prints (deg, cm; the roll shares as fractions; ``roll_share_others``:
    keel + rudder + hull damping + added mass).

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    boat : str
        Which boat.
    """
    b = data[(data["boat"] == boat) & (data["config"] == "baseline")].copy()
    b["pitch_amplitude_deg"] = np.degrees(b["pitch_amplitude"])
    b["heave_amplitude_cm"] = 100 * b["heave_amplitude"]
    b["roll_share_others"] = (b["roll_share_keel"] + b["roll_share_rudder"] + b["roll_share_damping"]
                              + b["roll_share_added_mass"])
    b["keel_aoa_deg"] = np.degrees(np.abs(b["keel_aoa"]))
    b["drift_angle_deg"] = np.degrees(b["drift_angle"])
    b["steady_heel_deg"] = np.degrees(b["steady_heel"])
    b["mean_pitch_deg"] = np.degrees(b["mean_pitch"])
    out = over.over_seeds(b, POINT, BASELINE_METRICS)
    out.insert(0, "boat", boat)
    return out


def restoring_errors(data: pd.DataFrame) -> dict:
    """Geometric righting moment against eq. 20 and its linearisation (eq. 66) over the heel
    range the boats reached in the wind plane (the largest |steady heel| of any run).

    Parameters
    ----------
    data : pandas.DataFrame
        The wind plane (:func:`plane_table`).
    """
    out = {}
    for boat in BOATS:
        p = get_boat(boat)
        reached = float(np.nanmax(np.abs(data[(data["boat"] == boat)]["steady_heel"])))
        reached = max(reached, math.radians(5.0))
        heels = np.linspace(math.radians(1.0), reached, 12)
        curve = stability.righting_curve(p, heels)
        phi_w = math.radians(10.0)
        k = p.rho_water * 9.81 * p.displaced_volume * p.gm_t
        linear = k * (1 - 2 * math.sin(phi_w) ** 2) * (heels - phi_w) + k * math.cos(phi_w) * math.sin(phi_w)
        geometric = curve["geometric"]
        model = curve["sin"] if p.paper_righting == "sin" else curve["sin_cos"]
        out[boat] = {"heel_reached_deg": math.degrees(reached),
                     "paper_formula_error": float(np.max(np.abs(model - geometric) / np.abs(geometric))),
                     "eq66_error": float(np.max(np.abs(linear - geometric) / np.abs(geometric)))}
    return out


def analyse(results: Results, smoke: bool) -> Analysis:
    """The study's numbers from its runs (and the time constants, run here).

    Parameters
    ----------
    results : sailmujoco.study.Results
        The runs of :func:`.scenario.runs` (and the sea's).
    smoke : bool
        The study's short pass.
    """
    seeds = tuple(int(s) for s in results.seeds)
    plane_seeds, single_seeds = part_seeds(seeds, "plane"), part_seeds(seeds, "single")
    table1_seeds = part_seeds(seeds, "table1")
    specs = plane_specs(smoke, plane_seeds)
    data = plane_table(specs, [results.sweeps[f"sweeps/{spec['name']}"] for spec in specs.values()])
    tc = time_constants()
    single = results.jobs[RUNS_JOB]
    n = len(single_seeds)
    parts = {name: single[i * n:(i + 1) * n] for i, name in enumerate(PART_NAMES)}
    course = pd.DataFrame([{"seed": s, **r} for s, r in zip(single_seeds, parts["course"], strict=True)])
    steady = pd.concat(parts["steady"], ignore_index=True)
    steady = steady[steady["seed"].isin(single_seeds)].reset_index(drop=True)
    drift = pd.DataFrame([{"seed": s, **r} for s, r in zip(single_seeds, parts["drift"], strict=True)])
    first = single[len(PART_NAMES) * n:len(PART_NAMES) * n + 6]  # Table 1 on its first seed
    keys = [(r, s) for r in ("dsyhs", "friction") for s in ("sim1", "sim2", "sim3")]
    table1 = dict(zip(keys, first, strict=True))
    effects = {(b, c): paired_effects(data, b, c) for b in BOATS for c in switches(b)}
    points = {key: effect_points(table, key[1]) for key, table in effects.items()}
    plane = {b: baseline_points(data, b) for b in BOATS}
    fitted = analyse_fitted(results, smoke) if FITTED_JOB in results.jobs else None
    return Analysis(data, effects, points, plane, tc, course, steady, drift, table1, restoring_errors(data),
                    seeds, plane_seeds, single_seeds, table1_seeds, analyse_sea(results, smoke), fitted)


def tally(verdicts, n_seeds: int, unit: str = "points") -> tuple[str, str]:
    """An assumption's verdict from its points' (each *holds*, *breaks* or *undecided at N
    seeds*): *breaks* where any point breaks, *holds* where every point holds, *undecided at N
    seeds* otherwise; and the count, e.g. ``"2 of 24 points break, 3 undecided"``.

    Parameters
    ----------
    verdicts : sequence of str
        The points' verdicts.
    n_seeds : int
        The seeds the points ran on (for the undecided verdict's text).
    unit : str
        What a point is called.
    """
    verdicts = list(verdicts)
    broke = sum(v == "breaks" for v in verdicts)
    held = sum(v == "holds" for v in verdicts)
    open_ = len(verdicts) - broke - held
    if not verdicts:
        return f"undecided at {n_seeds} seeds", f"no {unit}"
    word = "breaks" if broke else "holds" if held == len(verdicts) else f"undecided at {n_seeds} seeds"
    if word == "holds":
        return word, f"{held} of {len(verdicts)} {unit} hold"
    parts = [f"{broke} of {len(verdicts)} {unit} break"]
    if open_:
        parts.append(f"{open_} undecided")
    return word, ", ".join(parts)


def combined(verdicts: list[str], n_seeds: int) -> str:
    """Several criteria's verdicts as one: *breaks* if any breaks, *holds* if all hold,
    *undecided at N seeds* otherwise.

    Parameters
    ----------
    verdicts : list of str
        Each criterion's verdict.
    n_seeds : int
        The seeds the least-seeded criterion ran on.
    """
    if any(v == "breaks" for v in verdicts):
        return "breaks"
    if verdicts and all(v == "holds" for v in verdicts):
        return "holds"
    return f"undecided at {n_seeds} seeds"


def point_intervals(points: pd.DataFrame, column: str) -> list:
    """The intervals of ``column`` at each point of a table of points.

    Parameters
    ----------
    points : pandas.DataFrame
        A table of :func:`effect_points` or :func:`baseline_points`.
    column : str
        The number.
    """
    return [over.row_interval(r, column) for _, r in points.iterrows()]


def judge_points(points: pd.DataFrame, column: str, bound: float, sense: str = "below",
                 band: float | None = None) -> list[str]:
    """Each point's verdict on ``column`` against ``bound`` (:func:`studies.kit.seeds.decide`).

    Parameters
    ----------
    points : pandas.DataFrame
        A table of points.
    column : str
        The number.
    bound : float
        The bound (or the centre of the band for ``"within"``).
    sense : {"below", "above", "within"}
        What the claim requires.
    band : float, optional
        The band's half-width.
    """
    return [over.decide(i, bound, sense, band=band) for i in point_intervals(points, column)]
