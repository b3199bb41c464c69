"""The Fig. 7 study's figure and data files."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sailmujoco.figures import legend_below

from ..kit import save_figure, setup_matplotlib
from ..kit.saoud import PHI_MAX_DEG, TRUE_WIND, WORLDS
from ..kit.seeds import errorbar
from .analysis import HELD_DEG, Analysis

STYLE = {"S": dict(color="tab:blue", marker="o", label=f"S: optimal sail, $\\phi_{{max}}$ = {PHI_MAX_DEG:g}°"),
         "Bm": dict(color="tab:red", marker="s", label="Bm: Briere trimming (Fig. 5)"),
         "vel_max": dict(color="k", ls="--", marker=".", label="vel_max: best fixed sail")}
GRID_COLUMNS = ["world", "l_phi", "angle", "sail_deg", "seed", "status", "speed", "heel", "heading_error_rms"]


def write(analysis: Analysis, out: Path) -> None:
    """``fig7.csv`` (per angle, the means over the seeds), ``fig7_seeds.csv`` (per angle and seed),
    ``vel_max_grid.csv`` (every fixed-sail run) and ``fig7.png``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    analysis.table.to_csv(out / "fig7.csv", index=False)
    analysis.per_seed.to_csv(out / "fig7_seeds.csv", index=False)
    analysis.grid[GRID_COLUMNS].sort_values(["world", "l_phi", "angle", "sail_deg", "seed"]).to_csv(
        out / "vel_max_grid.csv", index=False)
    plot(analysis, out / "fig7.png")


def plot(analysis: Analysis, path: Path) -> None:
    """Fig. 7: steady speed of S, Bm and vel_max against ∠v_w^B, per world and l_φ: the mean over
    the seeds with its 95 % interval.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    path : pathlib.Path
        The PNG written.
    """
    table, l_phis = analysis.table, analysis.settings.l_phis
    plt = setup_matplotlib()
    fig, axes = plt.subplots(len(l_phis), len(WORLDS), figsize=(5.5 * len(WORLDS), 3.8 * len(l_phis)),
                             squeeze=False, sharex=True)
    titles = {"paper": "paper world (4-DOF reduced model)", "mujoco": "MuJoCo 6-DOF"}
    for row, l_phi in enumerate(l_phis):
        for col, world in enumerate(WORLDS):
            ax = axes[row, col]
            g = table[(table["world"] == world) & (table["l_phi"] == l_phi)].sort_values("angle")
            for name in ("vel_max", "S", "Bm"):
                errorbar(ax, g["angle"], [analysis.interval(world, l_phi, a, name) for a in g["angle"]],
                         ms=4, **STYLE[name])
            for law in ("S", "Bm"):
                if f"{law}_eq4" in g and g[f"{law}_eq4"].notna().any():
                    ax.plot(g["angle"], g[f"{law}_eq4"], ls=":", color=STYLE[law]["color"], lw=1.2,
                            label=f"{law}, check: eq. 4 righting moment")
            off = g[(np.degrees(g["psi_S"]) > HELD_DEG) & ~g["no_go"]]
            if len(off):
                ax.plot(off["angle"], off["S"], "o", mfc="white", color=STYLE["S"]["color"], ms=7,
                        label="S off heading 0 (rounds up)")
            for law in ("S", "Bm"):
                lost = g[~np.isfinite(g[law]) & ~g["no_go"]]
                if len(lost):
                    ax.plot(lost["angle"], np.zeros(len(lost)), "x", color=STYLE[law]["color"], ms=8,
                            label=f"{law} capsizes")
            for a in g.loc[g["no_go"], "angle"]:
                ax.axvspan(max(a - 7.5, 0.0), min(a + 7.5, 180.0), color="0.88", zorder=0, lw=0)
            if g["no_go"].any():
                ax.text(g.loc[g["no_go"], "angle"].min() - 7.5, 0.97, "no-go ", ha="right", va="top",
                        fontsize=8, color="0.3", transform=ax.get_xaxis_transform())
            ax.set_title(f"{titles[world]}, $l_\\phi$ = {l_phi:g} m", fontsize=10)
            ax.set_xlim(0, 180)
            ax.set_xticks(range(0, 181, 30))
            ax.set_ylim(0, None)
            if row == len(l_phis) - 1:
                ax.set_xlabel("$\\angle v_w^B$: true wind direction (blowing to) relative to heading "
                              "[deg]\n0 = dead run, 180 = head to wind")
            ax.set_ylabel("maximum velocity [m/s]")
    legend_below(fig, axes, ncol=3)
    fig.suptitle(f"Saoud Fig. 7 (reproduced): steady speed at |v_w| = {TRUE_WIND:g} m/s (at the sail); "
                 f"mean of N = {len(analysis.seeds)} seeds, bars: its 95 % interval")
    save_figure(fig, path)

