"""Froude-Krylov force: the undisturbed pressure of a linear wave field on the hull's columns.

The sea is a sum of deep-water components j (amplitude a_j, frequency omega_j, wavenumber
k_j = omega_j^2 / g, direction beta_j the component travels toward, from east
counter-clockwise, phase phi_j)::

    eta(x, y, t) = sum_j a_j cos(theta_j),
    theta_j      = k_j (x cos(beta_j) + y sin(beta_j)) - omega_j t + phi_j,
    p(x, y, z, t) = -rho g z + p_d,   p_d = rho g sum_j a_j exp(k_j z_s) cos(theta_j).

Linear theory gives p_d with exp(k_j z) (Newman, *Marine Hydrodynamics*, 1977, ch. 6;
Faltinsen, *Sea Loads on Ships and Offshore Structures*, 1990, ch. 2, Table 2.1, and ch. 3 for
the Froude-Kriloff force). Above the still level the exponential grows, so a crest would
over-press whatever lies in it. The pressure is therefore evaluated at the **vertically
stretched** height z_s = z - eta: the exponential's
argument is never positive in the water, and at the surface p = -rho g eta + rho g eta = 0
exactly, so cutting a column at the local surface leaves no pressure on the cut.
Wheeler (1970) stretching, z_s = (z - eta) / (1 + eta / d), is the other common choice; in
deep water (d -> infinity, this sea) it has no finite depth to stretch against, and vertical
stretching is its deep-water form with the same zero-pressure surface.

The force is the Froude-Krylov force: the pressure of the wave as if the hull were not there,
integrated over the wetted surface. By Gauss's theorem over the wet volume V of a column (the
cut at the surface carries p = 0)::

    F = -integral_S p n dS = -integral_V grad p dV
      = rho g V e_z - integral_V grad p_d dV,

the buoyancy of the water displaced up to the local surface plus the dynamic part. The
gradient of p_d is linearised (the a^2 term from differentiating the stretched argument is
left out)::

    -grad p_d = rho g sum_j a_j k_j exp(k_j z_s) (cos(beta_j) sin(theta_j),
                                                  sin(beta_j) sin(theta_j), -cos(theta_j)).

For an upright column from z_b to the surface this is F_z = A p(z_b), the pressure on its
bottom face, and the horizontal force A rho g sum_j a_j k_j (cos beta_j, sin beta_j)
sin(theta_j) (1 - exp(k_j (z_b - eta))) / k_j: a long wave tilts the buoyancy with the wave
slope, which is what rolls a boat on a beam sea.

Approximations, stated once: each column is cut where its axis meets the local surface eta_i,
taken at the world horizontal position of the column's point on the body plane z = 0 (the
phases theta_j are taken there too, constant along the column); along the axis the height,
hence the exponential, varies exactly with the column's tilt, as
:func:`sailmujoco.forces.hydrostatics.geometric_buoyancy` cuts each column along its axis. With
every amplitude zero the wrench is bit for bit that of ``geometric_buoyancy``.

Left out: diffraction (the hull's disturbance of the wave; at long waves its leading part is
the added mass times the water's acceleration, not included here), radiation (the waves the
moving hull makes), waves short against the hull (lambda ~ L or shorter), where diffraction is
as large as the Froude-Krylov force, green water on deck beyond the deck's own pressure, and
columns far from vertical at large heel (their horizontal offset along the axis against the
wave phase).
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.kernel import kernel
from .hydrostatics import buoyancy_wrench


@kernel(inline=True)
def wet_interval(h, r22, z_bottom, z_top, eta):
    """(lo, hi): the column's wet part in body z, cut where its axis meets the height ``eta``.

    The axis' world height at body z is h + r22 z, as in
    :func:`sailmujoco.forces.hydrostatics.submerged_volume` (there with eta = 0).

    Parameters
    ----------
    h : float
        World height of the column's body-z origin, m.
    r22 : float
        R[2, 2], the column axis' vertical component.
    z_bottom, z_top : float
        The column's ends in body z, m.
    eta : float
        The surface's height where the column is cut, m.
    """
    if abs(r22) < 1e-12:
        return (z_bottom, z_top) if h < eta else (0.0, 0.0)
    zw = (eta - h) / r22
    if r22 > 0.0:
        return z_bottom, min(z_top, zw)
    return max(z_bottom, zw), z_top


@kernel(inline=True)
def _column_weight(k, zs_lo, zs_hi, lo, hi):
    """(I, zeta): I = integral of exp(k z_s) along the wet axis, d(body z) (m), and the body z
    of its centroid, where the force density exp(k z_s) of one component acts.

    Measured from the end nearer the surface over the world height span d = abs(zs_hi - zs_lo)
    with q = k d: I = l exp(k z_s,top) (1 - exp(-q)) / q and the centroid lies the fraction
    1/q - 1/(exp(q) - 1) of the length l from that end (series below q = 1e-4).
    """
    if zs_hi >= zs_lo:
        z_near, zeta_near, zeta_far, d = zs_hi, hi, lo, zs_hi - zs_lo
    else:
        z_near, zeta_near, zeta_far, d = zs_lo, lo, hi, zs_lo - zs_hi
    q = k * d
    if q < 1e-4:
        mean = 1.0 - q * (0.5 - q / 6.0)
        frac = 0.5 - q / 12.0
    else:
        mean = -math.expm1(-q) / q
        frac = 1.0 / q - 1.0 / math.expm1(q)
    return (hi - lo) * math.exp(k * z_near) * mean, zeta_near + (zeta_far - zeta_near) * frac


@kernel(inline=True)
def _add_column_dynamic(dyn, rot, x, y, lo, hi, h_stretched, rga, amplitude, wavenumber,
                        cos_beta, sin_beta, cth, sth):
    """Add -integral grad p_d dV over one column's wet part (body z from ``lo`` to ``hi``) and
    its moment about CO to ``dyn`` (world force, world moment).

    ``h_stretched`` is the stretched height z_s of the column's body-z origin, h - eta_i;
    ``rga`` is rho g A; ``cos_beta``, ``sin_beta`` the components' directions; ``cth``, ``sth``
    cos and sin of their phases at the column.
    """
    r22 = rot[2, 2]
    zs_lo = h_stretched + r22 * lo
    zs_hi = h_stretched + r22 * hi
    fx = 0.0
    fy = 0.0
    fz = 0.0
    gx = 0.0  # sum_j zeta_j F_j: each component's force at its own centroid on the axis
    gy = 0.0
    gz = 0.0
    for j in range(amplitude.shape[0]):
        k = wavenumber[j]
        weight, zeta = _column_weight(k, zs_lo, zs_hi, lo, hi)
        f = rga * amplitude[j] * k * weight
        fxj = f * cos_beta[j] * sth[j]
        fyj = f * sin_beta[j] * sth[j]
        fzj = -f * cth[j]
        fx += fxj
        fy += fyj
        fz += fzj
        gx += zeta * fxj
        gy += zeta * fyj
        gz += zeta * fzj
    # lever: R (x, y, 0) to the axis point, R e_z along the axis (times G)
    rx = rot[0, 0] * x + rot[0, 1] * y
    ry = rot[1, 0] * x + rot[1, 1] * y
    rz = rot[2, 0] * x + rot[2, 1] * y
    ax, ay, az = rot[0, 2], rot[1, 2], rot[2, 2]
    dyn[0] += fx
    dyn[1] += fy
    dyn[2] += fz
    dyn[3] += ry * fz - rz * fy + ay * gz - az * gy
    dyn[4] += rz * fx - rx * fz + az * gx - ax * gz
    dyn[5] += rx * fy - ry * fx + ax * gy - ay * gx


@kernel(inline=True)
def _components(pos, omega, wavenumber, direction_to, phase, time):
    """Per component, once per call: rows cos(beta_j), sin(beta_j), k_j cos(beta_j),
    k_j sin(beta_j) and theta_j at CO's horizontal position."""
    comp = np.empty((5, wavenumber.shape[0]))
    for j in range(wavenumber.shape[0]):
        comp[0, j] = math.cos(direction_to[j])
        comp[1, j] = math.sin(direction_to[j])
        comp[2, j] = wavenumber[j] * comp[0, j]
        comp[3, j] = wavenumber[j] * comp[1, j]
        comp[4, j] = comp[2, j] * pos[0] + comp[3, j] * pos[1] - omega[j] * time + phase[j]
    return comp


