"""Saoud (2015) problem (5)/(14) compiled: :func:`optimal_sail_compiled`.

The same algorithm as :func:`controllers.saoud_optimum.optimal_sail` (the readable reference),
written once more for numba, operation for operation, so that it returns the same numbers bit
for bit (``tests/test_fast_controllers.py`` compares the two, and the sail law's actions, on
recorded observations and on a grid of winds). It shares the reference's parameters, result
type, argument checks and tolerances (:mod:`controllers.saoud_model`):

* the same formulas in the same order on floats; ``min``/``max`` as Python's (the first
  argument wins a tie or a NaN), ``x ** 2`` as CPython computes it (``pow(|x|, 2.0)`` of the
  C library: the exponent is passed in at run time so that the compiler cannot turn it
  into ``x * x``), ``math`` functions from the same C library;
* scipy's ``brentq`` (scipy/optimize/Zeros/brentq.c, with ``xtol=1e-14``, scipy's default
  ``rtol = 4 eps`` and 100 iterations) ported step for step, including its errors: a NaN
  function value (ValueError) and no convergence (RuntimeError);
* the candidates in the reference's order, the first of least cost winning.

About 2 us a case against 50-400 us for the reference.
"""

from __future__ import annotations

import math

import numpy as np

from sailmujoco.forces.sail import saoud_normal_coefficient
from sailmujoco.jit.kernel import clear_stale_cache, kernel
from sailmujoco.jit.ordered import geomspace

from .saoud_model import (
    BRANCH_TOL,
    DERIVATIVE_STEP,
    ROLL_SCAN,
    ROOT_SCAN,
    ROOT_TOL,
    SAME_ROOT,
    SECANT_ITERATIONS,
    TABLE_I,
    SailOptimum,
    SaoudParams,
    check_arguments,
)

clear_stale_cache(__file__)

_BRENT_XTOL = 1e-14  # the reference's brentq(..., xtol=1e-14)
_BRENT_RTOL = 4.0 * np.finfo(float).eps  # scipy.optimize.brentq's default rtol
_BRENT_ITERATIONS = 100  # scipy.optimize.brentq's default maxiter
# the reference's scan grids, as the reference builds them
_THRUST_GRID = np.concatenate((geomspace(1e-5, 1e-2, 7)[:-1], np.linspace(1e-2, 1.0, ROOT_SCAN + 1)))
_ROLL_GRID = np.linspace(-0.5 * math.pi, 0.5 * math.pi, ROLL_SCAN + 1)
_MAX_CANDIDATES = 8 + 2 * _THRUST_GRID.size + _ROLL_GRID.size
# status of a solve
OK, EMPTY, NAN_IN_BRENTQ, NO_CONVERGENCE = 0, 1, 2, 3
# residuals bracketed by brentq
_THRUST, _EQUILIBRIUM = 0, 1


@kernel
def _pymin(a, b):
    """Python's min(a, b) on floats: b only if b < a."""
    return b if b < a else a


@kernel
def _pymax(a, b):
    """Python's max(a, b) on floats: b only if b > a."""
    return b if b > a else a


@kernel
def _df(x):
    if x == 0.0:
        h = 1e-6
        return 2.0 * saoud_normal_coefficient(h) / h - saoud_normal_coefficient(2.0 * h) / (2.0 * h)
    h = _pymin(DERIVATIVE_STEP, abs(x) / 3.0)
    return (8.0 * (saoud_normal_coefficient(x + h) - saoud_normal_coefficient(x - h))
            - (saoud_normal_coefficient(x + 2.0 * h) - saoud_normal_coefficient(x - 2.0 * h))) / (12.0 * h)


@kernel
def _g(x):
    d = _df(x)
    if x == 0.0:
        return 0.5 * d
    fx = saoud_normal_coefficient(x)
    return fx * d / (x * d + fx)


