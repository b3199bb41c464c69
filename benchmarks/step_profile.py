"""Where a step's time goes: each part of a sub-step as a fraction of the bare mj_step.

Run: python benchmarks/step_profile.py [--boats B ...] [--hydrostatics paper geometric]
[--control] [--repeats N]

Per boat and hydrostatics, measured in this run on the same compiled MjModel (best of
``--repeats``; the machine's noise moves each cell by a few hundredths):

* ``bare``: ``mujoco.mj_step`` on a fresh MjData (no force models, no added mass), the unit;
* ``step(20)``: :meth:`BoatPhysics.step` with every force, per sub-step; ``forces off``: the
  same with every force switched off (``ForceSwitches``), so the compiled loop, the stage
  callback and ``mj_factorM`` alone;
* per RK4stage, each times 4 (a sub-step has four stages) and divided by the bare step:
  ``mj_factorM`` (the refactorisation after the added mass, timed in a compiled loop);
  ``callback``: the rest of the stage callback's cost (the cfunc call, the registry lookup,
  the counters), i.e. (forces off - bare) / 4 - kernel with everything off - mj_factorM;
  ``kernel off``: the force kernel with every model off (state checks, rotation, zeroing);
  then each force model alone, as the kernel with that model on minus the kernel with all
  off (timed in a compiled loop at RK4's stage times t, t + h/2, t + h/2, t + h, so the gust
  cosines' cache works as in a step): hydrostatics, keel, rudder, sail (with the wind at the
  sail), damping with the Delft residuary resistance (``resistance`` also alone: dsyhs minus
  friction), added mass, windage (with the wind at topsides and mast); ``wind`` is the wind's
  evaluation at the three heights alone (``wind_velocities``), part of sail and windage;
  ``kernel all``: the kernel with every model, which the parts should roughly sum to.

``--control`` adds the closed-loop control step (benchmarks/control_step_speed.py's parts,
robot + saoud and yacht + wille_roll, against their bare sub-steps): physics, the task's
measurement, the controller, the recording and the rest of the Python per control step.
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import time
from dataclasses import replace
from pathlib import Path

import mujoco
import numba
import numpy as np

from sailmujoco.forces import boat as kernels
from sailmujoco.forces.wind import WindConfig
from sailmujoco.forces.wind_kernels import wind_velocities
from sailmujoco.physics import BoatPhysics, ForceSwitches
from sailmujoco.step.mujoco_calls import mj_factorM, pointer

_boat_forces = kernels.boat_forces
OFF = ForceSwitches(hydrostatics="off", sail=False, keel=False, rudder=False, damping=False,
                    added_mass=False, windage=False)


@numba.njit
def _kernel_loop(n, t0, h, args):
    """The force kernel ``n`` times at RK4's stage times (no added mass into M)."""
    status = 0
    for i in range(n):
        stage = i % 4
        t = t0 + (i // 4) * h + (0.0, 0.5 * h, 0.5 * h, h)[stage]
        status += _boat_forces(t, *args, False)
    return status


@numba.njit
def _wind_loop(n, t0, h, z0, z1, z2, speed, frm, osc, gf, gp, ga, lz, wdt, wander, cache, out):
    for i in range(n):
        stage = i % 4
        t = t0 + (i // 4) * h + (0.0, 0.5 * h, 0.5 * h, h)[stage]
        wind_velocities(t, z0, z1, z2, 3, speed, frm, osc, gf, gp, ga, lz, wdt, wander, cache, out)
    return out[0]


@numba.njit
def _factor_loop(n, m, d):
    for _ in range(n):
        mj_factorM(pointer(m), pointer(d))


def best_of(fn, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


WIND = WindConfig(speed=8.0, direction_from=math.radians(45.0), seed=0)


def load(boat: str, forces: ForceSwitches) -> BoatPhysics:
    physics = BoatPhysics.load(boat, wind=WIND, forces=forces)
    physics.set_control([0.05, 0.4])
    physics.step(200)  # warm up (compile or load the cache), sail off the keyframe
    physics._prepare(1.0)
    return physics


def kernel_time(physics: BoatPhysics, n: int, repeats: int) -> float:
    """Seconds per call of the force kernel on ``physics``'s arrays and switches."""
    h = physics.model.opt.timestep
    args = tuple(physics._args)
    t0 = physics.data.time
    _kernel_loop(10, t0, h, args)
    # restore the gust cache's time between repeats: each repeat starts with a stale cache
    return best_of(lambda: _kernel_loop(n, t0, h, args), repeats) / n


def profile(boat: str, hydrostatics: str, steps: int, n: int, repeats: int) -> dict:
    full_forces = ForceSwitches(hydrostatics=hydrostatics)
    physics = load(boat, full_forces)
    off = load(boat, OFF)
    model = physics.model.ptr
    bare = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, bare, 0)
    bare.ctrl[:] = [0.05, 0.4]

    def run_bare():
        for _ in range(steps):
            mujoco.mj_step(model, bare)

    def stepper(p):
        def run():
            for _ in range(steps // 20):
                p.step(20)
        return run

    r = {}
    r["bare"] = best_of(run_bare, repeats) / steps
    r["step(20)"] = best_of(stepper(physics), repeats) / (steps // 20 * 20)
    r["forces off"] = best_of(stepper(off), repeats) / (steps // 20 * 20)
    d = physics.data.ptr
    _factor_loop(10, model._address, d._address)
    r["mj_factorM"] = best_of(lambda: _factor_loop(n, model._address, d._address), repeats) / n
    r["kernel off"] = kernel_time(off, n, repeats)
    r["callback"] = (r["forces off"] - r["bare"]) / 4 - r["kernel off"] - r["mj_factorM"]
    alone = {
        f"hydrostatics {hydrostatics}": replace(OFF, hydrostatics=hydrostatics),
        "keel": replace(OFF, keel=True),
        "rudder": replace(OFF, rudder=True),
        "sail (+ wind at 1 height)": replace(OFF, sail=True),
        "damping + resistance": replace(OFF, damping=True),
        "damping, friction only": replace(OFF, damping=True, resistance="friction"),
        "added mass": replace(OFF, added_mass=True),
        "windage (+ wind at 2)": replace(OFF, windage=True),
    }
    for name, forces in alone.items():
        r[name] = kernel_time(load(boat, forces), n, repeats) - r["kernel off"]
    r["resistance (dsyhs)"] = r["damping + resistance"] - r["damping, friction only"]
    w = physics.wind
    out = np.zeros(9)
    h = model.opt.timestep
    wind_args = (8.0, math.radians(45.0), w.oscillation, w.gust_frequency, w.gust_phase,
                 w.gust_amplitude, w.log_z, physics._P[kernels.P_WANDER_DT], w.wander, w.gust_cos, out)
    _wind_loop(10, d.time, h, 3.0, 0.8, 4.0, *wind_args)
    r["wind (3 heights)"] = best_of(lambda: _wind_loop(n, d.time, h, 3.0, 0.8, 4.0, *wind_args),
                                    repeats) / n
    r["kernel all"] = kernel_time(physics, n, repeats)
    return r


ROWS_SUBSTEP = ("step(20)", "forces off")
ROWS_STAGE = ("mj_factorM", "callback", "kernel off")


def print_profile(results: list) -> None:
    head = [f"{b[:6]} {h[:4]}" for b, h, _ in results]
    print(f"{'part (x bare mj_step; per stage parts x4)':44s} " + " ".join(f"{c:>12s}" for c in head))
    print(f"{'bare mj_step, us':44s} " + " ".join(f"{r['bare'] * 1e6:12.2f}" for *_, r in results))
    for key in ROWS_SUBSTEP:
        print(f"{key + ' per sub-step':44s} " + " ".join(f"{r[key] / r['bare']:12.2f}" for *_, r in results))
    keys = [k for k in results[0][2] if k not in ("bare", *ROWS_SUBSTEP)]
    for key in [*ROWS_STAGE, *[k for k in keys if k not in ROWS_STAGE]]:
        if key.startswith("hydrostatics"):
            cells = [4 * r[k] / r["bare"] for *_, r in results for k in r if k.startswith("hydrostatics")]
            key = "hydrostatics (the column's mode)"
        else:
            cells = [4 * r[key] / r["bare"] for *_, r in results]
        print(f"{key:44s} " + " ".join(f"{c:12.2f}" for c in cells))


def control_profile(steps: int, rounds: int) -> None:
    path = Path(__file__).with_name("control_step_speed.py")
    spec = importlib.util.spec_from_file_location("control_step_speed", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    columns = ("total", *module.PARTS, "plumbing")
    print(f"\n{'control step (x its bare sub-steps)':34s} " + " ".join(f"{c:>12s}" for c in columns))
    for boat, task, controller in module.PAIRS:
        r = module.measure(boat, task, controller, steps, rounds)
        print(f"{boat + ' + ' + controller:34s} " + " ".join(f"{r[c] / r['bare']:12.2f}" for c in columns))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--boats", nargs="+", default=["wille_yacht", "saoud_robot", "viel_boat"])
    parser.add_argument("--hydrostatics", nargs="+", default=["paper", "geometric"])
    parser.add_argument("--steps", type=int, default=4000, help="sub-steps per timing")
    parser.add_argument("--calls", type=int, default=20000, help="kernel calls per timing")
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--control", action="store_true", help="also the closed-loop control step")
    parser.add_argument("--control-steps", type=int, default=100)
    parser.add_argument("--control-rounds", type=int, default=5)
    args = parser.parse_args()
    results = [(b, h, profile(b, h, args.steps, args.calls, args.repeats))
               for b in args.boats for h in args.hydrostatics]
    print_profile(results)
    if args.control:
        control_profile(args.control_steps, args.control_rounds)
    print(f"(best of {args.repeats}; mujoco {mujoco.__version__}, numba {numba.__version__})")


if __name__ == "__main__":
    main()
