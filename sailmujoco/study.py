"""What a study is: a declared object the study runner executes.

A study regenerates one paper artefact (a figure or a table) and writes ``results/<name>/``:
PNG figures, CSV data and ``report.md``. Each study module declares one :class:`Study`::

    STUDY = Study(
        name="saoud_fig6",
        title="Saoud (2015) Fig. 6: ...",
        runs=runs,            # (smoke, seeds) -> Runs: the simulations, as data
        analyse=analyse,      # (Results, smoke) -> the numbers; Results.seeds: the seeds run
        write=write,          # (analysis, out) -> None: figures and CSV data into out
        report=report,        # (analysis, smoke) -> the Markdown text of report.md
        headline=headline,    # analysis -> {name: number}, printed and asserted by the tests
        seeds=5,              # N: every stochastic case runs on seeds 0..N-1
    )

and registers it under the ``sailmujoco.studies`` entry points (``name = "module:STUDY"``), so
``sailmujoco study NAME`` finds it without the library importing any study.

The runner (:func:`run_study`) executes the study's :class:`Runs` on the sweep engine, stores
every result under the study's folder as it finishes (``sweeps/...`` and ``jobs/<name>``, so
``resume`` runs only what is missing), then calls ``analyse``, ``write`` and ``report`` in that
order. A study whose second pass depends on the first (a finer grid around the best coarse
point) declares ``more_runs``: its runs are executed after the first pass and merged into the
same :class:`Results`.

**Seeds.** Every stochastic run (gusts, wind wander, the sea's phases, start jitter) is a case
times a seed. A study declares its N (``seeds``: the number that decides its headline verdicts
within the time ``study all`` may take); a smoke pass runs :data:`SMOKE_SEEDS`; ``sailmujoco study
--seeds N`` overrides both. The runner hands ``runs`` the seeds ``0 .. N-1`` and keeps every seed's
row; the analysis reads them from :attr:`Results.seeds` and states each number over them as a mean
with its interval (:mod:`sailmujoco.stats`).
"""

from __future__ import annotations

import inspect
import shutil
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from . import sweep

SMOKE_SEEDS = 2  # the seeds of a smoke pass: enough for an interval to exist
MAX_SEEDS = 1000  # the most seeds ``--seeds`` accepts


@dataclass(frozen=True)
class Runs:
    """A study's simulations as data.

    Parameters
    ----------
    sweeps : tuple of (dict, str)
        ``(sweep spec, folder)`` pairs; each sweep is stored in ``out/<folder>`` (a path relative
        to the study's folder) and its table is ``Results.sweeps[folder]``.
    jobs : mapping of str to (str, list)
        ``name -> ("package.module:function", items)``: ``function(item)`` for every JSON-able
        item, on the engine's workers; stored in ``out/jobs/<name>``, the results (in the order
        of the items) are ``Results.jobs[name]``.
    label : str
        Names the progress bar of these runs.
    """

    sweeps: tuple[tuple[dict, str], ...] = ()
    jobs: Mapping[str, tuple[str, list]] = field(default_factory=dict)
    label: str = "simulations"

    def __bool__(self) -> bool:
        return bool(self.sweeps) or bool(self.jobs)


@dataclass(frozen=True)
class Results:
    """What a study's runs returned.

    Parameters
    ----------
    sweeps : dict of str to pandas.DataFrame
        Each sweep's table (:func:`sailmujoco.sweep.run`), by its folder.
    jobs : dict of str to list
        Each job list's results, by its name, in the order of its items.
    seconds : float
        Wall time of the runs (all passes), for the report.
    root : pathlib.Path, optional
        The study's folder, where the sweeps' stores are (:meth:`records` reads them).
    seeds : tuple of int
        The seeds every stochastic case ran on (``0 .. N-1``).
    """

    sweeps: dict = field(default_factory=dict)
    jobs: dict = field(default_factory=dict)
    seconds: float = 0.0
    root: Path | None = None
    seeds: tuple = (0,)

    def records(self, folder: str) -> list[dict]:
        """The run records a sweep stored (parameters, metrics, the trajectory where its spec
        asks for one), in the order of its table's rows (the sweep's run order), read on demand.

        Parameters
        ----------
        folder : str
            The sweep's folder, as its :class:`Runs` entry names it.
        """
        stored = sweep.ResultStore(Path(self.root) / folder).done()
        return [stored[run_id] for run_id in self.sweeps[folder]["run_id"] if run_id in stored]

    def merged(self, other: Results) -> Results:
        """These results and ``other``'s together (``other`` wins a name held by both).

        Parameters
        ----------
        other : Results
            The results of a later pass.
        """
        return Results({**self.sweeps, **other.sweeps}, {**self.jobs, **other.jobs},
                       self.seconds + other.seconds, self.root or other.root, self.seeds)


