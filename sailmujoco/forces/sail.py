"""The sail: its normal and tangential coefficients and its force.

Saoud et al. (2015) §VII-A's C_N of the flat AR 5 sail, the tangential coefficient this
project models for it, the finite-wing C_N (``foils = "finite"``), and the sail force in the
frame of the flow handed in. The foil frame and the sign of alpha are those of
:mod:`sailmujoco.forces.foil_geometry`.
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.kernel import kernel
from .finite_wing import finite_sail_normal_coefficient
from .foil_geometry import foil_world_force, section_flow

# Saoud et al. (2015) §VII-A: C_N of the flat AR = 5 sail as a degree-5 polynomial of
# x = sin(alpha), odd-extended to x < 0.
SAOUD_CN_COEFFS = (7.15, -23.07, 39.45, -33.79, 11.52)  # p1..p5


@kernel
def saoud_normal_coefficient(x):
    """C_N(x), x = sin(alpha): Saoud (2015) §VII-A polynomial, odd in x (properties (2)).

    Parameters
    ----------
    x : float
        sin(alpha), alpha the sail's angle of attack (foil frame of :mod:`sailmujoco.forces.foil_geometry`).
    """
    ax = abs(x)
    p1, p2, p3, p4, p5 = 7.15, -23.07, 39.45, -33.79, 11.52
    value = ax * (p1 + ax * (p2 + ax * (p3 + ax * (p4 + ax * p5))))
    return value if x >= 0.0 else -value


@kernel
def sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction):
    """(C_N, C_T) of the flat AR 5 sail.

    C_N follows Saoud's polynomial. C_T (Saoud neglects it, Assumption 4) is modelled:
    a thin flat sail recovers a share ``suction_efficiency`` of the ideal leading-edge suction
    C_N tan(alpha) while the flow is attached, fading out past ``suction_stall`` as
    exp(-(sin(alpha)/sin(stall))^2), and both faces feel skin friction along the chord:

        C_T = e exp(-(sin a / sin a_s)^2) C_N sin(a) cos(a) - 2 C_f cos(a)

    (sin a cos a stands in for tan a so that C_T stays bounded at 90 deg). With e = 0.3,
    a_s = 15 deg, C_f = 0.005, |C_T| stays below 0.03 while C_N reaches 1.25, the "near zero"
    C_T of Saoud's Fig. 2b. It is even in alpha, as for any symmetric section. ``tangential``
    False sets C_T = 0 exactly, making the force exactly normal to the sail.

    Parameters
    ----------
    alpha : float
        Angle of attack, rad (foil frame of :mod:`sailmujoco.forces.foil_geometry`).
    tangential : bool
        Whether the sail has a tangential coefficient; False sets C_T = 0 exactly.
    suction_efficiency : float
        Share e of the ideal leading-edge suction C_N tan(alpha) recovered while attached, -.
    suction_stall : float
        Angle a_s past which the recovered suction fades, rad.
    friction : float
        Skin-friction coefficient C_f of each face, -.
    """
    s = math.sin(alpha)
    c_normal = saoud_normal_coefficient(s)
    if not tangential:
        return c_normal, 0.0
    return c_normal, tangential_coefficient(c_normal, s, math.cos(alpha), suction_efficiency,
                                            suction_stall, friction)


@kernel
def tangential_coefficient(c_normal, s, cs, suction_efficiency, suction_stall, friction):
    """C_T of the flat sail for its C_N at sin(alpha) = s, cos(alpha) = cs.

    The model of :func:`sail_coefficients`' docstring: recovered suction fading past the stall,
    and friction.

    Parameters
    ----------
    c_normal : float
        The sail's normal coefficient C_N at alpha, -.
    s, cs : float
        sin(alpha) and cos(alpha), alpha the angle of attack.
    suction_efficiency : float
        Share e of the ideal leading-edge suction recovered while attached, -.
    suction_stall : float
        Angle a_s past which the recovered suction fades, rad.
    friction : float
        Skin-friction coefficient C_f of each face, -.
    """
    fade = math.exp(-((s / math.sin(suction_stall)) ** 2))
    return suction_efficiency * fade * c_normal * s * cs - 2.0 * friction * cs


@kernel(inline=True)  # in the per-step physics kernel: inlined, it costs what the open block did
def flat_sail_force(flow, angle, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
                    chord, normal, out):
    """The flat sail's force at sail angle ``angle`` in ``flow`` (air velocity at the CE).

    The papers' sail (Saoud's C_N): the physics kernel, the Wille 4-DOF world and the roll
    controller's sail tables all call it; :func:`sail_force` with a finite-wing slope is the
    ``foils = "finite"`` form.

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        Air velocity relative to the sail at its centre of effort (where the air goes), m/s; the
        sail's chord and normal lie in the xy plane of its frame (the body frame in the kernels).
    angle : float
        Sail angle lambda, rad: 0 with the boom along -x (aft), positive with the boom to
        +y (port in the body frame).
    tangential : bool
        Whether the sail has a tangential coefficient; False sets C_T = 0 exactly.
    suction_efficiency : float
        Share e of the ideal leading-edge suction C_N tan(alpha) recovered while attached, -.
    suction_stall : float
        Angle a_s past which the recovered suction fades, rad.
    friction : float
        Skin-friction coefficient C_f of each face, -.
    rho_air : float
        Air density, kg/m^3.
    area : float
        Sail area A, m^2.
    chord, normal : numpy.ndarray, shape (3,)
        Work arrays: receive the chord axis (cos l, -sin l, 0) and normal axis (sin l, cos l, 0).
    out : numpy.ndarray, shape (3,)
        Receives the force F = q A (C_T c - C_N n), N, in the frame of ``flow``.

    Returns
    -------
    speed, alpha, c_n, c_t : float
        The in-plane air speed (m/s), the angle of attack (rad), C_N and C_T.
    """
    return sail_force(flow, angle, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
                      0.0, 0.0, chord, normal, out)


@kernel(inline=True)
def sail_force(flow, angle, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
               finite_slope, cd_max, chord, normal, out):
    """:func:`flat_sail_force` with Saoud's C_N or the finite wing's.

    C_N is Saoud's polynomial for ``finite_slope`` 0, and for ``finite_slope`` > 0 the finite
    wing's (:func:`finite_sail_coefficients`).

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        Air velocity relative to the sail at its centre of effort (where the air goes), m/s; the
        sail's chord and normal lie in the xy plane of its frame (the body frame in the kernels).
    angle : float
        Sail angle lambda, rad: 0 with the boom along -x (aft), positive with the boom to
        +y (port in the body frame).
    tangential : bool
        Whether the sail has a tangential coefficient; False sets C_T = 0 exactly.
    suction_efficiency : float
        Share e of the ideal leading-edge suction C_N tan(alpha) recovered while attached, -.
    suction_stall : float
        Angle a_s past which the recovered suction fades, rad.
    friction : float
        Skin-friction coefficient C_f of each face, -.
    rho_air : float
        Air density, kg/m^3.
    area : float
        Sail area A, m^2.
    finite_slope : float
        Lift slope of the finite sail at zero incidence, 1/rad (Helmbold); 0 for Saoud's C_N.
    cd_max : float
        The finite sail's C_D,max at 90 deg (Viterna & Corrigan), -; unused when ``finite_slope``
        is 0.
    chord, normal : numpy.ndarray, shape (3,)
        Work arrays: receive the chord axis (cos l, -sin l, 0) and normal axis (sin l, cos l, 0).
    out : numpy.ndarray, shape (3,)
        Receives the force F = q A (C_T c - C_N n), N, in the frame of ``flow``.

    Returns
    -------
    speed, alpha, c_n, c_t : float
        The in-plane air speed (m/s), the angle of attack (rad), C_N and C_T.
    """
    c, s = math.cos(angle), math.sin(angle)
    chord[0], chord[1], chord[2] = c, -s, 0.0
    normal[0], normal[1], normal[2] = s, c, 0.0
    _, _, speed, alpha = section_flow(flow, chord, normal)
    if finite_slope > 0.0:
        c_n, c_t = finite_sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction,
                                            finite_slope, cd_max)
    else:
        c_n, c_t = sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction)
    q_area = 0.5 * rho_air * speed * speed * area
    foil_world_force(q_area * c_t, -q_area * c_n, chord, normal, out)
    return speed, alpha, c_n, c_t


@kernel
def sail_forces(flow, sail_angles, tangential, suction_efficiency, suction_stall, friction, rho_air, area,
                out):
    """:func:`flat_sail_force` for each angle of ``sail_angles`` into ``out``.

    One compiled loop, for the roll controller's sail tables (some 300 000 angles).

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        Air velocity relative to the sail (where the air goes), m/s, in the sail's frame.
    sail_angles : numpy.ndarray, shape (n,)
        Sail angles, rad (as ``angle`` of :func:`flat_sail_force`).
    tangential : bool
        Whether the sail has a tangential coefficient; False sets C_T = 0 exactly.
    suction_efficiency : float
        Share e of the ideal leading-edge suction C_N tan(alpha) recovered while attached, -.
    suction_stall : float
        Angle a_s past which the recovered suction fades, rad.
    friction : float
        Skin-friction coefficient C_f of each face, -.
    rho_air : float
        Air density, kg/m^3.
    area : float
        Sail area, m^2.
    out : numpy.ndarray, shape (n, 3)
        Receives the force at each angle, N, in the frame of ``flow``.
    """
    chord, normal, force = np.zeros(3), np.zeros(3), np.zeros(3)
    for i in range(sail_angles.shape[0]):
        flat_sail_force(flow, sail_angles[i], tangential, suction_efficiency, suction_stall, friction,
                        rho_air, area, chord, normal, force)
        for k in range(3):
            out[i, k] = force[k]


@kernel
def finite_sail_coefficients(alpha, tangential, suction_efficiency, suction_stall, friction, slope, cd_max):
    """(C_N, C_T) of the flat finite sail.

    :func:`~sailmujoco.forces.finite_wing.finite_sail_normal_coefficient` with the sail's stall
    at ``suction_stall`` (the angle where its leading-edge suction collapses), and
    :func:`sail_coefficients`' tangential model on that C_N (suction share, fade, friction).

    Parameters
    ----------
    alpha : float
        Angle of attack, rad (foil frame of :mod:`sailmujoco.forces.foil_geometry`).
    tangential : bool
        Whether the sail has a tangential coefficient; False sets C_T = 0 exactly.
    suction_efficiency : float
        Share e of the ideal leading-edge suction C_N tan(alpha) recovered while attached, -.
    suction_stall : float
        Angle a_s past which the recovered suction fades, rad.
    friction : float
        Skin-friction coefficient C_f of each face, -.
    slope : float
        Lift slope of the finite sail at zero incidence, 1/rad (Helmbold).
    cd_max : float
        C_D,max at 90 deg (Viterna & Corrigan), -.
    """
    s = math.sin(alpha)
    c_normal = finite_sail_normal_coefficient(s, slope, suction_stall, cd_max)
    if not tangential:
        return c_normal, 0.0
    return c_normal, tangential_coefficient(c_normal, s, math.cos(alpha), suction_efficiency,
                                            suction_stall, friction)
