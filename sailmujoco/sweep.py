"""Parameter sweeps: one engine from a laptop (embedded Dask LocalCluster) to a Dask cluster.

A sweep is a TOML file (or the same dict in Python)::

    name = "lphi_vs_wind"
    boat = "saoud_robot"
    task = "heading_hold"
    world = "mujoco"
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

Every finished run is written atomically to ``<out>/runs/<run_id>.json`` as it finishes
(parameters, seed, metrics, wall time, package version, status and error text); the
consolidated table is ``<out>/results.parquet`` (``pandas.read_parquet``) and ``results.csv``.
``resume=True`` runs only what is missing. A run that raises is retried ``retries`` times and
then recorded as failed; a run whose simulation stops (capsize, non-finite state) is recorded
as ``stopped`` with its reason. Simulations run in worker processes (MuJoCo and numba state
stay per process).
"""

from __future__ import annotations

import hashlib
import inspect
import itertools
import json
import math
import os
import sys
import time
import traceback
from importlib import metadata
from pathlib import Path

import numpy as np

from . import __version__
from .tomlfile import read_toml

TOP_KEYS = {"name", "boat", "task", "world", "controller", "duration", "seeds", "metrics",
            "options", "grid", "zip", "trajectory_rate"}
NAMESPACES = ("env", "task", "boat", "controller")
ENV_OPTIONS = ("hydrostatics", "sail_mode", "dofs", "control_timestep", "paper_model",
               "sail_tangential", "added_mass_coupling", "vertical_damping", "restoring_axes",
               "resistance", "foils", "keel_downwash", "windage")
ENTRY_POINTS = "sailmujoco.controllers"


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
    for key in ("boat", "task", "world", "controller"):
        if key not in spec:
            raise SweepError(f"missing key {key!r}")
        if not isinstance(spec[key], str):
            raise SweepError(f"{key} must be a string, got {spec[key]!r}")
    choices = {"boat": sorted(BOATS), "task": list(TASKS), "world": list(WORLDS),
               "controller": sorted(controller_factories())}
    for key, allowed in choices.items():
        if spec[key] not in allowed:
            raise SweepError(f"{key} = {spec[key]!r} is not one of: {', '.join(allowed)}")
    out = dict(spec)
    out.setdefault("name", "sweep")
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
    _check_values(out, runs[0])
    return out


def _check_values(spec: dict, run: dict) -> None:
    """Build the first run's boat and task to catch out-of-range values early."""
    from .params import get_boat
    from .suite import TASKS

    try:
        get_boat(run["boat"], **run["boat_options"])
    except ValueError as err:
        raise SweepError(f"boat options {run['boat_options']}: {err}") from None
    try:
        TASKS[run["task"]](seed=0, **run["task_options"])
    except (TypeError, ValueError) as err:
        raise SweepError(f"task options {run['task_options']}: {err}") from None
    env = run["env_options"]
    choices = {"hydrostatics": ("off", "paper", "geometric"), "sail_mode": ("actuated", "sheeted"),
               "dofs": (4, 6), "paper_model": ("paper", "rigid")}
    for key, allowed in choices.items():
        if key in env and env[key] not in allowed:
            raise SweepError(f"env.{key} = {env[key]!r} is not one of {allowed}")


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
        self.runs_dir.mkdir(parents=True, exist_ok=True)

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

    def table(self, metrics: list | None = None):
        """The consolidated table (pandas DataFrame), one row per run."""
        import pandas as pd

        rows = []
        for record in sorted(self.done().values(), key=lambda r: r.get("index", 0)):
            row = {k: record[k] for k in ("run_id", "boat", "task", "world", "controller", "seed",
                                          "status", "error", "wall_time", "version")}
            for ns in NAMESPACES:
                for k, v in record.get(f"{ns}_options", {}).items():
                    row[f"{ns}.{k}"] = v
            for k, v in record.get("metrics", {}).items():
                if metrics is None or k in metrics:
                    row[k] = v
            rows.append(row)
        return pd.DataFrame(rows)

    def consolidate(self, metrics: list | None = None) -> Path:
        frame = self.table(metrics)
        path = self.out / "results.parquet"
        tmp = self.out / ".results.parquet.tmp"
        frame.to_parquet(tmp, index=False)
        os.replace(tmp, path)
        frame.to_csv(self.out / "results.csv", index=False)
        return path


