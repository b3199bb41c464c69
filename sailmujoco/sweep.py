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
(hydrostatics, sail_mode, dofs, control_timestep, paper_model), ``task.`` to the task,
``boat.`` to the boat's parameter factory, ``controller.`` to the controller factory.
Controllers are found by name through the ``sailmujoco.controllers`` entry points, so the
library never imports a controller.

Every option value of every run is checked before any run starts (boats, tasks and
controllers built once per distinct option set, the environment once per distinct ``env.``
set), so a bad value anywhere in the grid ends as one line naming it.

Every finished run is written atomically to ``<out>/runs/<run_id>.json`` as it finishes
(parameters, seed, metrics, package version, status and error text); the consolidated table is
``<out>/results.parquet`` (``pandas.read_parquet``) and ``results.csv``, one row per run of
*this* sweep. Its columns: ``sweep_id`` (``<name>-<first 8 of spec_hash>``) and ``spec_hash``
(SHA-256 of the normalised description, 16 hex digits), ``run_id``, boat, task, world,
controller, seed, ``status``, ``error``, ``wall_time`` (the run's duration in wall seconds in
its worker: build, simulate, metrics, of its last attempt; NaN for a run the cluster lost),
``attempts``, ``version``, then one column per option (``<namespace>.<name>``) and per metric
(the metric ``duration`` is the simulated time the run covered, less than asked if it stopped).

A folder holds one sweep: the command line refuses a different description in a folder that
already holds one (``run(..., exclusive=True)``; :func:`check_folder`); the library by default
lets sweeps share a folder (runs are stored by the hash of their parameters) and still writes a
table of this sweep's runs only.

