"""Option values of the right kind: a flag true or false, a number finite, text a string.

The kind of an option is the kind of its default (a factory's keyword default, or the physics
options' default), so a sweep file, ``make_controller`` and ``--set`` refuse ``kp = "two"`` in
one line before anything runs, instead of failing deep inside the first step.
"""

from __future__ import annotations

import inspect
import math

from .errors import SweepError


def signature_defaults(fn) -> dict:
    """``{name: (default, None allowed)}`` of ``fn``'s parameters that have a default.

    Parameters
    ----------
    fn : callable
        A factory (or any function whose keywords are options).
    """
    return {name: (p.default, p.default is None or "None" in str(p.annotation))
            for name, p in inspect.signature(fn).parameters.items() if p.default is not p.empty}


def check_kinds(namespace: str, options: dict, defaults: dict, where: str = "") -> None:
    """Each option of the kind its default has: true/false for a flag, a finite number for a
    number, text for text; one line naming the first that is not.

    Parameters
    ----------
    namespace : str
        Where the options go, for the message (``"env"``, ``"controller"``).
    options : dict
        The options given.
    defaults : dict
        ``name -> (default, None allowed)`` (:func:`signature_defaults`).
    where : str
        Appended to the message (``", in sweep file 'x.toml'"``).
    """
    for name, value in options.items():
        if name not in defaults:
            continue
        default, none_ok = defaults[name]
        if value is None and none_ok:
            continue
        if isinstance(default, bool):
            ok, kind = isinstance(value, bool), "true or false"
        elif isinstance(default, (int, float)):
            ok = (isinstance(value, (int, float)) and not isinstance(value, bool)
                  and math.isfinite(value))
            kind = "a finite number"
        elif isinstance(default, str):
            ok, kind = isinstance(value, str), "a string"
        else:
            continue
        if not ok:
            raise SweepError(f"{namespace}.{name} = {value!r}: must be {kind}{where}")
