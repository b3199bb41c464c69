"""Viel et al. (2019) Fig. 3, one switching experiment: a run in a worker process.

A position-keeping episode in the paper world or a 6-DOF boat with one difference switched
(start under way, scaled circles, rudder law, control period, hull wind), or the PID
heading-hold check of what a boat can sail; it returns the task's metrics, a 2 Hz trajectory and
the measures of :mod:`.measures`.
"""

from __future__ import annotations

import math

import numpy as np
from sailmujoco.controllers.viel_loop import MODES

from sailmujoco import frames, sweep
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.jit.ordered import elementwise
from sailmujoco.loop import episode
from sailmujoco.loop import truth as T
from sailmujoco.physics import BoatPhysics, ForceSwitches
from sailmujoco.reference.viel import VielParams, VielWorld
from sailmujoco.tasks.environment import SailEnvironment
from sailmujoco.tasks.position import PositionKeeping
from sailmujoco.tasks.world import VielPhysics

from ..kit import run_episode, timer
from .measures import after_entry, behaviour, drift_after_stop
from .scenario import DEFAULT_START, PAPER_D_M, PAPER_D_T, PAPER_DT, PAPER_GAINS, TRAJECTORY_RATE


class StartedPositionKeeping(PositionKeeping):
    """``position_keeping`` started on a given compass heading and surge (the task itself draws a
    random heading at 0.5 m/s)."""

    def __init__(self, seed=None, heading_deg: float | None = None, surge: float = 0.5, **kwargs):
        """The task, to start on ``heading_deg`` at ``surge``.

        Parameters
        ----------
        seed : int, optional
            The task's seed.
        heading_deg : float, optional
            Start heading [compass deg]; ``None`` keeps the task's start.
        surge : float
            Start surge [m/s] (with ``heading_deg``).
        **kwargs
            :class:`~sailmujoco.tasks.position.PositionKeeping`'s options.
        """
        super().__init__(seed, **kwargs)
        self.heading_deg = heading_deg
        self.surge = float(surge)

    def initialize_episode(self, physics):
        """The task's start, then the boat placed on the heading at the surge.

        Parameters
        ----------
        physics : sailmujoco.physics.BoatPhysics or sailmujoco.tasks.world.VielPhysics
            The episode's physics.
        """
        super().initialize_episode(physics)
        if self.heading_deg is not None:
            yaw = float(frames.yaw_from_heading(math.radians(self.heading_deg)))
            physics.place(tuple(self.start), yaw, self.surge)


class _Samples:
    """What a switching run keeps every ``every`` steps after the start: time, position, and the
    series of :func:`.measures.behaviour` (surge, sway, AWA, rudder, heel, sail, the mode)."""

    def __init__(self, policy, every: int):
        self.policy, self.every = policy, every
        self.t, self.x, self.y = [], [], []
        self.series = {"surge": [], "sway": [], "awa": [], "rudder": [], "heel": [], "sail": [], "mode": []}

    def sample(self, step, timestep, action) -> None:
        """From a TimeStep and the action that led to it (``suite.rollout``'s ``record``)."""
        if step == 0 or step % self.every:
            return
        o = timestep.observation
        self._keep(o["true_state"]["time"], o["position"][0], o["position"][1], o["true_state"]["u"],
                   o["true_state"]["v"], action[1], o["apparent_wind_angle"], action[0], o["heel"],
                   self.policy.info.get("mode", ""))

    def sample_row(self, row, command) -> None:
        """The same from a compiled step's truth row and command (with its mode code)."""
        self._keep(row[T.TIME], row[T.X], row[T.Y], row[T.U], row[T.V], command[1], row[T.AWA], command[0],
                   row[T.HEEL], MODES[int(command[2])])

    def _keep(self, t, x, y, surge, sway, sail, awa, rudder, heel, mode) -> None:
        self.t.append(float(t))
        self.x.append(float(x))
        self.y.append(float(y))
        for key, value in (("surge", surge), ("sway", sway), ("sail", sail), ("awa", awa), ("rudder", rudder),
                           ("heel", heel)):
            self.series[key].append(float(value))
        self.series["mode"].append(mode)


