"""Environment steps per second through Gymnasium against the same loop through dm_env, and both
against the bare mj_step of the same model, in one run.

Run: python benchmarks/gym_speed.py [--seconds 3] [--boat saoud_robot] [--task heading_hold]

``gym``: ``env.step(action)`` of ``gymnasium.make("sailmujoco/<Boat>-<Task>-v0")`` with a fixed
action in the middle of the box, resetting when an episode ends; ``dm_env``: the same task from
``suite.load`` stepped with the same action (in radians); ``bare``: 20 ``mujoco.mj_step`` calls of
the same compiled model on a fresh MjData (what MuJoCo alone costs for a 0.1 s control step).
The three take turns in short blocks for ``--seconds`` of wall time each, after a warm-up, and
each rate is the median of its blocks, so that a slower spell of the machine falls on all three.
Printed: env-steps per second, and each control step's cost in bare control steps (its 20
sub-steps); the adapter's share is gym against dm_env.
"""

from __future__ import annotations

import argparse
import statistics
import time

import gymnasium
import mujoco
import numpy as np

import sailmujoco.gym  # noqa: F401  (registers the ids)
from sailmujoco import suite
from sailmujoco.gym import gym_id

BLOCK = 0.2  # s of wall time per block


def _rate(step, seconds: float) -> float:
    """Median calls per second of ``step`` over blocks of BLOCK seconds, ``seconds`` in all."""
    rates, end = [], time.perf_counter() + seconds
    while time.perf_counter() < end:
        n, start = 0, time.perf_counter()
        while time.perf_counter() - start < BLOCK:
            step()
            n += 1
        rates.append(n / (time.perf_counter() - start))
    return statistics.median(rates)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=3.0, help="wall seconds per loop")
    parser.add_argument("--boat", default="saoud_robot")
    parser.add_argument("--task", default="heading_hold")
    args = parser.parse_args()

    gym_env = gymnasium.make(gym_id(args.boat, args.task))
    gym_env.reset(seed=0)
    action = np.zeros(gym_env.action_space.shape, dtype=gym_env.action_space.dtype)

    def gym_step():
        _, _, terminated, truncated, _ = gym_env.step(action)
        if terminated or truncated:
            gym_env.reset()

    dm_env = suite.load(args.boat, args.task, seed=0)
    spec = dm_env.action_spec()
    dm_action = 0.5 * (spec.minimum + spec.maximum)
    dm_env.reset()

    def dm_step():
        if dm_env.step(dm_action).last():
            dm_env.reset()

    model = dm_env.physics.model.ptr
    data = mujoco.MjData(model)
    substeps = round(dm_env.control_timestep() / model.opt.timestep)

    def bare_step():
        for _ in range(substeps):
            mujoco.mj_step(model, data)

    for step in (gym_step, dm_step, bare_step):  # warm-up: compiles, caches
        for _ in range(50):
            step()
    rates = {"gym": [], "dm_env": [], "bare": []}
    for _ in range(3):
        for name, step in (("gym", gym_step), ("dm_env", dm_step), ("bare", bare_step)):
            rates[name].append(_rate(step, args.seconds / 3))
    gym_rate, dm_rate, bare_rate = (statistics.median(rates[k]) for k in ("gym", "dm_env", "bare"))
    print(f"{args.boat} {args.task}, a {dm_env.control_timestep():g} s control step "
          f"({substeps} sub-steps of {model.opt.timestep:g} s)")
    print(f"gymnasium  {gym_rate:8.0f} env-steps/s   {bare_rate / gym_rate:5.2f} bare control steps each")
    print(f"dm_env     {dm_rate:8.0f} env-steps/s   {bare_rate / dm_rate:5.2f} bare control steps each")
    print(f"bare       {bare_rate:8.0f} control steps/s of {substeps} mj_step")
    print(f"the Gymnasium adapter costs {dm_rate / gym_rate - 1.0:+.0%} of a dm_env step")
    gym_env.close()


if __name__ == "__main__":
    main()
