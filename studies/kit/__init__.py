"""What every study shares: running an episode, the Markdown report, figures, verdicts.

A study declares a :class:`sailmujoco.study.Study` (its runs as data, its analysis, figures and
report) and registers it under the ``sailmujoco.studies`` entry points; the study runner
(:mod:`sailmujoco.cli.study`) executes its runs on the sweep engine and calls the rest.

This package gives those parts their common pieces: :func:`run_episode` (one episode, for the
job functions a study's runs name as ``"package.module:function"``), :class:`Report` (the
Markdown of report.md), :func:`setup_matplotlib` and :func:`save_figure` (the figures),
:func:`timer` (a wall clock) and :mod:`.verdict` (how far ours is from the paper's). Its other
modules hold what the studies of one paper share: :mod:`.saoud` and :mod:`.wille`.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from pathlib import Path

from sailmujoco import suite, sweep

from . import verdict


def run_episode(boat: str, task: str, world: str, controller, *, seed: int = 0,
                controller_options: dict | None = None, **options):
    """One episode; returns (metrics dict, per-step DataFrame, env).

    Parameters
    ----------
    boat, task, world : str
        A registered boat, task and world (:func:`sailmujoco.suite.load`).
    controller : str or callable
        A registered name (see ``sailmujoco.sweep.controller_factories``) or a callable
        ``factory(env) -> controller``.
    seed : int
        Seeds the initial state and the wind.
    controller_options : dict, optional
        Options of a registered controller.
    **options
        Further keywords of :func:`sailmujoco.suite.load`.
    """
    env = suite.load(boat, task, world, seed=seed, **options)
    if isinstance(controller, str):
        policy = sweep.make_controller(controller, env, **(controller_options or {}))
    else:
        policy = controller(env)
    trajectory = suite.rollout(env, policy)
    return env.task.metrics(), trajectory, env


@dataclass
class Report:
    """A Markdown report: paragraphs, tables of paper vs ours, figures.

    Every study's report reads the same way: the title, a :meth:`summary` (its numbers filled
    from the analysis), the study's main table, then the explanations, each under a
    :meth:`section` heading.

    Parameters
    ----------
    title : str
        The report's title (its first heading).
    parts : list of str
        The Markdown blocks added so far, in order (empty to start).
    """

    title: str
    parts: list = field(default_factory=list)

    def summary(self, text: str) -> None:
        """Open the report with its "Summary" section: at most :data:`SUMMARY_WORDS` words of
        prose, the main table to follow it (add that table next).

        Parameters
        ----------
        text : str
            The summary's Markdown, its numbers filled from the analysis.
        """
        self.parts.append("## Summary\n")
        self.paragraph(text)

    def section(self, heading: str, text: str = "") -> None:
        """Start a section (a level-2 heading), with its first paragraph if given.

        Parameters
        ----------
        heading : str
            The section's heading, without the ``##``.
        text : str
            Its first paragraph (none if empty).
        """
        self.parts.append(f"## {heading}\n")
        if text:
            self.paragraph(text)

    def paragraph(self, text: str) -> None:
        """Add a paragraph.

        Parameters
        ----------
        text : str
            Its Markdown (stripped; one blank line follows).
        """
        self.parts.append(text.strip() + "\n")

    def table(self, rows: list[dict], columns: list[str] | None = None) -> None:
        """Add a Markdown table (nothing for no rows); floats to 3 significant digits.

        Parameters
        ----------
        rows : list of dict
            One dict per row, column -> value.
        columns : list of str, optional
            The columns, in order (the first row's keys if not given).
        """
        if not rows:
            return
        columns = columns or list(rows[0])
        lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
        for row in rows:
            lines.append("| " + " | ".join(_cell(row.get(c, "")) for c in columns) + " |")
        self.parts.append("\n".join(lines) + "\n")

    def comparison(self, rows: list[dict]) -> None:
        """Rows of quantity / paper / world / ours / cause, with the difference of
        :func:`studies.kit.verdict.difference` (a row may give its ``floor`` and ``unit``), flagged ⚠
        beyond 10 %.

        Parameters
        ----------
        rows : list of dict
            quantity, world, paper, ours, cause (and optionally floor and unit) of each row.
        """
        table = []
        for row in rows:
            diff = verdict.difference(row["ours"], row.get("paper"), floor=row.get("floor", 0.0),
                                      unit=row.get("unit", ""))
            flag = " ⚠" if diff.finite and diff.beyond(verdict.TOLERANCE) else ""
            table.append({**row, "difference": diff.text() + flag})
        self.table(table, ["quantity", "world", "paper", "ours", "difference", "cause"])
        self.paragraph(verdict.DIFFERENCE_NOTE)

    def figure(self, path: Path, caption: str) -> None:
        """Add a figure beside the report, with its caption.

        Parameters
        ----------
        path : str or pathlib.Path
            The figure (its name is linked: it lies in the report's folder).
        caption : str
            The caption, in italics below it.
        """
        self.parts.append(f"![{caption}]({Path(path).name})\n\n*{caption}*\n")

    def text(self) -> str:
        """The report as Markdown: the title, then the parts in order."""
        return f"# {self.title}\n\n" + "\n".join(self.parts)


SUMMARY_WORDS = 200  # the most words of prose in a report's "Summary" section


def _cell(value) -> str:
    if value is None:
        return "—"
    if isinstance(value, float):
        if not math.isfinite(value):
            return "—"
        return f"{value:.3g}"
    return str(value).replace("|", "\\|")


def setup_matplotlib():
    """matplotlib.pyplot for a study's figures (Agg, constrained layout, the package's style)."""
    from sailmujoco import figures

    return figures.pyplot()


def save_figure(fig, path: Path) -> Path:
    """Check (:func:`sailmujoco.figures.problems`), write with nothing clipped, close; returns
    its path.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : pathlib.Path
        The PNG written.
    """
    from sailmujoco import figures

    return figures.save(fig, path)


def timer():
    """A clock started now: calling it gives the seconds since."""
    start = time.perf_counter()
    return lambda: time.perf_counter() - start
