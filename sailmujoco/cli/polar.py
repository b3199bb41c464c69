"""``sailmujoco polar BOAT --controller NAME``: the command and its arguments.

The polar itself is :mod:`sailmujoco.design.polar`.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from ..boat.catalogue import boat_label, get_boat
from ..design.polar import (
    DEFAULT_TWA,
    STEADY_WINDOW_S,
    best_vmg,
    finished_points,
    first_failure,
    over_seeds,
    plot_polar,
    sweep_table,
)
from ..design.polar_compare import comparison_markdown, comparison_table, plot_comparison, ratio_summary
from ..design.reference_compare import plot_reference, polar_axes, reference_markdown, reference_table
from ..design.reference_polar import REFERENCE_HEIGHT, read_reference_polar
from ..options import World, choices
from ..sweep import controller_label
from .arguments import (
    POSITIVE_SECONDS,
    SEEDS,
    WORKERS,
    HelpFormatter,
    controller_options,
    floats,
    number,
    out_folder,
    setting,
)

POSITIVE_METRES = number(0.0, low_open=True, unit="m")

DESCRIPTION = f"""\
The steady speed of BOAT at every true wind speed x true wind angle, each point a heading_hold
run in a steady wind (no gusts) from TWA off the starboard bow, its speed the mean over the
last {STEADY_WINDOW_S:g} s. Writes polar_<controller>.png and .csv into --out, and prints the best VMG upwind
and downwind. 'best' is the brute-force polar: every fixed sail angle, the fastest kept.
With --seeds N each point is sailed N times (the seed draws the start heading and, with
--gusts, the gusts): its speed is the mean with its 95 % interval, each seed's row is kept in
polar_<controller>_seeds.csv, and --compare's ratios are paired by seed. With --reference the
polar is held against a published one: reference.png, reference.csv and reference.md."""


def add_parser(subparsers) -> argparse.ArgumentParser:
    """Add ``polar`` to the ``sailmujoco`` sub-commands.

    Parameters
    ----------
    subparsers : argparse._SubParsersAction
        From ``ArgumentParser.add_subparsers``.

    Returns
    -------
    argparse.ArgumentParser
        The ``polar`` parser.
    """
    parser = subparsers.add_parser(
        "polar", help="polar diagram (speed vs true wind angle) of a boat",
        formatter_class=HelpFormatter, description=DESCRIPTION,
        epilog="examples:\n"
               "  sailmujoco polar saoud_robot --controller saoud --compare best,briere\n"
               "  sailmujoco polar wille_yacht --controller my_law.py:make "
               "--option gain=0.5 --tws 3,6 --twa 40:180:20 --workers 2")
    parser.add_argument("boat", help="a registered boat (sailmujoco list) or a boat file (.toml)")
    parser.add_argument("--controller", default="saoud",
                        help="sail law + heading rudder by name (saoud, briere, pid, best, ...), "
                             "module:factory or file.py:factory")
    parser.add_argument("--option", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="a keyword of --controller's factory, e.g. kp=2.0 (repeatable); the "
                             "controllers of --compare run with their defaults")
    parser.add_argument("--compare", help="other controllers to compare, comma separated "
                                          "('best' = brute-force fixed-sail vel_max)")
    parser.add_argument("--world", default="mujoco", choices=choices(World),
                        help="mujoco: the 6-DOF boat; paper: the paper's reduced model")
    parser.add_argument("--tws", type=floats,
                        help="true wind speeds at 10 m, m/s: '2,4,6' or 'start:stop:step' (default: 2,4,6; "
                             "with --reference: the file's)")
    parser.add_argument("--twa", type=floats,
                        help="true wind angles off the bow, deg: '30,90' or 'start:stop:step' (default: "
                             "30:180:15; with --reference: the file's below the spinnaker, and the beat)")
    parser.add_argument("--reference", metavar="FILE",
                        help="a reference polar (CSV: tws_kn, twa_deg, boat_speed_kn[, point]) to hold ours "
                             "against, or 'orc:eleven_metre' (ORC's 11:Metre polar, shipped)")
    parser.add_argument("--reference-height", type=POSITIVE_METRES, default=REFERENCE_HEIGHT, metavar="M",
                        help="the height of the reference's wind speeds, m (ORC: 10)")
    parser.add_argument("--seconds", type=POSITIVE_SECONDS, default=60.0,
                        help="simulated seconds per point")
    parser.add_argument("--duration", dest="seconds", type=POSITIVE_SECONDS, default=argparse.SUPPRESS,
                        help=argparse.SUPPRESS)  # the same option, under the sweep file's name
    parser.add_argument("--seeds", type=SEEDS, default=1, metavar="N",
                        help="sail each point on seeds 0..N-1 (default 1: one steady run); its speed is "
                             "then the mean with its 95 %% interval")
    parser.add_argument("--gusts", action="store_true",
                        help="gusts and wander in the wind, drawn by the seed (default: a steady wind)")
    parser.add_argument("--out", help="output folder (default results/polar/<boat>-<controller>)")
    parser.add_argument("--scheduler", help="Dask scheduler address, or 'serial'")
    parser.add_argument("--workers", type=WORKERS, help="worker processes (0 or unset: all cores)")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    parser.set_defaults(func=run_cli)
    return parser


def run_cli(args) -> int:
    """The ``polar`` sub-command: the polar of a boat and sail law (and comparisons), PNG + CSV.

    Parameters
    ----------
    args : argparse.Namespace
        ``boat``, ``controller``, ``option`` (``(key, value)`` pairs of the controller's
        options), ``compare`` (comma separated, or None), ``world``, ``tws``,
        ``twa``, ``seconds`` (simulated seconds per point), ``seeds``, ``gusts``, ``out``,
        ``scheduler``, ``workers``, ``no_progress``.

    Returns
    -------
    int
        0; 2 where a point failed (one line on stderr: why the first failed point failed and
        when; the CSVs written so far are kept).
    """
    get_boat(args.boat)  # an unknown boat fails here, with the list of known ones
    reference = read_reference_polar(args.reference, args.reference_height) if args.reference else None
    tws, twa = ((polar_axes(reference)) if reference is not None
                else ([2.0, 4.0, 6.0], [float(a) for a in DEFAULT_TWA]))
    args.tws = args.tws or tws
    args.twa = args.twa or twa
    if args.option and args.controller == "best":
        raise ValueError("--option: 'best' is every fixed sail angle and takes no options")
    own = {} if args.controller == "best" else controller_options(args)  # checked before any run
    label = controller_label(args.controller)
    out = out_folder(args.out or Path("results") / "polar" / f"{boat_label(args.boat)}-{label}")
    names = [args.controller] + [c for c in (args.compare or "").split(",") if c]
    frames, points, kept = {}, {}, []
    seeds = tuple(range(args.seeds))
    for name in names:
        print(f"polar {args.boat} / {name}: TWS {_listed(args.tws)} m/s x TWA {_listed(args.twa)} deg "
              f"({args.world}, {args.seconds:g} s per point"
              + (f", {len(seeds)} seeds{', gusts' if args.gusts else ''}" if len(seeds) > 1 else "") + ")")
        table, spec = sweep_table(args.boat, name, out, tws=args.tws, twa=args.twa,
                                  world=args.world, duration=args.seconds,
                                  scheduler=args.scheduler, workers=args.workers,
                                  progress=not args.no_progress,
                                  options={f"controller.{key}": value for key, value in own.items()}
                                  if name == args.controller else None, seeds=seeds, gusts=args.gusts)
        points[name] = finished_points(table, name)
        frames[name] = over_seeds(points[name])
        csv = out / f"polar_{controller_label(name)}.csv"
        frames[name].to_csv(csv, index=False)
        if len(seeds) > 1:
            points[name].to_csv(out / f"polar_{controller_label(name)}_seeds.csv", index=False)
        n_points = len(frames[name])
        kept.append(f"{csv} ({n_points} point{'' if n_points == 1 else 's'})")
        failure = first_failure(table, spec, name)
        if failure is not None:
            failed = int((table["status"] == "failed").sum())
            print(f"sailmujoco polar: {failure}; {failed} of {len(table)} runs failed; kept what "
                  f"finished: {', '.join(kept)}", file=sys.stderr)
            return 2
    main_frame = frames[args.controller]
    png = out / f"polar_{controller_label(args.controller)}.png"
    plot_polar(main_frame, png, f"{boat_label(args.boat)}, {args.controller} ({args.world})")
    over = " (mean over seeds)" if len(seeds) > 1 else ""
    for tws, best in best_vmg(main_frame).items():
        (au, vu), (ad, vd) = best["upwind"], best["downwind"]
        print(f"  TWS {tws:g} m/s: best VMG upwind {vu:.2f} m/s at {au:g} deg, "
              f"downwind {vd:.2f} m/s at {ad:g} deg{over}")
    print(f"wrote {png} and {out / f'polar_{controller_label(args.controller)}.csv'}")
    if len(frames) > 1:
        _write_comparison(args, frames, points, out)
    if reference is not None:
        _write_reference(args, main_frame, reference, out)
    return 0


def _write_reference(args, frame, reference, out: Path) -> None:
    """reference.png, reference.csv and reference.md: our polar against ``reference``."""
    table = reference_table(frame, reference)
    table.to_csv(out / "reference.csv", index=False)
    plot_reference(frame, reference, out / "reference.png",
                   f"{boat_label(args.boat)} ({args.controller}, {args.world}) against {reference.name}")
    text = (f"# {boat_label(args.boat)} against {reference.name}\n\n"
            f"`sailmujoco polar {args.boat} --controller {args.controller} --reference {args.reference}`"
            f" ({args.world}, {args.seconds:g} s per point; the reference's wind at "
            f"{args.reference_height:g} m, ours at 10 m)\n\n" + reference_markdown(table, reference.name)
            + "\nThe reference:\n\n" + "".join(f"> {line}\n" for line in reference.source.splitlines()))
    (out / "reference.md").write_text(text, encoding="utf-8")
    outside = int((abs(table["ratio"] - 1.0) > 0.10).sum())
    print(f"  against {reference.name}: ours / reference {table['ratio'].min():.2f}-"
          f"{table['ratio'].max():.2f} over {len(table)} points, {outside} more than 10 % off")
    print(f"wrote {out / 'reference.png'}, {out / 'reference.md'} and {out / 'reference.csv'}")


def _write_comparison(args, frames: dict, points: dict, out: Path) -> None:
    """compare.png, compare.csv and compare.md of the ``--compare`` sail laws."""
    compare = out / "compare.png"
    plot_comparison(frames, compare, f"{args.boat}: steady speed by sail law ({args.world})")
    table = comparison_table(points)
    table.to_csv(out / "compare.csv", index=False)
    command = f"sailmujoco polar {args.boat} --controller {args.controller} --compare {args.compare}"
    settings = (f"world {args.world}, TWS {', '.join(f'{v:g}' for v in args.tws)} m/s, TWA "
                f"{', '.join(f'{v:g}' for v in args.twa)} deg, {args.seconds:g} s per point"
                + (f", {args.seeds} seeds{' in gusts' if args.gusts else ''}" if args.seeds > 1 else ""))
    summary = ratio_summary(table)
    (out / "compare.md").write_text(comparison_markdown(table, summary, command, settings),
                                    encoding="utf-8")
    print(f"wrote {compare}, {out / 'compare.md'} and {out / 'compare.csv'}")


def _listed(values) -> str:
    return "[" + ", ".join(f"{v:.4g}" for v in values) + "]"
