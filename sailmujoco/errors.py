"""The exceptions of a run: the simulation left the valid state space (:class:`SimulationStopped`),
or the controller failed (:class:`ControllerFailed`, raised by :func:`act`)."""

from __future__ import annotations

import numpy as np


class SimulationStopped(RuntimeError):
    """The simulation left the valid state space; ``reason`` says how.

    Parameters
    ----------
    reason : str
        Why the run stopped (for example "capsized: |heel| > 90 deg").
    time : float
        Simulated time at which it stopped, s.
    """

    def __init__(self, reason: str, time: float):
        super().__init__(f"simulation stopped at t = {time:.3f} s: {reason}")
        self.reason = reason
        self.time = time


def one_line(text: str, limit: int = 200) -> str:
    """``text`` on one line (runs of white space made one space), cut to ``limit`` characters.

    Parameters
    ----------
    text : str
        Any text (an exception's message).
    limit : int
        The most characters kept; a cut ends with "...".
    """
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[: limit - 3] + "..."


class ControllerFailed(RuntimeError):
    """A controller raised, or gave an action that is not finite or not of the action's shape.

    The message is one line: ``controller my_ctrl.py:make raised at t = 3.20 s: ValueError: boom``.
    The exception the controller raised, if any, is the ``__cause__``.

    Parameters
    ----------
    controller : str
        The controller as it was named (``"pid"``, ``"my_ctrl.py:make"``).
    time : float
        Simulated time of the observation the controller was given, s.
    what : str
        What it did: ``"raised"`` or ``"gave a bad action"``.
    detail : str
        The exception (``"ValueError: boom"``) or the action and what was expected, one line.

    Attributes
    ----------
    note : str
        The message without the controller's name, for a frame's note
        (``controller raised at t = 3.20 s: ValueError: boom``).
    kept : object or None
        What the run kept up to the failure, set by whoever stopped there (the
        :class:`~sailmujoco.video.Recording` of the video cut at the failure), else None.
    """

    def __init__(self, controller: str, time: float, what: str, detail: str):
        super().__init__(f"controller {controller} {what} at t = {time:.2f} s: {detail}")
        self.controller, self.time, self.what, self.detail = controller, float(time), what, detail
        self.note = f"controller {what} at t = {time:.2f} s: {detail}"
        self.kept = None


def act(policy, timestep, *, controller: str, time: float, shape: tuple = (2,)):
    """``policy(timestep)``, checked: a finite action of ``shape``; else :class:`ControllerFailed`.

    Parameters
    ----------
    policy : callable
        The controller: ``policy(timestep) -> action``.
    timestep : dm_env.TimeStep
        What it is given.
    controller : str
        Its name, for the message.
    time : float
        Simulated time of ``timestep``, s, for the message.
    shape : tuple of int
        The action's shape (the environment's ``action_spec().shape``).

    Returns
    -------
    object
        The action, as the controller gave it.

    Raises
    ------
    ControllerFailed
        The controller raised (any ``Exception``; the original is the ``__cause__``), or its
        action is not a finite array of ``shape``.
    """
    try:
        action = policy(timestep)
    except Exception as err:
        raise ControllerFailed(controller, time, "raised",
                               one_line(f"{type(err).__name__}: {err}")) from err
    try:
        values = np.asarray(action, dtype=float)
    except (TypeError, ValueError):
        values = None
    if values is None or values.shape != tuple(shape) or not np.isfinite(values).all():
        shown = one_line(values if values is not None else repr(action), 80)
        expected = " x ".join(str(n) for n in shape)
        raise ControllerFailed(controller, time, "gave a bad action",
                               f"{shown} ({expected} finite numbers expected)")
    return action
