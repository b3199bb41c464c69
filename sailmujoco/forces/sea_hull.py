"""The hull in the sea: what the waves add to calm water's buoyancy, summed on a coarse grid.

The force kernel keeps calm water's buoyancy on the hull's fine columns as it is
(:func:`sailmujoco.forces.hydrostatics.geometric_buoyancy`, bit for bit) and adds the sea's part,
:func:`hull_sea_wrench`, on the coarse regular grid of :mod:`sailmujoco.hull_grid`:

    F = F_calm(fine) + [F_sea(grid) - F_calm(grid)],

where F_sea is :func:`sailmujoco.forces.wave_pressure.froude_krylov`'s force (each column cut at
the local surface eta_i, the wave's pressure stretched to it) and F_calm the grid's own still-water
buoyancy, so the bracket vanishes with the waves and the grid's error in the hull's shape cancels.
Three more terms, each with its switch (:class:`sailmujoco.options.ForceSwitches`):

* **Froude-Krylov** (``wave_pressure_decay``): the dynamic pressure
  rho g sum_j a_j e^(k_j z_s) cos(theta_j) on each column, its exponential expanded to third
  order in k_j z_s (:data:`ORDERS` terms; the columns span the hull's draft, tenths of a metre,
  so k z_s stays below about 0.5 for the components that carry the sea's energy). Each column's
  force is then sum_n J_n / n! times sum_j a_j k_j^(n+1) (...)_j, with J_n = integral of z_s^n
  along its wet part: the sums over components are products and additions only. False: the
  pressure hydrostatic to the local surface, p = -rho g z_s (the n = 0 term of the horizontal
  force, no vertical dynamic part): the form of VRX's and most simulators' wave buoyancy.
* **Diffraction** (``wave_diffraction``): G. I. Taylor's long-wave approximation (Newman,
  *Marine Hydrodynamics*, 1977, ch. 4.15; Faltinsen 1990, ch. 3): a body small against the
  wavelength feels (rho V + A) times the water's acceleration; rho V is the Froude-Krylov force
  above, A times the acceleration the diffraction force. It is summed strip-wise: the added mass
  A11, A22, A33 (the boat's, the same that the mass matrix holds at CO) shared among the grid's
  stations in proportion to b(x)^2 (:func:`sailmujoco.hull_grid.section_weights`), each strip
  taking the water's acceleration on the centre line at its section's centroid depth, turned to
  body axes, and acting at (x_i, 0, 0), the height where the mass matrix holds the added mass, so
  that the long wave's sway force and the added mass's inertia cancel as they do for a body
  carried by the water. The water's rotation (zero: irrotational) gives no roll or pitch term.
* **Relative damping** (``wave_damping``): the water's vertical velocity at the waterplane, its
  mean over the grid's columns at the centre of flotation and the rate of its slope along the
  hull (a least-squares line in x), returned in ``water`` for the heave and pitch damping
  (:func:`sailmujoco.forces.damping.vertical_damping`) to act on the motion relative to it.

Left out: waves near or shorter than the hull (lambda ~ L), where diffraction is as large as the
Froude-Krylov force and no longer the long-wave term; the waves the moving hull radiates beyond
the damping it has in calm water; added resistance in waves; green water; the second-order
(drift) forces.
"""

from __future__ import annotations

import math

from .._jit import kernel
from .hydrostatics import buoyancy_wrench
from .wave_pressure import wet_interval

ORDERS = 4  # e^x ~ 1 + x + x^2/2 + x^3/6
_GAUSS_X = (-0.7745966692414834, 0.0, 0.7745966692414834)  # 3-point Gauss-Legendre on [-1, 1]
_GAUSS_W = (0.5555555555555556, 0.8888888888888888, 0.5555555555555556)
# rows of the scratch array (per component): coefficients a_j k_j^(n+1) (cos b, sin b, 1) for
# n < ORDERS, a_j, a_j omega_j, a_j omega_j^2, the station's phasor, the x step's, then the rows'
_AX, _AY, _AZ = 0, ORDERS, 2 * ORDERS
_A, _AW, _AA, _ER, _EI, _SR, _SI, _ROWS = (3 * ORDERS + i for i in range(8))
SCRATCH_ROWS = _ROWS  # scratch rows of the sea array, plus two per grid row
SMALL_SIZE = 5 * ORDERS + 30  # scratch floats


