"""The task registry: every task class by its ``name``, registered with :func:`register_task`.

A task module decorates its classes::

    @register_task
    class SpeedTrial(SailTask):
        name = "speed_trial"

and :func:`sailmujoco.suite.load` finds them by name. A user's task registers the same way at
run time (no reinstall): define the class, decorate it, then ``suite.load(boat, "my_task")``.
"""

from __future__ import annotations

from .base import SailTask

TASKS: dict[str, type[SailTask]] = {}


def register_task(cls: type[SailTask]) -> type[SailTask]:
    """Register a task class under its ``name`` (a class decorator; returns the class).

    Parameters
    ----------
    cls : type
        A subclass of :class:`sailmujoco.tasks.base.SailTask` with its own ``name``.

    Raises
    ------
    ValueError
        If ``cls`` is not a SailTask subclass, keeps the base's name, or its name is taken by
        another class.
    """
    if not (isinstance(cls, type) and issubclass(cls, SailTask)):
        raise ValueError(f"register_task takes a SailTask subclass, got {cls!r}")
    if cls.name == SailTask.name:
        raise ValueError(f"task class {cls.__name__} needs a name of its own (class attribute `name`)")
    held = TASKS.get(cls.name)
    if held is not None and held is not cls:
        raise ValueError(f"task name {cls.name!r} is taken by {held.__module__}.{held.__qualname__}")
    TASKS[cls.name] = cls
    return cls
