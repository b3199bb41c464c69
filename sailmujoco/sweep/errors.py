"""The sweep's error, the check of its counts (workers, retries), and which failed runs the
cluster lost (:func:`lost`: the only failures tried again)."""

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


def lost(record: dict) -> bool:
    """Whether a recorded run failed because the cluster lost it (its worker died, or the task
    could not be run), not because of its simulation: these alone are retried, and ``resume``
    runs them again.

    A run's own exception (its controller raised, its action was not finite, an option was
    refused) is caught in its worker and recorded there: the same seed and the same code raise
    it again, so trying again only repeats it.

    Parameters
    ----------
    record : dict
        A run's stored record.
    """
    if record.get("status") != "failed":
        return False
    return bool(record.get("lost")) or str(record.get("error") or "").startswith("KilledWorker")
