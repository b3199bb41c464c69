"""The real-boats report, its CSV data and its figures."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sailmujoco import figures
from sailmujoco.design.reference_compare import plot_reference

from ..kit import Report
from . import scenario
from .analysis import BAND, Analysis, within
from .scenario import CASES, CAUSES, TITLE


def write(analysis: Analysis, out: Path) -> None:
    """``orc.csv``, ``checks.csv``, ``heel.csv``, ``tank.csv``, each case's ``polar_<case>.csv``;
    ``polar_eleven_metre.png``, ``polar_wille_yacht.png`` and ``tank.png``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    a = analysis
    a.orc.to_csv(out / "orc.csv", index=False)
    a.checks.to_csv(out / "checks.csv", index=False)
    a.heel.to_csv(out / "heel.csv", index=False)
    a.tank.to_csv(out / "tank.csv", index=False)
    for case, frame in a.polars.items():
        frame.to_csv(out / f"polar_{scenario.slug(case)}.csv", index=False)
    orc = scenario.reference()
    plot_reference(a.polars["as built"], orc, out / "polar_eleven_metre.png",
                   "eleven_metre (made from its class dimensions) against ORC's 11:Metre")
    if "wille_yacht" in a.polars:
        plot_reference(a.polars["wille_yacht"], orc, out / "polar_wille_yacht.png",
                       "wille_yacht (main only) against ORC's 11:Metre, its ceiling")
    plot_tank(a, out / "tank.png")


