"""Running sweeps and job lists: :func:`run`, :func:`run_many`, :func:`run_jobs`, and what a
worker does with one run (:func:`execute`) or one job (:func:`execute_job`)."""

from __future__ import annotations

import hashlib
import json
import os
import sys
import time
import traceback
from pathlib import Path

from .. import __version__
from ..loop.episode import run_compiled, trajectory_sample
from ..progress import Progress
from .controllers import make_controller
from .engine import Engine
from .errors import SweepError, check_count, lost
from .spec import check_folder, expand, load_spec, plain, spec_hash, sweep_id, validate
from .store import ResultStore, decode, encode


def run(spec, out, *, scheduler: str | None = None, workers: int | None = None,
        resume: bool = False, retries: int = 2, progress: bool = True, exclusive: bool = True,
        engine: Engine | None = None):
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
        Extra attempts of a run the cluster lost (its worker died, its connection closed). A
        run that raised in its own simulation is recorded as failed at once, never retried:
        same seed, same code, same error. :func:`failures` says why runs failed.
    progress : bool
        Show progress on stderr: a bar on a terminal, a line per 10 % elsewhere.
    exclusive : bool
        Refuse ``out`` if it holds a sweep with another description (default, as the command
        line); ``False`` lets sweeps share a folder.
    engine : Engine, optional
        Run on this :class:`Engine` (a worker pool shared by many sweeps and jobs; left open);
        ``scheduler`` and ``workers`` then must be left out.
    """
    tables, _ = run_many([(spec, out)], scheduler=scheduler, workers=workers, resume=resume,
                         retries=retries, progress=progress, exclusive=exclusive, engine=engine)
    return tables[0]


def run_many(sweeps: list, jobs: list = (), *, scheduler: str | None = None,
             workers: int | None = None, resume: bool = False, retries: int = 2,
             job_retries: int = 0, progress: bool = True, exclusive: bool = True,
             engine: Engine | None = None, label: str | None = None) -> tuple[list, list]:
    """Several sweeps and job lists at once, all their runs queued together on one engine (no
    worker waits for one sweep to end before the next starts); returns (the table of each
    sweep, the results of each job list), in the order given.

    Parameters
    ----------
    sweeps : list of tuple
        ``(spec, out)`` pairs, as :func:`run` takes them.
    jobs : list of tuple
        ``(function, jobs, out)`` triples, as :func:`run_jobs` takes them.
    scheduler, workers, resume, retries, progress, exclusive, engine
        As :func:`run`.
    job_retries : int
        :func:`run_jobs`'s ``retries``, for every job list.
    label : str, optional
        Names the progress bar (default: the sweep's name, or "runs").
    """
    check_count("retries", retries, "")
    check_count("job_retries", job_retries, "")
    if engine is not None and (scheduler is not None or workers is not None):
        raise SweepError("give an engine, or scheduler and workers, not both")
    own = engine is None
    if own:
        Engine.check(scheduler, workers)
    prepared = []
    for spec, out in sweeps:
        spec = load_spec(spec) if isinstance(spec, (str, Path)) else validate(spec)
        if exclusive:
            check_folder(spec, out)
        prepared.append((spec, out))
    for function, _, _ in jobs:
        _resolve(function)  # a wrong name: one line now, not one per job in the workers
    if own:
        engine = Engine(scheduler, workers) if sweeps else Engine("serial")
    session = f"{os.getpid()}-{time.time():.6f}"
    parts = [_SweepPart(spec, out, resume, session, retries) for spec, out in prepared]
    parts += [_JobPart(function, items, out, resume, job_retries) for function, items, out in jobs]
    if label is None:
        label = f"sweep {prepared[0][0]['name']}" if len(parts) == 1 and sweeps else "runs"
    bar = None
    try:
        counts = dict.fromkeys(("ok", "stopped", "failed"), 0) if sweeps else {}
        for part in parts if sweeps else ():  # jobs are counted, not tallied
            for status, n in part.counts.items():
                counts[status] = counts.get(status, 0) + n
        bar = Progress(sum(p.total for p in parts), label, sys.stderr,
                       initial=sum(p.total - len(p.todo) for p in parts), show=progress,
                       counts=counts, **({} if sweeps else {"unit": "sim"}))
        items = [(p.task, r, p.store, p.retries, p.again) for p in parts for r in p.todo]
        engine.execute(items, bar if sweeps else _Count(bar))
        bar.close()
    except KeyboardInterrupt:  # Ctrl-C: the tables hold the runs that finished; resume the rest
        if bar is not None:
            bar.close()
            for part in parts[:len(prepared)]:
                part.consolidate()
        raise
    finally:
        if own:
            engine.close()
    tables = [part.finish() for part in parts[:len(prepared)]]
    results = [part.finish() for part in parts[len(prepared):]]
    return tables, results


class _SweepPart:
    """One sweep of :func:`run_many`: its store, runs and the runs to do."""

    def __init__(self, spec: dict, out, resume: bool, session: str, retries: int):
        self.spec, self.retries, self.task = spec, retries, execute
        # only a run the cluster lost is tried again: a run that raised in its own simulation
        # (its controller, a non-finite action, an option refused late) is deterministic, the
        # same seed and code raise the same error, so a retry would only repeat it
        self.again = lost
        self.store = ResultStore(out)
        self.runs = expand(spec)
        sid, digest = sweep_id(spec), spec_hash(spec)
        for i, r in enumerate(self.runs):
            r.update(index=i, session=session, sweep_id=sid, spec_hash=digest)
        (self.store.out / "sweep.json").write_text(json.dumps(spec, indent=1, default=plain))
        done = self.store.done() if resume else {}
        kept = {r["run_id"]: done[r["run_id"]] for r in self.runs
                if r["run_id"] in done and not lost(done[r["run_id"]])}
        self.todo = [r for r in self.runs if r["run_id"] not in kept]
        self.total = len(self.runs)
        self.counts = {}
        for record in kept.values():
            self.counts[record["status"]] = self.counts.get(record["status"], 0) + 1

    def consolidate(self) -> None:
        self.store.consolidate(self.spec.get("metrics"), [r["run_id"] for r in self.runs])

    def finish(self):
        self.consolidate()
        return self.store.table(self.spec.get("metrics"), [r["run_id"] for r in self.runs])


def execute(run: dict) -> dict:
    """Simulate one run (in a worker process); its record. Never raises for a simulation failure.

    Parameters
    ----------
    run : dict
        A run as :func:`~sailmujoco.sweep.spec.expand` gives it.
    """
    from ..suite import load

    start = time.perf_counter()
    record = {**run, "status": "ok", "error": None, "version": __version__, "host": os.uname()[1]}
    try:
        env = load(run["boat"], run["task"], run["world"], seed=run["seed"],
                   time_limit=run.get("duration"), boat_options=run["boat_options"],
                   waves=run.get("waves_options") or None, **run["env_options"], **run["task_options"])
        controller = make_controller(run["controller"], env, **run["controller_options"])
        if hasattr(controller, "reset"):
            controller.reset(run["seed"])
        timestep = env.reset()
        trajectory = []
        rate = run.get("trajectory_rate")
        every = max(1, int(round(1.0 / (rate * env.control_timestep())))) if rate else 0
        step = 0
        compiled = run_compiled(env, controller)
        if compiled is not None:  # the same steps, bit for bit, in one native call (sailmujoco.loop)
            step, timestep = compiled.steps, compiled.timestep
            if every:
                trajectory = [trajectory_sample(compiled.rows[k - 1]) for k in range(every, step, every)]
                if step % every == 0:
                    trajectory.append(_trajectory_sample(timestep.observation))
        while not timestep.last():
            timestep = env.step(controller(timestep))
            step += 1
            if every and step % every == 0:
                trajectory.append(_trajectory_sample(timestep.observation))
        metrics = env.task.metrics()
        if metrics.get("stopped"):
            record["status"] = "stopped"
            record["error"] = str(metrics["stopped"])
        record["metrics"] = {k: plain(v) for k, v in metrics.items()}
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
            "heel": float(observation["heel"]), "pitch": float(ts["pitch"]), "u": float(ts["u"])}


# ----------------------------------------------------------------------------- study jobs
def run_jobs(function: str, jobs: list[dict], out, *, engine: Engine | None = None,
             resume: bool = False, retries: int = 0, progress: bool = True,
             label: str = "jobs") -> list:
    """``[f(job) for job in jobs]`` on ``engine`` (default: in this process), where ``f`` is the
    function named ``function`` (``"package.module:name"``, importable in the workers).

    Each job is a JSON-able dict (tuples, numpy numbers and arrays and pandas DataFrames are
    kept through :func:`encode`); its result, of the same kinds, is stored in the
    :class:`ResultStore` ``out`` under the hash of the function's name and the job (see
    :func:`job_id`) as it finishes. ``resume``: the jobs already stored there are not run again.
    Results come back in the order of ``jobs``, always as read back from their stored form (a
    resumed job gives what a fresh one gives). A job that raises is retried ``retries`` times,
    then a :class:`SweepError` names it with its error (the jobs that finished stay stored).

    Parameters
    ----------
    function : str
        The job function, ``"package.module:name"``.
    jobs : list of dict
        The jobs.
    out : str or Path
        The results folder of the job list.
    engine : Engine, optional
        Where the jobs run (default: in this process).
    resume : bool
        Skip the jobs already stored in ``out``.
    retries : int
        Extra attempts of a job that raises.
    progress : bool
        Show progress on stderr.
    label : str
        Names the progress bar.
    """
    _, results = run_many([], [(function, jobs, out)], engine=engine, resume=resume,
                          job_retries=retries, progress=progress, label=label)
    return results[0]


class _JobPart:
    """One job list of :func:`run_many`: its store, jobs and the jobs to do."""

    def __init__(self, function: str, jobs: list, out, resume: bool, retries: int):
        self.function, self.retries, self.task = function, retries, execute_job
        self.again = _any_failure  # a job list asks for its retries itself (default none)
        self.store = ResultStore(out, indent=None)
        self.jobs = [{"run_id": job_id(function, job), "function": function, "job": job, "index": i}
                     for i, job in enumerate(jobs)]
        done = self.store.done() if resume else {}
        kept = {t["run_id"] for t in self.jobs if done.get(t["run_id"], {}).get("status") == "ok"}
        self.todo = list({t["run_id"]: t for t in self.jobs if t["run_id"] not in kept}.values())
        self.total = len(self.todo) + len({t["run_id"] for t in self.jobs} & kept)
        self.counts = {"ok": self.total - len(self.todo)}

    def finish(self) -> list:
        records = self.store.done()
        results = []
        for t in self.jobs:
            record = records.get(t["run_id"], {})
            if record.get("status") != "ok":
                raise SweepError(f"job {t['index']} ({self.function}, {_short(t['job'])}) failed: "
                                 f"{record.get('error') or 'no record'}")
            results.append(decode(record["result"]))
        return results


class _Count:
    """A progress bar's count without the ok/stopped/failed tallies (a job either finishes, or
    ends the list with its error)."""

    def __init__(self, bar):
        self.bar = bar

    def update(self, **_) -> None:
        self.bar.update()


def _any_failure(record: dict) -> bool:
    """Every failed job is tried again, up to the job list's ``retries``."""
    return True


