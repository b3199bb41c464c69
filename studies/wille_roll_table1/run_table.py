"""The Table 1 runs by case, world, simulation and seed (:class:`RunTable`): each run's numbers
(:func:`studies.kit.wille.table1_numbers`), their means over the seeds with 95 % intervals, the
roll reductions paired by seed (:func:`reduction`: law on against law off on the same gusts),
the gust realisations and the lag switch."""

from __future__ import annotations

import numpy as np

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.stats import Interval

from ..kit import seeds as over
from ..kit.wille import BOAT, table1_numbers
from .scenario import LAG_SWITCH_S, realisation_seeds


def reduction(before: dict, after: dict) -> float:
    """The share of the roll amplitude a law takes away.

    Parameters
    ----------
    before, after : dict
        Two runs' numbers (:func:`studies.kit.wille.table1_numbers`).

    Returns
    -------
    float
        1 - after's roll amplitude / before's.
    """
    return 1.0 - after["roll_amplitude"] / before["roll_amplitude"]


class RunTable:
    """The runs by (case, world, sim, seed): each run's numbers, the seed means.

    Parameters
    ----------
    results : dict
        (case, world, sim, seed) -> the run (:func:`studies.kit.wille.table1_simulate`).
    seeds : sequence of int
        The headline seeds.
    """

    def __init__(self, results: dict, seeds):
        self.raw = results
        self.seeds = tuple(seeds)
        self.n = {k: table1_numbers(v) for k, v in results.items() if k[0] not in ("fig8 sail",)}

    def get(self, case, world, sim, seed=0) -> dict:
        """One run's numbers (:func:`studies.kit.wille.table1_numbers`).

        Parameters
        ----------
        case : str
            A key of :data:`.scenario.CASES` (or ``"shares"``).
        world : str
            A key of :data:`.scenario.WORLDS`.
        sim : str
            A key of :data:`.scenario.SIMS`.
        seed : int
            The gust realisation.

        Returns
        -------
        dict
            The numbers.
        """
        return self.n[(case, world, sim, seed)]

    def has(self, case, world, sim, seed=0) -> bool:
        """Whether that run was made (the parameters of :meth:`get`).

        Parameters
        ----------
        case, world, sim : str
            The run's case, world and simulation.
        seed : int
            The gust realisation.

        Returns
        -------
        bool
            True when it was.
        """
        return (case, world, sim, seed) in self.n

    def values(self, world, sim, key) -> np.ndarray:
        """One number of the headline runs, one per seed (in the order of :attr:`seeds`).

        Parameters
        ----------
        world : str
            A key of :data:`.scenario.WORLDS`.
        sim : str
            A key of :data:`.scenario.SIMS`.
        key : str
            The number (a key of :func:`studies.kit.wille.table1_numbers`).

        Returns
        -------
        numpy.ndarray
            The values.
        """
        return np.array([self.get("main", world, sim, s)[key] for s in self.seeds], dtype=float)

    def interval(self, world, sim, key) -> Interval:
        """One number of the headline runs over the seeds: its mean with the 95 % interval.

        Parameters
        ----------
        world : str
            A key of :data:`.scenario.WORLDS`.
        sim : str
            A key of :data:`.scenario.SIMS`.
        key : str
            The number.

        Returns
        -------
        sailmujoco.stats.Interval
            Mean [low, high] over the seeds.
        """
        return over.interval(self.values(world, sim, key))

    def mean(self, world, sim) -> dict:
        """The headline runs' numbers, averaged over the seeds.

        Parameters
        ----------
        world : str
            A key of :data:`.scenario.WORLDS`.
        sim : str
            A key of :data:`.scenario.SIMS`.

        Returns
        -------
        dict
            The seed means.
        """
        values = [self.get("main", world, sim, s) for s in self.seeds]
        return {k: float(np.mean([v[k] for v in values])) for k in values[0]}

    def reduction(self, world, base, sim, case="main", seeds=None) -> Interval:
        """The share of the roll amplitude the law takes away, seed by seed on the same gusts
        (1 - amplitude of ``sim`` / amplitude of ``base``), over the seeds.

        Parameters
        ----------
        world : str
            A key of :data:`.scenario.WORLDS`.
        base, sim : str
            The law-off and the law-on simulation.
        case : str
            The case of the law-on runs (the law-off runs are the same case where it ran them,
            else the headline's).
        seeds : sequence of int, optional
            The seeds (the headline seeds if not given).

        Returns
        -------
        sailmujoco.stats.Interval
            Mean [low, high] of the per-seed reductions.
        """
        seeds = self.seeds if seeds is None else tuple(seeds)
        before_case = case if all(self.has(case, world, base, s) for s in seeds) else "main"
        cuts = [reduction(self.get(before_case, world, base, s), self.get(case, world, sim, s)) for s in seeds]
        return over.interval(cuts)

    def cut(self, world, base, sim) -> Interval:
        """How many degrees of roll amplitude the law takes away, paired by seed (``base`` minus
        ``sim`` on the same gusts).

        Parameters
        ----------
        world : str
            A key of :data:`.scenario.WORLDS`.
        base, sim : str
            The law-off and the law-on simulation.

        Returns
        -------
        sailmujoco.stats.Interval
            Mean [low, high] of the per-seed differences (deg).
        """
        return over.paired(self.values(world, base, "roll_amplitude"), self.values(world, sim, "roll_amplitude"))

    def realisations(self) -> list[tuple[int, dict, dict]]:
        """(seed, sim 1, sim 3) of the paper world over the headline seeds and the extra
        realisations.

        Returns
        -------
        list of tuple
            (seed, sim 1's numbers, sim 3's numbers).
        """
        cases = [("main", seed) for seed in self.seeds]
        cases += [("realisations", seed) for seed in realisation_seeds(self.seeds)]
        return [(seed, self.get(case, "paper", "sim1", seed), self.get(case, "paper", "sim3", seed))
                for case, seed in cases if self.has(case, "paper", "sim3", seed)]

    def lag(self, seed, fast: bool = False) -> list[tuple[float, dict]]:
        """(T_lambda, sim 3) of the paper world for one seed, the paper's 0.5 s first; control at
        10 Hz, or at 1 / FAST_CONTROL_S with ``fast``.

        Parameters
        ----------
        seed : int
            The gust realisation.
        fast : bool
            The runs at the fast control rate.

        Returns
        -------
        list of tuple
            (T_lambda in s, sim 3's numbers).
        """
        first, prefix = ("rate", "rate lag") if fast else ("main", "lag")
        pts = [(get_boat(BOAT).sail.time_constant, first)] + [(t, f"{prefix} {t:g}") for t in LAG_SWITCH_S]
        return [(t, self.get(case, "paper", "sim3", seed)) for t, case in pts
                if self.has(case, "paper", "sim3", seed)]

    def median_seed(self, world="paper") -> int:
        """The headline seed of the median sim-1 roll amplitude (the one the figures show).

        Parameters
        ----------
        world : str
            A key of :data:`.scenario.WORLDS`.

        Returns
        -------
        int
            The seed.
        """
        amps = [(self.get("main", world, "sim1", s)["roll_amplitude"], s) for s in self.seeds]
        return sorted(amps)[len(amps) // 2][1]
