"""What a lock-step control step of ``sailmujoco ros2`` costs with an rclpy node answering it,
against the bare step of the same model.

Run, with a Python that has rclpy (docs/ros2.md's ``.venv-ros``), as root or where user
namespaces are allowed (DDS stays inside a loopback-only network namespace)::

    .venv-ros/bin/python benchmarks/ros2_lockstep.py [--seconds 120] [--rounds 3]

Each round runs the bridge (the 11:Metre, a wind from the east) and docs/ros2.md's heading-hold
node in a fresh namespace and reads the bridge's own count: control steps and the wall time from
its first publication to its last. The same run measures the bare ``mujoco.mj_step`` of the
boat's compiled model (medians). A control step is 0.1 s of sim time: the physics' steps in it,
the instruments, nine messages each way through DDS and both processes' Python; its cost over
the bare step's says where the time goes, and 0.1 s over it is the speed against real time.
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import mujoco

from sailmujoco.physics import BoatPhysics

ROOT = Path(__file__).resolve().parents[1]
BOAT = "eleven_metre"


def lockstep_round(seconds: float) -> tuple[int, float]:
    """(control steps, wall seconds) of one lock-step run of ``seconds`` simulated."""
    legs = f"0:{seconds / 2:g},300:{seconds / 2:g}"
    script = (f'"$1" -m sailmujoco ros2 {BOAT} --set wind_from_deg=90 --seconds {seconds:g} & '
              f'"$1" {ROOT}/examples/ros2/heading_hold.py --legs {legs} > /dev/null; wait $!')
    env = {**os.environ, "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST", "ROS_DOMAIN_ID": "42",
           "SAILMUJOCO_QUIET": "1"}
    done = subprocess.run(["unshare", "-rn", "sh", "-c", 'ip link set lo up && sh -c "$0" sh "$@"', script,
                           sys.executable], capture_output=True, text=True, env=env, timeout=600)
    found = re.search(r"(\d+) steps \(([0-9.]+) s simulated\) in ([0-9.]+) s", done.stdout)
    if done.returncode != 0 or found is None:
        sys.exit(f"the bridge did not finish: {done.stderr.strip()[-400:]}")
    return int(found.group(1)), float(found.group(3))


def bare_seconds(steps: int) -> tuple[float, float]:
    """(seconds per bare mj_step of the boat's compiled model, its time step)."""
    physics = BoatPhysics.load(BOAT)
    model = physics.model.ptr
    data = mujoco.MjData(model)
    t0 = time.perf_counter()
    for _ in range(steps):
        mujoco.mj_step(model, data)
    return (time.perf_counter() - t0) / steps, physics.timestep()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seconds", type=float, default=120.0, help="simulated seconds a round")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    try:
        import rclpy  # noqa: F401
    except ImportError:
        sys.exit("this Python has no rclpy: run it with docs/ros2.md's .venv-ros/bin/python")
    lock, bare = [], []
    for _ in range(args.rounds):
        bare_step, dt = bare_seconds(20000)
        bare.append(bare_step)
        steps, wall = lockstep_round(args.seconds)
        lock.append(wall / steps)
    c, b = statistics.median(lock), statistics.median(bare)
    print("boat          bare mj_step   control step (0.1 s)   control/bare   physics steps in it   "
          "times real time")
    print(f"{BOAT:12s} {b * 1e6:10.1f} us {c * 1e3:14.2f} ms {c / b:14.0f} {0.1 / dt:16.0f} "
          f"{0.1 / c:19.1f}")
    print(f"(mujoco {mujoco.__version__}; medians of {args.rounds} rounds of {args.seconds:g} s simulated)")


if __name__ == "__main__":
    main()
