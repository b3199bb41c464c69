"""The compiled wind: the velocity the force kernels read at a time and a height.

Wille (2016a) eqs. 39-43 evaluated from the tables of a :class:`~sailmujoco.forces.wind.WindField`
(its ``gust_frequency``, ``gust_phase``, ``gust_amplitude`` over ``log_z``, and the ``wander``
series): the gust sum of cosines (eq. 39), the mean log profile (eq. 40), the direction wander
(eq. 43) and the resulting world velocity (ENU, where the air goes to). The configuration, the
spectrum and the seeded realisation of those tables are in :mod:`sailmujoco.forces.wind`.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.kernel import kernel
from .lane_math import SINCOS_RANGE, sincos


@kernel
def gust_cosines(t, frequency, phase, cache):
    """cos(2 pi f_k t + Y_k) of eq. 39 for every k into ``cache[1:]``, once per time.

    ``cache[0]`` holds the time the cosines are for (NaN: none yet). They depend on t alone, so
    one force evaluation (sail, topsides, mast) and RK4's two mid-step stages share them (300 of
    a sub-step's 400 cosines); the same expression either way, so the same bits.

    Parameters
    ----------
    t : float
        Time, s.
    frequency, phase : numpy.ndarray, shape (n,)
        Gust component frequencies f_k (Hz) and phases Y_k (rad).
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    """
    if cache[0] == t:
        return
    two_pi_t = 2.0 * math.pi * t
    n = frequency.shape[0]
    bound = 0.0  # the largest argument's size bound: the polynomial cosine's range
    for k in range(n):
        bound = max(bound, abs(two_pi_t * frequency[k]) + abs(phase[k]))
    if bound < SINCOS_RANGE:  # on vector lanes (forces/lane_math.py: within 2 ulp of math.cos)
        for k in range(n):
            c, _ = sincos(two_pi_t * frequency[k] + phase[k])
            cache[1 + k] = c
    else:
        for k in range(n):
            cache[1 + k] = math.cos(two_pi_t * frequency[k] + phase[k])
    cache[0] = t


@kernel(inline=True)
def _gust_place(z, log_z):
    """(j, s): the interval of ``log_z`` holding ln z and the fraction s across it (clamped)."""
    lz = math.log(max(z, 1e-6))
    m = log_z.shape[0]
    if lz <= log_z[0]:
        return 0, 0.0
    if lz >= log_z[m - 1]:
        return m - 2, 1.0
    j = np.searchsorted(log_z, lz) - 1
    return j, (lz - log_z[j]) / (log_z[j + 1] - log_z[j])


@kernel(inline=True)
def _gust_amplitude(amplitude, j, s, k):
    """Component k's amplitude at the height of (j, s) (:func:`_gust_place`), linear in ln z."""
    return amplitude[j, k] + s * (amplitude[j + 1, k] - amplitude[j, k])


@kernel
def gust_sum(z, cache, amplitude, log_z):
    """U_g(z, t), eq. 39, from the cosines of :func:`gust_cosines`, amplitudes linear in ln z.

    Parameters
    ----------
    z : float
        Height above the water, m.
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    amplitude, log_z : numpy.ndarray, shapes (m, n) and (m,)
        Component amplitudes sqrt(2 S df) (m/s) at the heights whose ln (m) is ``log_z``.
    """
    j, s = _gust_place(z, log_z)
    total = 0.0
    for k in range(amplitude.shape[1]):
        total += _gust_amplitude(amplitude, j, s, k) * cache[1 + k]
    return total


@kernel
def gust_sums3(z0, z1, z2, cache, amplitude, log_z):
    """:func:`gust_sum` at three heights in one pass over the components.

    Each height's sum adds the same terms in the same order as :func:`gust_sum`, so each is
    bit for bit that sum; the three chains of additions run side by side instead of one after
    the other (the sum is bound by the latency of its additions).

    Parameters
    ----------
    z0, z1, z2 : float
        Heights above the water, m.
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    amplitude, log_z : numpy.ndarray, shapes (m, n) and (m,)
        Component amplitudes sqrt(2 S df) (m/s) at the heights whose ln (m) is ``log_z``.
    """
    j0, s0 = _gust_place(z0, log_z)
    j1, s1 = _gust_place(z1, log_z)
    j2, s2 = _gust_place(z2, log_z)
    t0 = 0.0
    t1 = 0.0
    t2 = 0.0
    for k in range(amplitude.shape[1]):
        c = cache[1 + k]
        t0 += _gust_amplitude(amplitude, j0, s0, k) * c
        t1 += _gust_amplitude(amplitude, j1, s1, k) * c
        t2 += _gust_amplitude(amplitude, j2, s2, k) * c
    return t0, t1, t2


@kernel
def gust_speed(t, z, frequency, phase, amplitude, log_z):
    """U_g(z, t), eq. 39, with amplitudes interpolated linearly in ln z.

    Parameters
    ----------
    t, z : float
        Time (s) and height above the water (m).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`WindField`: f_k (Hz), Y_k (rad), the amplitudes sqrt(2 S df)
        (m/s), shape (m, n), at the heights whose ln (m) is ``log_z``.
    """
    cache = np.full(frequency.shape[0] + 1, np.nan)
    gust_cosines(t, frequency, phase, cache)
    return gust_sum(z, cache, amplitude, log_z)


