"""Assumption validation, the sea's part of the report: where each difference comes from.

Each difference a sea makes (:func:`.sea_analysis.attribution`) takes one of the sea's two
paths into the boat, the hull or the keel and rudder (:data:`.sea.PATHS`): :func:`path_of`
says which, :func:`path_counts` how many per series and metric, :func:`named` in words with
the switches that show it, and :func:`mechanisms_section` writes the report's section.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from . import sea
from .sea_analysis import DIFFERENCE, EXPLAINS, HEADING_LOST_DEG, SERIES, SeaAnalysis, lost_cases, metrics_of


def paths(s: SeaAnalysis) -> list[str]:
    """The path of every difference beyond ``DIFFERENCE`` (:func:`path_of`).

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    """
    return [path_of(row) for _, row in s.mechanisms.iterrows()]


def _rows_of(s: SeaAnalysis, series: str, metric: str) -> pd.DataFrame:
    """The mechanisms' rows of one series and metric."""
    m = s.mechanisms
    if m.empty:
        return m
    return m[(m["series"] == SERIES[series]) & (m["metric"] == metrics_of(series)[metric][0])]


def path_of(row) -> str:
    """Which of the sea's paths a difference takes: "hull", "foils", "either" (neither switch
    removes half of it: each path alone makes more than half) or "stalled" (neither switch
    removes half, and a path's rerun lost its heading).

    Parameters
    ----------
    row : mapping
        A row of :func:`.sea_analysis.attribution`.
    """
    if row["mechanism"]:
        return {"wave_hull": "hull", "wave_foil_flow": "foils"}[row["mechanism"]]
    if any(row[f"{name}_stalled"] for name in sea.PATHS):
        return "stalled"
    return "either"


PATH_WORDS = {"hull": "the hull", "foils": "the foils", "either": "either path alone", "stalled": "stalled"}


def path_counts(rows: pd.DataFrame) -> str:
    """How many differences take each path, e.g. "the hull 20, the foils 1 (of 21)".

    Parameters
    ----------
    rows : pandas.DataFrame
        Rows of :func:`.sea_analysis.attribution`.
    """
    if rows.empty:
        return "—"
    paths = [path_of(row) for _, row in rows.iterrows()]
    return ", ".join(f"{PATH_WORDS[p]} {paths.count(p)}" for p in PATH_WORDS if paths.count(p)) + \
        f" (of {len(paths)})"


def mechanism_text(s: SeaAnalysis, series: str, metric: str) -> str:
    """:func:`path_counts` of one series and metric.

    Parameters
    ----------
    s : SeaAnalysis
        The sea's numbers.
    series, metric : str
        A key of ``SERIES`` and one of its metrics.
    """
    return path_counts(_rows_of(s, series, metric))


def _switch(row, name: str) -> str:
    return f"{sea.MECHANISM_NAMES[name]} (`env.{name} = {_off(name)}` removes {_percent(row[f'{name}_removed'])})"


def _removals(row, names) -> str:
    """"`env.a = false` removes 12 % and `env.b = false` removes 80 %"."""
    return " and ".join(f"`env.{n} = {_off(n)}` removes {_percent(row[f'{n}_removed'])}" for n in names)


def named(row) -> str:
    """The path a difference takes and, where one explains it, the hull's refinement
    (:func:`.sea_analysis.attribution`), in words with their switches.

    Parameters
    ----------
    row : mapping
        A row of :func:`.sea_analysis.attribution`.
    """
    path, refinement = row["mechanism"], row.get("refinement", "")
    if path and row.get("path_alone", False):
        other = next(n for n in sea.PATHS if n != path)
        return (f"{sea.MECHANISM_NAMES[path]} alone (`env.{other} = {_off(other)}` removes "
                f"{_percent(row[f'{other}_removed'])}; with `env.{path} = {_off(path)}` the boat lost its heading)")
    if path and refinement and path == "wave_hull":
        return f"{_switch(row, path)}, chiefly {_switch(row, refinement)}"
    if path:
        return _switch(row, path)
    removed = {name: row[f"{name}_removed"] for name, _ in sea.MECHANISMS}
    finite = {k: v for k, v in removed.items() if np.isfinite(v)}
    if not finite:
        return "every rerun stalled" if all(row[f"{n}_stalled"] for n in removed) else "no rerun finished"
    paths = " and ".join(f"`env.{n} = {_off(n)}` {_percent(finite[n])}" for n in sea.PATHS if n in finite)
    if any(row[f"{n}_stalled"] for n in sea.PATHS):
        return f"not attributed: a path's rerun lost its heading (the other's switch removes {paths})"
    if refinement:
        return f"{_switch(row, refinement)}; each path alone makes more than half of it ({paths} removed)"
    return (f"either path alone makes more than half of it (their switches remove {paths}): the two "
            "do not add")


def _percent(share: float) -> str:
    return f"{round(100.0 * share)} %"  # an int: no "-0 %"


def _off(name: str) -> str:
    value = dict(sea.MECHANISMS)[name]
    return f'"{value}"' if isinstance(value, str) else str(value).lower()


