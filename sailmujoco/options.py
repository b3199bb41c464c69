"""The physics options of an environment: each set of choices defined once, as a ``Literal``.

Everything that offers these choices (``suite.load``, the sweep files' ``env.`` keys, their
checks and messages) reads them from here: :func:`choices` gives a ``Literal``'s values as a
tuple, :func:`literal_fields` the fields of a dataclass that take one.

==================== ======================= ==== ===========================================
option               choices (default first) unit what it is; what the other forms are for
==================== ======================= ==== ===========================================
sail_mode            "actuated", "sheeted"   --   the action's sail command: an angle (rad);
                                                  "sheeted": a sheet length (m), the boom
                                                  swinging free up to the angle it allows
dofs                 6, 4                    --   the hull free; 4: heave and pitch held, as in
                                                  Wille's and Saoud's reduced models
paper_model          "paper", "rigid"        --   the Wille 4-DOF paper world with eq. 4 as
                                                  printed; "rigid": rigid-hull yaw kinematics
                                                  (:mod:`sailmujoco.reference.wille`)
hydrostatics         "geometric", "paper",   --   buoyancy integrated over the hull's columns;
                     "off"                        "paper": the papers' restoring moment and
                                                  linear heave and pitch springs; "off": none
sail, keel, rudder,  True, False             --   each force model on; off to see the others
damping, added_mass                               alone
sail_tangential      True, False             --   the sail's tangential force C_T; False makes
                                                  Saoud's Assumption 4 true
added_mass_coupling  "impulse",              --   heave added mass's velocity terms: forces
                     "manoeuvring",               (no mean), no Munk moments; "manoeuvring":
                     "kirchhoff"                  none; "kirchhoff": all (unbounded fluid)
vertical_damping     "world", "body"         --   heave and pitch damping on the vertical
                                                  motion; "body": on body w and q
restoring_axes       "horizontal", "body"    --   the papers' restoring moments about level
                                                  axes; "body": about body axes
resistance           "dsyhs", "friction"     --   friction plus the Delft series' residuary
                                                  resistance; "friction": Wille eq. 15 alone
foils                "finite", "paper"       --   finite-wing lift slope and 3-D post-stall;
                                                  "paper": Saoud's sail polynomial and Wille
                                                  eq. 23 on the 2-D table
keel_downwash        True, False             --   the keel's downwash at the rudder
windage              True, False             --   air drag of topsides and mast
wave_hull            True, False             --   in a sea, the waves' forces on the hull
                                                  (pressure, diffraction, relative damping);
                                                  False: still water at the hull alone
wave_foil_flow       True, False             --   in a sea, the orbital velocity at keel and
                                                  rudder; False: still water (or the current)
wave_diffraction     True, False             --   in a sea, the hull's added mass times the
                                                  water's acceleration (long-wave diffraction)
wave_damping         "relative", "absolute"  --   in a sea, heave and pitch damping on the
                                                  motion relative to the water; "absolute":
                                                  on the hull's own motion
wave_pressure_decay  True, False             --   in a sea, the wave's pressure decaying with
                                                  depth as e^(kz) (Froude-Krylov); False:
                                                  hydrostatic to the local surface
wave_reflection      True, False             --   in a sea, short waves' mean reflection
                                                  force on the hull's side (Faltinsen)
rig_interaction      "lumped_vortex", "none" --   with a headsail: the sails in each other's
                                                  flow; "none": each alone, the rig their sum
boat_options         a mapping               SI   keyword arguments of the boat's parameter
                                                  factory (e.g. ``{"l_phi": 0.1}``)
waves                None, a ``WaveConfig``  SI   the sea (:mod:`sailmujoco.forces.waves`);
                     or a mapping of its          None or ``hs = 0``: calm water. A mapping
                     fields                       may give ``direction_from_deg`` (deg)
timestep             None, a time > 0        s    the physics step; None: the world's own
==================== ======================= ==== ===========================================

The first choice listed is the default: the boat as built. The other forms are the papers' forms or the
forms a model replaced, kept so that their effect can be measured (the force modules' docstrings give
the reasons and sources). The MuJoCo world reads every option but ``paper_model``. Wille's 4-DOF paper
world (:mod:`sailmujoco.reference.wille`) reads ``paper_model``, the on/off switches of the five force
models and ``sail_tangential``, and keeps the papers' forms of the rest; Viel's paper world reads none
of them. Every world reads ``timestep`` (:mod:`sailmujoco.step.timing`). All are checked in every world.
``world`` ("mujoco", "paper") is :func:`sailmujoco.suite.load`'s third argument. The paper worlds are
calm water, as in the papers: they ignore ``waves``; in the MuJoCo world the 6-DOF boat feels the sea
(docs/physics.md, "The boat in the sea"), and ``dofs=4`` refuses one.
"""

