"""The numbers of the Fig. 7 study: per angle, the steady speeds of S, Bm, the checks and
vel_max, their ratios, and the no-go zone."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from sailmujoco.study import Results

from ..kit.saoud import PHI_MAX_DEG, TRUE_WIND, WORLDS
from .scenario import JOBS, LAWS, Settings, best_of, law_runs, settings, tidy

NO_GO_FRACTION = 0.15  # vel_max below this fraction of the true wind: the boat does not sail there
TIE = 0.01  # S counts as at least as fast as Bm when S >= (1 - TIE) Bm
HELD_DEG = 20.0  # deg, rms heading error above which the vel_max run did not hold heading 0


@dataclass(frozen=True)
class Analysis:
    """What the runs gave.

    Parameters
    ----------
    settings : Settings
        The grid and durations run.
    grid : pandas.DataFrame
        Every fixed-sail run of both worlds (coarse, then finer, per world).
    table : pandas.DataFrame
        Per (world, l_φ, angle): the speeds of every law, vel_max, their ratios, heel, sail,
        rms heading error, and whether the angle is in the no-go zone.
    numbers : dict
        The headline numbers (:func:`summarise`).
    runs : int
        Simulations run.
    wall_s : float
        Wall time of the simulations [s].
    """

    settings: Settings
    grid: pd.DataFrame
    table: pd.DataFrame
    numbers: dict
    runs: int
    wall_s: float


def fig7_table(curves: pd.DataFrame, grid: pd.DataFrame) -> pd.DataFrame:
    """Per (world, l_φ, angle): the laws' steady speeds, heel, sail and heading error beside the
    best fixed sail (``vel_max``, and ``vel_max_30`` within the roll limit), their ratios, no-go.

    Parameters
    ----------
    curves : pandas.DataFrame
        The laws' runs (:func:`~.scenario.law_runs`).
    grid : pandas.DataFrame
        The fixed-sail runs (:func:`~.scenario.tidy`).
    """
    table = curves.pivot_table(index=["world", "l_phi", "angle"], columns="law", values="speed",
                               dropna=False).reset_index()
    best = best_of(grid).rename(columns={"speed": "vel_max", "heel": "heel_vel_max",
                                         "sail_deg": "sail_vel_max", "heading_error_rms": "psi_rms_vel_max"})
    limited = best_of(grid, PHI_MAX_DEG + 1.0)[["world", "l_phi", "angle", "speed"]].rename(
        columns={"speed": "vel_max_30"})
    table = table.merge(best, on=["world", "l_phi", "angle"], how="left")
    table = table.merge(limited, on=["world", "l_phi", "angle"], how="left")
    heel = curves.pivot_table(index=["world", "l_phi", "angle"], columns="law", values="heel",
                              dropna=False).reset_index()
    heel = heel.rename(columns={c: f"heel_{c}" for c in heel.columns if c in LAWS})
    table = table.merge(heel, on=["world", "l_phi", "angle"], how="left")
    sail = curves.pivot_table(index=["world", "l_phi", "angle"], columns="law", values="sail_deg",
                              dropna=False).reset_index()
    sail = sail.rename(columns={c: f"sail_{c}" for c in sail.columns if c in LAWS})
    table = table.merge(sail, on=["world", "l_phi", "angle"], how="left")
    psi = curves.pivot_table(index=["world", "l_phi", "angle"], columns="law", values="heading_error_rms",
                             dropna=False).reset_index()
    psi = psi.rename(columns={c: f"psi_{c}" for c in psi.columns if c in LAWS})
    table = table.merge(psi, on=["world", "l_phi", "angle"], how="left")
    for law in LAWS:
        if law in table:
            table[f"{law}_over_vel_max"] = table[law] / table["vel_max"]
    table["no_go"] = table["vel_max"] < NO_GO_FRACTION * TRUE_WIND
    return table


def summarise(table: pd.DataFrame, l_phis) -> dict:
    """Per world and l_φ, over the sailable angles: S/vel_max and Bm/vel_max (min, mean, max),
    the share of angles where S is within 10 % of vel_max and at least as fast as Bm.

    Parameters
    ----------
    table : pandas.DataFrame
        :func:`fig7_table`.
    l_phis : sequence of float
        The metacentric heights run [m].
    """
    out = {}
    for world in WORLDS:
        for l_phi in l_phis:
            g = table[(table["world"] == world) & (table["l_phi"] == l_phi) & ~table["no_go"]]
            key = f"{world}_lphi{l_phi:g}"
            for law in ("S", "Bm"):
                ratio = g[f"{law}_over_vel_max"]
                out[f"min_{law}_over_vel_max_{key}"] = float(ratio.min())
                out[f"mean_{law}_over_vel_max_{key}"] = float(ratio.mean())
            out[f"max_S_over_vel_max_{key}"] = float(g["S_over_vel_max"].max())
            out[f"share_S_within_10pc_{key}"] = float(np.mean(g["S_over_vel_max"] >= 0.9)) if len(g) else \
                float("nan")
            out[f"share_S_at_least_Bm_{key}"] = float(np.mean(g["S"] >= (1.0 - TIE) * g["Bm"])) \
                if len(g) else float("nan")
            out[f"sailable_angles_{key}"] = int(len(g))
    return out



def analyse(results: Results, smoke: bool) -> Analysis:
    """The fixed-sail grid of both passes and the laws' runs, as the Fig. 7 table.

    Parameters
    ----------
    results : sailmujoco.study.Results
        Both passes' results.
    smoke : bool
        The short pass.
    """
    grid = pd.concat([tidy(results.sweeps[f"sweep-velmax-{w}/{step}"], w) for w in WORLDS
                      for step in ("coarse", "finer") if f"sweep-velmax-{w}/{step}" in results.sweeps],
                     ignore_index=True)
    curves = law_runs(results.jobs[JOBS])
    table = fig7_table(curves, grid)
    run = settings(smoke)
    return Analysis(run, grid, table, summarise(table, run.l_phis), int(len(grid) + len(curves)),
                    results.seconds)


def headline(analysis: Analysis) -> dict:
    """The headline numbers, the simulations run and their wall time.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {**analysis.numbers, "runs": analysis.runs, "wall_s": analysis.wall_s}
