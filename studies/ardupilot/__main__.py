"""ArduPilot's sailboat code on the 6-DOF boats and on its own SIM_Sailboat: the same mission
(100 m straight upwind and home, 5 m/s of wind), calm and in a 1 m sea, as a report.

::

    python -m sailmujoco.studies.ardupilot --ardurover path/to/ardurover --seeds 4

It needs ArduPilot's Rover built for SITL (``ardurover``, with ArduPilot's ``rover.parm`` and
``sailboat.parm`` beside it) and pymavlink; sailmujoco depends on neither, so this comparison is
not part of ``sailmujoco study all``. It writes ``results/ardupilot/``: ``report.md``,
``flights.csv`` (one row per flight), ``tracks.png``, ``heel.png`` and each flight's record under
``flights/``. docs/ardupilot.md runs the same thing by hand.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .cases import cases, ours_parameters
from .mission import Mission, environment_ready, find_ardurover, fly
from .report import load_flight, save_flight, write_all


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m sailmujoco.studies.ardupilot", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ardurover", help="ArduPilot's Rover SITL program or its folder "
                                            "(default $SAILMUJOCO_ARDUROVER, else ardurover on the PATH)")
    parser.add_argument("--seeds", type=int, default=4,
                        help="flights of each case in the sea (seeds 0..N-1; 1 to 20, default 4); calm "
                             "cases fly twice")
    parser.add_argument("--out", default="results/ardupilot", help="output folder (default results/ardupilot)")
    parser.add_argument("--speedup", type=int, default=10, help="ArduPilot's --speedup (1 to 50, default 10)")
    parser.add_argument("--instance", type=int, default=0,
                        help="ArduPilot's -I (0 to 9, default 0): its ports and ours move by 10 per instance, "
                             "to fly beside another SITL")
    parser.add_argument("--only", help="fly only the cases whose label contains this text")
    parser.add_argument("--report-only", action="store_true",
                        help="fly nothing: write the report from the flights kept under --out")
    args = parser.parse_args(argv)
    if not 1 <= args.seeds <= 20:
        parser.error(f"--seeds must be from 1 to 20, got {args.seeds}")
    if not 0 <= args.instance <= 9:
        parser.error(f"--instance must be from 0 to 9, got {args.instance}")
    if not 1 <= args.speedup <= 50:
        parser.error(f"--speedup must be from 1 to 50, got {args.speedup}")
    out = Path(args.out)
    todo = [c for c in cases(args.seeds) if not args.only or args.only in c.label]
    if args.report_only:
        kept = [(c, Mission(sea=c.sea), load_flight(out / "flights" / c.folder)) for c in todo]
        kept = [k for k in kept if k[2] is not None]
        if not kept:
            print(f"sailmujoco.studies.ardupilot: no flight kept under {out / 'flights'}", file=sys.stderr)
            return 2
        write_all(kept, out)
        print(f"report: {out / 'report.md'} ({len(kept)} flights)")
        return 0
    ardurover = find_ardurover(args.ardurover)
    problem = ardurover if isinstance(ardurover, str) else environment_ready()
    if problem:
        print(f"sailmujoco.studies.ardupilot: {problem}", file=sys.stderr)
        return 2
    flights = []
    start = time.perf_counter()
    for k, case in enumerate(todo, 1):
        mission = Mission(sea=case.sea)
        parameters = dict(case.parameters)
        if case.simulator != "sailboat" and case.tuned:
            parameters.update(ours_parameters(case.simulator))
        work = out / "flights" / case.folder
        print(f"[{k}/{len(todo)}] {case.label}, seed {case.seed} ...", flush=True)
        try:
            flight = fly(case.simulator, mission, ardurover, work, seed=case.seed, parameters=parameters,
                         speedup=args.speedup, instance=args.instance, motor=case.motor, say=print)
        except (RuntimeError, OSError) as err:
            print(f"  failed: {err}", flush=True)
            continue
        save_flight(flight, work)
        flights.append((case, mission, flight))
        home = flight.reached.get(2)
        done = f"home after {home:.0f} s" if home else "not home"
        print(f"  {done}; {flight.wall:.0f} s wall "
              f"({time.perf_counter() - start:.0f} s in all)", flush=True)
    if not flights:
        print("sailmujoco.studies.ardupilot: no flight finished", file=sys.stderr)
        return 2
    write_all(flights, out)
    print(f"report: {out / 'report.md'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