def plot_tank(a: Analysis, path: Path) -> None:
    """The canoe body's residuary resistance per weight against the tank's, per Froude number.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    path : pathlib.Path
        The PNG written.
    """
    plt = figures.pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(10.0, 4.2))
    for _, group in a.tank.groupby(["lcb", "cp", "l_over_displ13", "b_over_t", "l_over_b"]):
        left.plot(group["tank"], group["ours"], "-", color="0.6", lw=0.8)
    top = float(max(a.tank["tank"].max(), a.tank["ours"].max()))
    left.plot([0, top], [0, top], "k--", lw=1.0, label="ours = tank")
    left.set_xscale("symlog", linthresh=1.0)
    left.set_yscale("symlog", linthresh=1.0)
    left.set_xlabel("tank R_r / (rho g V) x 1000 [-]")
    left.set_ylabel("our canoe body's R_r / (rho g V) x 1000 [-]")
    left.set_title("each grey line one of the 22 hulls", fontsize=9)
    left.legend(loc="upper left", fontsize=8)
    valid = a.tank[a.tank["tank"] > 0]
    fns = sorted(valid["fn"].unique())
    right.boxplot([valid.loc[valid["fn"] == fn, "ratio"].to_numpy() for fn in fns], positions=fns,
                  widths=0.012, manage_ticks=False)
    right.axhline(1.0, color="k", lw=0.8)
    right.axhspan(1.0 - BAND, 1.0 + BAND, color="tab:green", alpha=0.15, label="within 10 %")
    right.set_xlabel("Froude number Fn [-]")
    right.set_ylabel("ours / tank [-]")
    right.set_yscale("log")
    right.set_title("the 22 hulls at each Froude number", fontsize=9)
    right.legend(loc="upper right", fontsize=8)
    fig.suptitle("Residuary resistance: this project's canoe body of each Delft hull's L/V^(1/3) and L/B "
                 "against the tank", fontsize=10)
    figures.save(fig, path, dpi=110)


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of ``report.md``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass.
    """
    a, n = analysis, analysis.numbers
    text = Report(TITLE)
    text.summary(_summary(a, smoke))
    text.table(_orc_rows(a))
    text.section("Each point that misses, against the switches that sail it", _outside_paragraph(a))
    if not a.outside.empty:
        text.table(_outside_rows(a))
        text.paragraph(_outside_verdict(a))
    text.section("What each switch changes", _checks_paragraph(a))
    text.table(_check_rows(a))
    text.section("Heel at 52 deg against ORC's speed guides",
                 "ORC's speed guides for club keelboats show the heel near 0 at 6 kn, about 15 deg at 10 kn "
                 "and 22-26 deg from about 14 kn (the crew on the rail, the sails flattened and reefed). "
                 "Ours, the crew on the rail, at the best trim and at full sail:")
    text.table([{"TWS [kn]": r["tws_kn"], "heel at the best trim [deg]": r["heel_deg"],
                 "its trim": _trim(r), "heel at full sail [deg]": r["heel_full_sail_deg"],
                 "ORC's pattern [deg]": f"{r['orc_low']:g}-{r['orc_high']:g}"} for _, r in a.heel.iterrows()])
    if "wille_yacht" in a.polars:
        text.section("The Wille yacht as built, with ORC as its ceiling", _wille_paragraph(a))
    text.section("The canoe body against the Delft tank", _tank_paragraph(a))
    text.table(_tank_rows(a))
    text.section("Method", scenario.__doc__.split("\n\n", 1)[1])
    text.section("Runs", f"{a.runs} simulations (`study all`'s log gives their time); headline ratio range "
                 f"{n['ratio_min']:.2f}-{n['ratio_max']:.2f}."
                 + (" Smoke pass: one wind, two angles, two sail angles, 30 s runs." if smoke else ""))
    text.figure(Path("polar_eleven_metre.png"), "The 11:Metre (solid) against ORC's polar (dashed)")
    text.figure(Path("tank.png"), "The canoe body's residuary resistance against the Delft tank")
    return text.text()


def _summary(a: Analysis, smoke: bool) -> str:
    n = a.numbers
    by_wind = ", ".join(f"{k.split('_')[1].removesuffix('kn')} kn {v:.2f}" for k, v in n.items()
                        if k.startswith("ratio_") and k.endswith("kn_mean"))
    winds = ", ".join(f"{w:g}" for w in sorted(a.outside["tws_kn"].unique())) if not a.outside.empty else "none"
    heel = a.heel.iloc[-1]
    return (f"The 11:Metre, made from its class dimensions by the rules of `sailmujoco.boat.principal` and "
            f"sailed with ORC's crew on the rail at each point's best trim (sail angle, reef, flat), sails "
            f"at {n['ratio_min']:.2f}-{n['ratio_max']:.2f} of ORC's polar of the class (mean ratio by TWS: "
            f"{by_wind}). {n['points_outside_10pct']} of its {n['points']} points miss (more than {BAND:.0%} "
            f"from ORC's, or a beat more than 3 deg off ORC's angle), at TWS {winds} kn; for "
            f"{n['misses_explained_by_a_switch']} of them a switch of the next section shows the cause. At {heel['tws_kn']:g} kn it heels {heel['heel_deg']:.0f} deg at 52 deg "
            f"({_trim(heel)}), where ORC's boat heels {heel['orc_low']:g}-{heel['orc_high']:g} deg. The canoe "
            f"body's residuary resistance is {n['tank_ratio_median_fn_0.2_0.45']:.2f} times the Delft tank's "
            "(median over 22 hulls, Fn 0.2-0.45)." + (" (Smoke pass: too short to read.)" if smoke else ""))


def _trim(r) -> str:
    """A polar row's trim in words: sail angle, and the reef and flat where not full."""
    parts = [f"sail {r['sail_deg']:g} deg"]
    if r.get("reef", 1.0) < 1.0:
        parts.append(f"reefed to {r['reef']:g}")
    if r.get("flat", 1.0) < 1.0:
        parts.append(f"flattened to {r['flat']:g}")
    return ", ".join(parts)


