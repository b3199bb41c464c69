"""Running studies: finding them, their order and titles, one worker pool, resume, progress.

``sailmujoco study NAME`` (or ``all``) comes here. The studies are found through the
``sailmujoco.studies`` entry points (``name = "module:STUDY"``, a :class:`sailmujoco.study.Study`),
so the library imports none of them directly. Every study of one command runs on one worker
pool (:class:`sailmujoco.sweep.Engine`); a finished study leaves a marker (``done.json``: the
study, smoke or not, the digest of the code) beside its report, and ``--resume`` keeps the
studies whose marker matches and runs only the missing simulations of the others.

A study's title and the scenario ``--video`` films are its :class:`~sailmujoco.study.Study`'s
``title`` and ``video``; ``--help`` reads the titles from the studies' sources, without
importing them, so it stays fast.
"""

from __future__ import annotations

import ast
import json
import time
from pathlib import Path

from ..names import unknown_message

STUDY_ENTRY_POINTS = "sailmujoco.studies"
STUDY_ORDER = ("saoud_fig3_fig4", "saoud_fig6", "saoud_fig7", "wille_course_table2",
               "wille_roll_table1", "viel_fig3", "real_boats", "assumptions")
DONE_MARKER = "done.json"
CODE_PACKAGES = ("sailmujoco", "sailmujoco.controllers", "sailmujoco.studies", "sailmujoco.xml")
CODE_SUFFIXES = (".py", ".xml", ".dat", ".csv", ".toml")
SMOKE_VIDEO_SECONDS = 5.0  # the longest film of a smoke run


def studies() -> dict:
    """Every registered study.

    Returns
    -------
    dict
        name -> its entry point (``load()`` gives the :class:`~sailmujoco.study.Study`;
        ``module`` names its module).
    """
    from importlib import metadata

    return {ep.name: ep for ep in metadata.entry_points(group=STUDY_ENTRY_POINTS)}


def study_names(found: dict | None = None) -> list[str]:
    """The registered studies in the order ``study all`` runs them.

    Parameters
    ----------
    found : dict, optional
        The studies (:func:`studies`); found afresh if not given.
    """
    found = studies() if found is None else found
    return [n for n in STUDY_ORDER if n in found] + sorted(set(found) - set(STUDY_ORDER))


def select(name: str) -> list[str]:
    """The studies ``sailmujoco study NAME`` runs: ``NAME``, or every one for ``"all"``.

    Parameters
    ----------
    name : str
        A study's name, or ``"all"``.

    Raises
    ------
    ValueError
        For a name that is not registered (one line, with the nearest known one).
    """
    order = study_names()
    if name == "all":
        return order
    if name not in order:
        raise ValueError(unknown_message("study", name, ["all", *order], "sailmujoco study"))
    return [name]


def _source_title(path: Path) -> str:
    """The title a study's source declares: ``title=`` of its ``STUDY = Study(...)`` (a string,
    or the name of a string assigned in the module or in a sibling module it imports it from);
    "" when it is none of these."""
    constants, imported, title = {}, {}, None
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if isinstance(node, ast.ImportFrom) and node.level == 1 and node.module:
            sibling = path.parent / f"{node.module.replace('.', '/')}.py"
            imported.update({alias.asname or alias.name: (sibling, alias.name) for alias in node.names})
        if not isinstance(node, ast.Assign):
            continue
        for target in node.targets:
            if isinstance(target, ast.Name) and isinstance(node.value, ast.Constant):
                constants[target.id] = node.value.value
            if isinstance(target, ast.Name) and target.id == "STUDY" and isinstance(node.value, ast.Call):
                title = next((k.value for k in node.value.keywords if k.arg == "title"), None)
    if isinstance(title, ast.Constant):
        return str(title.value)
    if isinstance(title, ast.Name) and title.id in constants:
        return str(constants[title.id])
    if isinstance(title, ast.Name) and title.id in imported and path.name == "__init__.py":
        sibling, name = imported[title.id]
        if sibling.is_file():
            return _constant(sibling, name)
    return ""


def _constant(path: Path, name: str) -> str:
    """The string a module assigns to ``name`` at its top level ("" if none)."""
    for node in ast.parse(path.read_text(encoding="utf-8")).body:
        if (isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant)
                and any(isinstance(t, ast.Name) and t.id == name for t in node.targets)):
            return str(node.value.value)
    return ""


def study_titles() -> dict[str, str]:
    """name -> the study's title, read from its source without importing it (``--help`` stays
    fast); "" where the source is not found (run from a source tree that is not installed)."""
    import importlib.util

    titles = {}
    found = studies()
    for name in study_names(found):
        title = ""
        try:
            spec = importlib.util.find_spec(found[name].module)
        except (ImportError, ValueError):
            spec = None
        if spec is not None and spec.origin and spec.origin.endswith(".py"):
            title = _source_title(Path(spec.origin))
        titles[name] = title
    return titles


