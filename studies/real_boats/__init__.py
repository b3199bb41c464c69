"""Real boats: the 11:Metre made from its class dimensions against ORC's polar of the class, the
Wille yacht beside it, and the canoe body against the Delft tank.

:mod:`.scenario` holds what runs (the polars of each case, the tank comparison), :mod:`.analysis`
the ratios and the switches' effects, :mod:`.report` the report, its CSV data and figures.
"""

from sailmujoco.study import Study

from .analysis import analyse, headline
from .report import report, write
from .scenario import NAME, SEEDS, TITLE, VIDEO, more_runs, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, more_runs=more_runs, video=VIDEO, seeds=SEEDS)
