"""``sailmujoco sweep FILE``: run a sweep file on the embedded cluster (or a Dask scheduler),
print a summary and where its table lies."""

from __future__ import annotations

import sys
from pathlib import Path

from .arguments import INTERRUPTED


def run_cli(args) -> int:
    """The ``sweep`` sub-command: run a sweep file, write its table.

    Parameters
    ----------
    args : argparse.Namespace
        ``file``, ``out``, ``scheduler``, ``workers``, ``resume``, ``retries``, ``no_progress``.

    Returns
    -------
    int
        0, or :data:`~sailmujoco.arguments.INTERRUPTED` after Ctrl-C (the runs done are kept).
    """
    from . import sweep

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
    for metric in spec.get("metrics", [])[:5]:
        print("  " + sweep.summarise(table, metric))
    print(f"table: {out / 'results.parquet'} (pandas.read_parquet) and results.csv")
    return 0
