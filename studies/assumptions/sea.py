"""Assumption validation, the sea's scenario: what a sea does to the boats, the runs as data.

The papers sail in calm water. Three series measure what a sea changes, each against the same
run in calm water:

* the wind plane (:func:`plane_sea_specs`): each boat at every point of the study's wind
  plane, in the fetch-limited JONSWAP sea that point's wind raises
  (:meth:`sailmujoco.options.WaveConfig.from_wind`) over the boat's fetch (``FETCH``),
  the waves from the wind's bearing; the calm runs are the same specs without the sea;
* Wille's roll controller (:func:`table1_sea_jobs`): Table 1's three simulations in
  fully developed Pierson-Moskowitz seas of the heights ``SEA_HS`` (:func:`developed_sea`),
  from the wind's bearing; the calm runs (:func:`table1_calm_jobs`) are the study's own Table 1
  runs again, their heel and heading kept;
* Saoud's optimal sail (:func:`saoud_sea_specs`): the robot holding its heading on a beam reach
  in Saoud's wind, in the same seas.

**Seeds.** Every case in a sea runs on each seed of the study (:attr:`sailmujoco.study.Results.seeds`):
the seed draws the sea's phases and frequencies (``waves.seed``) and, in Table 1's runs, the
gusts and the wind's wander as well (the run's own seed, the same in calm water, so each sea run
is paired with the calm run of its seed). The calm runs of the wind plane and of Saoud's sail
sail a steady wind from an exact start: deterministic, run once and paired with every seed.

A run that stops early (a capsize) is kept with its reason. Each run's roll is the standard
deviation of its heel over the measured window and its heading error the RMS over the same
window (:func:`window_statistics`). What each difference comes from is
measured by a second pass (:func:`mechanism_spec`, :func:`mechanism_jobs`): the case rerun on its
first ``MECHANISM_SEEDS`` seeds with each of the sea's two paths (``PATHS``) switched off in turn,
and the largest difference of each wind-plane series and metric with the hull's refinements
(``MECHANISMS``) off as well.
"""

from __future__ import annotations

import inspect
import math

import numpy as np

from sailmujoco import constants
from sailmujoco.options import N_COMPONENTS, PM_HS, PM_PEAK, ForceSwitches, WaveConfig
from sailmujoco.study import Runs
from sailmujoco.suite import TASKS

from ..kit.saoud import wind_speed_10
from .scenario import BOATS, plane_specs, table1_jobs
from .scenario import runs as scenario_runs

FETCH = {"saoud_robot": 2_000.0, "wille_yacht": 20_000.0}  # m, the open water upwind of each boat
FETCH_REASON = {
    "saoud_robot": "a 1.5 m robot sails on a lake: 2 km of open water upwind",
    "wille_yacht": "a cruising yacht sails along a coast: 20 km of a bay or a sound upwind",
}
SEA_COMPONENTS = N_COMPONENTS  # -, components of each sea (full study): the kernel's default
SMOKE_COMPONENTS = 4  # -, components of each sea (smoke)
SEA_SEEDS = 4  # N: the seeds a full pass of the sea runs (the study's; --seeds overrides it)
MECHANISM_SEEDS = 2  # the first seeds on which the mechanism reruns run (the budget's limit)
# the calm runs of the wind plane and of Saoud's sail: a steady wind, an exact start (deterministic)
STEADY = {"task.gusts": False, "task.wander": False, "task.heading_jitter_deg": 0.0}
SEA_HS = (0.5, 1.0, 2.0)  # m, the seas of Table 1's runs and of Saoud's optimal sail
SMOKE_HS = (1.0,)  # m, the smoke pass's one sea
SMOKE_POINT = (10.0, 60.0)  # (m/s, deg): the one wind-plane point in a sea of the smoke pass
TRAJECTORY_RATE = 10.0  # Hz: heel, pitch and heading are stored at this rate (roll, pitch, heading error)
SAOUD_WIND_FROM_DEG = 90.0  # deg, compass: a beam reach, the heading held north
SAOUD_DURATION = 90.0  # s (smoke: 25 s): longer than the plane's 50 s, a 2 m sea ramps up over 21 s
SMOKE_DURATION = 25.0  # s
TABLE1_SEA_SIMS = ("sim1", "sim2", "sim3")
SMOKE_TABLE1_SIMS = ("sim3",)
# The sea's mechanisms, each switched off in turn: (physics option, value that switches it off).
# The first two are the sea's two paths into the boat (both off: the calm boat, to the bit);
# the others refine the hull's path.
MECHANISMS = (("wave_hull", False), ("wave_foil_flow", False), ("wave_diffraction", False),
              ("wave_damping", "absolute"), ("wave_pressure_decay", False))
