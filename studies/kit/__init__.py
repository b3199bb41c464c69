"""What every study shares: running an episode, the Markdown report, figures, verdicts.

A study declares a :class:`sailmujoco.study.Study` (its runs as data, its analysis, figures and
report) and registers it under the ``sailmujoco.studies`` entry points; the study runner
(:mod:`sailmujoco.study_runner`) executes its runs on the sweep engine and calls the rest. The
job functions its runs name (``"package.module:function"``) call :func:`run_episode`; its
report is a :class:`Report`; :mod:`.verdict` states how far ours is from the paper's.
Modules of this package hold what several studies of one paper share (:mod:`.saoud`).

A study still written as one script registers its ``run(out, smoke, workers, progress, video,
engine, resume) -> dict`` instead; its simulations go through :func:`run_batch`,
:func:`run_jobs` and :func:`run_sweep` on :func:`engine_for`'s engine, stored under ``out``
(``resume`` runs only what is not stored there yet).
"""

from __future__ import annotations

import contextlib
import math
import shutil
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

    Parameters
    ----------
    title : str
        The report's title (its first heading).
    parts : list of str
        The Markdown blocks added so far, in order (empty to start).
    """

    title: str
    parts: list = field(default_factory=list)

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

    def write(self, out: Path) -> Path:
        """Write :meth:`text` to ``out/report.md``; returns its path.

        Parameters
        ----------
        out : pathlib.Path
            The study's folder.
        """
        path = Path(out) / "report.md"
        path.write_text(self.text())
        return path


def _cell(value) -> str:
    if value is None:
        return "—"
    if isinstance(value, float):
        if not math.isfinite(value):
            return "—"
        return f"{value:.3g}"
    return str(value).replace("|", "\\|")


@contextlib.contextmanager
def engine_for(engine: sweep.Engine | None, workers: int | None):
    """``engine`` if given (left open), else an engine of this study's own, closed at the end: in
    this process for ``workers=1``, else an embedded cluster of ``workers`` processes.

    Parameters
    ----------
    engine : sailmujoco.sweep.Engine or None
        An engine to use.
    workers : int, optional
        Worker processes of an engine of its own.
    """
    if engine is not None:
        yield engine
        return
    with sweep.Engine("serial" if workers == 1 else None, workers) as own:
        yield own


def run_batch(engine: sweep.Engine, out: Path, *, sweeps: list = (), jobs: list = (),
              resume: bool = False, progress: bool = True, label: str = "simulations") -> tuple[list, list]:
    """Sweeps and job lists queued together on the engine (:func:`sailmujoco.sweep.run_many`);
    returns (each sweep's table, each job list's results in input order).

    ``sweeps``: ``(spec, folder)`` pairs, one folder per sweep; ``jobs``: ``(function, jobs,
    name)`` triples (``"package.module:function"``, its JSON-able jobs), stored in
    ``out/jobs/<name>``. Folders and stores are cleared first (fresh results) unless
    ``resume``: then only what is not stored yet runs (a folder holding another sweep, e.g. a
    smoke run's, is cleared: nothing of it to resume).

    Parameters
    ----------
    engine : sailmujoco.sweep.Engine
        The worker pool.
    out : pathlib.Path
        The study's folder.
    sweeps : list of (dict, pathlib.Path)
        Sweep specs and their folders.
    jobs : list of (str, list, str)
        Job function, its items and the store's name.
    resume : bool
        Keep what is stored and run the rest.
    progress : bool
        Show progress on stderr.
    label : str
        Names the progress bar.
    """
    for spec, folder in sweeps:
        same = False
        if resume:
            try:
                sweep.check_folder(sweep.validate(spec), folder)
                same = True
            except sweep.SweepError:
                same = False
        if not same:
            shutil.rmtree(folder, ignore_errors=True)
    stores = []
    for function, items, name in jobs:
        store = Path(out) / "jobs" / name
        if not resume:
            shutil.rmtree(store, ignore_errors=True)
        stores.append((function, items, store))
    return sweep.run_many(list(sweeps), stores, engine=engine, resume=resume, progress=progress,
                          label=label)


def run_jobs(function: str, jobs: list, out: Path, engine: sweep.Engine, *, resume: bool = False,
             progress: bool = True, label: str = "simulations") -> list:
    """``[function(job) for job in jobs]`` on the engine, stored in ``out/jobs/<label>``
    (:func:`run_batch`).

    Parameters
    ----------
    function : str
        ``"package.module:function"``.
    jobs : list
        Its JSON-able items.
    out : pathlib.Path
        The study's folder.
    engine : sailmujoco.sweep.Engine
        The worker pool.
    resume : bool
        Keep what is stored and run the rest.
    progress : bool
        Show progress on stderr.
    label : str
        Names the store and the progress bar.
    """
    return run_batch(engine, out, jobs=[(function, jobs, label)], resume=resume, progress=progress,
                     label=label)[1][0]


def run_sweep(spec: dict, folder: Path, engine: sweep.Engine, *, resume: bool = False,
              progress: bool = True):
    """One sweep into ``folder`` on the engine (:func:`run_batch`); its table.

    Parameters
    ----------
    spec : dict
        The sweep.
    folder : pathlib.Path
        Its folder.
    engine : sailmujoco.sweep.Engine
        The worker pool.
    resume : bool
        Keep what is stored and run the rest.
    progress : bool
        Show progress on stderr.
    """
    return run_batch(engine, Path(folder).parent, sweeps=[(spec, folder)], resume=resume,
                     progress=progress, label=f"sweep {spec['name']}")[0][0]


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
