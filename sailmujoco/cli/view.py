"""``sailmujoco view BOAT TASK --controller NAME``: the command and its arguments.

The viewer itself is :func:`sailmujoco.viewer.view.watch`.
"""

from __future__ import annotations

import argparse
import sys

from ..boat.catalogue import boat_label
from ..errors import ControllerFailed
from ..options import World, choices
from ..viewer.view import KEYS, watch
from ..viewer.window import NoDisplay
from .arguments import (
    POSITIVE_SECONDS,
    SEED,
    HelpFormatter,
    add_controller_arguments,
    check_settings,
    controller_options,
    number,
    setting,
)
from .waves import add_waves_argument, waves_from_arguments

EXAMPLES = """examples:
  sailmujoco view wille_yacht heading_hold --controller pid
  sailmujoco view saoud_robot heading_hold --controller pid --option kp=2.0 --set wind_speed=4
  sailmujoco view saoud_robot heading_hold --controller my_law.py:make --paused
  sailmujoco view wille_yacht beam_reach_roll --controller wille_roll --waves hs=1.5 \\
      --waves tp=6     # a 1.5 m sea from the wind's bearing
  xvfb-run -a sailmujoco view wille_yacht heading_hold --controller pid --seconds 10 \\
      --screenshot view.png        # headless: a virtual display"""


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Add ``view`` to the ``sailmujoco`` sub-commands.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        From ``ArgumentParser.add_subparsers``.

    Returns
    -------
    argparse.ArgumentParser
        The ``view`` parser.
    """
    parser = subparsers.add_parser(
        "view", help="watch a task run in MuJoCo's interactive viewer (needs a display)",
        formatter_class=HelpFormatter, epilog=KEYS + "\n\n" + EXAMPLES,
        description="Run TASK on BOAT under a controller in MuJoCo's interactive viewer, at real\n"
                    "time, with the wind arrow, force arrows and heel/speed text of the videos.\n"
                    "Without a display it says so in one line (exit status 2): record a video\n"
                    "with 'sailmujoco video' instead (headless: xvfb-run sailmujoco view ...).")
    parser.add_argument("boat", help="a registered boat (sailmujoco list) or a boat file (.toml)")
    parser.add_argument("task", help="a registered task (sailmujoco list)")
    add_controller_arguments(parser)
    parser.add_argument("--world", default="mujoco", choices=choices(World),
                        help="paper: the paper's reduced model, drawn as the 6-DOF boat posed from its state")
    parser.add_argument("--seconds", type=POSITIVE_SECONDS,
                        help="stop after this much simulated time and close the window (default: run "
                             "the task to its end and keep the window open until it is closed)")
    parser.add_argument("--fps", type=number(0.0, low_open=True, unit="frames per simulated second"),
                        default=30.0, help="frames per simulated second (default 30)")
    parser.add_argument("--paused", action="store_true", help="start paused (space runs)")
    parser.add_argument("--no-forces", action="store_true", help="no force arrows")
    parser.add_argument("--no-overlay", action="store_true", help="no text")
    parser.add_argument("--seed", type=SEED, default=0, help="seeds the task and the controller")
    parser.add_argument("--screenshot", metavar="PATH",
                        help="at the end, save the last state as this PNG, drawn from the window's "
                             "camera with the videos' map and numbers")
    parser.add_argument("--set", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="task or environment option, e.g. case=3 or hydrostatics=paper (repeatable)")
    add_waves_argument(parser)
    parser.set_defaults(func=run_cli)
    return parser


def run_cli(args) -> int:
    """The ``view`` sub-command.

    Parameters
    ----------
    args : argparse.Namespace
        The arguments of :func:`add_parser`'s parser.

    Returns
    -------
    int
        0; 2 where no window can be opened (one line on stderr that points to ``sailmujoco
        video``) or where the controller raised or gave a bad action (one line with the time).
    """
    from ..sweep import validate

    check_settings(args.set, args.task)

    # names first, so that without a display the suggested video command is one that runs
    validate({"boat": args.boat, "task": args.task, "world": args.world, "controller": args.controller})
    options = controller_options(args)
    settings = dict(args.set)
    waves = waves_from_arguments(args.waves, args.task, args.world, args.seed, settings)
    if waves is not None:
        settings["waves"] = waves
    try:
        result = watch(args.boat, args.task, args.controller, world=args.world, seconds=args.seconds,
                       controller_options=options,
                       seed=args.seed, fps=args.fps, forces=not args.no_forces,
                       overlay=not args.no_overlay, paused=args.paused,
                       screenshot_path=args.screenshot, **settings)
    except NoDisplay as err:
        print(f"sailmujoco view: cannot open a window: {err}; {_video_hint(args)}", file=sys.stderr)
        return 2
    except ControllerFailed as err:
        saved = f"; wrote {args.screenshot}: {err.kept}" if err.kept else ""
        print(f"sailmujoco view: {err}; the run stops there{saved}", file=sys.stderr)
        return 2
    stopped = result["stopped"]
    print(f"viewed {result['sim_time']:.2f} s simulated in {result['wall_time']:.2f} s "
          f"(real-time factor {result['real_time_factor']:.2f}); the boat moved "
          f"{result['distance']:.2f} m" + (f"; stopped: {stopped}" if stopped else ""))
    if result["screenshot"]:
        print(f"wrote {args.screenshot}: {result['screenshot']}")
    return 0


def _video_hint(args) -> str:
    """The ``sailmujoco video`` command that records what ``args`` would have shown."""
    world = f" --world {args.world}" if args.world != "mujoco" else ""
    options = "".join(f" --option {key}={value!r}" for key, value in args.option)
    options += "".join(f" --waves {key}={value}" for key, value in getattr(args, "waves", []))
    return (f"record a video instead: sailmujoco video {args.boat} {args.task} "
            f"--controller {args.controller}{options}{world} "
            f"--out results/{boat_label(args.boat)}_{args.task}.mp4")