PATHS = ("wave_hull", "wave_foil_flow")
MECHANISM_ON = {name: getattr(ForceSwitches(), name) for name, _ in MECHANISMS}  # the sea as built
MECHANISM_NAMES = {  # what each switch takes out, in words
    "wave_hull": "the waves' forces on the hull",
    "wave_foil_flow": "the orbital flow at the keel and rudder",
    "wave_diffraction": "the hull's diffraction force",
    "wave_damping": "heave and pitch damping relative to the water",
    "wave_pressure_decay": "the wave pressure's decay with depth"}
SEA_JOB = "assumptions_sea"  # the job list of Table 1's runs in a sea
CALM_JOB = "assumptions_sea_calm"  # ... of the same runs in calm water (the heel kept)
MECHANISM_JOB = "assumptions_sea_mechanisms"  # ... and of their reruns, a mechanism off
SEA_COST = 1.4  # the cost of a simulated second in a sea against one in calm water (the budget's unit)
BUDGET = 73_437.0  # simulated seconds the sea's full pass may take, both passes together: 1.5 times
#                   one realisation of each of its 72 cases, their calm runs and 290 reruns


def developed_sea(hs: float) -> tuple[float, float]:
    """(Hs m, Tp s) of the fully developed Pierson-Moskowitz sea of height ``hs``.

    The wind that raises it: U19.5 = sqrt(g Hs/0.21) (Stewart 2008 eq. 16.33); its peak period
    Tp = 2 pi U19.5/(0.877 g) (eq. 16.30), so Tp = 4.99 sqrt(Hs) s.

    Parameters
    ----------
    hs : float
        Significant wave height, m, > 0.
    """
    u19_5 = math.sqrt(constants.GRAVITY * hs / PM_HS)
    return hs, 2.0 * math.pi * u19_5 / (PM_PEAK * constants.GRAVITY)


def wind_sea(boat: str, u10: float, n_components: int, seed: int = 0) -> WaveConfig:
    """The fetch-limited sea a 10 m wind ``u10`` raises over ``boat``'s fetch.

    Parameters
    ----------
    boat : str
        A boat of ``FETCH``.
    u10 : float
        Mean wind speed at 10 m, m/s.
    n_components : int
        Components of the sea.
    seed : int
        The sea's seed (its phases and frequencies).
    """
    return WaveConfig.from_wind(u10, "fetch_limited", FETCH[boat], n_components=n_components, seed=seed)


def _components(smoke: bool) -> int:
    return SMOKE_COMPONENTS if smoke else SEA_COMPONENTS


def _with_trajectory(spec: dict, name: str) -> dict:
    return {**spec, "name": name, "trajectory_rate": TRAJECTORY_RATE,
            "options": {**spec["options"], **STEADY}, "zip": dict(spec["zip"])}


def _over_seeds(zipped: dict, seeds) -> dict:
    """``zipped``'s rows, each once per seed (case by case, seed by seed), with ``waves.seed``."""
    n = len(zipped[next(iter(zipped))]) if zipped else 1
    out = {key: [v for v in values for _ in seeds] for key, values in zipped.items()}
    out["waves.seed"] = [int(seed) for _ in range(n) for seed in seeds]
    return out


