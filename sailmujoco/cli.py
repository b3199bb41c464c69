"""The ``sailmujoco`` command."""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

import numpy as np

from .sweep import MAX_LOCAL_WORKERS

CHECK_LEGEND = """\
  max|heel|  largest heel over the run (deg)
  mean u     mean surge speed (m/s)
  V/V0       submerged hull volume at the run's last step over the design displacement volume
             (geometric hydrostatics only, '-' for paper; 1 = floating at its design weight,
             it swings about 1 while the boat heaves)
  us/step    wall time per physics sub-step (microseconds)"""


def _check(args) -> int:
    """Load every boat in both hydrostatic modes, sail it in gusty wind, report health."""
    from . import stability
    from .forces.wind import WindConfig
    from .params import BOATS, get_boat
    from .physics import BoatPhysics, ForceSwitches, SimulationStopped

    boats = args.boat or sorted(BOATS)
    plots = _out_folder(args.plots) if args.plots else None  # a bad folder fails before the runs
    failures = 0
    print(f"sailmujoco check: {args.seconds:g} s in {args.wind:g} m/s gusty wind, "
          f"random commands every 0.5 s, seed {args.seed}")
    header = (f"{'boat':12s} {'hydrostatics':12s} {'status':8s} {'max|heel|':>9s} "
              f"{'mean u':>7s} {'V/V0':>7s} {'us/step':>8s}")
    print(CHECK_LEGEND)
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
                  f"{np.mean(speeds):7.2f} {'-' if math.isnan(ratio) else f'{ratio:.3f}':>7s} "
                  f"{1e6 * elapsed / max(steps, 1):8.1f}")
        small = math.radians(2.0)
        moment = stability.righting_moment(params, small)
        expected = params.rho_water * 9.81 * params.displaced_volume * params.gm_t * small
        print(f"{'':12s} geometric righting moment at 2°: {moment:.4g} N m, "
              f"rho g V GM phi = {expected:.4g} N m ({100 * (moment / expected - 1):+.2f} %)")
    if plots:
        for boat in boats:
            path = plots / f"righting_curve_{boat}.png"
            _plot_righting_curve(get_boat(boat), path)
            print(f"wrote {path}")
    print("health: OK" if failures == 0 else f"health: {failures} run(s) stopped early")
    return 0 if failures == 0 else 1


def _plot_righting_curve(params, path: Path) -> None:
    from . import figures, stability

    plt = figures.pyplot()
    heel = np.radians(np.linspace(0.0, 89.0, 90))
    curve = stability.righting_curve(params, heel)
    scale, unit = figures.moment_unit(max(float(np.max(np.abs(curve[k]))) for k in ("geometric", "sin")))
    fig, ax = plt.subplots(figsize=(7, 4.6))
    deg = np.degrees(heel)
    ax.plot(deg, curve["geometric"] / scale, lw=2.2, label="geometric hull (6-DOF)")
    ax.plot(deg, curve["sin_cos"] / scale, "--",
            label=r"$\rho g \nabla GM_t \sin\phi\cos\phi$ (Wille eq. 20)")
    ax.plot(deg, curve["sin"] / scale, ":", label=r"$m g l_\phi \sin\phi$ (Saoud eq. 4)")
    ax.plot(deg[:25], curve["linear"][:25] / scale, color="0.6", lw=1, label=r"$\rho g \nabla GM_t\,\phi$")
    ax.set_xlabel("heel φ [deg]")
    ax.set_ylabel(f"righting moment [{unit}]")
    ax.set_title(f"{params.name}: righting moment vs heel (GM_t = {params.gm_t:g} m)")
    ax.set_xlim(0, 90)
    ax.set_ylim(bottom=0)
    figures.legend_below(fig, ax, ncol=2)
    figures.save(fig, path, dpi=120)


def _sweep(args) -> int:
    """Run a sweep file on the embedded cluster (or a Dask scheduler); write its table."""
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


def _out_folder(path) -> Path:
    """``--out`` as a folder, created if missing; a file there is one line, exit 2."""
    path = Path(path)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except (FileExistsError, NotADirectoryError):
        raise ValueError(f"--out {str(path)!r} is (or lies under) a file; give a folder") from None
    except OSError as err:  # no permission, a read-only or virtual file system
        raise ValueError(f"cannot make the folder {str(path)!r}: {err.strerror}") from None
    return path


