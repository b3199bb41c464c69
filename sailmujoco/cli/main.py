"""The ``sailmujoco`` command: each sub-command and the function that runs it (``add_parser`` beside it).

====================  =============================================================
``list``              :func:`sailmujoco.cli.listing.run_cli`
``check``             :func:`sailmujoco.cli.health.run_cli`
``sweep FILE``        :func:`sailmujoco.cli.sweep.run_cli`
``polar BOAT``        :func:`sailmujoco.cli.polar.run_cli`
``study NAME``        :func:`sailmujoco.cli.study.run_studies`
``video BOAT TASK``   :func:`sailmujoco.cli.video.run_cli`
``view BOAT TASK``    :func:`sailmujoco.cli.view.run_cli`
``boat ACTION``       :func:`sailmujoco.cli.boat.run_cli`
``sitl BOAT``         :func:`sailmujoco.cli.sitl.run_cli`
``ros2 BOAT [TASK]``  :func:`sailmujoco.cli.ros2.run_cli`
====================  =============================================================

Bad input (a ``ValueError`` from any command) is one line on stderr and exit status 2; Ctrl-C is
one line and :data:`~sailmujoco.cli.arguments.INTERRUPTED`.
"""

from __future__ import annotations

import argparse
import sys
from importlib import metadata

from . import boat as boat_cli
from . import health, listing, polar, ros2, sitl, video, view
from . import study as study_runner
from . import sweep as sweep_cli
from .arguments import (
    INTERRUPTED,
    POSITIVE_SECONDS,
    SEED,
    SEEDS,
    WORKERS,
    HelpFormatter,
    number,
    out_folder,
)

EXAMPLES = """examples:
  sailmujoco list
  sailmujoco check --boat saoud_robot
  sailmujoco sweep --example > example.toml && sailmujoco sweep example.toml --workers 2
  sailmujoco polar saoud_robot --controller saoud --tws 4 --twa 45:180:15
  sailmujoco study saoud_fig6 --smoke
  sailmujoco video wille_yacht heading_hold --controller my_law.py:make --option gain=0.5 --out run.mp4

a controller of your own: a factory(env, **options) in any file, named 'path/to/file.py:factory'
(or 'package.module:factory') wherever a controller is asked for; no package, no reinstall.
bad input is one line on stderr and exit status 2; Ctrl-C is one line and exit status 130."""


def version() -> str:
    """The installed distribution's version (``sailmujoco --version``).

    Returns
    -------
    str
    """
    try:
        return metadata.version("sailmujoco")
    except metadata.PackageNotFoundError:  # a source tree on the path, not installed
        from .. import __version__

        return __version__


def _study(args) -> int:
    """Run one study, or all of them, into results/<study>/ (:mod:`sailmujoco.cli.study`)."""
    names = study_runner.select(args.name)
    root = out_folder(args.out)
    return study_runner.run_studies(names, root, smoke=args.smoke, workers=args.workers,
                                    scheduler=args.scheduler, resume=args.resume,
                                    progress=not args.no_progress, video=args.video, seeds=args.seeds)