from __future__ import annotations

import dataclasses
import functools
import math
import typing
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from .constants import GRAVITY
from .names import check_known
from .step.timing import check_timestep

World = Literal["mujoco", "paper"]
SailMode = Literal["actuated", "sheeted"]
Dofs = Literal[6, 4]
PaperModel = Literal["paper", "rigid"]
# the order is the kernel's code for the mode (forces/boat.py packs its index)
Hydrostatics = Literal["off", "paper", "geometric"]
AddedMassCoupling = Literal["impulse", "manoeuvring", "kirchhoff"]  # heave/pitch couplings (added_mass.py)
VerticalDamping = Literal["world", "body"]  # heave/pitch damping on vertical motion / body w, q
RestoringAxes = Literal["horizontal", "body"]  # paper restoring moments about level / body axes
Resistance = Literal["friction", "dsyhs"]  # ITTC friction only (Wille eq. 15) / + DSYHS residuary
Foils = Literal["paper", "finite"]  # the papers' foil coefficients / finite-wing slope and stall
WaveDamping = Literal["relative", "absolute"]  # in a sea: damping on motion relative to the water / own
RigInteraction = Literal["lumped_vortex", "none"]  # with a headsail: the sails' mutual flow / each alone


# ---- the sea state ----------------------------------------------------------------------
Spectrum = Literal["regular", "pm", "jonswap"]
SPECTRA = typing.get_args(Spectrum)
SEA_KINDS = ("fully_developed", "fetch_limited")
N_COMPONENTS = 16  # -, default number of components (the cost and the error: docs/physics.md)
GAMMA_RANGE = (1.0, 7.0)  # -, JONSWAP gamma, DNV-RP-C205 §3.5.5
MAX_WIND = 100.0  # m/s, U10 for a wind-raised sea, as WindConfig.speed
U19_5_PER_U10 = 1.026  # -, Stewart (2008) eq. 16.29
PM_HS = 0.21  # -, g Hs / U19.5^2 of a fully developed sea, Stewart (2008) eq. 16.33
PM_PEAK = 0.877  # -, omega_p U19.5 / g of a fully developed sea, Stewart (2008) eq. 16.30
FETCH_HS = 1.6e-3  # -, g Hs/U10^2 = 1.6e-3 chi^(1/2), Shore Protection Manual (1984) eq. 3-33
FETCH_TP = 0.2857  # -, g Tp/U10 = 0.2857 chi^(1/3), Shore Protection Manual (1984) eq. 3-34


def _finite(name: str, value, unit: str) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"WaveConfig.{name} must be a finite number{unit}, got {value!r}")


