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
added_mass_coupling  "manoeuvring",          --   no forward-speed added-mass terms in heave and
                     "kirchhoff"                  pitch; "kirchhoff": the unbounded-fluid terms
vertical_damping     "world", "body"         --   heave and pitch damping on the vertical
                                                  motion; "body": on body w and q
restoring_axes       "horizontal", "body"    --   the papers' restoring moments about level
                                                  axes; "body": about body axes
resistance           "dsyhs", "friction"     --   ITTC friction plus the Delft series'
                                                  residuary resistance; "friction": Wille
                                                  eq. 15 alone
foils                "finite", "paper"       --   finite-wing lift slope and 3-D post-stall;
                                                  "paper": Saoud's sail polynomial and Wille
                                                  eq. 23 on the 2-D table
keel_downwash        True, False             --   the keel's downwash at the rudder
windage              True, False             --   air drag of topsides and mast
wave_hull            True, False             --   in a sea, the waves' forces on the hull
                                                  (their pressure, diffraction and the
                                                  damping relative to the water); False:
                                                  the hull in still water, the sea at the
                                                  foils alone
wave_foil_flow       True, False             --   in a sea, the waves' orbital velocity in the
                                                  keel's and rudder's flow; False: the foils
                                                  in still water (or the current)
wave_diffraction     True, False             --   in a sea, the hull's added mass times the
                                                  water's acceleration (long-wave diffraction)
wave_damping         "relative", "absolute"  --   in a sea, heave and pitch damping on the
                                                  motion relative to the water; "absolute":
                                                  on the hull's own motion
wave_pressure_decay  True, False             --   in a sea, the wave's pressure decaying with
                                                  depth as e^(kz) (Froude-Krylov); False:
                                                  hydrostatic to the local surface
boat_options         a mapping               SI   keyword arguments of the boat's parameter
                                                  factory (e.g. ``{"l_phi": 0.1}``)
waves                None, a ``WaveConfig``  SI   the sea (:mod:`sailmujoco.forces.waves`);
                     or a mapping of its          None or ``hs = 0``: calm water. A mapping
                     fields                       may give ``direction_from_deg`` (deg)
==================== ======================= ==== ===========================================

The first choice listed is the default: the boat as built. The other forms are the papers'
forms or the forms a model replaced, kept so that their effect can be measured (the force
modules' docstrings give the reasons and sources). The MuJoCo world reads every option but
``paper_model``. Wille's 4-DOF paper world (:mod:`sailmujoco.reference.wille`) reads
``paper_model``, the on/off switches of the five force models and ``sail_tangential``, and
keeps the papers' forms of the rest; Viel's paper world reads none. All are checked in every
world. ``world`` ("mujoco", "paper") is :func:`sailmujoco.suite.load`'s third argument. The
paper worlds are calm water, as in the papers: they ignore ``waves``; in the MuJoCo world the
6-DOF boat feels the sea (docs/physics.md, "The boat in the sea"), and ``dofs=4`` refuses one.
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

from .forces.waves import WaveConfig
from .names import check_known

World = Literal["mujoco", "paper"]
SailMode = Literal["actuated", "sheeted"]
Dofs = Literal[6, 4]
PaperModel = Literal["paper", "rigid"]
# the order is the kernel's code for the mode (forces/boat.py packs its index)
Hydrostatics = Literal["off", "paper", "geometric"]
AddedMassCoupling = Literal["manoeuvring", "kirchhoff"]  # heave/pitch forward-speed terms out / in
VerticalDamping = Literal["world", "body"]  # heave/pitch damping on vertical motion / body w, q
RestoringAxes = Literal["horizontal", "body"]  # paper restoring moments about level / body axes
Resistance = Literal["friction", "dsyhs"]  # ITTC friction only (Wille eq. 15) / + DSYHS residuary
Foils = Literal["paper", "finite"]  # the papers' foil coefficients / finite-wing slope and stall
WaveDamping = Literal["relative", "absolute"]  # in a sea: damping on motion relative to the water / own


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
    added_mass_coupling : {"manoeuvring", "kirchhoff"}
        Without, or with, the forward-speed added-mass terms in heave and pitch.
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
    wave_hull, wave_foil_flow, wave_diffraction, wave_pressure_decay : bool
        The sea's mechanisms (in calm water they change nothing): the waves' forces on the
        hull (False: the hull in still water); the orbital velocity at the foils; the
        long-wave diffraction force; the dynamic pressure's decay with depth
        (docs/physics.md, "The boat in the sea").
    wave_damping : {"relative", "absolute"}
        In a sea, heave and pitch damping on the motion relative to the water, or on the
        hull's own.
    """

    hydrostatics: Hydrostatics = "geometric"
    sail: bool = True
    keel: bool = True
    rudder: bool = True
    damping: bool = True
    added_mass: bool = True
    sail_tangential: bool = True
    added_mass_coupling: AddedMassCoupling = "manoeuvring"
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

    def __post_init__(self):
        _check_fields(self)


@dataclass(frozen=True)
class PhysicsOptions(ForceSwitches):
    """Every physics option of an environment: the force switches, the boat as built and the
    paper world's model (the table of :mod:`sailmujoco.options`). The defaults are the boat as
    built in the MuJoCo world.

    Parameters
    ----------
    hydrostatics, sail, keel, rudder, damping, added_mass, sail_tangential
        As :class:`ForceSwitches`.
    added_mass_coupling, vertical_damping, restoring_axes, resistance, foils
        As :class:`ForceSwitches`.
    keel_downwash, windage : bool
        As :class:`ForceSwitches`.
    wave_hull, wave_foil_flow, wave_diffraction, wave_damping, wave_pressure_decay
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
    """

    sail_mode: SailMode = "actuated"
    dofs: Dofs = 6
    paper_model: PaperModel = "paper"
    boat_options: Mapping = field(default_factory=dict, hash=False)
    waves: WaveConfig | None = None

    def __post_init__(self):
        _check_fields(self)
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
