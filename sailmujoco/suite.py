"""The task suite: ``load(boat, task, world)`` returns a ``dm_env.Environment``.

Worlds:

- ``"mujoco"``: the 6-DOF MuJoCo boat (:class:`sailmujoco.physics.BoatPhysics`);
- ``"paper"``: the paper's reduced model: Wille's 4-DOF equations with the boat's
  parameters (:class:`sailmujoco.reference.wille.Wille4DOF`), or, for
  ``position_keeping``, Viel's 3-DOF model with its own Table 1 boat
  (:class:`sailmujoco.reference.viel.VielWorld`; the ``boat`` argument then only
  names the run).

Example::

    from sailmujoco import suite
    env = suite.load("wille_yacht", "heading_hold", world="mujoco", seed=0)
    timestep = env.reset()

Physics options (:class:`sailmujoco.options.PhysicsOptions`) go in ``physics=``, or one by one
as keywords next to the task's options::

    env = suite.load("saoud_robot", "heading_hold", physics={"hydrostatics": "paper", "dofs": 4})
    env = suite.load("saoud_robot", "heading_hold", hydrostatics="paper", dofs=4)  # the same
"""

from __future__ import annotations

import inspect
import math

import numpy as np

from .boat.catalogue import BOATS, get_boat
from .boat.fitted import actuator_options, sensor_options
from .boat.params import BoatParams
from .loop.episode import rollout_row, run_compiled
from .names import check_known
from .options import FORCE_FIELDS, PHYSICS_FIELDS, ForceSwitches, PhysicsOptions, World, choices
from .physics import BoatPhysics
from .step.timing import sub_steps
from .tasks.base import check_number
from .tasks.environment import SailEnvironment
from .tasks.registry import TASKS
from .tasks.world import PaperPhysics, VielPhysics

# isort: off
# the built-in tasks register on import, in this order (the order of TASKS, SUITE and the gym ids)
from .tasks import sailing  # noqa: F401
from .tasks import position  # noqa: F401
from .tasks import course  # noqa: F401
from .tasks import station  # noqa: F401
from .tasks import scanning  # noqa: F401
# isort: on

__all__ = ["SUITE", "TASKS", "WORLDS", "keyword_options", "load", "load_batch", "rollout", "task_options"]
WORLDS = choices(World)


def _in_paper_world(params: BoatParams) -> bool:
    """Whether Wille's 4-DOF paper world can sail ``params``: the main alone, no crew."""
    return not (params.carries_headsail or params.carries_crew)


SUITE = tuple((boat, task, world) for boat in BOATS for task in TASKS for world in WORLDS
              if world == "mujoco" or _in_paper_world(get_boat(boat)))  # the paper worlds: one sail, no crew
# keywords of load that are neither task options nor physics fields
_FORCES, _PARAMS = "forces", "params"


def task_options(task: str) -> tuple:
    """The option names the task ``task`` takes (its constructor's and its bases', less seed and
    the base's options the task lays itself, its ``fixed_options``).

    Parameters
    ----------
    task : str
        A registered task (``TASKS``).
    """
    names = list(getattr(TASKS[task], "fixed_options", ()))
    for cls in TASKS[task].__mro__:
        init = vars(cls).get("__init__")
        if init is None:
            continue
        for name, p in inspect.signature(init).parameters.items():
            if (p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)
                    and name not in ("self", "seed") and name not in names):
                names.append(name)
    return tuple(names[len(getattr(TASKS[task], "fixed_options", ())):])


def keyword_options(task: str) -> tuple:
    """The names :func:`load` takes in ``**options`` for ``task``: the task's options, every
    physics field (:data:`sailmujoco.options.PHYSICS_FIELDS`), ``forces`` and ``params``.

    Parameters
    ----------
    task : str
        A registered task (``TASKS``).
    """
    return task_options(task) + PHYSICS_FIELDS + (_FORCES, _PARAMS)


