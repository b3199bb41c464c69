"""The optimal sail angle of Saoud (2015): problem (5), or (14) under a roll limit.

:func:`optimal_sail` follows the paper's route (§VI-A, §VII-A): the roots of eq. 13 by two
secant runs, each root turned into (delta_s, phi) by eqs. 10c, 8b and 8a, the candidate of
least cost J winning; near beam reach, where both runs can find the same root, the
thrust-producing factor of eq. 13 is bracketed instead (:func:`thrust_branch_roots`).
:func:`brute_force_sail` solves the same problem by exhaustive search, using none of eqs. 6-13:
the reference for the tests and the studies.

The model, its frames and the readings of the text are in :mod:`controllers.saoud_model`;
:func:`controllers.saoud_solver.optimal_sail_compiled` is :func:`optimal_sail` compiled, bit
for bit.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import optimize

from sailmujoco.forces.sail import saoud_normal_coefficient
from sailmujoco.frames import wrap_angle
from sailmujoco.jit.ordered import elementwise, geomspace

from .saoud_model import (
    BRANCH_TOL,
    ROLL_SCAN,
    ROOT_SCAN,
    ROOT_TOL,
    SAME_ROOT,
    SECANT_ITERATIONS,
    TABLE_I,
    SailOptimum,
    SaoudParams,
    branch_point,
    check_arguments,
    eq13_residual,
    fold_sail_angle,
    normal_coefficient,
    sail_candidate,
)

_BISECTIONS = 45  # bisections of the brute force's heel brackets (2 deg / 2^45 ~ 1e-15 rad)

# --- the paper's route: roots of eq. 13 and the candidates they give ----------------------


def candidates_from_root(x: float, v1: float, v2: float, beta: float) -> list[SailOptimum]:
    """(delta_s, phi) from a root x of eq. 13, by eqs. 10c, 8b and 8a.

    phi from eq. 10c on the branch cos(2 phi) > 0 that the paper writes (sqrt(1 - y^2) =
    1 / sqrt(1 + gb^2)); cos delta_s from eq. 8b; sin delta_s = +-sqrt(1 - cos^2 delta_s), the
    sign being the one that satisfies eq. 8a (eq. 13 squared it away; eq. 12 divides by V1,
    which fails at Theta_V = +-pi/2). Both signs are kept when both satisfy 8a (V1 ~ 0).

    Parameters
    ----------
    x : float
        A root of eq. 13, signed: sin(alpha_s) [-].
    v1, v2 : float
        V_bar_1 = cos(Theta_V), V_bar_2 = sin(Theta_V) [-] (§V).
    beta : float
        beta of :meth:`SaoudParams.beta` [-].

    Returns
    -------
    list of SailOptimum
        None, one or two candidates.
    """
    point = branch_point(x, v1, v2, beta)
    if point is None:
        return []
    phi, cos_delta = point
    if abs(cos_delta) > 1.0 + 1e-9:
        return []
    cos_delta = max(-1.0, min(1.0, cos_delta))
    sin_mag = math.sqrt(1.0 - cos_delta * cos_delta)
    out = []
    for sign in (1.0, -1.0):
        sin_delta = sign * sin_mag
        if abs(v1 * sin_delta - v2 * math.cos(phi) * cos_delta - x) < BRANCH_TOL:  # eq. 8a
            out.append(sail_candidate(math.atan2(sin_delta, cos_delta), phi, v1, v2))
    return out


def _roll_limited_candidates(phi: float, v1: float, v2: float, beta: float) -> list[SailOptimum]:
    """Points of the roll equilibrium with the heel held at ``phi`` (§VI-B).

    Solves beta sin(phi) + f(V1 sin delta - V2 cos phi cos delta) cos delta = 0 (eqs. 5, 8a,
    8b) for delta_s in [-pi/2, pi/2]: a scan brackets every sign change, brentq refines it.
    """
    sin_phi, cos_phi = math.sin(phi), math.cos(phi)

    def equilibrium(delta):  # Saoud (2015) eq. 5 (constraint), with eq. 8a for sin(alpha_s)
        x = v1 * math.sin(delta) - v2 * cos_phi * math.cos(delta)
        return beta * sin_phi + normal_coefficient(x) * math.cos(delta)

    grid = np.linspace(-0.5 * math.pi, 0.5 * math.pi, ROLL_SCAN + 1).tolist()
    values = [equilibrium(d) for d in grid]
    out = []
    for a, b, fa, fb in zip(grid[:-1], grid[1:], values[:-1], values[1:], strict=True):
        if fa == 0.0:
            out.append(sail_candidate(a, phi, v1, v2, roll_limited=True))
        elif fa * fb < 0.0:
            delta = optimize.brentq(equilibrium, a, b, xtol=1e-14)
            out.append(sail_candidate(delta, phi, v1, v2, roll_limited=True))
    return out


def _secant_root(v1: float, v2: float, beta: float, x0: float, x1: float) -> float | None:
    """|x| of a root of eq. 13 in (0, 1] by the secant method from (x0, x1), or None.

    Written on floats: scipy.optimize.newton's secant costs ~0.3 ms a case in overhead alone.
    """
    f0, f1 = eq13_residual(x0, v1, v2, beta), eq13_residual(x1, v1, v2, beta)
    root = None
    for _ in range(SECANT_ITERATIONS):
        if f1 == 0.0:
            root = x1
            break
        if f1 == f0:
            break
        x2 = x1 - f1 * (x1 - x0) / (f1 - f0)
        if not math.isfinite(x2):
            break
        if abs(x2 - x1) < ROOT_TOL:
            root = x2
            break
        x0, f0, x1, f1 = x1, f1, x2, eq13_residual(x2, v1, v2, beta)
    if root is None:
        return None
    root = abs(root)  # eq. 13 is even in x (Lemma 2)
    return min(root, 1.0) if 0.0 < root <= 1.0 + 1e-12 else None


def eq13_roots(v1: float, v2: float, beta: float) -> list[float]:
    """Roots |x| in (0, 1] of eq. 13 from the paper's two secant runs (§VII-A).

    The initial guesses are "close to zero and +-1"; eq. 13 is even in x (Lemma 2), so the
    roots are sought as |x|. Normally the two runs give the two roots (one per sign of
    sin(delta_s), see :func:`thrust_branch_residual`), but near beam reach both can converge
    to the same one: :func:`optimal_sail` then falls back on :func:`thrust_branch_roots`.

    Parameters
    ----------
    v1, v2 : float
        V_bar_1 = cos(Theta_V), V_bar_2 = sin(Theta_V) [-] (§V).
    beta : float
        beta of :meth:`SaoudParams.beta` [-].
    """
    roots: list[float] = []
    for x0, x1 in ((1e-3, 2e-2), (1.0 - 1e-3, 1.0 - 2e-2)):
        root = _secant_root(v1, v2, beta, x0, x1)
        if root is not None and all(abs(root - r) >= SAME_ROOT for r in roots):
            roots.append(root)
    return roots


def thrust_branch_residual(r: float, v1: float, v2: float, beta: float) -> float:
    """Residual of eq. 8a on the thrust-producing branch of eq. 13, at x = -sign(V2) r.

    Eq. 13 is V1^2 z^2 + V1^2 (1 - z^2) = V1^2 with z from eq. 12 and sqrt(1 - z^2) from
    eq. 11, i.e. (V1 sin delta_s)^2 = V1^2 (1 - cos^2 delta_s) with V1 sin delta_s taken from
    eq. 8a: the square of  V1 sigma sqrt(1 - cos^2 delta_s) - V2 cos phi cos delta_s - x = 0,
    sigma = sign(sin delta_s). A negative cost J = f(x) sin(delta_s) needs sigma = -sign(x) =
    sign(V2); this is that factor, with cos delta_s clipped to [-1, 1].

    Parameters
    ----------
    r : float
        |x| = |sin(alpha_s)| [-].
    v1, v2 : float
        V_bar_1 = cos(Theta_V), V_bar_2 = sin(Theta_V) [-] (§V).
    beta : float
        beta of :meth:`SaoudParams.beta` [-].
    """
    side = math.copysign(1.0, v2)
    x = -side * r
    point = branch_point(x, v1, v2, beta)
    if point is None:
        return -x
    phi, cos_delta = point
    sin_mag = math.sqrt(max(0.0, 1.0 - cos_delta * cos_delta))
    return side * v1 * sin_mag - v2 * math.cos(phi) * cos_delta - x  # Saoud (2015) eq. 8a


def thrust_branch_roots(v1: float, v2: float, beta: float) -> list[float]:
    """Roots r = |x| in (0, 1] of :func:`thrust_branch_residual`: a scan brackets, brentq refines.

    Unlike eq. 13 itself, whose two roots merge into a double root at beam reach (V1 = 0), this
    factor has simple roots there, so bracketing finds them.

    Parameters
    ----------
    v1, v2 : float
        V_bar_1 = cos(Theta_V), V_bar_2 = sin(Theta_V) [-] (§V).
    beta : float
        beta of :meth:`SaoudParams.beta` [-].
    """
    grid = np.concatenate((geomspace(1e-5, 1e-2, 7)[:-1], np.linspace(1e-2, 1.0, ROOT_SCAN + 1)))
    grid = grid.tolist()
    values = [thrust_branch_residual(r, v1, v2, beta) for r in grid]
    roots = []
    for a, b, fa, fb in zip(grid[:-1], grid[1:], values[:-1], values[1:], strict=True):
        if fa == 0.0:
            roots.append(a)
        elif fa * fb < 0.0:
            roots.append(optimize.brentq(thrust_branch_residual, a, b, args=(v1, v2, beta), xtol=1e-14))
    if values[-1] == 0.0:
        roots.append(grid[-1])
    return roots



def optimal_sail(theta_v: float, apparent_speed: float, l_phi: float, phi_max: float | None = None,
                 params: SaoudParams = TABLE_I) -> SailOptimum:
    """Optimal sail angle of Saoud (2015): problem (5), or (14) when ``phi_max`` is given.

    Parameters
    ----------
    theta_v : float
        Theta_V = atan2(V2, V1) [rad], the direction of V = R_z(psi)^T (v - v_w) in the heading
        frame (§IV); positive when the wind comes from port.
    apparent_speed : float
        |V| > 0 [m/s] (Assumption 3).
    l_phi : float
        Metacentric height [m] (> 0).
    phi_max : float, optional
        Roll limit [rad], in (0, pi/2). None: problem (5), whose optimum has |phi*| <= pi/4
        (Remark 1).
    params : SaoudParams
        Mass, sail area, g, rho_air, h_s.

    Returns
    -------
    SailOptimum
        delta_s*, phi*, alpha_s* [rad] and J*, in Saoud's frames. Our sail angle is
        ``sail_angle_from_saoud(result.delta)``.

    Notes
    -----
    §VI-A and §VII-A: eq. 13 is solved twice by the secant method, from initial guesses near 0
    and near 1 in x = sin(alpha_s) (the paper writes the sign as -sign(V2); eq. 13 is even in x,
    so the roots are searched as |x| and given that sign, which puts delta_s* in
    [-pi/2, pi/2]). Each root gives phi (eq. 10c), cos delta_s (eq. 8b) and sin delta_s
    (eq. 8a); the candidate of least cost J wins. The feathered sail (x = 0, phi = 0,
    delta_s along V, J = 0) is always feasible and is kept as a fallback: it is the optimum
    head to wind (Theta_V = 0), where eq. 13 has no useful root.
    Our addition: when no root of the two runs gives thrust (J < 0), which happens between
    |Theta_V| = 90 deg and ~116 deg for some boats (both runs converge to the root of the
    other sign of sin delta_s), the thrust-producing factor of eq. 13 is bracketed and solved
    (:func:`thrust_branch_roots`).
    §VI-B: with ``phi_max`` the roll-limit candidates phi = sign(V2) phi_max join the set and
    candidates with |phi| > phi_max are dropped.

    About 0.05 ms a case (0.08 ms with ``phi_max``; up to ~0.4 ms with the fallback).
    """
    check_arguments(apparent_speed, l_phi, phi_max)
    v1, v2 = math.cos(theta_v), math.sin(theta_v)  # V_bar_1, V_bar_2 (§V)
    beta = params.beta(l_phi, apparent_speed)
    side = math.copysign(1.0, v2)  # sign(V_bar_2); Remark 1: sign(phi*) = sign(V_bar_2)

    # the feathered sail: sin(alpha_s) = 0 in eq. 8a, phi = 0 by eq. 8b
    candidates = [sail_candidate(math.atan(v2 / v1) if v1 != 0.0 else 0.5 * side * math.pi, 0.0, v1, v2)]
    from_roots = [c for root in eq13_roots(v1, v2, beta)
                  for c in candidates_from_root(-side * root, v1, v2, beta)]  # sign(x) = -sign(V_bar_2)
    if v2 != 0.0 and not any(c.cost < 0.0 for c in from_roots):
        # the secant runs missed the thrust-producing root (near beam reach): bracket it
        from_roots += [c for root in thrust_branch_roots(v1, v2, beta)
                       for c in candidates_from_root(-side * root, v1, v2, beta)]
    candidates.extend(from_roots)
    if phi_max is not None:  # Saoud (2015) eq. 14 and §VI-B
        candidates = [c for c in candidates if abs(c.phi) <= phi_max]
        candidates.extend(_roll_limited_candidates(side * phi_max, v1, v2, beta))
    return min(candidates, key=lambda c: c.cost)


# --- brute force (reference for the tests and the studies) ---------------------------------

_f_array = np.frompyfunc(saoud_normal_coefficient, 1, 1)


def _f_vec(x: np.ndarray) -> np.ndarray:
    """f on an array, element by element through the same kernel."""
    return _f_array(x).astype(float)


def _sin(x):
    """sin element by element from the C library (numpy's SIMD sine varies by CPU)."""
    return elementwise(math.sin, x)


def _cos(x):
    """cos element by element from the C library (numpy's SIMD cosine varies by CPU)."""
    return elementwise(math.cos, x)


def _equilibrium_roots(deltas: np.ndarray, v1: float, v2: float, beta: float, phi_step: float):
    """Every heel phi in [-pi/2, pi/2] of the roll equilibrium (eq. 4, constraint of 5) at each delta.

    Returns flat arrays (delta, phi). A grid of heels ``phi_step`` apart brackets the sign
    changes of beta sin(phi) + f(V1 sin delta - V2 cos phi cos delta) cos delta, and
    bisection refines them to ~1e-14 rad.
    """
    phis = np.linspace(-0.5 * math.pi, 0.5 * math.pi, int(math.ceil(math.pi / phi_step)) + 1)

    def h(delta, phi):  # Saoud (2015) eq. 5 constraint, with eq. 8a for sin(alpha_s)
        x = v1 * _sin(delta) - v2 * _cos(phi) * _cos(delta)
        return beta * _sin(phi) + _f_vec(x) * _cos(delta)

    values = h(deltas[:, None], phis[None, :])
    rows, cols = np.nonzero(np.sign(values[:, :-1]) * np.sign(values[:, 1:]) <= 0.0)
    dd, lo, hi, h_lo = deltas[rows], phis[cols], phis[cols + 1], values[rows, cols]
    for _ in range(_BISECTIONS):
        mid = 0.5 * (lo + hi)
        h_mid = h(dd, mid)
        left = np.sign(h_mid) == np.sign(h_lo)
        lo, h_lo, hi = np.where(left, mid, lo), np.where(left, h_mid, h_lo), np.where(left, hi, mid)
    return dd, 0.5 * (lo + hi)


def equilibrium_heels(delta: float, theta_v: float, apparent_speed: float, l_phi: float,
                      params: SaoudParams = TABLE_I, phi_step: float = math.radians(2.0)) -> np.ndarray:
    """Every steady heel phi in [-pi/2, pi/2] [rad] of the roll equilibrium (eq. 4) at sail angle
    ``delta`` [rad] (Saoud's frames), e.g. to score another sail law on the reduced model.

    Parameters
    ----------
    delta : float
        Saoud's sail angle delta_s [rad].
    theta_v : float
        Theta_V [rad] (§IV).
    apparent_speed : float
        |V| [m/s].
    l_phi : float
        Metacentric height [m].
    params : SaoudParams
        Mass, sail area, g, rho_air, h_s.
    phi_step : float
        Spacing of the heel grid that brackets the equilibria [rad].
    """
    beta = params.beta(l_phi, apparent_speed)
    _, phis = _equilibrium_roots(np.array([float(delta)]), math.cos(theta_v), math.sin(theta_v), beta,
                                 phi_step)
    return np.unique(np.round(phis, 12))  # a heel on a grid node is bracketed twice


def sail_cost(delta: float, phi: float, theta_v: float) -> float:
    """J = f(sin alpha_s) sin delta_s [-] (eq. 5) with sin alpha_s from eq. 8a; all angles [rad].

    Parameters
    ----------
    delta : float
        Saoud's sail angle delta_s [rad].
    phi : float
        Heel [rad].
    theta_v : float
        Theta_V [rad] (§IV).
    """
    return sail_candidate(delta, phi, math.cos(theta_v), math.sin(theta_v)).cost


def brute_force_sail(theta_v: float, apparent_speed: float, l_phi: float, phi_max: float | None = None,
                     params: SaoudParams = TABLE_I, *, full_circle: bool = False,
                     delta_step: float = math.radians(1.0), phi_step: float = math.radians(2.0),
                     levels: int = 3, basins: int = 2) -> SailOptimum:
    """Problem (5) (or (14)) by exhaustive search, using none of eqs. 6-13.

    Parameters
    ----------
    theta_v, apparent_speed, l_phi, phi_max, params
        As for :func:`optimal_sail` [rad, m/s, m, rad].
    full_circle : bool
        Grid delta_s over [-pi, pi] (True) or over [-pi/2, pi/2] (False, enough by Lemma 1).
    delta_step, phi_step : float
        Spacing of the coarse sail-angle grid and of the heel grid that brackets the roll
        equilibria [rad].
    levels : int
        Number of refinements, each on a grid 20 times finer around the best point.
    basins : int
        Number of separated coarse minima that are refined (guards against near-ties).

    Returns
    -------
    SailOptimum
        Folded into [-pi/2, pi/2] (Lemma 1); ``roll_limited`` is always False.

    Notes
    -----
    At each gridded sail angle every heel of the roll equilibrium is found, those with
    |phi| > phi_max dropped, and J evaluated; the best points are searched again on finer
    grids. About 20 ms a case with the defaults (the final delta_s step is 1e-4 rad): a
    reference for the tests, not a controller.
    """
    v1, v2 = math.cos(theta_v), math.sin(theta_v)
    beta = params.beta(l_phi, apparent_speed)
    limit = math.inf if phi_max is None else phi_max

    def search(deltas):
        dd, pp = _equilibrium_roots(deltas, v1, v2, beta, phi_step)
        keep = np.abs(pp) <= limit
        dd, pp = dd[keep], pp[keep]
        x = v1 * _sin(dd) - v2 * _cos(pp) * _cos(dd)  # eq. 8a
        return dd, pp, _f_vec(x) * _sin(dd)  # eq. 5

    span = math.pi if full_circle else 0.5 * math.pi
    n = int(math.ceil(2.0 * span / delta_step)) + 1
    step = 2.0 * span / (n - 1)
    dd, pp, cost = search(np.linspace(-span, span, n))
    starts: list[float] = []
    for i in np.argsort(cost):  # the best grid points of separated basins
        if all(abs(wrap_angle(dd[i] - s)) > 3.0 * step for s in starts):
            starts.append(float(dd[i]))
        if len(starts) == basins:
            break
    best = None
    for start in starts:
        centre, width = start, step
        for _ in range(levels):
            dd, pp, cost = search(np.linspace(centre - 2.0 * width, centre + 2.0 * width, 81))
            if cost.size == 0:
                break
            i = int(np.argmin(cost))
            centre, width = float(dd[i]), width / 20.0
            if best is None or cost[i] < best[2]:
                best = (float(dd[i]), float(pp[i]), float(cost[i]))
    if best is None:
        raise RuntimeError("no point of the roll equilibrium on the grid")
    delta, phi, _ = best
    return sail_candidate(fold_sail_angle(delta), phi, v1, v2)