@dataclass(frozen=True)
class WaveConfig:
    """A sea state: spectrum, height, period, direction, spreading and seed. SI, radians.

    ``hs = 0`` is calm water.

    Parameters
    ----------
    spectrum : {"regular", "pm", "jonswap"}
        ``"regular"``: one Airy wave; ``"pm"``: Pierson-Moskowitz; ``"jonswap"``: JONSWAP.
    hs : float
        Significant wave height Hs = 4 sqrt(m0), m, >= 0; for ``"regular"`` the crest-to-trough
        height H.
    tp : float
        Peak period, s, > 0; for ``"regular"`` the period T.
    direction_from : float
        Compass bearing the waves come from, rad (0: from the north, travelling south).
    gamma : float
        JONSWAP peak enhancement factor, in [1, 7] (read by ``"jonswap"`` only).
    spreading : float or None
        None: long-crested (every component travels the mean direction); s > 0: each
        component's direction drawn from cos^(2s)((theta - theta_0)/2). Not for ``"regular"``.
    n_components : int
        Number of components of a spectral sea, >= 1.
    seed : int
        Seeds the frequencies, phases and directions, >= 0.
    """

    spectrum: Spectrum = "jonswap"
    hs: float = 0.0
    tp: float = 6.0
    direction_from: float = 0.0
    gamma: float = 3.3
    spreading: float | None = None
    n_components: int = N_COMPONENTS
    seed: int = 0

    def __post_init__(self):
        check_known([self.spectrum], SPECTRA, "WaveConfig.spectrum", kind="spectrum")
        _finite("hs", self.hs, " (m)")
        if self.hs < 0.0:
            raise ValueError(f"WaveConfig.hs must be >= 0 m, got {self.hs!r}")
        _finite("tp", self.tp, " (s)")
        if self.tp <= 0.0:
            raise ValueError(f"WaveConfig.tp must be > 0 s, got {self.tp!r}")
        _finite("direction_from", self.direction_from, " (rad)")
        _finite("gamma", self.gamma, "")
        if not GAMMA_RANGE[0] <= self.gamma <= GAMMA_RANGE[1]:
            raise ValueError(f"WaveConfig.gamma must be in [1, 7], got {self.gamma!r}")
        if self.spreading is not None:
            _finite("spreading", self.spreading, " or None")
            if self.spreading <= 0.0:
                raise ValueError(f"WaveConfig.spreading must be > 0 or None, got {self.spreading!r}")
            if self.spectrum == "regular":
                raise ValueError("WaveConfig.spreading must be None for spectrum 'regular' "
                                 f"(a regular wave is long-crested), got {self.spreading!r}")
        for name, low in (("n_components", 1), ("seed", 0)):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
                raise ValueError(f"WaveConfig.{name} must be an integer >= {low}, got {value!r}")

    @classmethod
    def from_wind(cls, u10: float, kind: str = "fully_developed", fetch: float | None = None,
                  direction_from: float = 0.0, *, spreading: float | None = None,
                  n_components: int = N_COMPONENTS, seed: int = 0) -> WaveConfig:
        """The sea a steady wind raises: fully developed (Pierson-Moskowitz) or fetch-limited.

        ``"fully_developed"``: a ``"pm"`` sea with Hs = 0.21 U19.5^2/g, omega_p = 0.877 g/U19.5,
        U19.5 = 1.026 U10 (Pierson & Moskowitz 1964; Stewart 2008 eqs. 16.29-16.33).
        ``"fetch_limited"``: a ``"jonswap"`` sea (gamma 3.3) with Hs = 1.6e-3 chi^(1/2) U10^2/g,
        Tp = 0.2857 chi^(1/3) U10/g, chi = g F/U10^2 (Hasselmann et al. 1973; Shore Protection
        Manual 1984 eqs. 3-33, 3-34), each at most its fully developed value. See
        :mod:`sailmujoco.forces.wave_spectra`. No wind (``u10 = 0``) is calm water.

        Parameters
        ----------
        u10 : float
            Mean wind speed at 10 m, m/s, in [0, 100] (``WindConfig.speed``).
        kind : {"fully_developed", "fetch_limited"}
            Which growth stage.
        fetch : float or None
            Fetch, m, > 0, for ``"fetch_limited"``; None for ``"fully_developed"``.
        direction_from : float
            Compass bearing the wind and the waves come from, rad.
        spreading, n_components, seed
            As :class:`WaveConfig`.
        """
        check_known([kind], SEA_KINDS, "WaveConfig.from_wind", kind="kind")
        if isinstance(u10, bool) or not isinstance(u10, (int, float)) or \
                not 0.0 <= u10 <= MAX_WIND:
            raise ValueError(f"WaveConfig.from_wind: u10 must be in [0, {MAX_WIND:g}] m/s, got {u10!r}")
        if kind == "fully_developed" and fetch is not None:
            raise ValueError(f"WaveConfig.from_wind: fetch must be None for a fully developed sea, "
                             f"got {fetch!r}")
        if kind == "fetch_limited" and (isinstance(fetch, bool) or not isinstance(fetch, (int, float))
                                        or not math.isfinite(fetch) or fetch <= 0.0):
            raise ValueError(f"WaveConfig.from_wind: fetch must be > 0 m for a fetch-limited sea, "
                             f"got {fetch!r}")
        spectrum = "pm" if kind == "fully_developed" else "jonswap"
        common = dict(spectrum=spectrum, direction_from=direction_from, spreading=spreading,
                      n_components=n_components, seed=seed)
        if u10 == 0.0:
            return cls(hs=0.0, **common)
        hs, tp = fully_developed_sea(u10) if kind == "fully_developed" else fetch_limited_sea(u10, fetch)
        return cls(hs=hs, tp=tp, **common)


