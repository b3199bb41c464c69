"""The verdicts and differences the study reports print, computed from the numbers in their tables.

Every report's "difference", "range", "holds / breaks" and "the limit binds" text comes from here,
so one set of rules (tested in tests/test_verdict.py) decides them all:

* :func:`difference` — ours against a reference. Relative when it means something: both numbers
  of the same sign and ``|reference|`` above a floor; then it is the change in *size*,
  ``(|ours| - |reference|) / |reference|`` (-0.54 m against -2.15 m is -75 %: ours is a quarter
  of the paper's, not "75 % more"). When the signs differ or the reference is within the floor
  of zero a percentage says nothing, and the absolute difference ``ours - reference`` is given
  in the quantity's unit.
* :func:`value_range` — "min … max" of the finite values of one array: the same numbers the study
  writes to its CSV, nothing filtered out silently.
* :func:`judge` — "holds" only when every value is within the threshold (a value that is not a
  number cannot be within), "breaks at k of n points" otherwise, with the count.
  :func:`combined` joins several criteria: "holds" only when every one holds.
* :func:`limit_state` — "binds" only when the value reaches the limit within a tolerance.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

TOLERANCE = 0.10  # a difference beyond 10 % is flagged in the comparison tables
DIFFERENCE_NOTE = ("*difference*: ours against the paper as a change in size, (|ours| − |paper|) / |paper|, when "
                   "both have the same sign; the absolute difference, in the quantity's unit, when the signs "
                   "differ or the paper's number is 0; ⚠ beyond 10 %.")


@dataclass(frozen=True)
class Difference:
    """ours against reference: ``value`` is a fraction when ``relative``, else ours - reference.

    Parameters
    ----------
    value : float
        (|ours| - |reference|) / |reference| when ``relative``, else ours - reference in ``unit``;
        nan when either is not a number.
    relative : bool
        Whether ``value`` is a relative change in size.
    reference : float
        The reference's number.
    floor : float
        Below this size the reference counts as zero.
    unit : str
        The quantity's unit.
    """

    value: float
    relative: bool
    reference: float
    floor: float = 0.0
    unit: str = ""

    @property
    def finite(self) -> bool:
        return math.isfinite(self.value)

    def beyond(self, tolerance: float = TOLERANCE) -> bool:
        """Beyond ``tolerance``: of the reference's size when relative; of max(|reference|,
        floor) in the quantity's unit when absolute. Not a number is beyond.

        Parameters
        ----------
        tolerance : float
            The fraction allowed.
        """
        if not self.finite:
            return True
        if self.relative:
            return abs(self.value) > tolerance
        return abs(self.value) > tolerance * max(abs(self.reference), self.floor)

    def text(self, digits: int = 0) -> str:
        """The difference as report text: "+12 %", or "+0.3 m (signs differ)", or "—".

        Parameters
        ----------
        digits : int
            Decimals of a relative difference, in per cent.
        """
        if not self.finite:
            return "—"
        if self.relative:
            return f"{100 * self.value:+.{digits}f} %"
        unit = f" {self.unit}" if self.unit else ""
        why = "signs differ" if self.reference and abs(self.reference) > self.floor else "reference ≈ 0"
        return f"{self.value:+.3g}{unit} ({why})"


def difference(ours, reference, *, floor: float = 0.0, unit: str = "") -> Difference:
    """ours against reference (see the module's docstring). Not a number when either is not.

    Parameters
    ----------
    ours, reference : float or array_like
        Our number(s) and the reference's (the paper's), in the same unit.
    floor : float
        Below this size the reference counts as zero: the difference is then absolute.
    unit : str
        The quantity's unit, for the text of an absolute difference.

    Returns
    -------
    Difference
    """
    try:
        a, r = float(ours), float(reference)
    except (TypeError, ValueError):
        return Difference(float("nan"), False, float("nan"), floor, unit)
    if not (math.isfinite(a) and math.isfinite(r)):
        return Difference(float("nan"), False, r, floor, unit)
    if abs(r) > floor and r != 0.0 and a * r >= 0.0:
        return Difference((abs(a) - abs(r)) / abs(r), True, r, floor, unit)
    return Difference(a - r, False, r, floor, unit)


def differences(ours, reference, *, floor: float = 0.0, unit: str = "") -> list[Difference]:
    """:func:`difference` point by point.

    Parameters
    ----------
    ours, reference : float or array_like
        Our number(s) and the reference's (the paper's), in the same unit.
    floor : float
        Below this size the reference counts as zero: the difference is then absolute.
    unit : str
        The quantity's unit, for the text of an absolute difference.

    Returns
    -------
    list of Difference
    """
    a = np.asarray(ours, dtype=float).ravel()
    r = np.asarray(reference, dtype=float).ravel()
    return [difference(x, y, floor=floor, unit=unit) for x, y in zip(a, r, strict=True)]


def finite(values, scale: float = 1.0) -> np.ndarray:
    """The finite values, flattened and scaled.

    Parameters
    ----------
    values : array_like
        The numbers (flattened).
    scale : float
        Factor the values are multiplied by first (100: fractions as per cent).

    Returns
    -------
    numpy.ndarray
    """
    v = np.asarray(values, dtype=float).ravel() * scale
    return v[np.isfinite(v)]


def value_range(values, scale: float = 1.0, fmt: str = "{:.3g}") -> str:
    """"min … max" of the finite values (times ``scale``); "—" when there are none.

    Parameters
    ----------
    values : array_like
        The numbers (flattened).
    scale : float
        Factor the values are multiplied by first (100: fractions as per cent).
    fmt : str
        Format of each end.
    """
    v = finite(values, scale)
    if not v.size:
        return "—"
    return f"{fmt.format(v.min())} … {fmt.format(v.max())}"


def range_of(diffs: list[Difference], fmt: str = "{:+.1f}") -> str:
    """The range of a list of differences: the relative ones in %, the absolute ones (signs
    differ, or the reference within its floor of zero) apart in their unit, each with its count.

    Parameters
    ----------
    diffs : list of Difference
        The differences.
    fmt : str
        Format of each end of the relative range, in per cent.
    """
    rel = [d.value for d in diffs if d.finite and d.relative]
    ab = [d.value for d in diffs if d.finite and not d.relative]

    def count(n):
        return f"{n} point" + ("s" if n != 1 else "")

    parts = []
    if rel:
        parts.append(f"{value_range(rel, 100, fmt)} % ({count(len(rel))})")
    if ab:
        unit = next(d.unit for d in diffs if d.finite and not d.relative)
        floor = next(d.floor for d in diffs if d.finite and not d.relative)
        span = f"{ab[0]:+.3g}" if len(ab) == 1 else value_range(ab, 1.0, "{:+.3g}")
        parts.append(f"{span} {unit} where the reference is below {floor:g} {unit} "
                     f"({count(len(ab))})".replace("  ", " "))
    return "; ".join(parts) if parts else "—"


@dataclass(frozen=True)
class Judgement:
    """Whether every value is within a threshold.

    Parameters
    ----------
    n : int
        Values judged.
    beyond : int
        Values beyond the threshold.
    missing : int
        Values that are not numbers (counted beyond).
    """

    n: int
    beyond: int
    missing: int

    @property
    def holds(self) -> bool:
        return self.n > 0 and self.beyond == 0

    def text(self, unit: str = "points") -> str:
        """"holds (n of n points)", "breaks at k of n points", or "no data".

        Parameters
        ----------
        unit : str
            What a value is called in the text.
        """
        if self.n == 0:
            return "no data"
        if self.holds:
            return f"holds ({self.n} of {self.n} {unit})"
        missing = f", {self.missing} without a value" if self.missing else ""
        return f"breaks at {self.beyond} of {self.n} {unit}{missing}"


def judge(values, *, below: float | None = None, above: float | None = None,
          magnitude: bool = False) -> Judgement:
    """Every value (its size if ``magnitude``) must be < ``below`` and > ``above``.

    Parameters
    ----------
    values : array_like
        The numbers judged (flattened); one that is not a number is beyond.
    below, above : float, optional
        Open bounds; None: no bound on that side.
    magnitude : bool
        Judge |value|.

    Returns
    -------
    Judgement
    """
    v = np.asarray(values, dtype=float).ravel()
    x = np.abs(v) if magnitude else v
    ok = np.isfinite(x)
    with np.errstate(invalid="ignore"):
        if below is not None:
            ok &= x < below
        if above is not None:
            ok &= x > above
    return Judgement(n=int(v.size), beyond=int(v.size - np.count_nonzero(ok)),
                     missing=int(np.count_nonzero(~np.isfinite(v))))


def judge_differences(diffs: list[Difference], tolerance: float = TOLERANCE) -> Judgement:
    """Every difference within ``tolerance`` (:meth:`Difference.beyond`).

    Parameters
    ----------
    diffs : list of Difference
        The differences.
    tolerance : float
        The fraction allowed.

    Returns
    -------
    Judgement
    """
    return Judgement(n=len(diffs), beyond=sum(d.beyond(tolerance) for d in diffs),
                     missing=sum(not d.finite for d in diffs))


def combined(parts: dict[str, Judgement]) -> str:
    """One verdict from several criteria: "holds" only when every one holds; each named with its
    own count.

    Parameters
    ----------
    parts : dict of str to Judgement
        Criterion name -> its judgement.
    """
    word = "holds" if parts and all(j.holds for j in parts.values()) else "breaks"
    return f"{word} ({'; '.join(f'{name}: {j.text()}' for name, j in parts.items())})"


def limit_state(value: float, limit: float, tolerance: float) -> str:
    """"binds" when |value| reaches the limit within ``tolerance``; "exceeded" beyond it;
    "does not bind" below.

    Parameters
    ----------
    value : float
        The value (its size is compared).
    limit, tolerance : float
        The limit and the tolerance, in the value's unit.
    """
    v = abs(float(value))
    if not math.isfinite(v):
        return "no value"
    if v > limit + tolerance:
        return "exceeded"
    if v >= limit - tolerance:
        return "binds"
    return "does not bind"
