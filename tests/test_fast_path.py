"""The compiled force kernels agree with the interpreted reference path to 1e-10.

Every force model is one source; the reference path runs it in the Python interpreter
(numba disabled), the fast path compiled. Random states cover heel, pitch, drift, rates,
rudder and sail angles, wind and current.
"""

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sailmujoco import frames
from sailmujoco.boat.catalogue import BOATS
from sailmujoco.forces import boat as kernels
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

N_STATES = 40


def evaluate(boat: str, hydrostatics: str, seed: int, switches: dict | None = None) -> dict:
    """Forces for N_STATES random states (the same states in any process)."""
    rng = np.random.default_rng(seed)
    wind = WindConfig(speed=9.0, direction_from=1.0, seed=seed, current_east=0.3,
                      current_north=-0.2)
    physics = BoatPhysics.load(boat, wind=wind, forces=ForceSwitches(hydrostatics=hydrostatics,
                                                                     **(switches or {})))
    d = physics.data.ptr
    out = {"terms": [], "qfrc": [], "madd": [], "diag": [], "status": []}
    for _ in range(N_STATES):
        d.time = rng.uniform(0.0, 300.0)
        d.qpos[0:3] = rng.normal(size=3) * [50.0, 50.0, 0.05 * physics.params.hull.canoe_draft]
        d.qpos[3:7] = frames.quat_from_euler(rng.uniform(-1.0, 1.0), rng.uniform(-0.2, 0.2),
                                             rng.uniform(-math.pi, math.pi))
        d.qpos[7] = rng.uniform(-0.6, 0.6)
        d.qpos[8] = rng.uniform(-1.9, 1.9)
        d.qvel[:] = rng.normal(size=d.qvel.size) * [3, 3, 0.3, 0.5, 0.2, 0.4, 1.0, 1.0]
        physics._compute_forces()
        out["terms"].append(physics._terms.tolist())
        out["qfrc"].append(physics.data.ptr.qfrc_applied.tolist())
        out["madd"].append(physics._madd.tolist())
        out["diag"].append(physics._diag.tolist())
        out["status"].append(int(physics._status))
    return out


# the papers' forms, and the boat as built (residuary resistance, finite-wing foils,
# keel downwash, windage) on both boats
PAPER = {"resistance": "friction", "foils": "paper", "keel_downwash": False, "windage": False}
BUILT = {"resistance": "dsyhs", "foils": "finite", "keel_downwash": True, "windage": True}


@pytest.mark.parametrize("boat,hydrostatics,switches",
                         [("wille_yacht", "geometric", PAPER), ("saoud_robot", "paper", PAPER),
                          ("wille_yacht", "geometric", BUILT), ("saoud_robot", "geometric", BUILT)])
def test_compiled_equals_interpreted(boat, hydrostatics, switches, tmp_path):
    fast = evaluate(boat, hydrostatics, 21, switches)
    script = (f"import json, sys; sys.path.insert(0, {str(Path(__file__).parent)!r});"
              f"from test_fast_path import evaluate;"
              f"json.dump(evaluate({boat!r}, {hydrostatics!r}, 21, {switches!r}),"
              f" open({str(tmp_path / 'r.json')!r}, 'w'))")
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    subprocess.run([sys.executable, "-c", script], check=True, env=env, timeout=600, cwd=tmp_path)
    reference = json.loads((tmp_path / "r.json").read_text())
    assert fast["status"] == reference["status"]
    assert all(s == kernels.STATUS_OK for s in fast["status"])
    for key in ("terms", "qfrc", "madd", "diag"):
        a, b = np.array(fast[key]), np.array(reference[key])
        scale = np.maximum(1.0, np.abs(b))
        assert np.max(np.abs(a - b) / scale) < 1e-10, key
    # the states were not trivial: every term acted somewhere
    terms = np.abs(np.array(fast["terms"])).max(axis=(0, 2))
    idle = {kernels.T_EXT} | (set() if switches["windage"] else {kernels.T_WINDAGE})
    assert np.all(terms[[k for k in range(len(kernels.TERMS)) if k not in idle]] > 0.0)


FAST_PATH_CHECK = """
import itertools, json
from sailmujoco.forces import boat as kernels
from sailmujoco.boat.catalogue import BOATS
from sailmujoco.physics import BoatPhysics, ForceSwitches
entries = []
for boat, hydrostatics, forms, sail_mode in itertools.product(
        sorted(BOATS), ("geometric", "paper"), ("built", "paper"), ("actuated", "sheeted")):
    switches = ({} if forms == "built" else
                dict(resistance="friction", foils="paper", keel_downwash=False, windage=False))
    physics = BoatPhysics.load(boat, sail_mode=sail_mode,
                               forces=ForceSwitches(hydrostatics=hydrostatics, **switches))
    physics.step(3)
    entries.append(physics._kernel.compiled)
from sailmujoco.step import four_dof, native
from sailmujoco.boat.catalogue import get_boat
held = [b for b in sorted(BOATS) if not get_boat(b).carries_crew]  # a crew's slide needs the free hull
for boat, hydrostatics in itertools.product(held, ("geometric", "paper")):
    four = BoatPhysics.load(boat, dofs=4, forces=ForceSwitches(hydrostatics=hydrostatics))
    four.step(3)
    four.model.opt.integrator = 0  # Euler: the split path calls it too
    four.step(3)
entries.append(four_dof.FORCES_4DOF.compiled)
print(json.dumps({"signatures": len(kernels.boat_forces.signatures),
                  "signatures_4dof": len(native.forces_4dof.signatures), "entries": entries}))
"""


def test_the_compiled_kernel_stays_on_its_fast_path():
    """Every boat, both hydrostatics, both force forms and both sail modes call the force kernel
    (and the 4-DOF boats the compiled 4-DOF stage) with one numba signature, so each physics
    calls its compiled entry point directly. A second
    signature (an int where a float was, a new array type) would silently put every step back
    through numba's type dispatch, about 4x slower: this test fails instead. It runs
    in a fresh process so that no other test's calls are counted."""
    out = subprocess.run([sys.executable, "-c", FAST_PATH_CHECK], capture_output=True, text=True,
                         timeout=600, env={k: v for k, v in os.environ.items()
                                           if k != "NUMBA_DISABLE_JIT"})
    assert out.returncode == 0, out.stderr[-2000:]
    result = json.loads(out.stdout.strip().splitlines()[-1])
    assert result["signatures"] == 1
    assert result["signatures_4dof"] == 1  # the compiled 4-DOF stage, every boat and mode
    # every boat x both hydrostatics x both force forms x both sail modes, and the 4-DOF stage
    assert len(result["entries"]) == 8 * len(BOATS) + 1 and all(result["entries"])
