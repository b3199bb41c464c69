"""Parameter sweeps: one engine from a laptop (embedded Dask LocalCluster) to a Dask cluster.

A sweep is a TOML file (or the same dict in Python)::

    name = "lphi_vs_wind"
    boat = "saoud_robot"
    task = "heading_hold"
    world = "mujoco"           # or "paper" (default: mujoco)
    controller = "pid"
    duration = 60.0            # s per run (default: the task's)
    seeds = [0, 1]
    metrics = ["mean_surge"]   # optional; default: every metric of the task

    [options]                  # fixed for every run
    "env.hydrostatics" = "geometric"
    "task.wind_speed" = 6.0

    [grid]                     # product over every axis
    "boat.l_phi" = [0.1, 1.0]
    "controller.kp" = [0.5, 1.0, 2.0]

    [zip]                      # zipped axes (equal lengths), crossed with the grid
    "task.wind_from_deg" = [60.0, 90.0]
    "task.desired_heading_deg" = [0.0, 10.0]

Option keys are ``<namespace>.<name>``: ``env.`` goes to :func:`sailmujoco.suite.load`
(``control_timestep`` and the physics options, :class:`sailmujoco.options.PhysicsOptions`:
hydrostatics, sail_mode, dofs, paper_model, the force switches), ``task.`` to the task,
``boat.`` to the boat's parameter factory, ``controller.`` to the controller factory.
Controllers are found by name through the ``sailmujoco.controllers`` entry points (so the
library never imports a controller), or by import path: ``"package.module:factory"``, or
``"my_law.py:factory"``, a file read relative to the sweep file, as a boat file
(``boat = "my_boat.toml"``) is. A misspelt key refuses in one line naming the table, the
key and the nearest accepted name.

Every option value of every run is checked before any run starts (boats, tasks and
controllers built once per distinct option set, the environment once per distinct ``env.``
set; a value of another kind than the option's default, ``"controller.kp" = "two"``, is
refused by its kind), so a bad value anywhere in the grid ends as one line naming it. The
``metrics`` asked for are checked against the ones the task reports with the sweep's options
(``mean_sped`` is one line with the nearest name, not a column of no data).
``sailmujoco sweep --example`` prints a complete sweep file, and ``sailmujoco sweep --help``
lists its keys (``sailmujoco.sweep.spec.KEYS``) and namespaces.

Every finished run is written atomically to ``<out>/runs/<run_id>.json`` as it finishes
(parameters, seed, metrics, package version, status and error text); the consolidated table is
``<out>/results.parquet`` (``pandas.read_parquet``) and ``results.csv``, one row per run of
*this* sweep. Its columns: ``sweep_id`` (``<name>-<first 8 of spec_hash>``) and ``spec_hash``
(SHA-256 of the normalised description, 16 hex digits), ``run_id``, boat, task, world,
controller, seed, ``status``, ``error``, ``wall_time`` (the run's duration in wall seconds in
its worker: build, simulate, metrics, of its last attempt; NaN for a run the cluster lost),
``attempts``, ``version``, then one column per option (``<namespace>.<name>``) and per metric
(the metric ``duration`` is the simulated time the run covered, less than asked if it stopped).

A folder holds one sweep: :func:`run` refuses a different description in a folder that
already holds one (:func:`check_folder`), as the command line does; ``exclusive=False`` lets
sweeps share a folder (runs are stored by the hash of their parameters), and the table still
holds this sweep's runs only.

Studies run on the same engine (:class:`Engine`: one worker pool for many sweeps, and
:func:`run_jobs`: a function named by import path, ``"package.module:function"``, applied to
JSON-able job dicts, each result stored in a :class:`ResultStore` like a sweep run, so a
``resume`` runs only the missing jobs).

A run that raises in its own simulation (its controller raised, its action was not finite) is
recorded as failed at once, with its error, and never retried: same seed, same code, same
error. A run the cluster lost (its worker died, Dask's ``KilledWorker``, a closed connection,
a task that could not be run at all: ``lost`` in the run's record) is tried again up to
``retries`` times, and ``resume=True`` runs what is missing and the lost runs again. A run
whose simulation stops (capsize, non-finite state) is recorded as ``stopped`` with its reason,
a result counted apart from failures. :func:`failures` gives one line per distinct reason runs
failed, with their count and an example run; ``sailmujoco sweep`` prints these lines and exits
with status 1 when a run failed (2 for a description it refuses before any run). Simulations
run in worker processes (MuJoCo and numba state stay per process).

Modules: :mod:`.spec` (the description: checks, runs, ids), :mod:`.runs` (running sweeps and
job lists, one run in a worker), :mod:`.engine` (the worker pool), :mod:`.store` (records on
disk, the table, the JSON form of values), :mod:`.outcome` (why runs failed),
:mod:`.controllers` (controllers by name), :mod:`.errors`.
"""

from __future__ import annotations

from .controllers import (
    ENTRY_POINTS,
    check_controller_options,
    controller_factories,
    controller_factory,
    controller_label,
    make_controller,
    register_controller,
)
from .engine import CONNECT_TIMEOUT_S, MAX_LOCAL_WORKERS, Engine
from .errors import SweepError, lost
from .outcome import failures
from .runs import execute, execute_job, job_id, run, run_jobs, run_many
from .spec import (
    NAMESPACES,
    TOP_KEYS,
    check_folder,
    env_choices,
    env_options,
    expand,
    load_spec,
    run_id,
    spec_hash,
    sweep_id,
    validate,
)
from .store import ResultStore, decode, encode
from .summary import over_seeds

__all__ = ["over_seeds", "CONNECT_TIMEOUT_S", "ENTRY_POINTS", "MAX_LOCAL_WORKERS", "NAMESPACES", "TOP_KEYS",
           "Engine", "ResultStore", "SweepError", "check_controller_options", "check_folder",
           "controller_factories", "controller_factory", "controller_label", "decode", "encode",
           "env_choices", "env_options", "execute", "execute_job", "expand", "failures", "job_id",
           "load_spec", "lost", "make_controller", "register_controller", "run", "run_id", "run_jobs",
           "run_many", "spec_hash", "sweep_id", "validate"]
