"""Unknown names, refused in one line: the name, where it was given, the nearest accepted one.

Every place that takes names from a user (``suite.load``'s keywords, a controller's options, a
sweep file's keys, the command line's ``--set``) checks them here, so a misspelling reads the
same everywhere::

    unknown option 'hydrostatic' in suite.load; did you mean 'hydrostatics'? (accepted: dofs, ...)
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class UnknownName(ValueError):
    """A name that is not among the accepted ones; the message is one line."""


def nearest(name: str, accepted: Iterable[str]) -> str | None:
    """The accepted name closest to ``name`` (``difflib``'s ratio, at least 0.6), or None.

    Parameters
    ----------
    name : str
        The name given.
    accepted : iterable of str
        The names accepted there.
    """
    close = difflib.get_close_matches(str(name), [str(a) for a in accepted], n=1, cutoff=0.6)
    return close[0] if close else None


def unknown_message(kind: str, name: str, accepted: Iterable[str], where: str) -> str:
    """One line: ``unknown <kind> '<name>' in <where>; did you mean '<nearest>'? (accepted: ...)``.

    Parameters
    ----------
    kind : str
        What the name is (``"option"``, ``"controller"``, ``"key"``).
    name : str
        The name given.
    accepted : iterable of str
        The names accepted there.
    where : str
        Where it was given (``"suite.load"``, ``"controller 'pid'"``, ``"sweep file x.toml"``).
    """
    accepted = sorted(str(a) for a in accepted)
    guess = nearest(name, accepted)
    hint = f"; did you mean {guess!r}?" if guess else ""
    listing = ", ".join(accepted) if accepted else "none"
    return f"unknown {kind} {name!r} in {where}{hint} (accepted: {listing})"


def check_known(names: Iterable[str], accepted: Iterable[str], where: str, *, kind: str = "option",
                error: type[Exception] = UnknownName) -> None:
    """Raise ``error`` with :func:`unknown_message` for the first of ``names`` not accepted.

    Parameters
    ----------
    names : iterable of str
        The names given.
    accepted : iterable of str
        The names accepted there.
    where : str
        Where they were given, for the message.
    kind : str
        What the names are, for the message.
    error : type
        The exception raised (a ``ValueError`` subclass the caller's users already catch).
    """
    accepted = list(accepted)
    for name in names:
        if name not in accepted:
            raise error(unknown_message(kind, name, accepted, where))