def load(boat: str | BoatParams, task: str, world: str = "mujoco", *, seed: int | None = None,
         time_limit: float | None = None, control_timestep: float = 0.1,
         physics: PhysicsOptions | dict | None = None, flat_observation: bool = False,
         **options) -> SailEnvironment:
    """Build an environment.

    Parameters
    ----------
    boat : str, os.PathLike or BoatParams
        A registered boat (``BOATS``), a boat file (``"my_boat.toml"``,
        :mod:`sailmujoco.boat.file`), or a boat's parameters as an object (a changed copy, for
        a modelling switch). ``boat_options`` must be empty for a file or an object.
    task : str
        A registered task (``TASKS``).
    world : {"mujoco", "paper"}
        The 6-DOF MuJoCo boat, or the paper's reduced model (see the module docstring).
    seed : int, optional
        Seeds the initial-state randomisation and the wind.
    time_limit : float, optional
        Episode length in seconds (default: the task's, e.g. 200 s for course_hold).
    control_timestep : float
        Seconds per ``env.step``; the physics runs at its own fixed step underneath (the
        ``timestep`` physics option, which must divide it into whole sub-steps).
    physics : PhysicsOptions or dict, optional
        The physics options (:class:`sailmujoco.options.PhysicsOptions`, whose docstring
        tables them: force models and their forms, ``sail_mode``, ``dofs``, ``paper_model``,
        ``boat_options``), as an object or a dict of its fields; default: the boat as built.
    flat_observation : bool
        dm_control's option: every observation one float64 array under ``"observations"``.
    **options
        The task's options (e.g. ``case=3`` for position_keeping, ``wind_speed=4.0``;
        :func:`task_options` lists them), and any physics option given by its field name
        instead of in ``physics`` (``hydrostatics="paper"``, ``dofs=4``). ``forces=`` (a
        :class:`sailmujoco.options.ForceSwitches`) gives the force switches at once, and
        ``params=`` (a BoatParams) the boat's parameters with ``boat`` only naming the run.
        A name that is neither refuses in one line with the nearest accepted one; so does a
        physics option given twice (in ``physics`` and as a keyword, or in ``forces`` and
        by its field name).
    """
    check_known([task], TASKS, "suite.load", kind="task", error=ValueError)
    check_known([world], WORLDS, "suite.load", kind="world", error=ValueError)
    dt_ok = isinstance(control_timestep, (int, float)) and not isinstance(control_timestep, bool)
    if not (dt_ok and math.isfinite(control_timestep) and control_timestep > 0):
        raise ValueError(f"control_timestep must be a positive time in s, got {control_timestep!r}")
    if not isinstance(flat_observation, bool):
        raise ValueError(f"flat_observation must be True or False, got {flat_observation!r}")
    if time_limit is not None:
        time_limit = check_number("time_limit", time_limit, 0.0, low_open=True, unit="s")
    settings, own_options, params = _split(task, physics, options)
    step = {} if settings.timestep is None else {"max_step": settings.timestep}  # a paper world's
    if step:
        sub_steps(settings.timestep, control_timestep)  # one line unless it divides the control step
    params = _boat_params(boat, params, settings.boat_options)
    own_options["sensors"] = sensor_options(own_options.get("sensors"), base=params.sensors)
    own_options["actuators"] = actuator_options(own_options.get("actuators"), base=params.actuators)
    try:
        the_task = TASKS[task](seed=seed, **own_options)
    except TypeError as err:
        raise ValueError(f"bad option for task {task!r}: {err}") from None
    the_task.control_period = float(control_timestep)  # the instruments sample once per control step
    wind = the_task.wind()
    switches = settings.forces
    if world == "mujoco":
        world_physics = BoatPhysics.load(params=params, sail_mode=settings.sail_mode, wind=wind,
                                         forces=switches, dofs=settings.dofs, waves=settings.waves,
                                         timestep=settings.timestep)
    elif task == "position_keeping":
        from .reference.viel import VielWorld

        world_physics = VielPhysics.for_control(VielWorld(wind=wind, **step), control_timestep)
    else:
        from .reference.wille import Wille4DOF

        world_physics = PaperPhysics(Wille4DOF(params=_one_sail(params), wind=wind, switches=switches,
                                               model=settings.paper_model, **step))
    return SailEnvironment(world_physics, the_task, time_limit=time_limit or the_task.duration,
                           control_timestep=control_timestep, flat_observation=flat_observation,
                           legacy_step=False)


