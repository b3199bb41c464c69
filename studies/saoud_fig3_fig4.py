"""Saoud et al. (2015) Figs. 3-4: optimal roll, sail and attack angles against Theta_V.

Fig. 3: problem (5) for c1 (|V| = 5, l_phi = 1), c2 (8, 1), c3 (5, 0.1), c4 (8, 0.1), m/s and m.
Fig. 4: problem (14), |V| = 5, l_phi = 0.1, phi_max = 45, 20, 10 deg.

These figures are calculations on the paper's reduced model (Table I numbers, its C_N
polynomial), so there is one world here; what the 6-DOF boat makes of the optimum (its steady
heel against phi*) is measured in the assumptions study. The paper prints no numbers for these
figures: the report checks its stated properties (Remark 1; near-linear delta* at low wind;
saturation at high wind; alpha* not constant; the roll limit acting upwind) with ours.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd
from sailmujoco.controllers.saoud import SaoudParams, optimal_sail

from sailmujoco.figures import legend_below
from sailmujoco.study import Results, Runs, Study

from .kit import Report, save_figure, setup_matplotlib, verdict

NAME = "saoud_fig3_fig4"
TITLE = "Saoud (2015) Figs. 3-4: optimal sail, roll and attack angles vs apparent wind angle"
# the paper's cases of Fig. 3: |V| [m/s], l_φ [m]; the roll limits φ_max of Fig. 4 [deg], at
# |V| = 5 m/s, l_φ = 0.1 m; Remark 1's bound on |φ*| without a limit [deg]
PAPER_CASES = {"c1": (5.0, 1.0), "c2": (8.0, 1.0), "c3": (5.0, 0.1), "c4": (8.0, 0.1)}
PAPER_LIMITS_DEG = (45.0, 20.0, 10.0)
PAPER_FIG4_CASE = (5.0, 0.1)
PAPER_REMARK1_MAX_PHI_DEG = 45.0
# `--video` films the optimal sail at work on the robot (the figures themselves are static)
VIDEO = {"boat": "saoud_robot", "task": "speed_trial", "controller": "saoud", "seconds": 60.0}


def curves(step_deg: float) -> pd.DataFrame:
    """φ*, δs* and α* [deg] against Θ_V for the cases of Fig. 3 and the limits of Fig. 4.

    Parameters
    ----------
    step_deg : float
        The step of Θ_V over [-180°, 180°].
    """
    rows = []
    theta = np.arange(-180.0, 180.0 + 1e-9, step_deg)
    params = SaoudParams()
    for case, (speed, l_phi) in PAPER_CASES.items():
        for t in theta:
            o = optimal_sail(math.radians(t), speed, l_phi, None, params)
            rows.append(dict(figure=3, case=case, theta_v=t, delta=math.degrees(o.delta),
                             phi=math.degrees(o.phi), alpha=math.degrees(o.alpha)))
    speed, l_phi = PAPER_FIG4_CASE
    for limit in PAPER_LIMITS_DEG:
        for t in theta:
            o = optimal_sail(math.radians(t), speed, l_phi, math.radians(limit), params)
            rows.append(dict(figure=4, case=f"phi_max {limit:g}", theta_v=t,
                             delta=math.degrees(o.delta), phi=math.degrees(o.phi),
                             alpha=math.degrees(o.alpha)))
    return pd.DataFrame(rows)


LIMIT_TOLERANCE_DEG = 0.5  # |φ*| within this of φ_max: the limit binds


def _bound(value: float, limit: float) -> str:
    state = verdict.limit_state(value, limit, LIMIT_TOLERANCE_DEG)
    if state == "binds":
        return f"the limit binds (reached within {LIMIT_TOLERANCE_DEG:g}°)"
    if state == "does not bind":
        return f"within the bound; the limit does not bind ({limit - abs(value):.1f}° below it)"
    return f"bound violated (by {abs(value) - limit:.1f}°)" if state == "exceeded" else state


def runs(smoke: bool) -> Runs:
    """No simulation: the curves are solved in :func:`analyse`.

    Parameters
    ----------
    smoke : bool
        The short pass.
    """
    return Runs()


@dataclass(frozen=True)
class Analysis:
    """The optimal angles and the properties the paper states, measured.

    Parameters
    ----------
    data : pandas.DataFrame
        :func:`curves`: φ*, δs*, α* [deg] against Θ_V, both figures.
    max_phi : float
        Largest |φ*| over Θ_V and c1-c4 [deg].
    linear_miss : float
        c1: largest miss of a straight δ*(Θ_V), Θ_V in [-90°, -10°] [deg].
    saturates_c3, saturates_c4 : float
        |Θ_V| where |δ*| first reaches 75° for c3 and c4 [deg].
    alpha_span : float
        c3: span of |α*| over Θ_V in [30°, 150°] [deg].
    limited : dict of float to float
        Largest |φ*| for each roll limit of Fig. 4 [deg].
    """

    data: pd.DataFrame
    max_phi: float
    linear_miss: float
    saturates_c3: float
    saturates_c4: float
    alpha_span: float
    limited: dict


def _first_reach(fig3: pd.DataFrame, case: str, level: float = 75.0) -> float:
    g = fig3[(fig3["case"] == case) & (fig3["theta_v"] < 0)].sort_values("theta_v", ascending=False)
    hit = g[g["delta"].abs() >= level]
    return float(-hit["theta_v"].iloc[0]) if len(hit) else float("nan")


def analyse(results: Results, smoke: bool) -> Analysis:
    """Solve the curves and measure the properties the paper states about them.

    Parameters
    ----------
    results : sailmujoco.study.Results
        Empty (the study simulates nothing).
    smoke : bool
        The short pass: Θ_V by 10° instead of 1°.
    """
    data = curves(10.0 if smoke else 1.0)
    fig3, fig4 = data[data["figure"] == 3], data[data["figure"] == 4]
    c1 = fig3[(fig3["case"] == "c1") & (fig3["theta_v"].between(-90, -10))]
    slope, intercept = np.polyfit(c1["theta_v"], c1["delta"], 1)
    c3 = fig3[(fig3["case"] == "c3") & fig3["theta_v"].between(-150, -30)]
    return Analysis(
        data=data, max_phi=float(fig3["phi"].abs().max()),
        linear_miss=float(np.max(np.abs(c1["delta"] - (slope * c1["theta_v"] + intercept)))),
        saturates_c3=_first_reach(fig3, "c3"), saturates_c4=_first_reach(fig3, "c4"),
        alpha_span=float(c3["alpha"].abs().max() - c3["alpha"].abs().min()),
        limited={lim: float(fig4[fig4["case"] == f"phi_max {lim:g}"]["phi"].abs().max())
                 for lim in PAPER_LIMITS_DEG})


def headline(analysis: Analysis) -> dict:
    """The measured properties (degrees).

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    """
    return {"max_abs_phi_deg": analysis.max_phi, "c1_linear_miss_deg": analysis.linear_miss,
            "c3_saturates_at_deg": analysis.saturates_c3, "c4_saturates_at_deg": analysis.saturates_c4,
            "alpha_span_c3_deg": analysis.alpha_span,
            **{f"max_phi_limit_{lim:g}": v for lim, v in analysis.limited.items()}}


def _panels(axes, titles) -> None:
    for ax, title in zip(axes, titles, strict=True):
        ax.set_xlabel("apparent wind angle Θ_V [deg]")
        ax.set_ylabel(title.split(" ", 1)[1] + " [deg]")
        ax.set_title(title)
        ax.set_xlim(-180, 180)


def write(analysis: Analysis, out: Path) -> None:
    """``optimal_angles.csv``, ``fig3.png`` and ``fig4.png``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out, data = Path(out), analysis.data
    data.to_csv(out / "optimal_angles.csv", index=False)
    plt = setup_matplotlib()
    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    for case, group in data[data["figure"] == 3].groupby("case"):
        speed, l_phi = PAPER_CASES[case]
        label = f"{case}: |V| = {speed:g} m/s, l_φ = {l_phi:g} m"
        for ax, col in zip(axes, ("phi", "delta", "alpha"), strict=True):
            ax.plot(group["theta_v"], group[col], label=label)
    _panels(axes, ("(a) optimal roll φ*", "(b) optimal sail δs*", "(c) attack α*"))
    legend_below(fig, axes[0], ncol=4)
    fig.suptitle("Saoud Fig. 3 (reproduced): problem (5), no roll limit")
    save_figure(fig, out / "fig3.png")

    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for case, group in data[data["figure"] == 4].groupby("case", sort=False):
        axes[0].plot(group["theta_v"], group["phi"], label=case + "°")
        axes[1].plot(group["theta_v"], group["delta"], label=case + "°")
    _panels(axes, ("(a) optimal roll φ*", "(b) optimal sail δs*"))
    speed, l_phi = PAPER_FIG4_CASE
    legend_below(fig, axes[0], ncol=3, title=f"roll limit, at |V| = {speed:g} m/s, l_φ = {l_phi:g} m")
    fig.suptitle("Saoud Fig. 4 (reproduced): problem (14), roll limited")
    save_figure(fig, out / "fig4.png")


