"""The ``sailmujoco`` command: the arguments of each sub-command, and the module that runs it.

====================  =============================================================
``check``             :func:`sailmujoco.health.run_cli`
``sweep FILE``        :func:`sailmujoco.sweep_cli.run_cli`
``polar BOAT``        :func:`sailmujoco.polar.run_cli`
``study NAME``        :func:`sailmujoco.study_runner.run_studies`
``video BOAT TASK``   :func:`sailmujoco.video.run_cli` (its parser: :func:`sailmujoco.video.add_parser`)
``view BOAT TASK``    :func:`sailmujoco.view.run_cli` (its parser: :func:`sailmujoco.view.add_parser`)
``boat ACTION``       :func:`sailmujoco.boat_cli.run_cli` (its parser: :func:`sailmujoco.boat_cli.add_parser`)
====================  =============================================================

Bad input (a ``ValueError`` from any command) is one line on stderr and exit status 2; Ctrl-C is
one line and :data:`~sailmujoco.arguments.INTERRUPTED`.
"""

from __future__ import annotations

import argparse
import sys

from . import boat_cli, health, polar, study_runner, sweep_cli, video, view
from .arguments import INTERRUPTED, POSITIVE_SECONDS, SEED, WORKERS, floats, number, out_folder
from .options import World, choices


def _study(args) -> int:
    """Run one study, or all of them, into results/<study>/ (:mod:`sailmujoco.study_runner`)."""
    names = study_runner.select(args.name)
    root = out_folder(args.out)
    return study_runner.run_studies(names, root, smoke=args.smoke, workers=args.workers,
                                    scheduler=args.scheduler, resume=args.resume,
                                    progress=not args.no_progress, video=args.video)


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
                           epilog=study_runner.epilog(), formatter_class=argparse.RawDescriptionHelpFormatter)
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
    boat_cli.add_parser(sub)
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
                        help="sail law + heading rudder by name (saoud, briere, pid, best, ...), "
                             "module:factory or file.py:factory")
    parser.add_argument("--compare", help="other controllers to compare, comma separated "
                                          "('best' = brute-force fixed-sail vel_max)")
    parser.add_argument("--world", default="mujoco", choices=choices(World))
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