def job_id(function: str, job: dict) -> str:
    """Stable id of a job of ``function`` (16 hex digits).

    Parameters
    ----------
    function : str
        The job function's name, ``"package.module:name"``.
    job : dict
        The job (JSON-able through :func:`~sailmujoco.sweep.store.encode`).
    """
    text = json.dumps({"function": function, "job": encode(job)}, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def execute_job(task: dict) -> dict:
    """Run one job (in a worker process); a record with its encoded result, never raises.

    Parameters
    ----------
    task : dict
        ``run_id``, ``function`` (``"package.module:name"``) and ``job``.
    """
    start = time.perf_counter()
    record = {"run_id": task["run_id"], "function": task["function"], "job": encode(task["job"]),
              "status": "ok", "error": None, "version": __version__, "host": os.uname()[1]}
    try:
        record["result"] = encode(_resolve(task["function"])(task["job"]))
    except Exception as err:  # recorded; run_jobs names it
        record["status"] = "failed"
        record["error"] = f"{type(err).__name__}: {err}\n{traceback.format_exc(limit=3)}"
    record["wall_time"] = time.perf_counter() - start
    return record


def _resolve(function: str):
    import importlib

    module, _, name = function.partition(":")
    try:
        return getattr(importlib.import_module(module), name)
    except (ImportError, AttributeError, ValueError) as err:
        raise SweepError(f"cannot find the job function {function!r} ('package.module:name'): "
                         f"{err}") from None


def _short(job) -> str:
    text = json.dumps(encode(job), sort_keys=True)
    return text if len(text) <= 120 else text[:117] + "..."
