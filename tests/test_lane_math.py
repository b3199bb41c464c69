"""The sea's vectorisable sin, cos and exp against the C library's (math), in units in the last place."""

import math

import numba
import numpy as np
import pytest

from sailmujoco.forces import lane_math


@numba.njit
def _sincos_all(x, c, s):
    for i in range(x.size):
        c[i], s[i] = lane_math.sincos(x[i])


@numba.njit
def _exp_all(x, out):
    for i in range(x.size):
        out[i] = lane_math.exp(x[i])


def _ulps(value, reference):
    """|value - reference| in units of the reference's last place (of 1 for |reference| < 1e-300)."""
    spacing = np.spacing(np.maximum(np.abs(reference), np.spacing(1.0)))
    return np.abs(value - reference) / spacing


@pytest.mark.parametrize("scale", [1e-3, 1.0, 10.0, 1e3, 1e5, lane_math.SINCOS_RANGE])
def test_sincos_is_within_two_ulp_of_the_c_library(scale):
    x = np.random.default_rng(1).uniform(-scale, scale, 20_000)
    x = np.concatenate([x, [0.0, math.pi / 4, -math.pi / 4, math.pi / 2, math.pi, 3 * math.pi / 2]])
    c, s = np.empty_like(x), np.empty_like(x)
    _sincos_all(x, c, s)
    assert _ulps(c, np.cos(x)).max() <= 2.0
    assert _ulps(s, np.sin(x)).max() <= 2.0


def test_sincos_quadrants_and_identity():
    x = np.arange(-40, 41) * (math.pi / 4) + 1e-3
    c, s = np.empty_like(x), np.empty_like(x)
    _sincos_all(x, c, s)
    np.testing.assert_allclose(c * c + s * s, 1.0, rtol=0, atol=4e-16)
    assert np.all(np.sign(c) == np.sign(np.cos(x)))
    assert np.all(np.sign(s) == np.sign(np.sin(x)))


def test_exp_is_within_two_ulp_of_the_c_library():
    rng = np.random.default_rng(2)
    x = np.concatenate([rng.uniform(-700.0, 700.0, 20_000), rng.uniform(-1.0, 1.0, 20_000),
                        [0.0, -1e-300, 1e-12, -0.5 * math.log(2.0), 0.5 * math.log(2.0), 709.0]])
    out = np.empty_like(x)
    _exp_all(x, out)
    assert _ulps(out, np.exp(x)).max() <= 2.0
    assert out[-6] == 1.0


def test_exp_underflows_to_zero_below_its_range():
    x = np.array([-745.5, -800.0, -1e6, -np.inf])
    out = np.empty_like(x)
    _exp_all(x, out)
    assert np.all(out == 0.0)