def mechanisms_section(r, s: SeaAnalysis) -> None:
    """The report's section "Where each difference comes from": every difference by its path,
    the largest of each series and metric switch by switch, the cases left out.

    Parameters
    ----------
    r : studies.kit.Report
        The report being written.
    s : SeaAnalysis
        The sea's numbers.
    """
    names = ", ".join(f"`env.{name} = {_off(name)}`" for name, _ in sea.MECHANISMS)
    r.section("Where each difference comes from", (
        f"Every case with a difference beyond {100 * DIFFERENCE:g} % "
        f"is run again with each of the sea's mechanisms off in turn ({names}). The share "
        "of the difference a switch removes is 1 − (switched − calm)/(sea − calm). The sea reaches "
        "the boat by two paths, the hull (`env.wave_hull`) and the keel and rudder "
        "(`env.wave_foil_flow`); with both off the boat in a sea is the calm boat, to the bit. The "
        f"path whose switch removes at least {100 * EXPLAINS:g} % of the difference, the more of the "
        "two, is the one it takes; where neither does, each path alone makes more than half of the "
        "difference (the two do not add: each excites the same motion, or they cancel in part). The "
        "refinement of the hull's path (diffraction, damping relative to the water, the pressure's "
        "decay with depth) whose switch removes at least as much, the most, names the part of the "
        "hull's physics it comes from. Only cases where "
        "the calm run, the run in the sea and every switched run keep their heading are attributed: a "
        "switched run that loses it is marked stalled, its share not counted."))
    if s.mechanisms.empty:
        r.paragraph(f"No metric differs by more than {100 * DIFFERENCE:g} %.")
    else:
        r.paragraph("Every difference, by the path it takes and, where the hull's, by the refinement "
                    "that removes at least half of it:")
        r.table(_path_rows(s))
        either = [row for _, row in s.mechanisms.iterrows() if path_of(row) == "either"]
        if either:
            r.paragraph("Made by either path alone: " + "; ".join(
                f"{row['series']}, {row['case']}, {row['metric']} {row['calm']:.2f} → {row['sea']:.2f} "
                f"({_removals(row, sea.PATHS)})" for row in either) + ".")
        r.paragraph("The largest difference of each series and metric, each switch's share:")
        r.table(_largest_rows(s))
        idle = [name for name, _ in sea.MECHANISMS
                if (s.mechanisms[f"{name}_off"] == s.mechanisms["sea"]).all()]
        if idle:
            r.paragraph("Switched off, " + ", ".join(f"`env.{n} = {_off(n)}`" for n in idle)
                        + " leave" + ("s" if len(idle) == 1 else "") + " every metric of these reruns "
                        "as it is with the switch on, to the bit.")
    _left_out(r, s)


def _path_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for series, label in SERIES.items():
        for metric, (name, unit, _) in metrics_of(series).items():
            m = _rows_of(s, series, metric)
            if m.empty:
                continue
            paths = [path_of(row) for _, row in m.iterrows()]
            hull = m[[p == "hull" for p in paths]]
            finer = [sea.MECHANISM_NAMES[n] for n in hull["refinement"] if n]
            rows.append({"series": label, "metric": f"{name} [{unit}]", "differences": len(m),
                         **{(f"by {PATH_WORDS[p]}" if p != "stalled" else "not attributed (rerun stalled)"): paths.count(p)
                            for p in PATH_WORDS},
                         "of the hull's, chiefly": "; ".join(
                             f"{n}: {finer.count(n)}" for n in sorted(dict.fromkeys(finer), key=lambda n: -finer.count(n)))
                         or "no one refinement"})
    return rows


def _largest_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for _, m in s.mechanisms[s.mechanisms["largest"]].iterrows():
        row = {"series": m["series"], "case": m["case"], "metric": f"{m['metric']} [{m['unit']}]",
               "calm → sea": f"{m['calm']:.2f} → {m['sea']:.2f}"}
        for name, _ in sea.MECHANISMS:
            row[f"`env.{name} = {_off(name)}` removes"] = "stalled" if m[f"{name}_stalled"] else (
                _percent(m[f"{name}_removed"]) if np.isfinite(m[f"{name}_removed"]) else "—")
        row["explained by"] = named(m)
        rows.append(row)
    return rows


def _left_out(r, s: SeaAnalysis) -> None:
    lost = lost_cases(s.tables)
    if lost.empty:
        r.paragraph("Every case keeps its heading in calm water and in the sea: none is left out.")
        return
    r.paragraph(f"Left out: the {len(lost)} cases whose calm or sea run lost its heading (heading error RMS "
                f"over the window beyond {HEADING_LOST_DEG:g}°). Their difference is that of a boat off its "
                "course, not of one of the sea's mechanisms on a boat sailing it.")
    r.table([{"series": row["series"], "case": row["case"], "lost its heading": row["lost"],
              "heading error RMS, calm → sea [deg]": f"{row['heading_rms_calm']:.1f} → {row['heading_rms_sea']:.1f}",
              "speed or surge, calm → sea [m/s]": f"{row['speed_calm']:.2f} → {row['speed_sea']:.2f}"}
             for _, row in lost.iterrows()])
