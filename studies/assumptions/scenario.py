"""Assumption validation, the scenario: the boats, the switches, the runs as data.

The wind-plane sweeps (each boat as built and with one of the papers' simplifications made
true at a time, ``CONFIGS``), the reproduction scenarios of :mod:`.episodes` and Wille's Table 1
with and without residuary resistance (:mod:`studies.kit.wille`).
"""

from __future__ import annotations

from sailmujoco.boat.catalogue import SAOUD_CN_POLY
from sailmujoco.study import Runs

from ..kit.wille import TABLE1_DURATION, TABLE1_SMOKE_DURATION, TABLE1_WIND

NAME = "assumptions"
TITLE = "Assumption validation in 6-DOF: where the papers' simplifications hold and where they break"

ABOUT = """\
* the wind plane: true wind 2-14 m/s x true wind angle 30-180 deg, steady wind, heading held
  (``heading_hold``), the Saoud robot with Saoud's optimal sail and the Wille yacht with
  Wille's heading controller and lambda100 sail; each point run four times: as built
  (6-DOF, C_T on, actuated sail), with C_T switched off, with heave and pitch held, with a
  sheeted sail;
* the reproduction scenarios: Wille's close-hauled course hold (course controller, 6-DOF),
  Viel's position keeping (case 2, 3-DOF and 6-DOF robot), free decay and rudder steps;
* Saoud's static optimum at a few wind angles and speeds against the heel the boat reaches.
"""  # what the study runs (the report's "Scenarios" section)

BOATS = {"saoud_robot": "saoud", "wille_yacht": "wille_heading"}
# the scenario `sailmujoco study assumptions --video` films: the robot on a blustery reach
VIDEO = {"boat": "saoud_robot", "task": "heading_hold", "controller": "saoud", "seconds": 40.0,
         "wind_speed": 8.0, "wind_from_deg": 70.0}
CONFIGS = {"baseline": {}, "ct_off": {"env.sail_tangential": False}, "four_dof": {"env.dofs": 4},
           "sheeted": {"env.sail_mode": "sheeted"}}
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
SPEED_HOLDS = 0.05  # an assumption "holds" where it changes the steady speed by less than 5 %
HEEL_HOLDS_DEG = 1.0  # ... and the steady heel by less than 1 deg
SPEED_FLOOR = 0.3  # m/s: below it the as-built boat is stalled (in irons, or its heading lost) and
#                    a speed change is given in m/s, not in % of ~0 (studies.kit.verdict.difference)
PART_NAMES = ("course", "steady", "drift")  # the single scenarios (episodes.PARTS), in the job list's order
RUNS_JOB = "assumptions_runs"  # the job list's name


def plane_specs(smoke: bool) -> dict:
    """The wind-plane sweeps: {(boat, config): spec}.

    Parameters
    ----------
    smoke : bool
        The study's short pass (two wind speeds, two angles, 25 s).
    """
    tws = [4.0, 10.0] if smoke else [2.0, 5.0, 8.0, 11.0, 14.0]
    twa = [60.0, 150.0] if smoke else [30.0, 60.0, 90.0, 120.0, 150.0, 180.0]
    duration = 25.0 if smoke else 50.0
    specs = {}
    for boat, controller in BOATS.items():
        for config, options in CONFIGS.items():
            specs[(boat, config)] = {
                "name": f"{boat}-{config}", "boat": boat, "task": "heading_hold",
                "world": "mujoco", "controller": controller, "duration": duration,
                "options": {"task.gusts": False, "task.wander": False, "task.diagnostics": True,
                            "task.heading_jitter_deg": 0.0, "task.steady_window": duration / 3,
                            **options},
                "zip": {"task.wind_speed": [s for s in tws for _ in twa],
                        "task.wind_from_deg": [a for _ in tws for a in twa]}}
    return specs


def table1_jobs(smoke: bool) -> dict:
    """Wille (2016b) Table 1 sims 1-3 (seed 0, 6-DOF) with and without residuary resistance:
    {(resistance, sim): the job of :func:`studies.kit.wille.table1_simulate`}.

    Parameters
    ----------
    smoke : bool
        The study's short pass (Table 1's smoke duration).
    """
    return {(resistance, sim): dict(world="mujoco", sim=sim, seed=0, wind_speed=TABLE1_WIND,
                                    duration=TABLE1_SMOKE_DURATION if smoke else TABLE1_DURATION,
                                    env={"resistance": resistance})
            for resistance in ("dsyhs", "friction") for sim in ("sim1", "sim2", "sim3")}


def runs(smoke: bool) -> Runs:
    """The wind-plane sweeps and, as one job list, the course, steady-state and drift scenarios
    (``PART_NAMES``) and the Table 1 runs.

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    """
    jobs = [{"part": name, "smoke": smoke} for name in PART_NAMES]
    jobs += [{"part": "table1", "run": job} for job in table1_jobs(smoke).values()]
    return Runs(sweeps=tuple((spec, f"sweeps/{spec['name']}") for spec in plane_specs(smoke).values()),
                jobs={RUNS_JOB: (f"{__package__}.episodes:part", jobs)})