@kernel
def _eq13_residual(x, v1, v2, beta, two):
    fx = saoud_normal_coefficient(x)
    gx = _g(x)
    gb = 2.0 * v2 * gx / beta
    q = math.sqrt(1.0 + gb * gb)
    # Saoud (2015) eq. 13; (..) ** 2 as CPython computes it: pow(|a|, 2.0)
    return (2.0 * math.pow(abs(x * fx * q - v2 * v2 * gx), two)
            + v1 * v1 * beta * beta * gb * gb * q / (1.0 + q)
            - 2.0 * v1 * v1 * fx * fx * (1.0 + gb * gb))


@kernel
def _secant_root(v1, v2, beta, x0, x1, two):
    """|x| of a root of eq. 13 in (0, 1], or NaN (the reference's None)."""
    f0, f1 = _eq13_residual(x0, v1, v2, beta, two), _eq13_residual(x1, v1, v2, beta, two)
    found = False
    root = 0.0
    for _ in range(SECANT_ITERATIONS):
        if f1 == 0.0:
            root, found = x1, True
            break
        if f1 == f0:
            break
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        if not math.isfinite(x2):
            break
        if abs(x2 - x1) < ROOT_TOL:
            root, found = x2, True
            break
        x0, f0, x1, f1 = x1, f1, x2, _eq13_residual(x2, v1, v2, beta, two)
    if not found:
        return math.nan
    root = abs(root)
    return _pymin(root, 1.0) if 0.0 < root <= 1.0 + 1e-12 else math.nan


@kernel
def _branch_point(x, v2, beta):
    """(ok, phi, cos delta_s) of eqs. 10c and 8b; ok False where f(x) = 0."""
    fx = saoud_normal_coefficient(x)
    if fx == 0.0:
        return False, 0.0, 0.0
    gb = 2.0 * v2 * _g(x) / beta
    phi = 0.5 * math.atan(gb)
    return True, phi, -beta * math.sin(phi) / fx


@kernel
def _thrust_branch_residual(r, v1, v2, beta):
    side = math.copysign(1.0, v2)
    x = -side * r
    ok, phi, cos_delta = _branch_point(x, v2, beta)
    if not ok:
        return -x
    sin_mag = math.sqrt(_pymax(0.0, 1.0 - cos_delta * cos_delta))
    return side * v1 * sin_mag - v2 * math.cos(phi) * cos_delta - x


@kernel
def _equilibrium(delta, v1, v2, beta, sin_phi, cos_phi):
    x = v1 * math.sin(delta) - v2 * cos_phi * math.cos(delta)
    return beta * sin_phi + saoud_normal_coefficient(x) * math.cos(delta)


@kernel
def _residual(which, x, v1, v2, beta, sin_phi, cos_phi):
    if which == _THRUST:
        return _thrust_branch_residual(x, v1, v2, beta)
    return _equilibrium(x, v1, v2, beta, sin_phi, cos_phi)


@kernel
def _brentq(which, xa, xb, v1, v2, beta, sin_phi, cos_phi):
    """(root, status) of scipy.optimize.brentq(residual, xa, xb, xtol=1e-14), step for step."""
    xtol, rtol = _BRENT_XTOL, _BRENT_RTOL
    xpre, xcur = xa, xb
    xblk, fblk, spre, scur = 0.0, 0.0, 0.0, 0.0
    fpre = _residual(which, xpre, v1, v2, beta, sin_phi, cos_phi)
    if math.isnan(fpre):
        return xpre, NAN_IN_BRENTQ
    fcur = _residual(which, xcur, v1, v2, beta, sin_phi, cos_phi)
    if math.isnan(fcur):
        return xcur, NAN_IN_BRENTQ
    if fpre * fcur > 0.0:  # not reached: the callers bracket a sign change
        return 0.0, NAN_IN_BRENTQ
    if fpre == 0.0:
        return xpre, OK
    if fcur == 0.0:
        return xcur, OK
    for _ in range(_BRENT_ITERATIONS):
        if fpre * fcur < 0.0:
            xblk = xpre
            fblk = fpre
            spre = scur = xcur - xpre
        if abs(fblk) < abs(fcur):
            xpre = xcur
            xcur = xblk
            xblk = xpre
            fpre = fcur
            fcur = fblk
            fblk = fpre
        delta = (xtol + rtol * abs(xcur)) / 2.0
        sbis = (xblk - xcur) / 2.0
        if fcur == 0.0 or abs(sbis) < delta:
            return xcur, OK
        if abs(spre) > delta and abs(fcur) < abs(fpre):
            if xpre == xblk:  # interpolate
                stry = -fcur * (xcur - xpre) / (fcur - fpre)
            else:  # extrapolate
                dpre = (fpre - fcur) / (xpre - xcur)
                dblk = (fblk - fcur) / (xblk - xcur)
                stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre))
            a, b = abs(spre), 3.0 * abs(sbis) - delta
            if 2.0 * abs(stry) < (a if a < b else b):  # C's MIN(a, b); good short step
                spre = scur
                scur = stry
            else:  # bisect
                spre = sbis
                scur = sbis
        else:  # bisect
            spre = sbis
            scur = sbis
        xpre = xcur
        fpre = fcur
        if abs(scur) > delta:
            xcur += scur
        else:
            xcur += delta if sbis > 0.0 else -delta
        fcur = _residual(which, xcur, v1, v2, beta, sin_phi, cos_phi)
        if math.isnan(fcur):
            return xcur, NAN_IN_BRENTQ
    return xcur, NO_CONVERGENCE