def _number(low: float, *, low_open: bool, unit: str, integer: bool = False,
            high: float | None = None):
    """An argparse type: a finite number above ``low`` (or at least ``low``) and at most
    ``high``, else exit 2 with one line naming the range."""
    def parse(text: str):
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            value = None
        if (value is None or not math.isfinite(value) or (value <= low if low_open else value < low)
                or (high is not None and value > high)):
            kind = "an integer" if integer else "a number"
            upper = f" and <= {high:g}" if high is not None else ""
            raise argparse.ArgumentTypeError(
                f"must be {kind} {'>' if low_open else '>='} {low:g}{upper}"
                f"{' ' + unit if unit else ''}, got {text!r}")
        return value
    return parse


POSITIVE_SECONDS = _number(0.0, low_open=True, unit="s")
SEED = _number(0, low_open=False, unit="", integer=True)
WORKERS = _number(0, low_open=False, unit="(0: all cores)", integer=True,
                  high=MAX_LOCAL_WORKERS)


def _floats(text: str) -> list[float]:
    """'2,4,6' or 'start:stop:step' (stop included) -> floats."""
    if ":" in text:
        start, stop, step = (float(v) for v in text.split(":"))
        return [float(v) for v in np.arange(start, stop + 1e-9, step)]
    return [float(v) for v in text.split(",")]


def _polar(args) -> int:
    """Polar diagram of a boat and sail law (and comparisons), PNG + CSV."""
    from . import polar
    from .params import get_boat

    get_boat(args.boat)  # an unknown boat fails here, with the list of known ones
    out = _out_folder(args.out or Path("results") / "polar" / f"{args.boat}-{args.controller}")
    names = [args.controller] + [c for c in (args.compare or "").split(",") if c]
    frames = {}
    for name in names:
        print(f"polar {args.boat} / {name}: TWS {args.tws} m/s x TWA {args.twa} deg "
              f"({args.world}, {args.duration:g} s per point)")
        frames[name] = polar.compute(args.boat, name, out, tws=args.tws, twa=args.twa,
                                     world=args.world, duration=args.duration,
                                     scheduler=args.scheduler, workers=args.workers,
                                     progress=not args.no_progress)
        frames[name].to_csv(out / f"polar_{name}.csv", index=False)
    main_frame = frames[args.controller]
    png = out / f"polar_{args.controller}.png"
    polar.plot_polar(main_frame, png, f"{args.boat}, {args.controller} ({args.world})")
    for tws, best in polar.best_vmg(main_frame).items():
        (au, vu), (ad, vd) = best["upwind"], best["downwind"]
        print(f"  TWS {tws:g} m/s: best VMG upwind {vu:.2f} m/s at {au:g} deg, "
              f"downwind {vd:.2f} m/s at {ad:g} deg")
    print(f"wrote {png} and {out / f'polar_{args.controller}.csv'}")
    if len(frames) > 1:
        compare = out / "compare.png"
        polar.plot_comparison(frames, compare, f"{args.boat}: steady speed by sail law ({args.world})")
        table = polar.comparison_table(frames)
        table.to_csv(out / "compare.csv", index=False)
        command = f"sailmujoco polar {args.boat} --controller {args.controller} --compare {args.compare}"
        settings = (f"world {args.world}, TWS {', '.join(f'{v:g}' for v in args.tws)} m/s, TWA "
                    f"{', '.join(f'{v:g}' for v in args.twa)} deg, {args.duration:g} s per point")
        summary = polar.ratio_summary(table)
        (out / "compare.md").write_text(polar.comparison_markdown(table, summary, command, settings),
                                        encoding="utf-8")
        print(f"wrote {compare}, {out / 'compare.md'} and {out / 'compare.csv'}")
    return 0


