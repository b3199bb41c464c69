"""Hydrostatic restoring in two switchable modes. Gravity itself is MuJoCo's.

``paper``
    Wille (2016a) eq. 20: roll moment -rho g V GM_t sin(phi) cos(phi) (or Saoud eq. 4,
    -m g l_phi sin(phi), for the Saoud robot), plus the linear heave and pitch springs of the
    upright waterplane (k_z = rho g A_wp, k_theta = rho g V GM_L) that hold heave and pitch
    near their design values. The vertical force, weight - k_z (z_G - z_G0), acts through the
    CG; the roll and pitch moments act about level axes (a couple of vertical forces).
``geometric``
    Buoyancy integrated over the hull's columns against the flat water plane z = 0
    (:func:`sailmujoco.boat.hull.column_quadrature`). Each column is cut exactly along its axis;
    heave, pitch and roll restoring and the large-heel righting curve (deck-edge immersion,
    bilge emergence) follow from the geometry. At small heel it reproduces GM_t.
"""

from __future__ import annotations

import math

from ..jit.kernel import kernel


@kernel
def submerged_volume(pos_z, rot, columns):
    """(V, Qx, Qy, Qz): submerged volume and its first moment in body coordinates.

    Along a column at body (x, y) the world height is pos_z + R20 x + R21 y + R22 z, so it is
    wet below body z_w = -(pos_z + R20 x + R21 y) / R22 (above it when R22 < 0, upside down).

    Parameters
    ----------
    pos_z : float
        World height of CO (z up, water plane z = 0), m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    columns : numpy.ndarray, shape (5, n)
        The hull's vertical columns in body coordinates, rows (x, y, area, z_bottom, z_top) in m
        and m^2 (:func:`sailmujoco.boat.hull.column_quadrature`).

    Returns
    -------
    vol, qx, qy, qz : float
        V (m^3) and its first moment about CO along body x, y, z (m^4).
    """
    r20, r21, r22 = rot[2, 0], rot[2, 1], rot[2, 2]
    vol = 0.0
    qx = 0.0
    qy = 0.0
    qz = 0.0
    n = columns.shape[1]
    for k in range(n):
        x = columns[0, k]
        y = columns[1, k]
        area = columns[2, k]
        zb = columns[3, k]
        zt = columns[4, k]
        h = pos_z + r20 * x + r21 * y  # world height of the column's body-z origin
        if abs(r22) < 1e-12:
            lo, hi = (zb, zt) if h < 0.0 else (0.0, 0.0)
        elif r22 > 0.0:
            zw = -h / r22
            lo, hi = zb, min(zt, zw)
        else:
            zw = -h / r22
            lo, hi = max(zb, zw), zt
        if hi <= lo:
            continue
        dv = area * (hi - lo)
        vol += dv
        qx += dv * x
        qy += dv * y
        qz += dv * 0.5 * (lo + hi)
    return vol, qx, qy, qz


@kernel
def upright_submerged_volume(pos_z, rot, columns):
    """:func:`submerged_volume` of a hull not upside down (R22 >= 1e-12), the force kernel's.

    The same cut of each column, written without branches (a dry column adds zeros) and with
    the waterline's height taken by one multiplication by -1/R22 rather than a division per
    column (the division cost half the loop): within a few units in the last place of
    :func:`submerged_volume` (at most about 1e-14 of the volume). The four sums run in the
    columns' order, as every sum in the kernels does. Other attitudes go to
    :func:`submerged_volume`.

    Parameters
    ----------
    pos_z : float
        World height of CO (z up, water plane z = 0), m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    columns : numpy.ndarray, shape (5, n)
        The hull's vertical columns in body coordinates, rows (x, y, area, z_bottom, z_top).

    Returns
    -------
    vol, qx, qy, qz : float
        V (m^3) and its first moment about CO along body x, y, z (m^4).
    """
    r22 = rot[2, 2]
    if not r22 >= 1e-12:
        return submerged_volume(pos_z, rot, columns)
    r20, r21 = rot[2, 0], rot[2, 1]
    down = -1.0 / r22
    vol = 0.0
    qx = 0.0
    qy = 0.0
    qz = 0.0
    for k in range(columns.shape[1]):
        x = columns[0, k]
        y = columns[1, k]
        zb = columns[3, k]
        hi = min(columns[4, k], (pos_z + r20 * x + r21 * y) * down)  # wet below body z_w
        dv = columns[2, k] * max(hi - zb, 0.0)
        vol += dv
        qx += dv * x
        qy += dv * y
        qz += dv * (zb + hi)
    return vol, qx, qy, 0.5 * qz


