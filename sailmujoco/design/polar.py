"""Polar diagrams: steady boat speed over true wind speed x true wind angle, on the sweep engine.

Each polar point is a ``heading_hold`` run in a steady wind (no gusts, no wander) with the
wind coming from ``TWA`` off the starboard bow; the point's speed is the mean speed over
ground in the last ``steady_window`` seconds. The best VMG upwind (max v cos TWA, TWA < 90)
and downwind (max -v cos TWA, TWA > 90) are marked.

``best`` is the brute-force polar (Saoud 2015 Fig. 7's vel_max): every fixed sail angle of a
grid is sailed and the fastest steady speed kept, point by point.

**Seeds.** One seed (the default) sails each point once from a fixed start in a steady wind. With
N seeds each point is sailed N times, the seed drawing the start heading (the task's jitter) and,
with ``gusts``, the wind's gusts and wander; a point's speed is then the mean over its seeds with
its 95 % interval (``speed_low``, ``speed_high``), and a comparison's ratio to ``best`` is paired
by seed (the same start and wind in both).

A point whose run fails (its controller raises, or gives a bad action) is left out. ``sailmujoco
polar`` (:mod:`sailmujoco.cli.polar`) then keeps the CSVs of what finished, says in one line why and
when the first failed point failed (:func:`first_failure` runs that point again in its own process
to find out) and exits with status 2.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from .. import sweep
from ..boat.catalogue import boat_label
from ..errors import ControllerFailed, act, one_line

DEFAULT_TWS = (2.0, 4.0, 6.0)
DEFAULT_TWA = tuple(range(30, 181, 15))
BEST_SAIL_DEG = tuple(range(5, 91, 5))
STEADY_WINDOW_S = 20.0  # s, a point's speed is the mean over the last this many seconds


def polar_spec(boat: str, controller: str, tws, twa, *, world: str = "mujoco",
               duration: float = 60.0, steady_window: float = STEADY_WINDOW_S, controller_grid=None,
               options: dict | None = None, seeds=(0,), gusts: bool = False) -> dict:
    """The sweep description of one polar (TWS x TWA, heading north).

    Parameters
    ----------
    boat, controller : str
        The boat (a registered name or a boat file) and the registered controller.
    tws, twa : iterable of float
        True wind speeds (m/s) and true wind angles (deg, off the starboard bow); every pair is
        one run.
    world : {"mujoco", "paper"}
        The simulation.
    duration : float
        Simulated seconds per point.
    steady_window : float
        A point's speed is the mean over the last this many seconds.
    controller_grid : dict, optional
        Controller options swept at every point (``{"controller.sail_deg": [...]}``).
    options : dict, optional
        More sweep options (``"task.x"`` / ``"env.x"`` keys).
    seeds : sequence of int
        The seeds each point is sailed on; with more than one the seed draws the start heading
        (the task's jitter).
    gusts : bool
        Gusts and wander in the wind, drawn by the seed.

    Returns
    -------
    dict
        The sweep description (:mod:`sailmujoco.sweep`).
    """
    seeds = [int(s) for s in seeds]
    jitter = {} if len(seeds) > 1 else {"task.heading_jitter_deg": 0.0}
    tws_axis, twa_axis = [], []
    for s in tws:
        for a in twa:
            tws_axis.append(float(s))
            twa_axis.append(float(a))
    spec = {
        "name": f"polar-{boat_label(boat)}-{sweep.controller_label(controller)}", "boat": str(boat),
        "task": "heading_hold",
        "world": world, "controller": controller, "duration": float(duration), "seeds": seeds,
        "metrics": ["steady_speed", "steady_heel"],
        "options": {"task.gusts": bool(gusts), "task.wander": bool(gusts), "task.desired_heading_deg": 0.0,
                    "task.steady_window": float(steady_window), **jitter, **(options or {})},
        "zip": {"task.wind_speed": tws_axis, "task.wind_from_deg": twa_axis},
        "grid": dict(controller_grid or {}),
    }
    return spec


def compute(boat: str, controller: str, out, *, tws=DEFAULT_TWS, twa=DEFAULT_TWA,
            world: str = "mujoco", duration: float = 60.0, scheduler=None, workers=None,
            progress: bool = True, options: dict | None = None, seeds=(0,), gusts: bool = False):
    """Run a polar on the sweep engine.

    Parameters
    ----------
    boat : str
        The boat.
    controller : str
        A registered controller, or ``"best"``: every fixed sail angle of :data:`BEST_SAIL_DEG`,
        the fastest kept point by point.
    out : path
        Folder; the sweep writes into ``<out>/sweep-<controller>``.
    tws, twa : iterable of float
        True wind speeds (m/s) and angles (deg).
    world : {"mujoco", "paper"}
        The simulation.
    duration : float
        Simulated seconds per point.
    scheduler : str, optional
        Dask scheduler address, or ``"serial"``; default an embedded cluster.
    workers : int, optional
        Worker processes of the embedded cluster.
    progress : bool
        Show a progress bar.
    options : dict, optional
        More sweep options.
    seeds : sequence of int
        The seeds each point is sailed on (:func:`polar_spec`).
    gusts : bool
        Gusts and wander, drawn by the seed.

    Returns
    -------
    pandas.DataFrame
        Columns tws, twa, speed, heel (and sail_deg for ``best``), each the mean over the point's
        seeds that finished, speed_low and speed_high (its 95 % interval) and n (its seeds).
    """
    table, _ = sweep_table(boat, controller, out, tws=tws, twa=twa, world=world, duration=duration,
                           scheduler=scheduler, workers=workers, progress=progress, options=options,
                           seeds=seeds, gusts=gusts)
    return over_seeds(finished_points(table, controller))


def sweep_table(boat: str, controller: str, out, *, tws=DEFAULT_TWS, twa=DEFAULT_TWA,
                world: str = "mujoco", duration: float = 60.0, scheduler=None, workers=None,
                progress: bool = True, options: dict | None = None, seeds=(0,), gusts: bool = False) -> tuple:
    """Run a polar on the sweep engine: (its table, failed runs included, with the columns tws,
    twa, speed and heel; its sweep description).

    Parameters
    ----------
    boat, controller, out, tws, twa, world, duration, scheduler, workers, progress, options, seeds, gusts
        As :func:`compute`.
    """
    grid = {"controller.sail_deg": list(BEST_SAIL_DEG)} if controller == "best" else None
    name = "fixed_sail" if controller == "best" else controller
    spec = polar_spec(boat, name, tws, twa, world=world, duration=duration, controller_grid=grid,
                      options=options, seeds=seeds, gusts=gusts)
    # a polar re-run with other winds or duration goes into the same folder (the table keeps
    # this run's rows only): the sweep may replace another spec there (exclusive=False)
    folder = Path(out) / f"sweep-{sweep.controller_label(controller)}"
    table = sweep.run(spec, folder, scheduler=scheduler, workers=workers, progress=progress,
                      exclusive=False)
    table = table.rename(columns={"task.wind_speed": "tws", "task.wind_from_deg": "twa",
                                  "steady_speed": "speed", "steady_heel": "heel"})
    for column in ("speed", "heel"):  # no metric columns where no run finished
        if column not in table:
            table[column] = np.nan
    return table, spec


def finished_points(table, controller: str):
    """The polar of the runs that finished, one row per point and seed (for ``best``, the fastest
    sail at each point on each seed).

    Parameters
    ----------
    table : pandas.DataFrame
        A polar's sweep table (:func:`sweep_table`).
    controller : str
        The controller it was sailed with.

    Returns
    -------
    pandas.DataFrame
        ``tws``, ``twa``, ``seed``, ``speed``, ``heel`` (and ``sail_deg`` for ``best``), by TWS,
        TWA and seed.
    """
    ok = table[table["status"] == "ok"]
    if controller == "best":  # the fastest fixed sail at each point, seed by seed
        idx = ok.groupby(["tws", "twa", "seed"])["speed"].idxmax()
        best = ok.loc[idx].rename(columns={"controller.sail_deg": "sail_deg"})
        return best[["tws", "twa", "seed", "speed", "heel", "sail_deg"]].sort_values(["tws", "twa", "seed"])
    return ok[["tws", "twa", "seed", "speed", "heel"]].sort_values(["tws", "twa", "seed"])


def over_seeds(points):
    """A polar from its points' seeds: one row per (TWS, TWA) with the mean speed, heel (and
    sail_deg) over the seeds, ``speed_low`` and ``speed_high`` (the speed's 95 % interval,
    :mod:`sailmujoco.stats`) and ``n``, the seeds.

    Parameters
    ----------
    points : pandas.DataFrame
        :func:`finished_points`.
    """
    import pandas as pd

    from .. import stats

    rows = []
    for (tws, twa), group in points.groupby(["tws", "twa"], sort=True):
        speed = stats.mean_interval(group["speed"].to_numpy(dtype=float))
        row = {"tws": tws, "twa": twa, "speed": speed.mean, "speed_low": speed.low,
               "speed_high": speed.high, "heel": float(group["heel"].mean())}
        if "sail_deg" in group:
            row["sail_deg"] = float(group["sail_deg"].mean())
        rows.append({**row, "n": len(group)})
    columns = ["tws", "twa", "speed", "speed_low", "speed_high", "heel"]
    columns += ["sail_deg"] if "sail_deg" in points else []
    return pd.DataFrame(rows, columns=columns + ["n"])


def first_failure(table, spec: dict, controller: str) -> str | None:
    """Why the first failed run failed, one line with the simulated time (the sweep records the
    error, not when: the run is simulated again here, each action checked); None if none failed.

    Parameters
    ----------
    table : pandas.DataFrame
        A polar's sweep table (:func:`sweep_table`).
    spec : dict
        Its sweep description (:func:`polar_spec`).
    controller : str
        The controller it was sailed with.
    """
    failed = table[table["status"] == "failed"]
    if failed.empty:
        return None
    row = failed.iloc[0]
    run = next(r for r in sweep.expand(sweep.validate(spec)) if r["run_id"] == row["run_id"])
    where = f"TWS {row['tws']:g} m/s, TWA {row['twa']:g} deg"
    from ..suite import load

    env = None
    try:
        env = load(run["boat"], run["task"], run["world"], seed=run["seed"], time_limit=run.get("duration"),
                   boat_options=run["boat_options"], waves=run.get("waves_options") or None,
                   **run["env_options"], **run["task_options"])
        policy = sweep.make_controller(run["controller"], env, **run["controller_options"])
        if hasattr(policy, "reset"):
            policy.reset(run["seed"])
        timestep, shape = env.reset(), env.action_spec().shape
        while not timestep.last():
            timestep = env.step(act(policy, timestep, controller=controller,
                                    time=float(env.physics.time()), shape=shape))
    except ControllerFailed as err:
        return f"{err} ({where})"
    except Exception as err:
        when = f"at t = {env.physics.time():.2f} s" if env is not None else "before it started"
        return f"the run at {where} failed {when}: {one_line(f'{type(err).__name__}: {err}')}"
    recorded = one_line(str(row["error"] or "no error recorded").strip().splitlines()[0])
    return f"the run at {where} failed: {recorded} (it did not fail when run again)"


def best_vmg(frame):
    """Per TWS: (twa, vmg) of the best upwind and downwind velocity made good.

    Parameters
    ----------
    frame : pandas.DataFrame
        A polar (:func:`compute`).

    Returns
    -------
    dict
        TWS -> ``{"upwind": (twa_deg, vmg), "downwind": (twa_deg, vmg)}`` (m/s).
    """
    out = {}
    for tws, group in frame.groupby("tws"):
        twa = np.radians(group["twa"].to_numpy())
        speed = group["speed"].to_numpy()
        up = speed * np.cos(twa)
        down = -speed * np.cos(twa)
        iu, idn = int(np.argmax(up)), int(np.argmax(down))
        out[tws] = {"upwind": (float(group["twa"].iloc[iu]), float(up[iu])),
                    "downwind": (float(group["twa"].iloc[idn]), float(down[idn]))}
    return out


def half_polar(size: tuple[float, float]):
    """(figure, axes) of a polar diagram's half: TWA from 0 at the top, clockwise to 180.

    Parameters
    ----------
    size : tuple of float
        The figure's size, inches.
    """
    from .. import figures

    fig = figures.pyplot().figure(figsize=size)
    ax = fig.add_subplot(projection="polar")
    ax.set_theta_zero_location("N")
    ax.set_theta_direction(-1)
    ax.set_thetamin(0)
    ax.set_thetamax(180)
    return fig, ax


def plot_polar(frame, path, title: str) -> None:
    """The classic polar: speed against TWA, one curve per TWS, best VMG marked.

    Parameters
    ----------
    frame : pandas.DataFrame
        A polar (:func:`compute`).
    path : path
        The PNG written.
    title : str
        The figure's title.
    """
    from .. import figures

    fig, ax = half_polar((6.5, 6.5))
    vmg = best_vmg(frame)
    for tws, group in frame.groupby("tws"):
        (line,) = ax.plot(np.radians(group["twa"]), group["speed"], "-o", ms=3,
                          label=f"TWS {tws:g} m/s")
        speed_bars(ax, np.radians(group["twa"]), group, line.get_color())
        for kind, marker in (("upwind", "^"), ("downwind", "v")):
            a, _ = vmg[tws][kind]
            v = float(group.loc[group["twa"] == a, "speed"].iloc[0])
            ax.plot([math.radians(a)], [v], marker, ms=10, color=line.get_color(),
                    markeredgecolor="k")
    ax.annotate("true wind\nfrom 0° ", xy=(0.0, ax.get_rmax()), xycoords="data", xytext=(-14, 42),
                textcoords="offset points", ha="right", va="center", fontsize=8, color="red",
                arrowprops=dict(arrowstyle="-|>", color="red", lw=1.5), annotation_clip=False)
    ax.set_xlabel("true wind angle TWA [deg], from where the wind comes\n(▲ best VMG upwind, ▼ downwind)")
    ax.set_title(title + "\nradius: boat speed [m/s]", fontsize=10)
    figures.legend_below(fig, ax, ncol=3)
    figures.save(fig, path, dpi=120)


def speed_bars(ax, x, group, color) -> None:
    """The 95 % interval of each point's speed over its seeds, as error bars (none for one seed).

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The axes.
    x : array_like
        The points' positions (TWA, in the axes' unit).
    group : pandas.DataFrame
        The points (:func:`over_seeds`): ``speed``, ``speed_low``, ``speed_high``.
    color : str
        The bars' colour.
    """
    if "speed_low" not in group or not group["speed_low"].notna().any():
        return
    speed = group["speed"].to_numpy(dtype=float)
    low = np.where(group["speed_low"].notna(), group["speed_low"], speed)
    high = np.where(group["speed_high"].notna(), group["speed_high"], speed)
    ax.errorbar(x, speed, yerr=np.vstack([speed - low, high - speed]), fmt="none", ecolor=color,
                capsize=2, lw=1)
