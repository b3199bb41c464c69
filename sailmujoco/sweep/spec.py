"""A sweep's description: reading and checking it, its runs (:func:`expand`) and their ids.

The ``env.`` options and their allowed values come from :mod:`sailmujoco.options` (the fields
of :class:`~sailmujoco.options.PhysicsOptions`, less ``boat_options``, which is the ``boat.``
namespace) and ``control_timestep``; the ``task.``, ``boat.`` and ``controller.`` options from
the signatures of the task, the boat's parameter factory and the controller factory; the
``waves.`` options are the sea's (:data:`sailmujoco.options.WAVE_OPTIONS`), the MuJoCo world's
``waves`` physics option (a run without them is in calm water, its id as without the namespace).
The ``sensors.`` and ``actuators.`` figures become the task's ``sensors`` and ``actuators``
options, a dict each (a run without them has the id it had before they existed).
"""

from __future__ import annotations

import dataclasses
import hashlib
import inspect
import itertools
import json
import re
from pathlib import Path

import numpy as np

from ..boat.fitted import ActuatorOptions, SensorOptions
from ..boat.schema import is_boat_file
from ..errors import one_line
from ..names import check_known, nearest
from ..options import WAVE_OPTIONS, PhysicsOptions, literal_fields
from ..tomlfile import read_toml
from .controllers import controller_factory, factory_options, is_import_path, portable_name
from .errors import SweepError
from .kinds import check_kinds, signature_defaults

KEYS = {  # a sweep file's top-level keys, what each holds (``sweep --help`` lists them)
    "name": "the sweep's name: its folder results/sweeps/<name> (default: the file's stem)",
    "boat": "a registered boat, or a boat file 'my_boat.toml' relative to this file (required)",
    "task": "a registered task (required)",
    "world": "'mujoco' (the 6-DOF boat, default) or 'paper' (the paper's reduced model)",
    "controller": "a registered controller, 'module:factory' or 'file.py:factory' (required)",
    "duration": "simulated seconds per run (default: the task's)",
    "seeds": ("list of seeds, each a run of every combination (default [0]); summary.csv holds each "
              "metric's mean and 95 % interval over them"),
    "metrics": "the task's metrics to keep in the table (default: all of them)",
    "trajectory_rate": "Hz: also store x, y, heading, heel, pitch, u at this rate in each run's record",
    "options": "table: 'namespace.name' = value, the same for every run",
    "grid": "table: 'namespace.name' = [values], every combination of the axes",
    "zip": "table: 'namespace.name' = [values], equal lengths, taken together, crossed with the grid",
}
TOP_KEYS = tuple(KEYS)
NAMESPACE_HELP = {  # where an option of [options], [grid] or [zip] goes
    "env": "sailmujoco.suite.load: control_timestep and the physics options",
    "task": "the task's constructor (wind, references, ...)",
    "boat": "the boat's parameter factory",
    "controller": "the controller's factory",
    "waves": "the sea: hs (m), tp (s), spectrum, direction_from_deg, gamma, spreading, n_components, seed",
    "sensors": "the instruments' figures (preset = 'perfect' or 'typical', then any figure over it)",
    "actuators": "the actuators' figures (preset = 'perfect' or 'typical', then any figure over it)",
}
FIGURES = ("sensors", "actuators")  # namespaces that become one task option each (a dict of figures)
NAMESPACES = tuple(NAMESPACE_HELP)
TABLES = ("options", "grid", "zip")
RUN_KEYS = {"time_limit": "duration", "seed": "seeds"}  # suite.load's keywords a run sets itself


def env_options() -> dict:
    """``{name: default}`` of every ``env.`` option: the physics options (less
    ``boat_options`` and ``waves``, the ``boat.`` and ``waves.`` namespaces) and
    ``control_timestep``."""
    from ..suite import load

    fields = {f.name: f.default for f in dataclasses.fields(PhysicsOptions)}
    defaults = {name: fields[name] for name in env_option_names() if name != "control_timestep"}
    defaults["control_timestep"] = inspect.signature(load).parameters["control_timestep"].default
    return defaults


def env_option_names() -> tuple:
    """The names of the ``env.`` options (:func:`env_options`, without loading the simulation)."""
    return tuple(f.name for f in dataclasses.fields(PhysicsOptions)
                 if f.name not in ("boat_options", "waves")) + ("control_timestep",)


def env_choices() -> dict:
    """``{name: allowed values}`` of the ``env.`` options that take one of a set of choices."""
    return literal_fields(PhysicsOptions)


