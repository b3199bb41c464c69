"""``sailmujoco sitl BOAT``: the 6-DOF boat as ArduPilot SITL's JSON physics backend.

::

    sailmujoco sitl saoud_robot --wind-speed 5 --wind-from 0 --out results/sitl/robot
    ardurover --model JSON -w --defaults rover.parm,sailboat.parm,json_windvane.parm ...

It listens on UDP 9002 (``--port``), answers every servo packet with one physics step and the
boat's state, and ends when SITL stops sending for ``--timeout`` seconds (or after
``--seconds`` of simulated time); then it prints what it did (frames, resends, refusals, the
speed against real time) and writes the trajectory table, ``trajectory.csv`` (one row per
0.1 s, a file per run when SITL restarted), under ``--out``, and with ``--video`` films the run
once it is over. docs/ardupilot.md is the recipe.
"""

from __future__ import annotations

import math
import signal
import sys
from pathlib import Path

from .arguments import SEED, HelpFormatter, Terminated, file_argument, number, out_folder, raise_terminated
from .waves import add_waves_argument

EXAMPLES = """examples:
  sailmujoco sitl saoud_robot                                   # 5 m/s from the north, calm
  sailmujoco sitl wille_yacht --wind-speed 7 --wind-from 30 --waves hs=1 --sensors typical
  sailmujoco sitl my_boat.toml --port 9012 --out results/sitl/mine   # ardurover -I 1"""


def add_parser(sub) -> None:
    """Add ``sitl`` to the ``sailmujoco`` sub-commands.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The ``sailmujoco`` parser's sub-commands.
    """
    parser = sub.add_parser("sitl", help="the boat as ArduPilot SITL's JSON physics backend (lock-step)",
                            description="Sail BOAT as ArduPilot's physics: answer each servo packet of "
                                        "'ardurover --model JSON' with one physics step and the boat's "
                                        "state (docs/ardupilot.md).",
                            formatter_class=HelpFormatter, epilog=EXAMPLES)
    parser.add_argument("boat", help="a registered boat (sailmujoco list) or a boat file (.toml)")
    parser.add_argument("--wind-speed", type=number(0.0, low_open=False, unit="m/s", high=30.0), default=5.0,
                        metavar="M/S", help="true wind at 10 m (default 5)")
    parser.add_argument("--wind-from", type=float, default=0.0, metavar="DEG",
                        help="compass bearing the wind comes from (default 0: from the north)")
    parser.add_argument("--gusts", action="store_true", help="gusts and the wind's wander (default steady)")
    add_waves_argument(parser)
    parser.add_argument("--sensors", default=None, metavar="PRESET",
                        help="the wind vane's figures: perfect or typical (default: the boat's own)")
    parser.add_argument("--heading", type=float, default=0.0, metavar="DEG",
                        help="compass heading the boat starts on (default 0)")
    parser.add_argument("--hold", action="store_true",
                        help="moor the boat at its start (upright, at rest) until ArduPilot first steers: "
                             "it is launched on --heading when the mission starts, not left to drift "
                             "through ArduPilot's start-up")
    parser.add_argument("--motor", type=number(0.0, low_open=False, unit="N", high=1e4), default=0.0,
                        metavar="N", help="an auxiliary motor's thrust at full throttle, N (ArduPilot's "
                                          "channel 3: it motors through a tack that takes longer than 5 s); "
                                          "default 0: none, as the boats are built")
    parser.add_argument("--seed", type=SEED, default=0, help="seeds the wind, the sea and the vane's noise")
    parser.add_argument("--port", type=number(1024, low_open=False, unit="", integer=True, high=65535),
                        default=9002,
                        help="UDP port SITL sends to (default 9002; ardurover -I N: 9002 + 10 N)")
    parser.add_argument("--timeout", type=number(0.0, low_open=True, unit="s"), default=30.0,
                        help="seconds without a packet that end the run (default 30)")
    parser.add_argument("--seconds", type=number(0.0, low_open=True, unit="s"), default=None,
                        help="simulated seconds after which the run ends (default: until SITL stops)")
    parser.add_argument("--out", help="folder for trajectory.csv (default results/sitl/<boat>)")
    parser.add_argument("--record", metavar="FILE.mcap",
                        help="also write the run as an MCAP log of ROS 2 messages, 10 a simulated second "
                             "(docs/ros2.md; needs pip install 'sailmujoco[ros2]')")
    parser.add_argument("--video", metavar="FILE.mp4",
                        help="film the run: the boat drawn 5 times a simulated second once the run is over, "
                             "played at 25 frames a second (five times real time)")
    parser.set_defaults(func=run_cli)


def sea_of(args):
    """The run's sea from ``--waves`` (None: calm): from the wind's direction and drawn by
    ``--seed`` unless ``--waves`` gives its own.

    Parameters
    ----------
    args : argparse.Namespace
        ``waves``, ``wind_from``, ``seed``.
    """
    from ..options import wave_config

    if not args.waves:
        return None
    values = dict(args.waves)
    if "direction_from_deg" not in values:  # the waves come with the wind unless told
        values["direction_from"] = math.radians(args.wind_from)
    values.setdefault("seed", args.seed)
    return wave_config(values, "--waves")