@kernel
def _add_candidate(out, n, delta, phi, v1, v2, roll_limited):
    """Append the reference's sail_candidate(delta, phi, v1, v2, roll_limited) to ``out``: row
    (delta, phi, alpha, cost, roll_limited). Returns the new count."""
    x = v1 * math.sin(delta) - v2 * math.cos(phi) * math.cos(delta)  # Saoud (2015) eq. 8a
    cost = saoud_normal_coefficient(x) * math.sin(delta)  # Saoud (2015) eq. 5
    chordwise = v1 * math.cos(delta) + v2 * math.cos(phi) * math.sin(delta)
    alpha = math.atan2(x, math.copysign(math.sqrt(_pymax(0.0, 1.0 - x * x)), chordwise))
    out[n, 0], out[n, 1], out[n, 2], out[n, 3] = delta, phi, alpha, cost
    out[n, 4] = 1.0 if roll_limited else 0.0
    return n + 1


@kernel
def _from_root(out, n, x, v1, v2, beta):
    """The reference's candidates_from_root: up to two candidates appended to ``out``."""
    ok, phi, cos_delta = _branch_point(x, v2, beta)
    if not ok:
        return n
    if abs(cos_delta) > 1.0 + 1e-9:
        return n
    cos_delta = _pymax(-1.0, _pymin(1.0, cos_delta))
    sin_mag = math.sqrt(1.0 - cos_delta * cos_delta)
    for sign in (1.0, -1.0):
        sin_delta = sign * sin_mag
        if abs(v1 * sin_delta - v2 * math.cos(phi) * cos_delta - x) < BRANCH_TOL:  # eq. 8a
            n = _add_candidate(out, n, math.atan2(sin_delta, cos_delta), phi, v1, v2, False)
    return n


