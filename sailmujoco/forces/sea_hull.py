"""The hull in the sea: what the waves add to calm water's buoyancy, summed on a coarse grid.

The force kernel keeps calm water's buoyancy on the hull's fine columns as it is
(:func:`sailmujoco.forces.hydrostatics.geometric_buoyancy`, bit for bit) and adds the sea's part,
:func:`hull_sea_wrench`, on the coarse regular grid of :mod:`sailmujoco.boat.hull_grid`:

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
  stations in proportion to b(x)^2 (:func:`sailmujoco.boat.hull_grid.section_weights`), each strip
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

from ..boat.hull_grid import GRID_ROWS, GRID_STATIONS
from ..jit.kernel import kernel
from .hydrostatics import buoyancy_wrench
from .lane_math import sincos

ORDERS = 4  # e^x ~ 1 + x + x^2/2 + x^3/6
_GAUSS_X = (-0.7745966692414834, 0.0, 0.7745966692414834)  # 3-point Gauss-Legendre on [-1, 1]
_GAUSS_W = (0.5555555555555556, 0.8888888888888888, 0.5555555555555556)
# rows of the scratch array (per component): coefficients a_j k_j^(n+1) (cos b, sin b, 1) for
# n < ORDERS, a_j, a_j omega_j, a_j omega_j^2, the station's phasor, the x step's, then the rows'
_AX, _AY, _AZ = 0, ORDERS, 2 * ORDERS
_A, _AW, _AA, _ER, _EI, _SR, _SI, _ROWS = (3 * ORDERS + i for i in range(8))
SCRATCH_ROWS = _ROWS  # scratch rows of the sea array, plus two per grid row
CELL_ROWS = 2 + 3 * ORDERS  # per grid column: eta, d eta / dt, the Froude-Krylov sums
PART_ROWS = 15  # per grid column: its terms of the sums of :func:`_parts_wrench`
# scratch: the diffraction's wrench, the cells, the columns' terms
SMALL_SIZE = 6 + (CELL_ROWS + PART_ROWS) * 2 * GRID_STATIONS * GRID_ROWS


@kernel(inline=True)
def _setup(sea, dx, dy, nx, ny, decay, sc):
    """Fill the scratch rows: the sums' coefficients and the phasors at the first station, of
    one x step and at each row (polynomial sines and cosines, :mod:`.lane_math`)."""
    x0, y0 = -0.5 * (nx - 1) * dx, -0.5 * (ny - 1) * dy  # the first station and row, body x, y
    on = 1.0 if decay else 0.0  # the orders n >= 1 (all of the vertical force) with the decay
    for j in range(sea.shape[1]):
        a, k = sea[6, j], sea[2, j]
        kp = a * k
        sc[_AX, j] = kp * sea[3, j]
        sc[_AY, j] = kp * sea[4, j]
        sc[_AZ, j] = on * kp
        for n in range(1, ORDERS):
            kp *= k
            sc[_AX + n, j] = on * kp * sea[3, j]
            sc[_AY + n, j] = on * kp * sea[4, j]
            sc[_AZ + n, j] = on * kp
        sc[_A, j] = a
        sc[_AW, j] = a * sea[1, j]
        sc[_AA, j] = a * sea[1, j] * sea[1, j]
    for j in range(sea.shape[1]):
        sc[_ER, j], sc[_EI, j] = sincos(sea[7, j] + x0 * sea[8, j])  # first station, centre line
        sc[_SR, j], sc[_SI, j] = sincos(sea[8, j] * dx)
    for p in range((ny + 1) // 2):  # the rows lie in mirror pairs about the centre line
        y, mirror = y0 + p * dy, ny - 1 - p
        for j in range(sea.shape[1]):
            c, s = sincos(sea[9, j] * y)
            sc[_ROWS + 2 * p, j], sc[_ROWS + 2 * p + 1, j] = c, s
            sc[_ROWS + 2 * mirror, j], sc[_ROWS + 2 * mirror + 1, j] = c, -s


@kernel
def _cell_sums(sc, kappa_y, p, offset, cs, c):
    """Sum over components at one cell (station phasor times row p's, moved by ``offset`` along
    body y to the column's centre to first order, e^(i kappa_y offset) ~ 1 + i kappa_y offset):
    eta, d eta / dt and the ORDERS x 3 Froude-Krylov sums, into rows 0-13 of ``cs``' columns c
    and c + 1 (the cell's two parts)."""
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
    for col in range(c, c + 2):
        cs[0, col], cs[1, col] = eta, rate
        cs[2, col], cs[3, col], cs[4, col], cs[5, col] = s0, s1, s2, s3
        cs[6, col], cs[7, col], cs[8, col], cs[9, col] = s4, s5, s6, s7
        cs[10, col], cs[11, col], cs[12, col], cs[13, col] = s8, s9, s10, s11


@kernel(inline=True)
def _column_dynamic(cs, k, h_stretched, r22, lo, hi, rga):
    """The dynamic force on one column's wet part (world), and its sum of axial centroid times
    force (for the moment): (fx, fy, fz, gx, gy, gz).

    J_n / n! = integral of z_s^n / n! and Z_n / n! = integral of zeta z_s^n / n! along the wet
    axis by 3-point Gauss, exact for the polynomials of degree <= 4 they integrate; then each
    force is sum_n J_n / n! times its sum over components (column k of ``cs``, rows 2-13:
    :func:`_cell_sums`, ORDERS = 4).
    """
    half, mid = 0.5 * (hi - lo), 0.5 * (hi + lo)
    j0 = j1 = j2 = j3 = z0 = z1 = z2 = z3 = 0.0
    for g in range(3):
        zeta = mid + half * _GAUSS_X[g]
        z_s = h_stretched + r22 * zeta
        t0 = half * _GAUSS_W[g] * rga  # w z_s^n / n!
        t1 = t0 * z_s
        t2 = t1 * (z_s / 2.0)
        t3 = t2 * (z_s / 3.0)
        j0 += t0
        j1 += t1
        j2 += t2
        j3 += t3
        z0 += t0 * zeta
        z1 += t1 * zeta
        z2 += t2 * zeta
        z3 += t3 * zeta
    fx = j0 * cs[2, k] + j1 * cs[3, k] + j2 * cs[4, k] + j3 * cs[5, k]
    fy = j0 * cs[6, k] + j1 * cs[7, k] + j2 * cs[8, k] + j3 * cs[9, k]
    fz = -(j0 * cs[10, k] + j1 * cs[11, k] + j2 * cs[12, k] + j3 * cs[13, k])
    gx = z0 * cs[2, k] + z1 * cs[3, k] + z2 * cs[4, k] + z3 * cs[5, k]
    gy = z0 * cs[6, k] + z1 * cs[7, k] + z2 * cs[8, k] + z3 * cs[9, k]
    gz = -(z0 * cs[10, k] + z1 * cs[11, k] + z2 * cs[12, k] + z3 * cs[13, k])
    return fx, fy, fz, gx, gy, gz


@kernel
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
def _grid_phases(sea, decay_exp, sc, columns, rot, dx, dy, nx, ny, added, diffraction, cs, dyn_b):
    """Walk the grid's stations and rows: each cell's sums over components into ``cs``
    (:func:`_cell_sums`; zeros for a cell outside the deck) and, with ``diffraction``, each
    station's diffraction force into the body-frame wrench ``dyn_b``."""
    rows_y0 = -0.5 * (ny - 1) * dy  # body y of the first row's centre
    for i in range(nx):
        if diffraction:
            _add_diffraction(dyn_b, rot, (i - 0.5 * (nx - 1)) * dx, columns[5, i], added,
                             _station_acceleration(sc, sea, decay_exp[i]))
        for p in range(ny):
            c = 2 * (i * ny + p)
            if columns[2, c] <= 0.0 and columns[2, c + 1] <= 0.0:
                for row in range(CELL_ROWS):
                    cs[row, c] = cs[row, c + 1] = 0.0
                continue
            at = c if columns[2, c] > 0.0 else c + 1  # the phases: at the canoe part's centre
            _cell_sums(sc, sea[9], p, columns[1, at] - rows_y0 - p * dy, cs, c)
        for j in range(sea.shape[1]):  # the next station: times the x step
            er, ei = sc[_ER, j], sc[_EI, j]
            sc[_ER, j] = er * sc[_SR, j] - ei * sc[_SI, j]
            sc[_EI, j] = er * sc[_SI, j] + ei * sc[_SR, j]


@kernel
def _parts_wrench(pos, rot, columns, cs, rg, terms):
    """Each column of the grid in the sea: its change of wet volume and first moment against
    calm water, its dynamic force (:func:`_column_dynamic`) and moment about CO, and the
    waterplane's tallies. Returns (V, Qx, Qy, Qz, world force (3), world moment (3), area,
    area x, area x^2, area rate, area x rate).

    Each column's wet part is cut where its axis, at world height h + r22 z, meets the
    surface: as :func:`sailmujoco.forces.wave_pressure.wet_interval`, with r22 kept at least
    1e-12 from zero (a column lying flat is then wet or dry whole, as there). Every column's
    terms go into ``terms`` (PART_ROWS x columns) in a loop with no sum in it, which the
    compiler runs on vector lanes; then each sum runs over the columns in their order.
    """
    r22 = rot[2, 2]
    if abs(r22) < 1e-12:
        r22 = 1e-12 if r22 >= 0.0 else -1e-12
    inverse = 1.0 / r22
    upright = r22 > 0.0
    ax, ay, az = rot[0, 2], rot[1, 2], rot[2, 2]  # the columns' axis, world
    n = columns.shape[1]
    for k in range(n):
        x, y, area = columns[0, k], columns[1, k], columns[2, k]
        z_bottom, z_top = columns[3, k], columns[4, k]
        eta, rate = cs[0, k], cs[1, k]
        terms[10, k] = area
        terms[11, k] = area * x
        terms[12, k] = area * x * x
        terms[13, k] = area * rate
        terms[14, k] = area * x * rate
        h = pos[2] + rot[2, 0] * x + rot[2, 1] * y
        zw0, zw = -h * inverse, (eta - h) * inverse  # where the axis meets z = 0 and eta
        lo0 = z_bottom if upright else max(z_bottom, zw0)
        hi0 = min(z_top, zw0) if upright else z_top
        lo = z_bottom if upright else max(z_bottom, zw)
        hi = min(z_top, zw) if upright else z_top
        dv0 = area * max(hi0 - lo0, 0.0)
        dv = area * max(hi - lo, 0.0)
        terms[0, k] = dv - dv0
        terms[1, k] = (dv - dv0) * x
        terms[2, k] = (dv - dv0) * y
        terms[3, k] = dv * 0.5 * (lo + hi) - dv0 * 0.5 * (lo0 + hi0)
        wet = 1.0 if hi > lo else 0.0
        fx, fy, fz, gx, gy, gz = _column_dynamic(cs, k, h - eta, r22, lo, hi, rg * area * wet)
        rx = rot[0, 0] * x + rot[0, 1] * y  # the lever R (x, y, 0); R e_z along the axis
        ry = rot[1, 0] * x + rot[1, 1] * y
        rz = rot[2, 0] * x + rot[2, 1] * y
        terms[4, k], terms[5, k], terms[6, k] = fx, fy, fz
        terms[7, k] = ry * fz - rz * fy + ay * gz - az * gy
        terms[8, k] = rz * fx - rx * fz + az * gx - ax * gz
        terms[9, k] = rx * fy - ry * fx + ax * gy - ay * gx
    vol = qx = qy = qz = fwx = fwy = fwz = mwx = mwy = mwz = 0.0
    s_a = s_ax = s_axx = s_r = s_rx = 0.0
    for k in range(n):
        vol += terms[0, k]
        qx += terms[1, k]
        qy += terms[2, k]
        qz += terms[3, k]
        fwx += terms[4, k]
        fwy += terms[5, k]
        fwz += terms[6, k]
        mwx += terms[7, k]
        mwy += terms[8, k]
        mwz += terms[9, k]
        s_a += terms[10, k]
        s_ax += terms[11, k]
        s_axx += terms[12, k]
        s_r += terms[13, k]
        s_rx += terms[14, k]
    return (vol, qx, qy, qz, fwx, fwy, fwz, mwx, mwy, mwz, s_a, s_ax, s_axx, s_r, s_rx)


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
        The grid's columns (:func:`sailmujoco.boat.hull_grid.hull_grid`) and in row 5 each station's
        share of the added mass (:func:`sailmujoco.boat.hull_grid.section_weights`).
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
    _setup(sea, dx, dy, nx, ny, decay, sc)
    dyn_b = small[0:6]
    dyn_b[:] = 0.0
    parts = columns.shape[1]
    cs = small[6:6 + CELL_ROWS * parts].reshape((CELL_ROWS, parts))
    _grid_phases(sea, decay_exp, sc, columns, rot, dx, dy, nx, ny, added, diffraction, cs, dyn_b)
    start = 6 + CELL_ROWS * parts
    terms = small[start:start + PART_ROWS * parts].reshape((PART_ROWS, parts))
    (vol, qx, qy, qz, fwx, fwy, fwz, mwx, mwy, mwz, s_a, s_ax, s_axx, s_r, s_rx) = _parts_wrench(
        pos, rot, columns, cs, rho * g, terms)
    buoyancy_wrench(vol, qx, qy, qz, rot, rho, g, out)
    for row in range(3):  # world -> body: R^T
        out[row] += rot[0, row] * fwx + rot[1, row] * fwy + rot[2, row] * fwz + dyn_b[row]
        out[3 + row] += rot[0, row] * mwx + rot[1, row] * mwy + rot[2, row] * mwz + dyn_b[3 + row]
    x_mean = s_ax / s_a
    slope_rate = (s_rx - x_mean * s_r) / (s_axx - x_mean * s_ax)
    water[0] = s_r / s_a + slope_rate * (flotation_x - x_mean)
    water[1] = slope_rate