@kernel(inline=True)
def _setup(sea, dx, dy, nx, ny, decay, sc):
    """Fill the scratch rows: the sums' coefficients and the phasors at the first station and
    rows (three sines and cosines per component)."""
    for j in range(sea.shape[1]):
        a, omega, k = sea[6, j], sea[1, j], sea[2, j]
        cb, sb = sea[3, j], sea[4, j]
        kp = a * k
        for n in range(ORDERS):
            on = 1.0 if (decay or n == 0) else 0.0
            sc[_AX + n, j] = on * kp * cb
            sc[_AY + n, j] = on * kp * sb
            sc[_AZ + n, j] = kp if decay else 0.0
            kp *= k
        sc[_A, j] = a
        sc[_AW, j] = a * omega
        sc[_AA, j] = a * omega * omega
        theta = sea[7, j] - 0.5 * (nx - 1) * dx * sea[8, j]  # first station, centre line
        sc[_ER, j], sc[_EI, j] = math.cos(theta), math.sin(theta)
        sc[_SR, j], sc[_SI, j] = math.cos(sea[8, j] * dx), math.sin(sea[8, j] * dx)
        hr, hi = math.cos(0.5 * sea[9, j] * dy), math.sin(0.5 * sea[9, j] * dy)
        yr, yi = 1.0, 0.0  # conj(h)^(ny - 1): the first row's phasor, e^(i kappa_y y_0)
        for _ in range(ny - 1):
            yr, yi = yr * hr + yi * hi, yi * hr - yr * hi
        sr, si = hr * hr - hi * hi, 2.0 * hr * hi  # h^2: one row's step
        for p in range(ny):
            sc[_ROWS + 2 * p, j], sc[_ROWS + 2 * p + 1, j] = yr, yi
            yr, yi = yr * sr - yi * si, yr * si + yi * sr


@kernel(reassociate=True)
def _cell_sums(sc, kappa_y, p, offset, sums):
    """Sum over components at one cell (station phasor times row p's, moved by ``offset`` along
    body y to the column's centre to first order, e^(i kappa_y offset) ~ 1 + i kappa_y offset):
    eta, d eta / dt and the ORDERS x 3 Froude-Krylov sums, into ``sums``."""
    eta = 0.0
    rate = 0.0
    yr_row, yi_row = _ROWS + 2 * p, _ROWS + 2 * p + 1
    s0 = s1 = s2 = s3 = s4 = s5 = s6 = s7 = s8 = s9 = s10 = s11 = 0.0
    for j in range(sc.shape[1]):
        cr = sc[_ER, j] * sc[yr_row, j] - sc[_EI, j] * sc[yi_row, j]  # at the row's centre
        ci = sc[_ER, j] * sc[yi_row, j] + sc[_EI, j] * sc[yr_row, j]
        turn = kappa_y[j] * offset
        pr = cr - turn * ci  # cos(theta) at the column
        pi = ci + turn * cr  # sin(theta)
        eta += sc[_A, j] * pr
        rate += sc[_AW, j] * pi
        s0 += sc[_AX, j] * pi
        s1 += sc[_AX + 1, j] * pi
        s2 += sc[_AX + 2, j] * pi
        s3 += sc[_AX + 3, j] * pi
        s4 += sc[_AY, j] * pi
        s5 += sc[_AY + 1, j] * pi
        s6 += sc[_AY + 2, j] * pi
        s7 += sc[_AY + 3, j] * pi
        s8 += sc[_AZ, j] * pr
        s9 += sc[_AZ + 1, j] * pr
        s10 += sc[_AZ + 2, j] * pr
        s11 += sc[_AZ + 3, j] * pr
    sums[0], sums[1], sums[2], sums[3] = s0, s1, s2, s3
    sums[4], sums[5], sums[6], sums[7] = s4, s5, s6, s7
    sums[8], sums[9], sums[10], sums[11] = s8, s9, s10, s11
    return eta, rate


@kernel(inline=True)
def _column_dynamic(sums, h_stretched, r22, lo, hi, rga, moments, force):
    """The dynamic force on one column's wet part (world) and its sum of axial centroid times
    force (for the moment) into ``force`` (6,).

    J_n / n! = integral of z_s^n / n! and Z_n / n! = integral of zeta z_s^n / n! along the wet
    axis (``moments`` receives them, rows J then Z) by 3-point Gauss, exact for the
    polynomials of degree <= 4 they integrate; then each force is sum_n J_n / n! times its
    sum over components (:func:`_cell_sums`).
    """
    half, mid = 0.5 * (hi - lo), 0.5 * (hi + lo)
    for n in range(2 * ORDERS):
        moments[n] = 0.0
    for g in range(3):
        zeta = mid + half * _GAUSS_X[g]
        z_s = h_stretched + r22 * zeta
        term = half * _GAUSS_W[g] * rga  # w z_s^n / n!
        for n in range(ORDERS):
            moments[n] += term
            moments[ORDERS + n] += term * zeta
            term *= z_s / (n + 1)
    fx = fy = fz = gx = gy = gz = 0.0
    for n in range(ORDERS):
        j_n, z_n = moments[n], moments[ORDERS + n]
        fx += j_n * sums[n]
        fy += j_n * sums[ORDERS + n]
        fz -= j_n * sums[2 * ORDERS + n]
        gx += z_n * sums[n]
        gy += z_n * sums[ORDERS + n]
        gz -= z_n * sums[2 * ORDERS + n]
    force[0], force[1], force[2], force[3], force[4], force[5] = fx, fy, fz, gx, gy, gz


