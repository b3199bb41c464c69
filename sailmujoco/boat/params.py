"""The types of a boat's parameters: frozen dataclasses in SI units (foil, sail, boat).

Positions are in the body frame of :mod:`sailmujoco.frames` (origin CO on the waterline
midship, x forward, y port, z up). Added-mass derivatives keep the SNAME sign (negative).
The boats themselves, every number with its source, are in :mod:`sailmujoco.boat.catalogue`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np

from .. import constants as c
from .fitted import ActuatorOptions, SensorOptions, actuator_options, sensor_options
from .hull import HullShape


def _check_positive(obj, names):
    for name in names:
        value = getattr(obj, name)
        if not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0.0:
            raise ValueError(
                f"{type(obj).__name__}.{name} must be a positive finite number, got {value!r}")


def _check_finite(obj, names, low: float | None = None):
    """Each of ``names`` a finite number (and ``>= low`` where ``low`` is given)."""
    for name in names:
        value = getattr(obj, name)
        below = low is not None and isinstance(value, (int, float)) and value < low
        if not isinstance(value, (int, float)) or not math.isfinite(value) or below:
            bound = "" if low is None else f" >= {low:g}"
            raise ValueError(f"{type(obj).__name__}.{name} must be a finite number{bound}, got {value!r}")


@dataclass(frozen=True)
class Foil:
    """A keel or rudder: a symmetric NACA section of finite span.

    ``x``, ``z`` locate the centre of pressure (CP) in the body frame at zero deflection; a
    rudder turns about a vertical stock through its CP (a balanced rudder: no hinge moment).

    Parameters
    ----------
    area : float
        Planform area A, m^2.
    aspect_ratio : float
        Asp = span^2 / A, dimensionless.
    thickness_ratio : float
        t_max / c of the section, dimensionless.
    x : float
        CP forward of CO, m.
    z : float
        CP height above the waterline (negative: below), m.
    mass : float
        Mass of a moving foil (rudder blade), kg; 0 for a keel (part of the hull).
    max_angle : float
        Deflection saturation (rudder sigma_sat), rad.
    time_constant : float
        First-order actuator lag (rudder T_sigma), s.
    """

    area: float
    aspect_ratio: float
    thickness_ratio: float
    x: float
    z: float
    mass: float = 0.0
    max_angle: float = 0.0
    time_constant: float = 0.0

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
    third of the luff above the boom). The last three fields shape the tangential-force model
    of the flat sail (:func:`sailmujoco.forces.sail.sail_coefficients`).

    Parameters
    ----------
    area : float
        Sail area, m^2.
    aspect_ratio : float
        luff^2 / area, dimensionless.
    mast_x : float
        Mast position forward of CO, m.
    ce_aft : float
        CE behind the mast along the boom (Wille's l2), m.
    ce_height : float
        CE above the waterline (Wille's h1), m.
    mass : float
        Mass of the boom and sail (the part that turns), kg.
    max_angle : float
        Sail angle saturation lambda_sat, rad.
    time_constant : float
        T_lambda, first-order lag of the actuated sail / the sheet, s.
    suction_efficiency : float
        Share of the ideal leading-edge suction recovered, dimensionless.
    suction_stall : float
        Angle of attack past which the suction collapses, rad.
    friction_coefficient : float
        Skin friction coefficient per face (turbulent flat plate), dimensionless.
    camber : float
        Camber ratio f (depth / chord) of the rig's sails, main and headsail, dimensionless; 0: flat
        plates, the papers' sail (:mod:`sailmujoco.forces.sail_camber`).
    """

    area: float
    aspect_ratio: float
    mast_x: float
    ce_aft: float
    ce_height: float
    mass: float
    max_angle: float
    time_constant: float
    suction_efficiency: float = 0.3
    suction_stall: float = math.radians(15.0)
    friction_coefficient: float = 0.005
    camber: float = 0.0

    def __post_init__(self):
        _check_positive(self, ("area", "aspect_ratio", "ce_aft", "ce_height", "mass",
                               "max_angle", "time_constant"))
        if not (isinstance(self.camber, (int, float)) and 0.0 <= self.camber <= 0.25):
            raise ValueError(f"Sail.camber must be a camber ratio in [0, 0.25], got {self.camber!r}")

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
class Headsail:
    """A flat triangular headsail (a jib) on the forestay, ahead of the main.

    Its luff runs up the forestay from the tack to the head, ``head_aft`` behind the tack and
    ``luff_height`` above it; its foot is horizontal, from the tack to the clew. It turns about
    the vertical through its tack by the angle delta (0: clew straight aft, positive: clew to
    +y, port, as the main's lambda). Its sheet leads to the deck, so its load goes to the hull:
    it has no hinge of its own. Unless a controller sheets it, delta follows the main by the
    trim rule of :func:`sailmujoco.forces.headsail.headsail_angle`: the main's angle, held
    between ``min_angle`` (the sheet's lead) and ``max_angle``. Its force has the main's
    coefficients (:func:`sailmujoco.forces.sail.sail_force`) at its own aspect ratio.

    Parameters
    ----------
    area : float
        Sail area, m^2; 0: no headsail (the boat sails as with its main alone, bit for bit).
    luff_height : float
        Height of the head above the tack, m.
    head_aft : float
        The head's distance behind the tack (the forestay's run), m.
    tack_x : float
        The tack (the forestay's foot) forward of CO, m.
    tack_height : float
        The tack above the waterline, m.
    min_angle : float
        The smallest |delta| the sheet's lead allows, rad.
    max_angle : float
        The largest |delta|, rad.
    """

    area: float
    luff_height: float
    head_aft: float
    tack_x: float
    tack_height: float
    min_angle: float
    max_angle: float

    def __post_init__(self):
        _check_finite(self, ("area", "head_aft", "min_angle"), low=0.0)
        _check_positive(self, ("luff_height", "max_angle"))
        if not self.min_angle <= self.max_angle <= math.pi:
            raise ValueError(f"Headsail angles need 0 <= min_angle <= max_angle <= pi, got "
                             f"{self.min_angle!r}, {self.max_angle!r}")

    @property
    def foot(self) -> float:
        """Tack to clew, m (area = foot x luff_height / 2)."""
        return 2.0 * self.area / self.luff_height

    @property
    def aspect_ratio(self) -> float:
        """luff_height^2 / area, -."""
        return self.luff_height**2 / self.area if self.area > 0.0 else 0.0

    @property
    def ce_aft(self) -> float:
        """The centroid's distance behind the tack along the foot's line, m."""
        return (self.head_aft + self.foot) / 3.0

    @property
    def ce_height(self) -> float:
        """The centroid above the waterline, m."""
        return self.tack_height + self.luff_height / 3.0

    @property
    def section_chord(self) -> float:
        """The sail's chord at its centroid's height (2/3 of the foot), m; the centroid lies at its middle."""
        return 2.0 * self.foot / 3.0


