"""The boat's parameters packed into the flat array the force kernel reads.

:func:`pack_parameters` flattens a :class:`~sailmujoco.boat.params.BoatParams`, the force
switches (every field of :class:`~sailmujoco.options.ForceSwitches`, at the slots of
:data:`SWITCH_SLOTS`), the wind's mean and the sea's ramp and grid into ``P``, laid out by the
``P_*`` indices below; blocks of ``P`` are owned by one force module each, which defines the
offsets inside its block. numba dispatches a flat array
in well under a microsecond; a record of 60 fields takes many.
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from ..boat import hull as hull_geometry
from ..boat.params import BoatParams
from ..constants import GRAVITY
from ..options import (
    AddedMassCoupling,
    Foils,
    ForceSwitches,
    Hydrostatics,
    Resistance,
    RestoringAxes,
    VerticalDamping,
    WaveConfig,
    literal_fields,
)
from ..options import choices as literal_choices
from .crew import CREW_BLOCK_SIZE, loaded_canoe_body, pack_crew
from .finite_wing import pack_foil_block
from .headsail import HB_INTERACTION, HEADSAIL_BLOCK_SIZE, pack_headsail
from .resistance import delft_hull, pack_resistance
from .sea_kernels import (
    SB_DIFFRACTION,
    SB_FOIL_FLOW,
    SB_HULL,
    SB_PRESSURE_DECAY,
    SB_RAMP,
    SB_RELATIVE_DAMPING,
    pack_sea_block,
)
from .windage import pack_windage

HYDROSTATIC_MODES = literal_choices(Hydrostatics)  # the index is the kernel's code for the mode
# Each of these modelling choices keeps its alternative form, so its effect can be measured
# (forces/added_mass.py, forces/damping.py, forces/hydrostatics.py say why):
ADDED_MASS_COUPLINGS = literal_choices(AddedMassCoupling)  # the index is added_mass.py's code
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
 P_FLOTATION_X, P_ADDED_COUPLING, P_BODY_DAMPING, P_BODY_RESTORING,
 P_RESISTANCE_DSYHS, P_FINITE_FOILS, P_KEEL_DOWNWASH, P_ON_WINDAGE) = range(69)
# Blocks of P owned by one force module each (the module defines the offsets inside its block):
P_RESISTANCE_BLOCK, RESISTANCE_BLOCK_SIZE = 69, 64  # forces/resistance.py
P_FOIL_BLOCK, FOIL_BLOCK_SIZE = 133, 16  # forces/finite_wing.py (finite-wing forms)
P_WINDAGE_BLOCK, WINDAGE_BLOCK_SIZE = 149, 16  # forces/windage.py
P_SEA_BLOCK, SEA_BLOCK_SIZE = 165, 10  # forces/sea_kernels.py (ramp, switches, the hull's grid)
P_SEA_RAMP = P_SEA_BLOCK + SB_RAMP  # s, the waves' start-up ramp T_r; 0 in calm water
P_HEADSAIL_BLOCK = 175  # forces/headsail.py (HEADSAIL_BLOCK_SIZE floats)
P_NEW_SWITCHES = P_HEADSAIL_BLOCK + HEADSAIL_BLOCK_SIZE  # then one slot per switch with no slot below


# The force switches' slots, one per field of ForceSwitches: (slot, the value packed as 1.0);
# any other value packs 0.0; a choice of more than two forms (None) packs its index in its choices.
SWITCH_SLOTS = {
    "hydrostatics": (P_HYDRO_MODE, None),
    "sail": (P_ON_SAIL, True),
    "keel": (P_ON_KEEL, True),
    "rudder": (P_ON_RUDDER, True),
    "damping": (P_ON_DAMPING, True),
    "added_mass": (P_ON_ADDED, True),
    "sail_tangential": (P_TANGENTIAL, True),
    "added_mass_coupling": (P_ADDED_COUPLING, None),
    "vertical_damping": (P_BODY_DAMPING, "body"),
    "restoring_axes": (P_BODY_RESTORING, "body"),
    "resistance": (P_RESISTANCE_DSYHS, "dsyhs"),
    "foils": (P_FINITE_FOILS, "finite"),
    "keel_downwash": (P_KEEL_DOWNWASH, True),
    "windage": (P_ON_WINDAGE, True),
    "wave_hull": (P_SEA_BLOCK + SB_HULL, True),
    "wave_foil_flow": (P_SEA_BLOCK + SB_FOIL_FLOW, True),
    "wave_diffraction": (P_SEA_BLOCK + SB_DIFFRACTION, True),
    "wave_damping": (P_SEA_BLOCK + SB_RELATIVE_DAMPING, "relative"),
    "wave_pressure_decay": (P_SEA_BLOCK + SB_PRESSURE_DECAY, True),
    "rig_interaction": (P_HEADSAIL_BLOCK + HB_INTERACTION, "lumped_vortex"),
}
# A force added to ForceSwitches as an on/off field gets its slot here, after the blocks, in the
# order of the fields; the force reads it as P[switch_slot(name)] (docs/architecture.md, "Add a
# force"), so a new force needs no edit of this file.
_NEW_SWITCHES = [f.name for f in fields(ForceSwitches) if f.name not in SWITCH_SLOTS]
SWITCH_SLOTS.update({name: (P_NEW_SWITCHES + k, True) for k, name in enumerate(_NEW_SWITCHES)})
P_CREW_BLOCK = P_NEW_SWITCHES + len(_NEW_SWITCHES)  # forces/crew.py (CREW_BLOCK_SIZE floats)
P_SIZE = P_CREW_BLOCK + CREW_BLOCK_SIZE


_CHOICES = literal_fields(ForceSwitches)


def switch_slot(name: str) -> int:
    """The slot of ``P`` that holds the force switch ``name`` (a field of ForceSwitches).

    Parameters
    ----------
    name : str
        The switch's field name.

    Returns
    -------
    int
    """
    return SWITCH_SLOTS[name][0]


def pack_switches(switches: ForceSwitches, P: np.ndarray) -> None:
    """Write every force switch into its slot of ``P`` (:data:`SWITCH_SLOTS`).

    Parameters
    ----------
    switches : ForceSwitches
        The physics' force switches (checked when they were made).
    P : numpy.ndarray, shape (P_SIZE,)
        The packed parameters, written in place.
    """
    for name, (slot, on) in SWITCH_SLOTS.items():
        value = getattr(switches, name)
        P[slot] = _CHOICES[name].index(value) if on is None else float(value == on)


def pack_parameters(p: BoatParams, switches: ForceSwitches | None = None, *, wind=None,
                    wander_dt: float = 0.1, waves: WaveConfig | None = None) -> np.ndarray:
    """Flatten boat parameters and force switches into ``P`` (P_SIZE,), laid out by the P_* indices.

    Parameters
    ----------
    p : BoatParams
        The boat (SI units; positions in the body frame FLU about CO).
    switches : ForceSwitches, optional
        Which force models act and in which form (default ``ForceSwitches()``); every field
        is packed (:func:`pack_switches`).
    wind : WindConfig or None
        Mean speed (m/s), bearing it comes from (rad), current (m/s east, north); None: all 0.
    wander_dt : float
        Time step of the wind's wander series, s.
    waves : WaveConfig or None
        The sea: its ramp T_r (0 in calm water) and the hull's grid go into the sea's block.
    """
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
    pack_switches(ForceSwitches() if switches is None else switches, P)
    if wind is not None:
        P[P_WIND_SPEED], P[P_WIND_FROM] = wind.speed, wind.direction_from
        P[P_CURRENT_E], P[P_CURRENT_N] = wind.current_east, wind.current_north
    P[P_WANDER_DT] = wander_dt
    P[P_FLOTATION_X] = hull_geometry.centre_of_flotation_x(h)
    block = pack_resistance(delft_hull(loaded_canoe_body(p)), p.rho_water, GRAVITY)  # with its crew aboard
    P[P_RESISTANCE_BLOCK:P_RESISTANCE_BLOCK + block.size] = block
    block = pack_foil_block(p)
    P[P_FOIL_BLOCK:P_FOIL_BLOCK + block.size] = block
    pack_windage(p, P[P_WINDAGE_BLOCK:P_WINDAGE_BLOCK + WINDAGE_BLOCK_SIZE])
    pack_sea_block(h, waves, P[P_SEA_BLOCK:P_SEA_BLOCK + SEA_BLOCK_SIZE])
    pack_headsail(p, P[P_HEADSAIL_BLOCK:P_HEADSAIL_BLOCK + HEADSAIL_BLOCK_SIZE])
    pack_crew(p, P[P_CREW_BLOCK:P_CREW_BLOCK + CREW_BLOCK_SIZE])
    return P
