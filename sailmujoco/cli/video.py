"""``sailmujoco video BOAT TASK --controller NAME --out FILE.mp4``: the command and its arguments."""

from __future__ import annotations

import argparse
import sys
import textwrap

from ..errors import ControllerFailed
from ..options import World, choices
from ..ros2.record import RosbagsMissing, check_log_path
from ..video.gl import FIX, RenderingUnavailable
from ..video.recording import record
from ..video.scene import CAMERAS
from .arguments import (
    SEED,
    HelpFormatter,
    add_controller_arguments,
    check_settings,
    controller_options,
    file_argument,
    setting,
)
from .waves import add_waves_argument, waves_from_arguments

EXAMPLES = """examples:
  sailmujoco video wille_yacht heading_hold --controller pid --out results/pid.mp4
  sailmujoco video saoud_robot heading_hold --controller pid --option kp=2.0 --seconds 20 \\
      --camera top --set wind_speed=4 --out results/saoud_kp2.mp4 --still results/saoud_kp2.png
  sailmujoco video saoud_robot heading_hold --controller my_law.py:make --option gain=0.5 \\
      --out results/my_law.mp4
  sailmujoco video wille_yacht beam_reach_roll --controller wille_roll --seconds 30 \\
      --waves hs=1.5 --waves tp=6 --out results/beam_sea.mp4
      # a 1.5 m JONSWAP sea (the default spectrum), 6 s peak period, from the wind's bearing"""


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
        formatter_class=HelpFormatter, epilog=EXAMPLES,
        description=textwrap.fill("Run TASK on BOAT under a controller and write an H.264 mp4. "
                                  f"Needs an OpenGL platform: {FIX}.", 90))
    parser.add_argument("boat", help="a registered boat (sailmujoco list) or a boat file (.toml)")
    parser.add_argument("task", help="a registered task (sailmujoco list)")
    add_controller_arguments(parser)
    parser.add_argument("--world", default="mujoco", choices=choices(World),
                        help="mujoco: the 6-DOF boat; paper: the paper's reduced model, drawn as "
                             "the 6-DOF boat posed from its state")
    parser.add_argument("--seconds", type=float, default=30.0, help="simulated seconds (default 30)")
    parser.add_argument("--out", required=True, help="output file (.mp4); missing folders are made")
    parser.add_argument("--fps", type=float, default=25.0, help="frames per simulated second")
    parser.add_argument("--width", type=int, default=640, help="frame width, pixels (even)")
    parser.add_argument("--height", type=int, default=480, help="frame height, pixels (even)")
    parser.add_argument("--camera", default="follow", choices=CAMERAS,
                        help="follow: behind the boat; top: from above; side: abeam")
    parser.add_argument("--distance", type=float, help="follow camera distance, m")
    parser.add_argument("--bearing", type=float,
                        help="follow camera bearing from the bow, deg counter-clockwise (default: "
                             "astern on the side away from the boom, turned to see the sail's "
                             "face)")
    parser.add_argument("--no-forces", action="store_true", help="no force arrows")
    parser.add_argument("--no-overlay", action="store_true", help="no panel (map, numbers)")
    parser.add_argument("--seed", type=SEED, default=0, help="seeds the task and the controller")
    parser.add_argument("--still", help="also write the last frame as this PNG")
    parser.add_argument("--set", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="task or environment option, e.g. case=3 or hydrostatics=paper "
                             "(repeatable)")
    add_waves_argument(parser)
    parser.add_argument("--record", metavar="FILE.mcap",
                        help="also write the run as an MCAP log of ROS 2 messages (docs/ros2.md; needs "
                             "pip install 'sailmujoco[ros2]')")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
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
        0; 1 where no OpenGL platform loads (or, with --record, rosbags is missing); 2 where the
        controller raised or gave a bad action
        (the video, cut at that state, is kept). Each failure is one line on stderr.
    """
    check_settings(args.set, args.task)
    options = controller_options(args)
    waves = waves_from_arguments(args.waves, args.task, args.world, args.seed, dict(args.set))
    file_argument("--out", args.out, "run.mp4")
    if args.still:
        file_argument("--still", args.still, "last.png")
    if args.record:
        file_argument("--record", args.record, "run.mcap")
        check_log_path(args.record, "--record")
    try:
        rec = record(args.boat, args.task, args.controller, args.out, seconds=args.seconds,
                     controller_options=options,
                     world=args.world, fps=args.fps, width=args.width, height=args.height,
                     camera=args.camera, overlay=not args.no_overlay, forces=not args.no_forces,
                     seed=args.seed, still=args.still, progress=not args.no_progress,
                     follow_distance=args.distance, follow_bearing_deg=args.bearing,
                     waves=waves, log=args.record, **dict(args.set))
    except (RenderingUnavailable, RosbagsMissing) as err:
        print(f"sailmujoco video: error: {err}", file=sys.stderr)
        return 1
    except ControllerFailed as err:
        rec = err.kept
        still = f" and {args.still}" if args.still else ""
        print(f"sailmujoco video: {err}; the video stops there: {rec.path}{still} "
              f"({rec.sim_time:.1f} s of {args.seconds:g} s)", file=sys.stderr)
        return 2
    stopped = rec.metrics.get("stopped")
    print(f"wrote {rec.path}: {rec.frames} frames at {rec.fps:g} fps, {rec.sim_time:.1f} s simulated, "
          f"{rec.wall_time:.1f} s wall ({rec.render_rate:.1f} frames/s while recording)"
          + (f"; stopped: {stopped}" if stopped else ""))
    if args.still:
        print(f"wrote {args.still}")
    if args.record:
        print(f"wrote {args.record}")
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
