"""Assumption validation in full 6-DOF: where the papers' simplifications hold, where they break,
and what it costs the controller.

The study, in the order it runs: :mod:`.scenario` (the boats, the switches, the runs as data;
its ``ABOUT`` opens the report), :mod:`.episodes` (the single scenarios and the time constants),
:mod:`.analysis` (the wind plane, each switch's effect, the headline numbers), :mod:`.figures`
(figures and CSV data), :mod:`.table` (one row per assumption) and :mod:`.report` (report.md).
"""

from __future__ import annotations

from functools import partial
from pathlib import Path

from sailmujoco import study, sweep

from .analysis import analyse
from .figures import write
from .report import report
from .scenario import NAME, VIDEO, runs
from .table import headline

TITLE = "Assumption validation in 6-DOF: where the papers' simplifications hold and where they break"

STUDY = study.Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write,
                    report=partial(report, title=TITLE), headline=headline, video=VIDEO)


def run(out, smoke: bool = False, workers: int | None = None, progress: bool = True, video: bool = False,
        engine: sweep.Engine | None = None, resume: bool = False) -> dict:
    """Run the study into ``out`` (:func:`sailmujoco.study.run_study`); its headline numbers.

    Parameters
    ----------
    out : path
        The study's folder.
    smoke : bool
        The short pass.
    workers : int, optional
        Worker processes of an engine of its own (1: in this process), when ``engine`` is None.
    progress : bool
        Show progress on stderr.
    video : bool
        Unused here (the command line films ``VIDEO``).
    engine : sailmujoco.sweep.Engine, optional
        The worker pool to run on (left open).
    resume : bool
        Run only the simulations not stored in ``out`` yet.
    """
    if engine is not None:
        return study.run_study(STUDY, Path(out), engine, smoke=smoke, resume=resume, progress=progress)
    with sweep.Engine("serial" if workers == 1 else None, workers) as own:
        return study.run_study(STUDY, Path(out), own, smoke=smoke, resume=resume, progress=progress)
