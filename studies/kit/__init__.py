"""What every study shares: running an episode, the Markdown report, progress.

A study is a module of this package with::

    NAME = "saoud_fig6"
    TITLE = "..."
    def run(out: Path, smoke: bool = False, workers: int | None = None,
            progress: bool = True, video: bool = False, engine=None, resume: bool = False) -> dict

``run`` writes PNG figures, CSV data and ``report.md`` into ``out`` (results/<study>/) and
returns the headline numbers (the tests assert on them in smoke mode). It is registered under
the ``sailmujoco.studies`` entry points, so ``sailmujoco study NAME`` finds it.

Its simulations are sweeps and jobs (:func:`run_jobs`) on the sweep engine: on ``engine``
(:class:`sailmujoco.sweep.Engine`, the one worker pool of ``sailmujoco study all``), else on
one of its own (:func:`engine_for`: in this process for ``workers=1``). Their results are stored
under ``out``; ``resume`` runs only what is not stored there yet (an interrupted run's rest).
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

    ``controller`` is a registered name (see ``sailmujoco.sweep.controller_factories``) or a
    callable ``factory(env) -> controller``. ``options`` go to :func:`sailmujoco.suite.load`.
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
    """A Markdown report: paragraphs, tables of paper vs ours, figures."""

    title: str
    parts: list = field(default_factory=list)

    def paragraph(self, text: str) -> None:
        self.parts.append(text.strip() + "\n")

    def table(self, rows: list[dict], columns: list[str] | None = None) -> None:
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
        beyond 10 %."""
        table = []
        for row in rows:
            diff = verdict.difference(row["ours"], row.get("paper"), floor=row.get("floor", 0.0),
                                      unit=row.get("unit", ""))
            flag = " ⚠" if diff.finite and diff.beyond(verdict.TOLERANCE) else ""
            table.append({**row, "difference": diff.text() + flag})
        self.table(table, ["quantity", "world", "paper", "ours", "difference", "cause"])
        self.paragraph(verdict.DIFFERENCE_NOTE)

    def figure(self, path: Path, caption: str) -> None:
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
    this process for ``workers=1``, else an embedded cluster of ``workers`` processes."""
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
    smoke run's, is cleared: nothing of it to resume)."""
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
    (:func:`run_batch`)."""
    return run_batch(engine, out, jobs=[(function, jobs, label)], resume=resume, progress=progress,
                     label=label)[1][0]


def run_sweep(spec: dict, folder: Path, engine: sweep.Engine, *, resume: bool = False,
              progress: bool = True):
    """One sweep into ``folder`` on the engine (:func:`run_batch`); its table."""
    return run_batch(engine, Path(folder).parent, sweeps=[(spec, folder)], resume=resume,
                     progress=progress, label=f"sweep {spec['name']}")[0][0]


def setup_matplotlib():
    """matplotlib.pyplot for a study's figures (Agg, constrained layout, the package's style)."""
    from sailmujoco import figures

    return figures.pyplot()


def save_figure(fig, path: Path) -> Path:
    """Check (:func:`sailmujoco.figures.problems`), write with nothing clipped, close; returns
    its path."""
    from sailmujoco import figures

    return figures.save(fig, path)


def timer():
    start = time.perf_counter()
    return lambda: time.perf_counter() - start