METHOD = ("**Method.** N = 1 (seed 0): the curves are the solutions of Saoud's optimisation problems on "
          "the paper's reduced model, a static computation in which nothing is stochastic (no wind, sea "
          "or start is drawn), so every number is exact for the model and carries no interval; each "
          "property is checked on these numbers directly.")


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of ``report.md``: the paper's stated properties against ours.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass.
    """
    a = analysis
    remark1 = PAPER_REMARK1_MAX_PHI_DEG
    text = Report(TITLE)
    text.summary(_summary(a))
    text.comparison([
        {"quantity": "max |φ*| over Θ_V and c1-c4 (deg)", "world": "reduced model",
         "paper": f"≤ {remark1:g} (Remark 1)", "ours": a.max_phi,
         "cause": ("bound holds" if verdict.limit_state(a.max_phi, remark1, LIMIT_TOLERANCE_DEG) != "exceeded"
                   else "bound violated") + f" (|φ*| ≤ {a.max_phi:.1f}°)"},
        {"quantity": "c1: largest miss of a straight δ*(Θ_V), Θ_V in [-90°, -10°] (deg)",
         "world": "reduced model", "paper": None, "ours": a.linear_miss,
         "cause": "paper: 'approximated by a linear function' at low wind"},
        {"quantity": "|Θ_V| where |δ*| first reaches 75°: c3 / c4 (deg)", "world": "reduced model",
         "paper": None, "ours": f"{a.saturates_c3:.0f} / {a.saturates_c4:.0f}",
         "cause": ("saturates earlier at high wind, as the paper says" if a.saturates_c4 < a.saturates_c3
                   else "does not saturate earlier at high wind (the paper says it does)")},
        {"quantity": "c3: span of |α*| over Θ_V in [30°, 150°] (deg)", "world": "reduced model",
         "paper": None, "ours": a.alpha_span, "cause": "α* not constant (paper §VII-A)"},
        *[{"quantity": f"max |φ*| with φ_max = {lim:g}° (deg)", "world": "reduced model",
           "paper": f"≤ {lim:g}", "ours": v, "cause": _bound(v, lim)}
          for lim, v in a.limited.items()],
    ])
    text.section("Method", METHOD)
    text.section("Scenario", __doc__.split("\n\n", 1)[1])
    text.section("Figures")
    text.figure("fig3.png", "Fig. 3: optimal φ*, δs*, α* against Θ_V, cases c1-c4")
    text.figure("fig4.png", "Fig. 4: with the roll limit φ_max = "
                f"{', '.join(f'{lim:g}' for lim in PAPER_LIMITS_DEG)}°")
    return text.text()


def _summary(a: Analysis) -> str:
    """The properties the paper states for Figs. 3-4, each as this run measures it."""
    remark1 = PAPER_REMARK1_MAX_PHI_DEG
    within = verdict.limit_state(a.max_phi, remark1, LIMIT_TOLERANCE_DEG) != "exceeded"
    binds = [lim for lim, v in a.limited.items()
             if verdict.limit_state(v, lim, LIMIT_TOLERANCE_DEG) == "binds"]
    free = [lim for lim in a.limited if lim not in binds]
    limits = (f"the roll limit binds at φ_max = {' and '.join(f'{lim:g}°' for lim in binds) or 'none'}"
              + (f", not at {' or '.join(f'{lim:g}°' for lim in free)}" if free else ""))
    (fast, _), (slow, _) = PAPER_CASES["c4"], PAPER_CASES["c3"]
    return (
        "The optimal sail of Saoud's problems (5) and (14), solved on the paper's reduced model, "
        "against what the paper says of Figs. 3-4 (it prints no numbers for them). "
        f"|φ*| {'stays within' if within else 'exceeds'} Remark 1's {remark1:g}° "
        f"(at most {a.max_phi:.1f}°); at low wind δ* is close to a straight line in Θ_V (largest "
        f"miss {a.linear_miss:.2f}°); δ* reaches 75° at |Θ_V| = {a.saturates_c4:.0f}° at {fast:g} m/s "
        f"and {a.saturates_c3:.0f}° at {slow:g} m/s ("
        + ("earlier at high wind, as the paper says" if a.saturates_c4 < a.saturates_c3
           else "not earlier at high wind, against the paper")
        + f"); α* is not constant (span {a.alpha_span:.1f}°); {limits}.")


STUDY = Study(name=NAME, title=TITLE, runs=runs, analyse=analyse, write=write, report=report,
              headline=headline, video=VIDEO, seeds=1)  # static: nothing stochastic to run on seeds
