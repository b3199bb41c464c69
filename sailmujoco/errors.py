"""The exceptions of a run: the simulation left the valid state space (:class:`SimulationStopped`),
or the controller failed (:class:`ControllerFailed`, raised by :func:`act`); and the one check of
a number the user gives (:func:`check_number`), its error one line naming the option and range,
and of a set of figures given by a preset's name or a dict (:func:`preset_figures`,
:func:`check_figures`)."""

from __future__ import annotations

import dataclasses
import math

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


def check_number(name: str, value, low: float | None = None, high: float | None = None, *,
                 low_open: bool = False, unit: str = "") -> float:
    """``value`` as a float if it is a finite number within [low, high] (or (low, high] with
    ``low_open``); otherwise a ValueError naming the option and the accepted range.

    Parameters
    ----------
    name : str
        The option's name, for the error message.
    value : object
        The value given; a bool is refused.
    low, high : float or None
        Bounds, inclusive (``low`` exclusive with ``low_open``); None: unbounded on that side.
    low_open : bool
        Refuse ``value == low``.
    unit : str
        Unit named in the error message.
    """
    given = value
    ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)
    if ok:
        value = float(value)
        ok = math.isfinite(value) and (low is None or (value > low if low_open else value >= low)) \
            and (high is None or value <= high)
    if not ok:
        lo = "" if low is None else f"{'>' if low_open else '>='} {low:g}"
        hi = "" if high is None else f"<= {high:g}"
        allowed = " and ".join(p for p in (lo, hi) if p)
        rng = f" {allowed}{' ' + unit if unit else ''}" if allowed else (f" (in {unit})" if unit else "")
        raise ValueError(f"{name} must be a finite number{rng}, got {given!r}")
    return value


def preset_figures(value, presets: dict, kind: str, noun: str, base=None):
    """A figures object (the instruments', the actuators') from a preset's name, a dict of its
    fields over ``base`` (or over the preset its ``"preset"`` key names), an object of the
    presets' class, or None (``base``); a figure given makes it no longer perfect.

    Parameters
    ----------
    value : str, dict, the presets' class or None
        What the caller gave.
    presets : dict
        Preset name -> figures object; ``"perfect"`` among them.
    kind : str
        The option's name in a message ("sensors").
    noun : str
        One figure, with its article, in a message ("a sensor figure").
    base : the presets' class, optional
        What None gives and a dict without ``"preset"`` is over (default ``presets["perfect"]``;
        a boat file's own figures, for a boat that has them).
    """
    cls = type(presets["perfect"])
    base = presets["perfect"] if base is None else base
    if value is None:
        return base
    if isinstance(value, cls):
        return value
    if isinstance(value, str):
        if value not in presets:
            raise ValueError(f"{kind} must be one of {sorted(presets)} or a dict of figures, got {value!r}")
        return presets[value]
    if isinstance(value, dict):
        figures = dict(value)
        if "preset" in figures:
            base = preset_figures(figures.pop("preset"), presets, kind, noun)
        known = {f.name for f in dataclasses.fields(cls)}
        for key in figures:
            if key not in known:
                raise ValueError(f"{kind}.{key} is not {noun}; choose from {sorted(known)}")
        if figures and "perfect" not in figures:
            figures["perfect"] = False
        return dataclasses.replace(base, **figures)
    raise ValueError(f"{kind} must be a preset name, a dict of figures or {cls.__name__}, got {value!r}")


def check_figures(figures, kind: str, limits: dict) -> None:
    """Every field of a figures object checked: a bool field true or false, a number finite and
    at least its lower bound (``limits``: name -> (low, strict); 0 where not named), one line
    naming ``<kind>.<field>`` otherwise.

    Parameters
    ----------
    figures : dataclass instance
        The figures.
    kind : str
        The option's name in a message ("sensors").
    limits : dict
        Lower bounds other than ``>= 0``.
    """
    for f in dataclasses.fields(figures):
        value = getattr(figures, f.name)
        if f.type in (bool, "bool"):
            if not isinstance(value, bool):
                raise ValueError(f"{kind}.{f.name} must be true or false, got {value!r}")
            continue
        low, strict = limits.get(f.name, (0.0, False))
        check_number(f"{kind}.{f.name}", value, low, low_open=strict)
