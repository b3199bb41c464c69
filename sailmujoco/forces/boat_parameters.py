"""The boat's parameters packed into the flat array the force kernel reads.

:func:`pack_parameters` flattens a :class:`~sailmujoco.boat.params.BoatParams` and the force
switches into ``P``, laid out by the ``P_*`` indices below; blocks of ``P`` are owned by one
force module each, which defines the offsets inside its block. numba dispatches a flat array
in well under a microsecond; a record of 60 fields takes many.
"""

from __future__ import annotations

import numpy as np

from ..boat import hull as hull_geometry
from ..boat.params import BoatParams
from ..constants import GRAVITY
from ..options import AddedMassCoupling, Foils, Hydrostatics, Resistance, RestoringAxes, VerticalDamping
from ..options import choices as literal_choices
from .finite_wing import pack_foil_block
from .resistance import delft_hull, pack_resistance
from .windage import pack_windage

HYDROSTATIC_MODES = literal_choices(Hydrostatics)  # the index is the kernel's code for the mode
# Each of these modelling choices keeps its alternative form, so its effect can be measured
# (forces/added_mass.py, forces/damping.py, forces/hydrostatics.py say why):
ADDED_MASS_COUPLINGS = literal_choices(AddedMassCoupling)  # heave/pitch forward-speed terms out / in
VERTICAL_DAMPING_FORMS = literal_choices(VerticalDamping)  # heave/pitch damping on vertical motion / w, q
RESTORING_AXES = literal_choices(RestoringAxes)  # paper restoring moments about level axes / body axes
# The boat as built; the first value of each is the papers' form:
RESISTANCE_FORMS = literal_choices(Resistance)  # ITTC friction only (Wille eq. 15) / + DSYHS residuary
FOIL_FORMS = literal_choices(Foils)  # the papers' foil coefficients / finite-wing slope and stall

# ---- layout of the packed parameter array P -------------------------------------------
(P_RHO_W, P_RHO_A, P_NU_W, P_G, P_MASS, P_CG_X, P_CG_Z,
 P_A1, P_A2, P_A3, P_A4, P_A5, P_A6,
 P_D11, P_D22, P_D33, P_D55, P_D66, P_BF0, P_BL, P_OMEGA_ROLL, P_LENGTH, P_WETTED, P_FORM_K,
 P_CROSSFLOW_CD,
 P_RIGHTING_K, P_RIGHTING_SIN, P_K_HEAVE, P_K_PITCH,
 P_KEEL_AREA, P_KEEL_AR, P_KEEL_TC, P_KEEL_CHORD, P_KEEL_X, P_KEEL_Z,
 P_RUD_AREA, P_RUD_AR, P_RUD_TC, P_RUD_CHORD, P_RUD_X, P_RUD_Z,
 P_SAIL_AREA, P_MAST_X, P_BOOM_Z, P_CE_AFT, P_CE_HEIGHT, P_SUCTION, P_STALL, P_CF_SAIL,
 P_ON_SAIL, P_ON_KEEL, P_ON_RUDDER, P_HYDRO_MODE, P_ON_DAMPING, P_ON_ADDED, P_TANGENTIAL,
 P_WIND_SPEED, P_WIND_FROM, P_CURRENT_E, P_CURRENT_N, P_WANDER_DT,
 P_FLOTATION_X, P_FULL_KIRCHHOFF, P_BODY_DAMPING, P_BODY_RESTORING,
 P_RESISTANCE_DSYHS, P_FINITE_FOILS, P_KEEL_DOWNWASH, P_ON_WINDAGE) = range(69)
# Blocks of P owned by one force module each (the module defines the offsets inside its block):
P_RESISTANCE_BLOCK, RESISTANCE_BLOCK_SIZE = 69, 64  # forces/resistance.py
P_FOIL_BLOCK, FOIL_BLOCK_SIZE = 133, 16  # forces/finite_wing.py (finite-wing forms)
P_WINDAGE_BLOCK, WINDAGE_BLOCK_SIZE = 149, 16  # forces/windage.py
P_SEA_BLOCK, SEA_BLOCK_SIZE = 165, 10  # forces/sea_kernels.py (ramp, switches, the hull's grid)
P_SEA_RAMP = P_SEA_BLOCK  # s, the waves' start-up ramp T_r; 0 in calm water
P_SIZE = 175


