"""Argument converters and checks shared by the ``sailmujoco`` sub-commands.

Each converter is an argparse ``type``: a bad value exits 2 with one line that names the
accepted range. The checks raise :class:`ValueError` with one line, which the command turns
into ``sailmujoco: error: ...`` and exit status 2.
"""

from __future__ import annotations

import argparse
import ast
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from ..names import check_known
from ..sweep import MAX_LOCAL_WORKERS

INTERRUPTED = 130  # the shell's status for a command ended by Ctrl-C (128 + SIGINT)


def number(low: float, *, low_open: bool, unit: str, integer: bool = False,
           high: float | None = None) -> Callable[[str], float | int]:
    """An argparse type: a finite number above ``low`` (or at least ``low``) and at most ``high``.

    Parameters
    ----------
    low : float
        The lower bound.
    low_open : bool
        True: the value must be above ``low``; False: at least ``low``.
    unit : str
        Named after the range in the message ("s", "m/s"; "" for none).
    integer : bool
        Parse an integer rather than a float.
    high : float, optional
        The upper bound (included); none without it.

    Returns
    -------
    callable
        ``parse(text) -> value``; raises :class:`argparse.ArgumentTypeError` with one line
        naming the range.
    """
    def parse(text: str):
        """The number ``text`` gives, if within the range.

        Parameters
        ----------
        text : str
            The command-line text.
        """
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            value = None
        if (value is None or not math.isfinite(value) or (value <= low if low_open else value < low)
                or (high is not None and value > high)):
            kind = "an integer" if integer else "a number"
            upper = f" and <= {high:g}" if high is not None else ""
            raise argparse.ArgumentTypeError(
                f"must be {kind} {'>' if low_open else '>='} {low:g}{upper}"
                f"{' ' + unit if unit else ''}, got {text!r}")
        return value
    return parse


POSITIVE_SECONDS = number(0.0, low_open=True, unit="s")
SEED = number(0, low_open=False, unit="", integer=True)
WORKERS = number(0, low_open=False, unit="(0: all cores)", integer=True, high=MAX_LOCAL_WORKERS)
SEEDS = number(1, low_open=False, unit="", integer=True, high=1000)  # --seeds N (study.MAX_SEEDS)


def floats(text: str) -> list[float]:
    """A list of numbers: ``'2,4,6'`` or ``'start:stop:step'`` (stop included).

    Parameters
    ----------
    text : str
        The argument as typed.

    Returns
    -------
    list of float
    """
    if ":" in text:
        start, stop, step = (float(v) for v in text.split(":"))
        return [float(v) for v in np.arange(start, stop + 1e-9, step)]
    return [float(v) for v in text.split(",")]


def literal(text: str):
    """A ``--set`` value: a Python literal, TOML's true/false, or else the text itself.

    Parameters
    ----------
    text : str
        The value as typed.
    """
    if text.lower() in ("true", "false"):
        return text.lower() == "true"
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


def setting(text: str) -> tuple[str, object]:
    """An argparse type for ``--set KEY=VALUE``: ``(key, value)``, the value read by :func:`literal`.

    Parameters
    ----------
    text : str
        The argument as typed.
    """
    key, sep, value = text.partition("=")
    if not sep or not key:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.strip(), literal(value.strip())


def add_controller_arguments(parser: argparse.ArgumentParser, default: str | None = None) -> None:
    """``--controller NAME`` and the repeatable ``--option KEY=VALUE`` of its factory.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The command's parser.
    default : str, optional
        The controller without ``--controller``; None makes the option required.
    """
    parser.add_argument("--controller", required=default is None, default=default, metavar="NAME",
                        help="a registered controller (sailmujoco list), 'package.module:factory' or "
                             "'path/to/file.py:factory' (no package, no reinstall)")
    parser.add_argument("--option", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="a keyword of the controller's factory, e.g. kp=2.0 (repeatable; the "
                             "value a number, true/false, a list or text); checked against the "
                             "factory's keywords and the kinds of their defaults")


