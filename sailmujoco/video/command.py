"""``sailmujoco video BOAT TASK --controller NAME --out FILE.mp4``: the command and its arguments."""

from __future__ import annotations

import argparse
import sys

from ..arguments import SEED, check_settings, file_argument, setting
from ..options import World, choices
from .gl import FIX, RenderingUnavailable
from .recording import record
from .scene import CAMERAS


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Add ``video`` to the ``sailmujoco`` sub-commands.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        From ``ArgumentParser.add_subparsers``.

    Returns
    -------
    argparse.ArgumentParser
        The ``video`` parser.
    """
    parser = subparsers.add_parser(
        "video", help="record a task run as an mp4 (offscreen MuJoCo rendering)",
        description="Run TASK on BOAT under a controller and write an H.264 mp4. Needs an OpenGL "
                    f"platform: {FIX}.")
    parser.add_argument("boat")
    parser.add_argument("task")
    parser.add_argument("--controller", required=True,
                        help="a registered controller (pid, saoud, ...), module:factory or file.py:factory")
    parser.add_argument("--world", default="mujoco", choices=choices(World))
    parser.add_argument("--seconds", type=float, default=30.0, help="simulated seconds (default 30)")
    parser.add_argument("--out", required=True, help="output file (.mp4); missing folders are made")
    parser.add_argument("--fps", type=float, default=25.0, help="frames per simulated second")
    parser.add_argument("--width", type=int, default=640)
    parser.add_argument("--height", type=int, default=480)
    parser.add_argument("--camera", default="follow", choices=CAMERAS)
    parser.add_argument("--distance", type=float, help="follow camera distance, m")
    parser.add_argument("--bearing", type=float,
                        help="follow camera bearing from the bow, deg counter-clockwise (default: "
                             "astern on the side away from the boom, turned to see the sail's "
                             "face)")
    parser.add_argument("--no-forces", action="store_true", help="no force arrows")
    parser.add_argument("--no-overlay", action="store_true", help="no panel (map, numbers)")
    parser.add_argument("--seed", type=SEED, default=0)
    parser.add_argument("--still", help="also write the last frame as this PNG")
    parser.add_argument("--set", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="task or environment option, e.g. case=3 or hydrostatics=paper "
                             "(repeatable)")
    parser.add_argument("--no-progress", action="store_true")
    parser.set_defaults(func=run_cli)
    return parser


def run_cli(args) -> int:
    """The ``video`` sub-command.

    Parameters
    ----------
    args : argparse.Namespace
        The arguments of :func:`add_parser`'s parser.

    Returns
    -------
    int
        0, or 1 where no OpenGL platform loads (one line on stderr).
    """
    check_settings(args.set, args.task)
    file_argument("--out", args.out, "run.mp4")
    if args.still:
        file_argument("--still", args.still, "last.png")
    try:
        rec = record(args.boat, args.task, args.controller, args.out, seconds=args.seconds,
                     world=args.world, fps=args.fps, width=args.width, height=args.height,
                     camera=args.camera, overlay=not args.no_overlay, forces=not args.no_forces,
                     seed=args.seed, still=args.still, progress=not args.no_progress,
                     follow_distance=args.distance, follow_bearing_deg=args.bearing,
                     **dict(args.set))
    except RenderingUnavailable as err:
        print(f"sailmujoco video: error: {err}", file=sys.stderr)
        return 1
    stopped = rec.metrics.get("stopped")
    print(f"wrote {rec.path}: {rec.frames} frames at {rec.fps:g} fps, {rec.sim_time:.1f} s simulated, "
          f"{rec.wall_time:.1f} s wall ({rec.render_rate:.1f} frames/s while recording)"
          + (f"; stopped: {stopped}" if stopped else ""))
    if args.still:
        print(f"wrote {args.still}")
    return 0


def main(argv=None) -> int:
    """``python -m sailmujoco.video BOAT TASK --controller NAME --out FILE.mp4 ...``

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default: the command line's).

    Returns
    -------
    int
        The exit status (2 for bad input, one line on stderr).
    """
    parser = argparse.ArgumentParser(prog="python -m sailmujoco.video")
    add_parser(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args(["video", *(sys.argv[1:] if argv is None else argv)])
    try:
        return args.func(args)
    except ValueError as err:
        print(f"sailmujoco video: error: {err}", file=sys.stderr)
        return 2