def build_parser() -> argparse.ArgumentParser:
    """The ``sailmujoco`` parser: one sub-parser per command, its handler as ``func``.

    Returns
    -------
    argparse.ArgumentParser
    """
    parser = argparse.ArgumentParser(
        prog="sailmujoco", formatter_class=HelpFormatter, epilog=EXAMPLES,
        description="A MuJoCo 6-DOF testbed for autonomous sailboat control laws.")
    parser.add_argument("--version", action="version", version=f"sailmujoco {version()}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    _add_list(sub)
    _add_check(sub)
    _add_sweep(sub)
    polar.add_parser(sub)
    _add_study(sub)
    video.add_parser(sub)
    view.add_parser(sub)
    boat_cli.add_parser(sub)
    sitl.add_parser(sub)
    ros2.add_parser(sub)
    return parser


def _add_list(sub) -> None:
    parser = sub.add_parser("list", help="the boats, tasks, worlds, controllers and studies",
                            formatter_class=HelpFormatter,
                            description="What there is to run, one line each.",
                            epilog="examples:\n  sailmujoco list\n  sailmujoco list controllers")
    parser.add_argument("what", nargs="?", choices=listing.SECTIONS, help="only this section")
    parser.set_defaults(func=listing.run_cli)


def _add_study(sub) -> None:
    study = sub.add_parser("study", help="regenerate a paper's figures and tables (or 'all')",
                           formatter_class=HelpFormatter,
                           description="Run a study: its simulations on the sweep engine, then its "
                                       "report.md,\nCSV tables and PNG figures in <out>/<study>/.",
                           epilog=study_runner.epilog() + "\n\nexamples:\n"
                                  "  sailmujoco study saoud_fig6 --smoke      # a short pass\n"
                                  "  sailmujoco study wille_roll_table1 --seeds 10   # tighter intervals\n"
                                  "  sailmujoco study all --workers 2 --resume")
    study.add_argument("name", help="study name (listed below), or 'all'")
    study.add_argument("--smoke", action="store_true",
                       help="short runs: every path of the study, on reduced grids and durations")
    study.add_argument("--seeds", type=SEEDS, metavar="N",
                       help="run every stochastic case on seeds 0..N-1 (each study declares its own N; "
                            "--smoke: 2); its numbers are means with 95 %% intervals over them")
    study.add_argument("--out", default="results", help="results root")
    study.add_argument("--workers", type=WORKERS,
                       help="worker processes of the embedded cluster, one for every study (0: all cores; "
                            "1: in this process)")
    study.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    study.add_argument("--resume", action="store_true",
                       help="finish an interrupted run: skip the studies whose report finished, and run "
                            "only the missing simulations of the others")
    study.add_argument("--video", action="store_true", help="also record the main scenario")
    study.add_argument("--no-progress", action="store_true", help="no progress bar")
    study.set_defaults(func=_study)


def _add_check(sub) -> None:
    check = sub.add_parser("check", help="load every boat, sail it, print a health report",
                           description="Load every boat (or those given) in each hydrostatics "
                                       "mode, sail it in a gusty wind\nunder random commands and "
                                       "print one line per run: a quick check of a boat's model.",
                           epilog="columns of the report:\n" + health.CHECK_LEGEND
                                  + "\n\nexamples:\n  sailmujoco check\n"
                                    "  sailmujoco check --boat saoud_robot --seconds 60 --plots",
                           formatter_class=HelpFormatter)
    check.add_argument("--boat", action="append", help="only this boat (repeatable)")
    check.add_argument("--seconds", type=POSITIVE_SECONDS, default=20.0, help="simulated time per run (s)")
    check.add_argument("--wind", type=number(0.0, low_open=False, unit="m/s"), default=10.0,
                       help="mean wind at 10 m (m/s)")
    check.add_argument("--seed", type=SEED, default=0, help="seeds the wind and the initial state")
    check.add_argument("--plots", nargs="?", const="results/check", default=None,
                       metavar="DIR", help="write righting-curve plots (default results/check)")
    check.set_defaults(func=health.run_cli)


def _add_sweep(sub) -> None:
    sweep = sub.add_parser("sweep", help="run a parameter sweep described by a TOML file",
                           formatter_class=HelpFormatter, epilog=sweep_cli.epilog(),
                           description="Run every run of a sweep file on worker processes and "
                                       "write its table; each run\nis saved as it finishes, so "
                                       "--resume after Ctrl-C runs only the missing ones.")
    sweep.add_argument("file", nargs="?", help="the sweep file (TOML; its keys are listed below)")
    sweep.add_argument("--example", action="store_true",
                       help="print a complete, commented sweep file that runs as printed")
    sweep.add_argument("--out", help="results folder (default results/sweeps/<name>)")
    sweep.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    sweep.add_argument("--workers", type=WORKERS,
                       help="worker processes of the embedded cluster (0 or unset: all cores)")
    sweep.add_argument("--resume", action="store_true",
                       help="run only the missing runs and those lost with a worker that died")
    sweep.add_argument("--retries", type=number(0, low_open=False, unit="", integer=True), default=2,
                       help="extra attempts of a run lost with a worker that died (a run that raised "
                            "is not retried)")
    sweep.add_argument("--no-progress", action="store_true", help="no progress bar")
    sweep.set_defaults(func=sweep_cli.run_cli)


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
        :data:`~sailmujoco.cli.arguments.INTERRUPTED`.
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