@kernel(inline=True)
def _add_moment(dyn, rot, x, y, f):
    """Add the column's world force f[0:3] and its moment about CO to ``dyn``: the lever R (x, y, 0)
    to the axis, R e_z along it times the axial moments f[3:6]."""
    rx = rot[0, 0] * x + rot[0, 1] * y
    ry = rot[1, 0] * x + rot[1, 1] * y
    rz = rot[2, 0] * x + rot[2, 1] * y
    ax, ay, az = rot[0, 2], rot[1, 2], rot[2, 2]
    dyn[0] += f[0]
    dyn[1] += f[1]
    dyn[2] += f[2]
    dyn[3] += ry * f[2] - rz * f[1] + ay * f[5] - az * f[4]
    dyn[4] += rz * f[0] - rx * f[2] + az * f[3] - ax * f[5]
    dyn[5] += rx * f[1] - ry * f[0] + ax * f[4] - ay * f[3]


@kernel(reassociate=True)
def _station_acceleration(sc, sea, decay_row):
    """The water's acceleration (world, m/s^2) on the centre line at the station whose phasor
    the scratch holds, at depth factors ``decay_row`` (e^(k_j z_c))."""
    ax = 0.0
    ay = 0.0
    az = 0.0
    for j in range(sc.shape[1]):
        c = sc[_AA, j] * decay_row[j]
        horizontal = c * sc[_EI, j]  # d/dt of a omega e^(kz) cos(theta) = a omega^2 e^(kz) sin(theta)
        ax += horizontal * sea[3, j]
        ay += horizontal * sea[4, j]
        az -= c * sc[_ER, j]
    return ax, ay, az


@kernel(inline=True)
def _add_diffraction(dyn_b, rot, x, share, added, acc_w):
    """Add a strip's diffraction force share * A * R^T a_w, acting at body (x, 0, 0), to the
    body-frame wrench ``dyn_b``."""
    fx = share * added[0] * (rot[0, 0] * acc_w[0] + rot[1, 0] * acc_w[1] + rot[2, 0] * acc_w[2])
    fy = share * added[1] * (rot[0, 1] * acc_w[0] + rot[1, 1] * acc_w[1] + rot[2, 1] * acc_w[2])
    fz = share * added[2] * (rot[0, 2] * acc_w[0] + rot[1, 2] * acc_w[1] + rot[2, 2] * acc_w[2])
    dyn_b[0] += fx
    dyn_b[1] += fy
    dyn_b[2] += fz
    dyn_b[4] -= x * fz
    dyn_b[5] += x * fy


@kernel(inline=True)
def _add_part(pos, rot, columns, part, eta, rate, sums, rg, tally, moments, force, dyn):
    """One column of the grid in the sea: its change of wet volume and first moment against
    calm water (``tally`` 0-3), its waterplane tallies for the water's heave and pitch rates
    (4-8: area, area x, area x^2, area rate, area x rate) and its dynamic force into ``dyn``."""
    area, x, y = columns[2, part], columns[0, part], columns[1, part]
    tally[4] += area
    tally[5] += area * x
    tally[6] += area * x * x
    tally[7] += area * rate
    tally[8] += area * x * rate
    r22 = rot[2, 2]
    h = pos[2] + rot[2, 0] * x + rot[2, 1] * y
    lo0, hi0 = wet_interval(h, r22, columns[3, part], columns[4, part], 0.0)
    lo, hi = wet_interval(h, r22, columns[3, part], columns[4, part], eta)
    dv0 = area * max(hi0 - lo0, 0.0)
    dv = area * max(hi - lo, 0.0)
    tally[0] += dv - dv0
    tally[1] += (dv - dv0) * x
    tally[2] += (dv - dv0) * y
    tally[3] += dv * 0.5 * (lo + hi) - dv0 * 0.5 * (lo0 + hi0)
    if hi > lo:
        _column_dynamic(sums, h - eta, r22, lo, hi, rg * area, moments, force)
        _add_moment(dyn, rot, x, y, force)


