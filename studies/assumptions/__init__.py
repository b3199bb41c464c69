"""Assumption validation in full 6-DOF: where the papers' simplifications hold, where they break,
and what it costs the controller.

The study, in the order it runs: :mod:`.scenario` (the boats, the switches, the runs as data,
the seeds each part runs on; its ``ABOUT`` lists the scenarios in the report), :mod:`.durations`
(how long the single scenarios sail, and their cost), :mod:`.episodes` (the single scenarios and
the time constants), :mod:`.analysis` (the wind plane, each switch's effect seed by seed),
:mod:`.headline_numbers` (the numbers read off it), :mod:`.figures` (figures and CSV data),
:mod:`.table` (one row per assumption) and :mod:`.report` (report.md). What a sea does to the
boats: :mod:`.sea` (its runs; :func:`.sea.runs` is the study's first pass, the calm runs of
:func:`.scenario.runs` with the sea's, every part on the study's seeds), :mod:`.sea_cases`
(against calm water, case by case), :mod:`.sea_attribution` (the mechanism behind each
difference), :mod:`.sea_analysis` (the mechanism reruns and the whole), :mod:`.sea_figures`
(its files and figures), :mod:`.sea_mechanisms` and :mod:`.sea_report` (its sections). What
sensors and actuators as fitted do to each paper's controller: :mod:`.fitted` (its runs) and
:mod:`.fitted_analysis` (its numbers, rows and section). :mod:`.passes` puts the runs together:
the first pass, and the second that the first chooses.
"""

from sailmujoco.study import Study

from . import sea
from .analysis import analyse
from .fitted_figures import write
from .passes import first_runs, second_runs
from .report import report
from .scenario import NAME, SEEDS, TITLE, VIDEO
from .sea_report import headline

STUDY = Study(name=NAME, title=TITLE, runs=first_runs, analyse=analyse, write=write, report=report,
              headline=headline, more_runs=second_runs, video=VIDEO,
              seeds=max(SEEDS, getattr(sea, "SEA_SEEDS", SEEDS)))