def fully_developed_sea(u10: float) -> tuple[float, float]:
    """(Hs m, Tp s) of a fully developed sea in a wind U10 (Pierson & Moskowitz 1964).

    Hs = 0.21 U19.5^2/g, Tp = 2 pi U19.5/(0.877 g), U19.5 = 1.026 U10 (Stewart 2008
    eqs. 16.29, 16.30, 16.33).

    Parameters
    ----------
    u10 : float
        Mean wind speed at 10 m, m/s, > 0.
    """
    u = U19_5_PER_U10 * u10
    return PM_HS * u**2 / GRAVITY, 2.0 * math.pi * u / (PM_PEAK * GRAVITY)


def fetch_limited_sea(u10: float, fetch: float) -> tuple[float, float]:
    """(Hs m, Tp s) of a fetch-limited sea (JONSWAP growth laws), capped at full development.

    chi = g F/U10^2, Hs = 1.6e-3 chi^(1/2) U10^2/g, Tp = 0.2857 chi^(1/3) U10/g (Hasselmann
    et al. 1973, as the Shore Protection Manual 1984 eqs. 3-33 and 3-34 write them), each
    at most its value from :func:`fully_developed_sea`.

    Parameters
    ----------
    u10 : float
        Mean wind speed at 10 m, m/s, > 0.
    fetch : float
        Fetch, the distance the wind has blown over open water, m, > 0.
    """
    g = GRAVITY
    chi = g * fetch / u10**2
    hs_full, tp_full = fully_developed_sea(u10)
    hs = FETCH_HS * math.sqrt(chi) * u10**2 / g
    tp = FETCH_TP * chi ** (1.0 / 3.0) * u10 / g
    return min(hs, hs_full), min(tp, tp_full)


def choices(literal) -> tuple:
    """The values a ``Literal`` allows, in the order it names them.

    Parameters
    ----------
    literal : typing.Literal
        One of this module's sets of choices (e.g. :data:`Hydrostatics`).
    """
    return typing.get_args(literal)


@functools.cache
def literal_fields(cls) -> dict:
    """``{field name: choices}`` of the fields of dataclass ``cls`` annotated with a ``Literal``.

    Parameters
    ----------
    cls : type
        A dataclass whose annotations name this module's ``Literal`` types.
    """
    hints = typing.get_type_hints(cls)
    return {f.name: choices(hints[f.name]) for f in dataclasses.fields(cls)
            if typing.get_origin(hints[f.name]) is Literal}


@functools.cache
def _flag_fields(cls) -> tuple:
    hints = typing.get_type_hints(cls)
    return tuple(f.name for f in dataclasses.fields(cls) if hints[f.name] is bool)


def _check_fields(options) -> None:
    """One line for the first field of ``options`` outside its choices, or not True/False."""
    for name, allowed in literal_fields(type(options)).items():
        value = getattr(options, name)
        if isinstance(value, bool) or value not in allowed:
            raise ValueError(f"unknown {name} {value!r}; choose one of {allowed}")
    for name in _flag_fields(type(options)):
        value = getattr(options, name)
        if not isinstance(value, bool | np.bool_):
            raise ValueError(f"{name} must be True or False, got {value!r}")


