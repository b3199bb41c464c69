"""What a boat's instruments and fitted actuators add to a control step.

Run: python benchmarks/instruments_cost.py [--steps N] [--rounds R]

For (saoud_robot, speed_trial, saoud) and (wille_yacht, beam_reach_roll, wille_roll), a 0.1 s
control step (``action = controller(timestep); timestep = env.step(action)``) with
``sensors="perfect", actuators="perfect"`` (the observation as it always was) against the same
with ``"typical"`` for both, interleaved round by round in one run (medians), and the bare
``mujoco.mj_step`` of the control period's 20 sub-steps for scale. The goal: typical
instruments and actuators add at most 10 % to the control step.
"""

from __future__ import annotations

import argparse
import statistics
import time

import mujoco
import numpy as np
from sailmujoco.controllers import factories

from sailmujoco import suite
from sailmujoco.physics import BoatPhysics

PAIRS = (("saoud_robot", "speed_trial", "saoud"), ("wille_yacht", "beam_reach_roll", "wille_roll"))
FITS = ("perfect", "typical")


def episode(boat: str, task: str, controller: str, fit: str):
    """(env, controller, timestep) after 30 warm-up steps, with sensors and actuators ``fit``."""
    env = suite.load(boat, task, seed=0, sensors=fit, actuators=fit)
    policy = getattr(factories, controller)(env)
    policy.reset(0)
    timestep = env.reset()
    for _ in range(30):
        timestep = env.step(policy(timestep))
    return env, policy, timestep


def time_steps(env, policy, timestep, steps: int) -> tuple[float, object]:
    """Seconds per control step over ``steps`` steps (a new episode when one ends)."""
    start = time.perf_counter()
    for _ in range(steps):
        if timestep.last():
            timestep = env.reset()
        timestep = env.step(policy(timestep))
    return (time.perf_counter() - start) / steps, timestep


def bare_seconds(boat: str, steps: int) -> float:
    """Seconds per 20 bare mj_step of the boat's compiled model."""
    physics = BoatPhysics.load(boat)
    model = physics.model.ptr
    data = mujoco.MjData(model)
    start = time.perf_counter()
    for _ in range(steps * 20):
        mujoco.mj_step(model, data)
    return (time.perf_counter() - start) / steps


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=7)
    args = parser.parse_args()
    print("boat         bare 20 steps  perfect step  typical step  typical/perfect")
    for boat, task, controller in PAIRS:
        runs = {fit: list(episode(boat, task, controller, fit)) for fit in FITS}
        times = {fit: [] for fit in FITS}
        bare = []
        for _ in range(args.rounds):
            bare.append(bare_seconds(boat, args.steps // 3))
            for fit in FITS:
                seconds, runs[fit][2] = time_steps(*runs[fit], args.steps)
                times[fit].append(seconds)
        med = {fit: statistics.median(t) for fit, t in times.items()}
        print(f"{boat:12s} {statistics.median(bare) * 1e6:10.0f} us {med['perfect'] * 1e6:10.0f} us "
              f"{med['typical'] * 1e6:10.0f} us {med['typical'] / med['perfect']:10.3f}")
    print(f"(numpy {np.__version__}, mujoco {mujoco.__version__}; medians of {args.rounds} rounds)")


if __name__ == "__main__":
    main()