def _episode(env, policy, sample, sample_row, every: int) -> None:
    """``suite.rollout(env, policy, record=sample)``, by the compiled closed loop where one covers
    the pair (:mod:`sailmujoco.loop`: the same steps to the bit): ``sample_row`` is then fed the
    same numbers from the steps' truth rows and commands, ``sample`` the last step's TimeStep."""
    if hasattr(policy, "reset"):
        policy.reset(env.task.seed)
    timestep = env.reset()
    sample(0, timestep, None)
    compiled = episode.run_compiled(env, policy)
    step = 0
    if compiled is not None:
        for k in range(every, compiled.steps, every):
            sample_row(compiled.rows[k - 1], compiled.actions[k - 1])
        timestep, step = compiled.timestep, compiled.steps
        sample(step, timestep, compiled.actions[-1, :2].copy())
    while not timestep.last():
        action = policy(timestep)
        timestep, step = env.step(action), step + 1
        sample(step, timestep, action)


def simulate(spec: dict) -> dict:
    """One run of a switching experiment (in a worker process); returns metrics and a trajectory.

    Parameters
    ----------
    spec : dict
        ``kind`` ("position" or "heading_hold"), ``variant``, ``world`` ("paper" or a boat),
        ``case``, ``seed``, ``dt`` [s], ``p1`` [kg/m], ``rudder_law`` (the paper world's
        :class:`~sailmujoco.reference.viel.VielParams` reading of eqs. 7-8), ``start`` (m),
        ``heading_deg``, ``surge`` [m/s], ``scale`` (target radii ×), ``duration`` [s]; for
        heading_hold: ``wind_speed`` [m/s], ``desired_heading_deg``.
    """
    clock = timer()
    s = {"kind": "position", "seed": 0, "dt": PAPER_DT, "p1": VielParams().p1, "rudder_law": VielParams().rudder_law,
         "start": DEFAULT_START, "heading_deg": None, "surge": 0.5, "scale": 1.0, "duration": 200.0,
         **spec}
    if s["kind"] == "heading_hold":
        metrics, frame, _ = run_episode(
            s["world"], "heading_hold", "mujoco", "pid", seed=s["seed"], time_limit=s["duration"],
            desired_heading_deg=s["desired_heading_deg"], wind_speed=s["wind_speed"], wind_from_deg=180.0,
            gusts=False, wander=False)
        last = frame[frame["t"] >= frame["t"].iloc[-1] - 20.0]
        return {**spec, "steady_speed": float(metrics["steady_speed"]),
                "surge_mean": float(last["u"].mean()), "sway_mean": float(last["v"].mean()),
                "rudder_mean_deg": math.degrees(float(last["rudder"].mean())),
                "rudder_saturated": float(np.mean(np.abs(last["rudder"]) > math.radians(34.0))),
                "heading_error_rms_deg": math.degrees(float(metrics["heading_error_rms"])),
                "wall_time": clock()}
    d_t, d_m = PAPER_D_T * s["scale"], PAPER_D_M * s["scale"]
    task = StartedPositionKeeping(seed=s["seed"], case=s["case"], start=tuple(s["start"]), d_target=d_t,
                                  d_prearrival=d_m, heading_deg=s["heading_deg"], surge=s["surge"])
    if s["world"] == "paper":
        world = VielWorld(params=VielParams(p1=s["p1"], rudder_law=s["rudder_law"]), wind=task.wind())
        physics = VielPhysics.for_control(world, s["dt"])
    else:  # as sailmujoco.suite.load builds the MuJoCo world
        physics = BoatPhysics.load(params=get_boat(s["world"]), sail_mode="actuated", wind=task.wind(),
                                   forces=ForceSwitches(hydrostatics="geometric"), dofs=6)
    env = SailEnvironment(physics, task, time_limit=s["duration"], control_timestep=s["dt"],
                          legacy_step=False)
    policy = sweep.make_controller("viel", env, **{**PAPER_GAINS, "d_T": d_t, "d_M": d_m})
    every = max(1, int(round(1.0 / (TRAJECTORY_RATE * s["dt"]))))
    samples = _Samples(policy, every)
    _episode(env, policy, samples.sample, samples.sample_row, every)
    metrics = env.task.metrics()
    out = {**spec, "d_T": d_t, "d_M": d_m, "status": "stopped" if metrics.get("stopped") else "ok",
           **{k: float(metrics[k]) for k in ("entered_at", "max_distance_after_entry",
                                              "mean_distance_after_entry", "final_distance",
                                              "min_distance")},
           "trajectory": {"t": samples.t, "x": samples.x, "y": samples.y}, "wall_time": clock()}
    t, x, y = samples.t, samples.x, samples.y
    out.update(after_entry(np.array(t), elementwise(math.hypot, x, y), out["entered_at"], d_t))
    out.update(behaviour(np.array(t), samples.series, out["entered_at"],
                         math.radians(float(env.action_spec().maximum[0]))))
    out.update(drift_after_stop(np.array(t), np.array(x), np.array(y), samples.series, out["stopped_at"],
                                task.wind().direction_from))
    return out