@dataclass(frozen=True)
class Study:
    """One study, declared (see the module docstring for the order its parts are called in).

    Parameters
    ----------
    name : str
        The study's name: its folder under results/ and its name on the command line.
    title : str
        One line: the paper, the artefact and what it shows.
    runs : callable
        ``runs(smoke, seeds) -> Runs``: the simulations of the first pass, each stochastic case on
        every seed of ``seeds`` (a tuple of int); ``runs(smoke)`` for a study with none.
    analyse : callable
        ``analyse(results, smoke) -> analysis``: the study's numbers from its :class:`Results`.
    write : callable
        ``write(analysis, out)``: figures (PNG) and data (CSV) into the folder ``out``.
    report : callable
        ``report(analysis, smoke) -> str``: the Markdown of ``report.md``, prose filled from the
        analysis, the papers' values from the module's ``PAPER_*`` constants.
    headline : callable
        ``headline(analysis) -> dict``: the headline numbers (printed after the study, asserted
        by the tests in smoke mode).
    more_runs : callable, optional
        ``more_runs(results, smoke) -> Runs``: a second pass chosen from the first's results.
    video : mapping, optional
        The scenario ``--video`` films (:func:`sailmujoco.video.record_study_scenario`'s keywords).
    seeds : int
        N, the seeds of the full pass: the number that decides the study's headline verdicts
        within its share of ``study all``'s time (1 for a study with nothing stochastic).
    """

    name: str
    title: str
    runs: Callable[[bool], Runs]
    analyse: Callable[[Results, bool], Any]
    write: Callable[[Any, Path], None]
    report: Callable[[Any, bool], str]
    headline: Callable[[Any], dict]
    more_runs: Callable[[Results, bool], Runs] | None = None
    video: Mapping | None = None
    seeds: int = 1

    def seeds_for(self, smoke: bool, override: int | None = None) -> tuple[int, ...]:
        """The seeds a pass runs: ``0 .. N-1``, N from ``override`` (``--seeds``), else
        :data:`SMOKE_SEEDS` for a smoke pass (at most the study's own N), else :attr:`seeds`.

        Parameters
        ----------
        smoke : bool
            The short pass.
        override : int, optional
            ``--seeds N`` (1 to :data:`MAX_SEEDS`).
        """
        n = override if override is not None else min(SMOKE_SEEDS, self.seeds) if smoke else self.seeds
        return tuple(range(int(n)))


def _first_runs(study: Study, smoke: bool, seeds: tuple) -> Runs:
    """The study's first pass: ``runs(smoke, seeds)``, or ``runs(smoke)`` where it takes no seeds."""
    if len(inspect.signature(study.runs).parameters) >= 2:
        return study.runs(smoke, seeds)
    return study.runs(smoke)


def execute(runs: Runs, out: Path, engine: sweep.Engine, *, resume: bool = False,
            progress: bool = True, label: str | None = None) -> Results:
    """Run ``runs`` on ``engine``, all queued together, stored under ``out``.

    Folders and stores are cleared first (fresh results) unless ``resume``: then only what is not
    stored yet runs (a folder holding another sweep, e.g. a smoke run's, is cleared: nothing of it
    to resume).

    Parameters
    ----------
    runs : Runs
        The sweeps and job lists.
    out : pathlib.Path
        The study's folder.
    engine : sailmujoco.sweep.Engine
        The worker pool (left open).
    resume : bool
        Keep what is stored and run the rest.
    progress : bool
        Show progress on stderr.
    label : str, optional
        Names the progress bar (``runs.label`` if not given).
    """
    out = Path(out)
    start = time.perf_counter()
    sweeps = [(spec, out / folder) for spec, folder in runs.sweeps]
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
    for name, (function, items) in runs.jobs.items():
        store = out / "jobs" / name
        if not resume:
            shutil.rmtree(store, ignore_errors=True)
        stores.append((function, list(items), store))
    if not sweeps and not stores:
        return Results(root=out)
    tables, results = sweep.run_many(sweeps, stores, engine=engine, resume=resume,
                                     progress=progress, label=label or runs.label)
    return Results({folder: table for (_, folder), table in zip(runs.sweeps, tables, strict=True)},
                   dict(zip(runs.jobs, results, strict=True)), time.perf_counter() - start, out)


def run_study(study: Study, out: Path, engine: sweep.Engine, *, smoke: bool = False,
              resume: bool = False, progress: bool = True, seeds: int | None = None) -> dict:
    """Run one study into ``out``: its runs, analysis, figures and data, report.

    Parameters
    ----------
    study : Study
        The declared study.
    out : pathlib.Path
        Its folder (created if missing).
    engine : sailmujoco.sweep.Engine
        The worker pool its simulations run on.
    smoke : bool
        The study's short pass (for tests and a quick look).
    resume : bool
        Run only the simulations not stored in ``out`` yet.
    progress : bool
        Show progress on stderr.
    seeds : int, optional
        N, in place of the study's own (:meth:`Study.seeds_for`).

    Returns
    -------
    dict
        The study's headline numbers.
    """
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    chosen = study.seeds_for(smoke, seeds)
    results = execute(_first_runs(study, smoke, chosen), out, engine, resume=resume, progress=progress)
    results = replace(results, seeds=chosen)
    if study.more_runs is not None:
        more = study.more_runs(results, smoke)
        if more:
            results = results.merged(execute(more, out, engine, resume=resume, progress=progress))
    analysis = study.analyse(results, smoke)
    study.write(analysis, out)
    (out / "report.md").write_text(study.report(analysis, smoke))
    return study.headline(analysis)
