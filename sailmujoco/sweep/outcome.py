"""Why a sweep's runs failed, in one line per distinct reason (:func:`failures`), for the
command line's report and for a caller of :func:`~sailmujoco.sweep.run` who reads the table."""

from __future__ import annotations

from .spec import NAMESPACES

MAX_REASONS = 5  # distinct reasons listed; the rest are counted in one more line
MAX_REASON_CHARS = 200  # a reason longer than this (a long exception text) is cut


def reason(error) -> str:
    """The first line of a failed run's ``error`` (``"ValueError: ..."``, without the
    traceback that follows it), cut to ``MAX_REASON_CHARS``.

    Parameters
    ----------
    error : str or None
        The ``error`` column of a run's row.
    """
    lines = str(error or "").strip().splitlines()
    text = lines[0] if lines else "no error recorded"
    return text if len(text) <= MAX_REASON_CHARS else text[:MAX_REASON_CHARS - 3] + "..."


def failures(table) -> list[str]:
    """One line per distinct reason the sweep's runs failed (most frequent first): how many of
    the runs, the reason, and the first run that failed so (its position in the sweep, its
    ``run_id`` and the parameters that vary over the sweep). Empty when no run failed; a
    ``stopped`` run (a capsize) is a result, not a failure.

    ``failed 2 of 4 runs: ValueError: no target (e.g. run 1, 5983549715ddb795: seed=0
    controller.gain=2.0)``

    Parameters
    ----------
    table : pandas.DataFrame
        A sweep's table (:func:`~sailmujoco.sweep.run`), one row per run in the sweep's order.

    Returns
    -------
    list of str
    """
    if table.empty or "status" not in table:
        return []
    failed = table[table["status"] == "failed"]
    if failed.empty:
        return []
    varying = [c for c in table.columns
               if (c == "seed" or ("." in c and c.split(".", 1)[0] in NAMESPACES))
               and table[c].astype(str).nunique() > 1]
    groups: dict[str, list] = {}
    for position, (_, row) in zip(table.index.get_indexer(failed.index), failed.iterrows(), strict=True):
        groups.setdefault(reason(row["error"]), []).append((position, row))
    ranked = sorted(groups.items(), key=lambda item: -len(item[1]))  # stable: first seen first
    lines = []
    for text, rows in ranked[:MAX_REASONS]:
        position, row = rows[0]
        params = " ".join(f"{c}={row[c]}" for c in (varying or ["seed"]))
        lines.append(f"failed {len(rows)} of {_runs(len(table))}: {text} "
                     f"(e.g. run {position}, {row['run_id']}: {params})")
    rest = ranked[MAX_REASONS:]
    if rest:
        lines.append(f"failed {sum(len(rows) for _, rows in rest)} of {_runs(len(table))} for "
                     f"{len(rest)} other reasons (the error column of the table)")
    return lines


def _runs(n: int) -> str:
    return f"{n} run" if n == 1 else f"{n} runs"
