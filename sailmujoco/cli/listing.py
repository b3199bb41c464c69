"""``sailmujoco list``: what there is to run, one line each.

Boats (waterline length, mass, and the first sentence of their factory's docstring, which names
the source), tasks and controllers (the first sentence of their docstrings), worlds and
studies. Controllers are found as a sweep finds them (:func:`sailmujoco.sweep.controller_factories`:
the ``sailmujoco.controllers`` entry points and the names registered in this process); a
controller named by its import path is not listed, as it needs no registration.
"""

from __future__ import annotations

import re

from ..options import World, choices

SECTIONS = ("boats", "tasks", "worlds", "controllers", "studies")
WORLD_TEXT = {
    "mujoco": "the 6-DOF MuJoCo boat: every force model at every RK4 stage",
    "paper": "the paper's reduced model: Wille's 4-DOF equations with the boat's parameters, or "
             "Viel's 3-DOF model for position_keeping",
}
HEADINGS = {"boats": "boats (waterline length, mass, source)", "controllers": "controllers (also: "
            "'module:factory' or 'file.py:factory')"}
WIDTH = 110  # characters of a description before it is cut with "..."


def first_sentence(doc: str | None) -> str:
    """The first sentence of a docstring's first paragraph, on one line ("" without one).

    Parameters
    ----------
    doc : str or None
        The docstring.
    """
    paragraph = " ".join((doc or "").strip().split("\n\n")[0].replace("``", "").split())
    found = re.match(r"(.*?[.])(?=\s+[A-Z]|$)", paragraph)
    text = found.group(1) if found else paragraph
    return text if len(text) <= WIDTH else text[:WIDTH - 3].rstrip() + "..."


def boat_lines() -> dict[str, str]:
    """name -> "<waterline length> m  <mass> kg  <first sentence of the factory's docstring>"."""
    from ..boat.catalogue import BOATS, get_boat

    lines = {}
    for name, factory in BOATS.items():
        params = get_boat(name)
        lines[name] = (f"{params.hull.length:5.2f} m {params.mass:6g} kg  "
                       f"{first_sentence(factory.__doc__)}")
    return lines


def task_lines() -> dict[str, str]:
    """name -> the first sentence of the task's docstring."""
    from ..suite import TASKS

    return {name: first_sentence(cls.__doc__) for name, cls in TASKS.items()}


def controller_lines() -> dict[str, str]:
    """name -> the first sentence of the factory's docstring (or why it does not load)."""
    from ..sweep import controller_factories

    lines = {}
    for name, entry in sorted(controller_factories().items()):
        try:
            lines[name] = first_sentence(entry.load().__doc__)
        except Exception as err:  # a broken entry point of another package: say so, list the rest
            lines[name] = f"(does not load: {type(err).__name__}: {err})"
    return lines


def study_lines() -> dict[str, str]:
    """name -> the study's title."""
    from .study import study_titles

    return study_titles()


def world_lines() -> dict[str, str]:
    """name -> what the world simulates."""
    return {name: WORLD_TEXT.get(name, "") for name in choices(World)}


def listing(sections=SECTIONS) -> str:
    """The text of ``sailmujoco list``: a heading per section, one line per name.

    Parameters
    ----------
    sections : iterable of str
        Which of :data:`SECTIONS`, in the order given.

    Returns
    -------
    str
    """
    makers = {"boats": boat_lines, "tasks": task_lines, "worlds": world_lines,
              "controllers": controller_lines, "studies": study_lines}
    parts = []
    for section in sections:
        lines = makers[section]()
        width = max((len(n) for n in lines), default=0)
        rows = [f"  {n:{width}s}  {t}".rstrip() for n, t in lines.items()]
        parts.append(f"{HEADINGS.get(section, section)}:\n" + "\n".join(rows))
    return "\n\n".join(parts)


def run_cli(args) -> int:
    """The ``list`` sub-command.

    Parameters
    ----------
    args : argparse.Namespace
        ``what``: a section of :data:`SECTIONS`, or None for all of them.

    Returns
    -------
    int
        0.
    """
    print(listing([args.what] if args.what else SECTIONS))
    return 0
