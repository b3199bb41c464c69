"""The types of a boat's parameters: frozen dataclasses in SI units (foil, sail, boat).

Positions are in the body frame of :mod:`sailmujoco.frames` (origin CO on the waterline
midship, x forward, y port, z up). Added-mass derivatives keep the SNAME sign (negative).
The boats themselves, every number with its source, are in :mod:`sailmujoco.boats`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np

from . import constants as c
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