def _one_sail(params: BoatParams) -> BoatParams:
    """``params``, refused in one line where it carries a headsail or a crew (the paper world has
    the main alone and no crew)."""
    if not _in_paper_world(params):
        part = "a headsail" if params.carries_headsail else "a crew"
        raise ValueError(f"boat {params.name!r} carries {part}, and Wille's 4-DOF paper world has the "
                         f"main alone and no crew: sail it in the 'mujoco' world")
    return params


def _split(task: str, physics, options: dict) -> tuple[PhysicsOptions, dict, BoatParams | None]:
    """load's keywords sorted: (the physics options, the task's options, ``params`` or None)."""
    options = dict(options)
    forces = options.pop(_FORCES, None)
    params = options.pop(_PARAMS, None)
    check_known(options, keyword_options(task), "suite.load")
    flat = {k: v for k, v in options.items() if k in PHYSICS_FIELDS}
    if forces is not None:
        if not isinstance(forces, ForceSwitches) or isinstance(forces, PhysicsOptions):
            raise ValueError(f"forces must be a ForceSwitches (physics options go in physics=), "
                             f"got {forces!r}")
        if physics is not None:
            raise ValueError("suite.load: give forces= or physics=, not both (physics= holds the "
                             "force switches too)")
        twice = [k for k in FORCE_FIELDS if k in flat]
        if twice:
            raise ValueError(f"suite.load: give the force switches once, in forces= or as "
                             f"{twice[0]}=, not both")
        flat.update({k: getattr(forces, k) for k in FORCE_FIELDS})
    if physics is not None and flat:
        raise ValueError(f"suite.load: give the physics options once, in physics= or as keywords "
                         f"({', '.join(flat)}), not both")
    settings = PhysicsOptions.from_value(physics if physics is not None else flat, "suite.load(physics=...)")
    return settings, {k: v for k, v in options.items() if k not in PHYSICS_FIELDS}, params


def _boat_params(boat, params, boat_options: dict) -> BoatParams:
    """The boat's parameters: ``boat`` (a name or a BoatParams), or ``params`` naming it."""
    if isinstance(boat, BoatParams):
        if params is not None:
            raise ValueError("give the boat's parameters once, as boat or as params, not both")
        params = boat
    if params is None:
        return get_boat(boat, **boat_options)
    if boat_options:
        raise ValueError("give either params or boat_options, not both")
    return params


