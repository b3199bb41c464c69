"""The CPU-independent arithmetic of sailmujoco.jit.ordered against its definitions."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from sailmujoco.jit import ordered


def _exact_sum(terms) -> float:
    return float(sum(Fraction(t) for t in terms))


def test_products_sum_in_the_written_order():
    """Each entry is the left-to-right float sum of its products: with terms chosen so that
    another order rounds differently, the written order's value comes out."""
    m = np.array([[1e16, 1.0, -1e16], [3.0, 4.0, 5.0]])
    v = np.array([1.0, 1.0, 1.0])
    # ((1e16 + 1) - 1e16) = 0 in floats (1e16 + 1 rounds to 1e16); the exact sum is 1
    assert ordered.mat_vec(m, v)[0] == 0.0
    assert ordered.mat_vec(m, v)[1] == 12.0
    assert list(ordered.mat_t_vec(m.T.copy(), v)) == [0.0, 12.0]
    a = np.array([[2.0, -1.0], [0.5, 4.0]])
    b = np.array([[1.0, 3.0], [-2.0, 0.25]])
    assert ordered.mat_mat(a, b).tolist() == [[4.0, 5.75], [-7.5, 2.5]]


def test_solve_is_exact_on_a_system_with_a_known_answer_and_pivots():
    """A 4x4 system built from x = (1, -2, 3, 0.5): its solution, with a zero first pivot that
    forces a row exchange."""
    a = np.array([[0.0, 2.0, 1.0, 4.0], [1.0, 1.0, 0.0, 2.0], [3.0, 0.0, 1.0, -1.0], [2.0, 1.0, 3.0, 0.0]])
    x = np.array([1.0, -2.0, 3.0, 0.5])
    b = np.array([_exact_sum(a[i] * x) for i in range(4)])
    np.testing.assert_allclose(ordered.solve(a, b), x, rtol=0.0, atol=1e-14)
    assert a[0, 0] == 0.0  # the inputs are left as they were


def test_least_squares_2x2_full_rank_rank_one_and_zero():
    """Cramer's rule where the matrix is regular; the minimum-norm solution where a column is
    zero (the trim's column of a hull lying on its side) or the rows are parallel; zeros for a
    zero matrix: each as numpy's lstsq defines it."""
    cases = [(np.array([[2.0, 1.0], [1.0, 3.0]]), np.array([3.0, 5.0])),
             (np.array([[2.0, 0.0], [1.0, 0.0]]), np.array([4.0, 1.0])),
             (np.array([[1.0, 2.0], [2.0, 4.0]]), np.array([1.0, 3.0])),
             (np.zeros((2, 2)), np.array([1.0, 2.0]))]
    for jac, f in cases:
        np.testing.assert_allclose(ordered.least_squares_2x2(jac, f), np.linalg.lstsq(jac, f, rcond=None)[0],
                                   rtol=1e-14, atol=1e-15)
    # the zero column: x = J^T f / ||J||^2 = (2*4 + 1*1) / 5, no trim step
    assert ordered.least_squares_2x2(*cases[1]).tolist() == [9.0 / 5.0, 0.0]


@pytest.mark.parametrize("n", [1, 2, 3, 5, 8, 16, 40])
def test_gauss_legendre_integrates_polynomials_to_degree_2n_minus_1(n):
    """n nodes integrate x^k over [-1, 1] exactly for k <= 2n - 1: 2 / (k + 1) for even k, 0 odd."""
    x, w = ordered.gauss_legendre(n)
    assert np.all(np.diff(x) > 0.0) and np.all(w > 0.0)
    np.testing.assert_allclose(x, -x[::-1], atol=1e-15)  # symmetric about 0
    for k in range(2 * n):
        exact = 2.0 / (k + 1) if k % 2 == 0 else 0.0
        assert math.isclose(float(np.sum(w * x**k)), exact, rel_tol=1e-13, abs_tol=1e-14), k


def test_elementwise_power_and_geomspace_take_the_c_librarys_values():
    """Element by element, the same float as math's function of that element."""
    values = np.linspace(-3.0, 3.0, 12).reshape(3, 4)
    out = ordered.elementwise(math.exp, values)
    assert out.shape == (3, 4)
    assert out.tolist() == [[math.exp(v) for v in row] for row in values.tolist()]
    assert ordered.power(np.array([2.0, 9.0]), 0.5).tolist() == [math.pow(2.0, 0.5), 3.0]
    assert ordered.power(2.0, np.array([-1.0, 10.0])).tolist() == [0.5, 1024.0]
    points = ordered.geomspace(0.05, 60.0, 48)
    assert points[0] == 0.05 and points[-1] == 60.0
    np.testing.assert_allclose(points[1:] / points[:-1], (60.0 / 0.05) ** (1.0 / 47.0), rtol=1e-14)
