"""Assumption validation, the scenario: the boats, the switches, the runs as data.

The wind-plane sweeps (each boat as built and with one of the papers' simplifications made
true at a time, ``CONFIGS``), the reproduction scenarios of :mod:`.episodes` and Wille's Table 1
with and without residuary resistance (:mod:`studies.kit.wille`).

**Seeds.** The wind is steady in the wind plane and in Saoud's steady state, so there the seed
draws the start: the heading the boat starts on, uniform within ``JITTER_DEG`` of the heading it
holds. In Wille's course hold it draws the gusts, the wind's wander and the start heading (the
task's own), in Viel's position keeping the start heading (over the compass). Each comparison of
the boat as built with a paper's simplification is made seed by seed (the same start in both
arms). The budget (simulated seconds) sets how many of the study's seeds each part runs:
``PLANE_SEEDS`` for the wind plane, ``SINGLE_SEEDS`` for the single scenarios, ``TABLE1_SEEDS``
for Table 1 (:func:`part_seeds`); the switches run on the points of the plane with a true wind of
at least ``SWITCH_TWS_MIN`` (:func:`plane_specs`).
"""

from __future__ import annotations

from sailmujoco.boat.viel_identification import SAOUD_CN_POLY
from sailmujoco.study import Runs

from ..kit.verdict import TOLERANCE
from ..kit.wille import TABLE1_DURATION, TABLE1_SMOKE_DURATION, TABLE1_WIND
from .durations import part_seconds

NAME = "assumptions"
TITLE = "Assumption validation in 6-DOF: where the papers' simplifications hold and where they break"

ABOUT = """\
* the wind plane: true wind 2-14 m/s x true wind angle 30-180 deg, steady wind, heading held
  (``heading_hold``), the Saoud robot with Saoud's optimal sail and the Wille yacht with
  Wille's heading controller and lambda100 sail; each point as built (6-DOF, C_T on,
  actuated sail) and, where the true wind is 5-14 m/s, with one switch at a time: C_T off
  (robot), heave and pitch held, a sheeted sail (robot), each of the papers' forms of the boat;
  every run on each seed of the plane (the start heading drawn within 2 deg);
* the reproduction scenarios: Wille's close-hauled course hold (course controller, 6-DOF),
  Viel's position keeping (case 2, 3-DOF and 6-DOF robot), each on every seed of the single
  scenarios; free decay and rudder steps (deterministic);
* Saoud's static optimum at a few wind angles and speeds against the heel the boat reaches, on
  every seed of the single scenarios;
* Wille's Table 1 (sims 1-3) with and without residuary resistance, on its first seed.
"""  # what the study runs (the report's "Scenarios" section)

BOATS = {"saoud_robot": "saoud", "wille_yacht": "wille_heading"}
# the scenario `sailmujoco study assumptions --video` films: the robot on a blustery reach
VIDEO = {"boat": "saoud_robot", "task": "heading_hold", "controller": "saoud", "seconds": 40.0,
         "wind_speed": 8.0, "wind_from_deg": 70.0}
CONFIGS = {"baseline": {}, "ct_off": {"env.sail_tangential": False}, "four_dof": {"env.dofs": 4},
           "sheeted": {"env.sail_mode": "sheeted"}}
