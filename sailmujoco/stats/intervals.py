"""How sure a number over seeds is: intervals, paired differences, pass counts and the verdict rule.

Every stochastic result of the testbed (gusts, wind wander, the sea's phases, start jitter) is run
over N seeds, and every number the reports print from such runs comes from here, on
:mod:`scipy.stats`:

* :func:`mean_interval` — the mean over seeds with its 95 % interval. The default is Student's t
  (``scipy.stats.ttest_1samp(...).confidence_interval``): exact for normal samples and, unlike a
  bootstrap, honest at the small N a study can afford (a percentile bootstrap of 2-5 values
  covers far less than 95 %: with 2 values it can never be wider than their range). Where N is
  large and the sample skewed, ``method="bootstrap"`` gives the BCa interval of
  ``scipy.stats.bootstrap`` (seeded, so a report stays a pure function of its seeds).
* :func:`paired_difference` and :func:`paired_ratio` — two arms run on the same seeds (the same
  wind and sea in both) compared seed by seed: the interval of the per-seed differences (or
  ratios), which is the paired t-interval (``scipy.stats.ttest_rel``). The shared weather cancels
  in each difference, so it is much narrower than :func:`unpaired_difference` (Welch) whenever
  the arms are correlated.
* :func:`pass_rate` — k of n runs passed, with Wilson's score interval
  (``scipy.stats.binomtest(k, n).proportion_ci(method="wilson")``), which keeps its coverage at
  0 of n and n of n where the normal approximation collapses to a point.
* :func:`verdict` — *holds*, *breaks* or *undecided at N seeds*: the interval against the paper's
  bound or band (:data:`VERDICT_RULE`).

A sample whose values are all equal (a deterministic run repeated) has the interval [x, x]: its
spread is exactly zero, not unknown. A single value has no interval (nan ends), so its verdict is
undecided unless the run is deterministic.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Literal

import numpy as np

CONFIDENCE = 0.95  # every interval the reports print is a 95 % interval
BOOTSTRAP_RESAMPLES = 9999  # scipy.stats.bootstrap's resamples (its default)
BOOTSTRAP_SEED = 0  # the resampling's own seed: the same seeds give the same report bit for bit
VERDICT_RULE = ("*holds* when the whole 95 % interval over seeds meets the paper's bound (or lies "
                "inside its band), *breaks* when the whole interval misses it, *undecided at N seeds* "
                "when the interval straddles it")

Method = Literal["t", "bootstrap"]


@dataclass(frozen=True)
class Interval:
    """A mean over N seeds with its 95 % interval.

    Parameters
    ----------
    mean : float
        The sample mean (nan for no finite value).
    low, high : float
        The interval's ends (nan when it has none: fewer than two values that differ).
    n : int
        The number of finite values it rests on.
    method : str
        How the ends were found: ``"t"``, ``"bootstrap"``, ``"wilson"`` or ``"exact"`` (every value
        equal).
    """

    mean: float
    low: float
    high: float
    n: int
    method: str = "t"

    @property
    def decided(self) -> bool:
        """Whether the interval has finite ends."""
        return math.isfinite(self.low) and math.isfinite(self.high)

    @property
    def width(self) -> float:
        """high - low (nan without ends)."""
        return self.high - self.low

    def contains(self, value: float) -> bool:
        """Whether ``value`` lies within [low, high] (never without ends).

        Parameters
        ----------
        value : float
            The number tested.
        """
        return self.decided and self.low <= value <= self.high

    def scaled(self, factor: float) -> Interval:
        """The same interval in another unit (``factor`` > 0: 100 for per cent, degrees per radian).

        Parameters
        ----------
        factor : float
            The positive factor every end is multiplied by.
        """
        return Interval(self.mean * factor, self.low * factor, self.high * factor, self.n, self.method)

    def text(self, digits: int = 3, unit: str = "", n: bool = False) -> str:
        """``"mean [low, high]"`` to ``digits`` significant digits (``"mean (N=1)"`` without ends).

        Parameters
        ----------
        digits : int
            Significant digits of each number.
        unit : str
            Appended after the bracket (with a space), e.g. ``"m"``.
        n : bool
            Append ``", N=n"`` inside the bracket.
        """
        fmt = (lambda v: f"{v:.{digits}g}") if digits else (lambda v: f"{v:.0f}")
        if not math.isfinite(self.mean):
            return "—"
        tail = f" {unit}" if unit else ""
        if not self.decided:
            return f"{fmt(self.mean)}{tail} (N={self.n})"
        count = f", N={self.n}" if n else ""
        return f"{fmt(self.mean)} [{fmt(self.low)}, {fmt(self.high)}{count}]{tail}"

    def fixed(self, decimals: int = 1, unit: str = "") -> str:
        """``"mean [low, high]"`` with ``decimals`` decimal places.

        Parameters
        ----------
        decimals : int
            Decimal places.
        unit : str
            Appended after the bracket (with a space).
        """
        if not math.isfinite(self.mean):
            return "—"
        tail = f" {unit}" if unit else ""
        if not self.decided:
            return f"{self.mean:.{decimals}f}{tail} (N={self.n})"
        return f"{self.mean:.{decimals}f} [{self.low:.{decimals}f}, {self.high:.{decimals}f}]{tail}"


def _finite(values) -> np.ndarray:
    a = np.asarray(values, dtype=float).ravel()
    return a[np.isfinite(a)]


def mean_interval(values, *, method: Method = "t", confidence: float = CONFIDENCE) -> Interval:
    """The mean of ``values`` (one per seed) with its interval; values that are not numbers are
    left out (their count shows in ``n``).

    Parameters
    ----------
    values : array_like
        One number per seed.
    method : {"t", "bootstrap"}
        Student's t (the default: see the module docstring) or the BCa bootstrap.
    confidence : float
        The interval's confidence level.

    Raises
    ------
    ValueError
        For an unknown method, or a confidence outside (0, 1).
    """
    from scipy import stats

    if method not in ("t", "bootstrap"):
        raise ValueError(f"method must be 't' or 'bootstrap', got {method!r}")
    if not 0.0 < confidence < 1.0:
        raise ValueError(f"confidence must be within (0, 1), got {confidence!r}")
    a = _finite(values)
    if a.size == 0:
        return Interval(math.nan, math.nan, math.nan, 0, method)
    mean = float(a.mean())
    if np.all(a == a[0]):
        # a deterministic outcome: no spread, or one value: no interval
        return (Interval(mean, mean, mean, int(a.size), "exact") if a.size > 1
                else Interval(mean, math.nan, math.nan, 1, method))
    if method == "t":
        with warnings.catch_warnings():  # values equal but for rounding: scipy warns, the interval is right
            warnings.simplefilter("ignore", RuntimeWarning)
            ci = stats.ttest_1samp(a, 0.0).confidence_interval(confidence_level=confidence)
    else:
        ci = stats.bootstrap((a,), np.mean, confidence_level=confidence, method="BCa",
                             n_resamples=BOOTSTRAP_RESAMPLES,
                             random_state=np.random.default_rng(BOOTSTRAP_SEED)).confidence_interval
    return Interval(mean, float(ci.low), float(ci.high), int(a.size), method)


def _paired(a, b) -> tuple[np.ndarray, np.ndarray]:
    a, b = np.asarray(a, dtype=float).ravel(), np.asarray(b, dtype=float).ravel()
    if a.shape != b.shape:
        raise ValueError(f"paired arms need one value per seed in each, got {a.size} and {b.size}")
    keep = np.isfinite(a) & np.isfinite(b)
    return a[keep], b[keep]


def paired_difference(a, b, *, method: Method = "t", confidence: float = CONFIDENCE) -> Interval:
    """Arm ``a`` minus arm ``b``, seed by seed (``a[i]`` and ``b[i]`` ran on the same seed): the
    interval of the per-seed differences (the paired t-interval for ``method="t"``).

    Parameters
    ----------
    a, b : array_like
        One number per seed in each arm, in the same seed order.
    method : {"t", "bootstrap"}
        As :func:`mean_interval`.
    confidence : float
        The interval's confidence level.
    """
    a, b = _paired(a, b)
    return mean_interval(a - b, method=method, confidence=confidence)


def paired_ratio(a, b, *, method: Method = "t", confidence: float = CONFIDENCE) -> Interval:
    """Arm ``a`` over arm ``b``, seed by seed: the interval of the mean per-seed ratio a[i] / b[i]
    (seeds where b is 0 are left out).

    Parameters
    ----------
    a, b : array_like
        One number per seed in each arm, in the same seed order.
    method : {"t", "bootstrap"}
        As :func:`mean_interval`.
    confidence : float
        The interval's confidence level.
    """
    a, b = _paired(a, b)
    keep = b != 0.0
    return mean_interval(a[keep] / b[keep], method=method, confidence=confidence)


def unpaired_difference(a, b, *, confidence: float = CONFIDENCE) -> Interval:
    """mean(a) - mean(b) for arms drawn independently: Welch's interval (``scipy.stats.ttest_ind``
    with unequal variances). For arms run on the same seeds use :func:`paired_difference`.

    Parameters
    ----------
    a, b : array_like
        The two samples (any sizes, at least two values each).
    confidence : float
        The interval's confidence level.
    """
    from scipy import stats

    a, b = _finite(a), _finite(b)
    mean = float(a.mean() - b.mean()) if a.size and b.size else math.nan
    if a.size < 2 or b.size < 2:
        return Interval(mean, math.nan, math.nan, int(min(a.size, b.size)), "welch")
    ci = stats.ttest_ind(a, b, equal_var=False).confidence_interval(confidence_level=confidence)
    return Interval(mean, float(ci.low), float(ci.high), int(min(a.size, b.size)), "welch")


def pass_rate(passed: int, n: int, *, confidence: float = CONFIDENCE) -> Interval:
    """``passed`` of ``n`` runs: the fraction with Wilson's score interval.

    Parameters
    ----------
    passed : int
        Runs that passed (0 <= passed <= n).
    n : int
        Runs in all.
    confidence : float
        The interval's confidence level.

    Raises
    ------
    ValueError
        For a count outside 0 <= passed <= n.
    """
    from scipy import stats

    passed, n = int(passed), int(n)
    if n < 0 or not 0 <= passed <= max(n, 0):
        raise ValueError(f"passed must be within 0..n, got {passed} of {n}")
    if n == 0:
        return Interval(math.nan, math.nan, math.nan, 0, "wilson")
    ci = stats.binomtest(passed, n).proportion_ci(confidence_level=confidence, method="wilson")
    return Interval(passed / n, float(ci.low), float(ci.high), n, "wilson")


Sense = Literal["below", "above", "within"]


def verdict(interval: Interval, bound: float, sense: Sense = "below", *, band: float | None = None) -> str:
    """The verdict of :data:`VERDICT_RULE` for ``interval`` against the paper's ``bound``.

    Parameters
    ----------
    interval : Interval
        The number's interval over seeds.
    bound : float
        The paper's bound (``"below"``: the number must stay under it; ``"above"``: over it) or its
        number (``"within"``: the number must lie within ``band`` of it).
    sense : {"below", "above", "within"}
        What the claim requires.
    band : float, optional
        For ``"within"``: the half-width of the accepted band, in the number's unit.

    Returns
    -------
    str
        ``"holds"``, ``"breaks"`` or ``"undecided at N seeds"``.

    Raises
    ------
    ValueError
        For an unknown sense, or ``"within"`` without a non-negative band.
    """
    if sense not in ("below", "above", "within"):
        raise ValueError(f"sense must be 'below', 'above' or 'within', got {sense!r}")
    if sense == "within" and (band is None or not band >= 0.0):
        raise ValueError(f"band must be a number >= 0 for sense 'within', got {band!r}")
    undecided = f"undecided at {interval.n} seed{'s' if interval.n != 1 else ''}"
    if not interval.decided:
        return undecided
    lo, hi = interval.low, interval.high
    if sense == "below":
        inside, outside = hi < bound, lo >= bound
    elif sense == "above":
        inside, outside = lo > bound, hi <= bound
    else:
        inside = bound - band <= lo and hi <= bound + band
        outside = hi < bound - band or lo > bound + band
    return "holds" if inside else "breaks" if outside else undecided
