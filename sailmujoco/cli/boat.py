"""The ``sailmujoco boat`` command: ``export`` a boat as a boat file, ``make`` one from a class's
principal dimensions, ``check`` a boat file.

::

    sailmujoco boat make sailmujoco/data/eleven_metre_dimensions.toml --out my_class.toml  # each rule written
    sailmujoco boat export wille_yacht --out my_boat.toml   # every key with its unit and source
    sailmujoco boat export saoud_robot --sensors typical --actuators typical --out fitted.toml
    sailmujoco boat check my_boat.toml --out results/boat/my_boat --wind 6

``check`` prints the numbers of :func:`sailmujoco.design.check.check_boat` and writes ``gz.png``;
a bad file is one line per bad key on stderr and exit status 2. A file that keeps a built-in
boat's name with other parameters gets a one-line warning on stderr
(:func:`sailmujoco.boat.file.name_clash`).
"""

from __future__ import annotations

import sys
from pathlib import Path

from .arguments import HelpFormatter, file_argument, number, out_folder

EXAMPLES = """examples:
  sailmujoco boat make dimensions.toml --out my_class.toml  # LOA, LWL, beam, ... -> a boat file
  sailmujoco boat export saoud_robot --out my_boat.toml   # every key with its unit and source
  sailmujoco boat export saoud_robot --sensors typical --actuators typical --out my_boat.toml
  sailmujoco boat check my_boat.toml                      # numbers, gz.png, speeds in 6 m/s
  sailmujoco boat check my_boat.toml --wind 4 --out results/boat/mine
"""


def add_parser(sub) -> None:
    """Add ``boat export`` and ``boat check`` to the ``sailmujoco`` sub-commands.

    Parameters
    ----------
    sub : argparse._SubParsersAction
        The ``sailmujoco`` parser's sub-commands.
    """
    boat = sub.add_parser("boat", help="your boat from a file: export a boat, check a boat file",
                          description="Your boat from a file. 'export' writes a registered boat "
                                      "as a commented TOML boat file\n(every key with its unit and "
                                      "source); 'check' validates a boat file and prints\n"
                                      "its displacement, draft, LCB, GM_t, GZ curve (gz.png), "
                                      "natural periods and\nsteady speeds. A boat file goes "
                                      "wherever a boat name goes (suite.load, BOAT\narguments, "
                                      "'boat' in a sweep file).",
                          formatter_class=HelpFormatter, epilog=EXAMPLES)
    actions = boat.add_subparsers(dest="boat_command", required=True, metavar="ACTION",
                                  help="export, make or check")
    export = actions.add_parser("export", help="write a boat as a commented TOML boat file",
                                formatter_class=HelpFormatter, epilog=EXAMPLES,
                                description="Write a registered boat as a commented TOML boat file.")
    export.add_argument("name", help="a registered boat (sailmujoco list) or a boat file")
    export.add_argument("--out", metavar="FILE", help="the file to write (default: stdout)")
    for section, what in (("sensors", "instruments the controller reads through"),
                          ("actuators", "servos the commands go through")):
        export.add_argument(f"--{section}", choices=("perfect", "typical"), default=None,
                            help=f"the [{section}] section's preset: the {what} (default: the "
                                 "boat's own, perfect for a built-in boat)")
    export.set_defaults(func=run_cli)
    make = actions.add_parser("make", help="a boat file from a class's principal dimensions",
                              formatter_class=HelpFormatter, epilog=EXAMPLES,
                              description="Derive a boat from its principal dimensions (a TOML file with a "
                                          "[dimensions] table: name, loa, lwl, beam, draft,\ndisplacement, "
                                          "ballast, i, j, p, e, main_area, jib_area, optionally freeboard; "
                                          "SI units)\nby the rules of sailmujoco.boat.principal, each rule "
                                          "written beside its number.")
    make.add_argument("dimensions", help="the dimensions file (.toml)")
    make.add_argument("--out", metavar="FILE", help="the boat file to write (default: stdout)")
    make.set_defaults(func=run_cli)
    check = actions.add_parser("check", help="validate a boat file; its displacement, draft, LCB, "
                                             "GM_t, GZ curve, periods and speeds",
                               formatter_class=HelpFormatter, epilog=EXAMPLES,
                               description="Validate a boat file (one line per bad key) and report "
                                           "what a designer wants first.")
    check.add_argument("file", help="a boat file (or a registered boat)")
    check.add_argument("--out", metavar="DIR",
                       help="folder for gz.png and the speed runs (default results/boat/<boat>)")
    check.add_argument("--wind", type=number(0.0, low_open=True, unit="m/s", high=30.0),
                       default=6.0, metavar="M/S", help="true wind of the speed runs")
    check.set_defaults(func=run_cli)


def run_cli(args) -> int:
    """Run ``boat export`` or ``boat check``.

    Parameters
    ----------
    args : argparse.Namespace
        ``boat_command`` ("export": ``name``, ``out``, ``sensors``, ``actuators``; "make":
        ``dimensions``, ``out``; "check": ``file``, ``out``, ``wind``).

    Returns
    -------
    int
        0.
    """
    from ..boat.catalogue import boat_label, get_boat
    from ..boat.file import boat_toml, name_clash
    from ..boat.schema import is_boat_file

    if args.boat_command in ("export", "make"):
        if args.boat_command == "make":
            from ..boat.principal import boat_from_dimensions, read_dimensions

            text = boat_toml(boat_from_dimensions(read_dimensions(args.dimensions), get_boat("wille_yacht")))
        else:
            params = get_boat(args.name)
            fitted = {k: getattr(args, k) for k in ("sensors", "actuators") if getattr(args, k, None)}
            text = boat_toml(params.with_(**fitted) if fitted else params)
        if args.out is None:
            sys.stdout.write(text)
        else:
            file_argument("--out", args.out, "my_boat.toml")
            Path(args.out).write_text(text)
            print(f"wrote {args.out}", file=sys.stderr)
        return 0
    from ..design.check import check_boat

    params = get_boat(args.file)  # a bad file: one line per bad key, before anything is written
    clash = name_clash(params, args.file) if is_boat_file(args.file) else None
    if clash:
        print(clash, file=sys.stderr, flush=True)
    out = out_folder(args.out or Path("results") / "boat" / boat_label(args.file))
    result = check_boat(args.file, wind=args.wind, out=out, log=lambda line: print(line, flush=True))
    print(result.text())
    return 0

