"""Boat parameters: frozen dataclasses in SI units, the source of every number in the package.

Positions are in the body frame of :mod:`sailmujoco.frames` (origin CO on the waterline
midship, x forward, y port, z up). Added-mass derivatives keep the SNAME sign (negative).
Every number carries its source in a comment: a paper and table/equation, a derivation in
this file, or "guess" with the reason; ``xml/<boat>/README.md`` repeats them step by step.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np

from . import constants as c
from . import hull as hull_geometry
from .hull import HullShape


def _check_positive(obj, names):
    for name in names:
        value = getattr(obj, name)
        if not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0.0:
            raise ValueError(
                f"{type(obj).__name__}.{name} must be a positive finite number, got {value!r}")


@dataclass(frozen=True)
class Foil:
    """A keel or rudder: a symmetric NACA section of finite span.

    ``x``, ``z`` locate the centre of pressure (CP) in the body frame at zero deflection; a
    rudder turns about a vertical stock through its CP (a balanced rudder: no hinge moment).
    """

    area: float  # m^2, planform area A
    aspect_ratio: float  # -, Asp = span^2 / A
    thickness_ratio: float  # -, t_max / c
    x: float  # m, CP forward of CO
    z: float  # m, CP height (negative: below the waterline)
    mass: float = 0.0  # kg, of a moving foil (rudder blade); 0 for a keel (part of the hull)
    max_angle: float = 0.0  # rad, deflection saturation (rudder sigma_sat)
    time_constant: float = 0.0  # s, first-order actuator lag (rudder T_sigma)

    def __post_init__(self):
        _check_positive(self, ("area", "aspect_ratio", "thickness_ratio"))

    @property
    def span(self) -> float:
        return math.sqrt(self.aspect_ratio * self.area)

    @property
    def chord(self) -> float:
        return self.area / self.span


@dataclass(frozen=True)
class Sail:
    """A flat triangular mainsail on a boom that turns about the mast (body z axis).

    The centre of effort (CE) lies ``ce_aft`` behind the mast along the boom and ``ce_height``
    above the waterline; luff and foot follow from area and aspect ratio (a triangle: CE at a
    third of the luff above the boom).
    """

    area: float  # m^2
    aspect_ratio: float  # -, luff^2 / area
    mast_x: float  # m, mast position forward of CO
    ce_aft: float  # m, CE behind the mast along the boom (Wille's l2)
    ce_height: float  # m, CE above the waterline (Wille's h1)
    mass: float  # kg, boom and sail (the part that turns)
    max_angle: float  # rad, lambda_sat
    time_constant: float  # s, T_lambda, first-order lag of the actuated sail / the sheet
    # Tangential-force model of the flat sail (see forces/foil.py, sail_coefficients):
    suction_efficiency: float = 0.3  # -, share of the ideal leading-edge suction recovered
    suction_stall: float = math.radians(15.0)  # rad, angle past which the suction collapses
    friction_coefficient: float = 0.005  # -, skin friction per face (turbulent flat plate)

    def __post_init__(self):
        _check_positive(self, ("area", "aspect_ratio", "ce_aft", "ce_height", "mass",
                               "max_angle", "time_constant"))

    @property
    def luff(self) -> float:
        return math.sqrt(self.aspect_ratio * self.area)

    @property
    def foot(self) -> float:
        return 2.0 * self.area / self.luff

    @property
    def boom_height(self) -> float:
        return self.ce_height - self.luff / 3.0

    @property
    def masthead_height(self) -> float:
        return self.boom_height + self.luff


@dataclass(frozen=True)
class BoatParams:
    """Everything the MJCF builder, the force models and the reduced models need."""

    name: str
    mass: float  # kg, total (hull + rudder + boom/sail)
    inertia: tuple[float, float, float]  # kg m^2, (Ixx, Iyy, Izz) about the CG, body axes
    inertia_xz: float  # kg m^2, SNAME I_xz (MuJoCo fullinertia ixz takes it unchanged in FLU)
    cg_x: float  # m, CG forward of CO
    cg_z: float  # m, CG above the waterline
    hull: HullShape
    added_mass: tuple[float, float, float, float, float, float]  # SNAME X_udot..N_rdot, <= 0
    gm_t: float  # m, transverse metacentric height (paper value the hull is designed to)
    wetted_surface: float  # m^2, S_H of eq. 15
    form_factor: float  # -, k of eq. 15
    linear_damping: tuple[float, float, float, float, float]  # d11, d22, d33, d55, d66
    roll_friction: float  # B_F0 of eq. 19
    roll_lift: float  # B_L of eq. 19, kg m / rad
    roll_frequency: float  # rad/s, omega_roll_n of eq. 19
    crossflow_cd: float  # -, 2-D drag coefficient of hull sections, eqs. 17-18
    keel: Foil
    rudder: Foil
    sail: Sail
    rho_water: float = c.RHO_WATER
    rho_air: float = c.RHO_AIR_WILLE
    nu_water: float = c.NU_WATER
    nu_air: float = c.NU_AIR
    paper_righting: str = "sin_cos"  # eq. 20 (Wille) or "sin" (Saoud eq. 4)
    sources: dict = field(default_factory=dict, compare=False, hash=False)

    def __post_init__(self):
        _check_positive(self, ("mass", "gm_t", "wetted_surface", "roll_frequency"))
        if any((not math.isfinite(v)) or v <= 0 for v in self.inertia):
            raise ValueError(f"{self.name}: inertia must be positive, got {self.inertia}")
        if any((not math.isfinite(v)) or v > 0 for v in self.added_mass):
            raise ValueError(f"{self.name}: added-mass derivatives are SNAME (<= 0), "
                             f"got {self.added_mass}")
        if any((not math.isfinite(v)) or v < 0 for v in self.linear_damping):
            raise ValueError(f"{self.name}: linear damping must be >= 0, got {self.linear_damping}")
        if self.paper_righting not in ("sin_cos", "sin"):
            raise ValueError(f"paper_righting must be 'sin_cos' or 'sin', got {self.paper_righting!r}")
        if self.rudder.mass <= 0 or self.rudder.max_angle <= 0 or self.rudder.time_constant <= 0:
            raise ValueError("rudder needs a positive mass, max_angle and time_constant")

    @property
    def displaced_volume(self) -> float:
        """Design displacement, m^3 (weight = buoyancy)."""
        return self.mass / self.rho_water

    @property
    def added_mass_diagonal(self) -> np.ndarray:
        """Positive added masses (-X_udot, -Y_vdot, -Z_wdot, -K_pdot, -M_qdot, -N_rdot)."""
        return -np.asarray(self.added_mass, dtype=float)

    def with_(self, **changes) -> BoatParams:
        """A copy with some fields changed (validated again)."""
        unknown = set(changes) - {f.name for f in fields(self)}
        if unknown:
            raise ValueError(f"unknown BoatParams field(s) {sorted(unknown)}")
        return replace(self, **changes)


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
    sail_area = 22.8  # m^2, A_s, Appendix A
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
            *_radiation_damping(hull, mass, rho, zeta=0.2),  # d33, d55: ours, see below
            40.0,  # d_l66, kg m^2/(rad s), Appendix A ("d_l44", see docstring)
        ),
        roll_friction=15.0,  # B_F0, Appendix A
        roll_lift=70.0,  # B_L, Appendix A
        roll_frequency=2.4,  # omega_roll_n, rad/s, Appendix A
        crossflow_cd=1.0,  # guess: Hoerner's cross-flow C_D of a shallow, wide section ~0.8-1.2
        keel=Foil(area=0.93, aspect_ratio=1.75,  # A_k, Asp_k, Appendix A
                  thickness_ratio=0.09,  # NACA 0009 (§2.1)
                  x=0.66, z=-0.95),  # -l3, -h2 (eq. 30)
        rudder=Foil(area=0.30, aspect_ratio=2.97,  # A_r, Asp_r, Appendix A
                    thickness_ratio=0.15,  # NACA 0015 (§2.1)
                    x=-3.7, z=-0.7,  # -l4, -h3 (eq. 34)
                    mass=8.0,  # kg, guess: a 0.3 m^2 GRP blade and stock
                    max_angle=math.radians(35.0),  # sigma_sat, Appendix A
                    time_constant=0.2),  # T_sigma, s, Appendix A
        sail=Sail(area=sail_area,
                  aspect_ratio=5.0,  # the flat AR 5 sail of Saoud (2015) §VII-A stands in
                  # for Marchaj's p. 587 coefficients, which are not available to us
                  mast_x=1.82,  # -l1 (eq. 26)
                  ce_aft=1.35,  # l2, Appendix A
                  ce_height=5.2,  # h1, Appendix A
                  mass=30.0,  # kg, guess: aluminium boom + Dacron main of 22.8 m^2
                  max_angle=math.radians(110.0),  # lambda_sat, Appendix A
                  time_constant=0.5),  # T_lambda, s, Appendix A
        rho_air=c.RHO_AIR_WILLE,
        paper_righting="sin_cos",
        sources={"paper": "Wille, Hassani, Sprenger (2016a), Appendix A"},
    )


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
        linear_damping=(0.5, 2.0, *_radiation_damping(hull, mass, rho, zeta=0.2), 0.2),  # guess
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


def _radiation_damping(h: HullShape, mass: float, rho: float, zeta: float):
    """Linear heave and pitch damping (d33, d55) for a damping ratio ``zeta``.

    Not in the papers (they hold heave and pitch). Wave-radiation damping of a light hull is
    of order 0.1-0.3 of critical at its natural frequency; we take ``zeta`` of critical:
    d = 2 zeta sqrt(k (M + A)).
    """
    k33 = rho * c.GRAVITY * hull_geometry.waterplane_area(h)
    m33 = mass + hull_geometry.heave_added_mass(h, rho)
    v = mass / rho
    k55 = rho * c.GRAVITY * v * hull_geometry.bm_longitudinal(h)
    i55 = mass * (0.25 * h.length) ** 2 + hull_geometry.pitch_added_inertia(h, rho)
    return 2.0 * zeta * math.sqrt(k33 * m33), 2.0 * zeta * math.sqrt(k55 * i55)


BOATS = {"wille_yacht": wille_yacht, "saoud_robot": saoud_robot}


def get_boat(name: str, **options) -> BoatParams:
    """The parameters of a registered boat; ``options`` go to its factory (e.g. l_phi)."""
    try:
        factory = BOATS[name]
    except KeyError:
        raise ValueError(f"unknown boat {name!r}; known boats: {', '.join(sorted(BOATS))}") from None
    try:
        return factory(**options)
    except TypeError as err:
        raise ValueError(f"bad option for boat {name!r}: {err}") from None
