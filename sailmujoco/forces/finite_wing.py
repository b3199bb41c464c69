"""Finite-wing forms of the foils (``ForceSwitches.foils = "finite"``).

Helmbold's lift slope for the sail, keel and rudder, Viterna & Corrigan's post-stall, the hull
as an end plate on the keel, the keel's downwash at the rudder, and the block of these
constants packed into the boat's parameter array (the ``FB_*`` offsets).
"""

from __future__ import annotations

import math

import numpy as np

from ..frames import wrap_angle
from ..jit.kernel import kernel
from .damping import ittc_friction_coefficient
from .foil_sections import section_coefficients

# ---- finite-wing forms (ForceSwitches.foils = "finite") -------------------------------------
#
# Lift slope of a finite wing: Helmbold (1942), "Der unverwundene Ellipsenflügel als tragende
# Fläche", Jahrbuch der deutschen Luftfahrtforschung, I 111-113:
#     a = a0 / (sqrt(1 + (a0 / (pi A))^2) + a0 / (pi A)).
# It tends to Prandtl's lifting line a0 / (1 + a0/(pi A)) for large A and to Jones' slender-wing
# slope pi A / 2 for small A, so one formula serves the AR 5 sail and the keel of AR 1.75 (3.5
# with its image in the hull), where lifting line overstates the slope (by 12 % at A = 3.5).
# At A = 5 it gives 4.25 /rad against lifting line's 4.49 /rad; measured rectangular wings of
# A = 5 lie between (lifting line assumes elliptic loading).
#
# Post-stall: Viterna & Corrigan (1982), "Fixed pitch rotor performance of large horizontal axis
# wind turbines", NASA CP-2230, pp. 69-85: from a matching angle alpha_s to 90 deg
#     C_D = B1 sin^2 a + B2 cos a,     C_L = A1 sin 2a + A2 cos^2 a / sin a,
#     B1 = C_D,max = 1.11 + 0.018 A (A <= 50), A1 = B1 / 2,
#     B2 = (C_D,s - C_D,max sin^2 a_s) / cos a_s, A2 = (C_L,s - C_D,max sin a_s cos a_s) sin a_s / cos^2 a_s,
# so that C_L, C_D equal (C_L,s, C_D,s) at a_s and C_N(90 deg) = C_D(90 deg) = C_D,max. For A = 5
# that is 1.20, Hoerner's flat plate of the same aspect ratio (Fluid-Dynamic Drag, 1965, ch. 3).
# Beyond 90 deg the curves are mirrored as for a flat plate: C_N(pi - a) = C_N(a),
# C_L(pi - a) = -C_L(a), C_D(pi - a) = C_D(a).
THIN_AIRFOIL_SLOPE = 2.0 * math.pi  # 1/rad, a0 of a thin section (thin-airfoil theory)
# The hull as an end plate on the keel: a foil whose root meets a wall (here the canoe body) acts
# as the foil plus its mirror image, effective span twice the geometric one, so A_e = 2 A
# (Hoerner & Borst, Fluid-Dynamic Lift, 1985, ch. 3, "wall effect"; Larsson & Eliasson,
# Principles of Yacht Design, keel chapter, who note heel and a root gap reduce it). The keel
# is fixed to the hull with no gap: factor 2. The rudder turns on its stock below the counter,
# with a gap at its root and the hull rising to the transom above it: no end plate (factor 1).
KEEL_END_PLATE = 2.0  # -, A_e / A of the keel
RUDDER_END_PLATE = 1.0  # -, A_e / A of the rudder
# Section angle past which the table's 2-D post-stall is replaced by Viterna & Corrigan: beyond
# the table's own stall at every Reynolds number it holds (12-16 deg for Re >= 7e5, ~10 deg
# below), before its 2-D flat-plate branch (c_d 1.8 at 90 deg) takes over.
HYDROFOIL_MATCH_ANGLE = math.radians(20.0)  # rad, section (effective) angle

