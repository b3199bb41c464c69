"""A Gymnasium adapter over the suite's dm_env environments (the same environments, not a copy).

    env = sailmujoco.gym.SailGymEnv("wille_yacht", "heading_hold", world="mujoco")
    observation, info = env.reset(seed=0)
    observation, reward, terminated, truncated, info = env.step(env.action_space.sample())

Observations are the suite's nested dicts as ``gymnasium.spaces.Dict`` of ``Box`` (float64).
``terminated`` means the simulation stopped (capsize, non-finite state), ``truncated`` that the
time limit came; ``info`` carries the reward terms and, at the end, the task's metrics.
The action is [rudder angle (rad), sail angle (rad)], or with ``sail_mode="sheeted"`` [rudder
angle (rad), sheet length (m)]; the bounds are the actuators' (``action_space.low``/``high``) and
the dm_env spec's name spells the units ("rudder_rad,sail_rad" or "rudder_rad,sheet_m").
"""

from __future__ import annotations

import gymnasium
import numpy as np
from gymnasium import spaces

from . import suite


def _space(spec):
    if isinstance(spec, dict):
        return spaces.Dict({key: _space(value) for key, value in spec.items()})
    return spaces.Box(-np.inf, np.inf, shape=spec.shape, dtype=np.float64)


def _plain(observation):
    if isinstance(observation, dict):
        return {key: _plain(value) for key, value in observation.items()}
    return np.array(observation, dtype=np.float64, copy=True)


class SailGymEnv(gymnasium.Env):
    """``suite.load(boat, task, world, **options)`` behind the Gymnasium API."""

    metadata = {"render_modes": []}

    def __init__(self, boat: str = "wille_yacht", task: str = "heading_hold",
                 world: str = "mujoco", **options):
        self._args = (boat, task, world)
        self._options = options
        self._env = suite.load(boat, task, world, **options)
        spec = self._env.action_spec()
        self.action_space = spaces.Box(np.asarray(spec.minimum, dtype=np.float64),
                                       np.asarray(spec.maximum, dtype=np.float64), dtype=np.float64)
        self.observation_space = _space(self._env.observation_spec())

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        super().reset(seed=seed)
        if seed is not None or options:
            kwargs = dict(self._options, **(options or {}))
            if seed is not None:
                kwargs["seed"] = seed
            self._env = suite.load(*self._args, **kwargs)
        timestep = self._env.reset()
        return _plain(timestep.observation), {}

    def step(self, action):
        action = np.asarray(action, dtype=np.float64)
        timestep = self._env.step(action)
        task = self._env.task
        info = {"reward_terms": task.reward_terms(self._env.physics, timestep.observation)}
        terminated = bool(timestep.last() and timestep.discount == 0.0)
        truncated = bool(timestep.last() and not terminated)
        if timestep.last():
            info["metrics"] = task.metrics()
        return _plain(timestep.observation), float(timestep.reward or 0.0), terminated, truncated, info

    @property
    def unwrapped_dm_env(self):
        return self._env
