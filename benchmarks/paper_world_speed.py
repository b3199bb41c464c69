"""Speed of a paper-world control step, as a ratio to the bare mj_step of the same control period.

Run: python benchmarks/paper_world_speed.py [--repeats N]

Measured in this run, interleaved (median of ``--repeats`` rounds): "bare" is ``mujoco.mj_step``
on a fresh MjData of the 6-DOF boat the world stands in for, times the number of 5 ms physics
steps in the control period (Wille's yacht for the Wille 4-DOF world, Viel's boat for the Viel
3-DOF world, as ``studies/viel_fig3.py`` picks it); "world" is one control step of the paper
world: ``Wille4DOF.step(n)`` (the suite's 0.1 s: ``PaperPhysics``) and ``VielWorld.step(action,
dt)`` at Viel's 0.01 s (``studies/viel_fig3``) and the suite's 0.1 s, in gusty, wandering wind.
"""

from __future__ import annotations

import argparse
import math
import statistics
import time

import mujoco
import numpy as np

from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics
from sailmujoco.reference.viel import VielWorld
from sailmujoco.reference.wille import Wille4DOF

PHYSICS_DT = 0.005  # s, the boats' MuJoCo time step
WIND = WindConfig(speed=8.0, direction_from=math.radians(45.0), seed=0)


def bare_step(boat: str):
    """A function running ``n`` bare mj_step of ``boat``'s model."""
    physics = BoatPhysics.load(boat, wind=WIND)
    model = physics.model.ptr
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    data.ctrl[:] = [0.05, 0.4]

    def run(n):
        for _ in range(n):
            mujoco.mj_step(model, data)
    return run


def wille_step(model: str):
    world = Wille4DOF(wind=WIND, model=model)

    def start():
        world.reset()
        world.set_state_ours(u=3.0, sail=0.5)
        world.set_control([0.02, 0.5])

    def run(n):
        if world.time() > 30.0:  # restart now and then, as an episode would
            start()
        world.step(n)
    start()
    return run


def viel_step(dt: float):
    world = VielWorld(wind=WIND)
    start = np.array([0.0, 0.0, 0.3, 1.0, 0.0, 0.0])
    world.reset(start)
    action = np.array([0.05, 0.6])

    def run(_n):
        if world.time > 10.0:  # restart now and then (held controls end astern and spinning)
            world.reset(start)
        world.step(action, dt)
    return run


def per_call_us(fn, n_sub: int, calls: int) -> float:
    start = time.perf_counter()
    for _ in range(calls):
        fn(n_sub)
    return (time.perf_counter() - start) / calls * 1e6


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--calls", type=int, default=300, help="control steps per timing")
    args = parser.parse_args()
    bare = {"wille_yacht": bare_step("wille_yacht"), "viel_boat": bare_step("viel_boat")}
    # (label, world step, physics steps per control period, boat it stands in for)
    cases = [("Wille 4-DOF paper, 0.1 s", wille_step("paper"), 20, "wille_yacht"),
             ("Wille 4-DOF rigid, 0.1 s", wille_step("rigid"), 20, "wille_yacht"),
             ("Viel 3-DOF, 0.01 s", viel_step(0.01), 2, "viel_boat"),
             ("Viel 3-DOF, 0.1 s", viel_step(0.1), 20, "viel_boat")]
    for _, fn, n, boat in cases:  # warm up (JIT or cache load)
        fn(n)
        bare[boat](n)
    samples = {label: ([], []) for label, *_ in cases}
    for _ in range(args.repeats):
        for label, fn, n, boat in cases:
            samples[label][0].append(per_call_us(fn, n, args.calls))
            samples[label][1].append(per_call_us(bare[boat], n, args.calls))
    print(f"{'paper world, control period':28s} {'world step':>11s} {'bare mj_step x n':>17s} {'ratio':>6s}")
    for label, _fn, n, _boat in cases:
        world_us = statistics.median(samples[label][0])
        bare_us = statistics.median(samples[label][1])
        print(f"{label:28s} {world_us:8.1f} us {bare_us:10.1f} us ({n:2d}) {world_us / bare_us:6.2f}")
    print(f"(medians of {args.repeats} interleaved rounds of {args.calls} control steps; "
          f"mujoco {mujoco.__version__}; ratio = world / bare)")


if __name__ == "__main__":
    main()
