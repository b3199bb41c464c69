"""``sailmujoco sweep FILE``: run a sweep file on the embedded cluster (or a Dask scheduler),
print a summary and where its table lies; ``sailmujoco sweep --example`` prints a sweep file
that runs as printed."""

from __future__ import annotations

import sys
import textwrap
from pathlib import Path

from .arguments import INTERRUPTED

EXAMPLE = '''\
# A sweep: every combination of [grid], for each row of [zip], for each seed, is one run.
# Run it with: sailmujoco sweep example.toml --workers 2
name = "example"              # results go to results/sweeps/example/ (default: the file's stem)
boat = "saoud_robot"          # a registered boat (sailmujoco list), or "my_boat.toml": a boat file,
                              # relative to this file (sailmujoco boat export --help)
task = "heading_hold"
world = "mujoco"              # or "paper": the paper's reduced model (default: mujoco)
controller = "pid"            # or "my_module:factory", or "path/to/my_law.py:factory"
duration = 20.0               # simulated seconds per run (default: the task's)
seeds = [0, 1, 2]             # each seed runs every combination (default [0]); the summary
                              # gives each combination's mean and 95 % interval over them
metrics = ["mean_surge", "heading_error_rms"]  # default: every metric of the task

[options]                     # the same for every run; keys are "<namespace>.<name>"
"env.hydrostatics" = "geometric"   # env.: suite.load's physics options, control_timestep
"task.wind_speed" = 5.0            # task.: the task's options (m/s)
# "waves.hs" = 1.0                 # waves.: a sea state (sailmujoco.options.WaveConfig:
                                   # hs, tp, spectrum, direction_from_deg, ...); slower than calm
# "sensors.preset" = "typical"     # sensors.: the instruments the controller reads through
                                   # (perfect, typical, or any figure over them)
# "actuators.preset" = "typical"   # actuators.: the servos its commands go through

[grid]                        # every combination of these lists
"controller.kp" = [0.5, 1.0]       # controller.: the controller factory's keywords

[zip]                         # lists of equal length, taken together (not crossed)
"task.wind_from_deg" = [60.0, 90.0]
"task.desired_heading_deg" = [0.0, 10.0]
'''


def epilog() -> str:
    """The end of ``sailmujoco sweep --help``: the sweep file's keys and option namespaces, from
    :mod:`sailmujoco.sweep.spec`, and examples.

    Returns
    -------
    str
    """
    from ..sweep import spec

    keys = "\n".join(f"  {key:16s}{text}" for key, text in spec.KEYS.items())
    namespaces = "\n".join(f"  {ns + '.':12s}{text}" for ns, text in spec.NAMESPACE_HELP.items())
    choices = spec.env_choices()
    names = [f"{n} ({'|'.join(str(c) for c in choices[n])})" if n in choices else n
             for n in sorted(spec.env_option_names())]
    env = textwrap.fill(", ".join(names), 90, initial_indent="  env. options: ",
                        subsequent_indent="    ", break_on_hyphens=False)
    return (f"keys of a sweep file (TOML):\n{keys}\n\n"
            f"option keys of [options], [grid] and [zip] are \"<namespace>.<name>\":\n{namespaces}\n"
            f"{env}\n"
            "    (the others true or false: a force model on or off; control_timestep, timestep in s)\n"
            "  task., boat. and controller. options: the keywords of the task, boat factory and\n"
            "  controller factory (a misspelt one is refused, naming the accepted ones)\n\n"
            "every run's options and the metrics are checked before any run starts (a refused one:\n"
            "exit status 2). Each finished run is kept in <out>/runs/; the table is\n"
            "<out>/results.parquet and results.csv. A run whose simulation raised is recorded as\n"
            "failed, not retried (--retries: runs lost with a worker that died); the sweep then\n"
            "prints one line per distinct reason, with an example run, and exits with status 1\n"
            "(when no run finished, a last line says so and no summary.csv is written).\n\n"
            "examples:\n"
            "  sailmujoco sweep --example > example.toml\n"
            "  sailmujoco sweep example.toml --workers 2\n"
            "  sailmujoco sweep example.toml --resume          # after Ctrl-C: only the missing runs\n"
            "  sailmujoco sweep example.toml --scheduler tcp://host:8786")


