"""Saoud et al. (2015) Fig. 7, declared: maximum (steady) velocity against the relative wind
angle, for the optimal sail S, Briere's Bm and the brute-force vel_max.

:mod:`.scenario` holds the runs (the fixed-sail grid, refined in a second pass around each
best sail, and the laws' runs), :mod:`.analysis` the per-angle table and ratios,
:mod:`.figure` the figure and CSV data, :mod:`.report` the report's prose.
"""

from sailmujoco.study import Study

from .analysis import analyse, headline
from .figure import write
from .report import report
from .scenario import NAME, SEEDS, TITLE, VIDEO, more_runs, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, more_runs=more_runs, video=VIDEO, seeds=SEEDS)
