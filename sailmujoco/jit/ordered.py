"""Arithmetic whose bits do not depend on the CPU: small linear algebra summed in a written order,
and numpy's transcendental functions taken element by element from the C library.

Three things in a Python process pick their code by the CPU they run on, and give other last
bits on another machine for the same inputs:

- numpy's matrix products and ``numpy.linalg`` (and numba's, which call the same BLAS and
  LAPACK through scipy) go to OpenBLAS, which chooses its kernels at run time (an AVX-512
  machine's dot product sums in another order, and with fused multiply-adds, than an AVX2
  machine's);
- numpy's ufuncs ``sin``, ``cos``, ``exp``, ``log``, ``arctan2``, ``hypot``, ``power`` and their
  kin run SIMD kernels chosen at run time (on AVX-512 machines a vector math library whose
  results differ from the C library's in the last bits);
- numba compiles for the host CPU (with fused multiply-adds and vector widths of its own where a
  kernel lets the compiler reorder sums; the kernels here and in ``forces/`` never do).

So the closed loop and the set-up of a run (the boat's model, its sea and gusts, a controller's
gains) use the functions here, or ``math`` on scalars, instead. ``math`` calls the C library, one
binary on the machine, the same code on every x86-64 CPU with FMA (glibc picks its FMA variants
on every such CPU); MuJoCo is one binary for every x86-64 CPU with AVX. What is left to the CPU
is documented in docs/performance.md ("One answer on every machine"), and
``tests/test_cpu_targets.py`` runs the same trajectories with numba's kernels compiled for two
CPU targets and numpy's SIMD and BLAS kernels switched between two CPU generations.

Each kernel here is compiled with numba (inlined where it is called from another kernel) and
callable from Python, so that a Python path and its compiled twin give the same bits.
"""

from __future__ import annotations

import math

import numpy as np

from .kernel import kernel


@kernel(inline=True)
def mat_vec(m, v):
    """``m @ v`` for a small matrix, each row summed from its first column to its last.

    Parameters
    ----------
    m : numpy.ndarray, shape (r, c)
        The matrix.
    v : numpy.ndarray, shape (c,)
        The vector.

    Returns
    -------
    numpy.ndarray, shape (r,)
        sum_j m[i, j] v[j], in the order j = 0 .. c - 1.
    """
    out = np.empty(m.shape[0])
    for i in range(m.shape[0]):
        s = 0.0
        for j in range(m.shape[1]):
            s += m[i, j] * v[j]
        out[i] = s
    return out


@kernel(inline=True)
def mat_t_vec(m, v):
    """``m.T @ v`` for a small matrix (a rotation's inverse applied to a vector), each sum in the
    order of ``m``'s rows.

    Parameters
    ----------
    m : numpy.ndarray, shape (r, c)
        The matrix.
    v : numpy.ndarray, shape (r,)
        The vector.

    Returns
    -------
    numpy.ndarray, shape (c,)
        sum_i m[i, j] v[i], in the order i = 0 .. r - 1.
    """
    return mat_vec(m.T, v)  # the same sums: row j of m.T is column j of m


@kernel(inline=True)
def mat_mat(a, b):
    """``a @ b`` for small matrices, each entry summed in the order of the inner index.

    Parameters
    ----------
    a : numpy.ndarray, shape (r, n)
        The left matrix.
    b : numpy.ndarray, shape (n, c)
        The right matrix.

    Returns
    -------
    numpy.ndarray, shape (r, c)
        sum_k a[i, k] b[k, j], in the order k = 0 .. n - 1.
    """
    out = np.empty((a.shape[0], b.shape[1]))
    for i in range(a.shape[0]):
        for j in range(b.shape[1]):
            s = 0.0
            for k in range(a.shape[1]):
                s += a[i, k] * b[k, j]
            out[i, j] = s
    return out


@kernel(inline=True)
def solve(a, b):
    """Solve ``a x = b`` for a small square system: Gaussian elimination with partial pivoting
    (the row of largest magnitude in each column; the first such row on a tie), written out.

    Parameters
    ----------
    a : numpy.ndarray, shape (n, n)
        The matrix (not changed).
    b : numpy.ndarray, shape (n,)
        The right-hand side (not changed).

    Returns
    -------
    numpy.ndarray, shape (n,)
        x. A singular matrix gives inf or NaN entries, as a division by zero does.
    """
    n = a.shape[0]
    m = a.copy()
    x = b.copy()
    for col in range(n):
        pivot = col
        for row in range(col + 1, n):
            if abs(m[row, col]) > abs(m[pivot, col]):
                pivot = row
        if pivot != col:
            for k in range(n):
                m[col, k], m[pivot, k] = m[pivot, k], m[col, k]
            x[col], x[pivot] = x[pivot], x[col]
        for row in range(col + 1, n):
            factor = m[row, col] / m[col, col]
            for k in range(col, n):
                m[row, k] -= factor * m[col, k]
            x[row] -= factor * x[col]
    for row in range(n - 1, -1, -1):
        s = x[row]
        for k in range(row + 1, n):
            s -= m[row, k] * x[k]
        x[row] = s / m[row, row]
    return x


