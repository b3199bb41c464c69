"""Viel, Vautier, Wan & Jaulin (2019) Fig. 3: position keeping in the six winds of §5.

The study, in the order it runs: :mod:`.scenario` (the paper's values, the worlds, the runs as
data; its ``ABOUT`` opens the report), :mod:`.switches` (one switching experiment, in a worker)
and :mod:`.measures` (what a run's samples show: the stop, the excursions after it),
:mod:`.analysis` (the tables and the headline numbers), :mod:`.figures` (figures and CSV data),
:mod:`.causes` and :mod:`.report` (the prose of report.md).
"""

from sailmujoco.study import Study

from .analysis import analyse, headline
from .figures import write
from .report import report
from .scenario import NAME, SEEDS_N, TITLE, VIDEO, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, video=VIDEO, seeds=SEEDS_N)