@kernel
def hull_buoyancy(pos_z, rot, columns, rho, g, out):
    """:func:`geometric_buoyancy` with the column sums of :func:`upright_submerged_volume`
    (the force kernel's calm-water hydrostatics); returns the submerged volume.

    Parameters
    ----------
    pos_z, rot, columns, rho, g, out
        As :func:`geometric_buoyancy`.
    """
    vol, qx, qy, qz = upright_submerged_volume(pos_z, rot, columns)
    buoyancy_wrench(vol, qx, qy, qz, rot, rho, g, out)
    return vol


@kernel
def geometric_buoyancy(pos_z, rot, columns, rho, g, out):
    """Buoyancy wrench (body frame, about CO) into ``out``; returns the submerged volume.

    F_b = rho g V e_z,b and M_b = Q x F_b / V = rho g (Q x e_z,b), where e_z,b = R^T e_z is the
    world vertical in body axes and Q the first moment of the submerged volume.

    Parameters
    ----------
    pos_z : float
        World height of CO (z up, water plane z = 0), m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    columns : numpy.ndarray, shape (5, n)
        The hull's vertical columns in body coordinates, rows (x, y, area, z_bottom, z_top) in m
        and m^2 (:func:`sailmujoco.boat.hull.column_quadrature`).
    rho : float
        Water density, kg/m^3.
    g : float
        Gravitational acceleration, m/s^2.
    out : numpy.ndarray, shape (6,)
        Receives the wrench, N and N m.
    """
    vol, qx, qy, qz = submerged_volume(pos_z, rot, columns)
    buoyancy_wrench(vol, qx, qy, qz, rot, rho, g, out)
    return vol


@kernel(inline=True)
def buoyancy_wrench(vol, qx, qy, qz, rot, rho, g, out):
    """The wrench of buoyancy on a submerged volume into ``out`` (body frame, about CO).

    F_b = rho g V e_z,b and M_b = rho g (Q x e_z,b), with e_z,b = R^T e_z the world vertical in
    body axes: what :func:`geometric_buoyancy` and the Froude-Krylov force
    (:func:`sailmujoco.forces.wave_pressure.froude_krylov`) share.

    Parameters
    ----------
    vol : float
        Submerged volume V, m^3.
    qx, qy, qz : float
        Its first moment about CO along body x, y, z, m^4.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    rho : float
        Water density, kg/m^3.
    g : float
        Gravitational acceleration, m/s^2.
    out : numpy.ndarray, shape (6,)
        Receives the wrench, N and N m.
    """
    ex, ey, ez = rot[2, 0], rot[2, 1], rot[2, 2]
    rg = rho * g
    out[0] = rg * vol * ex
    out[1] = rg * vol * ey
    out[2] = rg * vol * ez
    out[3] = rg * (qy * ez - qz * ey)
    out[4] = rg * (qz * ex - qx * ez)
    out[5] = rg * (qx * ey - qy * ex)


@kernel
def paper_righting_moment(heel, righting_stiffness, righting_sin_only):
    """Roll restoring moment about body x (N m): Wille (2016a) eq. 20 or Saoud (2015) eq. 4.

    -K sin(phi) cos(phi) (Wille), or -K sin(phi) (Saoud, ``righting_sin_only``), with
    K = rho g V GM_t = m g l_phi.

    Parameters
    ----------
    heel : float
        Heel angle phi, rad (positive starboard down).
    righting_stiffness : float
        K = rho g V GM_t, N m/rad.
    righting_sin_only : bool
        Saoud's -K sin(phi) instead of Wille's -K sin(phi) cos(phi).
    """
    if righting_sin_only:
        return -righting_stiffness * math.sin(heel)
    return -righting_stiffness * math.sin(heel) * math.cos(heel)


