"""The compiled paper worlds (Wille 4-DOF, Viel 3-DOF) give the numbers of the Python ones, bit for bit.

Two checks on the same scenarios (gusty and wandering wind, current, the Wille world's ``paper``
and ``rigid`` models on both paper boats, Viel's two rudder laws, RK4 and RK45, a state that runs
away), each a run of a few control periods with changing commands, then the diagnostics:

* against trajectories written by the worlds' Python right-hand sides, of which the kernels
  are the compiled form (``data/paper_worlds_python_reference.json``, float.hex), by running this
  file as a script: ``python tests/test_paper_world_identity.py --write`` (only to be rerun on
  purpose). That file was written on one machine; libm, numpy's SIMD paths and the CPU's vector
  units move last bits from machine to machine (on two machines of the same Python, glibc, numpy
  and CPU flags, an AMD and an Intel one, a masthead wind differed in its last bit), so every
  number of it is compared to 1e-9 relative here;
* against the same source run in the interpreter (``NUMBA_DISABLE_JIT=1``, a subprocess), the
  reference path of every kernel (:mod:`sailmujoco.jit.kernel`).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import ForceSwitches, SimulationStopped
from sailmujoco.reference.viel import VielParams, VielWorld, observation_from_world
from sailmujoco.reference.wille import Wille4DOF

GOLDEN = Path(__file__).parent / "data" / "paper_worlds_python_reference.json"


GUSTY = dict(speed=8.0, direction_from=0.8, seed=3, current_east=0.2, current_north=-0.1)
WILLE_CASES = {  # name: (boat, boat options, model, integrator, switches, wind, start, control steps)
    "paper_gusty": ("wille_yacht", {}, "paper", "rk4", {}, GUSTY,
                    dict(u=3.0, heel=0.05, sail=0.5), 15),
    "rigid_gusty": ("wille_yacht", {}, "rigid", "rk4", {},
                    dict(speed=11.0, direction_from=2.0, seed=4, wander_intensity=0.05),
                    dict(u=2.0, heel=0.2, r=0.05, sail=0.8), 15),
    "saoud_rigid": ("saoud_robot", {"l_phi": 0.1}, "rigid", "rk4", {},
                    dict(speed=5.0, direction_from=-1.0, seed=5), dict(u=0.8, yaw=1.0, sail=0.6), 15),
    "saoud_paper_switches": ("saoud_robot", {}, "paper", "rk4",
                             {"sail_tangential": False, "added_mass": False},
                             dict(speed=6.0, direction_from=0.3, seed=6, gusts=False),
                             dict(u=0.5, v=0.1, p=0.2), 15),
    "paper_rk45": ("wille_yacht", {}, "paper", "rk45", {}, GUSTY, dict(u=3.0, sail=0.5), 3),
    "rigid_rk45": ("wille_yacht", {}, "rigid", "rk45", {}, GUSTY, dict(u=3.0, heel=0.1, sail=0.5), 3),
}
VIEL_CASES = {  # name: (params, wind, start, dt, control steps)
    "linear_gusty": (dict(), dict(speed=10.0, direction_from=math.pi, seed=2), (0, 0, 0.3, 1.0, 0.1, 0.0),
                     0.01, 40),
    "printed_oscillating": (dict(rudder_law="printed", p1=0.05),
                            dict(speed=7.0, direction_from=2.5, gusts=False, wander=False,
                                 speed_oscillation=2.0, direction_oscillation=0.3, oscillation_frequency=0.5),
                            (1.0, -2.0, -2.0, 0.5, 0.0, 0.1), 0.1, 10),
    "rk45": (dict(), dict(speed=10.0, direction_from=math.pi, seed=2), (0, 0, 0.3, 1.0, 0.1, 0.0), 0.1, 3),
}
# held controls that end astern and spinning: omega overflows and the run stops. When it stops is
# decided by the last bits: one ulp more or less in the start's v moves the stop from 35.07 s to
# 32.47 s or 31.46 s (measured on the compiled world), and the Python world stopped at 33.11 s on the
# machine that wrote the reference. So the runaway is compared as an event (a FloatingPointError
# naming the world, within the minute), not by its time or its overflowed state.
VIEL_RUNAWAY = (dict(speed=8.0, direction_from=math.radians(45.0), seed=0), (0.0, 0.0, 0.3, 1.0, 0.0, 0.0),
                (0.05, 0.6), 0.01)


def flat(value) -> list:
    """Every number in a (nested) dict/list/array, as float.hex (exact), in a fixed order."""
    if isinstance(value, dict):
        return [[k, flat(v)] for k, v in sorted(value.items())]
    if isinstance(value, (list, tuple, np.ndarray)):
        return [flat(v) for v in np.asarray(value, dtype=float).ravel()]
    return float(value).hex()


def wille_case(name: str) -> dict:
    boat, options, model, integrator, switches, wind, start, steps = WILLE_CASES[name]
    world = Wille4DOF(params=get_boat(boat, **options), wind=WindConfig(**wind), model=model,
                      integrator=integrator, switches=ForceSwitches(**switches))
    world.set_state_ours(**start)
    out = {"states": [], "stopped": ""}
    try:
        for k in range(steps):
            world.set_control([0.8 * math.sin(0.9 * k), 0.6 + 1.4 * math.cos(0.4 * k)])  # saturates at times
            world.step(20)
            if k % 3 == 2:
                out["states"].append(flat(world.state))
    except SimulationStopped as err:
        out["stopped"] = str(err)
    state = world.state.copy()
    out["forces"] = flat(world.forces(world.time(), state))
    out["forces_later"] = flat(world.forces(7.3, state + 0.01))
    out["rhs"] = flat(world._rhs(world.time(), state))
    out["force_terms"] = flat(world.force_terms())
    out["apparent_wind_ce"] = flat(world.apparent_wind_ce())
    out["apparent_wind_masthead"] = flat(world.apparent_wind_masthead())
    return out


def viel_case(name: str) -> dict:
    params, wind, start, dt, steps = VIEL_CASES[name]
    world = VielWorld(params=VielParams(**params), wind=WindConfig(**wind),
                      integrator="rk45" if name == "rk45" else "rk4")
    world.reset(np.array(start, dtype=float))
    out = {"states": []}
    for k in range(steps):
        world.step([0.9 * math.sin(0.5 * k), 1.8 * math.cos(0.2 * k)], dt)  # saturates now and then
        if k % 5 == 4 or k == steps - 1:
            out["states"].append(flat(world.state))
    out["forces"] = flat(world.forces())
    out["rates"] = flat(world.rates())
    out["rates_other"] = flat(world.rates(world.state + 0.1, [0.1, -0.3], 3.7))
    out["wrenches"] = flat(world.wrenches())
    out["observation"] = flat({k: v for k, v in observation_from_world(world, (3.0, 4.0)).items()
                               if k != "true_state"})
    out["true_state"] = flat(observation_from_world(world)["true_state"])
    return out


def viel_runaway() -> dict:
    wind, start, action, dt = VIEL_RUNAWAY
    world = VielWorld(wind=WindConfig(**wind))
    world.reset(np.array(start))
    message = ""
    try:
        while world.time < 60.0:
            world.step(np.array(action), dt)
    except FloatingPointError as err:
        message = str(err)
    return {"time": world.time.hex(), "state": flat(world.state), "message": message}


N_RANDOM_STATES = 400


def digest(values: list) -> str:
    return hashlib.sha256(np.asarray(values, dtype=float).tobytes()).hexdigest()


def wille_sweep(name: str) -> dict:
    """The right-hand side and the force terms at random states, times and commands."""
    boat, options, model, integrator, switches, wind, *_ = WILLE_CASES[name]
    world = Wille4DOF(params=get_boat(boat, **options), wind=WindConfig(**wind), model=model,
                      switches=ForceSwitches(**switches))
    rng = np.random.default_rng(11)
    low = np.array([-50, -50, -0.6, -math.pi, -1.0, -1.0, -0.5, -0.3, -0.7, -2.0])
    rates, forces = [], []
    for _ in range(N_RANDOM_STATES):
        state, t = rng.uniform(low, -low), rng.uniform(0.0, 300.0)
        world.set_control(rng.uniform(-2.0, 2.0, 2))
        rates.extend(world._rhs(t, state))
        forces.extend(np.concatenate(list(world.forces(t, state).values())))
    return {"rhs": digest(rates), "forces": digest(forces)}


def viel_sweep(name: str) -> dict:
    params, wind, *_ = VIEL_CASES[name]
    world = VielWorld(params=VielParams(**params), wind=WindConfig(**wind))
    rng = np.random.default_rng(12)
    low = np.array([-50, -50, -math.pi, -2.0, -1.0, -1.0])
    rates, forces = [], []
    for _ in range(N_RANDOM_STATES):
        state, action, t = rng.uniform(low, -low), rng.uniform(-2.0, 2.0, 2), rng.uniform(0.0, 300.0)
        rates.extend(world.rates(state, action, t))
        forces.extend(world.forces(state, action, t).values())
    return {"rates": digest(rates), "forces": digest(forces)}


def run_cases(runaway: bool = True) -> dict:
    out = {f"wille/{name}": wille_case(name) for name in WILLE_CASES}
    out.update({f"viel/{name}": viel_case(name) for name in VIEL_CASES})
    out.update({f"wille_rhs/{name}": wille_sweep(name) for name in WILLE_CASES if "rk45" not in name})
    out.update({f"viel_rhs/{name}": viel_sweep(name) for name in VIEL_CASES if name != "rk45"})
    if runaway:  # thousands of steps: too slow for the interpreted path
        out["viel/runaway"] = viel_runaway()
    return out


def _floats(value):
    """The float.hex strings of a flat() result as floats (other entries dropped)."""
    if isinstance(value, list):
        return [x for v in value for x in _floats(v)]
    if isinstance(value, str) and value.startswith(("0x", "-0x", "inf", "-inf", "nan")):
        return [float.fromhex(value)]
    return []


def test_compiled_worlds_equal_the_python_worlds_they_replaced():
    """Every number of every run (states, diagnostics; the runaway as an event) to 1e-9 relative of the Python
    worlds' (see the module docstring for why not bit for bit across machines); the digests of
    the right-hand sides at random states hold any bit, so they are compared exactly on this
    machine only, by the interpreted-source test below."""
    expected = json.loads(GOLDEN.read_text())
    got = run_cases()
    assert sorted(got) == sorted(expected)
    for name in expected:
        if name == "viel/runaway":
            continue
        for key, want_value in expected[name].items():
            want, have = _floats(want_value), _floats(got[name][key])
            assert len(want) == len(have), (name, key)
            if want:
                # an adaptive RK45 run turns a last-bit change into another step sequence: its
                # states then agree to the integrator's own tolerance (rtol 1e-6), not to rounding
                rtol = 1e-6 if "rk45" in name else 1e-9
                np.testing.assert_allclose(have, want, rtol=rtol, atol=1e-12, err_msg=f"{name} {key}")
            elif not isinstance(want_value, str) or not want_value.startswith(("0x", "-0x")):
                if key not in ("rhs", "rates", "forces"):  # the digests: see the docstring
                    assert got[name][key] == want_value, (name, key)
    for runaway in (expected["viel/runaway"], got["viel/runaway"]):
        assert runaway["message"].startswith("VielWorld: integration failed at t="), runaway["message"]
        assert float.fromhex(runaway["time"]) < 60.0
        omega = float.fromhex(runaway["state"][-1])
        assert not math.isfinite(omega) or abs(omega) > 1e300, runaway["state"]


def test_compiled_worlds_equal_their_interpreted_source():
    env = {**os.environ, "NUMBA_DISABLE_JIT": "1"}
    result = subprocess.run([sys.executable, __file__, "--print"], env=env, capture_output=True, text=True,
                            check=True, timeout=300)
    interpreted = json.loads(result.stdout)
    compiled = json.loads(json.dumps(run_cases(runaway=False)))
    assert sorted(interpreted) == sorted(compiled)
    for name in compiled:
        assert interpreted[name] == compiled[name], name


if __name__ == "__main__":
    if "--write" in sys.argv:
        GOLDEN.parent.mkdir(exist_ok=True)
        GOLDEN.write_text(json.dumps(run_cases(), indent=None, separators=(",", ":")) + "\n")
    elif "--print" in sys.argv:
        print(json.dumps(run_cases(runaway=False)))