@kernel(inline=True)
def _column_phases(comp, amplitude, dx, dy, cth, sth):
    """Fill ``cth``, ``sth`` with cos and sin of theta_j at the horizontal offset (dx, dy) from
    CO (world, m); return the surface elevation eta there, m."""
    eta = 0.0
    for j in range(amplitude.shape[0]):
        theta = comp[4, j] + comp[2, j] * dx + comp[3, j] * dy
        cth[j] = math.cos(theta)
        sth[j] = math.sin(theta)
        eta += amplitude[j] * cth[j]
    return eta


@kernel
def froude_krylov(pos, rot, columns, amplitude, omega, wavenumber, direction_to, phase, time,
                  rho, g, out):
    """Buoyancy plus Froude-Krylov wave force (body frame, about CO) into ``out``.

    F = rho g V e_z - sum_i integral_{V_i} grad p_d dV with each column i wet up to the local
    surface eta_i (module docstring: equations, stretching, approximations, sources). The
    moment of the buoyancy is rho g (Q x e_z,b) as in
    :func:`sailmujoco.forces.hydrostatics.geometric_buoyancy`; each component's dynamic force on
    a column acts on its axis at the centroid of exp(k z_s).

    Parameters
    ----------
    pos : numpy.ndarray, shape (3,)
        World position of CO (ENU, z up, still water plane z = 0), m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    columns : numpy.ndarray, shape (5, n)
        The hull's vertical columns in body coordinates, rows (x, y, area, z_bottom, z_top) in m
        and m^2 (:func:`sailmujoco.boat.hull.column_quadrature`).
    amplitude, omega, wavenumber, direction_to, phase : numpy.ndarray, shape (m,)
        The components: amplitudes a_j (m), angular frequencies omega_j (rad/s), wavenumbers
        k_j (rad/m; deep water omega_j^2 / g), the world angle each travels toward, from east
        counter-clockwise (rad), and phases phi_j (rad).
    time : float
        Simulation time t, s.
    rho : float
        Water density, kg/m^3.
    g : float
        Gravitational acceleration, m/s^2.
    out : numpy.ndarray, shape (6,)
        Receives the wrench, N and N m.

    Returns
    -------
    float
        The wet volume V (cut at the local surface), m^3.
    """
    m = amplitude.shape[0]
    comp = _components(pos, omega, wavenumber, direction_to, phase, time)
    cth = np.empty(m)  # cos(theta_j) at the column
    sth = np.empty(m)  # sin(theta_j) at the column
    r20, r21, r22 = rot[2, 0], rot[2, 1], rot[2, 2]
    vol = 0.0
    qx = 0.0
    qy = 0.0
    qz = 0.0
    dyn = np.zeros(6)  # dynamic force and moment about CO, world axes
    for i in range(columns.shape[1]):
        x = columns[0, i]
        y = columns[1, i]
        area = columns[2, i]
        dx = rot[0, 0] * x + rot[0, 1] * y  # column axis point (body z = 0) from CO, world
        dy = rot[1, 0] * x + rot[1, 1] * y
        eta = _column_phases(comp, amplitude, dx, dy, cth, sth)
        h = pos[2] + r20 * x + r21 * y  # world height of the column's body-z origin
        lo, hi = wet_interval(h, r22, columns[3, i], columns[4, i], eta)
        if hi <= lo:
            continue
        dv = area * (hi - lo)
        vol += dv
        qx += dv * x
        qy += dv * y
        qz += dv * 0.5 * (lo + hi)
        _add_column_dynamic(dyn, rot, x, y, lo, hi, h - eta, area * rho * g, amplitude,
                            wavenumber, comp[0], comp[1], cth, sth)
    buoyancy_wrench(vol, qx, qy, qz, rot, rho, g, out)
    for row in range(3):  # world -> body: R^T
        out[row] += rot[0, row] * dyn[0] + rot[1, row] * dyn[1] + rot[2, row] * dyn[2]
        out[3 + row] += rot[0, row] * dyn[3] + rot[1, row] * dyn[4] + rot[2, row] * dyn[5]
    return vol