@kernel
def _solve(v1, v2, beta, limited, phi_max, two, thrust_grid, roll_grid, out):
    """Candidates of the reference's optimal_sail into ``out`` (rows as _add_candidate's);
    returns (index of the first of least cost or -1, status)."""
    side = math.copysign(1.0, v2)
    n = _add_candidate(out, 0, math.atan(v2 / v1) if v1 != 0.0 else 0.5 * side * math.pi, 0.0,
                       v1, v2, False)
    # eq13_roots: the two secant runs, a root kept unless within SAME_ROOT of a kept one
    first = _secant_root(v1, v2, beta, 1e-3, 2e-2, two)
    second = _secant_root(v1, v2, beta, 1.0 - 1e-3, 1.0 - 2e-2, two)
    if not math.isnan(first):
        n = _from_root(out, n, -side * first, v1, v2, beta)
    if not math.isnan(second) and (math.isnan(first) or abs(second - first) >= SAME_ROOT):
        n = _from_root(out, n, -side * second, v1, v2, beta)
    thrust = False
    for i in range(1, n):
        if out[i, 3] < 0.0:
            thrust = True
    if v2 != 0.0 and not thrust:  # thrust_branch_roots: scan, then brentq in each bracket
        m = thrust_grid.size
        values = np.empty(m)
        for i in range(m):
            values[i] = _thrust_branch_residual(thrust_grid[i], v1, v2, beta)
        for i in range(m - 1):
            a, b, fa, fb = thrust_grid[i], thrust_grid[i + 1], values[i], values[i + 1]
            if fa == 0.0:
                n = _from_root(out, n, -side * a, v1, v2, beta)
            elif fa * fb < 0.0:
                root, status = _brentq(_THRUST, a, b, v1, v2, beta, 0.0, 0.0)
                if status != OK:
                    return -1, status
                n = _from_root(out, n, -side * root, v1, v2, beta)
        if values[m - 1] == 0.0:
            n = _from_root(out, n, -side * thrust_grid[m - 1], v1, v2, beta)
    keep = np.ones(n, dtype=np.bool_)
    if limited:  # Saoud (2015) eq. 14 and §VI-B
        for i in range(n):
            keep[i] = abs(out[i, 1]) <= phi_max
        phi = side * phi_max
        sin_phi, cos_phi = math.sin(phi), math.cos(phi)
        m = roll_grid.size
        values = np.empty(m)
        for i in range(m):
            values[i] = _equilibrium(roll_grid[i], v1, v2, beta, sin_phi, cos_phi)
        start = n
        for i in range(m - 1):
            a, b, fa, fb = roll_grid[i], roll_grid[i + 1], values[i], values[i + 1]
            if fa == 0.0:
                n = _add_candidate(out, n, a, phi, v1, v2, True)
            elif fa * fb < 0.0:
                delta, status = _brentq(_EQUILIBRIUM, a, b, v1, v2, beta, sin_phi, cos_phi)
                if status != OK:
                    return -1, status
                n = _add_candidate(out, n, delta, phi, v1, v2, True)
        keep = np.concatenate((keep, np.ones(n - start, dtype=np.bool_)))
    best = -1
    for i in range(n):  # min(candidates, key=cost): the first of least cost
        if keep[i] and (best < 0 or out[i, 3] < out[best, 3]):
            best = i
    return best, OK if best >= 0 else EMPTY


def optimal_sail_compiled(theta_v: float, apparent_speed: float, l_phi: float,
                          phi_max: float | None = None,
                          params: SaoudParams = TABLE_I) -> SailOptimum:
    """:func:`controllers.saoud_optimum.optimal_sail`, compiled: the same arguments, checks,
    errors and result, bit for bit.

    Parameters
    ----------
    theta_v : float
        Theta_V = atan2(V2, V1) [rad] (§IV).
    apparent_speed : float
        |V| > 0 [m/s].
    l_phi : float
        Metacentric height [m] (> 0).
    phi_max : float, optional
        Roll limit [rad], in (0, pi/2); None for problem (5).
    params : SaoudParams
        Mass, sail area, g, rho_air, h_s (default Table I).

    Returns
    -------
    SailOptimum
        delta_s*, phi*, alpha_s* [rad] and J*, in Saoud's frames.
    """
    check_arguments(apparent_speed, l_phi, phi_max)
    v1, v2 = math.cos(theta_v), math.sin(theta_v)  # V_bar_1, V_bar_2 (§V)
    beta = params.beta(l_phi, apparent_speed)
    out = np.empty((_MAX_CANDIDATES, 5))
    best, status = _solve(float(v1), float(v2), float(beta), phi_max is not None,
                          0.0 if phi_max is None else float(phi_max), 2.0, _THRUST_GRID,
                          _ROLL_GRID, out)
    if status == EMPTY:
        raise ValueError("min() arg is an empty sequence")  # as the reference's min()
    if status == NAN_IN_BRENTQ:
        raise ValueError("The function value is NaN; solver cannot continue.")
    if status == NO_CONVERGENCE:
        raise RuntimeError(f"Failed to converge after {_BRENT_ITERATIONS} iterations")
    delta, phi, alpha, cost, roll_limited = out[best].tolist()
    return SailOptimum(delta, phi, alpha, cost, roll_limited != 0.0)
