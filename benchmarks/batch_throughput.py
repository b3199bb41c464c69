"""Boat-steps per second against the number of boats stepped together, as ratios to bare MuJoCo.

Run: python benchmarks/batch_throughput.py [--sizes 1 10 100 1000] [--plot docs/throughput_vs_n.png]

For each N, N Saoud robots (all forces on, geometric hydrostatics, gusty wind, each its own
seed) step 0.1 s control periods (20 sub-steps) through :class:`sailmujoco.batch.BoatBatch`,
one compiled call per control period on all cores (numba threads), and one at a time through
``BoatPhysics.step(20)`` for comparison. "bare" is ``mujoco.mj_step`` of the same model on one
MjData in one thread, measured in the same run: the ratio 1.0 means "as fast as bare MuJoCo,
single-threaded"; on k cores the batch can exceed it.
"""

from __future__ import annotations

import argparse
import math
import os
import time

import mujoco
import numpy as np

from sailmujoco.batch import BoatBatch
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics


def robots(n: int) -> list[BoatPhysics]:
    boats = []
    for seed in range(n):
        wind = WindConfig(speed=3.0, direction_from=math.radians(30.0 + seed % 90), seed=seed)
        physics = BoatPhysics.load("saoud_robot", wind=wind)
        physics.set_control([0.05, 0.5])
        boats.append(physics)
    return boats


def bare_rate(model, seconds: float = 1.0) -> float:
    """Single-thread bare mj_step calls per second (best of 3)."""
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    data.ctrl[:] = [0.05, 0.5]
    best = 0.0
    for _ in range(3):
        count, start = 0, time.perf_counter()
        while time.perf_counter() - start < seconds / 3:
            for _ in range(200):
                mujoco.mj_step(model, data)
            count += 200
        best = max(best, count / (time.perf_counter() - start))
    return best


def batch_rate(boats, periods: int) -> float:
    batch = BoatBatch(boats)
    batch.step(20)  # warm up
    start = time.perf_counter()
    for _ in range(periods):
        batch.step(20)
    return len(boats) * 20 * periods / (time.perf_counter() - start)


def solo_rate(boats, periods: int) -> float:
    for b in boats:
        b.step(20)
    start = time.perf_counter()
    for _ in range(periods):
        for b in boats:
            b.step(20)
    return len(boats) * 20 * periods / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[1, 10, 100, 1000])
    parser.add_argument("--plot", default=None, help="write a PNG of throughput against N")
    args = parser.parse_args()
    rows = []
    model = None
    for n in args.sizes:
        boats = robots(n)
        model = boats[0].model.ptr
        periods = max(3, 2000 // n)
        bare = bare_rate(model)
        together = batch_rate(boats, periods)
        alone = solo_rate(robots(min(n, 100)), max(3, 2000 // min(n, 100)))
        rows.append((n, bare, together, alone))
        print(f"N={n:5d}  bare {bare:9.0f}/s  batch {together:9.0f} boat-steps/s "
              f"({together / bare:4.2f} x bare)  one at a time {alone:9.0f}/s "
              f"({alone / bare:4.2f} x bare)", flush=True)
    print(f"({os.cpu_count()} cores; numpy {np.__version__}, mujoco {mujoco.__version__})")
    if args.plot:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        n = [r[0] for r in rows]
        fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
        ax.plot(n, [r[2] / r[1] for r in rows], "o-", label="batched (BoatBatch, all cores)")
        ax.plot(n, [r[3] / r[1] for r in rows], "s--", label="one at a time (step(20))")
        ax.axhline(1.0, color="0.5", lw=0.8)
        ax.set_xscale("log")
        ax.set_xlabel("boats stepped together N [-]")
        ax.set_ylabel("boat-steps per second / bare mj_step rate [-]")
        ax.set_title(f"Saoud robot, all forces, {os.cpu_count()} cores")
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=2)
        fig.savefig(args.plot, dpi=120)
        print(f"wrote {args.plot}")


if __name__ == "__main__":
    main()
