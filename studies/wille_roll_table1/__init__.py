"""Wille (2016b) §5 Table 1, Figs. 3 and 5-8: roll stabilisation by the sail.

The study in five parts: :mod:`.scenario` (the runs, as data, and the paper's numbers),
:mod:`.analysis` (each run's numbers, the seed means, the moment shares and the Fig. 8 optima),
:mod:`.figures` (the figures and the CSV data), :mod:`.report` (the comparison with the paper)
and :mod:`.causes` (the cause of each difference, each checked by a switch). The beam reach
itself is :mod:`studies.kit.wille`'s Table 1 scenario.
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

TITLE = "Wille (2016b) §5 Table 1, Figs. 3 and 5-8: roll stabilisation by the sail"
# the scenario `sailmujoco study wille_roll_table1 --video` films
VIDEO = {"boat": "wille_yacht", "task": "beam_reach_roll", "controller": "wille_roll",
         "seconds": 60.0, "controller_options": {"wind": "perfect"}}

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
