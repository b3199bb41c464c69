"""The Wille yacht's scenarios, shared by the Wille studies (and the assumptions study).

* :func:`make_env`: the Wille yacht on a task and in a world, its sail force and sail actuator lag
  switchable (:func:`scaled_sail`).
* The Table 1 scenario of Wille, Hassani & Sprenger (2016b) §5: a beam reach (wind from the west,
  desired heading north, PID heading rudder) at U10 = :data:`TABLE1_WIND` with NORSOK gusts and
  direction wander, :data:`TABLE1_DURATION` s, metrics over the last :data:`TABLE1_WINDOW` s.
  One run is :func:`table1_simulate` (a job of the sweep engine), its numbers
  :func:`table1_numbers`.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from sailmujoco import suite, sweep
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.jit.ordered import mat_t_vec

BOAT = "wille_yacht"

TABLE1_WIND = 10.0  # m/s, U10 of Table 1
TABLE1_DURATION = 300.0  # s, §5
TABLE1_SMOKE_DURATION = 60.0  # s
TABLE1_WINDOW = 50.0  # s, the task's metric window (BeamReachRoll.window)
TABLE1_SIMS = {  # options of the registered "wille_roll" controller
    "sim1": dict(roll_control=False, wind="perfect"),
    "sim1_mean": dict(roll_control=False, wind="mean"),
    "sim2": dict(roll_control=True, wind="mean_speed"),
    "sim2_mean": dict(roll_control=True, wind="mean"),
    "sim3": dict(roll_control=True, wind="perfect"),
}
MOMENT_TERMS = ("sail", "restoring", "keel", "rudder", "damping", "added_mass")  # the roll moments
PAPER_GAIN = (9.0e4, 1.0e5)  # Wille (2016b) §4, the printed LQR gain K


def scaled_sail(params, factor: float, time_constant: float | None = None):
    """``params`` with the sail area (so every sail force, in the physics and in the lambda
    tables alike) multiplied by ``factor``; the CE position is kept.

    Parameters
    ----------
    params : sailmujoco.boat.params.BoatParams
        The boat.
    factor : float
        Multiplies the sail area.
    time_constant : float, optional
        Replaces the sail actuator's lag T_lambda (s) when given.

    Returns
    -------
    sailmujoco.boat.params.BoatParams
        ``params`` itself when nothing changes, else a copy.
    """
    sail = params.sail
    if factor != 1.0:
        sail = dataclasses.replace(sail, area=sail.area * factor)
    if time_constant is not None:
        sail = dataclasses.replace(sail, time_constant=time_constant)
    return params if sail is params.sail else dataclasses.replace(params, sail=sail)


def make_env(task: str, world: str, *, seed: int = 0, sail_factor: float = 1.0,
             sail_time_constant: float | None = None, paper_model: str = "paper",
             control_timestep: float = 0.1, dofs: int = 6, time_limit: float | None = None,
             **task_options):
    """The Wille yacht on ``task`` in ``world`` (:func:`sailmujoco.suite.load`).

    Parameters
    ----------
    task : str
        The task's name (``"course_hold"``, ``"beam_reach_roll"``, ...).
    world : str
        ``"paper"`` (Wille's 4-DOF equations) or ``"mujoco"`` (6-DOF).
    seed : int
        The gust realisation and initial state.
    sail_factor : float
        Multiplies the sail force (the sail switch, :func:`scaled_sail`).
    sail_time_constant : float, optional
        Replaces the sail actuator's lag T_lambda (s) (the lag switch).
    paper_model : str
        The paper world's yaw kinematics (``"paper"`` or ``"rigid"``).
    control_timestep : float
        The control period (s).
    dofs : int
        6, or 4 with heave and pitch held (MuJoCo world).
    time_limit : float, optional
        The episode's length (s).
    **task_options
        Further options of :func:`sailmujoco.suite.load` (task, wind and boat options).

    Returns
    -------
    sailmujoco.suite.SailEnvironment
        The environment.
    """
    params = scaled_sail(get_boat(BOAT), sail_factor, sail_time_constant)
    return suite.load(BOAT, task, world, seed=seed, control_timestep=control_timestep,
                      time_limit=time_limit, paper_model=paper_model, dofs=dofs, params=params,
                      **task_options)


def table1_simulate(job: dict) -> dict:
    """One Table 1 beam reach; returns metrics and a 10 Hz trajectory (with roll moments if asked).

    Parameters
    ----------
    job : dict
        ``world``, ``sim`` (a key of :data:`TABLE1_SIMS`), ``seed``, ``duration`` (s) and
        ``wind_speed`` (U10, m/s); optional: ``sail_factor``, ``sail_time_constant`` (s),
        ``paper_model``, ``dt`` (the control period, s), ``dofs``, ``env`` (more options of
        :func:`make_env`), ``heel_desired_deg``, ``gain`` (``"paper"``: the printed LQR gain
        :data:`PAPER_GAIN`), ``band_deg`` (the hysteresis band) and ``moments`` (record the roll
        moments of :data:`MOMENT_TERMS`).

    Returns
    -------
    dict
        ``metrics`` (the task's) and ``trajectory`` (a DataFrame, one row per control step).
    """
    env = make_env("beam_reach_roll", job["world"], seed=job["seed"],
                   sail_factor=job.get("sail_factor", 1.0), sail_time_constant=job.get("sail_time_constant"),
                   paper_model=job.get("paper_model", "paper"), control_timestep=job.get("dt", 0.1),
                   dofs=job.get("dofs", 6), time_limit=job["duration"], wind_speed=job["wind_speed"],
                   **job.get("env", {}))
    controller = sweep.make_controller("wille_roll", env, **TABLE1_SIMS[job["sim"]],
                                       heel_desired_deg=job.get("heel_desired_deg", 10.0))
    sail = controller.sail
    if job.get("gain") == "paper":  # the printed LQR gain in place of ours
        sail.lqr = dataclasses.replace(sail.lqr, K=np.array(PAPER_GAIN))
    if job.get("band_deg") is not None:  # the hysteresis band
        sail.heel_off = max(sail.heel_on - math.radians(job["band_deg"]), 0.0)
    physics = env.physics if job.get("moments") else None
    trajectory = suite.rollout(env, controller, record=lambda step, timestep, action: _row(
        timestep.observation, sail, physics))
    return {"metrics": env.task.metrics(), "trajectory": trajectory}


def _row(obs, sail, physics) -> dict:
    ts = obs["true_state"]
    row = {"t": float(ts["time"]), "heel_deg": math.degrees(float(obs["heel"])),
           "p_deg_s": math.degrees(float(obs["roll_rate"])), "u": float(ts["u"]),
           "heading_deg": math.degrees(math.remainder(float(obs["heading"]), 2 * math.pi)),
           "rudder_deg": math.degrees(float(ts["rudder"])), "sail_deg": math.degrees(float(ts["sail"])),
           "wind_ce": math.hypot(*ts["true_wind"]), "active": float(sail.active)}
    if physics is not None:  # roll moments about CO (N m, positive heeling to starboard)
        for term in MOMENT_TERMS:
            row[f"K_{term}"] = float(ts[f"{term}_wrench"][3])
        if hasattr(physics, "data"):  # 6-DOF: the weight's moment about CO, from MuJoCo
            d, m = physics.data, physics.model
            body = 1  # the hull: the root of the boat's kinematic tree
            rot = d.xmat[body].reshape(3, 3)
            moment = np.cross(d.subtree_com[body] - d.xpos[body], m.body_subtreemass[body] * m.opt.gravity)
            row["K_restoring"] += float(mat_t_vec(rot, moment)[0])
    return row


def table1_numbers(result: dict) -> dict:
    """The numbers of one Table 1 run (:func:`table1_simulate`) over the last
    :data:`TABLE1_WINDOW` s.

    Parameters
    ----------
    result : dict
        What :func:`table1_simulate` returned.

    Returns
    -------
    dict
        ``roll_amplitude``, ``max_roll_rate`` and ``mean_heel`` (deg, deg/s), ``mean_surge``
        (m/s), ``on`` (the share of the window the roll law is on), ``wind_ce`` (the mean wind
        speed at the sail, m/s), ``rudder_mean`` and ``heading_min`` (deg).
    """
    m, traj = result["metrics"], result["trajectory"]
    late = traj[traj["t"] >= traj["t"].iloc[-1] - TABLE1_WINDOW]
    return {"roll_amplitude": math.degrees(m["roll_amplitude"]),
            "max_roll_rate": math.degrees(m["max_roll_rate"]),
            "mean_surge": m["mean_surge"], "mean_heel": math.degrees(m["mean_heel"]),
            "on": float(late["active"].mean()), "wind_ce": float(late["wind_ce"].mean()),
            "rudder_mean": float(late["rudder_deg"].mean()),
            "heading_min": float(late["heading_deg"].min())}
