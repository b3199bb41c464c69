"""Assumption validation, the single scenarios: one run each per seed.

Wille's course correction against the drift sailed, Saoud's static optimum against the heel
reached, the lateral drift in Viel's position keeping, and a Wille Table 1 run, each in a worker
process (the job function :func:`part` runs one of them on one seed); and the free decay and
rudder step of both boats (:func:`time_constants`, in the analysing process: calm water, no
wind, an exact start, nothing drawn).
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
from sailmujoco.controllers.base import Composite

from sailmujoco import frames
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

from ..kit import run_episode
from ..kit.wille import table1_numbers, table1_simulate
from .durations import COURSE_SECONDS, DRIFT_SECONDS, STEADY_CASES, STEADY_L_PHI, STEADY_SECONDS
from .scenario import BOATS, JITTER_DEG


def course_correction_error(smoke: bool, seed: int = 0) -> dict:
    """Wille's correction beta_b (eqs. 57-59) against the drift the 6-DOF yacht really sails at.

    Parameters
    ----------
    smoke : bool
        The study's short pass (60 s instead of 200 s).
    seed : int
        Draws the gusts, the wind's wander and the start heading (the task's own).
    """
    log = []

    def factory(env):
        from sailmujoco.controllers.factories import wille_course

        controller = wille_course(env)
        rudder = controller.rudder

        def logged(observation):
            sigma = rudder(observation)
            ts = observation["true_state"]
            beta = math.atan2(float(ts["v"]) * math.cos(float(observation["heel"])), float(ts["u"]))
            log.append((float(ts["time"]), rudder.last_beta_b, -beta))  # FRD drift sign
            return sigma

        return Composite(logged, controller.sail)

    metrics, traj, _ = run_episode("wille_yacht", "course_hold", "mujoco", factory, seed=seed,
                                   time_limit=COURSE_SECONDS[not smoke])
    log = np.array(log)
    steady = log[log[:, 0] > log[-1, 0] / 2]
    return {"beta_b": float(np.mean(steady[:, 1])), "drift": float(np.mean(steady[:, 2])),
            "drift_error": metrics["drift_error"],
            "heel_max": float(np.max(np.abs(traj["heel"])))}


def saoud_steady_state(smoke: bool, seed: int = 0) -> pd.DataFrame:
    """Saoud's predicted phi* against the steady heel of the 6-DOF robot, same apparent wind.

    Parameters
    ----------
    smoke : bool
        The study's short pass (one wind, one l_phi).
    seed : int
        Draws the start heading (within ``JITTER_DEG`` of the heading held; the wind is steady).
    """
    rows = []
    cases = STEADY_CASES[not smoke]
    for boat_l_phi in STEADY_L_PHI[not smoke]:
        for wind, angle in cases:
            phis = []

            def factory(env, phis=phis, l_phi=boat_l_phi):
                from sailmujoco.controllers.factories import saoud

                controller = saoud(env, l_phi=l_phi, phi_max_deg=None)
                law = controller.sail

                def logged(observation):
                    angle_ = law(observation)
                    if law.last_optimum is not None:
                        phis.append((float(observation["true_state"]["time"]), law.last_optimum.phi))
                    return angle_

                return Composite(controller.rudder, logged)

            metrics, traj, _ = run_episode(
                "saoud_robot", "heading_hold", "mujoco", factory, seed=seed, time_limit=STEADY_SECONDS,
                boat_options={"l_phi": boat_l_phi}, wind_speed=wind, wind_from_deg=angle,
                gusts=False, wander=False, heading_jitter_deg=JITTER_DEG, steady_window=10.0)
            phis = np.array(phis)
            steady = phis[phis[:, 0] > 30.0][:, 1] if phis.size else np.array([np.nan])
            # Saoud's body frame is FLU like ours: his phi is our heel (positive starboard down)
            rows.append({"l_phi": boat_l_phi, "tws": wind, "twa": angle, "seed": seed,
                         # no optimum logged after 30 s (the run stopped): no value, and no
                         # numpy "Mean of empty slice" warning in the log
                         "phi_star_deg": math.degrees(float(np.mean(steady))) if steady.size else math.nan,
                         "heel_deg": math.degrees(metrics["steady_heel"]),
                         "speed": metrics["steady_speed"]})
    frame = pd.DataFrame(rows)
    frame["error_deg"] = frame["heel_deg"] - frame["phi_star_deg"]
    return frame


def lateral_drift(smoke: bool, seed: int = 0) -> dict:
    """Position keeping, case 2: the lateral speed (leeway) of the 3-DOF model and of the robot,
    both from the same start.

    Parameters
    ----------
    smoke : bool
        The study's short pass (60 s instead of 200 s).
    seed : int
        Draws the start heading (over the compass: the task's own).
    """
    out = {}
    for world in ("paper", "mujoco"):
        _, traj, _ = run_episode("saoud_robot", "position_keeping", world, "viel", seed=seed, case=2,
                                 time_limit=DRIFT_SECONDS[not smoke])
        out[world] = float(np.mean(np.abs(traj["v"])))
        out[world + "_max"] = float(np.max(np.abs(traj["v"])))
    return out


PARTS = {"course": course_correction_error, "steady": saoud_steady_state, "drift": lateral_drift}


def part(job: dict):
    """One of the study's single runs (a job of the sweep engine): a part of ``PARTS`` on one
    seed, or a Table 1 simulation (its numbers).

    Parameters
    ----------
    job : dict
        ``{"part": name, "smoke": bool, "seed": int}`` or ``{"part": "table1", "run": the
        Table 1 job}``.
    """
    if job["part"] == "table1":
        return table1_numbers(table1_simulate(job["run"]))
    return PARTS[job["part"]](job["smoke"], job.get("seed", 0))


def time_constants() -> dict:
    """Roll period (free decay) and yaw time constant (rudder step) of both boats, 6-DOF (run in
    this process, by the analysis)."""
    out = {}
    for boat in BOATS:
        p = get_boat(boat)
        physics = BoatPhysics.load(boat, wind=WindConfig(), forces=ForceSwitches(sail=False))
        with physics.reset_context():
            physics.data.qpos[3:7] = frames.quat_from_euler(math.radians(5.0), 0.0, 0.0)
        heels = []
        for _ in range(2000):
            physics.step(1)
            heels.append(physics.heel())
        heels = np.array(heels)
        t = np.arange(1, heels.size + 1) * physics.timestep()
        up = np.nonzero((heels[:-1] < 0) & (heels[1:] >= 0))[0]
        roll_period = float(np.mean(np.diff(t[up]))) if up.size > 1 else float("nan")
        # yaw: moving ahead at a typical speed (thrust held), then a 10 deg rudder step
        speed = 2.0 if boat == "wille_yacht" else 0.8
        physics = BoatPhysics.load(boat, wind=WindConfig(), forces=ForceSwitches(sail=False))
        physics.place((0.0, 0.0), 0.0, speed)
        drag = _surge_drag(physics)
        physics.set_external_wrench([drag, 0, 0, 0, 0, 0])
        physics.set_control([math.radians(10.0), 0.0])
        rates = []
        for _ in range(int(30.0 / physics.timestep())):
            physics.step(1)
            rates.append(physics.yaw_rate())
        rates = np.abs(np.array(rates))
        t = np.arange(1, rates.size + 1) * physics.timestep()
        final = rates[-200:].mean()
        reach = np.nonzero(rates >= (1 - math.exp(-1)) * final)[0]
        out[boat] = {"roll_period": roll_period,
                     "yaw_time_constant": float(t[reach[0]]) if reach.size else float("nan"),
                     "roll_natural": 2 * math.pi / roll_period if roll_period else float("nan"),
                     "ixx": p.inertia[0]}
    return out


def _surge_drag(physics) -> float:
    """The surge force [N] that holds the boat's speed: minus hull, keel and rudder drag now."""
    total = physics.force_term("damping")[0] + physics.force_term("keel")[0] + physics.force_term("rudder")[0]
    return -float(total)