# ----------------------------------------------------------------------------- the engine
def run(spec, out, *, scheduler: str | None = None, workers: int | None = None,
        resume: bool = False, retries: int = 2, progress: bool = True):
    """Run a sweep; returns the consolidated table (pandas DataFrame).

    Parameters
    ----------
    spec : dict or path
        The sweep description (validated here).
    out : path
        Results folder.
    scheduler : str, optional
        ``None``: an embedded Dask LocalCluster on the local cores (worker processes);
        ``"tcp://host:port"``: an existing Dask scheduler; ``"serial"``: in this process.
    workers : int, optional
        Worker processes of the embedded cluster (default: the number of cores).
    resume : bool
        Skip runs already recorded in ``out`` (finished, stopped, or failed after retries).
    retries : int
        Extra attempts for a run that raises.
    """
    spec = load_spec(spec) if isinstance(spec, (str, Path)) else validate(spec)
    store = ResultStore(out)
    runs = expand(spec)
    session = f"{os.getpid()}-{time.time():.6f}"
    for i, r in enumerate(runs):
        r["index"] = i
        r["session"] = session
    (store.out / "sweep.json").write_text(json.dumps(spec, indent=1, default=_plain))
    done = store.done() if resume else {}
    todo = [r for r in runs if r["run_id"] not in done]
    bar = _progress(len(runs), len(runs) - len(todo), progress)
    if scheduler == "serial":
        for r in todo:
            record = _with_retries(r, retries)
            store.write(record)
            bar.update(record)
    elif todo:
        _run_dask(todo, store, bar, scheduler, workers, retries)
    bar.close()
    store.consolidate(spec.get("metrics"))
    return store.table(spec.get("metrics"))


def _with_retries(r: dict, retries: int) -> dict:
    record = execute(r)
    attempt = 0
    while record["status"] == "failed" and attempt < retries:
        attempt += 1
        record = execute(r)
    record["attempts"] = attempt + 1
    return record


def _run_dask(todo, store, bar, scheduler, workers, retries):
    import logging

    from dask.distributed import Client, LocalCluster, as_completed

    for name in ("distributed", "distributed.scheduler", "distributed.nanny", "distributed.worker"):
        logging.getLogger(name).setLevel(logging.ERROR)

    cluster = None
    if scheduler is None:
        cluster = LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                               processes=True, dashboard_address=None)
        client = Client(cluster)
    else:
        client = Client(scheduler)
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
                          "metrics": {}, "version": __version__, "wall_time": float("nan")}
            if record["status"] == "failed" and attempts[r["run_id"]] <= retries:
                n = attempts[r["run_id"]]
                attempts[r["run_id"]] = n + 1
                again = client.submit(execute, r, key=f"run-{r['run_id']}-{n}", pure=False)
                owner[again.key] = r
                queue.add(again)
                continue
            record["attempts"] = attempts[r["run_id"]]
            store.write(record)
            bar.update(record)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


class _Progress:
    """Runs done, failures and ETA (tqdm when asked, silent otherwise)."""

    def __init__(self, total, already, show):
        self.failures = 0
        self.bar = None
        if show:
            from tqdm import tqdm

            self.bar = tqdm(total=total, initial=already, unit="run", file=sys.stderr,
                            dynamic_ncols=True)
            self.bar.set_postfix(failed=0)

    def update(self, record):
        if record["status"] != "ok":
            self.failures += 1
        if self.bar is not None:
            self.bar.update(1)
            self.bar.set_postfix(failed=self.failures)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _progress(total, already, show):
    return _Progress(total, already, show)


def summarise(table, metric: str) -> str:
    """A one-line summary of a metric over the finished runs (for the CLI)."""
    ok = table[table["status"] == "ok"] if "status" in table else table
    if metric not in ok or ok.empty:
        return f"{metric}: no data"
    values = ok[metric].astype(float)
    return (f"{metric}: n={values.size} mean={values.mean():.4g} min={values.min():.4g} "
            f"max={values.max():.4g}" + ("" if math.isfinite(values.mean()) else " (nan present)"))