# offsets inside P[P_FOIL_BLOCK : P_FOIL_BLOCK + FOIL_BLOCK_SIZE] (forces/boat.py)
(FB_SAIL_SLOPE, FB_SAIL_CD_MAX, FB_KEEL_RATIO, FB_KEEL_AR, FB_KEEL_CD_MAX, FB_RUDDER_RATIO,
 FB_RUDDER_AR, FB_RUDDER_CD_MAX, FB_MATCH_ANGLE, FB_DOWNWASH_GAIN, FB_DOWNWASH_K) = range(11)


@kernel
def helmbold_lift_slope(section_slope, aspect_ratio):
    """Helmbold (1942) lift slope of a wing of aspect ratio A with section slope a0, 1/rad.

    a = a0 / (sqrt(1 + (a0 / (pi A))^2) + a0 / (pi A)).

    Parameters
    ----------
    section_slope : float
        Section (2-D) lift slope a0, 1/rad (2 pi for a thin section).
    aspect_ratio : float
        (Effective) aspect ratio A of the wing, -.
    """
    k = section_slope / (math.pi * aspect_ratio)
    return section_slope / (math.sqrt(1.0 + k * k) + k)


@kernel
def viterna_corrigan_cd_max(aspect_ratio):
    """Viterna & Corrigan (1982): C_D,max = 1.11 + 0.018 A, A capped at 50.

    Parameters
    ----------
    aspect_ratio : float
        (Effective) aspect ratio A of the wing, -.
    """
    return 1.11 + 0.018 * min(aspect_ratio, 50.0)


@kernel
def viterna_corrigan(alpha, alpha_s, c_lift_s, c_drag_s, cd_max):
    """Viterna & Corrigan (1982) post-stall (C_L, C_D) at alpha in [alpha_s, pi/2].

    Matched to (C_L,s, C_D,s) at alpha_s (formulas in the block comment above).

    Parameters
    ----------
    alpha : float
        Angle of attack, rad, in [alpha_s, pi/2].
    alpha_s : float
        Matching angle, rad, in (0, pi/2).
    c_lift_s, c_drag_s : float
        C_L and C_D at the matching angle, -.
    cd_max : float
        C_D,max, the drag at 90 deg (:func:`viterna_corrigan_cd_max`), -.
    """
    ss, cs = math.sin(alpha_s), math.cos(alpha_s)
    b2 = (c_drag_s - cd_max * ss * ss) / cs
    a2 = (c_lift_s - cd_max * ss * cs) * ss / (cs * cs)
    s, c = math.sin(alpha), math.cos(alpha)
    return 0.5 * cd_max * math.sin(2.0 * alpha) + a2 * c * c / s, cd_max * s * s + b2 * c


@kernel
def finite_sail_normal_coefficient(x, slope, stall, cd_max):
    """C_N(x), x = sin(alpha), of a flat finite wing; odd in x like Saoud's (properties (2)).

    Attached (|alpha| <= stall, alpha folded to [0, 90 deg] as theta = asin|x|): C_N = a x, the
    finite-wing slope ``slope`` at zero incidence (Helmbold). The flow on a flat plate without
    leading-edge suction leaves the force normal to it, so at the stall C_L,s = C_N,s cos(stall),
    C_D,s = C_N,s sin(stall); past it Viterna & Corrigan's C_L, C_D, resolved on the normal:
    C_N = C_L cos(theta) + C_D sin(theta), which reaches C_D,max at 90 deg.

    Parameters
    ----------
    x : float
        sin(alpha), alpha the angle of attack (foil frame of :mod:`sailmujoco.forces.foil_geometry`).
    slope : float
        Lift slope at zero incidence, 1/rad (:func:`helmbold_lift_slope`).
    stall : float
        Stall angle, rad, where Viterna & Corrigan take over.
    cd_max : float
        C_D,max at 90 deg (:func:`viterna_corrigan_cd_max`), -.
    """
    ax = min(abs(x), 1.0)
    if ax <= math.sin(stall):
        value = slope * ax
    else:
        theta = math.asin(ax)
        c_n_s = slope * math.sin(stall)
        c_l, c_d = viterna_corrigan(theta, stall, c_n_s * math.cos(stall), c_n_s * math.sin(stall), cd_max)
        value = c_l * math.cos(theta) + c_d * ax
    return value if x >= 0.0 else -value


