"""Assumption validation, where each difference a sea makes comes from.

Every difference that breaks is rerun on the case's first :data:`.sea.MECHANISM_SEEDS` seeds
(those on which both runs kept their heading) with each of the sea's two paths into the boat
switched off in turn (:data:`.sea.PATHS`; both off, the calm boat to the bit): the share of the
difference a switch removes is 1 - (switched - calm)/(sea - calm), seed by seed, and its mean
with its interval. The path whose share's interval lies wholly above ``EXPLAINS``, the more of
the two, is the one the difference takes; where both lie wholly below, either path alone makes
more than half of it; otherwise it is undecided at those seeds (:func:`attribute`). The largest
difference of each series and metric is rerun with the hull's refinements off too, as far as the
sea's budget (:data:`.sea.BUDGET`) allows, and the refinement named the same way. A switched run
that loses its heading is reported as stalled.

The differences that break (:func:`differing_cases`) and the largest of each series and
metric (:func:`largest_cases`); a switch's share of a difference (:func:`shares`,
:func:`explains`, :func:`attribute`), the path it takes (:func:`path_taken`) and the
mechanisms' table (:func:`attribution`). The reruns themselves are planned and read by
:mod:`.sea_analysis`.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from sailmujoco import stats

from ..kit import seeds as kit_seeds
from . import sea
from .sea_cases import DIFFERENCE, SERIES, metrics_of

EXPLAINS = 0.5  # -, a switch explains a difference when it removes more than half of it


def differing_cases(tables: dict, smoke: bool) -> list[tuple[str, str, int]]:
    """(series, metric, case index) of every difference whose verdict is *breaks*, series by
    series, metric by metric. Smoke (two seeds decide little): the one largest mean difference
    beyond ``DIFFERENCE`` of a case with a seed on which both runs keep their heading.

    Parameters
    ----------
    tables : dict
        Series -> its cases (:func:`.sea_cases.summarise`).
    smoke : bool
        The study's short pass.
    """
    if smoke:
        found = [(abs(row[f"{metric}_rel"]), series, metric, int(row["case_index"]))
                 for series, table in tables.items() for metric in metrics_of(series)
                 for _, row in table.iterrows()
                 if row["n_kept"] and np.isfinite(row[f"{metric}_rel"]) and abs(row[f"{metric}_rel"]) > DIFFERENCE]
        return [max(found)[1:]] if found else []
    return [(series, metric, int(row["case_index"])) for series, table in tables.items()
            for metric in metrics_of(series) for _, row in table.iterrows() if row[f"{metric}_verdict"] == "breaks"]


def largest_cases(tables: dict, selected: list) -> list[tuple[str, str, int]]:
    """Of ``selected`` (:func:`differing_cases`), the largest mean difference of each series and
    metric.

    Parameters
    ----------
    tables : dict
        Series -> its cases (:func:`.sea_cases.summarise`).
    selected : list of (str, str, int)
        The differences.
    """
    best = {}
    for series, metric, case in selected:
        size = abs(float(tables[series].set_index("case_index").loc[case, f"{metric}_rel"]))
        if (series, metric) not in best or size > best[(series, metric)][0]:
            best[(series, metric)] = (size, case)
    return [(series, metric, case) for (series, metric), (_, case) in best.items()]



def shares(calm, sea_value, switched) -> np.ndarray:
    """The share of a difference a switch removes, seed by seed: 1 - (switched - calm)/(sea -
    calm) (1: the switch brings the metric back to calm; 0: it changes nothing; negative: it
    makes the difference larger); NaN where the seed's difference is 0 or its rerun has no value.

    Parameters
    ----------
    calm, sea_value, switched : array_like
        One value per seed: calm water, the sea with every mechanism on, the sea with the
        switch off.
    """
    calm, sea_value, switched = (np.asarray(v, dtype=float) for v in (calm, sea_value, switched))
    difference = sea_value - calm
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(difference != 0.0, 1.0 - (switched - calm) / difference, np.nan)


def explains(got: stats.Interval, share: float = EXPLAINS) -> str:
    """Whether a switch explains a difference: the verdict of its share's interval against
    ``share`` (*holds*: it removes more than that; *breaks*: at most that).

    Parameters
    ----------
    got : sailmujoco.stats.Interval
        The share removed, over seeds.
    share : float
        The least share of the difference a switch must remove to explain it.
    """
    return stats.verdict(got, share, "above")


def attribute(calm, sea_value, switched: dict, share: float = EXPLAINS):
    """Which mechanism a difference comes from: ``(name or None, {name: share removed})``.

    Each switch's share (:func:`shares`) is the mean over seeds with its interval. The name is
    the switch with the largest mean share among those whose interval lies wholly above
    ``share`` (:func:`explains`); None when none does.

    Parameters
    ----------
    calm : array_like
        The metric in calm water, one per seed.
    sea_value : array_like
        The metric in the sea, every mechanism on, one per seed.
    switched : dict
        Mechanism -> the metric in the sea with that mechanism off, one per seed.
    share : float
        The least share of the difference a switch must remove to explain it.
    """
    removed = {name: kit_seeds.interval(shares(calm, sea_value, value)) for name, value in switched.items()}
    holding = {name: got.mean for name, got in removed.items() if explains(got, share) == "holds"}
    return (max(holding, key=holding.get) if holding else None), removed


def path_taken(removed: dict, stalled: dict) -> str:
    """The path a difference takes from its two paths' shares (:func:`attribute`): "hull" or
    "foils" (the switch that explains it), "either" (each switch surely removes at most
    ``EXPLAINS``: each path alone makes more than half), "hull alone" or "foils alone" (that
    path's rerun lost its heading on every seed and the other's switch surely removes at most
    1 - ``EXPLAINS``: with both off the boat is the calm boat), "stalled" (a path's rerun lost
    its heading otherwise) or "undecided".

    Parameters
    ----------
    removed : dict
        Path -> its share's interval.
    stalled : dict
        Path -> (seeds whose rerun lost its heading, seeds rerun).
    """
    words = {"wave_hull": "hull", "wave_foil_flow": "foils"}
    holding = {n: removed[n].mean for n in sea.PATHS if explains(removed[n]) == "holds"}
    if holding:
        return words[max(holding, key=holding.get)]
    lost = [n for n in sea.PATHS if stalled[n][0]]
    if len(lost) == 1 and stalled[lost[0]][0] == stalled[lost[0]][1]:
        other = next(n for n in sea.PATHS if n != lost[0])
        if explains(removed[other], 1.0 - EXPLAINS) == "breaks":
            return f"{words[lost[0]]} alone"
    if lost:
        return "stalled"
    if all(explains(removed[n]) == "breaks" for n in sea.PATHS):
        return "either"
    return "undecided"



def attribution(runs: dict, tables: dict, reruns: pd.DataFrame, smoke: bool) -> pd.DataFrame:
    """The mechanisms' table: each difference of :func:`differing_cases` (``largest``: the
    largest of its series and metric), with, per mechanism rerun, the metric with it off
    (``<mechanism>_off``, the mean over the seeds rerun), the share it removes
    (``<mechanism>_removed`` with ``_low`` and ``_high``: :func:`attribute`; over the seeds on
    which the rerun kept its heading), the seeds whose rerun lost it (``<mechanism>_stalled``)
    and rerun (``<mechanism>_n``); the path it takes (``path``: :func:`path_taken`;
    ``mechanism``: the path's switch where one explains it) and the refinement of the hull's
    path that explains it (``refinement``), each "" when none does.

    Parameters
    ----------
    runs : dict
        Series -> its rows (:func:`.sea_cases.first_pass`).
    tables : dict
        Series -> its cases (:func:`.sea_cases.summarise`).
    reruns : pandas.DataFrame
        :func:`.sea_analysis._rerun_values`.
    smoke : bool
        The study's short pass.
    """
    selected = differing_cases(tables, smoke)
    largest = set(largest_cases(tables, selected))
    out = []
    for series, metric, case in selected:
        case_row = tables[series].set_index("case_index").loc[case]
        mine = reruns[(reruns["series"] == series) & (reruns["case_index"] == case)]
        rerun_seeds = list(dict.fromkeys(mine["seed"]))
        first = runs[series].set_index(["case_index", "seed"])
        calm = np.array([first.loc[(case, s), f"{metric}_calm"] for s in rerun_seeds], dtype=float)
        sea_value = np.array([first.loc[(case, s), f"{metric}_sea"] for s in rerun_seeds], dtype=float)
        values, stalled = {}, {}
        for name, _ in sea.MECHANISMS:
            these = mine[mine["mechanism"] == name].set_index("seed")
            if these.empty:
                continue
            got = np.array([these.loc[s, metric] if s in these.index else np.nan for s in rerun_seeds], dtype=float)
            lost = np.array([bool(these.loc[s, "stalled"]) if s in these.index else False for s in rerun_seeds])
            values[name] = np.where(lost, np.nan, got)
            stalled[name] = (int(lost.sum()), len(these))
        mechanism, removed = attribute(calm, sea_value, {n: values[n] for n in sea.PATHS if n in values})
        path = path_taken(removed, stalled) if all(n in removed for n in sea.PATHS) else "undecided"
        refinement, finer = attribute(calm, sea_value, {n: v for n, v in values.items() if n not in sea.PATHS})
        removed.update(finer)
        label, unit, _ = metrics_of(series)[metric]
        row = {"series": SERIES[series], "series_key": series, "metric_key": metric, "case": case_row["case"],
               "case_index": case, "metric": label, "unit": unit, "n": len(rerun_seeds),
               "mechanism_seeds": " ".join(str(s) for s in rerun_seeds),
               "largest": (series, metric, case) in largest, "verdict": case_row[f"{metric}_verdict"],
               "n_kept": int(case_row["n_kept"])}
        for column in ("calm", "sea", "change", "rel"):
            for end in ("", "_low", "_high"):
                row[f"{column}{end}"] = case_row[f"{metric}_{column}{end}"]
        for name, _ in sea.MECHANISMS:
            got = removed.get(name, stats.Interval(math.nan, math.nan, math.nan, 0))
            row[f"{name}_off"] = float(np.nanmean(values[name])) if name in values and np.isfinite(values[name]).any() \
                else math.nan
            row[f"{name}_removed"], row[f"{name}_removed_low"], row[f"{name}_removed_high"] = got.mean, got.low, got.high
            row[f"{name}_removed_n"] = got.n
            row[f"{name}_stalled"], row[f"{name}_n"] = stalled.get(name, (0, 0))
        row["path"], row["mechanism"], row["refinement"] = path, mechanism or "", refinement or ""
        out.append(row)
    return pd.DataFrame(out)


def removed_interval(row, name: str) -> stats.Interval:
    """The share of a difference switch ``name`` removes, from a row of :func:`attribution`.

    Parameters
    ----------
    row : mapping
        The row.
    name : str
        A mechanism of :data:`.sea.MECHANISMS`.
    """
    return stats.Interval(float(row[f"{name}_removed"]), float(row[f"{name}_removed_low"]),
                          float(row[f"{name}_removed_high"]), int(row[f"{name}_removed_n"]))
