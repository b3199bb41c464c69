"""The numbers of the Fig. 7 study: per angle and seed, the steady speeds of S, Bm, the checks and
vel_max; per angle, their means over the seeds and the ratios paired by seed with their
intervals; the paper's claims decided on them; the no-go zone."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco import stats
from sailmujoco.study import Results

from ..kit import seeds as over
from ..kit.saoud import PHI_MAX_DEG, TRUE_WIND, WORLDS
from ..kit.verdict import TOLERANCE
from .scenario import JOBS, LAWS, Settings, best_of, law_runs, settings, tidy

NO_GO_FRACTION = 0.15  # vel_max below this fraction of the true wind: the boat does not sail there
TIE = 0.01  # S counts as at least as fast as Bm when S >= (1 - TIE) Bm
HELD_DEG = 20.0  # deg, rms heading error above which a run did not hold heading 0
CLOSE = 1.0 - TOLERANCE  # "close to the maximum": S/vel_max above this (the project's 10 %)
KEYS = ["world", "l_phi", "angle"]


@dataclass(frozen=True)
class Analysis:
    """What the runs gave.

    Parameters
    ----------
    settings : Settings
        The grid and durations run.
    seeds : tuple of int
        The seeds.
    grid : pandas.DataFrame
        Every fixed-sail run of both worlds (the coarse grid on seed 0, the candidate sails on
        every seed), with its seed.
    per_seed : pandas.DataFrame
        Per (world, l_φ, angle, seed): the speed, heel, sail and rms heading error of every law
        and of that seed's vel_max.
    table : pandas.DataFrame
        Per (world, l_φ, angle): the means over the seeds, and whether it is in the no-go zone.
    numbers : dict
        The headline numbers (:func:`summarise`).
    runs : int
        Simulations run.
    wall_s : float
        Wall time of the simulations [s].
    """

    settings: Settings
    seeds: tuple
    grid: pd.DataFrame
    per_seed: pd.DataFrame
    table: pd.DataFrame
    numbers: dict
    runs: int
    wall_s: float

    def values(self, world: str, l_phi: float, angle: float, column: str) -> np.ndarray:
        """``column`` of :attr:`per_seed` at one point, in seed order (nan where absent).

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        angle : float
            ∠v_w^B [deg].
        column : str
            A law's name (its speed), ``vel_max``, or ``heel_<law>``, ``sail_<law>``, ``psi_<law>``.
        """
        p = self.per_seed
        g = p[(p["world"] == world) & (p["l_phi"] == l_phi) & (p["angle"] == angle)].sort_values("seed")
        if column not in g:
            return np.full(len(g), np.nan)
        return g[column].to_numpy(dtype=float)

    def interval(self, world: str, l_phi: float, angle: float, column: str) -> stats.Interval:
        """The mean of ``column`` over the seeds with its interval.

        Parameters
        ----------
        world, l_phi, angle, column
            As :meth:`values`.
        """
        return over.interval(self.values(world, l_phi, angle, column))

    def ratio(self, world: str, l_phi: float, angle: float, a: str, b: str) -> stats.Interval:
        """``a`` over ``b`` (speeds), paired by seed.

        Parameters
        ----------
        world, l_phi, angle
            As :meth:`values`.
        a, b : str
            Law names or ``vel_max``.
        """
        return over.paired(self.values(world, l_phi, angle, a), self.values(world, l_phi, angle, b),
                           ratio=True)

    def sailable(self, world: str, l_phi: float) -> list[float]:
        """The angles of ``world`` and ``l_phi`` outside the no-go zone.

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        """
        t = self.table
        g = t[(t["world"] == world) & (t["l_phi"] == l_phi) & ~t["no_go"]]
        return [float(x) for x in g["angle"]]

    def close(self, world: str, l_phi: float, angle: float) -> str:
        """"S close to vel_max" at one angle: S/vel_max above :data:`CLOSE`, paired by seed.

        Parameters
        ----------
        world, l_phi, angle
            As :meth:`values`.
        """
        s = self.values(world, l_phi, angle, "S")
        if not np.isfinite(s).any():
            return "breaks (S capsizes)"
        return over.decide(self.ratio(world, l_phi, angle, "S", "vel_max"), CLOSE, "above")

    def beats(self, world: str, l_phi: float, angle: float, a: str = "S", b: str = "Bm") -> str:
        """"S better than Bm" at one angle: a/b above 1 - :data:`TIE`, paired by seed; a law that
        capsizes on every seed loses to one that sails.

        Parameters
        ----------
        world, l_phi, angle
            As :meth:`values`.
        a, b : str
            The laws compared.
        """
        sa, sb = self.values(world, l_phi, angle, a), self.values(world, l_phi, angle, b)
        if np.isfinite(sa).any() and not np.isfinite(sb).any():
            return f"holds ({b} capsizes)"
        if not np.isfinite(sa).any():
            return f"breaks ({a} capsizes)"
        return over.decide(self.ratio(world, l_phi, angle, a, b), 1.0 - TIE, "above")

    def mean_gap(self, world: str, l_phi: float) -> stats.Interval:
        """Mean S/vel_max less mean Bm/vel_max over the sailable angles (Bm's where it sailed),
        seed by seed.

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        """
        angles = self.sailable(world, l_phi)
        if not angles:
            return over.interval([])
        per = {law: np.vstack([self.values(world, l_phi, a, law) / self.values(world, l_phi, a, "vel_max")
                               for a in angles]) for law in ("S", "Bm")}
        with np.errstate(invalid="ignore"):
            means = {law: np.nanmean(np.where(np.isfinite(v), v, np.nan), axis=0) for law, v in per.items()}
        return over.paired(means["S"], means["Bm"])


def _first_word(verdict: str) -> str:
    return verdict.split(" ", 1)[0]


def share(verdicts: list[str]) -> float:
    """The fraction of ``verdicts`` that hold (nan for none).

    Parameters
    ----------
    verdicts : list of str
        Per-angle verdicts.
    """
    return float(np.mean([_first_word(v) == "holds" for v in verdicts])) if verdicts else float("nan")


def overall(verdicts: list[str]) -> str:
    """One verdict for a claim made at every angle: *holds* when it holds at each, *breaks* when
    it breaks at one, else *undecided at N seeds* (the first undecided angle's text).

    Parameters
    ----------
    verdicts : list of str
        The per-angle verdicts.
    """
    if not verdicts:
        return "undecided (no sailable angle)"
    if all(_first_word(v) == "holds" for v in verdicts):
        return "holds"
    if any(_first_word(v) == "breaks" for v in verdicts):
        return "breaks"
    return next(v for v in verdicts if _first_word(v) not in ("holds", "breaks"))


def per_seed_table(curves: pd.DataFrame, grid: pd.DataFrame) -> pd.DataFrame:
    """Per (world, l_φ, angle, seed): every law's speed, heel, sail and rms heading error beside
    that seed's vel_max (the fastest candidate sail on that seed) and its heel, sail, heading error.

    Parameters
    ----------
    curves : pandas.DataFrame
        The laws' runs (:func:`~.scenario.law_runs`).
    grid : pandas.DataFrame
        The fixed-sail runs (:func:`~.scenario.tidy`).
    """
    keys = KEYS + ["seed"]
    table = curves.pivot_table(index=keys, columns="law", values="speed", dropna=False).reset_index()
    for name in ("heel", "sail_deg", "heading_error_rms"):
        more = curves.pivot_table(index=keys, columns="law", values=name, dropna=False).reset_index()
        prefix = {"heel": "heel", "sail_deg": "sail", "heading_error_rms": "psi"}[name]
        table = table.merge(more.rename(columns={c: f"{prefix}_{c}" for c in more.columns if c in LAWS}),
                            on=keys, how="left")
    best = best_of(grid, by_seed=True).rename(columns={"speed": "vel_max", "heel": "heel_vel_max",
                                                       "sail_deg": "sail_vel_max",
                                                       "heading_error_rms": "psi_vel_max"})
    table = table.merge(best, on=keys, how="left")
    with np.errstate(invalid="ignore", divide="ignore"):
        for law in LAWS:
            if law in table:
                table[f"{law}_over_vel_max"] = table[law] / table["vel_max"]
    return table


def fig7_table(per_seed: pd.DataFrame, grid: pd.DataFrame) -> pd.DataFrame:
    """Per (world, l_φ, angle): the means over the seeds of :func:`per_seed_table`'s columns,
    ``vel_max_30`` (seed 0's best fixed sail within the roll limit, the full grid) and no-go.

    Parameters
    ----------
    per_seed : pandas.DataFrame
        :func:`per_seed_table`.
    grid : pandas.DataFrame
        The fixed-sail runs (:func:`~.scenario.tidy`).
    """
    columns = [c for c in per_seed.columns if c not in KEYS + ["seed"]]
    table = per_seed.groupby(KEYS, sort=True)[columns].mean().reset_index()
    limited = best_of(grid, PHI_MAX_DEG + 1.0)[KEYS + ["speed"]].rename(columns={"speed": "vel_max_30"})
    table = table.merge(limited, on=KEYS, how="left")
    table["no_go"] = table["vel_max"] < NO_GO_FRACTION * TRUE_WIND
    return table


def summarise(a: Analysis) -> dict:
    """Per world and l_φ, over the sailable angles: the means of S/vel_max and Bm/vel_max (min,
    mean, max over the angles of the paired ratios' means), the share of angles where "S close to
    vel_max" and "S at least as fast as Bm" hold, and the verdicts.

    Parameters
    ----------
    a : Analysis
        The study's numbers (its ``numbers`` still empty).
    """
    out = {}
    for world in WORLDS:
        for l_phi in a.settings.l_phis:
            angles = a.sailable(world, l_phi)
            key = f"{world}_lphi{l_phi:g}"
            for law in ("S", "Bm"):
                ratios = np.array([a.ratio(world, l_phi, x, law, "vel_max").mean for x in angles])
                out[f"min_{law}_over_vel_max_{key}"] = float(np.nanmin(ratios)) if np.isfinite(ratios).any() \
                    else float("nan")
                out[f"mean_{law}_over_vel_max_{key}"] = float(np.nanmean(ratios)) if np.isfinite(ratios).any() \
                    else float("nan")
                if law == "S":
                    out[f"max_S_over_vel_max_{key}"] = float(np.nanmax(ratios)) if np.isfinite(ratios).any() \
                        else float("nan")
            close = [a.close(world, l_phi, x) for x in angles]
            beats = [a.beats(world, l_phi, x) for x in angles]
            out[f"share_S_within_10pc_{key}"] = share(close)
            out[f"share_S_at_least_Bm_{key}"] = share(beats)
            out[f"sailable_angles_{key}"] = len(angles)
            out[f"verdict_S_close_{key}"] = overall(close)
            out[f"verdict_S_at_least_Bm_{key}"] = overall(beats)
            gap = a.mean_gap(world, l_phi)
            out[f"mean_S_minus_Bm_over_vel_max_{key}"] = gap.mean
            out[f"verdict_mean_Bm_below_S_{key}"] = over.decide(gap, 0.0, "above")
    return out


def analyse(results: Results, smoke: bool) -> Analysis:
    """The fixed-sail runs of both passes and the laws' runs on every seed, as the Fig. 7 tables.

    Parameters
    ----------
    results : sailmujoco.study.Results
        Both passes' results (``results.seeds``: the seeds).
    smoke : bool
        The short pass.
    """
    grid = pd.concat([tidy(results.sweeps[f"sweep-velmax-{w}/{step}"], w) for w in WORLDS
                      for step in ("coarse", "finer", "best") if f"sweep-velmax-{w}/{step}" in results.sweeps],
                     ignore_index=True)
    curves = law_runs(results.jobs[JOBS])
    per_seed = per_seed_table(curves, grid)
    run = settings(smoke)
    a = Analysis(run, tuple(int(s) for s in results.seeds), grid, per_seed, fig7_table(per_seed, grid), {},
                 int(len(grid) + len(curves)), results.seconds)
    a.numbers.update(summarise(a))
    return a


def headline(analysis: Analysis) -> dict:
    """The headline numbers (means over seeds, the verdicts), the simulations run and their wall time.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {**analysis.numbers, "runs": analysis.runs, "wall_s": analysis.wall_s}
