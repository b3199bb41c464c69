"""The sweep's error, and the check of its counts (workers, retries)."""

from __future__ import annotations

import numbers


class SweepError(ValueError):
    """A sweep description that cannot run; the message names the key and what is allowed."""


def check_count(name: str, value, unit: str, none_ok: bool = False, high: int | None = None) -> None:
    """Raise :class:`SweepError` unless ``value`` is an integer >= 0 (and <= ``high``).

    Parameters
    ----------
    name : str
        The count's name, for the message.
    value : int
        The count given.
    unit : str
        What the count counts, for the message (may be empty).
    none_ok : bool
        Accept None too.
    high : int, optional
        The largest count accepted.
    """
    if value is None and none_ok:
        return
    if (isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0
            or (high is not None and value > high)):
        upper = f" and <= {high}" if high is not None else ""
        raise SweepError(f"{name} must be an integer >= 0{upper}{' ' + unit if unit else ''}, "
                         f"got {value!r}")
