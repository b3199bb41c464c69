"""Cost of a whole episode through the compiled closed loop against the Python path.

Run: python benchmarks/closed_loop_speed.py [--repeats N] [--seconds S]

The pairs a compiled loop covers (``controllers/viel_loop.py``): Viel's position keeping at the
paper's 0.01 s control period (``studies/viel_fig3``), wind case 5, ``S`` simulated seconds, in
Viel's 3-DOF world and on viel_boat in 6 DOF. Measured in one run, interleaved round by round
(medians):

* ``bare``: ``mujoco.mj_step`` of Viel's boat's 6-DOF model, 2 steps of 5 ms per control step
  (the 6-DOF boat's physics alone for the same period), as ``paper_world_speed.py``;
* ``python``: the sweep runner's episode with ``SAILMUJOCO_PYTHON_LOOP=1`` (the Python path:
  ``env.step(controller(timestep))``);
* ``compiled``: the same episode through the compiled loop (the default).

Each is printed per control step in us and as a ratio to ``bare``; the episodes' metrics are
checked to be equal.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

import mujoco
import numpy as np

from sailmujoco.physics import BoatPhysics
from sailmujoco.sweep.runs import execute

DT = 0.01  # s, Viel's control period


WORLDS = (("Viel's 3-DOF world", "wille_yacht", "paper"), ("viel_boat, 6 DOF", "viel_boat", "mujoco"))


def episode(seconds: float, boat: str, world: str) -> dict:
    """The sweep runner's run of the pair, ``seconds`` long."""
    return {"run_id": "bench", "boat": boat, "task": "position_keeping", "world": world, "seed": 0,
            "duration": seconds, "boat_options": {}, "env_options": {"control_timestep": DT},
            "task_options": {"case": 5}, "controller": "viel",
            "controller_options": {"d_M": 14.0, "d_T": 7.0, "k_s": 5.0, "k_p": 1.0, "k_v": 8.0}}


def timed_episode(run: dict, python: bool) -> tuple[float, dict]:
    """(seconds of wall time, metrics) of one episode by the chosen path."""
    if python:
        os.environ["SAILMUJOCO_PYTHON_LOOP"] = "1"
    else:
        os.environ.pop("SAILMUJOCO_PYTHON_LOOP", None)
    start = time.perf_counter()
    record = execute(run)
    seconds = time.perf_counter() - start
    assert record["status"] == "ok", record["error"]
    return seconds, record["metrics"]


def bare_seconds(steps: int) -> float:
    """Wall time of ``steps`` bare mj_step of viel_boat's model."""
    physics = BoatPhysics.load("viel_boat")
    model = physics.model.ptr
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    data.ctrl[:] = [0.05, 0.4]
    start = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--seconds", type=float, default=60.0)
    args = parser.parse_args()
    steps = int(round(args.seconds / DT))
    runs = [episode(args.seconds, boat, world) for _, boat, world in WORLDS]
    for run in runs:  # compile (or load) the kernels
        timed_episode(run, python=False)
        timed_episode(run, python=True)
    bare = []
    python, compiled = [[] for _ in runs], [[] for _ in runs]
    for _ in range(args.repeats):
        bare.append(bare_seconds(2 * steps) / steps)
        for i, run in enumerate(runs):
            seconds, slow = timed_episode(run, python=True)
            python[i].append(seconds / steps)
            seconds, fast = timed_episode(run, python=False)
            compiled[i].append(seconds / steps)
            assert repr(slow) == repr(fast), "the compiled loop gave other metrics than the Python path"
    b = statistics.median(bare)
    print(f"{'per control step (0.01 s)':<40}{'us':>10}{'ratio':>8}")
    print(f"{'bare: 2 mj_step of viel_boat':<40}{b * 1e6:>10.1f}{1.0:>8.2f}")
    for (name, _, _), slow, fast in zip(WORLDS, python, compiled, strict=True):
        for path, values in (("python path", slow), ("compiled loop", fast)):
            value = statistics.median(values)
            print(f"{name + ': ' + path:<40}{value * 1e6:>10.1f}{value / b:>8.2f}")
    print(f"(Viel position keeping, case 5, {args.seconds:g} s episodes through the sweep runner, median of "
          f"{args.repeats} interleaved rounds; numpy {np.__version__}, mujoco {mujoco.__version__})")


if __name__ == "__main__":
    main()
