"""Assumption validation in full 6-DOF: where the papers' simplifications hold, where they break,
and what it costs the controller.

The study, in the order it runs: :mod:`.scenario` (the boats, the switches, the runs as data;
its ``ABOUT`` lists the scenarios in the report), :mod:`.episodes` (the single scenarios and the time constants),
:mod:`.analysis` (the wind plane, each switch's effect, the headline numbers), :mod:`.figures`
(figures and CSV data), :mod:`.table` (one row per assumption) and :mod:`.report` (report.md).
"""

from sailmujoco.study import Study

from .analysis import analyse
from .figures import write
from .report import report
from .scenario import NAME, TITLE, VIDEO, runs
from .table import headline

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, video=VIDEO)
