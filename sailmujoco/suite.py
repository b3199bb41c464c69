"""The task suite: ``load(boat, task, world)`` returns a ``dm_env.Environment``.

Worlds
    ``"mujoco"``  the 6-DOF MuJoCo boat (:class:`sailmujoco.physics.BoatPhysics`);
    ``"paper"``   the paper's reduced model: Wille's 4-DOF equations with the boat's
                  parameters (:class:`sailmujoco.reference.wille.Wille4DOF`), or, for
                  ``position_keeping``, Viel's 3-DOF model with its own Table 1 boat
                  (:class:`sailmujoco.reference.viel.VielWorld`; the ``boat`` argument then only
                  names the run).

Example::

    from sailmujoco import suite
    env = suite.load("wille_yacht", "heading_hold", world="mujoco", seed=0)
    timestep = env.reset()
"""

from __future__ import annotations

import math

from .params import BOATS, get_boat
from .physics import BoatPhysics, ForceSwitches
from .tasks.base import PaperPhysics, SailEnvironment, check_number
from .tasks.position import PositionKeeping, VielPhysics
from .tasks.sailing import BeamReachRoll, CourseHold, HeadingHold, SpeedTrial

TASKS = {cls.name: cls for cls in (HeadingHold, CourseHold, BeamReachRoll, SpeedTrial,
                                   PositionKeeping)}
WORLDS = ("mujoco", "paper")
SUITE = tuple((boat, task, world) for boat in BOATS for task in TASKS for world in WORLDS)


def load(boat: str, task: str, world: str = "mujoco", *, seed: int | None = None,
         control_timestep: float = 0.1, time_limit: float | None = None,
         sail_mode: str = "actuated", hydrostatics: str = "geometric", dofs: int = 6,
         paper_model: str = "paper", sail_tangential: bool = True,
         added_mass_coupling: str = "manoeuvring", vertical_damping: str = "world",
         restoring_axes: str = "horizontal", resistance: str = "dsyhs",
         foils: str = "finite", keel_downwash: bool = True, windage: bool = True,
         forces: ForceSwitches | None = None, params=None,
         boat_options: dict | None = None, **task_options) -> SailEnvironment:
    """Build an environment.

    Parameters
    ----------
    boat, task, world : str
        A registered boat (``BOATS``), task (``TASKS``) and world (``WORLDS``).
    seed : int, optional
        Seeds the initial-state randomisation and the wind.
    control_timestep : float
        Seconds per ``env.step``; the physics runs at its own fixed step underneath.
    time_limit : float, optional
        Episode length in seconds (default: the task's, e.g. 200 s for course_hold).
    sail_mode, hydrostatics, dofs, forces
        MuJoCo world options (see :class:`sailmujoco.physics.BoatPhysics`). With
        ``sail_mode="sheeted"`` the action's second command is the sheet length in metres (the
        boom swings free up to the angle that length allows), not the sail angle in radians.
    paper_model : {"paper", "rigid"}
        Wille 4-DOF variant (see :mod:`sailmujoco.reference.wille`).
    sail_tangential : bool
        Keep the sail's tangential force C_T (False: Saoud's Assumption 4 made true).
    added_mass_coupling, vertical_damping, restoring_axes : str
        Hydrodynamic modelling forms (:class:`sailmujoco.physics.ForceSwitches`); the defaults
        are the models, the alternatives the forms they replaced, kept to measure the effect.
    resistance, foils, keel_downwash, windage
        The boat as built (:class:`sailmujoco.physics.ForceSwitches`), MuJoCo world only:
        ``resistance`` "dsyhs" (friction plus Delft residuary resistance) or "friction" (Wille
        eq. 15); ``foils`` "finite" (finite-wing lift slope, 3-D post-stall) or "paper";
        ``keel_downwash`` and ``windage`` on (default) or off.
    boat_options : dict, optional
        Passed to the boat's parameter factory (e.g. ``{"l_phi": 0.1}``).
    params : BoatParams, optional
        The boat's parameters as an object (a changed copy, for a modelling switch); then
        ``boat`` only names the run and ``boat_options`` must be empty.
    task_options
        Passed to the task (e.g. ``case=3`` for position_keeping).
    """
    if task not in TASKS:
        raise ValueError(f"unknown task {task!r}; known tasks: {', '.join(TASKS)}")
    if world not in WORLDS:
        raise ValueError(f"unknown world {world!r}; choose one of {WORLDS}")
    dt_ok = isinstance(control_timestep, (int, float)) and not isinstance(control_timestep, bool)
    if not (dt_ok and math.isfinite(control_timestep) and control_timestep > 0):
        raise ValueError(f"control_timestep must be a positive time in s, got {control_timestep!r}")
    if time_limit is not None:
        time_limit = check_number("time_limit", time_limit, 0.0, low_open=True, unit="s")
    if params is None:
        params = get_boat(boat, **(boat_options or {}))
    elif boat_options:
        raise ValueError("give either params or boat_options, not both")
    try:
        the_task = TASKS[task](seed=seed, **task_options)
    except TypeError as err:
        raise ValueError(f"bad option for task {task!r}: {err}") from None
    wind = the_task.wind()
    switches = forces or ForceSwitches(hydrostatics=hydrostatics, sail_tangential=sail_tangential,
                                       added_mass_coupling=added_mass_coupling,
                                       vertical_damping=vertical_damping, restoring_axes=restoring_axes,
                                       resistance=resistance, foils=foils,
                                       keel_downwash=keel_downwash, windage=windage)
    if world == "mujoco":
        physics = BoatPhysics.load(params=params, sail_mode=sail_mode, wind=wind, forces=switches,
                                   dofs=dofs)
    elif task == "position_keeping":
        from .reference.viel import VielWorld

        physics = VielPhysics.for_control(VielWorld(wind=wind), control_timestep)
    else:
        from .reference.wille import Wille4DOF

        physics = PaperPhysics(Wille4DOF(params=params, wind=wind, switches=switches,
                                         model=paper_model))
    return SailEnvironment(physics, the_task, time_limit=time_limit or the_task.duration,
                           control_timestep=control_timestep, legacy_step=False)


