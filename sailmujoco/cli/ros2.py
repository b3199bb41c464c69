"""``sailmujoco ros2 BOAT [TASK]``: the boat as a ROS 2 node, lock-step with sim time.

::

    sailmujoco ros2 eleven_metre --set sensors=typical --seconds 300 --record run.mcap

It publishes the boat's instruments and its truth on the topics of
:mod:`sailmujoco.ros2.contract` (``/clock``, ``/gps/fix``, ``/imu/data``, ``/wind/apparent``,
``/sim/odom``, ...) and reads ``/rudder/command`` and ``/sail/command``; each control step
waits for both (``--rate X``: free-running at X times real time instead). It ends at the
episode's end (``--seconds``, default the task's), when no command came for ``--timeout``
seconds, or on Ctrl-C, and prints what it did. docs/ros2.md is the recipe.
"""

from __future__ import annotations

import argparse
import signal
import sys

import numpy as np

from .arguments import (
    INTERRUPTED,
    SEED,
    HelpFormatter,
    Terminated,
    check_settings,
    file_argument,
    number,
    raise_terminated,
    setting,
)
from .waves import add_waves_argument, waves_from_arguments

EXAMPLES = """examples:
  sailmujoco ros2 eleven_metre                          # heading_hold's wind, lock-step
  sailmujoco ros2 wille_yacht course_hold --set sensors=typical --waves hs=1 --record run.mcap
  sailmujoco ros2 my_boat.toml --remap topics.toml --rate 1  # a team's topic names, real time"""


def add_parser(sub) -> None:
    """Add ``ros2`` to the ``sailmujoco`` sub-commands.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The ``sailmujoco`` parser's sub-commands.
    """
    parser = sub.add_parser("ros2", help="the boat as a ROS 2 node on standard topics, lock-step with /clock",
                            description="Sail BOAT on TASK as a ROS 2 node: publish its instruments "
                                        "(sensor_msgs, geometry_msgs) and truth (/sim), read "
                                        "/rudder/command and /sail/command (docs/ros2.md; needs "
                                        "pip install 'sailmujoco[ros2]').",
                            formatter_class=HelpFormatter, epilog=EXAMPLES)
    parser.add_argument("boat", help="a registered boat (sailmujoco list) or a boat file (.toml)")
    parser.add_argument("task", nargs="?", default="heading_hold",
                        help="a registered task: its wind, start and length (default heading_hold)")
    parser.add_argument("--seconds", type=number(0.0, low_open=True, unit="s"), default=None,
                        help="simulated seconds (default: the task's)")
    parser.add_argument("--seed", type=SEED, default=0,
                        help="seeds the task, the wind, the sea and the sensors")
    parser.add_argument("--set", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="task or environment option, e.g. sensors=typical or wind_speed=6 (repeatable)")
    add_waves_argument(parser)
    parser.add_argument("--origin", type=_origin, default=None, metavar="LAT,LON",
                        help="where the world's origin lies, degrees (default 59.9,10.7: the Oslo fjord)")
    parser.add_argument("--remap", metavar="FILE.toml",
                        help="the team's topic names: a [topics] table of default name = new name")
    parser.add_argument("--rate", type=number(0.0, low_open=True, unit="times real time", high=1000.0),
                        default=None, metavar="X",
                        help="free-running at X times real time, the latest commands held (default: "
                             "lock-step, each step waits for both commands)")
    parser.add_argument("--timeout", type=number(0.0, low_open=True, unit="s"), default=30.0,
                        help="lock-step: seconds of wall time without a command that end the run "
                             "(default 30)")
    parser.add_argument("--record", metavar="FILE.mcap",
                        help="also write the run as an MCAP log of the same messages")
    parser.set_defaults(func=run_cli)


def _origin(text: str):
    from ..ros2.geodesy import Origin

    try:
        latitude, longitude = (float(part) for part in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected LAT,LON in degrees, e.g. 59.9,10.7, "
                                         f"got {text!r}") from None
    if not (-90.0 < latitude < 90.0 and -180.0 <= longitude <= 180.0):
        raise argparse.ArgumentTypeError(f"latitude must lie in (-90, 90) and longitude in [-180, 180] "
                                         f"degrees, got {text!r}")
    return Origin(latitude=latitude, longitude=longitude)


def run_cli(args) -> int:
    """Run ``sailmujoco ros2``.

    Parameters
    ----------
    args : argparse.Namespace
        ``boat``, ``task``, ``seconds``, ``seed``, ``set``, ``waves``, ``origin``, ``remap``,
        ``rate``, ``timeout``, ``record``.

    Returns
    -------
    int
        0; 1 where rclpy (or, with --record, rosbags) is missing; 2 where ROS 2 does not start or
        a topic carries another type (one line on stderr).
    """
    from .. import suite
    from ..boat.catalogue import boat_label
    from ..ros2.contract import DEFAULT_ORIGIN, read_remap
    from ..ros2.node import Bridge, BridgeError, RclpyMissing, require_rclpy
    from ..ros2.record import McapLog, RosbagsMissing, check_log_path

    check_settings(args.set, args.task)
    settings = dict(args.set)
    waves = waves_from_arguments(args.waves, args.task, "mujoco", args.seed, settings)
    names = read_remap(args.remap) if args.remap else None
    origin = args.origin or DEFAULT_ORIGIN
    if args.record:
        file_argument("--record", args.record, "run.mcap")
        check_log_path(args.record, "--record")
    if waves is not None:
        settings["waves"] = waves
    try:
        require_rclpy()  # before a first run's minute of compiling, not after it
    except RclpyMissing as err:
        print(f"sailmujoco ros2: {err}", file=sys.stderr)
        return 1
    env = suite.load(args.boat, args.task, seed=args.seed, time_limit=args.seconds, **settings)
    # a first run compiles numba's kernels on the first step: a throwaway copy takes it before the
    # clock starts, so that the stack's nodes do not wait through it mid-run
    warm = suite.load(args.boat, args.task, seed=args.seed, time_limit=args.seconds, **settings)
    warm.reset()
    warm.step(np.zeros(warm.action_spec().shape))
    log = bridge = None
    previous = signal.signal(signal.SIGTERM, raise_terminated)
    try:
        log = McapLog(env, args.record, origin=origin) if args.record else None
        bridge = Bridge(env, origin=origin, names=names, rate=args.rate, timeout=args.timeout, record=log,
                        say=lambda line: print(line, flush=True))
        how = "lock-step" if args.rate is None else f"free-running at {args.rate:g} times real time"
        print(f"ros2: {boat_label(args.boat)} on {args.task}, {how}", flush=True)
        counters = bridge.run()
    except (RclpyMissing, RosbagsMissing) as err:
        print(f"sailmujoco ros2: {err}", file=sys.stderr)
        return 1
    except BridgeError as err:
        print(f"sailmujoco ros2: {err}", file=sys.stderr)
        return 2
    except (Terminated, KeyboardInterrupt) as stop:
        if bridge is None:
            return INTERRUPTED
        counters = bridge.counters
        counters.ended = "interrupted" if isinstance(stop, KeyboardInterrupt) else "terminated"
    finally:
        signal.signal(signal.SIGTERM, previous)
        if log is not None:
            log.close()
    print(f"ros2: {counters.steps} steps ({counters.simulated:.1f} s simulated) in {counters.wall:.1f} s, "
          f"{counters.speed:.1f} times real time; {counters.resent} resent, {counters.refused} refused; "
          f"ended: {counters.ended}" + (f"; the log in {args.record}" if args.record else ""), flush=True)
    return 0