def run_cli(args) -> int:
    """The ``sweep`` sub-command: run a sweep file, write its table (or print the example).

    Parameters
    ----------
    args : argparse.Namespace
        ``file``, ``example``, ``out``, ``scheduler``, ``workers``, ``resume``, ``retries``,
        ``no_progress``.

    Returns
    -------
    int
        0; 1 when a run failed (one line per distinct reason on stderr, then one more when no
        run finished); or
        :data:`~sailmujoco.cli.arguments.INTERRUPTED` after Ctrl-C (the runs done are kept).
    """
    from .. import sweep

    if args.example:
        if args.file:
            raise ValueError("give a sweep FILE or --example, not both")
        print(EXAMPLE, end="")
        return 0
    if not args.file:
        raise ValueError("give a sweep FILE (TOML); 'sailmujoco sweep --example' prints one")
    spec = sweep.load_spec(args.file)
    out = Path(args.out or Path("results") / "sweeps" / spec["name"])
    sweep.check_folder(spec, out)  # a file, or another sweep's folder: one line, exit 2
    runs = sweep.expand(spec)
    where = args.scheduler or f"embedded Dask cluster, {args.workers or 'all'} worker(s)"
    print(f"sweep {spec['name']!r} ({sweep.sweep_id(spec)}): {len(runs)} runs ({spec['boat']}, "
          f"{spec['task']}, {spec['world']}, {spec['controller']}) on {where} -> {out}", flush=True)
    try:
        table = sweep.run(spec, out, scheduler=args.scheduler, workers=args.workers,
                          resume=args.resume, retries=args.retries, progress=not args.no_progress,
                          exclusive=True)
    except KeyboardInterrupt:
        saved = len(list((out / "runs").glob("*.json")))
        print(f"sailmujoco sweep: interrupted; {saved} of {len(runs)} runs are saved in {out} "
              f"(results.parquet holds them); 'sailmujoco sweep {args.file} --out {out} --resume' "
              "runs the rest", file=sys.stderr)
        return INTERRUPTED
    counts = {"ok": 0, "stopped": 0, "failed": 0, **table["status"].value_counts().to_dict()}
    print("status: " + ", ".join(f"{k} {v}" for k, v in counts.items())
          + (" (stopped: the simulation ended early, e.g. a capsize; see the error column)"
             if counts["stopped"] else ""))
    from ..sweep import summary

    metrics = spec.get("metrics") or [c for c in table.columns if c not in summary.NOT_METRICS
                                      and c not in summary.combination_columns(table)]
    by_combination = sweep.over_seeds(table, metrics)
    if not by_combination.empty:
        by_combination.to_csv(out / "summary.csv", index=False)
    else:  # no run finished: no summary, not one left from an earlier sweep in this folder
        (out / "summary.csv").unlink(missing_ok=True)
    for metric in metrics[:5]:
        print("\n".join("  " + line for line in summary.lines(by_combination, metric, table)))
    print(f"table: {out / 'results.parquet'} (pandas.read_parquet) and results.csv; over seeds: "
          + ("summary.csv" if not by_combination.empty else "none (no run finished)"), flush=True)
    failed = sweep.failures(table)
    for line in failed:  # one line per distinct reason; the traceback is in the run's record
        print(f"sailmujoco sweep: {line}", file=sys.stderr)
    if failed and not counts["ok"]:  # nothing to summarise: say so last, in one line
        stopped = f", {counts['stopped']} stopped early" if counts["stopped"] else ""
        print(f"sailmujoco sweep: no run finished ({counts['failed']} of {len(table)} runs failed"
              f"{stopped})", file=sys.stderr)
    return 1 if failed else 0