def _orc_rows(a: Analysis) -> list[dict]:
    rows = []
    for _, r in a.orc.iterrows():
        what = "boat speed" if r["point"] == "fixed" else "beat VMG"
        off = not within(r["ratio"], r["point"], r["twa"], r["twa_reference"])
        rows.append({"TWS [kn]": r["tws_kn"], "point": what, "TWA ours / ORC [deg]":
                     f"{r['twa']:g} / {r['twa_reference']:g}", "ours [kn]": r["ours_kn"],
                     "ORC [kn]": r["reference_kn"], "ours / ORC": f"{r['ratio']:.2f}{' ⚠' if off else ''}"})
    return rows


def _check_rows(a: Analysis) -> list[dict]:
    """One row per case: ours / ORC at each (TWS, TWA) of the switches, and in brackets / full sail."""
    rows = []
    points = sorted({(r["tws_kn"], r["twa"]) for _, r in a.checks.iterrows()
                     if r["case"] not in ("as built", "full sail", "wille_yacht", *CAUSES)})
    meaning = {**{case: CASES[case][2] for case in CASES}, "full sail": "neither reef nor flattening"}
    for case in ("as built", "full sail", *CASES):
        if case == "wille_yacht" or case not in a.polars or case in {r["case"] for r in rows}:
            continue
        row = {"case": case, "what it changes": meaning[case]}
        for tws, twa in points:
            c = a.checks[(a.checks["case"] == case) & np.isclose(a.checks["tws_kn"], tws)
                         & np.isclose(a.checks["twa"], twa)]
            cell = "—" if c.empty else f"{c['to_orc'].iloc[0]:.2f} ({c['to_built'].iloc[0]:.2f})"
            row[f"{tws:g} kn, {twa:g}°"] = cell
        rows.append(row)
    return rows


def _effect(a: Analysis, case: str, tws: float) -> float:
    c = a.checks[(a.checks["case"] == case) & np.isclose(a.checks["tws_kn"], tws)]
    return float(c["to_built"].mean()) if not c.empty else float("nan")


def _checks_paragraph(a: Analysis) -> str:
    light, strong = min(a.checks["tws_kn"]), max(a.checks["tws_kn"])
    parts = [f"'{case}' {_effect(a, case, light):.2f} at {light:g} kn and {_effect(a, case, strong):.2f} at "
             f"{strong:g} kn" for case in CASES if case not in ("as built", "wille_yacht")
             and case in a.polars]
    return ("Each switch changes one thing from the boat at full sail and sails the same points, each at its "
            "own best sail angle. The table gives ours / ORC and, in brackets, ours / full sail; averaged "
            f"over 52 and 90 deg the speed over the full-sail speed is {'; '.join(parts)}.")


def _outside_paragraph(a: Analysis) -> str:
    if a.outside.empty:
        return "Every point holds."
    return ("Two switches sail every angle of the lightest and the strongest wind, beat included: "
            "'flat sails', the papers' flat plates in place of the 11:Metre's cambered rig (its camber "
            "of 0.10 is a guess, set before the comparison), and 'ORC's areas, no surge damping', the "
            "sail areas ORC measured (14 % more than the class's, the main's roach counted) with the "
            "resistance a VPP has (without the linear surge damping the boat takes from the Wille "
            "yacht, Wille eq. 13). A beat can miss on its VMG, on its angle or on both; each is held "
            "against the switches on its own. Each point that misses, with its ratio to ORC in each (✓: "
            "what it missed by holds there):")


