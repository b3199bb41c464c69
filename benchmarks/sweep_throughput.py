"""Sweep throughput with 1 and 2 worker processes of the embedded Dask cluster.

Run: python benchmarks/sweep_throughput.py [--runs N] [--duration S]

Prints runs per minute and simulated seconds per wall-clock second for each worker count and
the speed-up of 2 workers over 1 (the cluster's start-up is excluded: it is started, warmed
with one run per worker, then timed). Same sweep, same machine, same run.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

from dask.distributed import Client, LocalCluster

from sailmujoco import sweep


def spec(runs: int, duration: float) -> dict:
    return {"name": "throughput", "boat": "saoud_robot", "task": "heading_hold", "world": "mujoco",
            "controller": "pid", "duration": duration, "seeds": list(range(runs)),
            "metrics": ["mean_surge"]}


def measure(workers: int, runs: int, duration: float) -> float:
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        with tempfile.TemporaryDirectory() as warm:  # import and JIT-load in every worker
            sweep.run(spec(workers, 2.0), warm, scheduler=cluster.scheduler_address,
                      progress=False)
        client.run(lambda: None)
        with tempfile.TemporaryDirectory() as out:
            start = time.perf_counter()
            table = sweep.run(spec(runs, duration), out, scheduler=cluster.scheduler_address,
                              progress=False)
            elapsed = time.perf_counter() - start
    assert (table["status"] == "ok").all()
    return elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=24)
    parser.add_argument("--duration", type=float, default=60.0)
    args = parser.parse_args()
    print(f"{args.runs} runs of {args.duration:g} s (saoud_robot, heading_hold, mujoco, pid) "
          f"on {os.cpu_count()} cores")
    times = {}
    for workers in (1, 2):
        elapsed = measure(workers, args.runs, args.duration)
        times[workers] = elapsed
        print(f"{workers} worker(s): {elapsed:6.1f} s wall, {60 * args.runs / elapsed:6.1f} runs/min, "
              f"{args.runs * args.duration / elapsed:7.1f} simulated s per wall s")
    print(f"speed-up 2 workers / 1 worker: {times[1] / times[2]:.2f}x")


if __name__ == "__main__":
    main()
