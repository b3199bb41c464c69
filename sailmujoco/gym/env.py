"""One environment of the suite behind the Gymnasium API (:class:`SailGymEnv`; the manual is
:mod:`sailmujoco.gym`)."""

from __future__ import annotations

import dataclasses

import gymnasium
import numpy as np
from gymnasium import spaces
from gymnasium.error import ResetNeeded

from .. import suite
from ..boat.catalogue import get_boat
from ..options import PHYSICS_FIELDS, PhysicsOptions
from ..tasks.base import check_number
from . import spaces as gym_spaces
from .render import RENDER_MODES, FrameRenderer, WindowRenderer, declared_modes

# keywords that shape the spaces: given at construction only
_FIXED = ("time_limit", "control_timestep", "include_true_state")


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


def check_flag(name: str, value) -> bool:
    """``value`` if it is a bool, else a one-line ValueError naming ``name``.

    Parameters
    ----------
    name : str
        The option's name.
    value : object
        The value given.
    """
    if not isinstance(value, bool):
        raise ValueError(f"{name} must be True or False, got {value!r}")
    return value


def step_outcome(dm_env, timestep, limits: dict) -> tuple[float, bool, bool, dict]:
    """Gymnasium's (reward, terminated, truncated, info) of a dm_env step of ``dm_env``.

    ``terminated``: the simulation stopped (capsize, non-finite state) or the state left the
    envelope (:func:`sailmujoco.gym.spaces.outside`), which ends the episode here with the
    task's stop reward; ``truncated``: the time limit came. ``info["reward_terms"]`` holds the
    reward's named terms (their sum is the reward) and, at the end, ``info["metrics"]`` the
    task's metrics.

    Parameters
    ----------
    dm_env : SailEnvironment
        The environment that stepped.
    timestep : dm_env.TimeStep
        Its step.
    limits : dict
        The envelope, :func:`sailmujoco.gym.spaces.bounds`.
    """
    task = dm_env.task
    reward = float(timestep.reward)
    terminated = bool(timestep.last() and timestep.discount == 0.0)
    truncated = bool(timestep.last() and not terminated)
    if not terminated:
        reason = gym_spaces.outside(task.last_observation, limits)
        if reason is not None:
            reward = dm_env.end_episode(reason, dm_env.steps_left() + 1)
            terminated, truncated = True, False
    info = {"reward_terms": dict(task.last_reward_terms)}
    if terminated or truncated:
        info["metrics"] = task.metrics()
    return reward, terminated, truncated, info


def _hull_length(physics) -> float:
    """The hull length of a world's boat, m (Viel's 3-DOF world is Viel's boat, ``viel_boat``)."""
    params = getattr(physics, "params", None)
    return (params if params is not None else get_boat("viel_boat")).hull.length