ROBOT_ONLY = ("ct_off", "sheeted")  # Saoud's assumptions about the robot's sail: not run on the yacht
# The arm that is the paper's simplification in each comparison; the other is the boat as built
# (6-DOF), except for the sheeted sail: Saoud's actuated sail (as built) is the paper's there
PAPER_ARM = {"ct_off": "ct_off", "four_dof": "four_dof", "sheeted": "baseline"}
# The boat as built, each of its differences from the papers' boat switched off in turn
# (physics.ForceSwitches): (config, sweep options, row title, what the papers assume)
BUILT = (
    ("paper_hydrostatics", {"env.hydrostatics": "paper"},
     "Restoring by formula: eq. 20 / Saoud eq. 4 in place of the hull's geometric buoyancy",
     "Wille eq. 20; Saoud eq. 4"),
    ("friction_only", {"env.resistance": "friction"},
     "Friction-only resistance: no wave-making (residuary) resistance",
     "Wille eqs. 15-16 (ITTC-57 friction with form factor)"),
    ("paper_foils", {"env.foils": "paper"},
     f"The papers' foil coefficients: sail slope {SAOUD_CN_POLY[0]:g} /rad, 2-D post-stall drag",
     "Saoud §VII-A C_N polynomial; Wille eq. 23 with the 2-D table"),
    ("no_downwash", {"env.keel_downwash": False},
     "Rudder in undisturbed flow: no keel downwash", "Wille eqs. 34-36"),
    ("no_windage", {"env.windage": False},
     "No windage on hull and rig", "Wille, Saoud (Viel has p1 on the true wind)"),
)
CONFIGS.update({name: options for name, options, _, _ in BUILT})
PAPER_ARM.update({name: name for name, _, _, _ in BUILT})
SPEED_HOLDS = TOLERANCE  # an assumption "holds" where it changes the steady speed by less than 10 %
HEEL_HOLDS_DEG = 1.0  # ... and the steady heel by less than 1 deg
SPEED_FLOOR = 0.3  # m/s: below it the as-built boat is stalled (in irons, or its heading lost) and
#                    a speed change is given in m/s, not in % of ~0 (studies.kit.verdict.difference)
PART_NAMES = ("course", "steady", "drift")  # the single scenarios (episodes.PARTS), in the job list's order
RUNS_JOB = "assumptions_runs"  # the job list's name
JITTER_DEG = 2.0  # deg: the start heading is drawn uniformly within this of the heading held
SEEDS = 4  # N: the study's seeds (the sea runs every one); the calm parts take the first few:
PLANE_SEEDS = 2  # ... the wind plane (16 sweeps of 30 or 24 points: the budget allows two)
SINGLE_SEEDS = 3  # ... the single scenarios (course hold, Saoud's steady state, position keeping)
TABLE1_SEEDS = 1  # ... Table 1 with and without residuary resistance (a note, no verdict)
SWITCH_TWS_MIN = 5.0  # m/s: the switches run where the true wind is at least this (the boats
#                       barely move at 2 m/s, and the budget takes two seeds only without it)


def part_seeds(seeds, part: str) -> tuple:
    """The seeds of ``seeds`` (the study's) that a part runs: the first ``PLANE_SEEDS`` for
    ``"plane"``, ``SINGLE_SEEDS`` for ``"single"``, ``TABLE1_SEEDS`` for ``"table1"``.

    Parameters
    ----------
    seeds : sequence of int
        The study's seeds.
    part : {"plane", "single", "table1"}
        Which part.
    """
    cap = {"plane": PLANE_SEEDS, "single": SINGLE_SEEDS, "table1": TABLE1_SEEDS}[part]
    return tuple(int(s) for s in seeds)[:cap]


