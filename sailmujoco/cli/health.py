"""``sailmujoco check``: load every boat in both hydrostatic modes, sail it, report its health.

Each boat sails ``--seconds`` in gusty wind under random rudder and sail commands (new every
0.5 s, drawn from ``--seed``), once with the paper's restoring formula and once with the
geometric hull. A row per run gives its status, largest heel, mean surge speed, submerged
volume over the design displacement and the wall time per physics sub-step; a line per boat
compares the geometric righting moment at 2 deg with rho g V GM phi. ``--plots`` also draws
each boat's righting curve.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from .arguments import out_folder

CHECK_LEGEND = """\
  max|heel|  largest heel over the run (deg)
  mean u     mean surge speed (m/s)
  V/V0       submerged hull volume at the run's last step over the design displacement volume
             (geometric hydrostatics only, '-' for paper; 1 = floating at its design weight,
             it swings about 1 while the boat heaves)
  us/step    wall time per physics sub-step (microseconds)"""
MODES = ("paper", "geometric")
COMMAND_PERIOD = 0.5  # s between random commands


def run_cli(args) -> int:
    """The ``check`` sub-command: a health report of every boat (or those of ``--boat``).

    Parameters
    ----------
    args : argparse.Namespace
        ``boat`` (list or None), ``seconds``, ``wind`` (m/s), ``seed``, ``plots`` (folder or None).

    Returns
    -------
    int
        0 when every run sailed to its end, 1 otherwise.
    """
    from ..boat.catalogue import BOATS, boat_label, get_boat

    boats = args.boat or sorted(BOATS)
    plots = out_folder(args.plots) if args.plots else None  # a bad folder fails before the runs
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
        for mode in MODES:
            failures += sail(boat, params, mode, args.seconds, args.wind, args.seed)
        print(righting_line(params))
    if plots:
        for boat in boats:
            path = plots / f"righting_curve_{boat_label(boat)}.png"
            plot_righting_curve(get_boat(boat), path)
            print(f"wrote {path}")
    print("health: OK" if failures == 0 else f"health: {failures} run(s) stopped early")
    return 0 if failures == 0 else 1


def sail(boat: str, params, mode: str, seconds: float, wind_speed: float, seed: int) -> int:
    """Sail one boat in one hydrostatic mode under random commands; print its row.

    Parameters
    ----------
    boat : str
        The boat's name (the row's first column).
    params : BoatParams
        Its parameters.
    mode : {"paper", "geometric"}
        The hydrostatics.
    seconds : float
        Simulated time (s).
    wind_speed : float
        Mean wind at 10 m (m/s), from 45 deg, gusty.
    seed : int
        Seeds the wind and the commands.

    Returns
    -------
    int
        The number of failures: 1 for a run that stopped early, 2 if its state is also not
        finite, else 0.
    """
    from ..forces.wind import WindConfig
    from ..physics import BoatPhysics, ForceSwitches, SimulationStopped

    wind = WindConfig(speed=wind_speed, direction_from=math.radians(45.0), seed=seed)
    physics = BoatPhysics.load(params=params, wind=wind, forces=ForceSwitches(hydrostatics=mode))
    rng = np.random.default_rng(seed)
    low, high = physics.model.actuator_ctrlrange.T
    heels, speeds = [], []
    status = "ok"
    failures = 0
    n_sub = int(round(COMMAND_PERIOD / physics.timestep()))
    start = time.perf_counter()
    steps = 0
    try:
        while physics.data.time < seconds - 1e-9:
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
    return failures


def righting_line(params) -> str:
    """The geometric righting moment at 2 deg against rho g V GM phi, as one report line.

    Parameters
    ----------
    params : BoatParams
        The boat.
    """
    from ..forces import stability

    small = math.radians(2.0)
    moment = stability.righting_moment(params, small)
    expected = params.rho_water * 9.81 * params.displaced_volume * params.gm_t * small
    return (f"{'':12s} geometric righting moment at 2°: {moment:.4g} N m, "
            f"rho g V GM phi = {expected:.4g} N m ({100 * (moment / expected - 1):+.2f} %)")


def plot_righting_curve(params, path: Path) -> None:
    """The righting moment against heel: geometric hull and the papers' formulas (PNG).

    Parameters
    ----------
    params : BoatParams
        The boat.
    path : Path
        The PNG written.
    """
    from .. import figures
    from ..forces import stability

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
