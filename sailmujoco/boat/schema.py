"""The boat file's keys (unit, meaning, accepted range) and reading a boat file back.

A boat file is TOML with one section per parameter type: ``[boat]`` (:class:`BoatParams`'s own
numbers), ``[hull]`` (:class:`~sailmujoco.boat.hull.HullShape`), ``[keel]`` and ``[rudder]``
(:class:`~sailmujoco.boat.params.Foil`), ``[sail]`` (:class:`~sailmujoco.boat.params.Sail`), an
optional ``[headsail]`` (:class:`~sailmujoco.boat.params.Headsail`), an optional ``[crew]``
(:class:`~sailmujoco.boat.params.Crew`), the optional ``[sensors]``
and ``[actuators]`` (the boat as fitted, :mod:`sailmujoco.boat.fitted_file`) and an optional
``[sources]`` table of notes. Every number is SI, angles in radians; arrays are
TOML arrays. :func:`read_boat` refuses a bad file with one line per problem, each naming the
file, the section and the key. Writing one: :mod:`sailmujoco.boat.file`.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass
from pathlib import Path

from ..names import nearest, unknown_message
from ..tomlfile import read_toml
from .fitted_file import FITTED, read_fitted
from .hull import HullShape
from .params import BoatParams, Crew, Foil, Headsail, Sail


@dataclass(frozen=True)
class Key:
    """One key of a boat file.

    Parameters
    ----------
    name : str
        The dataclass field it fills.
    unit : str
        Its unit ("-": dimensionless).
    meaning : str
        What it is, in a few words.
    low, high : float or None
        Accepted range (None: unbounded on that side).
    open_low : bool
        ``low`` itself is refused (a positive number when ``low`` is 0).
    length : int
        0 for a number; n for an array of n numbers.
    choices : tuple of str
        The accepted strings of a text key (empty: a number, or the boat's name).
    required : bool
        The key must be given (otherwise its dataclass default is taken).
    """

    name: str
    unit: str
    meaning: str
    low: float | None = None
    high: float | None = None
    open_low: bool = False
    length: int = 0
    choices: tuple = ()
    required: bool = True


def _positive(name, unit, meaning, **kw):
    return Key(name, unit, meaning, low=0.0, open_low=True, **kw)


def _at_least_0(name, unit, meaning, **kw):
    return Key(name, unit, meaning, low=0.0, **kw)


def _real(name, unit, meaning, **kw):
    return Key(name, unit, meaning, **kw)


def _foil(rudder: bool) -> tuple:
    moving = {"low": 0.0, "open_low": rudder, "required": rudder}
    return (
        _positive("area", "m^2", "planform area A"),
        _positive("aspect_ratio", "-", "Asp = span^2 / A"),
        Key("thickness_ratio", "-", "t_max / c of the NACA section", low=0.0, open_low=True, high=1.0),
        _real("x", "m", "centre of pressure forward of CO"),
        _real("z", "m", "centre of pressure above the waterline (below: negative)"),
        Key("mass", "kg", "mass of the moving blade (0 for a keel: part of the hull)", **moving),
        Key("max_angle", "rad", "deflection limit sigma_sat", high=math.pi, **moving),
        Key("time_constant", "s", "first-order actuator lag T_sigma", **moving),
    )


KEYS: dict[str, tuple[Key, ...]] = {
    "boat": (
        Key("name", "-", "the boat's name (an identifier); a built-in boat's name picks its scene"),
        _positive("mass", "kg", "total mass: hull, rudder, boom and sail"),
        _positive("inertia", "kg m^2", "(Ixx, Iyy, Izz) about the CG, body axes", length=3),
        _real("inertia_xz", "kg m^2", "I_xz about the CG, SNAME sign"),
        _real("cg_x", "m", "CG forward of CO (CO: on the waterline, midship)"),
        _real("cg_z", "m", "CG above the waterline (below: negative)"),
        Key("added_mass", "kg, kg, kg, kg m^2, kg m^2, kg m^2",
            "SNAME (X_udot, Y_vdot, Z_wdot, K_pdot, M_qdot, N_rdot), each <= 0", high=0.0, length=6),
        _positive("gm_t", "m", "transverse metacentric height (the reduced models' righting)"),
        _positive("wetted_surface", "m^2", "hull wetted surface S_H (Wille eq. 15 friction)"),
        _at_least_0("form_factor", "-", "form factor k (Wille eq. 15)"),
        _at_least_0("linear_damping", "kg/s, kg/s, N s/m, N m s/rad, N m s/rad",
                    "(d11, d22, d33, d55, d66): surge, sway, heave, pitch, yaw (Wille eq. 13)",
                    length=5),
        _at_least_0("roll_friction", "N m s/rad", "B_F0 (Wille eq. 19)"),
        _at_least_0("roll_lift", "kg m/rad", "B_L (Wille eq. 19)"),
        _positive("roll_frequency", "rad/s", "omega_roll_n (Wille eq. 19)"),
        _at_least_0("crossflow_cd", "-", "2-D drag coefficient of the hull sections (Wille eqs. 17-18)"),
        _positive("rho_water", "kg/m^3", "water density", required=False),
        _positive("rho_air", "kg/m^3", "air density", required=False),
        _positive("nu_water", "m^2/s", "kinematic viscosity of water", required=False),
        _positive("nu_air", "m^2/s", "kinematic viscosity of air", required=False),
        Key("paper_righting", "-", "the reduced models' righting moment: 'sin_cos' (Wille eq. 20) "
            "or 'sin' (Saoud eq. 4)", choices=("sin_cos", "sin"), required=False),
    ),
    "hull": (
        _positive("length", "m", "waterline length L"),
        _positive("half_beam", "m", "midship waterline half-breadth b0"),
        _positive("canoe_draft", "m", "depth t0 of the canoe body below the waterline"),
        _positive("freeboard", "m", "height of the flat deck above the waterline"),
        _positive("deck_half_beam", "m", "midship deck half-breadth, >= half_beam (absent: no flare)",
                  required=False),
    ),
    "keel": _foil(rudder=False),
    "rudder": _foil(rudder=True),
    "sail": (
        _positive("area", "m^2", "sail area"),
        _positive("aspect_ratio", "-", "luff^2 / area"),
        _real("mast_x", "m", "mast forward of CO"),
        _positive("ce_aft", "m", "centre of effort behind the mast along the boom (Wille's l2)"),
        _positive("ce_height", "m", "centre of effort above the waterline (Wille's h1)"),
        _positive("mass", "kg", "mass of the boom and sail (the part that turns)"),
        Key("max_angle", "rad", "sail angle limit lambda_sat", low=0.0, open_low=True, high=math.pi),
        _positive("time_constant", "s", "first-order lag T_lambda of the sail servo or sheet"),
        Key("suction_efficiency", "-", "share of the ideal leading-edge suction recovered",
            low=0.0, high=1.0, required=False),
        Key("suction_stall", "rad", "angle of attack past which the suction collapses",
            low=0.0, open_low=True, high=0.5 * math.pi, required=False),
        _at_least_0("friction_coefficient", "-", "skin friction coefficient per face",
                    required=False),
        Key("camber", "-", "camber ratio f/c of the rig's sails (0: flat plates)", low=0.0, high=0.25,
            required=False),
    ),
}
"""Section -> its keys, in the order of the dataclass fields they fill."""

OPTIONAL_KEYS: dict[str, tuple[Key, ...]] = {
    "headsail": (
        _at_least_0("area", "m^2", "sail area (0: no headsail)"),
        _positive("luff_height", "m", "height of the head above the tack"),
        _at_least_0("head_aft", "m", "the head behind the tack (the forestay's run, J for a masthead rig)"),
        _real("tack_x", "m", "the tack (the forestay's foot) forward of CO"),
        _real("tack_height", "m", "the tack above the waterline"),
        Key("min_angle", "rad", "smallest sheeting angle |delta| (the sheet's lead)", low=0.0, high=math.pi),
        Key("max_angle", "rad", "largest sheeting angle |delta|", low=0.0, open_low=True, high=math.pi),
    ),
    "crew": (
        _at_least_0("mass", "kg", "the crew's mass, on top of the boat's (0: no crew)"),
        _at_least_0("arm", "m", "the crew's centre of mass off the centreline on the weather rail"),
        _real("height", "m", "the crew's centre of mass above the waterline"),
        _real("x", "m", "the crew's centre of mass forward of CO"),
        _positive("shift_time", "s", "the time the crew takes to cross from rail to rail in a tack"),
    ),
}
"""The sections a boat may leave out (the boat then has none of that part)."""

SECTION_MEANING = {
    "boat": "the boat as a whole: mass, inertia, added mass, damping, fluids",
    "hull": "the canoe body (sailmujoco.boat.hull): parabolic planform, half-elliptic sections",
    "keel": "the keel, a fixed symmetric foil, part of the hull",
    "rudder": "the rudder, a balanced foil turning about a vertical stock through its CP",
    "sail": "the mainsail: a triangle on a boom turning about the mast, flat unless cambered",
    "headsail": "a headsail on the forestay, sheeted to the deck, trimmed to follow the main",
    "crew": "the crew as movable ballast on the weather rail, crossing when the boom crosses",
}
SECTION_TYPES = {"boat": BoatParams, "hull": HullShape, "keel": Foil, "rudder": Foil, "sail": Sail,
                 "headsail": Headsail, "crew": Crew}
"""Section -> the dataclass it fills."""
SOURCES = "sources"  # the optional table of notes


def is_boat_file(boat) -> bool:
    """Whether ``boat`` names a boat file (a path object, or a string ending in ``.toml``).

    Parameters
    ----------
    boat : object
        A boat argument (a registered name, a path, or parameters).
    """
    return isinstance(boat, os.PathLike) or (isinstance(boat, str) and boat.endswith(".toml"))


def read_boat(path) -> BoatParams:
    """The boat in the file at ``path``.

    Parameters
    ----------
    path : str or os.PathLike
        A boat file (:mod:`sailmujoco.boat.file` writes one).

    Returns
    -------
    BoatParams
        ``sources`` holds the file's ``[sources]`` table and each key's source comment.

    Raises
    ------
    ValueError
        One line per problem (unknown, missing or mistyped key, value out of range, missing
        section), each naming the file, the section and the key.
    """
    path = Path(path)
    data = read_toml(path, "boat file")
    params = boat_from_dict(data, str(path))
    return params.with_(sources={**params.sources, **comment_sources(path.read_text())})


def boat_from_dict(data: dict, where: str = "boat file") -> BoatParams:
    """A :class:`BoatParams` from a boat file's parsed tables.

    Parameters
    ----------
    data : dict
        The sections (``tomllib``'s result).
    where : str
        The file, for the messages.

    Returns
    -------
    BoatParams
    """
    if not any(isinstance(data.get(section), dict) for section in KEYS):
        raise ValueError(f"{where} is not a boat file: it has none of the sections "
                         f"{', '.join(f'[{s}]' for s in KEYS)} (`sailmujoco boat export` writes one)")
    known = [*KEYS, *OPTIONAL_KEYS, *FITTED, SOURCES]
    problems = [unknown_message("section", name, known, f"boat file {where}")
                for name in data if name not in known]
    values = {}
    for section, keys in KEYS.items():
        table = data.get(section)
        if not isinstance(table, dict):
            problems.append(f"{where}: missing section [{section}] ({SECTION_MEANING[section]})"
                            if table is None else f"{where}: [{section}] must be a table, got {table!r}")
            continue
        values[section], found = _section(table, keys, f"{where}: [{section}]")
        problems += found
    for section, keys in OPTIONAL_KEYS.items():
        table = data.get(section)
        if table is None:
            continue
        if not isinstance(table, dict):
            problems.append(f"{where}: [{section}] must be a table, got {table!r}")
            continue
        values[section], found = _section(table, keys, f"{where}: [{section}]")
        problems += found
    fitted, found = read_fitted(data, where)
    problems += found
    notes = data.get(SOURCES, {})
    if not isinstance(notes, dict) or not all(isinstance(v, str) for v in notes.values()):
        problems.append(f"{where}: [{SOURCES}] must be a table of strings")
    if problems:
        raise ValueError("\n".join(problems))
    return _build(values, fitted, dict(notes), where)


def _section(table: dict, keys: tuple, where: str) -> tuple[dict, list]:
    """(the values of one section by key, the problems found); ``where`` is ``file: [section]``."""
    by_name = {k.name: k for k in keys}
    unknown = [name for name in table if name not in by_name]
    problems = [unknown_message("key", name, by_name, where.replace(":", "", 1)) for name in unknown]
    misspelt = {nearest(name, by_name) for name in unknown}  # said once, as the unknown key
    values = {}
    for key in keys:
        if key.name not in table:
            if key.required and key.name not in misspelt:
                problems.append(f"{where} missing key {key.name!r} ({key.meaning}, {_unit(key)})")
            continue
        value, problem = _value(key, table[key.name])
        if problem:
            problems.append(f"{where} {key.name} {problem}")
        values[key.name] = value
    return values, problems


def _value(key: Key, raw):
    """(the value as the dataclass holds it, or None; a problem, or None)."""
    if key.choices:
        if raw not in key.choices:
            return None, f"must be one of {', '.join(map(repr, key.choices))}, got {raw!r}"
        return raw, None
    if key.name == "name":
        if not isinstance(raw, str) or not raw.isidentifier():
            return None, f"must be an identifier (letters, digits, _), got {raw!r}"
        return raw, None
    items = raw if key.length else [raw]
    if key.length and (not isinstance(raw, list) or len(raw) != key.length):
        return None, f"must be {_wanted(key)}, got {raw!r}"
    if not all(_is_number(v) for v in items):
        return None, f"must be {_wanted(key)}, got {raw!r}"
    numbers = tuple(float(v) for v in items)
    if not all(_in_range(key, v) for v in numbers):
        return None, f"must be {_wanted(key)}, got {raw!r}{_degrees_hint(key, numbers)}"
    return (numbers if key.length else numbers[0]), None


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _in_range(key: Key, v: float) -> bool:
    if key.low is not None and (v < key.low or (key.open_low and v == key.low)):
        return False
    return key.high is None or v <= key.high


def _unit(key: Key) -> str:
    return "dimensionless" if key.unit == "-" else f"in {key.unit}"


def _wanted(key: Key) -> str:
    """``a positive number in m^2``, ``3 numbers >= 0 in kg m^2``, ..."""
    if key.low == 0.0 and key.open_low and key.high is None:
        kind = "positive number"
    elif key.low is not None and key.high is not None:
        kind = f"number in {'(' if key.open_low else '['}{key.low:g}, {key.high:.6g}]"
    elif key.low is not None:
        kind = f"number >= {key.low:g}"
    elif key.high is not None:
        kind = f"number <= {key.high:g}"
    else:
        kind = "finite number"
    article = "an" if kind[0] in "aeiou" else "a"
    count = f"an array of {key.length} {kind}s" if key.length else f"{article} {kind}"
    return f"{count} {_unit(key)}"


def _degrees_hint(key: Key, numbers) -> str:
    """A hint when an angle in radians was given in degrees."""
    if key.unit == "rad" and any(v > math.pi for v in numbers):
        return f" (degrees? {numbers[0]:g} deg is {math.radians(numbers[0]):.6g} rad)"
    return ""


def _build(values: dict, fitted: dict, notes: dict, where: str) -> BoatParams:
    """The dataclasses from checked values and the fitted sections' figures; their own checks'
    errors name the file and section."""
    parts = {}
    for section in ("hull", "keel", "rudder", "sail", *(s for s in OPTIONAL_KEYS if s in values)):
        try:
            parts[section] = SECTION_TYPES[section](**values[section])
        except ValueError as err:
            raise ValueError(f"{where}: [{section}] {err}") from None
    try:
        return BoatParams(**values["boat"], **parts, **fitted, sources=notes)
    except ValueError as err:
        raise ValueError(f"{where}: [boat] {err}") from None


_SECTION_LINE = re.compile(r"^\s*\[([A-Za-z0-9_]+)\]")
_SOURCE_COMMENT = re.compile(r"^\s*([A-Za-z0-9_]+)\s*=.*#\s*\[[^\]]*\]\s*(.+?)\s*$")


def comment_sources(text: str) -> dict:
    """``{"<section>.<key>": source}`` from the comments ``key = value  # [unit] source``.

    Parameters
    ----------
    text : str
        A boat file's text.
    """
    sources, section = {}, ""
    for line in text.splitlines():
        header = _SECTION_LINE.match(line)
        if header:
            section = header.group(1)
            continue
        found = _SOURCE_COMMENT.match(line)
        if found and (section in KEYS or section in FITTED):
            sources[f"{section}.{found.group(1)}"] = found.group(2)
    return sources
