"""A Gymnasium adapter over the suite's dm_env environments (the same environments, not a copy).

    import gymnasium
    import sailmujoco.gym  # registers the ids below

    env = gymnasium.make("sailmujoco/WilleYacht-HeadingHold-v0")
    observation, info = env.reset(seed=0)
    observation, reward, terminated, truncated, info = env.step(env.action_space.sample())

Ids
    ``sailmujoco/<Boat>-<Task>-v0`` for every boat and task of :mod:`sailmujoco.suite`, the
    suite's snake_case names in CamelCase: ``wille_yacht`` -> ``WilleYacht``, ``beam_reach_roll``
    -> ``BeamReachRoll``; :func:`gym_ids` lists them. Importing ``sailmujoco.gym`` registers them;
    without that import, ``gymnasium.make("sailmujoco.gym:sailmujoco/WilleYacht-HeadingHold-v0")``
    imports it first (Gymnasium 1.x has no plugin entry points). Keyword arguments of
    ``gymnasium.make`` go to :class:`SailGymEnv`, hence to ``suite.load``: ``world="paper"``,
    ``seed``, ``time_limit``, the physics options (``physics=``, a
    :class:`sailmujoco.options.PhysicsOptions` or dict, or field by field: ``sail_mode``,
    ``hydrostatics``, ...), task options, and ``normalize_action``.
    ``SailGymEnv(boat, task, ...)`` builds the same environment without the registry.

Episodes
    Gymnasium's contract: ``reset`` first, and again after an episode ended. ``step`` before
    ``reset``, or after ``terminated`` or ``truncated``, raises ``gymnasium.error.ResetNeeded``.
    ``terminated`` means the simulation stopped (capsize, non-finite state), ``truncated`` that
    the task's time limit came; ``info`` carries the reward terms and, at the end, the task's
    metrics.

Observations
    The suite's nested dicts as ``gymnasium.spaces.Dict`` of float64 ``Box``. Bounded only
    where the code guarantees the bound: ``heading``, ``apparent_wind_angle`` and
    ``true_state.wind_direction`` in [-pi, pi] (wrapped); ``apparent_wind_speed`` >= 0 (a norm);
    ``true_state.wind_speed_10`` in [0, 100] m/s (the wind's accepted range);
    ``true_state.time`` >= 0; ``true_state.pitch`` in [-pi/2, pi/2]; and in the MuJoCo world
    also ``heel``, ``true_state.heel`` and ``true_state.yaw`` in [-pi, pi] (Euler angles of the
    hull's rotation; the paper worlds integrate these angles unwrapped). Everything else is
    unbounded.

Actions
    [rudder angle (rad), sail angle (rad)], or with ``sail_mode="sheeted"`` [rudder angle (rad),
    sheet length (m)]; the bounds are the actuators' (``action_space.low``/``high``) and the
    dm_env spec's name spells the units ("rudder_rad,sail_rad" or "rudder_rad,sheet_m").
    With ``normalize_action=True`` the action space is ``Box(-1, 1)`` and each component ``a``
    is clipped to [-1, 1] and mapped linearly onto its actuator range [low, high]::

        command = low + (a + 1) / 2 * (high - low)

    so -1 gives the minimum, +1 the maximum and 0 the middle (zero rudder, zero sail angle).
"""

from __future__ import annotations

import dataclasses

import gymnasium
import numpy as np
from gymnasium import spaces
from gymnasium.error import ResetNeeded

from . import suite
from .forces.wind import MAX_SPEED
from .options import PHYSICS_FIELDS, PhysicsOptions
from .physics import BoatPhysics

NAMESPACE = "sailmujoco"
VERSION = 0

_PI = float(np.pi)
# Observation bounds the code guarantees in every world: key path -> (low, high)
_BOUNDS = {
    "heading": (-_PI, _PI),  # frames.heading_from_yaw / wrap_angle
    "apparent_wind_angle": (-_PI, _PI),  # atan2 / wrap_angle
    "apparent_wind_speed": (0.0, np.inf),  # a norm
    "true_state.wind_direction": (-_PI, _PI),  # wrap_angle
    "true_state.wind_speed_10": (0.0, MAX_SPEED),  # WindConfig refuses any other speed
    "true_state.time": (0.0, np.inf),
    "true_state.pitch": (-_PI / 2, _PI / 2),  # arcsin in the MuJoCo world, 0 in the planar ones
}
# ... and in the MuJoCo world only (atan2 of the hull's rotation matrix)
_MUJOCO_BOUNDS = {"heel": (-_PI, _PI), "true_state.heel": (-_PI, _PI), "true_state.yaw": (-_PI, _PI)}


def _camel(name: str) -> str:
    return "".join(part.capitalize() for part in name.split("_"))


