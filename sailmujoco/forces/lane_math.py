"""sin, cos and exp as polynomials, so that a loop over wave components runs on vector lanes.

numba compiles ``math.sin``, ``math.cos`` and ``math.exp`` to calls into the C library, one
element at a time (this numba's LLVM has no vector math library): in the sea's kernels, three
phasors and two exponentials per component and stage, those calls cost more than the rest of
the sea. The functions here are plain arithmetic, branch-free and inlined, so that a loop
calling them over the components is vectorised by the compiler.

Each reduces its argument with Cody and Waite's method (W. J. Cody and W. Waite, *Software
Manual for the Elementary Functions*, 1980, ch. 4 and 8): x = n c + r, the constant c (pi/2 or
ln 2) split into parts short enough that n times each is exact, then evaluates the Taylor series
of r, whose remainder at the degrees used is below 1e-19 on the reduced range (|r| <= pi/4:
sin to r^17, cos to r^18; |r| <= ln(2)/2: exp to r^14). Measured against the C library
(tests/test_lane_math.py): within 2 units in the last place over the ranges stated.

The constants are derived here, at import, from pi and ln 2 to 50 digits (exact rational
arithmetic), and the series' coefficients are 1/n!: nothing is tabulated by hand.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np

from ..jit.kernel import kernel

_PI_HALF = Fraction("1.5707963267948966192313216916397514420985846996875529")
_LN2 = Fraction("0.69314718055994530941723212145817656807550013436025525")
_PART_BITS = 30  # bits of each part's mantissa: n * part is exact for |n| < 2^23


def _parts(value: Fraction, count: int) -> tuple[float, ...]:
    """``value`` as ``count`` floats of _PART_BITS bits each (the last one rounded), summing to it."""
    parts = []
    for i in range(count):
        f = float(value)
        if i < count - 1:
            mantissa, exponent = math.frexp(f)
            f = math.ldexp(math.floor(mantissa * 2.0 ** _PART_BITS) / 2.0 ** _PART_BITS, exponent)
        parts.append(f)
        value -= Fraction(f)
    return tuple(parts)


_PIO2_1, _PIO2_2, _PIO2_3 = _parts(_PI_HALF, 3)
_LN2_1, _LN2_2 = _parts(_LN2, 2)
_TWO_OVER_PI = float(1 / _PI_HALF)
_LOG2_E = float(1 / _LN2)


def _inverse_factorial(n: int) -> float:
    return float(Fraction(1, math.factorial(n)))


# sin r = r (1 + r^2 (S1 + r^2 (S2 + ...))), S_i = (-1)^i / (2i + 1)!
_S1, _S2, _S3, _S4, _S5, _S6, _S7, _S8 = ((-1) ** i * _inverse_factorial(2 * i + 1) for i in range(1, 9))
# cos r = 1 + r^2 (C1 + r^2 (C2 + ...)), C_i = (-1)^i / (2i)!
_C1, _C2, _C3, _C4, _C5, _C6, _C7, _C8, _C9 = ((-1) ** i * _inverse_factorial(2 * i) for i in range(1, 10))
# e^r = 1 + r (1 + r (E2 + r (E3 + ...))), E_i = 1 / i!
_E2, _E3, _E4, _E5, _E6, _E7, _E8, _E9, _E10, _E11, _E12, _E13, _E14 = (
    _inverse_factorial(i) for i in range(2, 15))
EXP_LOW = -745.0  # exp(x) for x below is 0
EXP_HIGH = 709.0  # the largest argument exp takes (below overflow)
_POW2 = np.ldexp(1.0, np.arange(-1075, 1024))  # 2^n, n = -1075 ... 1023, indexed by n + 1075
SINCOS_RANGE = 2.0 ** 22  # |x| up to which sincos's reduction is exact (n < 2^23)


@kernel(inline=True)
def sincos(x):
    """(cos x, sin x), x in radians, |x| < SINCOS_RANGE: within 2 ulp of the C library.

    Parameters
    ----------
    x : float
        The angle, rad.
    """
    n = math.floor(x * _TWO_OVER_PI + 0.5)
    r = ((x - n * _PIO2_1) - n * _PIO2_2) - n * _PIO2_3  # |r| <= pi/4
    r2 = r * r
    s = r + r * r2 * (_S1 + r2 * (_S2 + r2 * (_S3 + r2 * (_S4 + r2 * (_S5 + r2 * (
        _S6 + r2 * (_S7 + r2 * _S8)))))))
    c = 1.0 + r2 * (_C1 + r2 * (_C2 + r2 * (_C3 + r2 * (_C4 + r2 * (_C5 + r2 * (
        _C6 + r2 * (_C7 + r2 * (_C8 + r2 * _C9))))))))
    q = int(n) & 3  # the quadrant: x = n pi/2 + r
    odd = float(q & 1)
    even = 1.0 - odd
    sign_sin = 1.0 - 2.0 * float(q >> 1)  # sin: +s, +c, -s, -c for q = 0, 1, 2, 3
    sign_cos = 1.0 - 2.0 * float(((q + 1) >> 1) & 1)  # cos: +c, -s, -c, +s
    return sign_cos * (even * c + odd * s), sign_sin * (even * s + odd * c)


@kernel(inline=True)
def exp(x):
    """e^x for x <= EXP_HIGH (0 below EXP_LOW): within 2 ulp of the C library for normal results.

    Parameters
    ----------
    x : float
        The exponent.
    """
    x = max(x, EXP_LOW)
    n = math.floor(x * _LOG2_E + 0.5)
    r = (x - n * _LN2_1) - n * _LN2_2  # |r| <= ln(2)/2
    p = 1.0 + r * (1.0 + r * (_E2 + r * (_E3 + r * (_E4 + r * (_E5 + r * (_E6 + r * (
        _E7 + r * (_E8 + r * (_E9 + r * (_E10 + r * (_E11 + r * (_E12 + r * (_E13 + r * _E14)))))))))))))
    return p * _POW2[int(n) + 1075]
