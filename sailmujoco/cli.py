"""The ``sailmujoco`` command: the arguments of each sub-command, and the module that runs it.

====================  =============================================================
``check``             :func:`sailmujoco.health.run_cli`
``sweep FILE``        :func:`sailmujoco.sweep_cli.run_cli`
``polar BOAT``        :func:`sailmujoco.polar.run_cli`
``study NAME``        the study runner below
``video BOAT TASK``   :func:`sailmujoco.video.run_cli` (its parser: :func:`sailmujoco.video.add_parser`)
``view BOAT TASK``    :func:`sailmujoco.view.run_cli` (its parser: :func:`sailmujoco.view.add_parser`)
====================  =============================================================

Bad input (a ``ValueError`` from any command) is one line on stderr and exit status 2; Ctrl-C is
one line and :data:`~sailmujoco.arguments.INTERRUPTED`.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from . import health, polar, sweep_cli, video, view
from .arguments import INTERRUPTED, POSITIVE_SECONDS, SEED, WORKERS, floats, number
from .arguments import out_folder as _out_folder  # the name the study section below uses

STUDY_ENTRY_POINTS = "sailmujoco.studies"


def _studies() -> dict:
    """name -> entry point of every registered study (the library imports none directly)."""
    from importlib import metadata

    return {ep.name: ep for ep in metadata.entry_points(group=STUDY_ENTRY_POINTS)}


STUDY_ORDER = ("saoud_fig3_fig4", "saoud_fig6", "saoud_fig7", "wille_course_table2",
               "wille_roll_table1", "viel_fig3", "assumptions")


def study_titles() -> dict[str, str]:
    """name -> the study's TITLE, read from its source without importing it (``--help`` stays fast)."""
    import ast
    import importlib.util

    titles = {}
    studies = _studies()
    for name in [n for n in STUDY_ORDER if n in studies] + sorted(set(studies) - set(STUDY_ORDER)):
        title = ""
        try:  # run from a source tree (python -m sailmujoco.cli in the repository root), the
            # studies are not yet the installed sailmujoco.studies: the list goes without titles
            spec = importlib.util.find_spec(studies[name].module)
        except (ImportError, ValueError):
            spec = None
        if spec is not None and spec.origin and spec.origin.endswith(".py"):
            tree = ast.parse(Path(spec.origin).read_text(encoding="utf-8"))
            for node in tree.body:
                named = any(getattr(target, "id", None) == "TITLE" for target in getattr(node, "targets", []))
                if named and isinstance(node.value, ast.Constant):
                    title = str(node.value.value)
        titles[name] = title
    return titles


def _study_epilog() -> str:
    titles = study_titles()
    width = max((len(n) for n in titles), default=0)
    return ("studies (each writes results/<name>/report.md, CSV data and PNG figures):\n"
            + "\n".join(f"  {n:{width}s}  {t}" for n, t in titles.items())
            + f"\n  {'all':{width}s}  every study above, in this order")


def _record_study_video(entry_point, out: Path, smoke: bool) -> None:
    """Record the study's main scenario (its module's VIDEO dict) into its results folder."""
    import importlib

    from . import video

    scenario = dict(getattr(importlib.import_module(entry_point.module), "VIDEO", {}) or {})
    if not scenario:
        print("      (this study has no scenario to film)")
        return
    if smoke:
        scenario["seconds"] = min(scenario.get("seconds", 60.0), 5.0)
    recording = video.record_study_scenario(out, **scenario)
    print(f"      video: {recording.path}")


DONE_MARKER = "done.json"


CODE_PACKAGES = ("sailmujoco", "sailmujoco.controllers", "sailmujoco.studies", "sailmujoco.xml")
CODE_SUFFIXES = (".py", ".xml", ".dat")


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


def _marker(name: str, smoke: bool, code: str) -> dict:
    from . import __version__

    return {"study": name, "smoke": bool(smoke), "code": code, "version": __version__}


def _finished(out: Path, marker: dict) -> bool:
    """Whether ``out`` holds a study's report finished with this marker (study, smoke, code)."""
    import json

    try:
        held = json.loads((out / DONE_MARKER).read_text())
    except (OSError, ValueError):
        return False
    return held == marker and (out / "report.md").is_file()


