"""Wille (2016b) §5 Table 1, Figs. 3 and 5-8: roll stabilisation by the sail.

The study in six parts: :mod:`.scenario` (the runs, as data, and the paper's numbers),
:mod:`.run_table` (each run's numbers by case, world, sim and seed), :mod:`.analysis` (the seed
means, the reductions' verdicts, the moment shares and the Fig. 8 optima),
:mod:`.figures` (the figures and the CSV data), :mod:`.report` (the comparison with the paper)
and :mod:`.causes` (the cause of each difference, each checked by a switch). The beam reach
itself is :mod:`studies.kit.wille`'s Table 1 scenario.
"""

from sailmujoco.study import Study

from .analysis import analyse, headline
from .figures import write
from .report import report
from .scenario import NAME, SEEDS, TITLE, VIDEO, runs

STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, video=VIDEO, seeds=SEEDS)