def gym_id(boat: str, task: str) -> str:
    """The registered id of ``suite.load(boat, task)``, e.g. "sailmujoco/WilleYacht-HeadingHold-v0".

    Parameters
    ----------
    boat : str
        A registered boat.
    task : str
        A registered task.
    """
    return f"{NAMESPACE}/{_camel(boat)}-{_camel(task)}-v{VERSION}"


def gym_ids() -> list[str]:
    """Every registered id: one per boat and task of the suite (the world is an option)."""
    return [gym_id(boat, task) for boat, task in _pairs()]


def _pairs():
    seen = []
    for boat, task, _world in suite.SUITE:
        if (boat, task) not in seen:
            seen.append((boat, task))
    return seen


def register_all() -> None:
    """Register :func:`gym_ids` with Gymnasium (done on import; calling again changes nothing)."""
    for boat, task in _pairs():
        env_id = gym_id(boat, task)
        if env_id not in gymnasium.registry:
            gymnasium.register(id=env_id, entry_point="sailmujoco.gym:SailGymEnv",
                               kwargs={"boat": boat, "task": task})


def _space(spec, bounds, path=""):
    if isinstance(spec, dict):
        return spaces.Dict({key: _space(value, bounds, f"{path}{key}.") for key, value in spec.items()})
    low, high = bounds.get(path[:-1], (-np.inf, np.inf))
    return spaces.Box(low, high, shape=spec.shape, dtype=np.float64)


def _merged(options: dict, update: dict) -> dict:
    """``options`` updated by ``update``; physics fields in ``update`` replace those of an
    ``options["physics"]`` (so a reset can change one physics option of an environment built
    with ``physics=``)."""
    merged = dict(options, **update)
    fields = {k: merged.pop(k) for k in update if k in PHYSICS_FIELDS}
    if fields and "physics" in options and "physics" not in update:
        physics = PhysicsOptions.from_value(options["physics"], "SailGymEnv.reset")
        merged["physics"] = dataclasses.replace(physics, **fields)
    else:
        merged.update(fields)
    return merged


def _plain(observation):
    if isinstance(observation, dict):
        return {key: _plain(value) for key, value in observation.items()}
    return np.array(observation, dtype=np.float64, copy=True)


class SailGymEnv(gymnasium.Env):
    """``suite.load(boat, task, world, **options)`` behind the Gymnasium API (see the module
    docstring for ids, spaces and ``normalize_action``).

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load`.
    normalize_action : bool
        Actions in [-1, 1], mapped onto the actuators' ranges.
    **options
        :func:`sailmujoco.suite.load`'s keywords (seed, time_limit, physics options, task
        options).
    """

    metadata = {"render_modes": []}

    def __init__(self, boat: str = "wille_yacht", task: str = "heading_hold",
                 world: str = "mujoco", *, normalize_action: bool = False, **options):
        if not isinstance(normalize_action, bool):
            raise ValueError(f"normalize_action must be True or False, got {normalize_action!r}")
        self._args = (boat, task, world)
        self._options = options
        self._env = suite.load(boat, task, world, **options)
        self._needs_reset = True
        spec = self._env.action_spec()
        self._low = np.asarray(spec.minimum, dtype=np.float64)
        self._high = np.asarray(spec.maximum, dtype=np.float64)
        self.normalize_action = normalize_action
        if normalize_action:
            self.action_space = spaces.Box(-1.0, 1.0, shape=self._low.shape, dtype=np.float64)
        else:
            self.action_space = spaces.Box(self._low, self._high, dtype=np.float64)
        bounds = dict(_BOUNDS, **(_MUJOCO_BOUNDS if isinstance(self._env.physics, BoatPhysics) else {}))
        self.observation_space = _space(self._env.observation_spec(), bounds)

    def actuator_command(self, action) -> np.ndarray:
        """The command the actuators get for ``action``: the action itself, or with
        ``normalize_action`` low + (clip(a, -1, 1) + 1) / 2 (high - low).

        Parameters
        ----------
        action : array_like
            An action of :attr:`action_space`.
        """
        action = np.asarray(action, dtype=np.float64)
        if not self.normalize_action:
            return action
        return self._low + (np.clip(action, -1.0, 1.0) + 1.0) * 0.5 * (self._high - self._low)

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """Start an episode; with ``seed`` or ``options`` the environment is built anew.

        Parameters
        ----------
        seed : int, optional
            The episode's seed (initial state and wind).
        options : dict, optional
            :func:`sailmujoco.suite.load` keywords replacing those given at construction.
        """
        super().reset(seed=seed)
        if seed is not None or options:
            kwargs = _merged(self._options, options or {})
            if seed is not None:
                kwargs["seed"] = seed
            self._env = suite.load(*self._args, **kwargs)
        timestep = self._env.reset()
        self._needs_reset = False
        return _plain(timestep.observation), {}

    def step(self, action):
        """One control step: (observation, reward, terminated, truncated, info).

        Parameters
        ----------
        action : array_like
            An action of :attr:`action_space`.
        """
        if self._needs_reset:
            raise ResetNeeded("step() needs reset() first: before the first episode and after an "
                              "episode ended (terminated or truncated)")
        timestep = self._env.step(self.actuator_command(action))
        task = self._env.task
        info = {"reward_terms": task.reward_terms(self._env.physics, timestep.observation)}
        terminated = bool(timestep.last() and timestep.discount == 0.0)
        truncated = bool(timestep.last() and not terminated)
        if timestep.last():
            info["metrics"] = task.metrics()
            self._needs_reset = True
        return _plain(timestep.observation), float(timestep.reward or 0.0), terminated, truncated, info

    @property
    def unwrapped_dm_env(self):
        """The suite's dm_env environment underneath."""
        return self._env


