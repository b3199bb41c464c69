"""The ``sailmujoco`` command."""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np


def _check(args) -> int:
    """Load every boat in both hydrostatic modes, sail it in gusty wind, report health."""
    from . import stability
    from .forces.wind import WindConfig
    from .params import BOATS, get_boat
    from .physics import BoatPhysics, ForceSwitches, SimulationStopped

    boats = args.boat or sorted(BOATS)
    failures = 0
    print(f"sailmujoco check: {args.seconds:g} s in {args.wind:g} m/s gusty wind, "
          f"random commands every 0.5 s, seed {args.seed}")
    header = (f"{'boat':12s} {'hydrostatics':12s} {'status':8s} {'max|heel|':>9s} "
              f"{'mean u':>7s} {'V/V0':>7s} {'us/step':>8s}")
    print(header)
    print("-" * len(header))
    for boat in boats:
        params = get_boat(boat)
        for mode in ("paper", "geometric"):
            wind = WindConfig(speed=args.wind, direction_from=math.radians(45.0), seed=args.seed)
            physics = BoatPhysics.load(params=params, wind=wind,
                                       forces=ForceSwitches(hydrostatics=mode))
            rng = np.random.default_rng(args.seed)
            low, high = physics.model.actuator_ctrlrange.T
            heels, speeds = [], []
            status = "ok"
            n_sub = int(round(0.5 / physics.timestep()))
            start = time.perf_counter()
            steps = 0
            try:
                while physics.data.time < args.seconds - 1e-9:
                    physics.set_control(rng.uniform(low, high))
                    physics.step(n_sub)
                    steps += n_sub
                    heels.append(physics.heel())
                    speeds.append(physics.surge_speed())
            except SimulationStopped as stop:
                status = stop.reason.split(":")[0]
                failures += 1
            elapsed = time.perf_counter() - start
            finite = np.all(np.isfinite(physics.data.qpos)) and np.all(np.isfinite(physics.data.qvel))
            if not finite:
                status = "NaN"
                failures += 1
            ratio = physics.submerged_volume() / params.displaced_volume if mode == "geometric" \
                else float("nan")
            print(f"{boat:12s} {mode:12s} {status:8s} {np.degrees(np.max(np.abs(heels))):8.1f}° "
                  f"{np.mean(speeds):7.2f} {ratio:7.3f} {1e6 * elapsed / max(steps, 1):8.1f}")
        small = math.radians(2.0)
        moment = stability.righting_moment(params, small)
        expected = params.rho_water * 9.81 * params.displaced_volume * params.gm_t * small
        print(f"{'':12s} geometric righting moment at 2°: {moment:.4g} N m, "
              f"rho g V GM phi = {expected:.4g} N m ({100 * (moment / expected - 1):+.2f} %)")
    if args.plots:
        out = Path(args.plots)
        out.mkdir(parents=True, exist_ok=True)
        for boat in boats:
            path = out / f"righting_curve_{boat}.png"
            _plot_righting_curve(get_boat(boat), path)
            print(f"wrote {path}")
    print("health: OK" if failures == 0 else f"health: {failures} run(s) stopped early")
    return 0 if failures == 0 else 1


def _plot_righting_curve(params, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from . import stability

    heel = np.radians(np.linspace(0.0, 89.0, 90))
    curve = stability.righting_curve(params, heel)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    deg = np.degrees(heel)
    ax.plot(deg, curve["geometric"] / 1e3, lw=2.2, label="geometric hull (6-DOF)")
    ax.plot(deg, curve["sin_cos"] / 1e3, "--", label=r"$\rho g \nabla GM_t \sin\phi\cos\phi$ (Wille eq. 20)")
    ax.plot(deg, curve["sin"] / 1e3, ":", label=r"$m g l_\phi \sin\phi$ (Saoud eq. 4)")
    ax.plot(deg[:25], curve["linear"][:25] / 1e3, color="0.6", lw=1, label=r"$\rho g \nabla GM_t\,\phi$")
    ax.set_xlabel("heel φ [deg]")
    ax.set_ylabel("righting moment [kN m]")
    ax.set_title(f"{params.name}: righting moment vs heel (GM_t = {params.gm_t:g} m)")
    ax.set_xlim(0, 90)
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _sweep(args) -> int:
    """Run a sweep file on the embedded cluster (or a Dask scheduler); write its table."""
    from . import sweep

    spec = sweep.load_spec(args.file)
    out = Path(args.out or Path("results") / "sweeps" / spec["name"])
    runs = sweep.expand(spec)
    where = args.scheduler or f"embedded Dask cluster, {args.workers or 'all'} worker(s)"
    print(f"sweep {spec['name']!r}: {len(runs)} runs ({spec['boat']}, {spec['task']}, "
          f"{spec['world']}, {spec['controller']}) on {where} -> {out}")
    table = sweep.run(spec, out, scheduler=args.scheduler, workers=args.workers,
                      resume=args.resume, retries=args.retries, progress=not args.no_progress)
    counts = table["status"].value_counts().to_dict()
    print("status: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    for metric in spec.get("metrics", [])[:5]:
        print("  " + sweep.summarise(table, metric))
    print(f"table: {out / 'results.parquet'} (pandas.read_parquet) and results.csv")
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="sailmujoco",
        description="A MuJoCo 6-DOF testbed for autonomous sailboat control laws.")
    sub = parser.add_subparsers(dest="command", required=True)
    check = sub.add_parser("check", help="load every boat, sail it, print a health report")
    check.add_argument("--boat", action="append", help="only this boat (repeatable)")
    check.add_argument("--seconds", type=float, default=20.0, help="simulated time per run (s)")
    check.add_argument("--wind", type=float, default=10.0, help="mean wind at 10 m (m/s)")
    check.add_argument("--seed", type=int, default=0)
    check.add_argument("--plots", nargs="?", const="results/check", default=None,
                       metavar="DIR", help="write righting-curve plots (default results/check)")
    check.set_defaults(func=_check)

    sweep = sub.add_parser("sweep", help="run a parameter sweep described by a TOML file")
    sweep.add_argument("file", help="sweep description (TOML), see sailmujoco.sweep")
    sweep.add_argument("--out", help="results folder (default results/sweeps/<name>)")
    sweep.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    sweep.add_argument("--workers", type=int, help="worker processes of the embedded cluster")
    sweep.add_argument("--resume", action="store_true", help="run only the missing runs")
    sweep.add_argument("--retries", type=int, default=2, help="extra attempts of a failing run")
    sweep.add_argument("--no-progress", action="store_true", help="no progress bar")
    sweep.set_defaults(func=_sweep)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except ValueError as err:  # bad input: one clear line, exit 2
        print(f"sailmujoco: error: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