@kernel
def mean_speed(z, mean_speed_10):
    """Log profile, eq. 40 (kernel twin of :func:`log_profile`).

    Parameters
    ----------
    z : float
        Height above the water, m.
    mean_speed_10 : float
        Mean wind speed at 10 m, m/s.
    """
    k = 0.0026
    z0 = 10.0 * math.exp(-2.0 / (5.0 * math.sqrt(k)))
    if z <= z0:
        return 0.0
    return mean_speed_10 * 2.5 * math.sqrt(k) * math.log(z / z0)


@kernel
def wander_angle(t, dt, series):
    """beta_flux(t), eq. 43, linear interpolation of the random walk.

    Parameters
    ----------
    t, dt : float
        Time and the time step of ``series``, s.
    series : numpy.ndarray
        The wander at ``k dt``, rad.
    """
    x = t / dt
    if x <= 0.0:
        return series[0]
    i = int(x)
    n = series.shape[0]
    if i >= n - 1:
        return series[n - 1]
    s = x - i
    return series[i] + s * (series[i + 1] - series[i])


@kernel
def wind_velocity(t, z, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z,
                  wander_dt, wander, out):
    """World wind velocity at (t, z) into ``out`` (3,), eqs. 40-43.

    Parameters
    ----------
    t, z : float
        Time (s) and height above the water (m).
    speed10, direction_from, oscillation, wander_dt, wander : float or numpy.ndarray
        U_m10 (m/s); the mean bearing the wind comes from (rad); the modulation (speed m/s,
        direction rad, frequency Hz); the wander series (rad) at ``k wander_dt`` seconds.
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`WindField`: f_k (Hz), Y_k (rad), the amplitudes sqrt(2 S df)
        (m/s), shape (m, n), at the heights whose ln (m) is ``log_z``.
    out : numpy.ndarray, shape (3,)
        Receives the velocity (ENU, where the air goes), m/s.
    """
    cache = np.full(frequency.shape[0] + 1, np.nan)
    wind_velocities(t, z, z, z, 1, speed10, direction_from, oscillation, frequency, phase, amplitude,
                    log_z, wander_dt, wander, cache, out)


@kernel
def wind_velocities(t, z0, z1, z2, count, speed10, direction_from, oscillation, frequency, phase,
                    amplitude, log_z, wander_dt, wander, cache, out):
    """World wind velocity at time t and ``count`` (1 to 3) heights z0, z1, z2 into
    ``out[3 i:3 i + 3]``: the boat's sail and windage points in one call.

    What depends on t alone (modulation, direction, the gust cosines) is evaluated once; each
    height's value is the same expression as for one height alone, so the same bits.

    Parameters
    ----------
    t : float
        Time, s.
    z0, z1, z2 : float
        Heights above the water, m.
    count : int
        How many of the heights to evaluate, 1 to 3.
    speed10, direction_from, oscillation, wander_dt, wander : float or numpy.ndarray
        U_m10 (m/s); the mean bearing the wind comes from (rad); the modulation (speed m/s,
        direction rad, frequency Hz); the wander series (rad) at ``k wander_dt`` seconds.
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`WindField`: f_k (Hz), Y_k (rad), the amplitudes sqrt(2 S df)
        (m/s), shape (m, n), at the heights whose ln (m) is ``log_z``.
    cache : numpy.ndarray, shape (n + 1,)
        ``cache[0]`` the time, ``cache[1:]`` the cosines (:func:`gust_cosines`).
    out : numpy.ndarray, shape (3 count,)
        Receives the velocities (ENU, where the air goes), m/s.
    """
    s = math.sin(2.0 * math.pi * oscillation[2] * t)
    mean10 = speed10 + oscillation[0] * s
    u0 = mean_speed(z0, mean10)
    u1 = mean_speed(z1, mean10) if count > 1 else 0.0
    u2 = mean_speed(z2, mean10) if count > 2 else 0.0
    if speed10 > 0.0:
        gust_cosines(t, frequency, phase, cache)
        if count == 1:
            u0 += gust_sum(z0, cache, amplitude, log_z)
        else:
            g0, g1, g2 = gust_sums3(z0, z1, z2, cache, amplitude, log_z)
            u0 += g0
            u1 += g1
            u2 += g2
    bearing = direction_from + wander_angle(t, wander_dt, wander) + oscillation[1] * s
    sb = math.sin(bearing)
    cb = math.cos(bearing)
    out[0] = -u0 * sb
    out[1] = -u0 * cb
    out[2] = 0.0
    if count > 1:
        out[3] = -u1 * sb
        out[4] = -u1 * cb
        out[5] = 0.0
    if count > 2:
        out[6] = -u2 * sb
        out[7] = -u2 * cb
        out[8] = 0.0
