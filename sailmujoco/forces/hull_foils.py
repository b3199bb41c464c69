"""The keel's and rudder's force: the flow at the foil's centre of pressure, lift and drag.

:func:`hull_foil_force` is called by the force kernel (:func:`sailmujoco.forces.boat.boat_forces`)
for the keel and for the rudder; :func:`point_flow` gives the flow relative to a point of the hull
(the foils', the sail's and the windage's).
"""

from __future__ import annotations

import math

from ..jit.kernel import kernel
from .finite_wing import finite_hydrofoil_coefficients
from .foil_geometry import foil_world_force, lift_drag_components, section_flow
from .foil_sections import hydrofoil_coefficients


@kernel
def point_flow(fluid_body, v, w, point, extra, out):
    """Fluid velocity relative to a point: fluid - (v + w x point + extra) (body frame).

    Parameters
    ----------
    fluid_body : numpy.ndarray, shape (3,)
        The fluid's velocity at the point, m/s, body frame.
    v, w : numpy.ndarray, shape (3,)
        The velocity of CO (m/s) and the angular velocity (rad/s), body frame.
    point : numpy.ndarray, shape (3,)
        The point, m, body frame about CO.
    extra : numpy.ndarray, shape (3,)
        A velocity of the point beyond the hull's (a hinge's turn), m/s.
    out : numpy.ndarray, shape (3,)
        Receives the relative flow, m/s.
    """
    out[0] = fluid_body[0] - (v[0] + w[1] * point[2] - w[2] * point[1] + extra[0])
    out[1] = fluid_body[1] - (v[1] + w[2] * point[0] - w[0] * point[2] + extra[1])
    out[2] = fluid_body[2] - (v[2] + w[0] * point[1] - w[1] * point[0] + extra[2])


@kernel(inline=True)  # called twice per step: inlined, it costs what the two blocks did
def hull_foil_force(angle, x, z, chord_length, aspect_ratio, thickness, area, rho, nu, water_b, v, w,
                    alpha_grid, log_re_grid, cl_table, cd_table, zero3, point, flow, chord, normal, force,
                    finite, lift_ratio, aspect_ratio_e, cd_max, match_angle, downwash):
    """Lift and drag of a keel or rudder, Wille (2016a) eqs. 30-36; the force into ``force``.

    The foil stands at (x, 0, z) in the body frame, turned by ``angle`` about -z: chord
    (cos, -sin, 0), normal (sin, cos, 0). The flow is the water's velocity relative to that
    point (``water_b`` less the hull's motion, the foil's own turn rate neglected); C_L, C_D from
    the section table at the chord Reynolds number, corrected for the aspect ratio
    (:func:`sailmujoco.forces.foil_sections.hydrofoil_coefficients`), or with ``finite`` the finite
    wing's (:func:`sailmujoco.forces.finite_wing.finite_hydrofoil_coefficients`). ``downwash``, when
    not 0, turns the inflow about the span by that angle against the angle of attack (the
    keel's downwash at the rudder): alpha -> alpha - downwash, same speed; lift and drag follow
    the turned flow.

    Parameters
    ----------
    angle : float
        The foil's turn about -z, rad (the rudder's sigma; 0 for the keel).
    x, z, chord_length : float
        The foil's centre of pressure in the body frame and its chord, m.
    aspect_ratio, thickness, area : float
        Geometric aspect ratio (-), thickness over chord (-) and planform area (m^2).
    rho, nu : float
        Water density (kg/m^3) and kinematic viscosity (m^2/s).
    water_b, v, w : numpy.ndarray, shape (3,)
        The water's velocity at the foil (the current, plus the waves' orbital velocity in a
        sea; m/s), the velocity of CO (m/s) and the angular velocity (rad/s), body frame.
    alpha_grid, log_re_grid, cl_table, cd_table : numpy.ndarray
        The section table (:func:`sailmujoco.forces.foil_sections.section_coefficients`).
    zero3, point, flow, chord, normal : numpy.ndarray, shape (3,)
        A zero vector (no point velocity beyond the hull's); work arrays, left holding this
        foil's point (m), flow (m/s), chord and normal axes (body frame).
    force : numpy.ndarray, shape (3,)
        Receives the force, N, body frame.
    finite : bool
        The finite-wing coefficients instead of Wille's eqs. 23-24.
    lift_ratio, aspect_ratio_e, cd_max, match_angle : float
        The finite wing's a/a0 (-), effective aspect ratio (-), C_D,max (-) and matching angle
        (rad), from the boat's ``FB_*`` block (:func:`~sailmujoco.forces.finite_wing.pack_foil_block`).
    downwash : float
        Inflow turn epsilon, rad (0: none).

    Returns
    -------
    alpha, speed, c_l : float
        The (turned) angle of attack (rad), the in-plane flow speed (m/s) and C_L.
    """
    point[0], point[1], point[2] = x, 0.0, z
    point_flow(water_b, v, w, point, zero3, flow)
    c, s = math.cos(angle), math.sin(angle)
    chord[0], chord[1], chord[2] = c, -s, 0.0
    normal[0], normal[1], normal[2] = s, c, 0.0
    wc, wn, speed, alpha = section_flow(flow, chord, normal)
    if downwash != 0.0:
        alpha = alpha - downwash
        wc, wn = -speed * math.cos(alpha), -speed * math.sin(alpha)  # alpha = atan2(-wn, -wc)
    if finite:
        c_l, c_d = finite_hydrofoil_coefficients(alpha, speed * chord_length / nu, lift_ratio, aspect_ratio_e,
                                                 cd_max, match_angle, thickness, alpha_grid, log_re_grid,
                                                 cl_table, cd_table)
    else:
        c_l, c_d = hydrofoil_coefficients(alpha, speed * chord_length / nu, aspect_ratio, thickness,
                                          alpha_grid, log_re_grid, cl_table, cd_table)
    fc, fn = lift_drag_components(wc, wn, speed, 0.5 * rho * speed * speed * area, c_l, c_d)
    foil_world_force(fc, fn, chord, normal, force)
    return alpha, speed, c_l