def _study(args) -> int:
    """Run one study, or all of them, into results/<study>/ (:mod:`sailmujoco.study_runner`)."""
    from . import study_runner

    names = study_runner.select(args.name)
    root = _out_folder(args.out)
    return study_runner.run_studies(names, root, smoke=args.smoke, workers=args.workers,
                                    scheduler=args.scheduler, resume=args.resume,
                                    progress=not args.no_progress, video=args.video)


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="sailmujoco",
        description="A MuJoCo 6-DOF testbed for autonomous sailboat control laws.")
    sub = parser.add_subparsers(dest="command", required=True)
    check = sub.add_parser("check", help="load every boat, sail it, print a health report",
                           epilog="columns of the report:\n" + CHECK_LEGEND,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
    check.add_argument("--boat", action="append", help="only this boat (repeatable)")
    check.add_argument("--seconds", type=POSITIVE_SECONDS, default=20.0, help="simulated time per run (s)")
    check.add_argument("--wind", type=_number(0.0, low_open=False, unit="m/s"), default=10.0,
                       help="mean wind at 10 m (m/s)")
    check.add_argument("--seed", type=SEED, default=0)
    check.add_argument("--plots", nargs="?", const="results/check", default=None,
                       metavar="DIR", help="write righting-curve plots (default results/check)")
    check.set_defaults(func=_check)

    sweep = sub.add_parser("sweep", help="run a parameter sweep described by a TOML file")
    sweep.add_argument("file", help="sweep description (TOML), see sailmujoco.sweep")
    sweep.add_argument("--out", help="results folder (default results/sweeps/<name>)")
    sweep.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    sweep.add_argument("--workers", type=WORKERS,
                       help="worker processes of the embedded cluster (0: all cores)")
    sweep.add_argument("--resume", action="store_true",
                       help="run only the missing runs and those lost with a worker that died")
    sweep.add_argument("--retries", type=_number(0, low_open=False, unit="", integer=True), default=2,
                       help="extra attempts of a failing run")
    sweep.add_argument("--no-progress", action="store_true", help="no progress bar")
    sweep.set_defaults(func=_sweep)

    polar = sub.add_parser("polar", help="polar diagram (speed vs true wind angle) of a boat")
    polar.add_argument("boat")
    polar.add_argument("--controller", default="saoud",
                       help="sail law + heading rudder by name (saoud, briere, pid, best, ...)")
    polar.add_argument("--compare", help="other controllers to compare, comma separated "
                                         "('best' = brute-force fixed-sail vel_max)")
    polar.add_argument("--world", default="mujoco", choices=("mujoco", "paper"))
    polar.add_argument("--tws", type=_floats, default=[2.0, 4.0, 6.0],
                       help="true wind speeds, m/s: '2,4,6' or 'start:stop:step'")
    polar.add_argument("--twa", type=_floats, default=[float(a) for a in range(30, 181, 15)],
                       help="true wind angles, deg: '30:180:15'")
    polar.add_argument("--duration", type=POSITIVE_SECONDS, default=60.0, help="seconds per point")
    polar.add_argument("--out", help="output folder (default results/polar/<boat>-<controller>)")
    polar.add_argument("--scheduler", help="Dask scheduler address, or 'serial'")
    polar.add_argument("--workers", type=WORKERS, help="worker processes (0: all cores)")
    polar.add_argument("--no-progress", action="store_true")
    polar.set_defaults(func=_polar)

    from . import study_runner

    study = sub.add_parser("study", help="regenerate a paper's figures and tables (or 'all')",
                           epilog=study_runner.epilog(), formatter_class=argparse.RawDescriptionHelpFormatter)
    study.add_argument("name", help="study name (listed below), or 'all'")
    study.add_argument("--smoke", action="store_true",
                       help="short runs: every path of the study, on reduced grids and durations")
    study.add_argument("--out", default="results", help="results root (default results/)")
    study.add_argument("--workers", type=WORKERS,
                       help="worker processes of the embedded cluster, one for every study (0: all cores; "
                            "1: in this process)")
    study.add_argument("--scheduler", help="Dask scheduler address tcp://host:port, or 'serial'")
    study.add_argument("--resume", action="store_true",
                       help="finish an interrupted run: skip the studies whose report finished, and run "
                            "only the missing simulations of the others")
    study.add_argument("--video", action="store_true", help="also record the main scenario")
    study.add_argument("--no-progress", action="store_true")
    study.set_defaults(func=_study)

    from . import video, view

    video.add_parser(sub)
    view.add_parser(sub)
    return parser


INTERRUPTED = 130  # the shell's status for a command ended by Ctrl-C (128 + SIGINT)


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except ValueError as err:  # bad input: one clear line, exit 2
        print(f"sailmujoco: error: {err}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # Ctrl-C: one line, not the traceback of wherever it landed
        print(f"sailmujoco {args.command}: interrupted", file=sys.stderr)
        return INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