def epilog() -> str:
    """The list of studies, with their titles, that ``sailmujoco study --help`` ends with."""
    titles = study_titles()
    width = max((len(n) for n in titles), default=0)
    return ("studies (each writes results/<name>/report.md, CSV data and PNG figures):\n"
            + "\n".join(f"  {n:{width}s}  {t}" for n, t in titles.items())
            + f"\n  {'all':{width}s}  every study above, in this order")


def study_code_digest() -> str:
    """SHA-256 (16 hex digits) of the code the studies run: the Python sources, boat models and
    data of the package, its controllers and studies. A study's finished marker holds it, so
    ``--resume`` re-runs a study whose code changed since."""
    import hashlib
    import importlib.util

    files = {}
    for name in CODE_PACKAGES:
        spec = importlib.util.find_spec(name)
        for folder in (spec.submodule_search_locations or []) if spec else []:
            for path in Path(folder).rglob("*"):
                if path.suffix in CODE_SUFFIXES and "__pycache__" not in path.parts:
                    files[f"{name}/{path.relative_to(folder).as_posix()}"] = path
    digest = hashlib.sha256()
    for key in sorted(files):
        digest.update(key.encode() + b"\0" + files[key].read_bytes())
    return digest.hexdigest()[:16]


def marker(name: str, smoke: bool, code: str, seeds: int | None = None) -> dict:
    """What ``done.json`` holds for a finished study.

    Parameters
    ----------
    name : str
        The study.
    smoke : bool
        Whether it ran in smoke mode.
    code : str
        :func:`study_code_digest` of the code it ran.
    seeds : int, optional
        ``--seeds N`` (none: the study's own N).
    """
    from .. import __version__

    return {"study": name, "smoke": bool(smoke), "code": code, "version": __version__, "seeds": seeds}


def finished(out: Path, held_marker: dict) -> bool:
    """Whether ``out`` holds a study's report finished with this marker (study, smoke, code).

    Parameters
    ----------
    out : pathlib.Path
        The study's folder.
    held_marker : dict
        The marker (:func:`marker`) a finished run of the same study and code leaves.
    """
    try:
        held = json.loads((out / DONE_MARKER).read_text())
    except (OSError, ValueError):
        return False
    return held == held_marker and (out / "report.md").is_file()


def record_video(scenario, out: Path, smoke: bool) -> None:
    """Film a study's main scenario into its folder (a smoke run films at most 5 s).

    Parameters
    ----------
    scenario : mapping or None
        :func:`sailmujoco.video.record_study_scenario`'s keywords; none: nothing to film.
    out : pathlib.Path
        The study's folder.
    smoke : bool
        A smoke run.
    """
    from .. import video

    scenario = dict(scenario or {})
    if not scenario:
        print("      (this study has no scenario to film)")
        return
    if smoke:
        scenario["seconds"] = min(scenario.get("seconds", 60.0), SMOKE_VIDEO_SECONDS)
    recording = video.record_study_scenario(out, **scenario)
    print(f"      video: {recording.path}")


def run_one(entry, out: Path, engine, *, smoke: bool = False, progress: bool = True,
            video: bool = False, resume: bool = False, seeds: int | None = None) -> dict:
    """Run one registered study into ``out`` (and film it with ``video``); its headline numbers.

    Parameters
    ----------
    entry : importlib.metadata.EntryPoint
        The study's entry point (:func:`studies`).
    out : pathlib.Path
        Its folder.
    engine : sailmujoco.sweep.Engine
        The worker pool.
    smoke : bool
        The study's short pass.
    progress : bool
        Show progress on stderr.
    video : bool
        Also film the study's main scenario.
    resume : bool
        Run only the simulations not stored in ``out`` yet.
    seeds : int, optional
        N seeds in place of the study's own.

    Raises
    ------
    TypeError
        When the entry point names something that is not a :class:`~sailmujoco.study.Study`.
    """
    from .. import study

    loaded = entry.load()
    if not isinstance(loaded, study.Study):
        raise TypeError(f"the study entry point in {entry.module} names a {type(loaded).__name__}, "
                        "not a sailmujoco.study.Study")
    headline = study.run_study(loaded, out, engine, smoke=smoke, resume=resume, progress=progress,
                               seeds=seeds)
    if video:
        record_video(loaded.video, out, smoke)
    return headline


