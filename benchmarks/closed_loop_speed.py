"""Cost of a whole episode through the compiled closed loop against the Python path.

Run: python benchmarks/closed_loop_speed.py [--repeats N] [--seconds S]

The pair the compiled loop covers (``sailmujoco.loop``): Viel's position keeping in Viel's
3-DOF world at the paper's 0.01 s control period (``studies/viel_fig3``'s paper column), wind
case 5, ``S`` simulated seconds. Measured in one run, interleaved round by round (medians):

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


def episode(seconds: float) -> dict:
    """The sweep runner's run of the pair, ``seconds`` long."""
    return {"run_id": "bench", "boat": "wille_yacht", "task": "position_keeping", "world": "paper", "seed": 0,
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
    run = episode(args.seconds)
    steps = int(round(args.seconds / DT))
    timed_episode(run, python=False)  # compile (or load) the kernels
    timed_episode(run, python=True)
    bare, python, compiled = [], [], []
    for _ in range(args.repeats):
        bare.append(bare_seconds(2 * steps) / steps)
        seconds, slow = timed_episode(run, python=True)
        python.append(seconds / steps)
        seconds, fast = timed_episode(run, python=False)
        compiled.append(seconds / steps)
        assert repr(slow) == repr(fast), "the compiled loop gave other metrics than the Python path"
    b = statistics.median(bare)
    print(f"{'per control step (0.01 s)':<28}{'us':>10}{'ratio':>8}")
    for name, values in (("bare 2 mj_step (viel_boat)", bare), ("python path", python),
                         ("compiled loop", compiled)):
        value = statistics.median(values)
        print(f"{name:<28}{value * 1e6:>10.1f}{value / b:>8.2f}")
    print(f"(Viel position keeping in Viel's world, case 5, {args.seconds:g} s episodes, median of "
          f"{args.repeats} interleaved rounds; numpy {np.__version__}, mujoco {mujoco.__version__})")


if __name__ == "__main__":
    main()
