"""Speed of a physics step with all forces, as a ratio to the bare mj_step of the same model.

Run: python benchmarks/step_speed.py [--steps N] [--integrator rk4|implicitfast|implicit|euler]
[--dofs 6|4]

Both are measured in this run, on the same compiled MjModel: "bare" is mujoco.mj_step on a
fresh MjData (no force models, no added mass); "sailmujoco" is BoatPhysics.step, which at
each stage of the integrator runs MuJoCo's forward dynamics with every force model (compiled
kernels), the added-mass update and refactorisation of the mass matrix, all sub-steps of one
call in compiled code (sailmujoco/step/native.py). Calls of step(1) show the per-call overhead;
step(20) is a 10 Hz control loop at the 5 ms physics step. ``--python-loop`` times the stage
work called from Python instead (``BoatPhysics.compiled_loop = False``, the Python
reference of the compiled step) in the same run. ``--integrator`` sets
MuJoCo's integrator on that model (both columns): the default RK4 runs the force models at
each of its four stages, the first-order ones once per step. ``--dofs 4`` times the boats with
heave and pitch held (the reduced models' assumption, the assumption study's switch): MuJoCo's
RK4 calls a Python callback at each stage, which calls the compiled 4-DOF stage
(``native.forces_4dof``); ``--python-loop`` then times that stage in Python.
"""

from __future__ import annotations

import argparse
import math
import time

import mujoco
import numpy as np

from sailmujoco.forces.wind import WindConfig
from sailmujoco.options import Dofs, choices
from sailmujoco.physics import BoatPhysics, ForceSwitches


def best_of(fn, repeats=5):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


INTEGRATORS = {"rk4": mujoco.mjtIntegrator.mjINT_RK4,
               "implicitfast": mujoco.mjtIntegrator.mjINT_IMPLICITFAST,
               "implicit": mujoco.mjtIntegrator.mjINT_IMPLICIT,
               "euler": mujoco.mjtIntegrator.mjINT_EULER}


def measure(boat: str, hydrostatics: str, steps: int, integrator: str | None = None,
            python_loop: bool = False, dofs: int = 6) -> dict:
    wind = WindConfig(speed=8.0, direction_from=math.radians(45.0), seed=0)
    physics = BoatPhysics.load(boat, wind=wind, forces=ForceSwitches(hydrostatics=hydrostatics),
                               dofs=dofs)
    physics.compiled_loop = not python_loop
    if integrator is not None:
        physics.model.opt.integrator = INTEGRATORS[integrator]
    physics.set_control([0.05, 0.4])
    physics.step(200)  # warm up (and JIT, if not cached)
    model = physics.model.ptr
    bare = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, bare, 0)
    bare.ctrl[:] = [0.05, 0.4]

    def run_bare():
        for _ in range(steps):
            mujoco.mj_step(model, bare)

    def run_single():
        for _ in range(steps):
            physics.step(1)

    def run_control():
        for _ in range(steps // 20):
            physics.step(20)

    t_bare = best_of(run_bare) / steps * 1e6
    t_single = best_of(run_single) / steps * 1e6
    t_control = best_of(run_control) / (steps // 20 * 20) * 1e6
    return {"boat": boat, "hydrostatics": hydrostatics, "bare_us": t_bare,
            "step1_us": t_single, "step20_us": t_control}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=20000)
    parser.add_argument("--integrator", choices=sorted(INTEGRATORS), default=None,
                        help="MuJoCo integrator (default: the model's, RK4)")
    parser.add_argument("--python-loop", action="store_true",
                        help="also time the compiled step's Python reference (stage work called from Python)")
    parser.add_argument("--dofs", type=int, choices=choices(Dofs), default=6,
                        help="6 (default), or 4: heave and pitch held")
    args = parser.parse_args()
    print(f"{'boat':12s} {'hydrostatics':12s} {'bare mj_step':>13s} {'step(1)':>9s} "
          f"{'ratio':>6s} {'step(20)':>9s} {'ratio':>6s}")
    for boat in ("wille_yacht", "saoud_robot", "viel_boat"):
        for hydrostatics in ("paper", "geometric"):
            for python_loop in ((False, True) if args.python_loop else (False,)):
                r = measure(boat, hydrostatics, args.steps, args.integrator, python_loop, args.dofs)
                label = f"{r['hydrostatics']}{' (py)' if python_loop else ''}"
                print(f"{r['boat']:12s} {label:12s} {r['bare_us']:10.2f} us "
                      f"{r['step1_us']:6.2f} us {r['step1_us'] / r['bare_us']:6.2f} "
                      f"{r['step20_us']:6.2f} us {r['step20_us'] / r['bare_us']:6.2f}")
    name = args.integrator or "model default"
    print(f"({args.dofs} DOF; integrator {name}; numpy {np.__version__}, mujoco {mujoco.__version__}; "
          f"ratio = time / bare mj_step)")


if __name__ == "__main__":
    main()
