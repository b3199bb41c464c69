"""The courses report, its CSV data and its figures."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from sailmujoco import figures

from ..kit import Report
from .analysis import BASE, HARD, Analysis, ordered
from .scenario import BOATS, BOOK_RUDDER, DURATION, SCORES, TASKS, TITLE

EVENT = {"upwind_downwind": "race (WRSC 2019)", "precision_navigation": "precision navigation (SailBot 2022)",
         "station_keeping": "station keeping (SailBot 2022)", "area_scanning": "area scanning (WRSC 2019)"}
ARM_COLOURS = {BASE: "tab:blue", HARD: "tab:orange"}


def write(analysis: Analysis, out: Path) -> None:
    """``runs.csv`` (one row per run), ``summary.csv`` (each case over the seeds), ``changes.csv``,
    ``causes.csv``; ``tracks.png`` and ``scores.png``.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    out : pathlib.Path
        The study's folder.
    """
    out = Path(out)
    a = analysis
    ordered(a.runs).to_csv(out / "runs.csv", index=False)
    ordered(a.summary).to_csv(out / "summary.csv", index=False)
    if len(a.changes):
        ordered(a.changes).to_csv(out / "changes.csv", index=False)
    a.causes.to_csv(out / "causes.csv", index=False)
    plot_tracks(a, out / "tracks.png")
    plot_scores(a, out / "scores.png")


def _draw_scene(ax, scene: dict | None) -> None:
    """The marks (circles of their radius), the line and the box or the square."""
    if not scene:
        return
    for mark in scene.get("marks", []):
        ax.add_patch(figures.pyplot().Circle(mark, scene["radii"][0], fill=False, color="k", lw=0.8))
    if scene.get("line"):
        (x0, y0), (x1, y1) = scene["line"]
        ax.plot([x0, x1], [y0, y1], "k-", lw=1.2)
    if scene.get("corners"):
        corners = np.array(scene["corners"] + scene["corners"][:1])
        ax.plot(corners[:, 0], corners[:, 1], "k--", lw=0.8)


def plot_tracks(a: Analysis, path: Path) -> None:
    """Each event (a row) on each boat (a column): the first seed's track in both conditions.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    path : pathlib.Path
        The PNG written.
    """
    plt = figures.pyplot()
    tasks = [t for t in TASKS if any(k[0] == t for k in a.tracks)]
    boats = [b for b in BOATS if any(k[1] == b for k in a.tracks)]
    fig, axes = plt.subplots(len(tasks), len(boats), figsize=(max(3.2 * len(boats), 6.0), 3.1 * len(tasks)),
                             squeeze=False)
    for i, task in enumerate(tasks):
        for j, boat in enumerate(boats):
            ax = axes[i][j]
            for arm, colour in ARM_COLOURS.items():
                got = a.tracks.get((task, boat, arm))
                if got is None:
                    continue
                track = np.asarray(got["track"], float)
                ax.plot(track[:, 1], track[:, 2], color=colour, lw=0.9, label=arm)
                _draw_scene(ax, got["scene"])
            ax.set_aspect("equal", adjustable="datalim")
            ax.set_title(f"{boat}: {task}", fontsize=9)
            ax.set_xlabel("east [m]", fontsize=8)
            ax.set_ylabel("north [m]", fontsize=8)
            ax.tick_params(labelsize=7)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncol=2, fontsize=8)
    fig.suptitle(f"Tracks on seed {min(a.seeds)}; the wind from the north (up)", fontsize=10)
    figures.save(fig, path)


def plot_scores(a: Analysis, path: Path) -> None:
    """Each event's score per boat, both conditions, with the 95 % intervals over the seeds.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    path : pathlib.Path
        The PNG written.
    """
    plt = figures.pyplot()
    tasks = [t for t in TASKS if t in set(a.summary["task"])]
    fig, axes = plt.subplots(1, len(tasks), figsize=(max(3.6 * len(tasks), 7.0), 3.4), squeeze=False)
    for ax, task in zip(axes[0], tasks, strict=True):
        rows = a.summary[a.summary["task"] == task]
        boats = [b for b in BOATS if b in set(rows["boat"])]
        for k, (arm, colour) in enumerate(ARM_COLOURS.items()):
            mine = rows[rows["arm"] == arm].set_index("boat")
            x = np.arange(len(boats)) + (k - 0.5) * 0.3
            mean = np.array([mine.loc[b, "mean"] if b in mine.index else np.nan for b in boats], float)
            low = np.array([mine.loc[b, "low"] if b in mine.index else np.nan for b in boats], float)
            high = np.array([mine.loc[b, "high"] if b in mine.index else np.nan for b in boats], float)
            low, high = np.where(np.isfinite(low), low, mean), np.where(np.isfinite(high), high, mean)
            ax.errorbar(x, mean, yerr=np.vstack([mean - low, high - mean]), fmt="o", color=colour, capsize=3,
                        label=arm)
        metric, unit, better = SCORES[task]
        ax.set_xticks(np.arange(len(boats)), boats, rotation=20, fontsize=8)
        ax.set_xlim(-0.6, len(boats) - 0.4)
        ax.set_ylabel(f"{metric}" + (f" [{unit}]" if unit else "") + f" ({better} is better)", fontsize=8)
        ax.set_title(EVENT[task], fontsize=9)
    axes[0][0].legend(fontsize=7)
    fig.suptitle("Scores over the seeds (95 % intervals); a race's time: its finishers'", fontsize=10)
    figures.save(fig, path)


def _score_cell(row) -> str:
    task = row["task"]
    unit = SCORES[task][1]
    if not np.isfinite(row["mean"]):
        text = "no finish" if task == "upwind_downwind" else "—"
    elif np.isfinite(row["low"]) and np.isfinite(row["high"]) and row["high"] > row["low"]:
        text = f"{row['mean']:.3g} [{row['low']:.3g}, {row['high']:.3g}]" + (f" {unit}" if unit else "")
    else:
        text = f"{row['mean']:.3g}" + (f" {unit}" if unit else "")
    if task == "upwind_downwind":
        text += f", {row['finished']}/{row['n']} finished"
    return text


def main_table(a: Analysis) -> list[dict]:
    """One row per event and boat: the score in both conditions, the change and its cause.

    Parameters
    ----------
    a : Analysis
        The study's numbers.
    """
    rows = []
    summary = ordered(a.summary)
    for (task, boat), case in summary.groupby(["task", "boat"], sort=False):
        by_arm = {r["arm"]: r for _, r in case.iterrows()}
        if BASE not in by_arm or HARD not in by_arm:
            continue
        got = a.changes[(a.changes["task"] == task) & (a.changes["boat"] == boat) & (a.changes["arm"] == HARD)]
        verdict, cause = "—", ""
        if len(got):
            c = got.iloc[0]
            verdict = c["verdict"] if c["verdict"] != "no change shown" else f"no change shown at N = {len(a.seeds)}"
            if c["loses"]:
                named = a.causes[(a.causes["task"] == task) & (a.causes["boat"] == boat)]
                cause = str(named.iloc[0]["cause"]) if len(named) else "not run"
        rows.append({"event": EVENT[task], "boat": boat, BASE: _score_cell(by_arm[BASE]),
                     HARD: _score_cell(by_arm[HARD]), "verdict": verdict, "cause (switch)": cause})
    return rows


def _book_rudder(a: Analysis) -> list[dict]:
    rows = []
    for boat in BOATS:
        arms = {}
        for arm in (BASE, BOOK_RUDDER):
            got = a.summary[(a.summary["task"] == "upwind_downwind") & (a.summary["boat"] == boat)
                            & (a.summary["arm"] == arm)]
            if len(got):
                arms[arm] = got.iloc[0]
        if len(arms) == 2:
            rows.append({"boat": boat, **{f"{arm}: finished": f"{r['finished']}/{r['n']}" for arm, r in arms.items()},
                         **{f"{arm}: tacks": f"{r['tacks']:.1f}" for arm, r in arms.items()},
                         **{f"{arm}: astern [s]": f"{r['astern_s']:.1f}" for arm, r in arms.items()}})
    return rows


def report(analysis: Analysis, smoke: bool) -> str:
    """The Markdown of report.md.

    Parameters
    ----------
    analysis : Analysis
        The study's numbers.
    smoke : bool
        The short pass.
    """
    a = analysis
    text = Report(TITLE)
    text.summary(_summary(a, smoke))
    text.table(main_table(a))
    text.section("Scores and tracks")
    span = f"seeds {a.seeds[0]}-{a.seeds[-1]}" if len(a.seeds) > 1 else f"seed {a.seeds[0]}"
    text.paragraph(
        f"**Method.** N = {len(a.seeds)} ({span}); every score is the mean over them with its 95 % "
        "Student-t interval, `mean [low, high]` (a race's time over the runs that finished); the "
        "arms are compared seed by seed (the same wind and sea in both). The seed draws the gusts, "
        "the wander, the start heading and the sea's phases. *Loses*: fewer runs finish, or the "
        "paired change's interval lies wholly on the worse side; *gains*: on the better side; "
        "otherwise no change is shown at N seeds.")
    text.figure(Path("scores.png"), "Each event's score per boat in calm water with perfect "
                "instruments and in the sea with typical ones, over the seeds")
    text.figure(Path("tracks.png"), "The first seed's tracks, with the marks, lines, box and square")
    text.section("What breaks it, named by a switch", (
        "Each case that loses in the sea with typical instruments ran again with each half of the "
        "change alone, on the same seeds: the sea with perfect instruments (`sea alone`) and typical "
        "instruments and servos in calm water (`instruments alone`). The half that loses as well "
        "names the cause."))
    if len(a.causes):
        causes = a.causes.assign(arm=HARD)
        text.table(ordered(causes).drop(columns="arm").to_dict("records"))
    else:
        text.paragraph("No case lost in the sea with typical instruments: no switch was run.")
    text.paragraph(
        "The law's own switch: Jaulin's book writes the rudder as (delta_r_max / pi) sawtooth(theta - "
        "theta_bar), a third of the IRSC listing's gain near the heading (`rudder=\"sawtooth\"`). "
        "Sailed on the race in calm water, seed by seed against the listing's rudder; a tack that "
        "stalls leaves the boat going astern:")
    book = _book_rudder(a)
    if book:
        text.table(book)
    else:
        text.paragraph("(Not run in the smoke pass.)")
    text.section("The events as laid", (
        "The wind 5 m/s from the north, gusting and wandering; the start on a beam reach at 1 m/s. "
        "The race: WRSC 2019's fleet race, a windward mark 100 m up from a 20 m line, reached "
        f"within 5 m, the time to the line's crossing (a run ends at the finish or at "
        f"{DURATION['upwind_downwind']:.0f} s). Precision navigation: SailBot 2022's, two buoys 50 m "
        "downwind of a 10 m gate, 20 m apart, 2 points a buoy and 6 back through the gate. Station "
        "keeping: SailBot 2022's 40 m box 60 m upwind, 2 points a minute inside over the five "
        "minutes from the first entry. Area scanning: WRSC 2019's 60 m square of 2.5 m cells, 50 m "
        "upwind, 15 minutes. The sea: the wind's fully developed sea (Pierson-Moskowitz, Hs 0.56 m, "
        "Tp 3.7 s, 22 m long), from the wind. The events are sailed on lakes and in harbours, "
        "whose chop is shorter (2 km of fetch: Hs 0.11 m, Tp 1.3 s, 2.8 m long); the sea model "
        "leaves out waves shorter than the hull (`sailmujoco.forces.sea_hull`), and in that chop "
        "its coarse grid turned the 11:Metre against full rudder, so the study sails the longer "
        "sea that every boat here feels as modelled."))
    if smoke:
        text.paragraph("Smoke pass: one boat, the race and station keeping, short runs: too short to read.")
    return text.text()


def _summary(a: Analysis, smoke: bool) -> str:
    base = a.summary[a.summary["arm"] == BASE]
    races = base[base["task"] == "upwind_downwind"]
    finished = int(races["finished"].sum())
    total = int(races["n"].sum())
    hard = a.changes[a.changes["arm"] == HARD] if len(a.changes) else a.changes
    losing = int(hard["loses"].sum()) if len(hard) else 0
    named = ordered(a.causes.assign(arm=HARD)).to_dict("records") if len(a.causes) else []
    causes = ", ".join(f"{r['boat']} {r['task']}: {r['cause']}" for r in named) or "none"
    return (
        f"Jaulin and Le Bars' line following sailed each event on {len(set(a.runs['boat']))} boats over "
        f"N = {len(a.seeds)} seeds. In calm water with perfect instruments the race was finished in "
        f"{finished} of {total} runs, tacking on every boat. In the wind's sea with typical "
        f"instruments and servos {losing} of {len(hard)} cases lose against calm water; the switch "
        f"that names each cause: {causes}." + (" Smoke pass." if smoke else ""))
