"""A boat file's ``[sensors]`` and ``[actuators]`` sections: the instruments a controller reads
through and the servos its commands go through, as fitted to this boat.

Both sections are optional; a file without them has ``perfect`` ones (every reading the true
value, every command passed on unchanged), as the papers assume. A section holds any figures
of :class:`~sailmujoco.boat.fitted.SensorOptions` or :class:`~sailmujoco.boat.fitted.ActuatorOptions`,
over ``perfect`` or over the preset its ``preset`` key names::

    [sensors]
    preset = "typical"
    compass_noise_deg = 4.0  # [deg] our compass's datasheet

``boat export`` writes every figure with its unit and the source of its value; a task's own
``sensors=`` and ``actuators=`` (or a sweep's ``sensors.*`` keys) override the file's, and a
dict of figures given there without ``preset`` is over the file's figures.
"""

from __future__ import annotations

from dataclasses import fields

from . import fitted

__all__ = ["FITTED", "fitted_lines", "fitted_summary", "read_fitted"]

FITTED = {
    "sensors": ("the instruments the controller reads through (sailmujoco.boat.fitted); optional, "
                "left out: perfect", fitted.SENSOR_FIGURES, fitted.SENSOR_PRESETS, fitted.sensor_options),
    "actuators": ("the servos the commands go through (sailmujoco.boat.fitted); optional, left out: "
                  "perfect", fitted.ACTUATOR_FIGURES, fitted.ACTUATOR_PRESETS, fitted.actuator_options),
}
"""Section -> (its meaning, figure -> (unit, meaning, typical source), its presets, the function
that makes its figures object)."""


def read_fitted(data: dict, where: str) -> tuple[dict, list[str]]:
    """The figures objects of a boat file's fitted sections, and the problems found.

    Parameters
    ----------
    data : dict
        The boat file's parsed tables.
    where : str
        The file, for the messages.

    Returns
    -------
    tuple
        (``{"sensors": SensorOptions, "actuators": ActuatorOptions}`` for the sections given,
        one line per problem, each naming the file and the section's key).
    """
    values, problems = {}, []
    for section, (meaning, _, _, make) in FITTED.items():
        table = data.get(section)
        if table is None:
            continue
        if not isinstance(table, dict):
            problems.append(f"{where}: [{section}] must be a table ({meaning}), got {table!r}")
            continue
        try:
            values[section] = make(table)
        except ValueError as err:
            problems.append(f"{where}: [{section}] {err}")
    return values, problems


def fitted_lines(figures, section: str, sources: dict) -> list[str]:
    """A fitted section as boat file lines: every figure with its unit and source.

    Parameters
    ----------
    figures : SensorOptions or ActuatorOptions
        The section's figures.
    section : {"sensors", "actuators"}
        Which section.
    sources : dict
        The boat's own notes (``"<section>.<figure>"`` -> source), taken before the preset's.
    """
    meaning, table, presets, _ = FITTED[section]
    typical = presets["typical"]
    lines = ["", f"[{section}]  # {meaning}",
             '# a preset\'s figures, then any figure over them: preset = "perfect" or "typical"']
    for f in fields(figures):
        unit, what, typical_source = table[f.name]
        value = getattr(figures, f.name)
        source = sources.get(f"{section}.{f.name}") or (
            typical_source if not figures.perfect and value == getattr(typical, f.name) else "")
        text = ("true" if value else "false") if isinstance(value, bool) else repr(float(value))
        line = f"{f.name} = {text}  # [{unit}]"
        lines += [f"# {what}", f"{line} {source}" if source else line]
    return lines


def fitted_summary(figures, section: str) -> str:
    """One line of a fitted section's figures: ``perfect``, or each figure that acts, with its
    unit (``gnss_cep 2.5 m, gnss_rate_hz 5 Hz, ...``).

    Parameters
    ----------
    figures : SensorOptions or ActuatorOptions
        The section's figures.
    section : {"sensors", "actuators"}
        Which section.
    """
    if figures.perfect:
        return ("perfect (every reading the true value)" if section == "sensors"
                else "perfect (every command passed on unchanged)")
    table = FITTED[section][1]
    parts = []
    for f in fields(figures):
        value = getattr(figures, f.name)
        if f.name == "perfect" or value is False or value == 0:
            continue
        unit = table[f.name][0]
        parts.append(f.name if value is True else
                     f"{f.name} {value:g}" + ("" if unit == "-" else f" {unit}"))
    return ", ".join(parts) or "none acts (every figure 0)"
