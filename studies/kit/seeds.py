"""Numbers over seeds in a study: a table's groups as means with 95 % intervals, the report's
method line, verdict cells and error bars, all from :mod:`sailmujoco.stats`.

A study runs each stochastic case on the seeds :attr:`sailmujoco.study.Results.seeds` and keeps
one row per case and seed; :func:`over_seeds` turns those rows into one row per case with the
mean, its interval and N; :func:`paired` compares two arms seed by seed (the same wind and sea in
both); :func:`method_line` says in the report how the numbers were made; :func:`decide` and
:func:`verdict_cell` say *holds*, *breaks* or *undecided at N seeds*.
"""

from __future__ import annotations

import warnings

import numpy as np
import pandas as pd

from sailmujoco import stats


def interval(values, **options) -> stats.Interval:
    """The mean of ``values`` (one per seed) with its 95 % interval (:func:`sailmujoco.stats.mean_interval`).

    Parameters
    ----------
    values : array_like
        One number per seed.
    **options
        ``method`` or ``confidence`` of :func:`sailmujoco.stats.mean_interval`.
    """
    return stats.mean_interval(values, **options)


def over_seeds(rows: pd.DataFrame, by: list[str], columns: list[str]) -> pd.DataFrame:
    """One row per group of ``by``: for each of ``columns`` its mean, ``<column>_low``,
    ``<column>_high`` (the 95 % interval over the group's seeds) and ``n`` (the seeds).

    Parameters
    ----------
    rows : pandas.DataFrame
        One row per case and seed.
    by : list of str
        The columns that name a case (not the seed).
    columns : list of str
        The numbers to state over seeds.
    """
    out = []
    for key, group in rows.groupby(by, sort=False, dropna=False):
        key = key if isinstance(key, tuple) else (key,)
        row = dict(zip(by, key, strict=True))
        for c in columns:
            got = stats.mean_interval(group[c].to_numpy(dtype=float))
            row.update({c: got.mean, f"{c}_low": got.low, f"{c}_high": got.high})
        row["n"] = len(group)
        out.append(row)
    return pd.DataFrame(out)


def row_interval(row, column: str, n: int | None = None) -> stats.Interval:
    """The :class:`~sailmujoco.stats.Interval` a row of :func:`over_seeds` holds for ``column``.

    Parameters
    ----------
    row : mapping or pandas.Series
        A row of :func:`over_seeds`.
    column : str
        The number.
    n : int, optional
        Its N (the row's ``n`` if not given).
    """
    return stats.Interval(float(row[column]), float(row[f"{column}_low"]), float(row[f"{column}_high"]),
                          int(n if n is not None else row["n"]))


def paired(a, b, *, ratio: bool = False) -> stats.Interval:
    """Arm ``a`` against arm ``b`` seed by seed: the interval of a - b (or a / b with ``ratio``).

    Parameters
    ----------
    a, b : array_like
        One number per seed in each arm, in the same seed order.
    ratio : bool
        The per-seed ratio instead of the difference.
    """
    return stats.paired_ratio(a, b) if ratio else stats.paired_difference(a, b)


def cell(got: stats.Interval, digits: int = 3, unit: str = "") -> str:
    """A table cell: ``"mean [low, high]"`` to ``digits`` significant digits.

    Parameters
    ----------
    got : sailmujoco.stats.Interval
        The number over seeds.
    digits : int
        Significant digits.
    unit : str
        Appended after the bracket.
    """
    return got.text(digits, unit)


def decide(got: stats.Interval, bound: float, sense: str = "below", band: float | None = None) -> str:
    """*holds*, *breaks* or *undecided at N seeds* (:func:`sailmujoco.stats.verdict`).

    Parameters
    ----------
    got : sailmujoco.stats.Interval
        The number over seeds.
    bound : float
        The paper's bound, or its number for ``sense="within"``.
    sense : {"below", "above", "within"}
        What the claim requires.
    band : float, optional
        For ``"within"``: the accepted half-width, in the number's unit.
    """
    return stats.verdict(got, bound, sense, band=band)


def method_line(seeds, *, what: str = "every stochastic number", extra: str = "") -> str:
    """The report's method line: the seeds, the interval and the verdict rule.

    Parameters
    ----------
    seeds : sequence of int
        The seeds run.
    what : str
        What the intervals are given for.
    extra : str
        A sentence appended (what the seed draws in this study).
    """
    seeds = list(seeds)
    span = f"seeds {seeds[0]}-{seeds[-1]}" if len(seeds) > 1 else f"seed {seeds[0]}"
    return (f"**Method.** N = {len(seeds)} ({span}); {what} is the mean over them with its 95 % "
            f"Student-t interval, `mean [low, high]`; arms compared seed by seed (the same wind and "
            f"sea in both). Verdict: {stats.VERDICT_RULE}." + (f" {extra}" if extra else ""))


def errorbar(ax, x, intervals, **style):
    """Means with their 95 % intervals as error bars on ``ax`` (ends that are not numbers: a
    marker alone).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    x : array_like
        The positions.
    intervals : sequence of sailmujoco.stats.Interval
        One per position.
    **style
        Keywords of ``Axes.errorbar``.
    """
    mean = np.array([i.mean for i in intervals], dtype=float)
    low = np.array([i.low if i.decided else i.mean for i in intervals], dtype=float)
    high = np.array([i.high if i.decided else i.mean for i in intervals], dtype=float)
    style.setdefault("capsize", 3)
    return ax.errorbar(x, mean, yerr=np.vstack([mean - low, high - mean]), **style)


def band(ax, t, runs, **style):
    """The mean over seeds of time series ``runs`` (one row per seed, on the times ``t``) as a line,
    with the band of its pointwise 95 % interval; returns the line.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    t : array_like
        The times.
    runs : array_like
        Shape (seeds, len(t)).
    **style
        Keywords of ``Axes.plot`` (``color``, ``label``, ...).
    """
    from scipy import stats as scipy_stats

    runs = np.atleast_2d(np.asarray(runs, dtype=float))
    mean = runs.mean(axis=0)
    (line,) = ax.plot(t, mean, **style)
    if runs.shape[0] > 1:
        with np.errstate(invalid="ignore", divide="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)  # times where the seeds agree to rounding
            ci = scipy_stats.ttest_1samp(runs, 0.0, axis=0).confidence_interval(stats.CONFIDENCE)
        low, high = np.where(np.isfinite(ci.low), ci.low, mean), np.where(np.isfinite(ci.high), ci.high, mean)
        ax.fill_between(t, low, high, color=line.get_color(), alpha=0.2, linewidth=0)
    return line
