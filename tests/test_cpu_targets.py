"""The same bits whatever CPU the run's code was compiled for or picked its kernels by.

Two processes run the same trajectories (calm water, a sea, typical instruments and servos, a
paper world, Viel's 100 Hz loop), each with numba's cache of its own: one with numba's kernels
compiled for the host CPU and numpy and OpenBLAS on their own choice of kernels; the other with
the kernels compiled for a generic x86-64 (no AVX, no FMA), numpy's run-time SIMD kernels
switched off (``NPY_DISABLE_CPU_FEATURES``) and OpenBLAS held to its oldest x86-64 kernels
(``OPENBLAS_CORETYPE=Prescott``). That is, in one machine, what another CPU does to the code. Every
column of every trajectory and every metric must be the same float, bit for bit.

What this cannot check is the C library: glibc chooses its own ``exp``, ``sin``, ``pow`` and kin by
CPU (FMA or not), for MuJoCo, numba's kernels and Python alike (docs/performance.md, "One answer
on every machine").
"""

from __future__ import annotations

import json
import math
import os
import pickle
import platform
import subprocess
import sys

import numpy as np
import pytest
import scipy.linalg

# (boat, task, world, controller, seconds, options): a short trajectory of each kind
CASES = {
    "calm, robot, Saoud's sail": ("saoud_robot", "heading_hold", "mujoco", "saoud", 20.0, {}),
    "sea, yacht, Wille's roll LQR": ("wille_yacht", "beam_reach_roll", "mujoco", "wille_roll", 20.0,
                                     {"waves": {"hs": 1.0, "tp": 5.0}}),
    "instruments and servos, yacht, Wille's course": ("wille_yacht", "course_hold", "mujoco", "wille_course",
                                                      20.0, {"sensors": "typical", "actuators": "typical"}),
    "4 DOF, robot, Briere's sail": ("saoud_robot", "heading_hold", "mujoco", "briere", 10.0, {"dofs": 4}),
    "paper world, yacht, Wille's roll LQR": ("wille_yacht", "beam_reach_roll", "paper", "wille_roll", 20.0,
                                             {}),
    "100 Hz, Viel's position keeping": ("viel_boat", "position_keeping", "mujoco", "viel", 5.0, {"case": 3}),
}

_RUN = r"""
import pickle, sys
import numpy as np
from numba.core.registry import cpu_target
from numpy._core._multiarray_umath import __cpu_features__
from sailmujoco import suite, sweep
cases = pickle.loads(bytes.fromhex(sys.argv[1]))
out = {}
for name, (boat, task, world, controller, seconds, options) in cases.items():
    env = suite.load(boat, task, world, seed=3, time_limit=seconds, **options)
    log = suite.rollout(env, sweep.make_controller(controller, env))
    out[name] = ({c: log[c].to_numpy(dtype=float) for c in log.columns}, env.task.metrics())
codegen = cpu_target.target_context.codegen()
out["__target__"] = (codegen._get_host_cpu_name(), codegen._tm_features,
                     sorted(k for k, v in __cpu_features__.items() if v))
sys.stdout.buffer.write(pickle.dumps(out))
"""


def _run(tmp_path, name, env_extra):
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES", "NPY_DISABLE_CPU_FEATURES",
                        "OPENBLAS_CORETYPE", "NUMBA_DISABLE_JIT")}
    env.update(NUMBA_CACHE_DIR=str(tmp_path / f"numba-{name}"), SAILMUJOCO_QUIET="1", **env_extra)
    # run from the test's own folder: from the repository root, "-c" would import the source tree's
    # sailmujoco, which lacks the controllers an install (pip install .) puts inside it
    return subprocess.Popen([sys.executable, "-c", _RUN, pickle.dumps(CASES).hex()], env=env, cwd=tmp_path,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def _dispatched_numpy_features() -> list[str]:
    """The SIMD features numpy dispatches to on this CPU (what NPY_DISABLE_CPU_FEATURES can take)."""
    from numpy._core._multiarray_umath import __cpu_dispatch__, __cpu_features__
    return [f for f in __cpu_dispatch__ if __cpu_features__.get(f)]


@pytest.mark.skipif(platform.machine() not in ("x86_64", "AMD64"), reason="the targets named are x86-64's")
def test_trajectories_are_the_same_bits_for_two_cpu_targets(tmp_path):
    host = _run(tmp_path, "host", {})
    other = _run(tmp_path, "generic", {
        "NUMBA_CPU_NAME": "generic", "NUMBA_CPU_FEATURES": "",
        "NPY_DISABLE_CPU_FEATURES": " ".join(_dispatched_numpy_features()),
        "OPENBLAS_CORETYPE": "Prescott"})
    results = []
    for process in (host, other):
        stdout, stderr = process.communicate(timeout=1800)
        assert process.returncode == 0, stderr.decode()[-3000:]
        results.append(pickle.loads(stdout))
    a, b = results
    # the two processes did run on different targets: numba's CPU and features, numpy's SIMD
    assert a.pop("__target__")[:2] != b["__target__"][:2]
    assert b.pop("__target__")[0] == "generic"
    for name in CASES:
        (log_a, metrics_a), (log_b, metrics_b) = a[name], b[name]
        assert log_a.keys() == log_b.keys()
        assert len(log_a["t"]) > 40, name  # the run went the distance
        for column in log_a:
            differs = np.flatnonzero(~((log_a[column] == log_b[column])
                                       | (np.isnan(log_a[column]) & np.isnan(log_b[column]))))
            assert differs.size == 0, (f"{name}: {column} first differs at t = "
                                       f"{log_a['t'][differs[0]]:.1f} s: {log_a[column][differs[0]]!r} "
                                       f"against {log_b[column][differs[0]]!r}")
        assert json.dumps(metrics_a, default=repr) == json.dumps(metrics_b, default=repr), name


def test_the_roll_lqr_in_closed_form_is_scipys_riccati_solution():
    """The roll LQR's gain, solved in closed form so that LAPACK's kernels cannot move its bits,
    is the stabilising solution scipy's CARE solver finds, at heels either side of 45 deg."""
    from sailmujoco.controllers.wille_roll_lqr import roll_lqr
    for phi_w in (0.0, math.radians(10.0), math.radians(30.0), math.radians(60.0)):
        for q, r in (((0.75, 1.0), 1e-10), ((1.0, 2.0), 1e-3), ((4.0, 0.1), 10.0)):
            lqr = roll_lqr(phi_w=phi_w, q=q, r=r)
            a, b = lqr.A[1, 0], lqr.B[1, 0]
            p2, p3 = lqr.K[0] * r / b, lqr.K[1] * r / b  # K = R^-1 B^T P = (b / r) (p2, p3)
            p = np.array([[b * b / r * p2 * p3 - a * p3, p2], [p2, p3]])
            # the Riccati equation holds to rounding, against the size of its largest term
            terms = [lqr.A.T @ p, p @ lqr.A, p @ lqr.B @ lqr.B.T @ p / r, lqr.Q]
            residual = terms[0] + terms[1] - terms[2] + terms[3]
            assert np.abs(residual).max() <= 1e-12 * max(np.abs(t).max() for t in terms)
            reference = scipy.linalg.solve_continuous_are(lqr.A, lqr.B, lqr.Q, lqr.R)
            np.testing.assert_allclose(lqr.K, (lqr.B.T @ reference).ravel() / r, rtol=1e-6)
            closed = lqr.A - lqr.B @ lqr.K[None, :]
            assert np.all(np.linalg.eigvals(closed).real < 0.0)