def film_problem(path) -> str | None:
    """Why ``--video PATH`` could not be filmed here (one line), found before the run rather
    than after it; None when it can.

    Parameters
    ----------
    path : str
        ``--video``.
    """
    from ..video.child import ChildRenderer
    from ..video.encoding import encoder
    from ..video.gl import RenderingUnavailable

    if not str(path).lower().endswith(".mp4"):
        return "the film is an .mp4 file"
    try:
        encoder()
        ChildRenderer().close()  # the process that will draw the film can render
    except (ImportError, RenderingUnavailable) as err:
        return str(err)
    return None


def run_cli(args) -> int:
    """Run ``sailmujoco sitl``.

    Parameters
    ----------
    args : argparse.Namespace
        ``boat``, ``wind_speed``, ``wind_from``, ``gusts``, ``waves``, ``sensors``, ``heading``,
        ``hold``, ``motor``, ``seed``, ``port``, ``timeout``, ``seconds``, ``out``, ``record``,
        ``video``.

    Returns
    -------
    int
        0; 1 where ``--record`` needs rosbags; 2 where the port is taken, SITL never sent a packet or
        ``--video`` cannot be filmed (one line on stderr).
    """
    from ..boat.catalogue import boat_label
    from ..sitl.backend import JsonBackend, SitlError

    waves = sea_of(args)
    if args.video:
        problem = film_problem(args.video)
        if problem:
            print(f"sailmujoco sitl: --video {args.video}: {problem}", file=sys.stderr)
            return 2
    mcap = _mcap_log(args.record)
    if mcap == 1:
        return 1
    out = out_folder(args.out or Path("results") / "sitl" / boat_label(args.boat))
    backend = JsonBackend(args.boat, wind_speed=args.wind_speed, wind_from_deg=args.wind_from,
                          gusts=args.gusts, waves=waves, sensors=args.sensors, heading_deg=args.heading,
                          hold=args.hold, motor_thrust=args.motor, film=bool(args.video), seed=args.seed,
                          log=lambda line: print(line, flush=True), mcap=mcap)
    print(f"sitl: {args.boat} ({backend.dt * 1e3:g} ms a frame) waiting for ArduPilot's servo packets on "
          f"UDP 127.0.0.1:{args.port}", flush=True)
    # SIGTERM or Ctrl-C: the run ends as on a timeout
    previous = signal.signal(signal.SIGTERM, raise_terminated)
    try:
        counters = backend.serve(port=args.port, timeout=args.timeout, seconds=args.seconds)
    except SitlError as err:
        print(f"sailmujoco sitl: {err}", file=sys.stderr)
        return 2
    except (Terminated, KeyboardInterrupt) as stop:
        counters = backend.counters
        how = "interrupted" if isinstance(stop, KeyboardInterrupt) else "terminated"
        print(f"sitl: {how} at t = {backend.time():.2f} s", flush=True)
    finally:
        signal.signal(signal.SIGTERM, previous)
        if mcap is not None:
            mcap.close()
        for i, rows in enumerate(backend.runs):
            if rows:
                name = "trajectory.csv" if len(backend.runs) == 1 else f"trajectory_{i}.csv"
                backend.trajectory(i).to_csv(out / name, index=False)
    if args.video:
        _film(backend, args, waves)
    simulated = counters.answered * backend.dt
    speed = simulated / counters.lock_step if counters.lock_step > 0 else math.nan
    print(f"sitl: {counters.answered} frames ({simulated:.1f} s simulated) in {counters.lock_step:.1f} s of "
          f"lock-step, {speed:.1f} times real time; {counters.resent} sent again, "
          f"{counters.refused} refused, {counters.resets} restarts; the trajectory in {out}"
          + (f", the log in {args.record}" if args.record else ""))
    return 0


def _mcap_log(path):
    """``--record``'s log (None without it); 1 where rosbags is missing (said in one line)."""
    if not path:
        return None
    from ..ros2.record import McapLog, RosbagsMissing, check_log_path
    file_argument("--record", path, "run.mcap")
    check_log_path(path, "--record")
    try:
        return McapLog(None, path)
    except RosbagsMissing as err:
        print(f"sailmujoco sitl: {err}", file=sys.stderr)
        return 1


def _film(backend, args, waves) -> None:
    """Film the last run that moved (``--video``)."""
    from ..boat.catalogue import boat_label
    from ..sitl.film import film

    snapshots = next((snaps for snaps in reversed(backend.films) if snaps), [])
    if not snapshots:
        print("sitl: nothing to film: the boat never moved", flush=True)
        return
    labels = (f"{boat_label(args.boat)} · ArduPilot SITL · {args.wind_speed:g} m/s "
              f"from {args.wind_from:g} deg" + (" · sea" if waves is not None else ""))
    print(f"sitl: filming {len(snapshots)} frames ({snapshots[-1].time - snapshots[0].time:.0f} s sailed) "
          f"to {args.video}", flush=True)
    film(snapshots, backend.params, args.video, waves=waves, labels=labels, progress=sys.stdout.isatty())
