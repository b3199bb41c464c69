"""The numbers of the Fig. 6 study: the segment means of every trial on every seed, and the
S/Bm ratios, paired by seed, with their intervals and the paper's claims decided on them."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco import stats
from sailmujoco.study import Results

from ..kit import seeds as over
from ..kit.saoud import WORLDS
from ..kit.verdict import TOLERANCE
from .scenario import ANGLES_DEG, JOBS, SEGMENTS, Case, cases, jobs, l_phis_for

WINDOW = 10.0  # s, the end of each segment over which the means are taken
HELD_DEG = 20.0  # deg, a segment whose mean |heading| exceeds this did not hold heading 0
SERIES_COLUMNS = list(Case._fields) + ["seed", "t", "speed", "u", "heel_deg", "heading_deg", "sail_deg",
                                       "rudder_deg", "awa_deg"]
# the paper's sentence, segment by segment, as a claim on S/Bm: (sense, bound, band, words).
# "perform equally" downwind: S/Bm within the project's tolerance of 1; "gain" beam reach and
# upwind: S/Bm above 1.
CLAIMS = {10.0: ("within", 1.0, TOLERANCE, "equal downwind"),
          45.0: ("above", 1.0, None, "S gains beam reach"),
          80.0: ("above", 1.0, None, "S gains upwind")}
MORE_UPWIND = "the gain larger upwind than beam reach"  # S/Bm(80°) - S/Bm(45°) above 0
NOT_COMPARABLE = "not comparable"


@dataclass(frozen=True)
class Analysis:
    """What the trials gave.

    Parameters
    ----------
    l_phis : tuple of float
        The metacentric heights of the main runs [m].
    checks : list of Case
        The check runs (one switch each).
    seeds : tuple of int
        The seeds every trial ran on.
    rows : pandas.DataFrame
        One row per trial and seed: the case's fields, ``seed`` and :func:`segment_stats`.
    series : pandas.DataFrame
        Every run's time series (10 Hz), its case's fields and seed in the first columns.
    numbers : dict
        The headline numbers (means over seeds, the verdicts, heading held, checks' speeds).
    wall_s : float
        Wall time of the simulations [s].
    """

    l_phis: tuple
    checks: list
    seeds: tuple
    rows: pd.DataFrame
    series: pd.DataFrame
    numbers: dict
    wall_s: float

    def values(self, case: Case, name: str) -> np.ndarray:
        """One :func:`segment_stats` entry of ``case`` per seed, in seed order.

        Parameters
        ----------
        case : Case
            The trial.
        name : str
            The entry, e.g. ``"speed_45"``.
        """
        g = self.rows[(self.rows[list(Case._fields)] == pd.Series(case._asdict())).all(axis=1)]
        return g.sort_values("seed")[name].to_numpy(dtype=float)

    def interval(self, case: Case, name: str) -> stats.Interval:
        """The mean of one entry over the seeds with its 95 % interval.

        Parameters
        ----------
        case : Case
            The trial.
        name : str
            The entry, e.g. ``"speed_45"``.
        """
        return over.interval(self.values(case, name))

    def held(self, case: Case, angle: float) -> int:
        """The seeds on which ``case`` held heading 0 in the segment at ``angle``.

        Parameters
        ----------
        case : Case
            The trial.
        angle : float
            The segment's ∠v_w^B [deg].
        """
        return int(np.sum(self.values(case, f"held_{angle:g}") > 0.5))

    def ratios(self, world: str, l_phi: float, angle: float, **switch) -> np.ndarray:
        """S/Bm of the segment mean speeds, seed by seed.

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        angle : float
            The segment's ∠v_w^B [deg].
        **switch
            The switches of a check (:class:`~.scenario.Case` fields).
        """
        s = self.values(Case(world, l_phi, "S", **switch), f"speed_{angle:g}")
        b = self.values(Case(world, l_phi, "Bm", **switch), f"speed_{angle:g}")
        with np.errstate(invalid="ignore", divide="ignore"):
            return s / b

    def ratio(self, world: str, l_phi: float, angle: float, **switch) -> stats.Interval:
        """S/Bm of the segment mean speeds, paired by seed: the mean per-seed ratio and its interval.

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        angle : float
            The segment's ∠v_w^B [deg].
        **switch
            The switches of a check (:class:`~.scenario.Case` fields).
        """
        s = self.values(Case(world, l_phi, "S", **switch), f"speed_{angle:g}")
        b = self.values(Case(world, l_phi, "Bm", **switch), f"speed_{angle:g}")
        return over.paired(s, b, ratio=True)

    def comparable(self, world: str, l_phi: float, angle: float) -> bool:
        """Whether S and Bm both held heading 0 in the segment on every seed.

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        angle : float
            The segment's ∠v_w^B [deg].
        """
        n = len(self.seeds)
        return all(self.held(Case(world, l_phi, law), angle) == n for law in ("S", "Bm"))

    def verdict(self, world: str, l_phi: float, angle: float) -> str:
        """The paper's claim for the segment (:data:`CLAIMS`) decided on the paired S/Bm interval;
        :data:`NOT_COMPARABLE` where a law lost heading 0 on some seed.

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        angle : float
            The segment's ∠v_w^B [deg].
        """
        if not self.comparable(world, l_phi, angle):
            return NOT_COMPARABLE
        sense, bound, band, _ = CLAIMS[angle]
        return over.decide(self.ratio(world, l_phi, angle), bound, sense, band)

    def more_upwind(self, world: str, l_phi: float) -> stats.Interval:
        """S/Bm at 80° less S/Bm at 45°, seed by seed ("even more when sailing upwind").

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        """
        return over.paired(self.ratios(world, l_phi, 80.0), self.ratios(world, l_phi, 45.0))

    def more_upwind_verdict(self, world: str, l_phi: float) -> str:
        """:data:`MORE_UPWIND` decided on :meth:`more_upwind` (above 0).

        Parameters
        ----------
        world : str
            The world.
        l_phi : float
            The metacentric height [m].
        """
        if not all(self.comparable(world, l_phi, a) for a in (45.0, 80.0)):
            return NOT_COMPARABLE
        return over.decide(self.more_upwind(world, l_phi), 0.0, "above")


def segment_stats(series: pd.DataFrame) -> dict:
    """Means over the last ``WINDOW`` s of each segment (nan where the run stopped before).

    Parameters
    ----------
    series : pandas.DataFrame
        One trial's time series (:func:`~.scenario.episode`).
    """
    out = {"stopped": series.attrs.get("stopped"), "end": float(series["t"].iloc[-1])}
    for _, angle, end in SEGMENTS:
        w = series[(series["t"] >= end - WINDOW - 1e-9) & (series["t"] <= end + 1e-9)]
        finished = out["end"] >= end - 1e-6
        for name, column in (("speed", "speed"), ("heel", "heel_deg"), ("heading", "heading_deg")):
            out[f"{name}_{angle:g}"] = float(w[column].mean()) if finished else float("nan")
        out[f"rudder_{angle:g}"] = float(w["rudder_deg"].abs().mean()) if finished else float("nan")
        out[f"max_heading_{angle:g}"] = float(series[(series["t"] <= end)]["heading_deg"].abs().max())
        out[f"held_{angle:g}"] = bool(finished and abs(out[f"heading_{angle:g}"]) <= HELD_DEG)
    return out


def variant(case: Case) -> str:
    """The switches of a case that differ from the main runs, as 'name=value' joined by ','.

    Parameters
    ----------
    case : Case
        A run.
    """
    base = Case(case.world, case.l_phi, case.law)
    diff = [f"{f}={getattr(case, f)}" for f in Case._fields[3:] if getattr(case, f) != getattr(base, f)]
    return ",".join(diff) or "as run"


def _numbers(a: Analysis) -> dict:
    numbers, n = {}, len(a.seeds)
    for world in WORLDS:
        for l_phi in a.l_phis:
            s, b = Case(world, l_phi, "S"), Case(world, l_phi, "Bm")
            for angle in ANGLES_DEG:
                key = f"{world}_lphi{l_phi:g}_{angle:g}"
                numbers[f"speed_S_{key}"] = a.interval(s, f"speed_{angle:g}").mean
                numbers[f"speed_Bm_{key}"] = a.interval(b, f"speed_{angle:g}").mean
                numbers[f"ratio_{key}"] = a.ratio(world, l_phi, angle).mean
                numbers[f"held_{key}"] = a.comparable(world, l_phi, angle)
                numbers[f"verdict_{key}"] = a.verdict(world, l_phi, angle)
            key = f"{world}_lphi{l_phi:g}"
            numbers[f"more_upwind_{key}"] = a.more_upwind(world, l_phi).mean
            numbers[f"verdict_more_upwind_{key}"] = a.more_upwind_verdict(world, l_phi)
    for case in a.checks:
        tag = f"{case.world}_{variant(case)}_{case.law}"
        for angle in ANGLES_DEG:
            numbers[f"check_{tag}_{angle:g}"] = a.interval(case, f"speed_{angle:g}").mean
            numbers[f"check_held_{tag}_{angle:g}"] = a.held(case, angle) == n
    return numbers


def analyse(results: Results, smoke: bool) -> Analysis:
    """The segment means of every trial on every seed and the headline numbers.

    Parameters
    ----------
    results : sailmujoco.study.Results
        The trials' results (the job list of :func:`~.scenario.runs`); ``results.seeds`` the seeds.
    smoke : bool
        The short pass.
    """
    l_phis = l_phis_for(smoke)
    seeds = tuple(int(s) for s in results.seeds)
    _, checks = cases(l_phis)
    rows, frames = [], []
    for (case, seed), result in zip(jobs(smoke, seeds), results.jobs[JOBS], strict=True):
        series = result["series"]
        series.attrs["stopped"] = result["stopped"]
        rows.append({**case._asdict(), "seed": seed, **segment_stats(series)})
        frames.append(series.assign(**case._asdict(), seed=seed))
    series = pd.concat(frames, ignore_index=True)[SERIES_COLUMNS]
    a = Analysis(l_phis, checks, seeds, pd.DataFrame(rows), series, {}, results.seconds)
    a.numbers.update(_numbers(a))
    return a


def headline(analysis: Analysis) -> dict:
    """The headline numbers (means over seeds, the verdicts), and the simulations' wall time.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {**analysis.numbers, "wall_s": analysis.wall_s}
