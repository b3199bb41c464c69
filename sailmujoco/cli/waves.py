"""``--waves KEY=VALUE`` of ``sailmujoco video`` and ``sailmujoco view``: the sea a run sails in.

The keys are a sweep file's ``waves.`` keys (:data:`sailmujoco.options.WAVE_OPTIONS`: ``hs``,
``tp``, ``spectrum``, ``direction_from_deg``, ``gamma``, ``spreading``, ``n_components``,
``seed``), one per ``--waves``, read as :func:`sailmujoco.options.wave_config` reads them.
Without ``direction_from_deg`` the waves come from the wind's mean bearing at the start of the
run (the task's wind for that seed), as a wind-driven sea does. No ``--waves``, or ``hs=0``, is
calm water.
"""

from __future__ import annotations

import argparse

from ..names import check_known
from ..options import N_COMPONENTS, WAVE_OPTIONS, wave_config
from .arguments import setting


def add_waves_argument(parser: argparse.ArgumentParser) -> None:
    """Add the repeatable ``--waves KEY=VALUE`` to a command's parser.

    Parameters
    ----------
    parser : argparse.ArgumentParser
        The ``video`` or ``view`` parser.
    """
    parser.add_argument("--waves", type=setting, action="append", default=[], metavar="KEY=VALUE",
                        help="the sea, one key per --waves (repeatable): hs (significant height, m; "
                             "0: calm, the default), tp (peak period, s), spectrum (jonswap, pm, "
                             "regular), direction_from_deg (compass bearing the waves come from; "
                             "default: the wind's), gamma, spreading, n_components (default "
                             f"{N_COMPONENTS}; more: a finer spectrum, a slower step), seed")


def wind_bearing(task: str, seed: int, settings: dict) -> float:
    """The compass bearing (rad) the task's wind comes from at the start of a run.

    Parameters
    ----------
    task : str
        A registered task.
    seed : int
        The run's seed (a task may draw its wind from it).
    settings : dict
        The run's ``--set`` options; the task's own are given to it.
    """
    from ..suite import TASKS, task_options

    own = {key: value for key, value in settings.items() if key in task_options(task)}
    try:
        return float(TASKS[task](seed=seed, **own).wind().direction_from)
    except TypeError as err:
        raise ValueError(f"bad option for task {task!r}: {err}") from None


def waves_from_arguments(pairs, task: str, world: str, seed: int, settings: dict):
    """The sea of ``--waves`` pairs: a ``WaveConfig``, or None without any.

    Parameters
    ----------
    pairs : list of (str, object)
        The ``--waves`` pairs, as :func:`sailmujoco.cli.arguments.setting` reads them.
    task : str
        The run's task (its wind gives the default direction).
    world : str
        The run's world: a paper world is calm water and refuses a sea.
    seed : int
        The run's seed.
    settings : dict
        The run's ``--set`` options.

    Returns
    -------
    WaveConfig or None

    Raises
    ------
    ValueError
        One line naming ``--waves`` and the key, with what it accepts.
    """
    if not pairs:
        return None
    values = dict(pairs)
    check_known(values, WAVE_OPTIONS, "--waves", kind="sea option", error=ValueError)
    if world != "mujoco":
        raise ValueError(f"--waves: the {world} world is calm water, as in the papers; a sea needs "
                         f"--world mujoco")
    if "waves" in settings:
        raise ValueError("give the sea once: --waves KEY=VALUE or --set waves=..., not both")
    if "direction_from_deg" not in values:
        values["direction_from"] = wind_bearing(task, seed, settings)
    try:
        return wave_config(values, "--waves")
    except ValueError as err:  # WaveConfig's one line, named after the option
        text = str(err).replace("WaveConfig.", "--waves ").replace("waves.", "--waves ")
        raise ValueError(text if "--waves" in text else f"--waves: {text}") from None
