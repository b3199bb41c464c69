"""Viel's position keeping task (``tasks/position.py``) in a compiled closed loop: which task
objects a loop may stand in for, their numbers, and the reward from the truth vector."""

from __future__ import annotations

import numpy as np

from ..jit.kernel import kernel
from ..reference.hypot import hypot
from ..tasks.base import SailTask
from ..tasks.position import FAR, PositionKeeping
from . import truth as T

# the hooks a loop writes out: a subclass may change anything else (where the boat starts: the
# loop begins after the reset) but not these
HOOKS = ("reward_terms", "references", "record", "before_step", "after_step", "get_reward", "get_observation",
         "measurement", "get_termination", "reward_floor", "observation_of")


def covers(task) -> bool:
    """Whether ``task`` is position keeping as the loop writes it out: PositionKeeping's own hooks,
    the truth measured (:meth:`~sailmujoco.tasks.base.SailTask.measures_truth`).

    Parameters
    ----------
    task : sailmujoco.tasks.base.SailTask
        The environment's task.
    """
    kind = type(task)
    own = (getattr(kind, h, None) is getattr(PositionKeeping, h, getattr(SailTask, h, None)) for h in HOOKS)
    return isinstance(task, PositionKeeping) and task.measures_truth() and all(own)


def task_numbers(task) -> np.ndarray:
    """The task's numbers as :func:`position_reward` reads them: the target (x, y, m), d_T (m) and
    the distance term's floor FAR (target radii).

    Parameters
    ----------
    task : sailmujoco.tasks.position.PositionKeeping
        The task.
    """
    return np.array([task.target[0], task.target[1], task.d_target, FAR], dtype=np.float64)


@kernel(inline=True)
def position_reward(truth, task):
    """``PositionKeeping.reward_terms``' one term, ``distance`` = -min(d, FAR d_T) / d_T.

    Parameters
    ----------
    truth : numpy.ndarray
        The truth of the state (:mod:`sailmujoco.loop.truth`).
    task : numpy.ndarray, shape (4,)
        :func:`task_numbers`.
    """
    d = hypot(truth[T.X] - task[0], truth[T.Y] - task[1])
    return -min(d, task[3] * task[2]) / task[2]