def _study(args) -> int:
    """Run one study, or all of them, into results/<study>/, on one worker pool."""
    import json

    from . import sweep

    studies = _studies()
    order = [n for n in STUDY_ORDER if n in studies] + sorted(set(studies) - set(STUDY_ORDER))
    names = order if args.name == "all" else [args.name]
    unknown = [n for n in names if n not in studies]
    if unknown:
        raise ValueError(f"unknown study {unknown[0]!r}; known: all, {', '.join(order)}")
    root = _out_folder(args.out)
    code = study_code_digest()
    start = time.perf_counter()
    took: dict[str, float] = {}
    # one worker pool for every study: in this process for --workers 1, an embedded cluster
    # (started at the first simulations) or the --scheduler's cluster
    scheduler = args.scheduler or ("serial" if args.workers == 1 else None)
    with sweep.Engine(scheduler, None if scheduler else args.workers) as engine:
        for i, name in enumerate(names, 1):
            out = root / name
            out.mkdir(parents=True, exist_ok=True)
            t0 = time.perf_counter()
            marker = _marker(name, args.smoke, code)
            left = len(names) - i + 1  # this one included; those kept by --resume are not counted
            note = (f"; {_progress_note(t0 - start, list(took.values()), len(took) + left)}"
                    if len(names) > 1 else "")
            if args.resume and _finished(out, marker):
                print(f"[{i}/{len(names)}] study {name}{' (smoke)' if args.smoke else ''}: finished "
                      f"before, kept ({out / 'report.md'})", flush=True)
                continue
            print(f"[{i}/{len(names)}] study {name}{' (smoke)' if args.smoke else ''} -> {out}"
                  + (" (resumed)" if args.resume else "") + note, flush=True)
            (out / DONE_MARKER).unlink(missing_ok=True)
            headline = studies[name].load()(out, smoke=args.smoke, workers=args.workers,
                                            progress=not args.no_progress, video=args.video,
                                            engine=engine, resume=args.resume)
            if args.video:
                _record_study_video(studies[name], out, args.smoke)
            (out / DONE_MARKER).write_text(json.dumps(marker, indent=1) + "\n")
            took[name] = time.perf_counter() - t0
            shown = ", ".join(f"{k} {v:.3g}" if isinstance(v, float) else f"{k} {v}"
                              for k, v in list(headline.items())[:6])
            print(f"      done in {took[name]:.0f} s: {shown}", flush=True)
    if len(took) > 1:
        print(timing_table(took, time.perf_counter() - start))
    print(f"all done in {time.perf_counter() - start:.0f} s; reports: "
          + ", ".join(str(root / n / "report.md") for n in names))
    return 0


def _clock(seconds: float) -> str:
    seconds = int(round(seconds))
    return f"{seconds // 3600}:{seconds % 3600 // 60:02d}:{seconds % 60:02d}"


def _progress_note(elapsed: float, took: list[float], total: int) -> str:
    """'elapsed 0:01:05, ETA 0:04:20 (...)' before study len(took)+1 of ``total``: the ETA is
    the finished studies' mean time times the studies left (none before the first ends)."""
    if not took:
        return f"elapsed {_clock(elapsed)}, ETA after the first study"
    left = total - len(took)
    return (f"elapsed {_clock(elapsed)}, ETA {_clock(left * sum(took) / len(took))} "
            f"({left} left x the mean {sum(took) / len(took):.0f} s of the {len(took)} done)")


def timing_table(took: dict[str, float], wall: float) -> str:
    """The time each study took, and the total, as a plain text table."""
    width = max([len("total (wall)")] + [len(n) for n in took])
    lines = [f"{'study':{width}s} {'time [s]':>9s} {'share':>6s}", "-" * (width + 17)]
    total = sum(took.values()) or 1.0
    for name, seconds in took.items():
        lines.append(f"{name:{width}s} {seconds:9.1f} {100 * seconds / total:5.0f} %")
    lines.append(f"{'total (wall)':{width}s} {wall:9.1f}")
    return "\n".join(lines)