@kernel
def _attached_hydrofoil(alpha, reynolds, lift_ratio, aspect_ratio, cd0, c_friction,
                        alpha_grid, log_re_grid, cl_table, cd_table):
    """Table lift at the effective angle alpha_e = alpha a/a0 and the eq. 24 drag reading with
    the finite wing's induced drag C_L^2 / (pi A_e)."""
    cl, cd = section_coefficients(alpha * lift_ratio, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    return cl, (cd - cd0) + cl * cl / (math.pi * aspect_ratio) + c_friction


@kernel
def finite_hydrofoil_coefficients(alpha, reynolds, lift_ratio, aspect_ratio, cd_max, match_angle,
                                  thickness_ratio, alpha_grid, log_re_grid, cl_table, cd_table):
    """Finite-wing C_L, C_D of the keel or rudder (``foils = "finite"``).

    * Attached: lifting line's reading of a 2-D section on a finite wing: the section works at
      the effective angle alpha_e = alpha - alpha_i; for the linear range alpha_e = alpha a/a0,
      a = Helmbold(a0 = 2 pi, A_e) (``lift_ratio`` = a/a0), so C_L(alpha) = c_l(alpha a/a0):
      slope a at zero incidence, the section's own c_l,max, reached at a larger angle (finite
      wings stall later). The table's 0-2 deg slope is 6.30 /rad at Re >= 8e4, 2 pi to 0.4 %.
      Drag as :func:`~sailmujoco.forces.foil_sections.hydrofoil_coefficients` reads Wille
      (2016a) eq. 24, with the induced drag on A_e.
    * Past the section angle ``match_angle`` (alpha > match_angle a0/a): Viterna & Corrigan
      matched there, C_D -> C_D,max(A_e) at 90 deg instead of the 2-D table's 1.8.
    * |alpha| > 90 deg: mirrored as a flat plate (C_L odd about 90 deg, C_D even).

    Parameters
    ----------
    alpha : float
        Angle of attack, rad (foil frame of :mod:`sailmujoco.forces.foil_geometry`); wrapped to [-pi, pi).
    reynolds : float
        Reynolds number on the chord, -.
    lift_ratio : float
        a/a0, the finite wing's lift slope over the section's 2 pi, - (``FB_KEEL_RATIO`` or
        ``FB_RUDDER_RATIO`` of :func:`pack_foil_block`).
    aspect_ratio : float
        Effective aspect ratio A_e, - (``FB_KEEL_AR`` or ``FB_RUDDER_AR``).
    cd_max : float
        C_D,max(A_e) at 90 deg, - (``FB_KEEL_CD_MAX`` or ``FB_RUDDER_CD_MAX``).
    match_angle : float
        Section (effective) angle where Viterna & Corrigan take over, rad (``FB_MATCH_ANGLE``).
    thickness_ratio : float
        Thickness over chord t/c, -.
    alpha_grid, log_re_grid, cl_table, cd_table : numpy.ndarray
        The section table, as for
        :func:`~sailmujoco.forces.foil_sections.section_coefficients`.

    Returns
    -------
    c_lift, c_drag : float
        C_L and C_D on the foil's planform area.
    """
    a = wrap_angle(alpha)
    sign = 1.0 if a >= 0.0 else -1.0
    phi = abs(a)
    if phi > 0.5 * math.pi:
        phi = math.pi - phi
        sign = -sign
    _, cd0 = section_coefficients(0.0, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    c_friction = 2.0 * (1.0 + 2.0 * thickness_ratio) * ittc_friction_coefficient(reynolds)  # eq. 24
    phi_s = match_angle / lift_ratio
    if phi <= phi_s:
        c_lift, c_drag = _attached_hydrofoil(phi, reynolds, lift_ratio, aspect_ratio, cd0, c_friction,
                                             alpha_grid, log_re_grid, cl_table, cd_table)
    else:
        c_lift_s, c_drag_s = _attached_hydrofoil(phi_s, reynolds, lift_ratio, aspect_ratio, cd0, c_friction,
                                                 alpha_grid, log_re_grid, cl_table, cd_table)
        c_lift, c_drag = viterna_corrigan(phi, phi_s, c_lift_s, c_drag_s, cd_max)
    return sign * c_lift, c_drag


def downwash_factor(distance: float, keel_span: float) -> float:
    """k in epsilon = k C_L,keel / (pi A_e,keel) at ``distance`` behind the keel's CP.

    The keel and its image in the hull form one wing of span b_e = 2 ``keel_span``; the rudder
    sits near its plane of symmetry (the hull). For elliptic loading the rolled-up tip vortices
    lie s = (pi/4)(b_e/2) either side of it (same lift rho V Gamma0 (pi b_e / 4) as the elliptic
    sheet). Biot-Savart for two semi-infinite trailing vortices starting at the keel (Anderson,
    Fundamentals of Aerodynamics, §5.2, induced velocity of a semi-infinite filament) gives the
    downwash behind the centre, as a share of the far wake's 2 C_L / (pi A)::

        k = 1 + x / sqrt(x^2 + s^2),

    1 at the keel (Prandtl's downwash at the lifting line) and 2 far behind. The bound vortex's
    share (it is the keel's own, and singular on its line) and the rudder's depth below the
    vortices' plane are left out; the latter makes k an upper bound.

    Parameters
    ----------
    distance : float
        x: from the keel's CP aft to the rudder's CP, along body x, m.
    keel_span : float
        The keel's geometric span, m.
    """
    s = 0.25 * math.pi * keel_span
    return 1.0 + distance / math.sqrt(distance * distance + s * s)


def pack_foil_block(p, end_plate_keel: float = KEEL_END_PLATE,
                    end_plate_rudder: float = RUDDER_END_PLATE) -> np.ndarray:
    """The finite-wing constants of a boat, laid out by the ``FB_*`` offsets.

    The block goes into the boat's parameter array at ``P_FOIL_BLOCK`` (see
    :func:`sailmujoco.forces.boat.pack_parameters`), FOIL_BLOCK_SIZE floats at most.

    Parameters
    ----------
    p : BoatParams
        The boat: its sail, keel and rudder aspect ratios, and the keel's and rudder's x (body
        frame, m) and span.
    end_plate_keel, end_plate_rudder : float
        A_e / A of the keel and of the rudder, - (the hull as an end plate).

    Returns
    -------
    numpy.ndarray, shape (11,)
        The block.
    """
    block = np.zeros(11)
    block[FB_SAIL_SLOPE] = helmbold_lift_slope(THIN_AIRFOIL_SLOPE, p.sail.aspect_ratio)
    block[FB_SAIL_CD_MAX] = viterna_corrigan_cd_max(p.sail.aspect_ratio)
    for base, foil, end_plate in ((FB_KEEL_RATIO, p.keel, end_plate_keel),
                                  (FB_RUDDER_RATIO, p.rudder, end_plate_rudder)):
        ar = end_plate * foil.aspect_ratio
        block[base] = helmbold_lift_slope(THIN_AIRFOIL_SLOPE, ar) / THIN_AIRFOIL_SLOPE
        block[base + 1] = ar
        block[base + 2] = viterna_corrigan_cd_max(ar)
    block[FB_MATCH_ANGLE] = HYDROFOIL_MATCH_ANGLE
    k = downwash_factor(p.keel.x - p.rudder.x, p.keel.span)
    block[FB_DOWNWASH_K] = k
    block[FB_DOWNWASH_GAIN] = k / (math.pi * end_plate_keel * p.keel.aspect_ratio)
    return block
