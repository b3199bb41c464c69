"""Cost of a sea: ``step(20)`` of each boat in a JONSWAP sea, as a ratio to the same boat's
``step(20)`` in calm water and to the bare ``mj_step`` of the same model, all in this run.

Run: python benchmarks/sea_step_speed.py [--hs 1.5] [--tp 6] [--components 100] [--seconds 2]

"calm" is ``BoatPhysics.step(20)`` without a sea (the calm-water kernel, bit for bit as
without the option); "sea" the same with ``waves=WaveConfig(spectrum="jonswap", hs, tp,
n_components)``: at every RK4 stage the Froude-Krylov pressure on every hull column for every
component, and the orbital flow at the keel and the rudder. "bare" is 20 ``mujoco.mj_step``
calls on a fresh MjData of the same model. The three take turns in short blocks (``BLOCK``
seconds each) for ``--seconds`` of wall time in all, after one warm-up call each; each cost is
the median of its blocks' means, and each ratio the median of the ratios of blocks taken side
by side, so that a slower or faster spell of the machine (another process, the clock's
frequency) falls on all three alike.
"""

from __future__ import annotations

import argparse
import statistics
import time

import mujoco

from sailmujoco.boat.catalogue import BUILT_IN
from sailmujoco.options import N_COMPONENTS, WaveConfig
from sailmujoco.physics import BoatPhysics

BLOCK = 0.05  # s, the wall time of one block of calls


def block_mean(call, budget: float) -> float:
    """Mean wall seconds of ``call()`` over about ``budget`` seconds."""
    start, n = time.perf_counter(), 0
    while time.perf_counter() - start < budget:
        call()
        n += 1
    return (time.perf_counter() - start) / n


def interleaved(calls: dict, seconds: float) -> dict:
    """Each call's block means, the calls taking turns in blocks of ``BLOCK`` seconds for about
    ``seconds`` in all, after one warm-up call each: name -> list of mean wall seconds per call."""
    for call in calls.values():
        call()
    out = {name: [] for name in calls}
    for _ in range(max(1, round(seconds / (BLOCK * len(calls))))):
        for name, call in calls.items():
            out[name].append(block_mean(call, BLOCK))
    return out


def median_ratio(a: list, b: list) -> float:
    """The median of a[i] / b[i], blocks taken side by side."""
    return statistics.median(x / y for x, y in zip(a, b, strict=True))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hs", type=float, default=1.5, help="significant wave height, m")
    parser.add_argument("--tp", type=float, default=6.0, help="peak period, s")
    parser.add_argument("--components", type=int, default=N_COMPONENTS, help="wave components")
    parser.add_argument("--seconds", type=float, default=2.0, help="wall seconds per timing")
    args = parser.parse_args()
    sea = WaveConfig(spectrum="jonswap", hs=args.hs, tp=args.tp, n_components=args.components)
    print(f"step(20), JONSWAP hs {args.hs:g} m, tp {args.tp:g} s, {args.components} components; "
          "ratios in this run")
    print(f"{'boat':12s} {'bare':>9s} {'calm':>9s} {'sea':>10s} {'sea/calm':>9s} {'sea/bare':>9s}")
    for boat in BUILT_IN:
        calm, rough = BoatPhysics.load(boat), BoatPhysics.load(boat, waves=sea)
        model = calm.model.ptr
        bare_data = mujoco.MjData(model)
        mujoco.mj_resetDataKeyframe(model, bare_data, 0)

        def bare(model=model, data=bare_data):
            for _ in range(20):
                mujoco.mj_step(model, data)

        t = interleaved({"bare": bare, "calm": lambda p=calm: p.step(20), "sea": lambda p=rough: p.step(20)},
                        3 * args.seconds)
        median = {name: statistics.median(values) for name, values in t.items()}
        print(f"{boat:12s} {median['bare'] * 1e3:7.3f}ms {median['calm'] * 1e3:7.3f}ms "
              f"{median['sea'] * 1e3:8.3f}ms "
              f"{median_ratio(t['sea'], t['calm']):8.2f}x {median_ratio(t['sea'], t['bare']):8.2f}x")


if __name__ == "__main__":
    main()