@kernel
def paper_restoring(pos_z, rot, weight, righting_stiffness, righting_sin_only, k_heave,
                    k_pitch, cg_x, cg_z, body_axes, out):
    """Paper-mode restoring wrench (body frame, about CO) into ``out``.

    Roll moment -K sin(phi) cos(phi), Wille (2016a) eq. 20, or -K sin(phi), Saoud (2015) eq. 4
    (``righting_sin_only``). Pitch: k_pitch sin(theta)
    (theta > 0 bow up; the moment pushes the bow down). Heave: world-vertical force
    weight - k_heave (z_G - z_G0) through the CG, where z_G is the CG's world height: the reduced
    models hold the CG's height (Saoud writes his equations at G), so a spring on CO's height
    would couple roll into heave when the CG lies below CO.

    Restoring is a couple of vertical forces (buoyancy and weight), so its moment is horizontal
    at any attitude: the roll moment acts about x1, the horizontal heading direction, and the
    pitch moment about y1 = e_z x x1. The roll moment about x1 is eq. 20 / cos(theta): body x
    makes the angle theta with x1, so the generalised force on the heel angle is eq. 20 exactly,
    and the restoring is the gradient of the potential 1/2 K sin^2(phi) (or K (1 - cos(phi)))
    + k_theta (1 - cos(theta)) + 1/2 k_z (z_G - z_G0)^2 - W z_G: an undamped boat keeps its
    energy (tests/test_energy.py). In the papers' 4-DOF models the body x axis *is* horizontal
    (theta = 0), so this is their eq. 20 / eq. 4. ``body_axes`` puts them about body x and y
    instead: heeled and trimmed, that form has a world-vertical (yaw) part,
    +725 N m on the yacht at heel -5 deg, pitch -1 deg, 44 % of the rudder's yaw moment under
    sail; it is kept only to measure that difference.

    Parameters
    ----------
    pos_z : float
        World height of CO (z up, water plane z = 0), m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world (body FLU, world ENU).
    weight : float
        The boat's weight m g, N (the buoyancy at the design waterline).
    righting_stiffness : float
        K = rho g V GM_t (= m g l_phi), N m/rad.
    righting_sin_only : bool
        Saoud's -K sin(phi) instead of Wille's -K sin(phi) cos(phi).
    k_heave : float
        Heave spring k_z = rho g A_wp, N/m.
    k_pitch : float
        Pitch spring k_theta = rho g V GM_L, N m/rad.
    cg_x, cg_z : float
        The CG in the body frame, m; the CG's design world height is ``cg_z`` (CO on the
        waterline).
    body_axes : bool
        Roll and pitch moments about body x and y instead of the level axes x1, y1.
    out : numpy.ndarray, shape (6,)
        Receives the wrench, N and N m.
    """
    heel = math.atan2(rot[2, 1], rot[2, 2])
    pitch = math.asin(max(-1.0, min(1.0, rot[2, 0])))
    z_cg = pos_z + rot[2, 0] * cg_x + rot[2, 2] * cg_z
    fz = weight - k_heave * (z_cg - cg_z)
    ex, ey, ez = rot[2, 0], rot[2, 1], rot[2, 2]
    fx, fy, fz_b = fz * ex, fz * ey, fz * ez
    # r_G x F with r_G = (cg_x, 0, cg_z)
    mx = -cg_z * fy
    my = cg_z * fx - cg_x * fz_b
    mz = cg_x * fy
    roll = paper_righting_moment(heel, righting_stiffness, righting_sin_only)
    pitch_moment = k_pitch * math.sin(pitch)
    out[0] = fx
    out[1] = fy
    out[2] = fz_b
    if body_axes:
        out[3] = mx + roll
        out[4] = my + pitch_moment
        out[5] = mz
        return
    # x1 = (R00, R10, 0) / |.|, y1 = (-R10, R00, 0) / |.| in the world; body = R^T (world)
    hx, hy = rot[0, 0], rot[1, 0]
    hn = math.sqrt(hx * hx + hy * hy)
    if hn < 1e-12:  # bow straight up or down: no heading; any horizontal axis will do
        hx, hy, hn = 1.0, 0.0, 1.0
    x1x, x1y = hx / hn, hy / hn
    roll /= hn  # hn = cos(theta): the generalised force on the heel is eq. 20 (docstring)
    mwx = roll * x1x - pitch_moment * x1y
    mwy = roll * x1y + pitch_moment * x1x
    out[3] = mx + rot[0, 0] * mwx + rot[1, 0] * mwy
    out[4] = my + rot[0, 1] * mwx + rot[1, 1] * mwy
    out[5] = mz + rot[0, 2] * mwx + rot[1, 2] * mwy
