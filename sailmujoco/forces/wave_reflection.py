"""The mean force of short waves reflected by the hull's side (``wave_reflection``).

Waves much shorter than the hull do not move it; they are reflected by its side, and the
reflected waves carry momentum away: a mean (second-order) force pushing the hull along the
waves. The pressure-integration and added-mass terms of :mod:`sailmujoco.forces.sea_hull` are
first order and long-wave; their means are the motion part of the added resistance, which
vanishes for short waves. This term is the short-wave part, after Faltinsen, Minsaas, Liapis
and Skjørdal (1980, "Prediction of resistance and propulsion of a ship in a seaway", 13th
Symposium on Naval Hydrodynamics; also Faltinsen 1990, *Sea Loads*, ch. 5) for a wall-sided
hull in short regular waves of amplitude a, frequency omega and wavenumber k, with forward
speed U:

    F = -1/2 rho g a^2 * integral over the waterline's lit part of
        [ (e.n)^2 + (2 omega U / g) (1 + t_x (t.e)) ] alpha(k, T) n dl,

with e the direction the wave travels, n the waterline's outward normal, t its tangent (the
bracket is Faltinsen's sin^2(theta + beta) + (2 omega U/g)(1 - cos theta cos(theta + beta))
written with vectors; in head seas it is (1 + 2 omega U / g) sin^2 theta), the lit part being
where e.n < 0. The canoe body is not wall-sided to infinite depth: each station's reflection is
scaled by Fujii and Takahashi's (1975) draft factor

    alpha = pi^2 I1(1.5 k T)^2 / (pi^2 I1(1.5 k T)^2 + K1(1.5 k T)^2),

with T the section's depth, in the 1.5 k T form of STAwave-2 (ITTC recommended procedure
7.5-04-01-01.1); alpha -> 1 for a deep side, and a yacht's shallow canoe body (B/T about 10)
reflects little: at lambda/L = 0.5 the Wille yacht's midship alpha is 0.12.

Each component of a sea adds its own mean force (the mean second-order force of a linear sea
is the sum of the components' own); the waterline is the upright one (heel and the motions
are left out of the geometry, as in the formula). The keel and rudder, thin foils edge-on to
head waves, reflect nothing in this model.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from ..jit.kernel import kernel

REFLECTION_STATIONS = 24  # stations along the waterline (midpoint rule)
# rows of the waterline array (the port side's; the starboard side mirrors y), then one per component
WL_X, WL_B, WL_NX, WL_NY, WL_TX, WL_TY, WL_DL, WL_ROWS = range(8)


def draft_factor(k, depth):
    """Fujii and Takahashi's reflection factor alpha(1.5 k T) (module docstring), -.

    Parameters
    ----------
    k : float or numpy.ndarray
        Wavenumber, rad/m.
    depth : float or numpy.ndarray
        Draft T of the reflecting side, m.
    """
    x = 1.5 * np.asarray(k, dtype=float) * np.asarray(depth, dtype=float)
    i1 = math.pi**2 * special.i1(x) ** 2
    return i1 / (i1 + special.k1(x) ** 2)


def station_rows(x, b, slope, dx) -> np.ndarray:
    """The waterline array's geometric rows (x, b, n_x, n_y, t_x, t_y, dl) of the port side's
    stations at x (m), half-breadth b (m), db/dx and length along x dx (m): the outward normal
    (-b', 1) / c and the tangent (1, b') / c, c = sqrt(1 + b'^2), and dl = c dx.

    Parameters
    ----------
    x, b, slope, dx : array_like, shape (n,)
        The stations' x and half-breadth (m), the waterline's slope db/dx and each station's
        length along x (m).
    """
    slope = np.asarray(slope, dtype=float)
    c = np.sqrt(1.0 + slope**2)
    return np.vstack([np.asarray(x, dtype=float), np.asarray(b, dtype=float), -slope / c, 1.0 / c,
                      1.0 / c, slope / c, c * np.asarray(dx, dtype=float)])


def waterline_array(hull, amplitude=(), k=()) -> np.ndarray:
    """The kernel's ``waterline`` array: the upright waterline's stations (:func:`station_rows`,
    port side; the starboard side mirrors it), then one row per component j of
    a_j^2 alpha(k_j, t(x)) / 2 at each station (m^2).

    Parameters
    ----------
    hull : HullShape
        The canoe body (:mod:`sailmujoco.boat.hull`: b = b0 (1 - s^2), t = t0 (1 - s^2)).
    amplitude, k : sequence of float
        The components' amplitudes (m) and wavenumbers (rad/m), in the sea array's order;
        empty in calm water.
    """
    n = REFLECTION_STATIONS
    dx = hull.length / n
    x = (np.arange(n) + 0.5) * dx - 0.5 * hull.length
    f = hull.fullness(x)
    out = np.zeros((WL_ROWS + len(amplitude), n))
    out[:WL_ROWS] = station_rows(x, hull.half_beam * f, -8.0 * hull.half_beam * x / hull.length**2,
                                 np.full(n, dx))
    for j, (a, kj) in enumerate(zip(amplitude, k, strict=True)):
        out[WL_ROWS + j] = 0.5 * a * a * draft_factor(kj, hull.canoe_draft * f)
    return np.ascontiguousarray(out)


@kernel
def reflection_wrench(sea, waterline, u, rho, g, out):
    """The short waves' mean reflection force (module docstring), body frame about CO, into
    ``out``.

    Parameters
    ----------
    sea : numpy.ndarray, shape (rows, m)
        The sea array at this stage (:mod:`sailmujoco.forces.sea_kernels`): rows 0 (a_j), 1
        (omega_j), 2 (k_j), 6 (the ramped amplitude) and 8-9 (the body-frame wavevector).
    waterline : numpy.ndarray, shape (7 + m, n)
        :func:`waterline_array`.
    u : float
        The surge speed through the water, m/s.
    rho, g : float
        Water density (kg/m^3) and gravity (m/s^2).
    out : numpy.ndarray, shape (6,)
        Receives the wrench (the force in x and y, the moment about z), N and N m.
    """
    for i in range(6):
        out[i] = 0.0
    for j in range(sea.shape[1]):
        ex, ey = sea[8, j], sea[9, j]  # the wave's direction in the body's horizontal plane
        norm = math.sqrt(ex * ex + ey * ey)
        if norm == 0.0 or sea[0, j] == 0.0:
            continue
        ex, ey = ex / norm, ey / norm
        ramp = sea[6, j] / sea[0, j]
        rga = rho * g * ramp * ramp
        speed = 2.0 * sea[1, j] * u / g
        for i in range(waterline.shape[1]):
            coef = rga * waterline[WL_ROWS + j, i] * waterline[WL_DL, i]  # per side
            nx, tx = waterline[WL_NX, i], waterline[WL_TX, i]
            for side in (1.0, -1.0):  # port (y = b), starboard (y = -b)
                ny = side * waterline[WL_NY, i]
                en = ex * nx + ey * ny
                if en >= 0.0:
                    continue  # in the shadow
                te = tx * ex + side * waterline[WL_TY, i] * ey
                f = coef * (en * en + speed * (1.0 + tx * te))
                fx, fy = -f * nx, -f * ny
                out[0] += fx
                out[1] += fy
                out[5] += waterline[WL_X, i] * fy - side * waterline[WL_B, i] * fx