class SailGymEnv(gymnasium.Env):
    """``suite.load(boat, task, world, **options)`` behind the Gymnasium API (the module
    :mod:`sailmujoco.gym` documents ids, spaces, reward and rendering).

    Parameters
    ----------
    boat, task, world : str
        As :func:`sailmujoco.suite.load` (``boat`` may be a BoatParams or a boat file).
    normalize_action : bool
        Actions in [-1, 1], mapped linearly onto the actuators' ranges; False: the actuators'
        own units and ranges.
    include_true_state : bool
        Add the privileged true state to the observation, as the keys ``true_state_<key>``.
    area : float
        Half-width of the square sailing area around the origin, m; leaving it ends the episode.
    render_mode : {None, "rgb_array", "human"}
        ``"rgb_array"``: :meth:`render` returns a frame of the video renderer;
        ``"human"``: each step is drawn in MuJoCo's viewer (a display is needed).
    render_width, render_height : int
        Frame size of ``"rgb_array"``, pixels.
    camera : str
        ``"rgb_array"``'s camera: "follow", "top" or "side" (:mod:`sailmujoco.video`).
    **options
        :func:`sailmujoco.suite.load`'s keywords (seed, time_limit, control_timestep, physics
        options, task options).
    """

    metadata = {"render_modes": declared_modes(), "render_fps": 10}

    def __init__(self, boat="wille_yacht", task: str = "heading_hold", world: str = "mujoco", *,
                 normalize_action: bool = True, include_true_state: bool = False,
                 area: float = gym_spaces.DEFAULT_AREA, render_mode: str | None = None,
                 render_width: int = 480, render_height: int = 360, camera: str = "follow",
                 **options):
        self.normalize_action = check_flag("normalize_action", normalize_action)
        self.include_true_state = check_flag("include_true_state", include_true_state)
        area = check_number("area", area, 0.0, low_open=True, unit="m")
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise ValueError(f"render_mode must be None or one of {RENDER_MODES}, got {render_mode!r}")
        self._args, self._options = (boat, task, world), options
        self._kwargs = options  # the suite.load keywords of the environment now loaded
        self._env = self._load(options)
        self._needs_reset = True
        spec = self._env.action_spec()
        self._low = np.asarray(spec.minimum, dtype=np.float64)
        self._high = np.asarray(spec.maximum, dtype=np.float64)
        if normalize_action:
            self.action_space = spaces.Box(-1.0, 1.0, shape=self._low.shape, dtype=np.float32)
        else:
            self.action_space = spaces.Box(self._low.astype(np.float32), self._high.astype(np.float32),
                                           dtype=np.float32)
        dt = self._env.control_timestep()
        steps = self._env.max_steps()
        obs_spec = self._env.observation_spec()
        wrenches = [key for key in obs_spec.get("true_state", {}) if key.endswith("_wrench")]
        self.limits = gym_spaces.bounds(area, np.inf if steps is None else (steps + 1) * dt,
                                        _hull_length(self._env.physics), wrenches)
        self.observation_space = gym_spaces.observation_space(obs_spec, self.limits)
        self.metadata = dict(self.metadata, render_fps=1.0 / dt)
        self.render_mode = render_mode
        labels = f"{boat if isinstance(boat, str) else boat.name} · {task} ({world})"
        self._renderer = None
        if render_mode == "rgb_array":
            self._renderer = FrameRenderer(int(render_width), int(render_height), camera, labels)
        elif render_mode == "human":
            self._renderer = WindowRenderer(1.0 / dt, labels)

    def _load(self, options: dict):
        return suite.load(*self._args, include_true_state=self.include_true_state, **options)

    def actuator_command(self, action) -> np.ndarray:
        """The command the actuators get for ``action`` (see :mod:`sailmujoco.gym`, Actions).

        Parameters
        ----------
        action : array_like
            An action of :attr:`action_space`.
        """
        return gym_spaces.actuator_command(action, self._low, self._high, self.normalize_action)

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """Start an episode; with ``seed`` or ``options`` the environment is built anew.

        Parameters
        ----------
        seed : int, optional
            The episode's seed (initial state and wind).
        options : dict, optional
            :func:`sailmujoco.suite.load` keywords replacing those given at construction
            (not ``time_limit``, ``control_timestep`` or ``include_true_state``: they shape the
            spaces).
        """
        super().reset(seed=seed)
        fixed = [key for key in (options or {}) if key in _FIXED]
        if fixed:
            raise ValueError(f"reset(options=...) cannot change {fixed[0]} (it shapes the spaces); "
                             f"build a new environment")
        if seed is not None or options:
            kwargs = _merged(self._options, options or {})
            if seed is not None:
                kwargs["seed"] = seed
            self._env = self._load(kwargs)
            self._kwargs = kwargs
        timestep = self._env.reset()
        self._needs_reset = False
        self._show()
        return gym_spaces.gym_observation(timestep.observation, self.observation_space), {}

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
        reward, terminated, truncated, info = step_outcome(self._env, timestep, self.limits)
        self._needs_reset = terminated or truncated
        self._show()
        observation = gym_spaces.gym_observation(timestep.observation, self.observation_space)
        return observation, reward, terminated, truncated, info

    def _show(self) -> None:
        if self.render_mode == "human":
            self._renderer.show(self._args[0], self._env, self._kwargs)

    def render(self):
        """``"rgb_array"``: the current state as an RGB frame, (height, width, 3) uint8;
        ``"human"``: None (each step is drawn as it happens); no render mode: None."""
        if self.render_mode == "rgb_array":
            return self._renderer.render(self._args[0], self._env, self._kwargs)
        return None

    def close(self) -> None:
        """Free the renderer's GL context or close the viewer's window."""
        if self._renderer is not None:
            self._renderer.close()

    @property
    def unwrapped_dm_env(self):
        """The suite's dm_env environment underneath."""
        return self._env