@dataclass(frozen=True)
class Crew:
    """The crew as movable ballast: a mass that sits on the weather rail and crosses in a tack.

    The crew's mass rides a slide across the deck (the body y axis) at ``x`` and ``height``; it
    is the model's last joint (:mod:`sailmujoco.boat.mjcf`). The crew sits on the side opposite
    the boom, the weather side, ``arm`` from the centreline; when the boom crosses, it crosses
    at a steady walk that takes ``shift_time`` from rail to rail
    (:mod:`sailmujoco.forces.crew`). On the rail its weight rights the boat by
    m g arm cos(heel) more than on the centreline.

    Parameters
    ----------
    mass : float
        The crew's mass, kg (on top of the boat's ``mass``); 0: no crew (the boat bit for bit).
    arm : float
        The crew's centre of mass off the centreline on the rail, m.
    height : float
        The crew's centre of mass above the waterline, m.
    x : float
        The crew's centre of mass forward of CO, m.
    shift_time : float
        The time the crew takes to cross from rail to rail (a steady walk of 2 arm / shift_time), s.
    """

    mass: float
    arm: float
    height: float
    x: float
    shift_time: float

    def __post_init__(self):
        _check_finite(self, ("mass", "arm"), low=0.0)
        _check_positive(self, ("shift_time",))
        _check_finite(self, ("height", "x"))


