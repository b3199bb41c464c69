"""Assumption validation in full 6-DOF: where the papers' simplifications hold, where they break,
and what it costs the controller.

The study, in the order it runs: :mod:`.scenario` (the boats, the switches, the runs as data;
its ``ABOUT`` lists the scenarios in the report), :mod:`.episodes` (the single scenarios and the time constants),
:mod:`.analysis` (the wind plane, each switch's effect, the headline numbers), :mod:`.figures`
(figures and CSV data), :mod:`.table` (one row per assumption) and :mod:`.report` (report.md).
What a sea does to the boats: :mod:`.sea` (its runs), :mod:`.sea_analysis` (against calm water,
and the mechanism behind each difference) and :mod:`.sea_report` (its files and sections).
"""

from sailmujoco.study import Study

from .analysis import analyse
from .report import report
from .scenario import NAME, TITLE, VIDEO
from .sea import runs
from .sea_analysis import mechanism_runs
from .sea_report import headline, write

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, more_runs=mechanism_runs, video=VIDEO)
