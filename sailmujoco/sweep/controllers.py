"""Controllers by name: the ``sailmujoco.controllers`` entry points, so the library never
imports a controller. A factory is ``factory(env, **options) -> controller``."""

from __future__ import annotations

import inspect
from importlib import metadata

from ..names import check_known
from .errors import SweepError

ENTRY_POINTS = "sailmujoco.controllers"


def controller_factories() -> dict:
    """name -> entry point of every registered controller factory."""
    return {ep.name: ep for ep in metadata.entry_points(group=ENTRY_POINTS)}


def factory_options(factory) -> tuple | None:
    """The option names ``factory`` takes by keyword (less ``env``, ``self`` and ``seed``), or
    None when it takes any (``**options``).

    Parameters
    ----------
    factory : callable
        A controller factory (or any function whose keywords are options).
    """
    parameters = inspect.signature(factory).parameters.values()
    if any(p.kind is p.VAR_KEYWORD for p in parameters):
        return None
    return tuple(p.name for p in parameters if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
                 and p.name not in ("self", "seed", "env"))


def controller_factory(name: str):
    """The factory of the registered controller ``name``; an unknown name refuses in one line
    with the nearest registered one.

    Parameters
    ----------
    name : str
        A registered controller (:func:`controller_factories`).
    """
    factories = controller_factories()
    check_known([name], factories, "the registered controllers", kind="controller", error=SweepError)
    return factories[name].load()


def make_controller(name: str, env, **options):
    """Build the controller ``name`` for ``env``.

    Parameters
    ----------
    name : str
        A registered controller (:func:`controller_factories`).
    env : SailEnvironment
        The environment it controls (its factory reads the boat and the action spec).
    **options
        The factory's options; a name it does not take refuses in one line with the nearest.
    """
    factory = controller_factory(name)
    accepted = factory_options(factory)
    if accepted is not None:
        check_known(options, accepted, f"controller {name!r}", error=SweepError)
    return factory(env, **options)
