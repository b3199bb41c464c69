"""Cost of one control step through the task API, as a ratio to the bare mj_step of its sub-steps.

Run: python benchmarks/control_step_speed.py [--steps N] [--rounds R] [--world mujoco|paper]
[--dofs 6|4]

For (saoud_robot, speed_trial, saoud) and (wille_yacht, beam_reach_roll, wille_roll), a 0.1 s
control step is ``action = controller(timestep); timestep = env.step(action)`` on
``suite.load(...)``. Measured in the same run, interleaved round by round (medians):

* ``bare``: 20 calls of ``mujoco.mj_step`` on a fresh MjData of the same compiled model (no
  force models, no added mass): what MuJoCo alone costs for the control period;
* ``total``: the control step, uninstrumented;
* its parts, from a second, instrumented episode: ``physics`` (``physics.step(20)``),
  ``observation`` (the task's measurement of the state, wherever it is first asked for),
  ``recording`` (``after_step``: what the metrics keep), ``controller``
  (``controller(timestep)``), and ``plumbing``: the rest of that episode's step (dm_control's
  step, action checks, reward, termination, the TimeStep, and the clocks themselves).

Ratios are to ``bare``; the issue's target for the total is 2 (3 is the floor). Timings on a
shared machine are noisy: compare ratios within one run. ``--world paper`` runs the same tasks
and controllers in Wille's 4-DOF paper world (bare: the 6-DOF boat's 20 mj_step, as
``paper_world_speed.py``); ``--dofs 4`` the MuJoCo boats with heave and pitch held.
"""

from __future__ import annotations

import argparse
import statistics
import time

import mujoco
import numpy as np
from sailmujoco.controllers import factories

from sailmujoco import suite
from sailmujoco.options import Dofs, World, choices
from sailmujoco.physics import BoatPhysics

PAIRS = (("saoud_robot", "speed_trial", "saoud"), ("wille_yacht", "beam_reach_roll", "wille_roll"))
PARTS = ("physics", "observation", "controller", "recording")


def episode(boat: str, task: str, controller: str, seed: int = 0, world: str = "mujoco",
            dofs: int = 6):
    """(env, controller, first timestep), warmed up by 30 control steps (JIT, caches)."""
    env = suite.load(boat, task, world, seed=seed, **({"dofs": dofs} if world == "mujoco" else {}))
    policy = getattr(factories, controller)(env)
    policy.reset(seed)
    timestep = env.reset()
    for _ in range(30):
        timestep = env.step(policy(timestep))
    return env, policy, timestep


class Clocked:
    """Wraps a method and adds its wall time to ``totals[name]``; the time of a clocked call
    made inside it counts for that call's part, not this one (a stack of running clocks)."""

    running: list = []

    def __init__(self, totals: dict, name: str, fn):
        self.totals, self.name, self.fn = totals, name, fn

    def __call__(self, *args):
        start = time.perf_counter()
        self.running.append(self)
        try:
            return self.fn(*args)
        finally:
            self.running.pop()
            elapsed = time.perf_counter() - start
            self.totals[self.name] += elapsed
            if self.running:
                self.totals[self.running[-1].name] -= elapsed


def instrument(env, policy, totals: dict):
    """Clock the parts of a control step on this env (instance attributes shadow the methods)."""
    physics, task = env.physics, env.task
    physics.step = Clocked(totals, "physics", physics.step)
    task.after_step = Clocked(totals, "recording", task.after_step)
    task.get_observation = Clocked(totals, "observation", task.get_observation)
    if hasattr(task, "measurement"):  # the measurement of the state, wherever it is first asked for
        task.measurement = Clocked(totals, "observation", task.measurement)
    return Clocked(totals, "controller", policy)


def measure(boat: str, task: str, controller: str, steps: int, rounds: int, world: str = "mujoco",
            dofs: int = 6) -> dict:
    env, policy, timestep = episode(boat, task, controller, world=world, dofs=dofs)
    env_i, policy_i, timestep_i = episode(boat, task, controller, world=world, dofs=dofs)
    model = (env.physics if world == "mujoco" else BoatPhysics.load(boat)).model.ptr
    bare = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, bare, 0)
    bare.ctrl[:] = [0.05, 0.4]
    n_sub = int(round(env.control_timestep() / model.opt.timestep))
    totals = dict.fromkeys(PARTS, 0.0)
    clocked = instrument(env_i, policy_i, totals)
    samples: dict[str, list[float]] = {
        k: [] for k in ("bare", "total", "instrumented", *PARTS, "plumbing")}
    for _ in range(rounds):
        start = time.perf_counter()
        for _ in range(steps * n_sub):
            mujoco.mj_step(model, bare)
        samples["bare"].append((time.perf_counter() - start) / steps)
        start = time.perf_counter()
        for _ in range(steps):
            timestep = env.step(policy(timestep))
            if timestep.last():
                timestep = env.step(policy(env.reset()))
        samples["total"].append((time.perf_counter() - start) / steps)
        for key in totals:
            totals[key] = 0.0
        start = time.perf_counter()
        for _ in range(steps):
            timestep_i = env_i.step(clocked(timestep_i))
            if timestep_i.last():
                timestep_i = env_i.step(clocked(env_i.reset()))
        samples["instrumented"].append((time.perf_counter() - start) / steps)
        for key in PARTS:
            samples[key].append(totals[key] / steps)
        samples["plumbing"].append(samples["instrumented"][-1] - sum(totals.values()) / steps)
    return {key: statistics.median(values) * 1e6 for key, values in samples.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=200, help="control steps per round")
    parser.add_argument("--rounds", type=int, default=7)
    parser.add_argument("--world", choices=choices(World), default="mujoco")
    parser.add_argument("--dofs", type=int, choices=choices(Dofs), default=6,
                        help="MuJoCo world: 6 (default) or 4 (heave and pitch held)")
    args = parser.parse_args()
    columns = ("total", *PARTS, "plumbing")
    print(f"{'boat + controller':26s} {'bare 20 mj_step':>16s} "
          + " ".join(f"{c:>16s}" for c in columns))
    for boat, task, controller in PAIRS:
        r = measure(boat, task, controller, args.steps, args.rounds, args.world, args.dofs)
        cells = " ".join(f"{r[c]:8.1f} us {r[c] / r['bare']:5.2f}" for c in columns)
        print(f"{boat + ' + ' + controller:26s} {r['bare']:13.1f} us {cells}")
    print(f"({args.world} world, {args.dofs if args.world == 'mujoco' else 4} DOF; us per control "
          f"step, median of {args.rounds} interleaved rounds of {args.steps} steps; "
          f"ratio = time / bare; numpy {np.__version__}, mujoco {mujoco.__version__})")


if __name__ == "__main__":
    main()