def pack_parameters(p: BoatParams, *, hydrostatics: str = "geometric", sail: bool = True,
                    keel: bool = True, rudder: bool = True, damping: bool = True,
                    added_mass: bool = True, sail_tangential: bool = True, wind=None,
                    wander_dt: float = 0.1, added_mass_coupling: str = "manoeuvring",
                    vertical_damping: str = "world", restoring_axes: str = "horizontal",
                    resistance: str = "dsyhs", foils: str = "finite", keel_downwash: bool = True,
                    windage: bool = True, sea_ramp: float = 0.0) -> np.ndarray:
    """Flatten boat parameters and force switches into ``P`` (P_SIZE,), laid out by the P_* indices.

    Parameters
    ----------
    p : BoatParams
        The boat (SI units; positions in the body frame FLU about CO).
    hydrostatics, added_mass_coupling, vertical_damping, restoring_axes, resistance, foils : str
        The modelling forms, one of ``HYDROSTATIC_MODES``, ``ADDED_MASS_COUPLINGS``,
        ``VERTICAL_DAMPING_FORMS``, ``RESTORING_AXES``, ``RESISTANCE_FORMS``, ``FOIL_FORMS``.
    sail, keel, rudder, damping, added_mass, keel_downwash, windage : bool
        Whether each force term is on (``keel_downwash``: the keel's downwash at the rudder;
        ``windage``: the topsides' and mast's).
    sail_tangential : bool
        Whether the sail has a tangential coefficient (False: C_T = 0).
    wind : WindConfig or None
        Mean speed (m/s), bearing it comes from (rad), current (m/s east, north); None: all 0.
    wander_dt : float
        Time step of the wind's wander series, s.
    sea_ramp : float
        The waves' start-up ramp T_r, s (0 in calm water).
    """
    for name, value, choices in (("hydrostatics", hydrostatics, HYDROSTATIC_MODES),
                                 ("added_mass_coupling", added_mass_coupling, ADDED_MASS_COUPLINGS),
                                 ("vertical_damping", vertical_damping, VERTICAL_DAMPING_FORMS),
                                 ("restoring_axes", restoring_axes, RESTORING_AXES),
                                 ("resistance", resistance, RESISTANCE_FORMS),
                                 ("foils", foils, FOIL_FORMS)):
        if value not in choices:
            raise ValueError(f"unknown {name} {value!r}; choose one of {choices}")
    h = p.hull
    volume = p.displaced_volume
    P = np.zeros(P_SIZE)
    P[P_RHO_W], P[P_RHO_A], P[P_NU_W], P[P_G] = p.rho_water, p.rho_air, p.nu_water, GRAVITY
    P[P_MASS], P[P_CG_X], P[P_CG_Z] = p.mass, p.cg_x, p.cg_z
    P[P_A1:P_A6 + 1] = p.added_mass_diagonal
    P[P_D11:P_D66 + 1] = p.linear_damping
    P[P_BF0], P[P_BL], P[P_OMEGA_ROLL] = p.roll_friction, p.roll_lift, p.roll_frequency
    P[P_LENGTH], P[P_WETTED], P[P_FORM_K] = h.length, p.wetted_surface, p.form_factor
    P[P_CROSSFLOW_CD] = p.crossflow_cd
    P[P_RIGHTING_K] = p.rho_water * GRAVITY * volume * p.gm_t
    P[P_RIGHTING_SIN] = 1.0 if p.paper_righting == "sin" else 0.0
    P[P_K_HEAVE] = p.rho_water * GRAVITY * hull_geometry.waterplane_area(h)
    P[P_K_PITCH] = p.rho_water * GRAVITY * volume * hull_geometry.gm_longitudinal(h, p.cg_z)
    for base, foil in ((P_KEEL_AREA, p.keel), (P_RUD_AREA, p.rudder)):
        P[base:base + 6] = (foil.area, foil.aspect_ratio, foil.thickness_ratio, foil.chord,
                            foil.x, foil.z)
    s = p.sail
    P[P_SAIL_AREA], P[P_MAST_X], P[P_BOOM_Z] = s.area, s.mast_x, s.boom_height
    P[P_CE_AFT], P[P_CE_HEIGHT] = s.ce_aft, s.ce_height
    P[P_SUCTION], P[P_STALL], P[P_CF_SAIL] = (s.suction_efficiency, s.suction_stall,
                                              s.friction_coefficient)
    P[P_ON_SAIL], P[P_ON_KEEL], P[P_ON_RUDDER] = float(sail), float(keel), float(rudder)
    P[P_HYDRO_MODE] = HYDROSTATIC_MODES.index(hydrostatics)
    P[P_ON_DAMPING], P[P_ON_ADDED], P[P_TANGENTIAL] = (float(damping), float(added_mass),
                                                       float(sail_tangential))
    if wind is not None:
        P[P_WIND_SPEED], P[P_WIND_FROM] = wind.speed, wind.direction_from
        P[P_CURRENT_E], P[P_CURRENT_N] = wind.current_east, wind.current_north
    P[P_WANDER_DT] = wander_dt
    P[P_FLOTATION_X] = hull_geometry.centre_of_flotation_x(h)
    P[P_FULL_KIRCHHOFF] = float(added_mass_coupling == "kirchhoff")
    P[P_BODY_DAMPING] = float(vertical_damping == "body")
    P[P_BODY_RESTORING] = float(restoring_axes == "body")
    P[P_RESISTANCE_DSYHS] = float(resistance == "dsyhs")
    block = pack_resistance(delft_hull(h), p.rho_water, GRAVITY)
    P[P_RESISTANCE_BLOCK:P_RESISTANCE_BLOCK + block.size] = block
    P[P_FINITE_FOILS] = float(foils == "finite")
    block = pack_foil_block(p)
    P[P_FOIL_BLOCK:P_FOIL_BLOCK + block.size] = block
    P[P_KEEL_DOWNWASH], P[P_ON_WINDAGE] = float(keel_downwash), float(windage)
    pack_windage(p, P[P_WINDAGE_BLOCK:P_WINDAGE_BLOCK + WINDAGE_BLOCK_SIZE])
    P[P_SEA_RAMP] = sea_ramp  # forces/sea_kernels.py, ramp_duration
    return P
