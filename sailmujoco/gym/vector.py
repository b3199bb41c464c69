"""The suite's native vector environment behind Gymnasium's vector API (:class:`SailVectorEnv`;
the manual is :mod:`sailmujoco.gym`)."""

from __future__ import annotations

import gymnasium
import numpy as np
from gymnasium.vector.utils import batch_space, concatenate, create_empty_array

from .. import suite
from ..names import check_known
from . import spaces as gym_spaces
from .env import SailGymEnv, step_outcome


class SailVectorEnv(gymnasium.vector.VectorEnv):
    """``num_envs`` environments of one boat and task as a Gymnasium ``VectorEnv``, stepped
    together (:func:`sailmujoco.suite.load_batch`: in the MuJoCo world the boats' physics is
    one compiled call per step on all cores). ``gymnasium.make_vec(id, num_envs,
    vectorization_mode="vector_entry_point")`` builds one.

    Environment i is ``SailGymEnv(boat, task, world, seed=seeds[i], **options)`` (default seeds
    0 .. num_envs-1; ``reset(seed=s)`` rebuilds them with seeds s, s+1, ...); the spaces are
    SailGymEnv's, batched, and so are rewards, flags and the envelope. Autoreset is
    Gymnasium's "next step" mode: the step after an environment's episode ends resets it and
    returns its first observation with reward 0 and neither flag set. ``infos`` follows
    Gymnasium's vector convention: ``infos["reward_terms"][name]`` is an array over the
    environments with the mask ``infos["reward_terms"]["_" + name]`` saying which environments
    have that term this step (and ``infos["_reward_terms"]`` which have any);
    ``infos["metrics"][name]`` and its mask ``infos["metrics"]["_" + name]`` hold the task's
    metrics of the environments whose episode ended on this step, ``infos["_metrics"]`` says
    which did.

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load`.
    num_envs : int
        The number of environments.
    seeds : iterable of int, optional
        One seed per environment (default 0 .. num_envs-1).
    normalize_action, include_true_state, area
        As :class:`~sailmujoco.gym.SailGymEnv`.
    max_episode_steps : int, optional
        End (truncate) each episode after this many steps at the latest; ``make_vec`` passes
        the id's.
    render_mode : None
        Only None: render one :class:`~sailmujoco.gym.SailGymEnv` instead.
    **options
        :func:`sailmujoco.suite.load`'s keywords shared by every environment (not ``seed``).
    """

    metadata = {"render_modes": [], "autoreset_mode": gymnasium.vector.AutoresetMode.NEXT_STEP}

    def __init__(self, boat="wille_yacht", task: str = "heading_hold", world: str = "mujoco", *,
                 num_envs: int = 2, seeds=None, normalize_action: bool = True,
                 include_true_state: bool = False, area: float = gym_spaces.DEFAULT_AREA,
                 max_episode_steps: int | None = None, render_mode: str | None = None, **options):
        if isinstance(num_envs, bool) or not isinstance(num_envs, int) or num_envs < 1:
            raise ValueError(f"num_envs must be an integer >= 1, got {num_envs!r}")
        if "seed" in options:
            raise ValueError("give seeds (one per environment) or reset(seed=...), not seed")
        if render_mode is not None:
            raise ValueError(f"SailVectorEnv: render_mode must be None (render a SailGymEnv), "
                             f"got {render_mode!r}")
        options = self._limited(task, options, max_episode_steps)
        self._single = SailGymEnv(boat, task, world, normalize_action=normalize_action,
                                  include_true_state=include_true_state, area=area, **options)
        self._args = (boat, task, world)
        self._options = dict(options, include_true_state=include_true_state)
        self.num_envs = num_envs
        self.render_mode = None
        self.single_observation_space = self._single.observation_space
        self.single_action_space = self._single.action_space
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self._build(list(range(num_envs)) if seeds is None else list(seeds))

    @staticmethod
    def _limited(task: str, options: dict, max_episode_steps) -> dict:
        """``options`` with a time limit no longer than ``max_episode_steps`` control steps."""
        options = dict(options)
        if max_episode_steps is None:
            return options
        if isinstance(max_episode_steps, bool) or not isinstance(max_episode_steps, int) \
                or max_episode_steps < 1:
            raise ValueError(f"max_episode_steps must be an integer >= 1, got {max_episode_steps!r}")
        check_known([task], suite.TASKS, "SailVectorEnv", kind="task", error=ValueError)
        limit = options.get("time_limit") or suite.TASKS[task].duration
        dt = options.get("control_timestep", 0.1)
        if (max_episode_steps - 0.5) * dt < limit:  # half a step short: the step count is exact
            options["time_limit"] = (max_episode_steps - 0.5) * dt
        return options

    def _build(self, seeds) -> None:
        if len(seeds) != self.num_envs:
            raise ValueError(f"seeds must be one per environment ({self.num_envs}), got {len(seeds)}")
        self._batch = suite.load_batch(*self._args, seeds=seeds, **self._options)

    @property
    def batch(self):
        """The underlying :class:`sailmujoco.batch.BatchEnvironment`."""
        return self._batch

    def _observations(self, timesteps):
        space = self.single_observation_space
        out = create_empty_array(space, self.num_envs)
        return concatenate(space, [gym_spaces.gym_observation(t.observation, space) for t in timesteps], out)

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
        actions = np.asarray(actions)
        if actions.shape != self.action_space.shape:
            raise ValueError(f"actions must have shape {self.action_space.shape}, got {actions.shape}")
        timesteps = self._batch.step([self._single.actuator_command(a) for a in actions])
        rewards = np.zeros(self.num_envs)
        terminated = np.zeros(self.num_envs, dtype=bool)
        truncated = np.zeros(self.num_envs, dtype=bool)
        infos: dict = {}
        for i, (env, timestep) in enumerate(zip(self._batch.envs, timesteps, strict=True)):
            if timestep.first():  # the autoreset step
                continue
            rewards[i], terminated[i], truncated[i], info = step_outcome(env, timestep, self._single.limits)
            infos = self._add_info(infos, info, i)
        return self._observations(timesteps), rewards, terminated, truncated, infos