@dataclass(frozen=True)
class ForceSwitches:
    """Which force models act, and in which form (the table of :mod:`sailmujoco.options`).

    Parameters
    ----------
    hydrostatics : {"geometric", "paper", "off"}
        Buoyancy from the hull's geometry, the papers' restoring terms, or none.
    sail, keel, rudder, damping, added_mass : bool
        Each force model on (default) or off.
    sail_tangential : bool
        The sail's tangential force C_T (False: Saoud's Assumption 4 made true).
    added_mass_coupling : {"impulse", "manoeuvring", "kirchhoff"}
        Heave added mass's velocity terms: forces but no Munk moments, none, or all.
    vertical_damping : {"world", "body"}
        Heave and pitch damping on the vertical motion, or on body w and q.
    restoring_axes : {"horizontal", "body"}
        The papers' restoring moments about level axes, or about body axes.
    resistance : {"dsyhs", "friction"}
        Friction plus the Delft series' residuary resistance, or friction alone (Wille eq. 15).
    foils : {"finite", "paper"}
        Finite-wing lift slope and 3-D post-stall, or the papers' foil coefficients.
    keel_downwash : bool
        The keel's downwash at the rudder.
    windage : bool
        Air drag of topsides and mast.
    wave_hull, wave_foil_flow, wave_diffraction, wave_pressure_decay, wave_reflection : bool
        The sea's mechanisms (in calm water they change nothing): the waves' forces on the
        hull (False: the hull in still water); the orbital velocity at the foils; the long-wave
        diffraction; the pressure's decay with depth; the short waves' reflection (docs/physics.md).
    wave_damping : {"relative", "absolute"}
        In a sea, heave and pitch damping on the motion relative to the water, or on the
        hull's own.
    rig_interaction : {"lumped_vortex", "none"}
        With a headsail, the sails in each other's flow or each alone (forces/headsail.py).
    """

    hydrostatics: Hydrostatics = "geometric"
    sail: bool = True
    keel: bool = True
    rudder: bool = True
    damping: bool = True
    added_mass: bool = True
    sail_tangential: bool = True
    added_mass_coupling: AddedMassCoupling = "impulse"
    vertical_damping: VerticalDamping = "world"
    restoring_axes: RestoringAxes = "horizontal"
    resistance: Resistance = "dsyhs"
    foils: Foils = "finite"
    keel_downwash: bool = True
    windage: bool = True
    wave_hull: bool = True
    wave_foil_flow: bool = True
    wave_diffraction: bool = True
    wave_damping: WaveDamping = "relative"
    wave_pressure_decay: bool = True
    wave_reflection: bool = True
    rig_interaction: RigInteraction = "lumped_vortex"

    def __post_init__(self):
        _check_fields(self)