def load_batch(boat: str, task: str, world: str = "mujoco", *, n: int | None = None,
               seeds=None, options=None, **common):
    """N environments stepped together (:class:`sailmujoco.batch.BatchEnvironment`).

    ``seeds``: one seed per environment (default ``range(n)``); ``options``: one dict of
    :func:`load` options per environment (e.g. different winds or force switches), merged over
    ``common``. In the MuJoCo world (6 or 4 DOF) the boats step in one compiled call on all cores;
    every environment behaves exactly as ``load(boat, task, world, seed=..., **options)``.
    """
    from .batch import BatchEnvironment

    if seeds is None:
        if n is None:
            n = len(options) if options is not None else None
        if isinstance(n, bool) or not isinstance(n, int) or n < 1:
            raise ValueError(f"n must be an integer >= 1 (or give seeds), got {n!r}")
        seeds = list(range(n))
    seeds = list(seeds)
    options = [{} for _ in seeds] if options is None else list(options)
    if len(options) != len(seeds) or not seeds:
        raise ValueError(f"seeds ({len(seeds)}) and options ({len(options)}) must be one per "
                         "environment, at least one")
    return BatchEnvironment([load(boat, task, world, seed=seed, **{**common, **extra})
                             for seed, extra in zip(seeds, options, strict=True)])


def rollout(env, controller):
    """Run one episode of ``env`` with ``controller``; returns a pandas DataFrame, one row per
    control step: t, x, y (m), heading, heel (rad) and heel_deg, roll_rate, yaw_rate (rad/s),
    u, v, speed (m/s), rudder, sail (rad), awa (rad), aws (m/s)."""
    import math

    import numpy as np
    import pandas as pd

    def row(observation):
        ts = observation["true_state"]
        return {"t": float(ts["time"]), "x": float(observation["position"][0]),
                "y": float(observation["position"][1]), "heading": float(observation["heading"]),
                "heel": float(observation["heel"]), "heel_deg": math.degrees(float(observation["heel"])),
                "roll_rate": float(observation["roll_rate"]), "yaw_rate": float(observation["yaw_rate"]),
                "u": float(ts["u"]), "v": float(ts["v"]),
                "speed": float(np.linalg.norm(observation["velocity"])),
                "rudder": float(ts["rudder"]), "sail": float(ts["sail"]),
                "awa": float(observation["apparent_wind_angle"]),
                "aws": float(observation["apparent_wind_speed"])}

    if hasattr(controller, "reset"):
        controller.reset(env.task.seed)
    timestep = env.reset()
    rows = [row(timestep.observation)]
    while not timestep.last():
        timestep = env.step(controller(timestep))
        rows.append(row(timestep.observation))
    return pd.DataFrame(rows)
