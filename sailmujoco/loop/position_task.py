"""Viel's position keeping task (``tasks/position.py``), compiled: its reward from the truth vector."""

from __future__ import annotations

from ..jit.kernel import kernel
from ..reference.hypot import hypot
from . import truth as T

# the task's numbers: the target (x, y, m), d_T (m), the distance term's floor FAR (target radii)
TASK_SIZE = 4


@kernel(inline=True)
def position_reward(truth, task):
    """``PositionKeeping.reward_terms``' one term, ``distance`` = -min(d, FAR d_T) / d_T."""
    d = hypot(truth[T.X] - task[0], truth[T.Y] - task[1])
    return -min(d, task[3] * task[2]) / task[2]
