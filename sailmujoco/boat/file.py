"""Boat files: a boat's parameters as commented TOML, written and read back exactly.

``sailmujoco boat export NAME --out my_boat.toml`` (or :func:`write_boat`) writes a boat, every
key with its unit and source; edit it, then give the file wherever a boat name goes:
``suite.load("my_boat.toml", "heading_hold")``, ``--boat my_boat.toml``, ``boat =
"my_boat.toml"`` in a sweep file. The keys, their units and accepted ranges are in
:data:`sailmujoco.boat.schema.KEYS`. Floats are written with ``repr``, so a boat written and
read back equals the original (``==``) and sails bit for bit like it.
"""

from __future__ import annotations

import json
import math
from dataclasses import fields
from pathlib import Path

from .catalogue import BUILT_IN, get_boat
from .fitted_file import FITTED, fitted_lines
from .params import BoatParams
from .schema import KEYS, OPTIONAL_KEYS, SECTION_MEANING, SECTION_TYPES, SOURCES, Key
from .sources import SOURCES as BUILT_IN_SOURCES

__all__ = ["boat_toml", "name_clash", "write_boat"]

HEADER = """\
# {name}: a sailmujoco boat file.
# Give it wherever a boat name goes: suite.load("FILE", "heading_hold"), --boat FILE, or
# boat = "FILE" in a sweep file; `sailmujoco boat check FILE` reports its stability, periods
# and speeds. SI units, angles in radians; positions in the body frame: CO on the waterline
# midship, x forward, y port, z up. Each key: value  # [unit] source. An optional key may be
# left out (its default is taken).
"""


def boat_toml(params: BoatParams, name: str | None = None) -> str:
    """The boat file of ``params``: commented TOML, one section per parameter type.

    Parameters
    ----------
    params : BoatParams
        The boat.
    name : str, optional
        The name written (default ``params.name``).

    Returns
    -------
    str
        The file's text; :func:`read_boat` of it equals ``params``.
    """
    name = params.name if name is None else name
    reference = get_boat(params.name) if params.name in BUILT_IN else None
    lines = [HEADER.format(name=name).rstrip("\n")]
    for section, keys in KEYS.items():
        holder = params if section == "boat" else getattr(params, section)
        ref_holder = None if reference is None else (
            reference if section == "boat" else getattr(reference, section))
        lines += ["", f"[{section}]  # {SECTION_MEANING[section]}"]
        for key in keys:
            value = name if key.name == "name" else getattr(holder, key.name)
            lines += _key_lines(section, key, value,
                                _source(params, section, key.name, value, ref_holder))
    for section, keys in OPTIONAL_KEYS.items():
        holder = getattr(params, section)
        if holder is None:
            continue
        lines += ["", f"[{section}]  # {SECTION_MEANING[section]}"]
        for key in keys:
            value = getattr(holder, key.name)
            lines += _key_lines(section, key, value, _source(params, section, key.name, value, None))
    for section in FITTED:
        lines += fitted_lines(getattr(params, section), section, params.sources)
    notes = {k: str(v) for k, v in params.sources.items() if "." not in str(k)}
    if notes:
        lines += ["", f"[{SOURCES}]  # notes on the boat as a whole"]
        lines += [f"{_toml_key(k)} = {_toml_string(v)}" for k, v in notes.items()]
    return "\n".join(lines) + "\n"


def write_boat(params_or_name, path) -> Path:
    """Write a boat file.

    Parameters
    ----------
    params_or_name : BoatParams or str
        The boat: its parameters, a registered name (built as by default) or a boat file.
    path : str or os.PathLike
        The file written.

    Returns
    -------
    Path
        ``path``.
    """
    params = params_or_name if isinstance(params_or_name, BoatParams) else get_boat(params_or_name)
    path = Path(path)
    path.write_text(boat_toml(params))
    return path


def name_clash(params: BoatParams, where) -> str | None:
    """The warning for a boat file that keeps a built-in boat's name but not its parameters.

    A copy of a shipped boat's file, edited, still says ``name = "saoud_robot"``: its model,
    its check and its figures then carry the built-in boat's name for another boat.

    Parameters
    ----------
    params : BoatParams
        The boat read from the file.
    where : str or os.PathLike
        The file, named in the warning.

    Returns
    -------
    str or None
        One line, or ``None`` where the name is no built-in boat's or the parameters are the
        built-in boat's as built by default (an unedited export).
    """
    if params.name not in BUILT_IN or params == get_boat(params.name):
        return None
    own = Path(where).stem if Path(where).stem.isidentifier() else "my_boat"
    return (f"warning: {where}: name = {_toml_string(params.name)} is a built-in boat's, but the "
            f"parameters differ from it; give the boat a name of its own (e.g. name = {_toml_string(own)})")


def _source(params: BoatParams, section: str, key: str, value, ref_holder) -> str:
    """A key's source: the boat's own note, else the built-in boat's where the value is its."""
    own = params.sources.get(f"{section}.{key}")
    if own:
        return str(own)
    if ref_holder is None or key == "name":
        return ""
    if getattr(ref_holder, key) != value:
        return f"differs from the built-in {params.name}"
    return BUILT_IN_SOURCES.get(params.name, {}).get(f"{section}.{key}", "")


def _key_lines(section: str, key: Key, value, source: str) -> list[str]:
    """The comment line and the ``key = value  # [unit] source`` line of one key."""
    meaning = f"# {key.meaning}"
    if not key.required:
        default = {f.name: f.default for f in fields(SECTION_TYPES[section])}[key.name]
        meaning += f"; optional (default {_toml_value(default) if default is not None else 'none'})"
    if value is None:  # an optional key without a value (deck_half_beam)
        return [meaning, f"# {key.name} = (left out)"]
    unit = key.unit if key.unit != "rad" else f"rad = {math.degrees(value):.6g} deg"
    line = f"{key.name} = {_toml_value(value)}  # [{unit}]"
    return [meaning, f"{line} {source}" if source else line]


def _toml_value(value) -> str:
    if isinstance(value, str):
        return _toml_string(value)
    if isinstance(value, (tuple, list)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    return repr(float(value))  # repr: the shortest text that reads back to the same float


def _toml_string(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)  # a JSON string is a TOML basic string


def _toml_key(key) -> str:
    key = str(key)
    return key if key.replace("_", "").replace("-", "").isalnum() else _toml_string(key)