class SailVectorEnv(gymnasium.vector.VectorEnv):
    """``num_envs`` environments of one boat and task as a Gymnasium ``VectorEnv``, stepped
    together (:func:`sailmujoco.suite.load_batch`: in the MuJoCo world the boats' physics is
    one compiled call per step on all cores).

    Environment i is ``SailGymEnv(boat, task, world, seed=seeds[i], **options)`` (default seeds
    0 .. num_envs-1; ``reset(seed=s)`` rebuilds them with seeds s, s+1, ...); the spaces are
    SailGymEnv's, batched. Autoreset is Gymnasium's "next step" mode: the step after an
    environment's episode ends resets it and returns its first observation with reward 0 and
    neither flag set. ``infos["metrics"]`` holds the task's metrics of environments whose
    episode ended on this step (None elsewhere).

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load`.
    num_envs : int
        The number of environments.
    seeds : iterable of int, optional
        One seed per environment (default 0 .. num_envs-1).
    normalize_action : bool
        As :class:`SailGymEnv`.
    **options
        :func:`sailmujoco.suite.load`'s keywords shared by every environment (not ``seed``).
    """

    metadata = {"render_modes": [], "autoreset_mode": gymnasium.vector.AutoresetMode.NEXT_STEP}

    def __init__(self, boat: str = "wille_yacht", task: str = "heading_hold",
                 world: str = "mujoco", *, num_envs: int = 2, seeds=None,
                 normalize_action: bool = False, **options):
        from gymnasium.vector.utils import batch_space

        if isinstance(num_envs, bool) or not isinstance(num_envs, int) or num_envs < 1:
            raise ValueError(f"num_envs must be an integer >= 1, got {num_envs!r}")
        if "seed" in options:
            raise ValueError("give seeds (one per environment) or reset(seed=...), not seed")
        self._args, self._options = (boat, task, world), options
        self._single = SailGymEnv(boat, task, world, normalize_action=normalize_action, **options)
        self.num_envs = num_envs
        self.single_observation_space = self._single.observation_space
        self.single_action_space = self._single.action_space
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self._build(list(range(num_envs)) if seeds is None else list(seeds))

    def _build(self, seeds) -> None:
        if len(seeds) != self.num_envs:
            raise ValueError(f"seeds must be one per environment ({self.num_envs}), got {len(seeds)}")
        self._batch = suite.load_batch(*self._args, seeds=seeds, **self._options)

    @property
    def batch(self):
        """The underlying :class:`sailmujoco.batch.BatchEnvironment`."""
        return self._batch

    def _observations(self, timesteps):
        from gymnasium.vector.utils import concatenate, create_empty_array

        out = create_empty_array(self.single_observation_space, self.num_envs)
        return concatenate(self.single_observation_space, [_plain(t.observation) for t in timesteps], out)

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """Reset every environment; with ``seed`` they are rebuilt with seeds seed, seed+1, ...

        Parameters
        ----------
        seed : int, optional
            The first environment's seed.
        options : dict, optional
            Refused: build a new vector environment to change options.
        """
        super().reset(seed=seed)
        if options:
            raise ValueError("SailVectorEnv.reset takes no options; build a new one to change them")
        if seed is not None:
            self._build([int(seed) + i for i in range(self.num_envs)])
        return self._observations(self._batch.reset()), {}

    def step(self, actions):
        """One control step of every environment (Gymnasium's vector API).

        Parameters
        ----------
        actions : array_like
            One action per environment, shape ``(num_envs, 2)``.
        """
        actions = np.asarray(actions, dtype=np.float64)
        if actions.shape != self.action_space.shape:
            raise ValueError(f"actions must have shape {self.action_space.shape}, got {actions.shape}")
        timesteps = self._batch.step([self._single.actuator_command(a) for a in actions])
        last = np.array([t.last() for t in timesteps])
        terminated = last & np.array([t.discount == 0.0 for t in timesteps])
        rewards = np.array([float(t.reward or 0.0) for t in timesteps])
        metrics = [env.task.metrics() if end else None
                   for env, end in zip(self._batch.envs, last, strict=True)]
        return (self._observations(timesteps), rewards, terminated, last & ~terminated,
                {"metrics": metrics})


register_all()