@dataclass(frozen=True)
class BoatParams:
    """Everything the MJCF builder, the force models and the reduced models need.

    Equation numbers are Wille (2016a)'s.

    Parameters
    ----------
    name : str
        The boat's name (the MJCF model's name and file name).
    mass : float
        Total mass (hull + rudder + boom/sail), kg.
    inertia : tuple of float
        (Ixx, Iyy, Izz) about the CG, body axes, kg m^2.
    inertia_xz : float
        SNAME I_xz, kg m^2 (MuJoCo's fullinertia ixz takes it unchanged in FLU).
    cg_x : float
        CG forward of CO, m.
    cg_z : float
        CG above the waterline, m.
    hull : HullShape
        The canoe body.
    added_mass : tuple of float
        SNAME derivatives (X_udot, Y_vdot, Z_wdot, K_pdot, M_qdot, N_rdot), <= 0; kg for the
        translations, kg m^2 for the rotations.
    gm_t : float
        Transverse metacentric height (paper value the hull is designed to), m.
    wetted_surface : float
        Hull wetted surface S_H of eq. 15, m^2.
    form_factor : float
        Form factor k of eq. 15, dimensionless.
    linear_damping : tuple of float
        (d11, d22, d33, d55, d66) of eq. 13 (d33, d55 ours): surge, sway, heave (N s/m), pitch and
    yaw (N m s/rad).
    roll_friction : float
        B_F0 of eq. 19, N m s/rad.
    roll_lift : float
        B_L of eq. 19, kg m / rad.
    roll_frequency : float
        omega_roll_n of eq. 19, rad/s.
    crossflow_cd : float
        2-D drag coefficient of the hull sections, eqs. 17-18, dimensionless.
    keel, rudder : Foil
        The appendages.
    sail : Sail
        The mainsail.
    rho_water, rho_air : float
        Densities, kg/m^3.
    nu_water, nu_air : float
        Kinematic viscosities, m^2/s.
    paper_righting : {"sin_cos", "sin"}
        The reduced models' righting moment: eq. 20 (Wille) or Saoud eq. 4.
    sensors : SensorOptions, str or dict
        The instruments a controller reads through
        (:func:`sailmujoco.boat.fitted.sensor_options`: a preset's name or a dict
        of figures is made into one); default ``perfect``. A task's own ``sensors=`` overrides it.
    actuators : ActuatorOptions, str or dict
        The servos the commands go through (:func:`sailmujoco.boat.fitted.actuator_options`);
        default ``perfect``. A task's own ``actuators=`` overrides it.
    headsail : Headsail or None
        A headsail beside the main (None: the main alone).
    crew : Crew or None
        The crew as movable ballast (None: no crew; ``mass`` is then the whole boat afloat).
    sources : dict
        Field -> where its number comes from (not compared).
    """

    name: str
    mass: float
    inertia: tuple[float, float, float]
    inertia_xz: float
    cg_x: float
    cg_z: float
    hull: HullShape
    added_mass: tuple[float, float, float, float, float, float]
    gm_t: float
    wetted_surface: float
    form_factor: float
    linear_damping: tuple[float, float, float, float, float]
    roll_friction: float
    roll_lift: float
    roll_frequency: float
    crossflow_cd: float
    keel: Foil
    rudder: Foil
    sail: Sail
    rho_water: float = c.RHO_WATER
    rho_air: float = c.RHO_AIR_WILLE
    nu_water: float = c.NU_WATER
    nu_air: float = c.NU_AIR
    paper_righting: str = "sin_cos"
    sensors: SensorOptions = SensorOptions()
    actuators: ActuatorOptions = ActuatorOptions()
    headsail: Headsail | None = None
    crew: Crew | None = None
    sources: dict = field(default_factory=dict, compare=False, hash=False)

    def __post_init__(self):
        object.__setattr__(self, "sensors", sensor_options(self.sensors))  # a preset or a dict: made one
        object.__setattr__(self, "actuators", actuator_options(self.actuators))
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
    def carries_headsail(self) -> bool:
        """Whether the boat has a headsail of some area (one of zero area is no headsail)."""
        return self.headsail is not None and self.headsail.area > 0.0

    @property
    def carries_crew(self) -> bool:
        """Whether the boat carries a crew of some mass (one of zero mass is no crew)."""
        return self.crew is not None and self.crew.mass > 0.0

    @property
    def displaced_volume(self) -> float:
        """Design displacement, m^3 (weight = buoyancy)."""
        return self.mass / self.rho_water

    @property
    def added_mass_diagonal(self) -> np.ndarray:
        """Positive added masses (-X_udot, -Y_vdot, -Z_wdot, -K_pdot, -M_qdot, -N_rdot)."""
        return -np.asarray(self.added_mass, dtype=float)

    def with_(self, **changes) -> BoatParams:
        """A copy with some fields changed (validated again).

        Parameters
        ----------
        **changes
            New values of :class:`BoatParams` fields by name; an unknown name raises a ValueError.
        """
        unknown = set(changes) - {f.name for f in fields(self)}
        if unknown:
            raise ValueError(f"unknown BoatParams field(s) {sorted(unknown)}")
        return replace(self, **changes)