def build_parser() -> argparse.ArgumentParser:
    """The ``sailmujoco`` parser: one sub-parser per command, its handler as ``func``.

    Returns
    -------
    argparse.ArgumentParser
    """
    parser = argparse.ArgumentParser(
        prog="sailmujoco",
        description="A MuJoCo 6-DOF testbed for autonomous sailboat control laws.")
    sub = parser.add_subparsers(dest="command", required=True)
    _add_check(sub)
    _add_sweep(sub)
    _add_polar(sub)
    study = sub.add_parser("study", help="regenerate a paper's figures and tables (or 'all')",
                           epilog=_study_epilog(), formatter_class=argparse.RawDescriptionHelpFormatter)
    study.add_argument("name", help="study name (listed below), or 'all'")
    study.add_argument("--smoke", action="store_true",
                       help="short runs: every path of the study, on reduced grids and durations")
    study.add_argument("--out", default="results", help="results root (default results/)")
    study.add_argument("--workers", type=WORKERS,
                       help="worker processes of the embedded cluster, one for every study (0: all cores; "
                            "1: in this process)")
    study.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    study.add_argument("--resume", action="store_true",
                       help="finish an interrupted run: skip the studies whose report finished, and run "
                            "only the missing simulations of the others")
    study.add_argument("--video", action="store_true", help="also record the main scenario")
    study.add_argument("--no-progress", action="store_true")
    study.set_defaults(func=_study)

    video.add_parser(sub)
    view.add_parser(sub)
    return parser


def _add_check(sub) -> None:
    check = sub.add_parser("check", help="load every boat, sail it, print a health report",
                           epilog="columns of the report:\n" + health.CHECK_LEGEND,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
    check.add_argument("--boat", action="append", help="only this boat (repeatable)")
    check.add_argument("--seconds", type=POSITIVE_SECONDS, default=20.0, help="simulated time per run (s)")
    check.add_argument("--wind", type=number(0.0, low_open=False, unit="m/s"), default=10.0,
                       help="mean wind at 10 m (m/s)")
    check.add_argument("--seed", type=SEED, default=0)
    check.add_argument("--plots", nargs="?", const="results/check", default=None,
                       metavar="DIR", help="write righting-curve plots (default results/check)")
    check.set_defaults(func=health.run_cli)


def _add_sweep(sub) -> None:
    sweep = sub.add_parser("sweep", help="run a parameter sweep described by a TOML file")
    sweep.add_argument("file", help="sweep description (TOML), see sailmujoco.sweep")
    sweep.add_argument("--out", help="results folder (default results/sweeps/<name>)")
    sweep.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    sweep.add_argument("--workers", type=WORKERS,
                       help="worker processes of the embedded cluster (0: all cores)")
    sweep.add_argument("--resume", action="store_true",
                       help="run only the missing runs and those lost with a worker that died")
    sweep.add_argument("--retries", type=number(0, low_open=False, unit="", integer=True), default=2,
                       help="extra attempts of a failing run")
    sweep.add_argument("--no-progress", action="store_true", help="no progress bar")
    sweep.set_defaults(func=sweep_cli.run_cli)


def _add_polar(sub) -> None:
    parser = sub.add_parser("polar", help="polar diagram (speed vs true wind angle) of a boat")
    parser.add_argument("boat")
    parser.add_argument("--controller", default="saoud",
                        help="sail law + heading rudder by name (saoud, briere, pid, best, ...)")
    parser.add_argument("--compare", help="other controllers to compare, comma separated "
                                          "('best' = brute-force fixed-sail vel_max)")
    parser.add_argument("--world", default="mujoco", choices=("mujoco", "paper"))
    parser.add_argument("--tws", type=floats, default=[2.0, 4.0, 6.0],
                        help="true wind speeds, m/s: '2,4,6' or 'start:stop:step'")
    parser.add_argument("--twa", type=floats, default=[float(a) for a in range(30, 181, 15)],
                        help="true wind angles, deg: '30:180:15'")
    parser.add_argument("--duration", type=POSITIVE_SECONDS, default=60.0, help="seconds per point")
    parser.add_argument("--out", help="output folder (default results/polar/<boat>-<controller>)")
    parser.add_argument("--scheduler", help="Dask scheduler address, or 'serial'")
    parser.add_argument("--workers", type=WORKERS, help="worker processes (0: all cores)")
    parser.add_argument("--no-progress", action="store_true")
    parser.set_defaults(func=polar.run_cli)


def main(argv=None) -> int:
    """Run ``sailmujoco`` with ``argv`` (default: the command line's).

    Parameters
    ----------
    argv : list of str, optional
        The arguments after ``sailmujoco``.

    Returns
    -------
    int
        The exit status: 0, 1 (a command's own failure), 2 (bad input) or
        :data:`~sailmujoco.arguments.INTERRUPTED`.
    """
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except ValueError as err:  # bad input: one clear line, exit 2
        print(f"sailmujoco: error: {err}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # Ctrl-C: one line, not the traceback of wherever it landed
        print(f"sailmujoco {args.command}: interrupted", file=sys.stderr)
        return INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