def load_spec(path) -> dict:
    """Read and validate a sweep TOML file.

    A ``boat`` given as a boat file (``boat = "my_boat.toml"``) and a ``controller`` given as a
    file (``controller = "my_law.py:make"``) are read relative to the sweep file and stored as
    absolute paths, so that every worker finds them.

    Parameters
    ----------
    path : str or Path
        The sweep file.
    """
    path = Path(path)
    spec = read_toml(path, "sweep file", SweepError)
    spec.setdefault("name", path.stem)
    if is_boat_file(spec.get("boat")):  # relative to the sweep file; absolute for the workers
        spec["boat"] = str((path.parent / spec["boat"]).resolve())
    controller = spec.get("controller")
    if isinstance(controller, str) and is_import_path(controller):  # a file: as the boat file
        target, _, factory = controller.rpartition(":")
        if target.endswith(".py"):
            spec["controller"] = f"{(path.parent / Path(target).expanduser()).resolve()}:{factory}"
    return validate(spec, source=f"sweep file {str(path)!r}")


def _parameters(fn) -> set:
    sig = inspect.signature(fn)
    return {n for n, p in sig.parameters.items()
            if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)} - {"self", "seed", "env"}


def _allowed_options(spec: dict) -> dict:
    from ..boat.catalogue import BOATS
    from ..suite import task_options

    boat = spec["boat"]
    allowed = {"env": set(env_options()), "task": set(task_options(spec["task"])),
               "boat": set() if is_boat_file(boat) else _parameters(BOATS[boat]),
               "waves": set(WAVE_OPTIONS),
               "sensors": {f.name for f in dataclasses.fields(SensorOptions)} | {"preset"},
               "actuators": {f.name for f in dataclasses.fields(ActuatorOptions)} | {"preset"}}
    accepted = factory_options(controller_factory(spec["controller"]))
    allowed["controller"] = set(accepted) if accepted is not None else None
    return allowed


def validate(spec: dict, *, source: str = "the sweep description") -> dict:
    """Check a sweep description; return it normalised (a new dict).

    Parameters
    ----------
    spec : dict
        The description (the TOML file's tables as a dict).
    source : str
        Where it came from, for the messages (e.g. ``"sweep file 'x.toml'"``).
    """
    from ..boat.catalogue import BOATS
    from ..suite import TASKS, WORLDS

    if not isinstance(spec, dict):
        raise SweepError("a sweep description must be a table (dict)")
    check_known(spec, TOP_KEYS, source, kind="key", error=SweepError)
    choices = {"boat": sorted(BOATS), "task": list(TASKS), "world": list(WORLDS)}
    spec = {"world": "mujoco", **spec}  # as suite.load: the MuJoCo world unless said
    for key in ("boat", "task", "world", "controller"):
        if key not in spec:
            listed = choices.get(key, ["a registered name, 'module:factory' or 'file.py:factory'"])
            raise SweepError(f"missing key {key!r} (one of: {', '.join(listed)})")
        if not isinstance(spec[key], str):
            raise SweepError(f"{key} must be a string, got {spec[key]!r}")
    for key, allowed in choices.items():
        if spec[key] not in allowed and not (key == "boat" and is_boat_file(spec[key])):
            boat_file = ", or a boat file ending in .toml" if key == "boat" else ""
            raise SweepError(f"{key} = {spec[key]!r} is not one of: {', '.join(allowed)}{boat_file}"
                             f"{_did_you_mean(spec[key], allowed)}")
    if is_boat_file(spec["boat"]):  # a missing or bad boat file: its own lines, before any run
        from ..boat.catalogue import get_boat

        spec["boat"] = str(Path(spec["boat"]).resolve())  # the workers may run elsewhere
        try:
            get_boat(spec["boat"])
        except ValueError as err:
            raise SweepError(str(err)) from None
    controller_factory(spec["controller"])  # an unknown name or a bad import path: one line
    out = dict(spec, controller=portable_name(spec["controller"]))
    _check_scalars(out)
    _check_tables(out, source)
    runs = expand(out)
    if not runs:
        raise SweepError("the sweep has no runs (empty grid)")
    _check_values(out, runs, source)
    return out


def _check_scalars(out: dict) -> None:
    """name, seeds, duration, trajectory_rate and metrics (defaults filled in ``out``)."""
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