def plane_sea_specs(smoke: bool, seeds=(0,)) -> dict:
    """The wind plane in calm water and in the sea each point's wind raises:
    ``{(boat, "calm" | "sea"): spec}``, the heel stored as a trajectory.

    Each boat's as-built spec (:func:`.scenario.plane_specs`, its wind steady and its start
    exact: ``STEADY``) with, in a sea, the zip's ``waves.hs``, ``waves.tp`` and
    ``waves.direction_from_deg`` (the wind's bearing) of :func:`wind_sea` at each point, each
    point once per seed of ``seeds`` (``waves.seed``: case by case, seed by seed). The calm
    runs are deterministic: each point once. Smoke: the point ``SMOKE_POINT`` only.

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The seeds of the seas.
    """
    specs = {}
    for boat in BOATS:
        base = plane_specs(smoke)[(boat, "baseline")]
        calm = _with_trajectory(base, f"{boat}-calm")
        calm["seeds"] = [0]
        if smoke:
            calm["zip"] = {"task.wind_speed": [SMOKE_POINT[0]], "task.wind_from_deg": [SMOKE_POINT[1]]}
        seas = [wind_sea(boat, u10, _components(smoke)) for u10 in calm["zip"]["task.wind_speed"]]
        sea = _with_trajectory(calm, f"{boat}-sea")
        sea["options"].update({"waves.spectrum": "jonswap", "waves.n_components": _components(smoke)})
        sea["zip"] = _over_seeds({**calm["zip"], "waves.hs": [w.hs for w in seas], "waves.tp": [w.tp for w in seas],
                                  "waves.direction_from_deg": list(calm["zip"]["task.wind_from_deg"])}, seeds)
        specs[(boat, "calm")], specs[(boat, "sea")] = calm, sea
    return specs


def saoud_sea_specs(smoke: bool, seeds=(0,)) -> dict:
    """Saoud's optimal sail (controller ``saoud``) on the robot, heading held north, beam reach
    in Saoud's wind (4 m/s at the sail, :func:`studies.kit.saoud.wind_speed_10`), in calm water
    (deterministic: once) and in the seas ``SEA_HS`` (each on every seed of ``seeds``):
    ``{"calm" | "sea": spec}``.

    Parameters
    ----------
    smoke : bool
        The study's short pass (one sea, 25 s).
    seeds : sequence of int
        The seeds of the seas.
    """
    duration = SMOKE_DURATION if smoke else SAOUD_DURATION
    heights = SMOKE_HS if smoke else SEA_HS
    calm = {"name": "saoud-calm", "boat": "saoud_robot", "task": "heading_hold", "world": "mujoco",
            "controller": "saoud", "duration": duration, "trajectory_rate": TRAJECTORY_RATE, "seeds": [0],
            "options": {**STEADY, "task.diagnostics": True, "task.steady_window": duration / 3,
                        "task.wind_speed": wind_speed_10(), "task.wind_from_deg": SAOUD_WIND_FROM_DEG},
            "zip": {}}
    seas = [developed_sea(hs) for hs in heights]
    sea = {**calm, "name": "saoud-sea",
           "options": {**calm["options"], "waves.spectrum": "pm", "waves.n_components": _components(smoke),
                       "waves.direction_from_deg": SAOUD_WIND_FROM_DEG},
           "zip": _over_seeds({"waves.hs": [hs for hs, _ in seas], "waves.tp": [tp for _, tp in seas]}, seeds)}
    return {"calm": calm, "sea": sea}


def table1_wind_from_deg() -> float:
    """The compass bearing Table 1's wind comes from (the ``beam_reach_roll`` task's), deg."""
    return math.degrees(TASKS["beam_reach_roll"](seed=0).wind().direction_from) % 360.0


def window_statistics(t, heel, heading_error, window: float, pitch=None) -> dict:
    """The roll, the pitch and the heading over a run's last ``window`` seconds.

    ``roll_sd``: the heel's standard deviation about its mean, deg (stable in a random sea,
    where the peak-to-peak is an extreme value that grows with the window's length);
    ``heading_rms``: the heading error's RMS, deg; ``roll_period``: the heel's mean
    zero-up-crossing period about its mean, s (NaN with fewer than two up-crossings);
    ``pitch_sd``: the pitch's standard deviation, deg, where ``pitch`` is given.

    Parameters
    ----------
    t : array_like
        Sample times, s.
    heel : array_like
        Heel at those times, rad.
    heading_error : array_like
        Heading minus the heading to hold, wrapped to [-pi, pi], rad.
    window : float
        The window's length, s.
    pitch : array_like, optional
        Pitch at those times, rad.
    """
    t, heel, error = (np.asarray(v, dtype=float) for v in (t, heel, heading_error))
    late = t >= (t[-1] if t.size else 0.0) - window
    out = {"pitch_sd": math.nan} if pitch is not None else {}
    if late.sum() < 4:
        return {"roll_sd": math.nan, "heading_rms": math.nan, "roll_period": math.nan, **out}
    if pitch is not None:
        out["pitch_sd"] = math.degrees(float(np.std(np.asarray(pitch, dtype=float)[late])))
    t, heel = t[late], heel[late] - np.mean(heel[late])
    up = t[1:][(heel[:-1] < 0.0) & (heel[1:] >= 0.0)]
    return {"roll_sd": math.degrees(float(np.std(heel))),
            "heading_rms": math.degrees(float(np.sqrt(np.mean(error[late] ** 2)))),
            "roll_period": float(np.mean(np.diff(up))) if up.size > 1 else math.nan, **out}


