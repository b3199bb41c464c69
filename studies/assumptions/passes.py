"""Assumption validation, the study's two passes: what runs first and what the first pass chooses.

The first pass is the calm runs and the sea's (:func:`.sea.runs`) with the sensors-and-actuators
arms (:func:`.fitted.fitted_jobs`); the second, the sea's mechanism reruns
(:func:`.sea_analysis.mechanism_runs`) with the switches that trace each fitted arm's change
over 10 % (:func:`.fitted_analysis.attribution_runs`).
"""

from __future__ import annotations

from sailmujoco.study import Results, Runs

from . import sea
from .fitted import FITTED_JOB, fitted_jobs
from .fitted_analysis import attribution_runs
from .sea_analysis import mechanism_runs


def first_runs(smoke: bool, seeds=(0,)) -> Runs:
    """The first pass: the calm and sea runs, and every scenario in every fitted arm.

    Parameters
    ----------
    smoke : bool
        The study's short pass.
    seeds : sequence of int
        The study's seeds.
    """
    base = sea.runs(smoke, seeds)
    return Runs(sweeps=base.sweeps,
                jobs={**base.jobs, FITTED_JOB: (f"{__package__}.fitted:fitted_run", fitted_jobs(smoke, seeds))},
                label=base.label)


def second_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: the sea's mechanism reruns and the fitted arms' switches.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass.
    smoke : bool
        The study's short pass.
    """
    mechanisms, switches = mechanism_runs(results, smoke), attribution_runs(results, smoke)
    label = " and ".join(r.label for r in (mechanisms, switches) if r)
    return Runs(sweeps=mechanisms.sweeps, jobs={**mechanisms.jobs, **switches.jobs},
                label=label or mechanisms.label)