def _check_tables(out: dict, source: str) -> None:
    """The keys of [options], [grid] and [zip]: known names, lists where a table sweeps them."""
    allowed = _allowed_options(out)
    for table in TABLES:
        values = out.setdefault(table, {})
        if not isinstance(values, dict):
            raise SweepError(f"[{table}] must be a table of 'namespace.name' keys")
        for key, value in values.items():
            namespace, _, name = key.partition(".")
            where = f"[{table}] key {key!r} of {source}"
            if not name:
                raise SweepError(f"[{table}] key {key!r}: expected '<namespace>.<name>' with "
                                 f"namespace one of {NAMESPACES}")
            check_known([namespace], NAMESPACES, where, kind="namespace", error=SweepError)
            if namespace == "env" and name in RUN_KEYS:  # suite.load's, but the run's here
                raise SweepError(f"{where}: not an env option; give the top-level key "
                                 f"{RUN_KEYS[name]!r}")
            if allowed[namespace] is not None:
                check_known([name], allowed[namespace], where, kind=f"{namespace} option",
                            error=SweepError)
            if table != "options" and (not isinstance(value, list) or not value):
                raise SweepError(f"[{table}] {key} must be a non-empty list of values, got {value!r}")
    lengths = {len(v) for v in out["zip"].values()}
    if len(lengths) > 1:
        raise SweepError(f"[zip] axes must have equal lengths, got {sorted(lengths)}")
    keys = [key for table in TABLES for key in out[table]]
    for ns in FIGURES:
        if f"task.{ns}" in keys and any(key.startswith(f"{ns}.") for key in keys):
            raise SweepError(f"give the {ns} once, as task.{ns} or as {ns}.<figure> keys, not both "
                             f"({source})")


def _distinct(runs: list[dict], key: str) -> list[dict]:
    """The first run of each distinct value of ``run[key]`` (an options dict)."""
    seen = {}
    for r in runs:
        seen.setdefault(json.dumps(r[key], sort_keys=True, default=repr), r)
    return list(seen.values())


