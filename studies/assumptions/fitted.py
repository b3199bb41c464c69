"""Assumption validation, sensors and actuators as fitted: the runs.

Every paper's controller reads perfect state and commands ideal actuators. Here each one sails
its own scenario three times on every seed: as the papers have it (``perfect`` sensors and
actuators), with a small boat's instruments (``typical`` sensors,
:mod:`sailmujoco.boat.fitted`) and with its fitted servos (``typical`` actuators, the same
module), the other half perfect. The seed draws the start (and in the
course hold the gusts and the wander) and, in the typical arms, the instruments' noise: the arms
are paired by seed, the same wind in all three.

Where an arm moves a controller's figure of merit by more than 10 % (the project's tolerance,
:data:`studies.kit.verdict.TOLERANCE`) the second pass
(:func:`attribution_jobs`) reruns it with one instrument (or one servo) made perfect at a time:
the switch that brings the difference back within 10 % is the one that made it.
"""

from __future__ import annotations

import math

import numpy as np

from sailmujoco.jit.ordered import elementwise

from ..kit import run_episode

FITTED_JOB = "assumptions_fitted"  # the first pass's job list
ATTRIBUTION_JOB = "assumptions_fitted_switches"  # the second pass's
ARMS = {"perfect": ("perfect", "perfect"), "sensors": ("typical", "perfect"),
        "actuators": ("perfect", "typical")}  # arm -> (sensors, actuators)
# the figures that make one instrument or one servo perfect, over the typical preset (a GNSS
# as fast as the control loop, no error, no latency; a vane with no noise and no filter still
# reads the masthead's own motion, which is the air it sits in, not an error of the sensor)
SENSOR_SWITCHES = {
    "gnss": {"gnss_cep": 0.0, "gnss_velocity_sigma": 0.0, "gnss_latency": 0.0, "gnss_rate_hz": 1000.0},
    "compass": {"compass_noise_deg": 0.0, "compass_deviation_deg": 0.0},
    "inclinometer": {"inclinometer_noise_deg": 0.0},
    "gyro": {"gyro_noise": 0.0, "gyro_bias_walk": 0.0},
    "vane": {"vane_noise": 0.0, "vane_filter_hz": 0.0},
    "log": {"log_scale_error": 0.0, "log_noise": 0.0},
}
ACTUATOR_SWITCHES = {
    "rudder servo": {"rudder_60deg_s": 0.0, "rudder_deadband_deg": 0.0, "rudder_backlash_deg": 0.0,
                     "rudder_resolution_deg": 0.0},
    "sail actuator": {"sail_full_range_s": 0.0, "sail_deadband": 0.0, "sail_backlash": 0.0,
                      "sail_resolution": 0.0},
}
SWITCHES = {"sensors": SENSOR_SWITCHES, "actuators": ACTUATOR_SWITCHES}
DEG = 180.0 / math.pi
VIEL_DT = 0.01  # s, Viel §5.1's control period (the viel_fig3 study's PAPER_DT)

# name -> the scenario: boat, task, controller (and its options), the task's options, seconds
# (smoke, full), the figure of merit (a metric of the task, or "late_distance": the mean distance
# to the target over the run's second half), its scale and unit in the report, the floor below
# which a difference is taken of the floor rather than of ~0, and the claim in words
SCENARIOS = {
    "saoud": {"boat": "saoud_robot", "task": "heading_hold", "controller": "saoud",
              "controller_options": {},
              "options": {"wind_speed": 6.0, "wind_from_deg": 90.0, "gusts": False, "wander": False,
                          "heading_jitter_deg": 2.0, "steady_window": 20.0},
              "seconds": (30.0, 60.0), "metric": "steady_speed", "scale": 1.0, "unit": "m/s",
              "floor": 0.3, "label": "Saoud's sail law, robot on a beam reach in 6 m/s: steady speed"},
    "wille_roll": {"boat": "wille_yacht", "task": "beam_reach_roll", "controller": "wille_roll",
                   "controller_options": {"wind": "perfect"}, "options": {},
                   "seconds": (40.0, 100.0), "metric": "roll_amplitude", "scale": DEG, "unit": "deg",
                   "floor": 1.0 / DEG, "label": "Wille's roll LQR, yacht on a gusty beam reach: roll amplitude"},
    "wille_course": {"boat": "wille_yacht", "task": "course_hold", "controller": "wille_course",
                     "controller_options": {}, "options": {},
                     "seconds": (60.0, 200.0), "metric": "drift_error", "scale": DEG, "unit": "deg",
                     "floor": 1.0 / DEG, "label": "Wille's course controller, yacht close-hauled: drift error"},
    "viel": {"boat": "viel_boat", "task": "position_keeping", "controller": "viel",
             "controller_options": {}, "options": {"case": 2, "control_timestep": VIEL_DT},
             "seconds": (60.0, 200.0), "metric": "late_distance", "scale": 1.0, "unit": "m",
             "floor": 1.0, "label": "Viel's position keeping, case 2, viel_boat: distance to the buoy, "
                                    "second half"},
}