@kernel
def hull_sea_wrench(pos, rot, sea, decay_exp, sc, columns, dx, dy, nx, ny, flotation_x, added, decay,
                    diffraction, rho, g, small, out, water):
    """The sea's part of the hull's force (module docstring), body frame about CO, into ``out``;
    the water's vertical velocity at the centre of flotation (m/s) and its slope's rate along
    the hull (rad/s) into ``water``.

    Parameters
    ----------
    pos : numpy.ndarray, shape (3,)
        World position of CO, m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world.
    sea : numpy.ndarray, shape (SEA_ROWS, m)
        The sea's rows with this stage's filled (:func:`sailmujoco.forces.sea_kernels.sea_stage`).
    decay_exp : numpy.ndarray, shape (nx, m)
        e^(k_j z_c,i) at each station's section centroid depth.
    sc : numpy.ndarray, shape (SCRATCH_ROWS + 2 ny, m)
        Scratch.
    columns : numpy.ndarray, shape (6, nx * ny)
        The grid's columns (:func:`sailmujoco.hull_grid.hull_grid`) and in row 5 each station's
        share of the added mass (:func:`sailmujoco.hull_grid.section_weights`).
    dx, dy : float
        The grid's steps, m.
    nx, ny : int
        Its stations and rows.
    flotation_x : float
        Centre of flotation, body x, m.
    added : numpy.ndarray, shape (3,)
        The hull's added mass A11, A22, A33 (positive), kg.
    decay, diffraction : bool
        The switches ``wave_pressure_decay`` and ``wave_diffraction``.
    rho, g : float
        Water density (kg/m^3) and gravitational acceleration (m/s^2).
    small : numpy.ndarray, shape (SMALL_SIZE,)
        Scratch.
    out : numpy.ndarray, shape (6,)
        Receives the wrench, N and N m.
    water : numpy.ndarray, shape (2,)
        Receives the water's vertical velocity at the centre of flotation (m/s) and the rate of
        its surface's slope along body x (rad/s, bow up positive).
    """
    m = sea.shape[1]
    _setup(sea, dx, dy, nx, ny, decay, sc)
    small[5 * ORDERS:] = 0.0
    sums, moments, force = small[0:3 * ORDERS], small[3 * ORDERS:5 * ORDERS], small[5 * ORDERS:5 * ORDERS + 6]
    acc, dyn = small[5 * ORDERS + 6:5 * ORDERS + 9], small[5 * ORDERS + 9:5 * ORDERS + 15]  # dyn: world
    dyn_b, tally = small[5 * ORDERS + 15:5 * ORDERS + 21], small[5 * ORDERS + 21:5 * ORDERS + 30]
    shares = columns[5]
    rows_y0 = -0.5 * (ny - 1) * dy  # body y of the first row's centre
    for i in range(nx):
        if diffraction:
            acc[0], acc[1], acc[2] = _station_acceleration(sc, sea, decay_exp[i])
            _add_diffraction(dyn_b, rot, (i - 0.5 * (nx - 1)) * dx, shares[i], added, acc)
        for p in range(ny):
            c = 2 * (i * ny + p)
            if columns[2, c] <= 0.0 and columns[2, c + 1] <= 0.0:
                continue
            at = c if columns[2, c] > 0.0 else c + 1  # the phases: at the canoe part's centre
            eta, rate = _cell_sums(sc, sea[9], p, columns[1, at] - rows_y0 - p * dy, sums)
            for part in range(c, c + 2):
                if columns[2, part] > 0.0:
                    _add_part(pos, rot, columns, part, eta, rate, sums, rho * g, tally, moments,
                              force, dyn)
        for j in range(m):  # the next station: times the x step
            er, ei = sc[_ER, j], sc[_EI, j]
            sc[_ER, j] = er * sc[_SR, j] - ei * sc[_SI, j]
            sc[_EI, j] = er * sc[_SI, j] + ei * sc[_SR, j]
    buoyancy_wrench(tally[0], tally[1], tally[2], tally[3], rot, rho, g, out)
    for row in range(3):  # world -> body: R^T
        out[row] += rot[0, row] * dyn[0] + rot[1, row] * dyn[1] + rot[2, row] * dyn[2] + dyn_b[row]
        out[3 + row] += (rot[0, row] * dyn[3] + rot[1, row] * dyn[4] + rot[2, row] * dyn[5]
                         + dyn_b[3 + row])
    s_a, s_ax, s_axx, s_r, s_rx = tally[4], tally[5], tally[6], tally[7], tally[8]
    x_mean = s_ax / s_a
    slope_rate = (s_rx - x_mean * s_r) / (s_axx - x_mean * s_ax)
    water[0] = s_r / s_a + slope_rate * (flotation_x - x_mean)
    water[1] = slope_rate
