"""Courses: the events autonomous sailboats compete in (WRSC's fleet race and area scanning,
SailBot's precision navigation and station keeping), sailed by Jaulin and Le Bars' line
following on every shipped boat, calm with perfect instruments and in the wind's sea with typical
ones, scored by the events' rules over seeds; a case that loses reruns with each half of the
change alone to name its cause.

:mod:`.scenario` holds what runs, :mod:`.analysis` the scores, changes and causes, :mod:`.report`
the report, its CSV data and figures.
"""

from sailmujoco.study import Study

from .analysis import analyse, headline, more_runs
from .report import report, write
from .scenario import NAME, SEEDS, TITLE, VIDEO, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, more_runs=more_runs, video=VIDEO, seeds=SEEDS)