def figure_of_merit(name: str, metrics: dict, trajectory) -> float:
    """A scenario's figure of merit from its run (SI: m/s, rad, m).

    Parameters
    ----------
    name : str
        The scenario (``SCENARIOS``).
    metrics : dict
        The task's metrics.
    trajectory : pandas.DataFrame
        The run's rows (``t``, ``x``, ``y``, ...).
    """
    metric = SCENARIOS[name]["metric"]
    if metric != "late_distance":
        return float(metrics[metric])
    late = trajectory[trajectory["t"] >= trajectory["t"].iloc[-1] / 2]
    return float(np.mean(elementwise(math.hypot, late["x"], late["y"])))  # the target is the origin


def fitted_run(job: dict) -> dict:
    """One run of a scenario with the job's sensors and actuators (a job of the sweep engine).

    Parameters
    ----------
    job : dict
        ``scenario``, ``seed``, ``smoke``, ``sensors`` and ``actuators`` (a preset's name or a
        dict of figures), and ``arm`` and ``switch`` (naming the run, not read).
    """
    s = SCENARIOS[job["scenario"]]
    metrics, trajectory, _ = run_episode(
        s["boat"], s["task"], "mujoco", s["controller"], seed=job["seed"],
        controller_options=s["controller_options"], time_limit=s["seconds"][not job["smoke"]],
        sensors=job["sensors"], actuators=job["actuators"], **s["options"])
    return {"value": figure_of_merit(job["scenario"], metrics, trajectory),
            "stopped": metrics.get("stopped")}


def fitted_jobs(smoke: bool, seeds) -> list[dict]:
    """The first pass: every scenario in every arm (``ARMS``) on every seed.

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The study's seeds.
    """
    return [{"scenario": name, "arm": arm, "switch": "", "seed": int(seed), "smoke": smoke,
             "sensors": sensors, "actuators": actuators}
            for name in SCENARIOS for arm, (sensors, actuators) in ARMS.items() for seed in seeds]


def attribution_jobs(flagged, smoke: bool, seeds) -> list[dict]:
    """The second pass: each flagged (scenario, arm) rerun with one instrument or servo of that
    arm made perfect at a time, on every seed.

    Parameters
    ----------
    flagged : iterable of (str, str)
        (scenario, arm) pairs whose difference from the perfect arm exceeded 10 %.
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The study's seeds.
    """
    jobs = []
    for name, arm in flagged:
        for switch, figures in SWITCHES[arm].items():
            fitted = {"preset": "typical", **figures}
            sensors, actuators = (fitted, "perfect") if arm == "sensors" else ("perfect", fitted)
            jobs += [{"scenario": name, "arm": arm, "switch": switch, "seed": int(seed), "smoke": smoke,
                      "sensors": sensors, "actuators": actuators} for seed in seeds]
    return jobs


def relative(value: float, reference: float, floor: float) -> float:
    """(value - reference) / max(|reference|, floor): the arm's change of the figure of merit.

    Parameters
    ----------
    value, reference : float
        The arm's and the perfect arm's figure on one seed.
    floor : float
        The scenario's floor (a reference below it counts as the floor).
    """
    return (value - reference) / max(abs(reference), floor)

