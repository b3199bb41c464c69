"""The dm_control environment of the suite: dm_control's step, an episode that ends (rather than
raises) when the simulation stops, and the reward a stop earns.

``suite.load`` returns a :class:`SailEnvironment`. With ``flat_observation=True`` (dm_control's
option) every observation is one float64 array under the key ``"observations"``
(``dm_control.rl.control.flatten_observation``), and :meth:`SailEnvironment.observation_spec`
says so.
"""

from __future__ import annotations

import math

import dm_env
import numpy as np
from dm_control.rl import control
from dm_env import specs

from ..errors import SimulationStopped


class SailEnvironment(control.Environment):
    """``control.Environment`` that ends the episode, rather than raising, when the simulation
    stops (capsize, non-finite state); the reason lands in ``task.metrics()['stopped']`` and the
    step's reward is the task's :meth:`~sailmujoco.tasks.base.SailTask.stop_reward` for the steps
    the episode had left.

    A step is dm_control's, in two halves around the physics so that a batch
    (:class:`sailmujoco.batch.BatchEnvironment`) can step the physics of many environments in
    one call between them: :meth:`before_physics` (the action), the physics, :meth:`after_physics`
    (record, reward, observation, the TimeStep).
    """

    def step(self, action):
        """One control step: the action, the physics sub-steps, then the TimeStep.

        Parameters
        ----------
        action : array_like, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)].

        Returns
        -------
        dm_env.TimeStep
            The last one if the simulation stopped during the step.
        """
        if self._reset_next_step:
            return self.reset()
        self.before_physics(action)
        try:
            self._physics.step(self._n_sub_steps)
        except SimulationStopped as stop:
            return self.stopped_step(stop.reason)
        return self.after_physics()

    def before_physics(self, action) -> None:
        """The task's ``before_step``: the action checked and set on the actuators.

        Parameters
        ----------
        action : array_like, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)].
        """
        self._task.before_step(action, self._physics)

    def after_physics(self):
        """The rest of dm_control's step once the physics has stepped: the TimeStep."""
        try:
            self._task.after_step(self._physics)
            reward = self._task.get_reward(self._physics)
            observation = self._task.get_observation(self._physics)
        except SimulationStopped as stop:
            return self.stopped_step(stop.reason)
        if self._flat_observation:
            observation = control.flatten_observation(observation)
        self._step_count += 1
        if self._step_count >= self._step_limit:
            discount = 1.0
        else:
            discount = self._task.get_termination(self._physics)
        if discount is not None:
            self._reset_next_step = True
            return dm_env.TimeStep(dm_env.StepType.LAST, reward, discount, observation)
        return dm_env.TimeStep(dm_env.StepType.MID, reward, 1.0, observation)

    def steps_left(self) -> int:
        """Control steps the episode has still to run before its time limit (the current
        step counted once it is under way: between ``before_physics`` and its TimeStep).

        Returns
        -------
        int
            ``ceil(step limit) - steps done``; 1 without a time limit (``time_limit=inf``).
        """
        if math.isinf(self._step_limit):
            return 1
        return max(math.ceil(self._step_limit) - self._step_count, 0)

    def compiled_steps(self) -> int:
        """The control steps a compiled closed loop (:mod:`sailmujoco.loop`) may take now: those
        left of an episode under way with a time limit and dict observations; 0 otherwise."""
        if self._reset_next_step or self._flat_observation or math.isinf(self._step_limit):
            return 0
        return self.steps_left()

    def sub_steps(self) -> int:
        """Physics sub-steps per control step."""
        return self._n_sub_steps

    def count_steps(self, n: int) -> None:
        """Count ``n`` control steps a compiled closed loop took (the TimeSteps it did not make).

        Parameters
        ----------
        n : int
            The steps, >= 0.
        """
        self._step_count += n

    def max_steps(self) -> int | None:
        """Control steps of a whole episode (the time limit over the control step), or None
        without a time limit."""
        return None if math.isinf(self._step_limit) else math.ceil(self._step_limit)

    def stopped_step(self, reason: str):
        """The last TimeStep of an episode whose simulation stopped for ``reason``.

        Its reward is the task's :meth:`~sailmujoco.tasks.base.SailTask.stop_reward` for this
        step and the ones the episode had left.

        Parameters
        ----------
        reason : str
            Why it stopped (capsized, non-finite state); recorded as ``task.metrics()['stopped']``.
        """
        reward = self.end_episode(reason, self.steps_left())
        # the state the run stopped in (a capsize is a valid state); the previous step's
        # observation only when that state cannot be measured (non-finite)
        observation = self._task.last_observation
        try:
            fresh = self._task.measurement(self._physics)[0]
        except (ValueError, FloatingPointError, SimulationStopped):
            fresh = None
        if fresh is not None and finite(fresh):
            observation = self._task.last_observation = fresh
        observation = self._task.observation_of(observation)
        if self._flat_observation:
            observation = control.flatten_observation(observation)
        return dm_env.termination(reward=reward, observation=observation)

    def end_episode(self, reason: str, steps: int) -> float:
        """End the episode now for ``reason``: the next step resets.

        Parameters
        ----------
        reason : str
            Why it ended; recorded as ``task.metrics()['stopped']``.
        steps : int
            The control steps the ending costs: this one and those the episode had left.

        Returns
        -------
        float
            The reward of the ending step, the task's ``stop_reward(steps)`` (its reward terms:
            ``task.last_reward_terms``).
        """
        self._task.stopped = reason
        self._reset_next_step = True
        return self._task.stop_reward(steps)

    def observation_spec(self):
        """The observation's specs: the task's, or with ``flat_observation`` one float64 array
        ``"observations"`` (dm_control's flat layout)."""
        if not self._flat_observation:
            return self._task.observation_spec(self._physics)
        flat = control.flatten_observation(self._task.get_observation(self._physics))
        return {key: specs.Array(value.shape, value.dtype, name=key) for key, value in flat.items()}


def finite(observation) -> bool:
    """Every number of a (nested) observation is finite.

    Parameters
    ----------
    observation : dict or array_like
        An observation, or one of its entries.
    """
    if isinstance(observation, dict):
        return all(finite(value) for value in observation.values())
    return bool(np.all(np.isfinite(np.asarray(observation, dtype=float))))