def table1_heading() -> float:
    """The compass heading Table 1's runs hold (the ``beam_reach_roll`` task's), rad."""
    return TASKS["beam_reach_roll"](seed=0).desired_heading


def _table1_sims(smoke: bool) -> tuple:
    return SMOKE_TABLE1_SIMS if smoke else TABLE1_SEA_SIMS


def table1_calm_jobs(smoke: bool, seeds=(0,)) -> list[dict]:
    """Table 1's simulations of :func:`table1_sea_jobs` in calm water (the study's own runs,
    :func:`.scenario.table1_jobs`, on each seed of ``seeds``: its gusts and wander), as jobs of
    :func:`table1_sea_run` with ``hs`` 0; sim by sim, seed by seed.

    Parameters
    ----------
    smoke : bool
        The study's short pass (sim 3).
    seeds : sequence of int
        The seeds.
    """
    jobs = table1_jobs(smoke)
    return [{"run": {**jobs[("dsyhs", sim)], "seed": int(seed)}, "hs": 0.0, "sim": sim, "seed": int(seed)}
            for sim in _table1_sims(smoke) for seed in seeds]


def table1_sea_jobs(smoke: bool, seeds=(0,)) -> list[dict]:
    """Table 1's simulations (as built, :func:`.scenario.table1_jobs`) in the seas ``SEA_HS``
    from the wind's bearing, each on every seed of ``seeds`` (the run's gusts and wander and the
    sea's phases): the jobs of :func:`studies.kit.wille.table1_simulate`, each with its ``hs``,
    ``sim`` and ``seed``; sim by sim, sea by sea, seed by seed.

    Parameters
    ----------
    smoke : bool
        The study's short pass (sim 3, one sea).
    seeds : sequence of int
        The seeds.
    """
    jobs = table1_jobs(smoke)
    out = []
    for sim in _table1_sims(smoke):
        for hs in (SMOKE_HS if smoke else SEA_HS):
            _, tp = developed_sea(hs)
            for seed in seeds:
                waves = {"spectrum": "pm", "hs": hs, "tp": tp, "direction_from_deg": table1_wind_from_deg(),
                         "n_components": _components(smoke), "seed": int(seed)}
                run = jobs[("dsyhs", sim)]
                out.append({"run": {**run, "seed": int(seed), "env": {**run["env"], "waves": waves}},
                            "hs": hs, "sim": sim, "seed": int(seed)})
    return out


def table1_sea_run(job: dict) -> dict:
    """One Table 1 run in a sea or in calm water (a job of the sweep engine): its numbers
    (:func:`studies.kit.wille.table1_numbers`), its roll and heading over the same window
    (:func:`window_statistics`), how long it sailed and why it stopped early.

    Parameters
    ----------
    job : dict
        An item of :func:`table1_sea_jobs`, :func:`table1_calm_jobs` or :func:`mechanism_jobs`
        (``run``: the job of :func:`studies.kit.wille.table1_simulate`).
    """
    from ..kit.wille import TABLE1_WINDOW, table1_numbers, table1_simulate

    result = table1_simulate(job["run"])
    stopped = result["metrics"].get("stopped")
    traj = result["trajectory"]
    held = table1_heading()
    error = [math.remainder(math.radians(h) - held, 2.0 * math.pi) for h in traj["heading_deg"]]
    stats = window_statistics(traj["t"], np.radians(traj["heel_deg"]), error, TABLE1_WINDOW)
    return {**table1_numbers(result), **stats, "sailed": float(traj["t"].iloc[-1]),
            "stopped": str(stopped) if stopped else ""}


