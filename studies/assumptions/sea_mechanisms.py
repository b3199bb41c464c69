"""Assumption validation, the sea's part of the report: where each difference comes from.

Each difference a sea makes (:func:`.sea_attribution.attribution`) takes one of the sea's two
paths into the boat, the hull or the keel and rudder (:data:`.sea.PATHS`), decided on the
mechanism reruns' seeds: :func:`path_of` says which, :func:`path_counts` how many per series and
metric, :func:`named` in words with the switches that show it, and :func:`mechanisms_section`
writes the report's section.
"""

from __future__ import annotations

import math

import pandas as pd

from . import sea
from .sea_analysis import SeaAnalysis
from .sea_attribution import EXPLAINS
from .sea_attribution import removed_interval as _removed
from .sea_cases import DIFFERENCE, HEADING_LOST_DEG, SERIES, lost_cases, metrics_of


def paths(s: SeaAnalysis) -> list[str]:
    """The path of every difference that breaks (:func:`path_of`).

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
    """Which of the sea's paths a difference takes: "hull", "foils" (its switch surely removes
    more than half of it, or the other's surely at most half where this one's rerun lost its
    heading), "either" (each switch surely removes at most half: each path alone makes more than
    half), "stalled" (a path's rerun lost its heading, and the other's share does not decide) or
    "undecided" (a share's interval straddles one half).

    Parameters
    ----------
    row : mapping
        A row of :func:`.sea_attribution.attribution` (``path``: :func:`.sea_attribution.path_taken`).
    """
    return row["path"].replace(" alone", "")


PATH_WORDS = {"hull": "the hull", "foils": "the foils", "either": "either path alone",
              "stalled": "stalled", "undecided": "undecided"}


def _undecided(s: SeaAnalysis) -> str:
    n = sorted({int(v) for v in s.mechanisms["n"]}) if not s.mechanisms.empty else [0]
    return f"undecided at {'-'.join(str(v) for v in dict.fromkeys([n[0], n[-1]]))} seeds"


def path_counts(rows: pd.DataFrame) -> str:
    """How many differences take each path, e.g. "the hull 20, the foils 1 (of 21)".

    Parameters
    ----------
    rows : pandas.DataFrame
        Rows of :func:`.sea_attribution.attribution`.
    """
    if rows.empty:
        return "—"
    taken = [path_of(row) for _, row in rows.iterrows()]
    return ", ".join(f"{PATH_WORDS[p]} {taken.count(p)}" for p in PATH_WORDS if taken.count(p)) + \
        f" (of {len(taken)})"


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


def share_text(row, name: str) -> str:
    """The share switch ``name`` removes, in per cent: ``mean [low, high] %`` (or "stalled").

    Parameters
    ----------
    row : mapping
        A row of :func:`.sea_attribution.attribution`.
    name : str
        A mechanism of :data:`.sea.MECHANISMS`.
    """
    if row[f"{name}_n"] and row[f"{name}_stalled"] == row[f"{name}_n"]:
        return "stalled"
    got = _removed(row, name)
    if not math.isfinite(got.mean):
        return "—"
    scaled = type(got)(100 * got.mean, 100 * got.low, 100 * got.high, got.n, got.method)
    return scaled.fixed(0, "%")


def _switch(row, name: str) -> str:
    return f"{sea.MECHANISM_NAMES[name]} (`env.{name} = {_off(name)}` removes {share_text(row, name)})"


def named(row) -> str:
    """The path a difference takes and, where one explains it, the hull's refinement
    (:func:`.sea_attribution.attribution`), in words with their switches.

    Parameters
    ----------
    row : mapping
        A row of :func:`.sea_attribution.attribution`.
    """
    path, refinement = row["mechanism"], row.get("refinement", "")
    taken = row["path"]
    if taken.endswith(" alone"):
        lost = "wave_hull" if taken.startswith("hull") else "wave_foil_flow"
        other = next(n for n in sea.PATHS if n != lost)
        return (f"{sea.MECHANISM_NAMES[lost]} alone (`env.{other} = {_off(other)}` removes "
                f"{share_text(row, other)}; with `env.{lost} = {_off(lost)}` the boat lost its heading)")
    if path and refinement and path == "wave_hull":
        return f"{_switch(row, path)}, chiefly {_switch(row, refinement)}"
    if path:
        return _switch(row, path)
    both = " and ".join(f"`env.{n} = {_off(n)}` {share_text(row, n)}" for n in sea.PATHS)
    if taken == "stalled":
        return f"not attributed: a path's rerun lost its heading ({both})"
    if taken == "either":
        return f"either path alone makes more than half of it (their switches remove {both}): the two do not add"
    return f"undecided at {int(row['n'])} seeds ({both} removed)"


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
    paths_off = ", ".join(f"`env.{name} = {_off(name)}`" for name in sea.PATHS)
    refined = int(s.mechanisms["largest"].sum()) if not s.mechanisms.empty else 0
    fewer = (f" (fewer seeds than the cases' {len(s.seeds)}: the reruns' budget)"
             if sea.MECHANISM_SEEDS < len(s.seeds) else "")
    r.section("Where each difference comes from", (
        f"Every case with a difference that breaks the ±{100 * DIFFERENCE:g} % band is run again, on its "
        f"first {sea.MECHANISM_SEEDS} seeds on which both runs kept their heading{fewer}, with each of the sea's two paths into the boat off "
        f"in turn ({paths_off}); the largest difference of each series and metric also with the hull's "
        "refinements off, as far as the sea's budget of simulated time allows (all mechanisms: "
        f"{names}). The share of the difference a switch removes is 1 − (switched − calm)/(sea − calm), "
        "seed by seed, given as its mean with its 95 % interval over those seeds. The sea reaches "
        "the boat by two paths, the hull (`env.wave_hull`) and the keel and rudder "
        "(`env.wave_foil_flow`); with both off the boat in a sea is the calm boat, to the bit. The "
        f"path whose share's interval lies wholly above {100 * EXPLAINS:g} %, the more of the two, is the "
        f"one it takes; where both lie wholly below, each path alone makes more than half of the "
        "difference (the two do not add: each excites the same motion, or they cancel in part); where "
        "an interval straddles the half, the path is undecided at those seeds. The refinement of the "
        "hull's path (diffraction, damping relative to the water, the pressure's decay with depth) "
        "whose share lies wholly above the half, the most, names the part of the hull's physics it "
        "comes from. A switched run that loses its heading is marked stalled, its seed not counted."))
    if s.mechanisms.empty:
        r.paragraph(f"No metric's difference breaks the ±{100 * DIFFERENCE:g} % band.")
    else:
        r.paragraph("Every difference that breaks, by the path it takes and, where the hull's, by the "
                    "refinement that surely removes more than half of it (refinements rerun for "
                    f"{refined} differences, the largest of their series and metric):")
        r.table(_path_rows(s))
        either = [row for _, row in s.mechanisms.iterrows() if path_of(row) == "either"]
        if either:
            r.paragraph("Made by either path alone: " + "; ".join(
                f"{row['series']}, {row['case']}, {row['metric']} ({named(row)})" for row in either) + ".")
        r.paragraph("The largest difference of each series and metric, each switch's share (— : not rerun):")
        r.table(_largest_rows(s))
    _left_out(r, s)


def _path_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for series, label in SERIES.items():
        for metric, (name, unit, _) in metrics_of(series).items():
            m = _rows_of(s, series, metric)
            if m.empty:
                continue
            taken = [path_of(row) for _, row in m.iterrows()]
            hull = m[[p == "hull" for p in taken]]
            finer = [sea.MECHANISM_NAMES[n] for n in hull["refinement"] if n]
            rows.append({"series": label, "metric": f"{name} [{unit}]", "differences that break": len(m),
                         **{(f"by {PATH_WORDS[p]}" if p not in ("stalled", "undecided")
                             else "not attributed (rerun stalled)" if p == "stalled" else _undecided(s)):
                            taken.count(p) for p in PATH_WORDS},
                         "of the hull's, chiefly": "; ".join(
                             f"{n}: {finer.count(n)}" for n in sorted(dict.fromkeys(finer), key=lambda n: -finer.count(n)))
                         or "no one refinement"})
    return rows


def _largest_rows(s: SeaAnalysis) -> list[dict]:
    rows = []
    for _, m in s.mechanisms[s.mechanisms["largest"]].iterrows():
        row = {"series": m["series"], "case": m["case"], "metric": f"{m['metric']} [{m['unit']}]",
               f"calm → sea (N={int(m['n_kept'])})": f"{_value(m, 'calm')} → {_value(m, 'sea')}",
               "seeds rerun": m["mechanism_seeds"]}
        for name, _ in sea.MECHANISMS:
            row[f"`env.{name} = {_off(name)}` removes"] = share_text(m, name) if m[f"{name}_n"] else "—"
        row["explained by"] = named(m)
        rows.append(row)
    return rows


def _value(row, column: str) -> str:
    from sailmujoco import stats

    got = stats.Interval(float(row[column]), float(row[f"{column}_low"]), float(row[f"{column}_high"]),
                         int(row["n_kept"]))
    return got.fixed(2)


def _left_out(r, s: SeaAnalysis) -> None:
    lost = lost_cases(s.tables)
    if lost.empty:
        r.paragraph("Every case keeps its heading on every seed, in calm water and in the sea: no seed is left out.")
        return
    r.paragraph(f"Left out: the seeds on which the calm or the sea run lost its heading (heading error RMS "
                f"over the window beyond {HEADING_LOST_DEG:g}°), in {len(lost)} cases. Their difference is that of "
                "a boat off its course, not of one of the sea's mechanisms on a boat sailing it; a case's "
                "numbers are over its other seeds.")
    r.table([{"series": row["series"], "case": row["case"],
              "seeds lost, calm / sea (of N)": f"{row['lost_calm']} / {row['lost_sea']} (of {row['n']})",
              "heading error RMS, calm → sea [deg]": f"{row['heading_rms_calm'].fixed(1)} → "
                                                    f"{row['heading_rms_sea'].fixed(1)}"}
             for _, row in lost.iterrows()])

