"""Wille (2016a) §4, Table 2 and Figs. 4-5: the heading and the course controller, close-hauled.

The study in four parts: :mod:`.scenario` (the runs, as data, and the paper's numbers),
:mod:`.analysis` (each run's drift; over the seeds, each number's interval, the error reduction,
the worlds paired by seed and the verdicts), :mod:`.figures` (Figs. 4-5 over the seeds, Table 2's
intervals and the CSV data) and :mod:`.report` (Table 2 against the paper, the switches and the
causes they show).
"""

from sailmujoco.study import Study

from .analysis import analyse, headline
from .figures import write
from .report import report
from .scenario import NAME, SEEDS, TITLE, VIDEO, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, video=VIDEO, seeds=SEEDS)
