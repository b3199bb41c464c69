"""The registered boats: one parameter factory each, the source of every number in the package.

Every number carries its source in a comment: a paper and table/equation, a derivation in
this file, or "guess" with the reason; ``xml/<boat>/README.md`` repeats them step by step.
Positions are in the body frame of :mod:`sailmujoco.frames`; the types are in
:mod:`sailmujoco.boat.params`.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

from .. import constants as c
from ..names import unknown_message
from . import hull as hull_geometry
from .hull import HullShape
from .params import BoatParams, Foil, Sail
from .principal import RIG_CAMBER, boat_from_dimensions, eleven_metre_dimensions
from .schema import is_boat_file, read_boat
from .trim import flattened, reefed
from .viel_identification import (
    VIEL_P6,
    VIEL_P7,
    VIEL_P8,
    VIEL_P9,
    VIEL_P10,
    viel_identified_rudder_area,
    viel_identified_sail_area,
)

# Heave and pitch radiation damping (d33 N s/m, d55 N m s/rad; not in the papers, which hold
# heave and pitch): Capytaine 3.0.0 (3-D panel method, zero speed, deep water, the canoe body
# below its still waterline, 1568-3200 panels, within 1.5 % of half as many) at each boat's
# natural frequencies: heave with k33 = rho g A_wp and M + A33(omega); pitch about the CG, about
# which the free hull pitches, with k55 = rho g V BM_L and I_yy + A55(omega). The fraction of
# critical damping this is: heave 0.31, 0.26, 0.27; pitch 0.27, 0.19, 0.13 (wille, saoud,
# viel). benchmarks/radiation_damping.py computes them (``pip install capytaine``).
RADIATION_DAMPING = {
    "wille_yacht": (19292.0, 62556.0),  # omega_3 = 3.87, omega_5 = 4.03 rad/s
    "saoud_robot": (214.2, 25.8),  # omega_3 = 8.88, omega_5 = 5.91 rad/s
    "viel_boat": (2910.0, 1610.0),  # omega_3 = 5.26, omega_5 = 3.65 rad/s
}

def wille_yacht() -> BoatParams:
    """The 8.8 m, 1600 kg yacht of Wille, Hassani & Sprenger (2016a), Appendix A.

    The extracted Appendix A table is garbled in places; the readings chosen:

    * Foil positions from eqs. 26, 30 and 34 rather than the table's signs: with
      V_f = ... - [-r y_f, r x_f - p z_f] (eq. 25), eq. 26 gives the sail CE at
      x = -(l1 + l2 cos(lambda)), so the mast stands at -l1 = 1.82 m forward of CO and the
      CE l2 = 1.35 m behind it along the boom, h1 = 5.2 m up; eq. 30 puts the keel CP at
      x = -l3 = 0.66 m, h2 = 0.95 m down; eq. 34 the rudder CP at x = -l4 = -3.7 m, h3 = 0.7 m
      down. The yaw and roll rows of eqs. 29, 33, 36 agree with these positions.
    * "d_l44 = 40": eq. 13 has no roll entry, so this is d_l66 (yaw), kg m^2/(rad s).
    * B_F0 = 15, B_L = 70 kg m/rad, omega_roll_n = 2.4 rad/s (the cell next to GM_t = 2.4 m).
      Our computed natural roll frequency sqrt(rho g V GM / (Ixx - K_pdot)) is 2.20 rad/s.
    """
    mass = 1.6e3  # kg, Appendix A ("displacement of 1600kg", §2.2)
    rho = c.RHO_WATER
    gm_t = 2.4  # m, Appendix A
    cg_z, hull = _wille_hull(mass, rho, gm_t)
    return BoatParams(
        name="wille_yacht",
        mass=mass,
        inertia=(6.8e3, 8.5e3, 8.5e3),  # Ixx, Izz: Appendix A; Iyy: guess = Izz (not in 4-DOF)
        inertia_xz=-13.4,  # Appendix A, SNAME
        cg_x=0.0, cg_z=cg_z,
        hull=hull,
        added_mass=(
            -1.6e2,  # X_udot, Appendix A
            -1.2e3,  # Y_vdot, Appendix A
            -hull_geometry.heave_added_mass(hull, rho),  # Z_wdot, strip theory (hull.py)
            -1.0e3,  # K_pdot, Appendix A
            -hull_geometry.pitch_added_inertia(hull, rho),  # M_qdot, strip theory (hull.py)
            -2.4e3,  # N_rdot, Appendix A. Y_rdot = -350 (Appendix A) is left out, as Wille's
            # eq. 11 leaves it out, so both worlds share the horizontal-plane hydrodynamics and
            # their difference is the degrees of freedom. What it would change (measured at
            # 7 m/s on this boat): its C_A yaw term -Y_rdot u r = 2 450 N m s is 4.0 % of the yaw
            # damping of keel, rudder and hull (60 700 N m s); its inertia coupling
            # Y_rdot^2 / ((m - Y_vdot)(I_zz - N_rdot)) = 0.4 % of the sway and yaw accelerations.
        ),
        gm_t=gm_t,
        wetted_surface=9.8,  # m^2, S_H, Appendix A
        form_factor=0.15,  # k, Appendix A
        linear_damping=(
            10.0,  # d_l11, kg/s, Appendix A
            16.0,  # d_l22, kg/s, Appendix A
            *RADIATION_DAMPING["wille_yacht"],  # d33, d55: BEM at the natural frequencies
            40.0,  # d_l66, kg m^2/(rad s), Appendix A ("d_l44", see docstring)
        ),
        roll_friction=15.0,  # B_F0, Appendix A
        roll_lift=70.0,  # B_L, Appendix A
        roll_frequency=2.4,  # omega_roll_n, rad/s, Appendix A
        crossflow_cd=1.0,  # guess: Hoerner's cross-flow C_D of a shallow, wide section ~0.8-1.2
        keel=_wille_keel(),
        rudder=_wille_rudder(),
        sail=_wille_sail(),
        rho_air=c.RHO_AIR_WILLE,
        paper_righting="sin_cos",
        sources={"paper": "Wille, Hassani, Sprenger (2016a), Appendix A"},
    )


def _wille_hull(mass: float, rho: float, gm_t: float) -> tuple[float, HullShape]:
    """(cg_z, hull) of :func:`wille_yacht`: its CG height and the hull designed for its GM_t."""
    # CG: the paper puts CO at the CG on the waterline (§2); a real yacht of this size gets its
    # stability from a ballast keel, so ours sits below it (xml/wille_yacht/README.md step 4).
    # Foil and sail positions stay the paper's, measured from CO on the waterline.
    ballast_ratio = 0.50  # -, guess: bulb keels of light 8-9 m keelboats carry 40-50 % of m
    z_ballast = -1.40  # m, guess: bulb centroid 0.08 m above the keel tip, which is the keel
    # span sqrt(Asp_k A_k) = 1.276 m (Appendix A) below the canoe body's 0.205 m draft (1.48 m)
    z_rest = 0.25  # m, guess: hull shell, deck, fit-out and mast above the ballast
    cg_z = ballast_ratio * z_ballast + (1.0 - ballast_ratio) * z_rest  # = -0.575 m
    hull = hull_geometry.design_for(
        length=8.8,  # m, L_WL, Appendix A
        displaced_volume=mass / rho,
        gm=gm_t, z_g=cg_z,
        freeboard=0.8,  # m, guess: typical for an 8-9 m cruiser-racer
        flare=1.3)  # deck / waterline half-breadth, guess: beam 2.69 m at the deck, 2.07 m at
    # the waterline (topsides flared 21 deg), as modern yachts carry their beam above the water
    return cg_z, hull


def _wille_keel() -> Foil:
    """The keel of :func:`wille_yacht` (Appendix A, eq. 30)."""
    return Foil(area=0.93, aspect_ratio=1.75,  # A_k, Asp_k, Appendix A
                thickness_ratio=0.09,  # NACA 0009 (§2.1)
                x=0.66, z=-0.95)  # -l3, -h2 (eq. 30)


def _wille_rudder() -> Foil:
    """The rudder of :func:`wille_yacht` (Appendix A, eq. 34)."""
    return Foil(area=0.30, aspect_ratio=2.97,  # A_r, Asp_r, Appendix A
                thickness_ratio=0.15,  # NACA 0015 (§2.1)
                x=-3.7, z=-0.7,  # -l4, -h3 (eq. 34)
                mass=8.0,  # kg, guess: a 0.3 m^2 GRP blade and stock
                max_angle=math.radians(35.0),  # sigma_sat, Appendix A
                time_constant=0.2)  # T_sigma, s, Appendix A


def _wille_sail() -> Sail:
    """The sail of :func:`wille_yacht` (Appendix A, eq. 26)."""
    return Sail(area=22.8,  # m^2, A_s, Appendix A
                aspect_ratio=5.0,  # the flat AR 5 sail of Saoud (2015) §VII-A stands in
                # for Marchaj's p. 587 coefficients, which are not available to us
                mast_x=1.82,  # -l1 (eq. 26)
                ce_aft=1.35,  # l2, Appendix A
                ce_height=5.2,  # h1, Appendix A
                mass=30.0,  # kg, guess: aluminium boom + Dacron main of 22.8 m^2
                max_angle=math.radians(110.0),  # lambda_sat, Appendix A
                time_constant=0.5)  # T_lambda, s, Appendix A


def saoud_robot(l_phi: float = 1.0) -> BoatParams:
    """A ~1.5 m, 15 kg robotic sailboat with the numbers of Saoud et al. (2015) Table I.

    Table I gives m = 15 kg, S_s = 1 m^2, h_s = 0.8 m, rho_air = 1.225; the metacentric height
    ``l_phi`` is the paper's parameter (0.1 m and 1 m). Hull, keel and rudder sizes are ours
    (xml/saoud_robot/README.md justifies them). The CG height follows from l_phi:
    z_G = z_B + BM - l_phi, so GM_t = l_phi exactly for the geometric hull too.

    The sail CE stands h_s = 0.8 m above the CG of the l_phi = 0.1 m boat, and stays there for
    other l_phi: with l_phi = 1 m the CG lies 0.84 m below the waterline and a CE 0.8 m above
    it would be at the waterline. So the heeling arm CE-CG is 0.8 m at l_phi = 0.1 and 1.7 m at
    l_phi = 1 in 6-DOF, while Saoud's reduced model keeps h_s = 0.8 m (a stated difference).

    Parameters
    ----------
    l_phi : float
        Saoud's metacentric height l_phi (GM_t), m, > 0.
    """
    if not math.isfinite(l_phi) or l_phi <= 0.0:
        raise ValueError(f"l_phi (metacentric height) must be positive, got {l_phi!r}")
    mass = 15.0  # kg, Table I
    rho = c.RHO_WATER
    length, half_beam = 1.5, 0.18  # m, ours: a 1.5 m robot of 0.36 m beam
    volume = mass / rho
    draft = volume / (4.0 * math.pi / 15.0 * half_beam * length)
    hull = HullShape(length, half_beam, draft, freeboard=0.12)  # freeboard: ours
    z_metacentre = hull_geometry.centre_of_buoyancy_z(hull) + hull_geometry.bm_transverse(hull)
    cg_z = z_metacentre - l_phi
    h_s = 0.8  # m, Table I
    ce_height = h_s + (z_metacentre - 0.1)  # CE above the CG of the l_phi = 0.1 m boat
    # ours: the hull with its deep ballast (radii of gyration ~0.3-0.4 m) plus the rig, whose
    # 0.5 kg sits up to 1.7 m from the CG (Ixx would be ~0.9 without it)
    inertia = (2.5, 3.5, 2.2)
    omega_roll = math.sqrt(mass * c.GRAVITY * l_phi / (inertia[0] + 0.15 * inertia[0]))
    keel_span, keel_chord = 0.35, 0.16  # m, ours
    rudder_span, rudder_chord = 0.22, 0.10  # m, ours: the yaw authority a 1 m^2 rig needs
    return BoatParams(
        name="saoud_robot",
        mass=mass,
        inertia=inertia,
        inertia_xz=0.0,
        cg_x=0.0, cg_z=cg_z,
        hull=hull,
        added_mass=(
            -0.10 * mass,  # X_udot: Wille's ratio X_udot/m = -0.10
            -0.75 * mass,  # Y_vdot: Wille's ratio -0.75
            -hull_geometry.heave_added_mass(hull, rho),  # strip theory
            -0.15 * inertia[0],  # K_pdot: Wille's ratio K_pdot/Ixx = -0.15
            -hull_geometry.pitch_added_inertia(hull, rho),  # strip theory
            -0.28 * inertia[2],  # N_rdot: Wille's ratio N_rdot/Izz = -0.28
        ),
        gm_t=l_phi,
        wetted_surface=hull_geometry.wetted_surface(hull),  # computed from the hull
        form_factor=0.15,  # Wille's k
        linear_damping=(0.5, 2.0, *RADIATION_DAMPING["saoud_robot"], 0.2),  # d11, d22, d66: guess
        roll_friction=0.02,  # guess, scaled so roll damping ratio ~ Wille's at rest
        roll_lift=0.3,  # guess
        roll_frequency=omega_roll,  # computed natural roll frequency
        crossflow_cd=1.0,  # guess, as for the yacht
        keel=Foil(area=keel_span * keel_chord, aspect_ratio=keel_span**2 / (keel_span * keel_chord),
                  thickness_ratio=0.09, x=0.0, z=-(draft + 0.45 * keel_span)),
        rudder=Foil(area=rudder_span * rudder_chord,
                    aspect_ratio=rudder_span**2 / (rudder_span * rudder_chord),
                    thickness_ratio=0.15, x=-0.65, z=-(0.05 + 0.4 * rudder_span),
                    mass=0.1, max_angle=math.radians(35.0), time_constant=0.2),
        sail=Sail(area=1.0,  # S_s, Table I
                  aspect_ratio=5.0,  # the flat AR 5 sail of §VII-A
                  mast_x=0.25,  # m, ours: puts the CE 5 cm behind the keel's CP
                  ce_aft=2.0 / math.sqrt(5.0) / 3.0,  # foot / 3 of the AR 5 triangle
                  ce_height=ce_height,
                  mass=0.5,  # kg, ours: carbon boom and sail
                  max_angle=math.pi,  # Assumption 5: fully actuated, delta_s in [-pi, pi]
                  time_constant=0.3),  # s, ours (Saoud gives none)
        rho_air=c.RHO_AIR_SAOUD,
        paper_righting="sin",  # Saoud eq. 4: m g l_phi sin(phi)
        sources={"paper": f"Saoud, Hua, Plumet, Ben Amar (2015), Table I; l_phi = {l_phi:g} m"},
    )


def viel_boat() -> BoatParams:
    """Viel, Vautier, Wan & Jaulin (2019)'s 300 kg boat (Table 1, from Melin / Jaulin) in 6-DOF.

    From Table 1: mass p9, yaw inertia p10, mast position p7, sail CE p6 behind the mast, rudder
    p8 behind G; the sail area from p4 (:func:`viel_identified_sail_area`), the rudder area from
    p5 (:func:`viel_identified_rudder_area`); the hull friction is Wille's eq. 15 with
    k = 0.15 (Viel's p2 is not taken over: it lumps wave resistance); the actuator limits of
    §2.1 (45 deg rudder, 90 deg sail). Viel's model is planar and gives no hull: length, beam,
    draft, keel, roll and pitch inertia, GM, added mass and damping are ours, for a ~4 m
    ballasted dinghy-like keelboat (xml/viel_boat/README.md). Not taken over: p1 (hull
    windage: forces/windage.py, from the boat's dimensions), p3 (Viel's yaw friction p3 omega v:
    in 6-DOF the keel, rudder and hull damp the yaw), p11 (the rudder brake: in 6-DOF the
    rudder's own drag brakes the boat).
    """
    mass = VIEL_P9  # kg, Viel Table 1 p9
    rho = c.RHO_WATER  # kg/m^3, sea water (Viel gives none)
    rho_air = c.RHO_AIR_SAOUD  # kg/m^3, Viel gives none: the ISA sea-level 1.225 (as Saoud Table I)
    gm_t, cg_z, hull = _viel_hull(mass, rho)
    wetted = hull_geometry.wetted_surface(hull)  # m^2, S_H computed from the hull
    inertia, added = _viel_inertia(mass, hull, rho)
    omega_roll = math.sqrt(mass * c.GRAVITY * gm_t / (inertia[0] - added[3]))  # computed
    keel, rudder = _viel_foils(hull, rho)
    return BoatParams(
        name="viel_boat",
        mass=mass,
        inertia=inertia,
        inertia_xz=0.585321,  # kg m^2, SNAME: the rig's alone (10 kg boom+sail at the CE, 3 kg rudder
        # at its CP, about G; mjcf.hull_inertial), taking the hull body's own I_xz as 0 (a guess)
        cg_x=0.0,  # G at CO: Viel's p7 and p8 are measured from G
        cg_z=cg_z,
        hull=hull,
        added_mass=added,
        gm_t=gm_t,
        wetted_surface=wetted,
        form_factor=0.15,  # k, Wille's (Appendix A): friction only. Viel's p2 v^2 lumps the
        # wave resistance too; that is DSYHS's residuary term (resistance="dsyhs"), not k's
        # (xml/viel_boat/README.md step 6 compares the two with p2 v^2)
        linear_damping=(
            2.0,  # d11, kg/s, guess: Wille's d_l11 / m ratio (10 / 1600) x 300, rounded up
            5.0,  # d22, kg/s, guess: Wille's d_l22 / m ratio (16 / 1600) x 300, rounded up
            *RADIATION_DAMPING["viel_boat"],  # d33, d55: BEM at the natural frequencies
            2.0,  # d66, kg m^2/(rad s), guess: Wille's d_l66 / Izz (40 / 8500) x 400
        ),
        roll_friction=2.8,  # B_F0, guess: Wille's 15 scaled by mass (300 / 1600)
        roll_lift=13.0,  # B_L, kg m / rad, guess: Wille's 70 scaled by mass
        roll_frequency=omega_roll,  # rad/s, computed natural roll frequency
        crossflow_cd=1.0,  # guess, as for the other boats (Hoerner ~0.8-1.2)
        keel=keel,
        rudder=rudder,
        sail=_viel_sail(rho_air),
        rho_water=rho,
        rho_air=rho_air,
        paper_righting="sin",  # Saoud eq. 4, m g GM sin(phi): a ballasted keelboat keeps its
        # righting arm to large heel, where eq. 20's sin cos peaks at 45 deg and falls to 0 at 90
        sources={"paper": "Viel, Vautier, Wan, Jaulin (2019), Table 1 (p2, p4-p10) and §2.1; "
                          "hull, keel, roll: ours (xml/viel_boat/README.md)"},
    )


def _viel_hull(mass: float, rho: float) -> tuple[float, float, HullShape]:
    """(gm_t, cg_z, hull) of :func:`viel_boat`: its stability and the hull designed for it."""
    # Stability for the 11.7 m^2 rig (guess, a 2.4mR-like keelboat: ~60-70 % ballast in a bulb):
    # 180 kg lead bulb at the keel tip z = -1.25 m, a 100 kg hull/deck at ~+0.05 m, a 20 kg rig
    # (mast, boom, sail) centred ~3.5 m up: z_G = (-225 + 5 + 70) / 300 = -0.50 m. GM_t follows
    # from the hull (z_B + BM - z_G of a 1.05 m beam): ~1.05 m. Checked: steady heel
    # under the eq. 15 sail in 10 m/s (tests/test_viel_boat.py, xml/viel_boat/README.md step 7).
    gm_t = 1.05  # m, guess (see above)
    cg_z = -0.50  # m, guess (see above)
    length = 2.0 * VIEL_P8  # m, L_WL, ours: the rudder p8 = 2 m behind G hangs on the transom
    # of a hull with G midships
    hull = hull_geometry.design_for(length=length, displaced_volume=mass / rho, gm=gm_t, z_g=cg_z,
                                    freeboard=0.4)  # m, guess: a small open keelboat's freeboard
    return gm_t, cg_z, hull


def _viel_inertia(mass: float, hull: HullShape, rho: float) -> tuple[tuple, tuple]:
    """(inertia, added_mass) of :func:`viel_boat`: Ixx, Iyy, Izz and the six added-mass terms."""
    # Ixx: guess, the sum of the ballast (180 kg 0.75 m below G: ~100), the hull shell (~100 kg
    # at radius ~0.5 m: ~25), the mast (12 kg, 8.4 m tall, centred 4.5 m above G: ~310) and the
    # boom + sail (10 kg at the CE 3.8 m above G: ~145) = ~580; Iyy: guess, the same vertical
    # terms (~555) plus the hull's length share (~300) = ~850; Izz: Viel Table 1 p10
    inertia = (580.0, 850.0, VIEL_P10)
    added = (-0.10 * mass,  # X_udot: Wille's ratio X_udot / m = -0.10
             -0.75 * mass,  # Y_vdot: Wille's ratio -0.75
             -hull_geometry.heave_added_mass(hull, rho),  # Z_wdot, strip theory (hull.py)
             -0.15 * inertia[0],  # K_pdot: Wille's ratio K_pdot / Ixx = -0.15
             -hull_geometry.pitch_added_inertia(hull, rho),  # M_qdot, strip theory (hull.py)
             -0.28 * inertia[2])  # N_rdot: Wille's ratio N_rdot / Izz = -0.28
    return inertia, added


def _viel_foils(hull: HullShape, rho: float) -> tuple[Foil, Foil]:
    """(keel, rudder) of :func:`viel_boat`; the rudder's area from p5."""
    keel_area, keel_ar = 0.6, 2.0  # m^2, -, guess: a 1.1 m fin (2.4mR-like) carrying the
    # ~900 N side force of the 11.7 m^2 sail at ~8 deg leeway and 2.4 m/s (with the rudder)
    rudder_ar = 3.0  # -, guess: a deep transom-hung blade
    rudder_area = viel_identified_rudder_area(rho, rudder_ar)  # m^2, from p5
    keel_span = math.sqrt(keel_ar * keel_area)
    rudder_span = math.sqrt(rudder_ar * rudder_area)
    keel = Foil(area=keel_area, aspect_ratio=keel_ar,
                thickness_ratio=0.09,  # guess: NACA 0009, as Wille's keel
                x=0.0,  # under G: Viel's eq. 5 keel force has no yaw moment in eq. 6
                z=-(hull.canoe_draft + 0.45 * keel_span))  # CP at 45 % of the span
    rudder = Foil(area=rudder_area, aspect_ratio=rudder_ar,
                  thickness_ratio=0.15,  # NACA 0015, as Wille's rudder
                  x=-VIEL_P8,  # m, Viel Table 1 p8
                  z=-(0.05 + 0.4 * rudder_span),  # CP at 40 % of the span below a 5 cm root
                  mass=3.0,  # kg, guess: a 0.26 m^2 GRP blade and stock
                  max_angle=math.pi / 4.0,  # Viel §2.1 delta_r,max
                  time_constant=0.2)  # s, T_sigma: Wille's (Viel gives none)
    return keel, rudder


def _viel_sail(rho_air: float) -> Sail:
    """The sail of :func:`viel_boat`; its area from p4."""
    sail_area = viel_identified_sail_area(rho_air)  # m^2, from p4
    luff = 7.65  # m: the luff of the flat AR 5 sail of this area (7.645 m, Saoud §VII-A's AR 5,
    # whose C_N polynomial the paper-form force model uses), rounded so that the CE height
    # 0.8 + luff / 3 = 3.35 m is exact in the MJCF's 6 digits
    sail_ar = luff**2 / sail_area  # -, 5.01
    boom_height = 0.8  # m, guess: boom 0.4 m above the 0.4 m deck
    return Sail(area=sail_area, aspect_ratio=sail_ar,
                mast_x=VIEL_P7,  # m, Viel Table 1 p7 (mast ahead of G)
                ce_aft=VIEL_P6,  # m, Viel Table 1 p6 (CE behind the mast along the boom)
                ce_height=boom_height + luff / 3.0,  # m, 3.35: triangle, CE luff/3 above the boom
                mass=10.0,  # kg, guess: a 3.1 m aluminium boom (~6) and an 11.7 m^2 Dacron main (~4)
                max_angle=math.pi / 2.0,  # Viel §2.1 delta_s,max
                time_constant=0.5)  # s, T_lambda: Wille's (Viel gives none)


# m^2, the main (its roach included) and the genoa as ORC measured them on two 11:Metres
# (certificates NOR151 and NOR317, 2025), against the class's 22.83 and 15.22
ORC_SAIL_AREAS = (29.43, 13.96)
SAIL_AREAS = ("class", "orc")


def eleven_metre(headsail: bool = True, camber: float = RIG_CAMBER, crew: bool = True, reef: float = 1.0,
                 flat: float = 1.0, areas: str = "class", surge_damping: bool = True) -> BoatParams:
    """The 10.3 m, 1600 kg 11:Metre One Design, made from its class's published dimensions.

    By the rules of :mod:`sailmujoco.boat.principal`, the Wille yacht its parent
    (xml/eleven_metre/README.md).

    Parameters
    ----------
    headsail : bool
        With the class's jib (False: the main alone).
    camber : float
        The sails' camber ratio (0: the papers' flat plates).
    crew : bool
        With ORC's 350 kg crew on the weather rail (False: no crew).
    reef, flat : float
        The depowering trims (:mod:`sailmujoco.boat.trim`): the main's hoist and the camber's
        multiplier, 1: full sail.
    areas : {"class", "orc"}
        The sail areas: the class's, or ORC's measured :data:`ORC_SAIL_AREAS` (the main's roach
        counted: the same luff, a longer mean foot).
    surge_damping : bool
        With the linear surge damping d11 the boat takes from the Wille yacht (Wille eq. 13,
        Froude-scaled) on top of the ITTC friction and the residuary resistance; False: d11 = 0,
        the resistance of a VPP.
    """
    if areas not in SAIL_AREAS:
        raise ValueError(f"areas must be one of {', '.join(map(repr, SAIL_AREAS))}, got {areas!r}")
    d = eleven_metre_dimensions(headsail)
    if not crew:
        d = replace(d, crew=0.0)
    if areas == "orc":
        d = replace(d, main_area=ORC_SAIL_AREAS[0], jib_area=ORC_SAIL_AREAS[1] if headsail else 0.0)
    boat = boat_from_dimensions(d, wille_yacht(), camber=camber)
    if not surge_damping:
        boat = boat.with_(linear_damping=(0.0, *boat.linear_damping[1:]))
    return flattened(reefed(boat, reef), flat)


BOATS = {"wille_yacht": wille_yacht, "saoud_robot": saoud_robot, "viel_boat": viel_boat,
         "eleven_metre": eleven_metre}
BUILT_IN = tuple(BOATS)


def register_boat(name: str, factory) -> None:
    """Register a boat's parameter factory under ``name`` (at run time, no reinstall).

    ``suite.load(name, task)``, ``get_boat(name, **options)`` and sweep files then find it.

    Parameters
    ----------
    name : str
        The boat's name (a new one: the built-in boats cannot be replaced).
    factory : callable
        ``factory(**options) -> BoatParams``; its keyword options are the boat's options
        (``boat_options`` in :func:`sailmujoco.suite.load`, ``boat.*`` keys in a sweep).
    """
    if not isinstance(name, str) or not name.isidentifier():
        raise ValueError(f"a boat's name must be an identifier, got {name!r}")
    if not callable(factory):
        raise ValueError(f"register_boat({name!r}, ...) needs a callable factory, got {factory!r}")
    if name in BUILT_IN and BOATS.get(name) is not factory:
        raise ValueError(f"{name!r} is a built-in boat; register yours under another name")
    BOATS[name] = factory


def get_boat(name_or_path, **options) -> BoatParams:
    """The parameters of a registered boat, or of the boat in a boat file.

    Parameters
    ----------
    name_or_path : str or os.PathLike
        A registered boat: a key of :data:`BOATS` (``wille_yacht``, ``saoud_robot``,
        ``viel_boat``, or one added by :func:`register_boat`); or a boat file, a path object or
        a string ending in ``.toml`` (:func:`sailmujoco.boat.schema.read_boat`).
    **options
        Keyword arguments of the boat's factory (e.g. ``l_phi`` for :func:`saoud_robot`); an
        option the factory does not take raises a ValueError. A boat file takes none.

    Returns
    -------
    BoatParams
    """
    if is_boat_file(name_or_path):
        if options:
            raise ValueError(f"boat file {str(name_or_path)!r} takes no boat options, got "
                             f"{', '.join(sorted(options))} (edit the file instead)")
        return read_boat(name_or_path)
    try:
        factory = BOATS[name_or_path]
    except (KeyError, TypeError):
        raise ValueError(unknown_message("boat", name_or_path, BOATS, "get_boat")
                         + " or a boat file ending in .toml") from None
    try:
        return factory(**options)
    except TypeError as err:
        raise ValueError(f"bad option for boat {name_or_path!r}: {err}") from None


def boat_label(boat) -> str:
    """A boat argument as a short name for folders and titles: a registered name as it is, a
    boat file by its file name without ``.toml``.

    Parameters
    ----------
    boat : str or os.PathLike
        A registered boat or a boat file.
    """
    return Path(boat).stem if is_boat_file(boat) else str(boat)
