"""Saoud et al. (2015) Fig. 6, declared: speed and roll over time, optimal sail S against Briere's Bm.

:mod:`.scenario` holds the speed trials (what runs), :mod:`.analysis` the segment means and
ratios, :mod:`.figure` the figures and CSV data, :mod:`.report` the report's prose.
"""

from sailmujoco.study import Study

from .analysis import analyse, headline
from .figure import write
from .report import report
from .scenario import NAME, SEEDS, TITLE, VIDEO, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, video=VIDEO, seeds=SEEDS)