def load_batch(boat: str, task: str, world: str = "mujoco", *, n: int | None = None,
               seeds=None, options=None, **common):
    """N environments stepped together (:class:`sailmujoco.batch.BatchEnvironment`).

    In the MuJoCo world (6 or 4 DOF) the boats step in one compiled call on all cores; every
    environment behaves exactly as ``load(boat, task, world, seed=..., **options)``.

    Parameters
    ----------
    boat, task, world
        As :func:`load`.
    n : int, optional
        The number of environments (default: one per seed, or one per options dict).
    seeds : iterable of int, optional
        One seed per environment (default ``range(n)``).
    options : list of dict, optional
        One dict of :func:`load` keywords per environment (e.g. different winds or force
        switches), merged over ``common``.
    **common
        :func:`load` keywords shared by every environment.
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


def rollout(env, controller, record=None):
    """Run one episode of ``env`` with ``controller``; a pandas DataFrame, one row per control
    step: t, x, y (m), heading, heel (rad) and heel_deg, roll_rate, yaw_rate (rad/s), u, v,
    speed (m/s), rudder, sail (rad), awa (rad), aws (m/s), or the rows ``record`` gives.

    The one episode loop: every study runs its episodes through it.

    Parameters
    ----------
    env : SailEnvironment
        An environment from :func:`load`.
    controller : callable
        ``controller(timestep) -> action`` (the protocol of :mod:`sailmujoco.controllers.base`);
        its ``reset(seed)``, if it has one, is called with the task's seed first. A rudder law
        and a sail law (``law(observation) -> angle``) go together into
        ``sailmujoco.controllers.base.Composite(rudder, sail)``; given anything else, the first
        step says what is needed, in one line.
    record : callable, optional
        ``record(step, timestep, action) -> dict or None``, called with the reset's TimeStep
        (step 0, action None), then after every step (step k >= 1, with the action that led to
        it), before the controller sees that TimeStep: the row of that step, or None for no
        row. It may read ``env`` and the controller's state there. Default: the row above, at
        every step.

    Returns
    -------
    pandas.DataFrame
        The rows, in step order.
    """
    import pandas as pd

    def row(step, timestep, action):
        observation = timestep.observation
        ts = observation["true_state"]
        return {"t": float(ts["time"]), "x": float(observation["position"][0]),
                "y": float(observation["position"][1]), "heading": float(observation["heading"]),
                "heel": float(observation["heel"]), "heel_deg": math.degrees(float(observation["heel"])),
                "roll_rate": float(observation["roll_rate"]), "yaw_rate": float(observation["yaw_rate"]),
                "u": float(ts["u"]), "v": float(ts["v"]),
                "speed": math.hypot(*observation["velocity"]),
                "rudder": float(ts["rudder"]), "sail": float(ts["sail"]),
                "awa": float(observation["apparent_wind_angle"]),
                "aws": float(observation["apparent_wind_speed"])}

    record = row if record is None else record
    rows = []

    def keep(step, timestep, action):
        kept = record(step, timestep, action)
        if kept is not None:
            rows.append(kept)

    if isinstance(controller, (tuple, list)) or not callable(controller):
        raise TypeError(f"suite.rollout: the controller must be callable, controller(timestep) -> "
                        f"[rudder, sail], got {type(controller).__name__}; {_LAWS}")
    if hasattr(controller, "reset"):
        controller.reset(env.task.seed)
    timestep = env.reset()
    step = 0
    keep(step, timestep, None)
    compiled = None
    if record is row and not timestep.last():
        compiled = run_compiled(env, controller)  # the same steps, bit for bit, in one native call
    if compiled is not None:
        rows.extend(rollout_row(truth) for truth in compiled.rows)
        timestep, step = compiled.timestep, compiled.steps
        keep(step, timestep, compiled.actions[-1, :2].copy())
    elif not timestep.last():
        action = _first_action(env, controller, timestep)
        timestep, step = env.step(action), 1
        keep(step, timestep, action)
    while not timestep.last():
        action = controller(timestep)
        timestep, step = env.step(action), step + 1
        keep(step, timestep, action)
    return pd.DataFrame(rows)


_LAWS = ("a rudder law and a sail law (observation -> angle [rad]) go together into "
         "sailmujoco.controllers.base.Composite(rudder, sail), which is one")


def _first_action(env, controller, timestep):
    """The controller's first action, checked: a controller takes the dm_env TimeStep and returns
    the task's action; anything else is one line saying what it needs."""
    try:
        action = controller(timestep)
    except (TypeError, KeyError, IndexError) as err:
        raise TypeError(f"suite.rollout: the controller failed on its first TimeStep "
                        f"({type(err).__name__}: {err}); a controller takes the dm_env TimeStep "
                        f"(its observation is timestep.observation) and returns [rudder, sail]; "
                        f"{_LAWS}") from err
    shape = env.action_spec().shape
    if np.shape(action) != shape:
        raise ValueError(f"suite.rollout: the controller returned {action!r}; the action is "
                         f"[rudder, sail] [rad], shape {shape}; {_LAWS}")
    return action