``resume=True`` runs what is missing, and re-runs the runs the cluster lost: those recorded as
failed because their worker died (Dask's ``KilledWorker``) or the task could not be run at all
(``lost`` in the run's record). A run that raised in its own simulation is not re-run: same
seed, same code, same error. A run that raises is retried ``retries`` times and then recorded
as failed; a run whose simulation stops (capsize, non-finite state) is recorded as ``stopped``
with its reason, and counted apart from failures. Simulations run in worker processes (MuJoCo
and numba state stay per process).
"""

from __future__ import annotations

import hashlib
import inspect
import itertools
import json
import logging
import math
import numbers
import os
import re
import sys
import time
import traceback
from importlib import metadata
from pathlib import Path

import numpy as np

from . import __version__
from .progress import Progress
from .tomlfile import read_toml

TOP_KEYS = {"name", "boat", "task", "world", "controller", "duration", "seeds", "metrics",
            "options", "grid", "zip", "trajectory_rate"}
NAMESPACES = ("env", "task", "boat", "controller")
ENV_OPTIONS = ("hydrostatics", "sail_mode", "dofs", "control_timestep", "paper_model",
               "sail_tangential", "added_mass_coupling", "vertical_damping", "restoring_axes",
               "resistance", "foils", "keel_downwash", "windage")
ENTRY_POINTS = "sailmujoco.controllers"
CONNECT_TIMEOUT_S = 3.0  # to reach a Dask scheduler given by address
# worker processes of an embedded cluster: more than a few per core only queue for the cores and
# cost memory (--workers 100000 tried to start as many processes and hung)
MAX_LOCAL_WORKERS = 4 * (os.cpu_count() or 1)


class SweepError(ValueError):
    """A sweep description that cannot run; the message names the key and what is allowed."""


# ----------------------------------------------------------------------------- controllers
def controller_factories() -> dict:
    """name -> entry point of every registered controller factory."""
    return {ep.name: ep for ep in metadata.entry_points(group=ENTRY_POINTS)}


def make_controller(name: str, env, **options):
    """Build the controller ``name`` for ``env`` (its factory takes env and options)."""
    factories = controller_factories()
    if name not in factories:
        raise SweepError(f"unknown controller {name!r}; known: {', '.join(sorted(factories))}")
    return factories[name].load()(env, **options)


# ----------------------------------------------------------------------------- description
def load_spec(path) -> dict:
    """Read and validate a sweep TOML file."""
    path = Path(path)
    spec = read_toml(path, "sweep file", SweepError)
    spec.setdefault("name", path.stem)
    return validate(spec)


def _parameters(fn) -> set:
    sig = inspect.signature(fn)
    return {n for n, p in sig.parameters.items()
            if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)} - {"self", "seed", "env"}


def _allowed_options(spec: dict) -> dict:
    from .params import BOATS
    from .suite import TASKS

    allowed = {"env": set(ENV_OPTIONS),
               "task": _parameters(TASKS[spec["task"]].__init__) | {"heading_jitter_deg"},
               "boat": _parameters(BOATS[spec["boat"]])}
    factories = controller_factories()
    allowed["controller"] = _parameters(factories[spec["controller"]].load())
    return allowed


def validate(spec: dict) -> dict:
    """Check a sweep description; return it normalised (a new dict)."""
    from .params import BOATS
    from .suite import TASKS, WORLDS

    if not isinstance(spec, dict):
        raise SweepError("a sweep description must be a table (dict)")
    unknown = set(spec) - TOP_KEYS
    if unknown:
        raise SweepError(f"unknown key(s) {sorted(unknown)}; allowed: {sorted(TOP_KEYS)}")
    choices = {"boat": sorted(BOATS), "task": list(TASKS), "world": list(WORLDS),
               "controller": sorted(controller_factories())}
    spec = {"world": "mujoco", **spec}  # as suite.load: the MuJoCo world unless said
    for key in ("boat", "task", "world", "controller"):
        if key not in spec:
            raise SweepError(f"missing key {key!r} (one of: {', '.join(choices[key])})")
        if not isinstance(spec[key], str):
            raise SweepError(f"{key} must be a string, got {spec[key]!r}")
    for key, allowed in choices.items():
        if spec[key] not in allowed:
            raise SweepError(f"{key} = {spec[key]!r} is not one of: {', '.join(allowed)}")
    out = dict(spec)
    out.setdefault("name", "sweep")
    # the name is a folder under results/sweeps/: one plain name, never a path out of it
    if not isinstance(out["name"], str) or not re.fullmatch(r"[A-Za-z0-9_][A-Za-z0-9_.+-]*", out["name"]):
        raise SweepError(f"name must be letters, digits and _ . + - (a folder name, not a path), "
                         f"got {out['name']!r}")
    seeds = out.setdefault("seeds", [0])
    if not isinstance(seeds, list) or not seeds or not all(isinstance(s, int) and not isinstance(s, bool)
                                                           for s in seeds):
        raise SweepError(f"seeds must be a non-empty list of integers, got {seeds!r}")
    if "duration" in out:
        d = out["duration"]
        if isinstance(d, bool) or not isinstance(d, (int, float)) or not (0 < d < 1e6):
            raise SweepError(f"duration must be a positive number of seconds, got {d!r}")
    if "trajectory_rate" in out:
        r = out["trajectory_rate"]
        if isinstance(r, bool) or not isinstance(r, (int, float)) or r <= 0:
            raise SweepError(f"trajectory_rate must be a positive rate in Hz, got {r!r}")
    if "metrics" in out and (not isinstance(out["metrics"], list)
                             or not all(isinstance(m, str) for m in out["metrics"])):
        raise SweepError(f"metrics must be a list of metric names, got {out['metrics']!r}")
    allowed = _allowed_options(out)
    for table in ("options", "grid", "zip"):
        values = out.setdefault(table, {})
        if not isinstance(values, dict):
            raise SweepError(f"[{table}] must be a table of 'namespace.name' keys")
        for key, value in values.items():
            namespace, _, name = key.partition(".")
            if namespace not in NAMESPACES or not name:
                raise SweepError(f"[{table}] key {key!r}: expected '<namespace>.<name>' with "
                                 f"namespace one of {NAMESPACES}")
            if name not in allowed[namespace]:
                raise SweepError(f"[{table}] key {key!r}: unknown {namespace} option {name!r}; "
                                 f"allowed: {', '.join(sorted(allowed[namespace]))}")
            if table != "options" and (not isinstance(value, list) or not value):
                raise SweepError(f"[{table}] {key} must be a non-empty list of values, got {value!r}")
    lengths = {len(v) for v in out["zip"].values()}
    if len(lengths) > 1:
        raise SweepError(f"[zip] axes must have equal lengths, got {sorted(lengths)}")
    runs = expand(out)
    if not runs:
        raise SweepError("the sweep has no runs (empty grid)")
    _check_values(out, runs)
    return out


def _distinct(runs: list[dict], key: str) -> list[dict]:
    """The first run of each distinct value of ``run[key]`` (an options dict)."""
    seen = {}
    for r in runs:
        seen.setdefault(json.dumps(r[key], sort_keys=True, default=repr), r)
    return list(seen.values())


def _check_kinds(namespace: str, options: dict, fn) -> None:
    """Each option of the kind its default in ``fn``'s signature has: true/false for a flag, a
    finite number for a number, text for text (None where the signature allows it)."""
    parameters = inspect.signature(fn).parameters
    for name, value in options.items():
        param = parameters.get(name)
        if param is None or param.default is param.empty:
            continue
        default = param.default
        if value is None and (default is None or "None" in str(param.annotation)):
            continue
        if isinstance(default, bool):
            ok, kind = isinstance(value, bool), "true or false"
        elif isinstance(default, (int, float)):
            ok = (isinstance(value, (int, float)) and not isinstance(value, bool)
                  and math.isfinite(value))
            kind = "a finite number"
        elif isinstance(default, str):
            ok, kind = isinstance(value, str), "a string"
        else:
            continue
        if not ok:
            raise SweepError(f"{namespace}.{name} = {value!r}: must be {kind}")


def _check_values(spec: dict, runs: list[dict]) -> None:
    """Check every run's option values before any run starts: each distinct boat, task and
    controller option set is built once, and the environment once per distinct ``env.`` set
    (a MuJoCo model build, about 0.05 s)."""
    from .params import get_boat
    from .suite import TASKS, load

    for r in _distinct(runs, "boat_options"):
        try:
            get_boat(r["boat"], **r["boat_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"boat options {r['boat_options']}: {err}") from None
    for r in _distinct(runs, "task_options"):
        try:
            TASKS[r["task"]](seed=0, **r["task_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"task options {r['task_options']}: {err}") from None
    choices = {"hydrostatics": ("off", "paper", "geometric"), "sail_mode": ("actuated", "sheeted"),
               "dofs": (4, 6), "paper_model": ("paper", "rigid")}
    env = None
    for r in _distinct(runs, "env_options"):
        _check_kinds("env", r["env_options"], load)
        for key, allowed in choices.items():  # also where the paper worlds ignore them
            if key in r["env_options"] and r["env_options"][key] not in allowed:
                raise SweepError(f"env.{key} = {r['env_options'][key]!r} is not one of {allowed}")
        try:
            built = load(r["boat"], r["task"], r["world"], seed=r["seed"], time_limit=r.get("duration"),
                         boat_options=r["boat_options"], **r["env_options"], **r["task_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"env options {r['env_options']}: {err}") from None
        env = env or built
    factory = controller_factories()[spec["controller"]].load()
    for r in _distinct(runs, "controller_options"):
        _check_kinds("controller", r["controller_options"], factory)
        try:
            factory(env, **r["controller_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"controller options {r['controller_options']}: {err}") from None


def expand(spec: dict) -> list[dict]:
    """Every run of a (validated) sweep: options x grid product x zip x seeds."""
    grid_keys = list(spec.get("grid", {}))
    grid_values = [spec["grid"][k] for k in grid_keys]
    zip_keys = list(spec.get("zip", {}))
    zip_rows = list(zip(*[spec["zip"][k] for k in zip_keys], strict=True)) if zip_keys else [()]
    runs = []
    for combo in itertools.product(*grid_values) if grid_keys else [()]:
        for row in zip_rows:
            for seed in spec.get("seeds", [0]):
                values = dict(spec.get("options", {}))
                values.update(zip(grid_keys, combo, strict=True))
                values.update(zip(zip_keys, row, strict=True))
                run = {"boat": spec["boat"], "task": spec["task"], "world": spec["world"],
                       "controller": spec["controller"], "seed": int(seed),
                       "duration": spec.get("duration"),
                       "trajectory_rate": spec.get("trajectory_rate")}
                for ns in NAMESPACES:
                    run[f"{ns}_options"] = {k.split(".", 1)[1]: v for k, v in sorted(values.items())
                                            if k.startswith(ns + ".")}
                run["run_id"] = run_id(run)
                runs.append(run)
    return runs


def run_id(run: dict) -> str:
    """Stable id of a run's parameters (16 hex digits)."""
    keys = ("boat", "task", "world", "controller", "seed", "duration", "trajectory_rate",  # not session
            "env_options", "task_options", "boat_options", "controller_options")
    text = json.dumps({k: run.get(k) for k in keys}, sort_keys=True, default=float)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def spec_hash(spec: dict) -> str:
    """Stable hash of a (validated) sweep description (16 hex digits)."""
    text = json.dumps(spec, sort_keys=True, default=_plain)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def sweep_id(spec: dict) -> str:
    """``<name>-<first 8 hex digits of the spec hash>``: which sweep a folder or row belongs to."""
    return f"{spec.get('name', 'sweep')}-{spec_hash(spec)[:8]}"


def check_folder(spec: dict, out) -> None:
    """Refuse ``out`` if it holds a sweep with another description (a file, not a folder, too).

    The same description may be re-run or resumed there."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise SweepError(f"results folder {str(out)!r} is a file, not a folder")
    path = out / "sweep.json"
    if not path.is_file():
        return
    try:
        held = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError):
        raise SweepError(f"{str(out)!r} holds an unreadable sweep.json; use --out elsewhere "
                         "or delete it") from None
    if not isinstance(held, dict) or spec_hash(held) != spec_hash(spec):
        held_id = sweep_id(held) if isinstance(held, dict) else "?"
        raise SweepError(f"{str(out)!r} holds sweep {held_id} with a different spec (this one is "
                         f"{sweep_id(spec)}); use --out elsewhere or delete it")


# ----------------------------------------------------------------------------- one run
def execute(run: dict) -> dict:
    """Simulate one run (in a worker process); never raises for a simulation failure."""
    from .suite import load

    start = time.perf_counter()
    record = {**run, "status": "ok", "error": None, "version": __version__, "host": os.uname()[1]}
    try:
        env = load(run["boat"], run["task"], run["world"], seed=run["seed"],
                   time_limit=run.get("duration"), boat_options=run["boat_options"],
                   **run["env_options"], **run["task_options"])
        controller = make_controller(run["controller"], env, **run["controller_options"])
        if hasattr(controller, "reset"):
            controller.reset(run["seed"])
        timestep = env.reset()
        trajectory = []
        rate = run.get("trajectory_rate")
        every = max(1, int(round(1.0 / (rate * env.control_timestep())))) if rate else 0
        step = 0
        while not timestep.last():
            timestep = env.step(controller(timestep))
            step += 1
            if every and step % every == 0:
                trajectory.append(_trajectory_sample(timestep.observation))
        metrics = env.task.metrics()
        if metrics.get("stopped"):
            record["status"] = "stopped"
            record["error"] = str(metrics["stopped"])
        record["metrics"] = {k: _plain(v) for k, v in metrics.items()}
        if every:
            record["trajectory"] = trajectory
    except Exception as err:  # recorded, the sweep goes on
        record["status"] = "failed"
        record["error"] = f"{type(err).__name__}: {err}\n{traceback.format_exc(limit=3)}"
        record["metrics"] = {}
    record["wall_time"] = time.perf_counter() - start
    return record


def _trajectory_sample(observation) -> dict:
    ts = observation["true_state"]
    return {"t": float(ts["time"]), "x": float(observation["position"][0]),
            "y": float(observation["position"][1]), "heading": float(observation["heading"]),
            "heel": float(observation["heel"]), "u": float(ts["u"])}


def _plain(value):
    if isinstance(value, (np.floating, float)):
        return float(value)
    if isinstance(value, (np.integer, int)) and not isinstance(value, bool):
        return int(value)
    return value


# ----------------------------------------------------------------------------- results store
class ResultStore:
    """``<out>/runs/<run_id>.json``, written atomically; a consolidated Parquet/CSV table."""

    def __init__(self, out):
        self.out = Path(out)
        self.runs_dir = self.out / "runs"
        try:
            self.runs_dir.mkdir(parents=True, exist_ok=True)
        except (FileExistsError, NotADirectoryError):
            raise SweepError(f"results folder {str(self.out)!r} is (or lies under) a file, "
                             "not a folder") from None
        except OSError as err:  # no permission, a read-only or virtual file system
            raise SweepError(f"cannot make the results folder {str(self.out)!r}: "
                             f"{err.strerror}") from None

    def path(self, rid: str) -> Path:
        return self.runs_dir / f"{rid}.json"

    def write(self, record: dict) -> None:
        tmp = self.runs_dir / f".{record['run_id']}.{os.getpid()}.tmp"
        tmp.write_text(json.dumps(record, default=_plain, indent=1))
        os.replace(tmp, self.path(record["run_id"]))

    def done(self) -> dict:
        out = {}
        for path in self.runs_dir.glob("*.json"):
            try:
                record = json.loads(path.read_text())
            except (OSError, json.JSONDecodeError):
                continue  # a torn file cannot exist (atomic writes), but be safe: rerun it
            out[record["run_id"]] = record
        return out

    def table(self, metrics: list | None = None, run_ids=None):
        """The consolidated table (pandas DataFrame), one row per run (of ``run_ids`` only, when
        given: the runs of one sweep)."""
        import pandas as pd

        rows = []
        keep = None if run_ids is None else set(run_ids)
        for record in sorted(self.done().values(), key=lambda r: r.get("index", 0)):
            if keep is not None and record["run_id"] not in keep:
                continue
            row = {"sweep_id": record.get("sweep_id"), "spec_hash": record.get("spec_hash")}
            row.update({k: record[k] for k in ("run_id", "boat", "task", "world", "controller", "seed",
                                               "status", "error", "wall_time")})
            row["attempts"] = record.get("attempts")
            row["version"] = record["version"]
            for ns in NAMESPACES:
                for k, v in record.get(f"{ns}_options", {}).items():
                    row[f"{ns}.{k}"] = v
            for k, v in record.get("metrics", {}).items():
                if metrics is None or k in metrics:
                    row[k] = v
            rows.append(row)
        return pd.DataFrame(rows)

    def consolidate(self, metrics: list | None = None, run_ids=None) -> Path:
        frame = self.table(metrics, run_ids)
        path = self.out / "results.parquet"
        tmp = self.out / ".results.parquet.tmp"
        frame.to_parquet(tmp, index=False)
        os.replace(tmp, path)
        frame.to_csv(self.out / "results.csv", index=False)
        return path


# ----------------------------------------------------------------------------- the engine
def run(spec, out, *, scheduler: str | None = None, workers: int | None = None,
        resume: bool = False, retries: int = 2, progress: bool = True, exclusive: bool = False):
    """Run a sweep; returns its table (pandas DataFrame): the rows of this sweep's runs.

    Parameters
    ----------
    spec : dict or path
        The sweep description (validated here: every run's option values, before any run).
    out : path
        Results folder.
    scheduler : str, optional
        ``None``: an embedded Dask LocalCluster on the local cores (worker processes);
        ``"tcp://host:port"``: an existing Dask scheduler (reached within ``CONNECT_TIMEOUT_S``,
        else a one-line :class:`SweepError`); ``"serial"``: in this process.
    workers : int, optional
        Worker processes of the embedded cluster (``None`` or 0: the number of cores).
    resume : bool
        Skip runs already recorded in ``out`` (finished, stopped, or failed after retries),
        except those the cluster lost (a worker died): they run again.
    retries : int
        Extra attempts for a run that raises (or whose worker dies).
    progress : bool
        Show progress on stderr: a bar on a terminal, a line per 10 % elsewhere.
    exclusive : bool
        Refuse ``out`` if it holds a sweep with another description (the command line's
        behaviour); by default sweeps may share a folder.
    """
    _check_count("workers", workers, "(0: all cores)", none_ok=True, high=MAX_LOCAL_WORKERS)
    _check_count("retries", retries, "")
    spec = load_spec(spec) if isinstance(spec, (str, Path)) else validate(spec)
    if scheduler is not None and not isinstance(scheduler, str):
        raise SweepError(f"scheduler must be an address tcp://host:port, 'serial' or None, "
                         f"got {scheduler!r}")
    if exclusive:
        check_folder(spec, out)
    client = _connect(scheduler) if scheduler not in (None, "serial") else None
    bar = None
    try:
        store = ResultStore(out)
        runs = expand(spec)
        session = f"{os.getpid()}-{time.time():.6f}"
        sid, digest = sweep_id(spec), spec_hash(spec)
        for i, r in enumerate(runs):
            r.update(index=i, session=session, sweep_id=sid, spec_hash=digest)
        (store.out / "sweep.json").write_text(json.dumps(spec, indent=1, default=_plain))
        done = store.done() if resume else {}
        kept = {r["run_id"]: done[r["run_id"]] for r in runs
                if r["run_id"] in done and not lost(done[r["run_id"]])}
        todo = [r for r in runs if r["run_id"] not in kept]
        counts = dict.fromkeys(("ok", "stopped", "failed"), 0)
        for record in kept.values():
            counts[record["status"]] = counts.get(record["status"], 0) + 1
        bar = Progress(len(runs), f"sweep {spec['name']}", sys.stderr, initial=len(kept),
                       show=progress, counts=counts)
        if scheduler == "serial":
            for r in todo:
                record = _with_retries(r, retries)
                store.write(record)
                bar.update(**{record["status"]: 1})
        elif todo:
            _run_dask(todo, store, bar, client, workers, retries)
        bar.close()
    except KeyboardInterrupt:  # Ctrl-C: the table holds the runs that finished; --resume the rest
        if bar is not None:
            bar.close()
            store.consolidate(spec.get("metrics"), [r["run_id"] for r in runs])
        raise
    finally:
        if client is not None:
            client.close()
    ids = [r["run_id"] for r in runs]
    store.consolidate(spec.get("metrics"), ids)
    return store.table(spec.get("metrics"), ids)


def lost(record: dict) -> bool:
    """Whether a recorded run failed because the cluster lost it (its worker died, or the task
    could not be run), not because of its simulation: ``resume`` runs these again."""
    if record.get("status") != "failed":
        return False
    return bool(record.get("lost")) or str(record.get("error") or "").startswith("KilledWorker")


def _check_count(name: str, value, unit: str, none_ok: bool = False, high: int | None = None) -> None:
    if value is None and none_ok:
        return
    if (isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0
            or (high is not None and value > high)):
        upper = f" and <= {high}" if high is not None else ""
        raise SweepError(f"{name} must be an integer >= 0{upper}{' ' + unit if unit else ''}, "
                         f"got {value!r}")


def _connect(address: str):
    """A Dask client of the scheduler at ``address``, or one line saying it cannot be reached."""
    from dask.distributed import Client

    _quiet_dask()
    try:
        return Client(address, timeout=CONNECT_TIMEOUT_S)
    except Exception as err:  # OSError (timeout, refused), ValueError (malformed), DNS errors
        why = (str(err).strip().splitlines() or [type(err).__name__])[0][:120]
        raise SweepError(f"cannot reach the Dask scheduler at {address!r} within "
                         f"{CONNECT_TIMEOUT_S:g} s ({why}); check --scheduler, or leave it out for "
                         "the embedded cluster") from None


def _quiet_dask() -> None:
    for name in ("distributed", "distributed.scheduler", "distributed.nanny", "distributed.worker",
                 "distributed.client", "distributed.core", "distributed.comm"):
        logging.getLogger(name).setLevel(logging.ERROR)


def _with_retries(r: dict, retries: int) -> dict:
    record = execute(r)
    attempt = 0
    while record["status"] == "failed" and attempt < retries:
        attempt += 1
        record = execute(r)
    record["attempts"] = attempt + 1
    return record


def _run_dask(todo, store, bar, client, workers, retries):
    """Run ``todo`` on ``client``'s cluster, or on an embedded LocalCluster when it is None."""
    from dask.distributed import Client, LocalCluster, as_completed

    _quiet_dask()
    cluster = own = None
    if client is None:
        # Ctrl-C reaches every process of the terminal's group: the worker processes are started
        # with SIGINT ignored (a child keeps an ignored signal, and Python then installs no
        # KeyboardInterrupt handler), so only this process stops, closes the cluster and says so
        # in one line instead of each worker printing its traceback. The scheduler's HTTP
        # server takes a free port (":0"), not 8787, which a second cluster on the machine holds.
        previous = _ignore_sigint()
        try:
            cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                   processes=True, dashboard_address=None,
                                   scheduler_kwargs={"dashboard_address": ":0"},
                                   silence_logs=logging.ERROR)
        finally:
            _restore_sigint(previous)
        client = own = Client(cluster)
    try:
        attempts = {}
        owner = {}
        pending = []
        for r in todo:
            future = client.submit(execute, r, key=f"run-{r['run_id']}-0", pure=False)
            owner[future.key] = r
            attempts[r["run_id"]] = 1
            pending.append(future)
        queue = as_completed(pending)
        for future in queue:
            r = owner[future.key]
            try:
                record = future.result()
            except Exception as err:  # a worker died too often, or the task could not run
                record = {**r, "status": "failed", "error": f"{type(err).__name__}: {err}",
                          "lost": True, "metrics": {}, "version": __version__,
                          "wall_time": float("nan")}
            if record["status"] == "failed" and attempts[r["run_id"]] <= retries:
                n = attempts[r["run_id"]]
                attempts[r["run_id"]] = n + 1
                again = client.submit(execute, r, key=f"run-{r['run_id']}-{n}", pure=False)
                owner[again.key] = r
                queue.add(again)
                continue
            record["attempts"] = attempts[r["run_id"]]
            store.write(record)
            bar.update(**{record["status"]: 1})
    finally:
        if own is not None:
            own.close()
        if cluster is not None:
            cluster.close()


def _ignore_sigint():
    """Ignore SIGINT (in the main thread only; elsewhere nothing); return what to restore."""
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        return None
    return signal.signal(signal.SIGINT, signal.SIG_IGN)


def _restore_sigint(previous) -> None:
    import signal

    if previous is not None:
        signal.signal(signal.SIGINT, previous)


def summarise(table, metric: str) -> str:
    """A one-line summary of a metric over the finished runs (for the CLI)."""
    ok = table[table["status"] == "ok"] if "status" in table else table
    if metric not in ok or ok.empty:
        return f"{metric}: no data"
    values = ok[metric].astype(float)
    return (f"{metric}: n={values.size} mean={values.mean():.4g} min={values.min():.4g} "
            f"max={values.max():.4g}" + ("" if math.isfinite(values.mean()) else " (nan present)"))
