"""Wille (2016a) §4, Table 2 and Figs. 4-5: the heading and the course controller, close-hauled.

The study in four parts: :mod:`.scenario` (the runs, as data, and the paper's numbers),
:mod:`.analysis` (each run's drift, the error reduction), :mod:`.figures` (Figs. 4-5 and the CSV
data) and :mod:`.report` (Table 2 against the paper, the switches and the causes they show).
"""

from __future__ import annotations

import functools
from pathlib import Path

from sailmujoco.study import Study, run_study

from ..kit import engine_for
from .analysis import analyse, headline
from .figures import write
from .report import markdown
from .scenario import NAME, jobs_for, runs

TITLE = "Wille (2016a) §4, Table 2 and Figs. 4-5: heading vs course controller, close-hauled"
# the scenario `sailmujoco study wille_course_table2 --video` films
VIDEO = {"boat": "wille_yacht", "task": "course_hold", "controller": "wille_course",
         "seconds": 60.0, "camera": "top", "control_timestep": 0.02}

STUDY = Study(NAME, TITLE, runs, analyse, write, functools.partial(markdown, TITLE), headline,
              video=VIDEO)

__all__ = ["NAME", "STUDY", "TITLE", "VIDEO", "jobs_for", "run"]


def run(out, smoke: bool = False, workers=None, progress: bool = True, video: bool = False,
        engine=None, resume: bool = False) -> dict:
    """Run the study into ``out`` (:func:`sailmujoco.study.run_study` on ``engine`` or one of
    its own); returns the headline numbers.

    Parameters
    ----------
    out : pathlib.Path
        The study's folder.
    smoke : bool
        The short pass.
    workers : int, optional
        Workers of the study's own engine (in this process for 1), when ``engine`` is not given.
    progress : bool
        Show progress on stderr.
    video : bool
        Unused here (the command line films :data:`VIDEO`).
    engine : sailmujoco.sweep.Engine, optional
        The worker pool to run on (left open).
    resume : bool
        Run only the simulations not stored in ``out`` yet.

    Returns
    -------
    dict
        The headline numbers.
    """
    with engine_for(engine, workers) as pool:
        return run_study(STUDY, Path(out), pool, smoke=smoke, resume=resume, progress=progress)