def _outside_verdict(a: Analysis) -> str:
    """Which misses the switches explain, which they do not, and where the beat's angle lies."""
    def name(r) -> str:
        return f"{r['tws_kn']:g} kn {'beat' if r['point'] == 'beat' else f'{r.twa:g} deg'}"

    words = []
    for case in CAUSES:
        speed = [name(r) for _, r in a.outside.iterrows() if r["speed_off"] and r.get(f"{case} speed holds")]
        angle = [name(r) for _, r in a.outside.iterrows() if r["angle_off"] and r.get(f"{case} angle holds")]
        if speed:
            words.append(f"'{case}' brings the speed or VMG within {BAND:.0%} at {', '.join(speed)}")
        if angle:
            words.append(f"'{case}' brings the beat's angle within 3 deg at {', '.join(angle)}")
    text = ("; ".join(words) + ". ") if words else ""
    left = [name(r) for _, r in a.outside.iterrows() if not r["explained"]]
    if left:
        text += (f"No switch here explains {'this miss' if len(left) == 1 else 'these misses'} "
                 f"({', '.join(left)}): {'its' if len(left) == 1 else 'their'} cause is not yet shown. ")
    else:
        text += ("For every miss, each thing it misses by (the speed, the VMG, the beat's angle) holds with one "
                 "of the two switches. ")
    beats = a.orc[a.orc["point"] == "beat"]
    lowest = min(scenario.BEAT_TWA_DEG)
    edge = beats[np.isclose(beats["twa"], lowest)]
    if not edge.empty:
        text += (f"The boat's best beat lies at the lowest angle it sailed, {lowest:g} deg, at "
                 + ", ".join(f"{t:g}" for t in edge["tws_kn"]) + " kn (ORC's beats "
                 + ", ".join(f"{t:g}" for t in edge["twa_reference"]) + " deg): it points higher than "
                 "ORC's boat, its optimum perhaps closer still to the wind.")
    return text.strip()


def _outside_rows(a: Analysis) -> list[dict]:
    rows = []
    for _, r in a.outside.iterrows():
        what = "boat speed" if r["point"] == "fixed" else "beat VMG"
        row = {"TWS [kn]": r["tws_kn"], "point": what,
               "TWA ours / ORC [deg]": f"{r['twa']:g} / {r['twa_reference']:g}", "as built": f"{r['ratio']:.2f}"}
        for case in CAUSES:
            if case not in r or not np.isfinite(r[case]):
                row[case] = "—"
                continue
            angle = f" at {r[f'{case} twa']:g} deg" if r["point"] == "beat" else ""
            marks = []
            if r["speed_off"] and r[f"{case} speed holds"]:
                marks.append("VMG ✓" if r["point"] == "beat" else "✓")
            if r["angle_off"] and r[f"{case} angle holds"]:
                marks.append("angle ✓")
            row[case] = f"{r[case]:.2f}{angle}{' ' + ', '.join(marks) if marks else ''}"
        rows.append(row)
    return rows


def _wille_paragraph(a: Analysis) -> str:
    w = a.checks[a.checks["case"] == "wille_yacht"]
    return (f"The Wille yacht (the 11:Metre's mass and main, Wille's hull and appendages, no jib) sails at "
            f"{w['to_orc'].min():.2f}-{w['to_orc'].max():.2f} of ORC's 11:Metre over the same fixed points: below "
            "its ceiling everywhere, as a boat with 60 % of the class's sail area should be.")


def _tank_paragraph(a: Analysis) -> str:
    t = a.tank
    return ("The canoe body takes each tank hull's slenderness L/V^(1/3) and L/B; its form fixes the rest "
            f"(its B/T then {t['our_b_over_t'].min():.2f}-{t['our_b_over_t'].max():.2f} against the tank's "
            f"{t['b_over_t'].min():.2f}-{t['b_over_t'].max():.2f}, Cp 0.533, LCB midship). Ours over the tank's, "
            "per Froude number over the 22 hulls (the tank's zero readings left out):")


def _tank_rows(a: Analysis) -> list[dict]:
    rows = []
    valid = a.tank[a.tank["tank"] > 0]
    for fn, group in valid.groupby("fn"):
        r = group["ratio"]
        rows.append({"Fn": fn, "tank, median ×1000": float(group["tank"].median()),
                     "ours, median ×1000": float(group["ours"].median()), "ours / tank, median": float(r.median()),
                     "range": f"{r.min():.2f}-{r.max():.2f}",
                     "within 10 %": f"{int((np.abs(r - 1.0) <= BAND).sum())} of {len(r)}"})
    return rows