def run_studies(names: list[str], root: Path, *, smoke: bool = False, workers: int | None = None,
                scheduler: str | None = None, resume: bool = False, progress: bool = True,
                video: bool = False, seeds: int | None = None) -> int:
    """Run the studies ``names`` into ``root/<name>/`` on one worker pool, printing where it is.

    Parameters
    ----------
    names : list of str
        The studies (:func:`select`), in the order they run.
    root : pathlib.Path
        The results root (an existing folder).
    smoke : bool
        Every study's short pass.
    workers : int, optional
        Worker processes of the embedded cluster (1: in this process).
    scheduler : str, optional
        A Dask scheduler's address, or ``"serial"``.
    resume : bool
        Keep the studies finished with this code; run only the missing simulations of the rest.
    progress : bool
        Show progress bars on stderr.
    video : bool
        Also film each study's main scenario.
    seeds : int, optional
        ``--seeds N``: every study's stochastic cases on seeds 0..N-1 (none: each study's own N).

    Returns
    -------
    int
        The command's exit status (0).
    """
    from .. import sweep

    found = studies()
    code = study_code_digest()
    start = time.perf_counter()
    took: dict[str, float] = {}
    # one worker pool for every study: in this process for --workers 1, an embedded cluster
    # (started at the first simulations) or the --scheduler's cluster
    scheduler = scheduler or ("serial" if workers == 1 else None)
    with sweep.Engine(scheduler, None if scheduler else workers) as engine:
        for i, name in enumerate(names, 1):
            out = root / name
            out.mkdir(parents=True, exist_ok=True)
            t0 = time.perf_counter()
            held = marker(name, smoke, code, seeds)
            left = len(names) - i + 1  # this one included; those kept by --resume are not counted
            note = (f"; {progress_note(t0 - start, list(took.values()), len(took) + left)}"
                    if len(names) > 1 else "")
            if resume and finished(out, held):
                print(f"[{i}/{len(names)}] study {name}{' (smoke)' if smoke else ''}: finished "
                      f"before, kept ({out / 'report.md'})", flush=True)
                continue
            n_seeds = _seeds_note(found[name], smoke, seeds)
            print(f"[{i}/{len(names)}] study {name}{' (smoke)' if smoke else ''}{n_seeds} -> {out}"
                  + (" (resumed)" if resume else "") + note, flush=True)
            (out / DONE_MARKER).unlink(missing_ok=True)
            headline = run_one(found[name], out, engine, smoke=smoke, progress=progress,
                               video=video, resume=resume, seeds=seeds)
            (out / DONE_MARKER).write_text(json.dumps(held, indent=1) + "\n")
            took[name] = time.perf_counter() - t0
            print(f"      done in {took[name]:.0f} s: {headline_line(headline)}", flush=True)
    if len(took) > 1:
        print(timing_table(took, time.perf_counter() - start))
    print(f"all done in {time.perf_counter() - start:.0f} s; reports: "
          + ", ".join(str(root / n / "report.md") for n in names))
    return 0


def _seeds_note(entry, smoke: bool, seeds: int | None) -> str:
    """', N seeds' for a study's start line (nothing when it cannot be loaded: run_one says why)."""
    try:
        n = len(entry.load().seeds_for(smoke, seeds))
    except Exception:
        return ""
    return f", {n} seed{'s' if n != 1 else ''}"


def headline_line(headline: dict, shown: int = 6) -> str:
    """The first ``shown`` headline numbers as 'name value, ...' (floats to 3 digits).

    Parameters
    ----------
    headline : dict
        A study's headline numbers.
    shown : int
        How many to show.
    """
    return ", ".join(f"{k} {v:.3g}" if isinstance(v, float) else f"{k} {v}"
                     for k, v in list(headline.items())[:shown])


def clock(seconds: float) -> str:
    """``seconds`` as H:MM:SS.

    Parameters
    ----------
    seconds : float
        A duration.
    """
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds % 3600 // 60:02d}:{seconds % 60:02d}"


def progress_note(elapsed: float, took: list[float], total: int) -> str:
    """'elapsed 0:01:05, ETA 0:04:20 (...)' before study len(took)+1 of ``total``: the ETA is
    the finished studies' mean time times the studies left (none before the first ends).

    Parameters
    ----------
    elapsed : float
        Seconds since the first study started.
    took : list of float
        The seconds each finished study took.
    total : int
        The studies of the run (finished ones included).
    """
    if not took:
        return f"elapsed {clock(elapsed)}, ETA after the first study"
    left = total - len(took)
    return (f"elapsed {clock(elapsed)}, ETA {clock(left * sum(took) / len(took))} "
            f"({left} left x the mean {sum(took) / len(took):.0f} s of the {len(took)} done)")


def timing_table(took: dict[str, float], wall: float) -> str:
    """The time each study took, and the total, as a plain text table.

    Parameters
    ----------
    took : dict of str to float
        Seconds per study, in the order they ran.
    wall : float
        The whole run's wall time, seconds.
    """
    width = max([len("total (wall)")] + [len(n) for n in took])
    lines = [f"{'study':{width}s} {'time [s]':>9s} {'share':>6s}", "-" * (width + 17)]
    total = sum(took.values()) or 1.0
    for name, seconds in took.items():
        lines.append(f"{name:{width}s} {seconds:9.1f} {100 * seconds / total:5.0f} %")
    lines.append(f"{'total (wall)':{width}s} {wall:9.1f}")
    return "\n".join(lines)