def switched(mechanism: str) -> dict:
    """The sea's mechanism switches with ``mechanism`` off and the others on.

    Parameters
    ----------
    mechanism : str
        A physics option of ``MECHANISMS``.
    """
    return {**MECHANISM_ON, mechanism: dict(MECHANISMS)[mechanism]}


def mechanism_spec(spec: dict, reruns: list[tuple[int, str]]) -> dict:
    """A sea sweep's runs again, each with one mechanism of ``MECHANISMS`` off (``env.`` keys):
    ``reruns`` lists (the run's index in the sea spec's zip, the mechanism), in that order.

    Parameters
    ----------
    spec : dict
        A sea spec (:func:`plane_sea_specs`, :func:`saoud_sea_specs`).
    reruns : list of (int, str)
        The runs to repeat and the mechanism each switches off.
    """
    zipped = {key: [] for key in spec["zip"]}
    zipped.update({f"env.{name}": [] for name in MECHANISM_ON})
    for index, name in reruns:
        for key, values in spec["zip"].items():
            zipped[key].append(values[index])
        for key, value in switched(name).items():
            zipped[f"env.{key}"].append(value)
    return {**spec, "name": f"{spec['name']}-mechanisms", "zip": zipped}


def mechanism_jobs(jobs: list[dict], reruns: list[tuple[int, str]]) -> list[dict]:
    """Table 1 runs in a sea (:func:`table1_sea_jobs`) again, each with one mechanism off:
    ``reruns`` lists (the job's index, the mechanism), in that order.

    Parameters
    ----------
    jobs : list of dict
        The Table 1 sea jobs.
    reruns : list of (int, str)
        The jobs to repeat and the mechanism each switches off.
    """
    out = []
    for index, name in reruns:
        job = jobs[index]
        run = {**job["run"], "env": {**job["run"]["env"], **switched(name)}}
        out.append({**job, "run": run, "mechanism": name})
    return out


def simulated_seconds(runs: Runs) -> float:
    """The cost of the sea's runs among ``runs``: their simulated seconds, a run in a sea
    counting ``SEA_COST`` per second and one in calm water 1 (the others' runs: 0).

    Parameters
    ----------
    runs : sailmujoco.study.Runs
        A pass's runs.
    """
    from sailmujoco.sweep.spec import expand, validate

    total = 0.0
    for spec, _ in runs.sweeps:
        if spec["name"].endswith(("-calm", "-sea", "-sea-mechanisms")):
            for run in expand(validate(spec)):
                total += run["duration"] * (SEA_COST if run.get("waves_options", {}).get("hs", 0.0) > 0.0 else 1.0)
    for name, (_, items) in runs.jobs.items():
        if name in (SEA_JOB, CALM_JOB, MECHANISM_JOB):
            total += sum(item["run"]["duration"] * (SEA_COST if "waves" in item["run"].get("env", {}) else 1.0)
                         for item in items)
    return total


def runs(smoke: bool, seeds=(0,)) -> Runs:
    """The study's first pass: its runs (:func:`.scenario.runs`) and the sea's, the wind plane
    in calm water and in a sea (:func:`plane_sea_specs`), Saoud's optimal sail
    (:func:`saoud_sea_specs`) and Table 1 in the seas (:func:`table1_sea_jobs`) and in calm
    water (:func:`table1_calm_jobs`), every case in a sea on each seed of ``seeds``.

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The seeds (:attr:`sailmujoco.study.Results.seeds`).
    """
    seeds = tuple(int(s) for s in seeds)
    takes_seeds = len(inspect.signature(scenario_runs).parameters) >= 2
    base = scenario_runs(smoke, seeds) if takes_seeds else scenario_runs(smoke)
    specs = [*plane_sea_specs(smoke, seeds).values(), *saoud_sea_specs(smoke, seeds).values()]
    return Runs(sweeps=base.sweeps + tuple((spec, f"sweeps/{spec['name']}") for spec in specs),
                jobs={**base.jobs,
                      SEA_JOB: (f"{__package__}.sea:table1_sea_run", table1_sea_jobs(smoke, seeds)),
                      CALM_JOB: (f"{__package__}.sea:table1_sea_run", table1_calm_jobs(smoke, seeds))},
                label=base.label)
