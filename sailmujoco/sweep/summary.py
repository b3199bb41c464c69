"""A sweep's metrics over its seeds: one row per combination with each metric's mean and 95 %
interval (:mod:`sailmujoco.stats`), written beside the table as ``summary.csv`` and printed by the
command line.

A sweep runs every combination of its grid on every seed of ``seeds``; the runs of one
combination differ only in their seed (the wind's gusts, the sea's phases, the start), so the
spread over them is what the seed does. A combination's ``<metric>`` is the mean over its seeds
that finished (``ok``), ``<metric>_low`` and ``<metric>_high`` its 95 % Student-t interval, and
``n`` the seeds it rests on.
"""

from __future__ import annotations

from .spec import NAMESPACES

CASE_COLUMNS = ("boat", "task", "world", "controller")  # with the namespaced options: one combination
NOT_METRICS = ("sweep_id", "spec_hash", "run_id", "seed", "status", "error", "wall_time", "attempts",
               "version")  # the table's columns that are neither a combination's nor a metric
MAX_LINES = 8  # the combinations a metric's summary prints (the rest are in summary.csv)


def combination_columns(table) -> list[str]:
    """The columns that name a combination: boat, task, world, controller and every
    ``<namespace>.<option>`` column (not the seed).

    Parameters
    ----------
    table : pandas.DataFrame
        A sweep's table (:func:`~sailmujoco.sweep.run`).
    """
    return [c for c in table.columns
            if c in CASE_COLUMNS or ("." in c and c.split(".", 1)[0] in NAMESPACES)]


def over_seeds(table, metrics: list[str]):
    """One row per combination: its columns, then for each metric the mean over its finished seeds,
    ``<metric>_low`` and ``<metric>_high`` (95 % interval) and ``n`` (seeds that finished).

    Parameters
    ----------
    table : pandas.DataFrame
        A sweep's table.
    metrics : list of str
        The metric columns to summarise (those missing from the table are left out).

    Returns
    -------
    pandas.DataFrame
        With these columns even when no run finished (then with no row).
    """
    import pandas as pd

    from .. import stats

    by = combination_columns(table)
    ok = table[table["status"] == "ok"] if "status" in table else table
    metrics = [m for m in metrics if m in table]
    columns = by + [c for m in metrics for c in (m, f"{m}_low", f"{m}_high")] + ["n"]
    rows = []
    # options may hold lists (a start position): group on their text, keep the first row's values.
    # The key is built row by row: DataFrame.agg(axis=1) of no row gives a frame, not a Series,
    # and groupby refuses a 2-D key
    keys = pd.Series(["|".join(values) for values in ok[by].astype(str).itertuples(index=False)],
                     index=ok.index, dtype=object)
    for _, group in ok.groupby(keys, sort=False):
        row = {c: group.iloc[0][c] for c in by}
        for m in metrics:
            got = stats.mean_interval(group[m].to_numpy(dtype=float))
            row.update({m: got.mean, f"{m}_low": got.low, f"{m}_high": got.high})
        row["n"] = len(group)
        rows.append(row)
    return pd.DataFrame(rows, columns=columns)


def lines(summary, metric: str, table) -> list[str]:
    """What the command line prints for ``metric``: one line per combination (at most
    :data:`MAX_LINES`), ``mean [low, high]`` over its seeds.

    Parameters
    ----------
    summary : pandas.DataFrame
        :func:`over_seeds` of the sweep.
    metric : str
        The metric.
    table : pandas.DataFrame
        The sweep's table (which of its columns vary names a combination).
    """
    from .. import stats

    if summary.empty or metric not in summary:
        return [f"{metric}: no finished run"]
    varying = [c for c in combination_columns(table) if table[c].astype(str).nunique() > 1]
    n = summary["n"]
    seeds = f"{n.min()}" if n.min() == n.max() else f"{n.min()}-{n.max()}"
    out = [f"{metric}: mean [95 % interval] over {seeds} seed(s) per combination"]
    for _, row in summary.head(MAX_LINES).iterrows():
        got = stats.Interval(float(row[metric]), float(row[f"{metric}_low"]), float(row[f"{metric}_high"]),
                             int(row["n"]))
        name = " ".join(f"{c}={row[c]}" for c in varying) or "every run"
        out.append(f"    {name}: {got.text(4)}")
    if len(summary) > MAX_LINES:
        out.append(f"    ... {len(summary) - MAX_LINES} more combinations in summary.csv")
    return out