def controller_options(args) -> dict:
    """``--option`` of ``args.controller`` as a dict, checked against its factory's keywords
    (one line naming an unknown option, or a value of the wrong kind, with what is accepted).

    Parameters
    ----------
    args : argparse.Namespace
        ``controller`` and ``option`` (:func:`add_controller_arguments`).

    Returns
    -------
    dict
    """
    from ..sweep import check_controller_options

    options = dict(args.option)
    check_controller_options(args.controller, options)
    return options


class HelpFormatter(argparse.RawDescriptionHelpFormatter):
    """Descriptions and epilogs as written (examples keep their lines), and every option's
    default in its help unless the help already names it (or the default is unset)."""

    def _get_help_string(self, action):
        text = action.help or ""
        default = action.default
        if ("default" in text or default is None or default is False or default == []
                or default == argparse.SUPPRESS or not action.option_strings):
            return text
        values = default if isinstance(default, (list, tuple)) else [default]
        shown = ",".join(f"{v:g}" if isinstance(v, float) else str(v) for v in values)
        return f"{text} (default: {shown})".strip()


def check_settings(settings, task: str | None = None) -> None:
    """``--set`` of ``video`` and ``view``: every key one that ``suite.load`` takes for ``task``
    (one line with the nearest name otherwise); the episode's seed and length have options of
    their own.

    Parameters
    ----------
    settings : iterable of (str, object)
        The ``--set`` pairs.
    task : str, optional
        The task they are for (its options are accepted); None checks the seed and length only.
    """
    settings = dict(settings)
    for key, option in (("time_limit", "--seconds"), ("seed", "--seed")):
        if key in settings:
            raise ValueError(f"--set {key}=... is the option {option}")
    from .. import suite

    if task is not None and task in suite.TASKS:
        check_known(settings, suite.keyword_options(task) + ("control_timestep",), "--set",
                    error=ValueError)


def out_folder(path) -> Path:
    """``--out`` as a folder, created if missing; a file there is one line (:class:`ValueError`).

    Parameters
    ----------
    path : str or path
        The folder.

    Returns
    -------
    Path
    """
    path = Path(path)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except (FileExistsError, NotADirectoryError):
        raise ValueError(f"--out {str(path)!r} is (or lies under) a file; give a folder") from None
    except OSError as err:  # no permission, a read-only or virtual file system
        raise ValueError(f"cannot make the folder {str(path)!r}: {err.strerror}") from None
    return path


def file_argument(option: str, text: str, example: str) -> None:
    """A file to write, its missing folders made; a folder there, a file among its parents or a
    folder that cannot be made is one line (:class:`ValueError`).

    Parameters
    ----------
    option : str
        The option's name in the message (``--out``).
    text : str
        The path as typed.
    example : str
        A file name the message suggests where a folder was given.
    """
    path = Path(text)
    if path.is_dir():
        raise ValueError(f"{option} {text!r} is a folder; give a file name such as "
                         f"{str(path / example)!r}")
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
    except (FileExistsError, NotADirectoryError):
        raise ValueError(f"{option} {text!r}: {str(path.parent)!r} is (or lies under) a file, "
                         f"not a folder") from None
    except OSError as err:  # no permission, a read-only or virtual file system
        raise ValueError(f"{option} {text!r}: cannot make the folder {str(path.parent)!r}: "
                         f"{err.strerror}") from None


class Terminated(Exception):
    """SIGTERM arrived: a long-running command (``sitl``, ``ros2``) ends as on a timeout, its
    tables and logs written."""


def raise_terminated(signum, frame):
    """A SIGTERM handler that raises :class:`Terminated` where the command is.

    Parameters
    ----------
    signum : int
        The signal.
    frame : frame
        Where it arrived.
    """
    raise Terminated
