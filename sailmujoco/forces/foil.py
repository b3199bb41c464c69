"""Foil forces: the keel, the rudder and the sail. Where the keel lift is computed.

Geometry of a foil section (one convention for all three foils)
    chord axis ``c``: in the section plane, pointing from the trailing edge to the leading edge
    (forward for the keel and for an undeflected rudder, from the clew to the mast for the sail);
    normal axis ``n`` = span x c (to port when undeflected); span axis up the mast/keel.
    ``w`` is the velocity of the fluid relative to the foil (where it flows to), projected on
    the section plane: spanwise flow is dropped (the cross-flow principle), which is how the
    force stays in the foil's own plane when the boat heels.
Angle of attack
    The fluid comes from d = -w. alpha = atan2(d.n, d.c), so alpha > 0 when the fluid comes
    from the +n side. This is Wille's alpha = -beta + pi (eqs. 28, 32, 35) written in the foil
    frame. Saoud's angle (§IV) has the opposite sign, alpha = -alpha_s, because his sail angle
    turns the other way (delta_s = -lambda, see controllers/saoud.py); the forces agree.
Lift and drag
    F = q A (C_L (span x w_hat) + C_D w_hat), q = rho |w|^2 / 2 (Wille eqs. 21-22): drag along
    the flow, lift perpendicular to it, away from the side the fluid comes from.
    In chord/normal components this is F = q A (C_T c - C_N n) with
    C_T = C_L sin(alpha) - C_D cos(alpha), C_N = C_L cos(alpha) + C_D sin(alpha) (Saoud §IV).
"""

from __future__ import annotations

# The foils' modules, by what they hold; every name is importable from here too.
from .finite_wing import (  # noqa: F401
    FB_DOWNWASH_GAIN,
    FB_DOWNWASH_K,
    FB_KEEL_AR,
    FB_KEEL_CD_MAX,
    FB_KEEL_RATIO,
    FB_MATCH_ANGLE,
    FB_RUDDER_AR,
    FB_RUDDER_CD_MAX,
    FB_RUDDER_RATIO,
    FB_SAIL_CD_MAX,
    FB_SAIL_SLOPE,
    HYDROFOIL_MATCH_ANGLE,
    KEEL_END_PLATE,
    RUDDER_END_PLATE,
    THIN_AIRFOIL_SLOPE,
    downwash_factor,
    finite_hydrofoil_coefficients,
    finite_sail_normal_coefficient,
    helmbold_lift_slope,
    pack_foil_block,
    viterna_corrigan,
    viterna_corrigan_cd_max,
)
from .foil_geometry import foil_world_force, lift_drag_components, section_flow  # noqa: F401
from .foil_sections import (  # noqa: F401
    SectionTable,
    hydrofoil_coefficients,
    naca0015,
    parse_section_table,
    section_coefficients,
    wrap_pi,
)
from .sail import (  # noqa: F401
    SAOUD_CN_COEFFS,
    finite_sail_coefficients,
    flat_sail_force,
    sail_coefficients,
    sail_force,
    sail_forces,
    saoud_normal_coefficient,
    tangential_coefficient,
)