def plane_specs(smoke: bool, seeds=(0,)) -> dict:
    """The wind-plane sweeps: {(boat, config): spec}, every point on each seed of ``seeds``
    (the start heading within ``JITTER_DEG``); the as-built boat over the whole plane, the
    switches (``CONFIGS`` but the baseline; ``ROBOT_ONLY`` on the robot alone) where the true
    wind is at least ``SWITCH_TWS_MIN``.

    Parameters
    ----------
    smoke : bool
        The study's short pass (two wind speeds, two angles, 25 s).
    seeds : sequence of int
        The seeds every point runs on.
    """
    tws = [4.0, 10.0] if smoke else [2.0, 5.0, 8.0, 11.0, 14.0]
    twa = [60.0, 150.0] if smoke else [30.0, 60.0, 90.0, 120.0, 150.0, 180.0]
    duration = 25.0 if smoke else 50.0
    specs = {}
    for boat, controller in BOATS.items():
        for config, options in CONFIGS.items():
            if boat != "saoud_robot" and config in ROBOT_ONLY:
                continue
            speeds = tws if config == "baseline" else [s for s in tws if s >= SWITCH_TWS_MIN]
            specs[(boat, config)] = {
                "name": f"{boat}-{config}", "boat": boat, "task": "heading_hold",
                "world": "mujoco", "controller": controller, "duration": duration,
                "seeds": [int(s) for s in seeds],
                "options": {"task.gusts": False, "task.wander": False, "task.diagnostics": True,
                            "task.heading_jitter_deg": JITTER_DEG, "task.steady_window": duration / 3,
                            **options},
                "zip": {"task.wind_speed": [s for s in speeds for _ in twa],
                        "task.wind_from_deg": [a for _ in speeds for a in twa]}}
    return specs


def table1_jobs(smoke: bool, seed: int = 0) -> dict:
    """Wille (2016b) Table 1 sims 1-3 (6-DOF, the seed drawing the gusts and the wind's wander)
    with and without residuary resistance: {(resistance, sim): the job of
    :func:`studies.kit.wille.table1_simulate`}.

    Parameters
    ----------
    smoke : bool
        The study's short pass (Table 1's smoke duration).
    seed : int
        The runs' seed.
    """
    return {(resistance, sim): dict(world="mujoco", sim=sim, seed=int(seed), wind_speed=TABLE1_WIND,
                                    duration=TABLE1_SMOKE_DURATION if smoke else TABLE1_DURATION,
                                    env={"resistance": resistance})
            for resistance in ("dsyhs", "friction") for sim in ("sim1", "sim2", "sim3")}


def single_jobs(smoke: bool, seeds=(0,)) -> list[dict]:
    """The job list: the course, steady-state and drift scenarios (``PART_NAMES``) on each seed
    of ``part_seeds(seeds, "single")``, then the Table 1 runs on ``part_seeds(seeds, "table1")``;
    each job carries its ``seed``.

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The study's seeds.
    """
    jobs = [{"part": name, "smoke": smoke, "seed": seed}
            for name in PART_NAMES for seed in part_seeds(seeds, "single")]
    for seed in part_seeds(seeds, "table1"):
        jobs += [{"part": "table1", "key": list(key), "seed": seed, "run": job}
                 for key, job in table1_jobs(smoke, seed).items()]
    return jobs


def runs(smoke: bool, seeds=(0,)) -> Runs:
    """The calm-water runs: the wind-plane sweeps (on ``part_seeds(seeds, "plane")``) and, as
    one job list, the single scenarios and Table 1 (:func:`single_jobs`).

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The study's seeds (:attr:`sailmujoco.study.Results.seeds`).
    """
    specs = plane_specs(smoke, part_seeds(seeds, "plane"))
    return Runs(sweeps=tuple((spec, f"sweeps/{spec['name']}") for spec in specs.values()),
                jobs={RUNS_JOB: (f"{__package__}.episodes:part", single_jobs(smoke, seeds))})


def simulated_seconds(runs_: Runs) -> float:
    """The cost of the calm runs among ``runs_`` (this module's sweeps and job list): their
    simulated seconds, a paper-world (3-DOF) second counting 0.2.

    Parameters
    ----------
    runs_ : sailmujoco.study.Runs
        A pass's runs.
    """
    names = {f"sweeps/{boat}-{config}" for boat in BOATS for config in CONFIGS}
    total = sum(spec["duration"] * len(spec["zip"]["task.wind_speed"]) * len(spec["seeds"])
                for spec, folder in runs_.sweeps if folder in names)
    _, items = runs_.jobs.get(RUNS_JOB, ("", []))
    return total + sum(part_seconds(job) for job in items)