def _check_values(spec: dict, runs: list[dict], source: str = "the sweep description") -> None:
    """Check every run's option values before any run starts: each distinct boat, task and
    controller option set is built once, and the environment once per distinct ``env.`` set
    (a MuJoCo model build, about 0.05 s); then the metrics asked for."""
    from ..boat.catalogue import BOATS, get_boat
    from ..suite import TASKS, load

    where = f", in {source}"
    boat_defaults = signature_defaults(BOATS[spec["boat"]]) if spec["boat"] in BOATS else {}
    for r in _distinct(runs, "boat_options"):
        check_kinds("boat", r["boat_options"], boat_defaults, where)
        try:
            get_boat(r["boat"], **r["boat_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"boat options {r['boat_options']}: {err}{where}") from None
    task_defaults = task_option_defaults(TASKS[spec["task"]])
    for r in _distinct(runs, "task_options"):
        check_kinds("task", r["task_options"], task_defaults, where)
        try:
            TASKS[r["task"]](seed=0, **r["task_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"task options {r['task_options']}: {err}{where}") from None
    _check_waves(runs, where)
    env_defaults = {name: (default, False) for name, default in env_options().items()}
    env = None
    for r in _distinct(runs, "env_options"):
        check_kinds("env", r["env_options"], env_defaults, where)
        for key, allowed in env_choices().items():  # also where the paper worlds ignore them
            if key in r["env_options"] and r["env_options"][key] not in allowed:
                value = r["env_options"][key]
                raise SweepError(f"env.{key} = {value!r} is not one of {allowed}{where}"
                                 f"{_did_you_mean(value, allowed)}")
        try:
            built = load(r["boat"], r["task"], r["world"], seed=r["seed"], time_limit=r.get("duration"),
                         boat_options=r["boat_options"], waves=r.get("waves_options") or None,
                         **r["env_options"], **r["task_options"])
        except (TypeError, ValueError) as err:
            given = ", ".join(f"env.{k} = {v!r}" for k, v in r["env_options"].items())
            raise SweepError(f"{given + ': ' if given else ''}{err}{where}") from None
        env = env or built
    factory = controller_factory(spec["controller"])
    for r in _distinct(runs, "controller_options"):
        check_kinds("controller", r["controller_options"], signature_defaults(factory), where)
        try:
            factory(env, **r["controller_options"])
        except (TypeError, ValueError) as err:
            raise SweepError(f"controller options {r['controller_options']}: {err}{where}") from None
        except Exception as err:  # the user's factory raised: every run would, so none is run
            raise SweepError(f"controller {spec['controller']} could not be built with options "
                             f"{r['controller_options']}: {one_line(f'{type(err).__name__}: {err}')}"
                             f"{where}") from None
    if spec.get("metrics"):
        check_metrics(spec["metrics"], runs, source)


def _did_you_mean(value, allowed) -> str:
    """``"; did you mean 'x'?"`` for the allowed value nearest a text ``value``, else ``""``."""
    guess = nearest(value, allowed) if isinstance(value, str) else None
    return f"; did you mean {guess!r}?" if guess is not None else ""


def _check_waves(runs: list[dict], where: str) -> None:
    """Each distinct sea of the runs (its ``waves.`` options) is a valid sea state, checked
    apart from the environment (also where a paper world ignores it): a refused value is one
    line naming the ``waves.`` option and its accepted range."""
    from ..options import wave_config

    for r in _distinct([r for r in runs if r.get("waves_options")], "waves_options"):
        try:
            wave_config(r["waves_options"], where="[waves]")
        except (TypeError, ValueError) as err:
            text = re.sub(r"\bWaveConfig\.", "waves.", str(err).splitlines()[0])
            raise SweepError(f"{text}{where}") from None


def task_option_defaults(task_class) -> dict:
    """``{name: (default, None allowed)}`` of a task's options: its constructor's keywords and
    its bases' (a subclass's default of a name before its base's).

    Parameters
    ----------
    task_class : type
        A registered task class.
    """
    defaults = {}
    for cls in reversed(task_class.__mro__):
        init = vars(cls).get("__init__")
        if init is not None and cls is not object:
            defaults.update(signature_defaults(init))
    defaults.pop("seed", None)  # the run's seed, not an option
    return defaults


def metric_names(run: dict) -> set:
    """The metrics the task of ``run`` reports, with its options: its summary of the initial
    state (no step is simulated), with ``stopped`` and ``duration``.

    Parameters
    ----------
    run : dict
        A run as :func:`expand` gives it.
    """
    from ..suite import load

    env = load(run["boat"], run["task"], run["world"], seed=run["seed"], time_limit=run.get("duration"),
               boat_options=run["boat_options"], **run["env_options"], **run["task_options"])
    env.reset()
    return set(env.task.summarise([env.task.record(env.physics)])) | {"stopped", "duration"}


def check_metrics(metrics: list, runs: list[dict], source: str = "the sweep description") -> None:
    """Refuse, in one line with the nearest name, a metric that no run's task reports.

    Each distinct set of environment and task options is asked for its metric names until
    every metric asked for is found (one environment build for most sweeps).

    Parameters
    ----------
    metrics : list of str
        The metric names asked for.
    runs : list of dict
        The sweep's runs (:func:`expand`).
    source : str
        Where the sweep came from, for the message.
    """
    known: set = set()
    for r in _distinct([{**r, "options": [r["env_options"], r["task_options"]]} for r in runs],
                       "options"):
        known |= metric_names(r)
        if known.issuperset(metrics):
            return
    check_known(metrics, known, f"'metrics' of {source}", kind="metric", error=SweepError)


def expand(spec: dict) -> list[dict]:
    """Every run of a (validated) sweep: options x grid product x zip x seeds.

    Parameters
    ----------
    spec : dict
        A description as :func:`validate` returns it.
    """
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
                if not run["waves_options"]:  # calm water: the run as without the namespace
                    del run["waves_options"]
                for ns in FIGURES:  # the task's option, a dict of figures (none given: as without)
                    figures = run.pop(f"{ns}_options")
                    if figures:
                        run["task_options"] = {**run["task_options"], ns: figures}
                run["run_id"] = run_id(run)
                runs.append(run)
    return runs


def run_id(run: dict) -> str:
    """Stable id of a run's parameters (16 hex digits).

    Parameters
    ----------
    run : dict
        A run as :func:`expand` gives it.
    """
    keys = ("boat", "task", "world", "controller", "seed", "duration", "trajectory_rate",  # not session
            "env_options", "task_options", "boat_options", "controller_options")
    keys += ("waves_options",) if run.get("waves_options") else ()
    text = json.dumps({k: run.get(k) for k in keys}, sort_keys=True, default=float)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def spec_hash(spec: dict) -> str:
    """Stable hash of a (validated) sweep description (16 hex digits).

    Parameters
    ----------
    spec : dict
        A description as :func:`validate` returns it.
    """
    text = json.dumps(spec, sort_keys=True, default=plain)
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def sweep_id(spec: dict) -> str:
    """``<name>-<first 8 hex digits of the spec hash>``: which sweep a folder or row belongs to.

    Parameters
    ----------
    spec : dict
        A description as :func:`validate` returns it.
    """
    return f"{spec.get('name', 'sweep')}-{spec_hash(spec)[:8]}"


def check_folder(spec: dict, out) -> None:
    """Refuse ``out`` if it holds a sweep with another description (a file, not a folder, too).

    The same description may be re-run or resumed there.

    Parameters
    ----------
    spec : dict
        A description as :func:`validate` returns it.
    out : str or Path
        The results folder.
    """
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


def plain(value):
    """``value`` as a plain Python number where it is a numpy one (for ``json.dumps``'s default).

    Parameters
    ----------
    value : object
        A value of a description or record.
    """
    if isinstance(value, (np.floating, float)):
        return float(value)
    if isinstance(value, (np.integer, int)) and not isinstance(value, bool):
        return int(value)
    return value