def elementwise(function, *values) -> np.ndarray:
    """``function`` (a scalar function of ``math``, or of the C library through it) applied to
    each element of ``values`` (broadcast against each other): numpy's ufunc with the CPU's SIMD
    kernel left out.

    Parameters
    ----------
    function : callable
        A function of floats returning a float (``math.exp``, ``math.hypot``, a lambda).
    *values : array_like
        Its arguments, of shapes that broadcast.

    Returns
    -------
    numpy.ndarray
        float64, the broadcast shape.
    """
    arrays = np.broadcast_arrays(*(np.asarray(v, dtype=np.float64) for v in values))
    return np.fromiter(map(function, *(a.ravel().tolist() for a in arrays)), dtype=np.float64,
                       count=arrays[0].size).reshape(arrays[0].shape)


def power(base, exponent) -> np.ndarray:
    """``base ** exponent`` element by element through the C library's ``pow`` (numpy's float
    power picks a SIMD kernel by CPU).

    Parameters
    ----------
    base, exponent : array_like
        Broadcast against each other.

    Returns
    -------
    numpy.ndarray
        float64.
    """
    return elementwise(math.pow, base, exponent)


def gauss_legendre(n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on [-1, 1], by Newton's method on P_n (numpy's
    ``leggauss`` starts from LAPACK's eigenvalues, whose last bits vary by CPU).

    Each root starts from Tricomi's estimate cos(pi (i - 1/4) / (n + 1/2)) and takes Newton
    steps, P_n and P_n' from the three-term recurrence (Abramowitz and Stegun 22.7.10 and
    22.8.5), until a step no longer moves it by more than 1e-15; the weight is
    2 / ((1 - x^2) P_n'(x)^2) (A&S 25.4.29).

    Parameters
    ----------
    n : int
        Number of nodes, >= 1.

    Returns
    -------
    x, w : numpy.ndarray, shape (n,)
        Nodes in increasing order and their weights.
    """
    x = np.empty(n)
    w = np.empty(n)
    for i in range(n):
        root = math.cos(math.pi * (i + 0.75) / (n + 0.5))
        for _ in range(100):
            p0, p1 = 1.0, root
            for k in range(2, n + 1):
                p0, p1 = p1, ((2 * k - 1) * root * p1 - (k - 1) * p0) / k
            slope = n * (root * p1 - p0) / (root * root - 1.0) if n > 1 else 1.0
            step = (p1 if n > 1 else root) / slope
            root -= step
            if abs(step) <= 1e-15:
                break
        p0, p1 = 1.0, root
        for k in range(2, n + 1):
            p0, p1 = p1, ((2 * k - 1) * root * p1 - (k - 1) * p0) / k
        slope = n * (root * p1 - p0) / (root * root - 1.0) if n > 1 else 1.0
        x[n - 1 - i] = root
        w[n - 1 - i] = 2.0 / ((1.0 - root * root) * slope * slope)
    return x, w


def least_squares_2x2(jac, f) -> np.ndarray:
    """The minimum-norm least-squares solution of ``jac x = f`` for a 2 x 2 ``jac``
    (``numpy.linalg.lstsq`` with its default cut-off, whose LAPACK varies by CPU), written out.

    Full rank (the smaller singular value above 2 eps times the larger, as lstsq's default
    ``rcond``): Cramer's rule. Rank one: the pseudo-inverse of a rank-one matrix, J^T / ||J||_F^2,
    times ``f``. Zero: zeros.

    Parameters
    ----------
    jac : array_like, shape (2, 2)
        The matrix.
    f : array_like, shape (2,)
        The right-hand side.

    Returns
    -------
    numpy.ndarray, shape (2,)
        x.
    """
    (a, b), (c, d) = ((float(v) for v in row) for row in np.asarray(jac, dtype=np.float64))
    f0, f1 = (float(v) for v in np.asarray(f, dtype=np.float64))
    frobenius2 = a * a + b * b + c * c + d * d
    det = a * d - b * c
    if frobenius2 == 0.0:
        return np.zeros(2)
    # sigma_min / sigma_max >= det / ||J||_F^2 within a factor 2: full rank above 2 eps
    if abs(det) > 2.0 * 2.220446049250313e-16 * frobenius2:
        return np.array([(d * f0 - b * f1) / det, (a * f1 - c * f0) / det])
    return np.array([(a * f0 + c * f1) / frobenius2, (b * f0 + d * f1) / frobenius2])


def geomspace(start: float, stop: float, num: int) -> np.ndarray:
    """``numpy.geomspace`` for positive ends, each point start (stop / start)^(i / (num - 1)) from
    the C library's ``pow`` (numpy takes them from its SIMD power, which varies by CPU); the ends
    exactly ``start`` and ``stop``.

    Parameters
    ----------
    start, stop : float
        The ends, > 0.
    num : int
        Number of points, >= 2.

    Returns
    -------
    numpy.ndarray, shape (num,)
        The points.
    """
    ratio = stop / start
    points = np.array([start * math.pow(ratio, i / (num - 1)) for i in range(num)])
    points[0], points[-1] = start, stop
    return points
