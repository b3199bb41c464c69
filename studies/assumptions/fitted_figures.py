"""Assumption validation, the fitted arms' files: every run and every change as CSV, and the
changes as one figure.

:func:`write` writes the study's other files first (:func:`.sea_figures.write`), then
``FITTED_FILES`` and ``FITTED_FIGURE``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..kit import save_figure, setup_matplotlib
from ..kit.verdict import TOLERANCE
from .fitted import SCENARIOS
from .fitted_analysis import ARM_WORDS, FittedAnalysis
from .sea_figures import write as write_sea

FITTED_FILES = {"runs": "fitted_runs.csv", "effects": "fitted_changes.csv"}
FITTED_FIGURE = "fitted_changes.png"
ARM_STYLE = {"sensors": {"color": "C0", "marker": "o"}, "actuators": {"color": "C3", "marker": "s"}}


def write(analysis, out: Path) -> None:
    """The study's other files and figures, then the fitted arms' (where they ran).

    Parameters
    ----------
    analysis : studies.assumptions.analysis.Analysis
        The study's numbers (``analysis.fitted``: the fitted arms').
    out : pathlib.Path
        The study's folder.
    """
    write_sea(analysis, out)
    if analysis.fitted is None:
        return
    out, f = Path(out), analysis.fitted
    f.runs.to_csv(out / FITTED_FILES["runs"], index=False)
    f.effects.to_csv(out / FITTED_FILES["effects"], index=False)
    _figure(f, out / FITTED_FIGURE)


def _figure(f: FittedAnalysis, path: Path) -> Path:
    """Each scenario's change in each arm, in per cent, with its interval and the ±10 % band."""
    plt = setup_matplotlib()
    names = list(SCENARIOS)
    fig, ax = plt.subplots(figsize=(8.0, 1.0 + 0.8 * len(names)))
    y = np.arange(len(names), dtype=float)
    ax.axvspan(-100 * TOLERANCE, 100 * TOLERANCE, color="0.9", label=f"±{100 * TOLERANCE:g} %: holds")
    ax.axvline(0.0, color="0.5", linewidth=0.8)
    for offset, arm in ((-0.15, "sensors"), (0.15, "actuators")):
        changes = [f.change(name, arm).scaled(100) for name in names]
        mean = np.array([c.mean for c in changes])
        low = np.array([c.low if c.decided else c.mean for c in changes])
        high = np.array([c.high if c.decided else c.mean for c in changes])
        ax.errorbar(mean, y + offset, xerr=np.vstack([mean - low, high - mean]), linestyle="none",
                    capsize=3, label=ARM_WORDS[arm], **ARM_STYLE[arm])
    ax.set_yticks(y, [f"{name}\n({SCENARIOS[name]['metric'].replace('_', ' ')})" for name in names])
    ax.invert_yaxis()
    ax.set_xlabel("change against perfect sensors and actuators, paired by seed [%]")
    ax.set_title(f"Sensors and actuators as fitted (mean and 95 % interval, N = {len(f.seeds)})")
    ax.legend(loc="best", fontsize="small")
    ax.grid(axis="x", alpha=0.3)
    return save_figure(fig, path)


__all__ = ["FITTED_FIGURE", "FITTED_FILES", "write"]