@dataclass(frozen=True)
class PhysicsOptions(ForceSwitches):
    """Every physics option of an environment: the force switches, the boat as built and the
    paper world's model (the table of :mod:`sailmujoco.options`). The defaults are the boat as
    built in the MuJoCo world.

    Parameters
    ----------
    hydrostatics, sail, keel, rudder, damping, added_mass, sail_tangential, rig_interaction
        As :class:`ForceSwitches`.
    added_mass_coupling, vertical_damping, restoring_axes, resistance, foils, keel_downwash, windage
        As :class:`ForceSwitches`.
    wave_hull, wave_foil_flow, wave_diffraction, wave_damping, wave_pressure_decay, wave_reflection
        As :class:`ForceSwitches`.
    sail_mode : {"actuated", "sheeted"}
        The sail command: an angle in rad, or a sheet length in m.
    dofs : {6, 4}
        The hull free, or heave and pitch held.
    paper_model : {"paper", "rigid"}
        The Wille 4-DOF paper world as printed, or with rigid-hull yaw kinematics.
    boat_options : mapping or None
        Keyword arguments of the boat's parameter factory (e.g. ``{"l_phi": 0.1}``).
    waves : WaveConfig, mapping or None
        The sea (:func:`wave_config`); None: calm water. Ignored by the paper worlds.
    timestep : float or None
        The integration step, s, > 0 (:mod:`sailmujoco.step.timing`); None: the world's own.
    """

    sail_mode: SailMode = "actuated"
    dofs: Dofs = 6
    paper_model: PaperModel = "paper"
    boat_options: Mapping = field(default_factory=dict, hash=False)
    waves: WaveConfig | None = None
    timestep: float | None = None

    def __post_init__(self):
        _check_fields(self)
        object.__setattr__(self, "timestep", check_timestep(self.timestep))
        if self.boat_options is None:
            object.__setattr__(self, "boat_options", {})
        if not isinstance(self.boat_options, Mapping) or not all(
                isinstance(k, str) for k in self.boat_options):
            raise ValueError(f"boat_options must be a mapping of option names to values, "
                             f"got {self.boat_options!r}")
        object.__setattr__(self, "boat_options", dict(self.boat_options))
        object.__setattr__(self, "waves", wave_config(self.waves))

    @property
    def forces(self) -> ForceSwitches:
        """The force switches among these options."""
        return ForceSwitches(**{name: getattr(self, name) for name in FORCE_FIELDS})

    @classmethod
    def from_value(cls, value, where: str) -> PhysicsOptions:
        """Physics options from None (the defaults), a ``PhysicsOptions``, or a dict of its fields.

        Parameters
        ----------
        value : None, PhysicsOptions or dict
            The options as given.
        where : str
            Where they were given, for the message naming an unknown key.
        """
        if value is None:
            return cls()
        if isinstance(value, cls):
            return value
        if not isinstance(value, Mapping):
            raise ValueError(f"physics options in {where} must be a PhysicsOptions or a dict of its "
                             f"fields, got {value!r}")
        check_known(value, PHYSICS_FIELDS, where)
        return cls(**value)


FORCE_FIELDS = tuple(f.name for f in dataclasses.fields(ForceSwitches))
PHYSICS_FIELDS = tuple(f.name for f in dataclasses.fields(PhysicsOptions))


# the sea's options by name (a sweep's ``waves.`` keys): WaveConfig's fields, the direction in degrees
WAVE_OPTIONS = tuple(f.name for f in dataclasses.fields(WaveConfig) if f.name != "direction_from") + (
    "direction_from_deg",)


def wave_config(value, where: str = "waves") -> WaveConfig | None:
    """A sea state from None, a ``WaveConfig`` or a mapping of its fields.

    A mapping may give the direction the waves come from in degrees, ``direction_from_deg``
    (compass bearing), instead of ``direction_from`` in radians.

    Parameters
    ----------
    value : None, WaveConfig or mapping
        The sea as given.
    where : str
        Where it was given, for the message naming an unknown key.
    """
    if value is None or isinstance(value, WaveConfig):
        return value
    if not isinstance(value, Mapping):
        raise ValueError(f"waves must be a WaveConfig, a mapping of its fields or None, got {value!r}")
    check_known(value, (*WAVE_OPTIONS, "direction_from"), where, kind="waves option")
    value = dict(value)
    if "direction_from_deg" in value:
        deg = value.pop("direction_from_deg")
        if "direction_from" in value:
            raise ValueError("waves: give direction_from (rad) or direction_from_deg, not both")
        if isinstance(deg, bool) or not isinstance(deg, (int, float)) or not math.isfinite(deg):
            raise ValueError(f"waves.direction_from_deg must be a finite number (deg), got {deg!r}")
        value["direction_from"] = math.radians(deg)
    return WaveConfig(**value)


def check_sea(waves, dofs: int) -> None:
    """One line unless ``waves`` is None or a WaveConfig the boat can feel (``hs > 0``: 6 DOF).

    Parameters
    ----------
    waves : object
        The ``waves`` given.
    dofs : int
        The boat's degrees of freedom (6, or 4 with heave and pitch held).
    """
    if waves is not None and not isinstance(waves, WaveConfig):
        raise ValueError(f"waves must be a WaveConfig or None, got {waves!r}")
    if waves is not None and waves.hs > 0.0 and dofs != 6:
        raise ValueError("waves need the 6-DOF boat (dofs=6): dofs=4 holds heave and pitch")
