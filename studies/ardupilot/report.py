"""The comparison's report: every flight's record and numbers, each case's numbers with their
intervals over its flights, the tracks and the heel drawn, and ``report.md``."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

from sailmujoco.stats import mean_interval

from .cases import SIMULATORS
from .measures import HEEL_MAX_DEG, measure

COLUMNS = ("mark_s", "home_s", "tacks", "tacks_timed_out", "heel_max_deg", "over_heel_max_pct", "xte_max_m",
           "xte_rms_m", "mean_speed")


def save_flight(flight, folder: Path) -> None:
    """Keep one flight as it lands: ``record.csv``, ``events.csv`` and ``flight.json`` in ``folder``.

    Parameters
    ----------
    flight : Flight
        Its record.
    folder : Path
        Where it goes.
    """
    folder.mkdir(parents=True, exist_ok=True)
    _write_csv(folder / "record.csv", flight.rows)
    _write_csv(folder / "events.csv", [{"t": t, "text": text} for t, text in flight.events])
    (folder / "flight.json").write_text(json.dumps({"reached": flight.reached, "waypoints": flight.waypoints,
                                                    "wall": flight.wall, "sim_log": flight.sim_log,
                                                    "autopilot": flight.autopilot}, indent=1))


def load_flight(folder: Path):
    """A flight :func:`save_flight` kept (None where it is incomplete).

    Parameters
    ----------
    folder : Path
        The flight's folder.
    """
    from .mission import Flight

    if not (folder / "flight.json").is_file():
        return None
    meta = json.loads((folder / "flight.json").read_text())
    with open(folder / "record.csv") as f:
        rows = [{k: (int(v) if k == "wp" else float(v)) for k, v in row.items()} for row in csv.DictReader(f)]
    with open(folder / "events.csv") as f:
        events = [(float(row["t"]), row["text"]) for row in csv.DictReader(f)]
    return Flight(rows=rows, events=events, reached={int(k): v for k, v in meta["reached"].items()},
                  waypoints=[tuple(p) for p in meta.get("waypoints", [])], wall=meta["wall"],
                  sim_log=meta["sim_log"], autopilot=meta.get("autopilot", ""))


def write_all(flights, out: Path) -> list[dict]:
    """Write ``flights.csv``, the figures and ``report.md`` under ``out``.

    Parameters
    ----------
    flights : list of (Case, Mission, Flight)
        What flew.
    out : Path
        The folder.

    Returns
    -------
    list of dict
        One row per flight: the case, its seed and its numbers.
    """
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for case, mission, flight in flights:
        rows.append({"case": case.label, "simulator": case.simulator, "sea": case.sea, "seed": case.seed,
                     **measure(flight, mission)})
    _write_csv(out / "flights.csv", rows)
    _figures(flights, out)
    (out / "report.md").write_text(report(rows, flights), encoding="utf-8")
    return rows


def _write_csv(path: Path, rows: list[dict]) -> None:
    with open(path, "w", newline="") as f:
        if not rows:
            return
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def summary(rows: list[dict]) -> list[dict]:
    """Each case's numbers over its flights: finished k of N, and each measure's mean with its
    95 % interval (times over the flights that finished).

    Parameters
    ----------
    rows : list of dict
        One per flight (:func:`write_all`).
    """
    order = list(dict.fromkeys(r["case"] for r in rows))
    out = []
    for case in order:
        mine = [r for r in rows if r["case"] == case]
        done = [r for r in mine if r["finished"]]
        entry = {"case": case, "n": len(mine), "finished": len(done)}
        for key in COLUMNS:
            pool = done if key in ("mark_s", "home_s") else mine
            values = [r[key] for r in pool if math.isfinite(r[key])]
            entry[key] = mean_interval(values) if values else None
        entry["reached_mark"] = sum(math.isfinite(r["mark_s"]) for r in mine)
        out.append(entry)
    return out


def _text(interval, decimals: int = 0) -> str:
    """``mean [low, high]``; every measure here is >= 0, so an interval's low end is shown no
    lower than 0."""
    if interval is None:
        return "—"
    if interval.n > 1 and interval.low == interval.high:
        return f"{interval.mean:.{decimals}f} (all {interval.n} equal)"
    if interval.n > 1 and interval.low < 0.0:
        return f"{interval.mean:.{decimals}f} [{0.0:.{decimals}f}, {interval.high:.{decimals}f}]"
    return interval.fixed(decimals)


def _versions(flights) -> str:
    """``git 90700977; ``: the ArduPilot the flights report, "" where none did."""
    found = sorted({f.autopilot for _, _, f in flights if f.autopilot})
    return f"git {', '.join(found)}; " if found else ""


def _mean(interval, decimals: int = 0) -> str:
    return "—" if interval is None else f"{interval.mean:.{decimals}f}"


def report(rows: list[dict], flights) -> str:
    """The Markdown of ``report.md``.

    Parameters
    ----------
    rows : list of dict
        One per flight (:func:`write_all`).
    flights : list of (Case, Mission, Flight)
        What flew.
    """
    table = summary(rows)
    lines = [
        "# ArduPilot's sailboat code: its own simulator against the 6-DOF boats",
        "",
        f"ArduPilot Rover ({_versions(flights)}sailboat mode, its rover and sailboat defaults) flies one mission: "
        f"from its start to a mark {flights[0][1].upwind:g} m straight upwind and back, in "
        f"{flights[0][1].wind_speed:g} m/s of wind from the north, calm and in a 1 m sea. Our boats lie moored "
        "at home on a broad reach (135 deg) until ArduPilot first steers (`sailmujoco sitl --hold`); "
        "SIM_Sailboat's boat, started on the same heading, sails off while ArduPilot starts up (its sheet is "
        "hauled in while disarmed), so its mission is laid from where it is when the mission starts. The "
        "same MAVLink client records every flight ten times a simulated second, so each number below is measured the "
        "same way in both simulators (studies/ardupilot/measures.py).",
        "",
        "- **SIM_Sailboat** (`--model sailboat`): ArduPilot's kinematic boat, no heel, a fixed 1.8 m turning "
        "circle, lift and drag tables in 10 deg steps; its sea is one sine (1 m high, the 6 s wave's "
        "length and speed) that only tilts it.",
        "- **Our boats** (`--model JSON` against `sailmujoco sitl`): the 6-DOF `wille_yacht` and "
        "`saoud_robot`; the sea is JONSWAP, Hs 1 m, Tp 6 s, from the wind, its phases drawn by the seed. "
        "`SAIL_ANGLE_IDEAL` (the angle of attack ArduPilot sheets to, 25 deg by default) is set to our sails' "
        "stall angle, 15 deg; one case keeps 25 deg on the robot. In the sea the robot carries a 10 N motor, "
        "which ArduPilot runs (channel 3, `sailmujoco sitl --motor`) to finish a tack that takes longer than "
        "5 s; twice it sails there without one.",
        "",
        f"Times are from AUTO, simulated seconds; a flight not home after {flights[0][1].limit:g} s is stopped. Intervals are 95 % over the flights of a case (times over "
        f"the flights that finished). Tacks are counted from the heading (bow through the wind between "
        f"20-90 deg off it on each side); \"timed out\" counts ArduPilot's own \"Tacking timed out\". "
        f"Heel is the largest |roll| and the share of the time beyond SAIL_HEEL_MAX ({HEEL_MAX_DEG:g} deg). "
        "Cross-track error is the distance from the leg's line (ArduPilot tacks at SAIL_XTRACK_MAX, 10 m).",
        "",
        "| case | flights | home | mark after (s) | home after (s) | tacks | tacks timed out | largest heel (deg) "
        "| time beyond 15 deg (%) | largest cross-track (m) | RMS cross-track (m) | mean speed (m/s) |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for e in table:
        lines.append(
            f"| {e['case']} | {e['n']} | {e['finished']} of {e['n']} | {_text(e['mark_s'])} | {_text(e['home_s'])} "
            f"| {_text(e['tacks'], 1)} | {_text(e['tacks_timed_out'], 1)} | {_text(e['heel_max_deg'], 1)} "
            f"| {_text(e['over_heel_max_pct'], 1)} | {_text(e['xte_max_m'], 1)} | {_text(e['xte_rms_m'], 1)} "
            f"| {_text(e['mean_speed'], 2)} |")
    lines += ["", "![tracks](tracks.png)", "", "![heel](heel.png)", "", "## What differs", ""]
    lines += findings(table)
    lines += ["", "## Each flight", "",
              "`flights.csv` has every flight's numbers; `flights/<case>/record.csv` its record and "
              "`events.csv` ArduPilot's messages. Wall time of the flights: "
              f"{sum(r['wall_s'] for r in rows):.0f} s for {len(rows)} flights.", ""]
    return "\n".join(lines)


def findings(table: list[dict]) -> list[str]:
    """The differences the table shows, in sentences filled from it.

    Parameters
    ----------
    table : list of dict
        :func:`summary`'s rows.
    """
    by = {e["case"]: e for e in table}
    out = []
    sim = by.get(f"{SIMULATORS[0][1]}, calm")
    for e in table:
        if e["case"].startswith(SIMULATORS[0][1]) or "SAIL_ANGLE_IDEAL 25" in e["case"] or sim is None:
            continue
        if e["finished"] == 0:
            out.append(f"- **{e['case']}**: home in none of {e['n']} flights (the mark reached in "
                       f"{e['reached_mark']}); {_mean(e['tacks_timed_out'], 1)} tacks a flight timed out, "
                       f"{_mean(e['mean_speed'], 2)} m/s on average.")
            continue
        against = (f"{e['home_s'].mean / sim['home_s'].mean:.1f} times SIM_Sailboat's calm "
                   f"{sim['home_s'].mean:.0f} s" if sim["home_s"] else "SIM_Sailboat never home")
        out.append(
            f"- **{e['case']}**: home in {e['finished']} of {e['n']} flights, after {_text(e['home_s'])} s, "
            f"{against}; largest heel {_text(e['heel_max_deg'], 1)} deg against SIM_Sailboat's "
            f"{sim['heel_max_deg'].mean:.1f} deg; {_mean(e['tacks'], 1)} tacks a flight, "
            f"{_mean(e['tacks_timed_out'], 1)} timed out.")
    default = next((e for e in table if "SAIL_ANGLE_IDEAL 25" in e["case"]), None)
    if default is not None:
        out.append(f"- **{default['case']}**: home in {default['finished']} of {default['n']}, the mark reached in "
                   f"{default['reached_mark']}; {_mean(default['tacks_timed_out'])} tacks timed out, "
                   f"{_mean(default['mean_speed'], 2)} m/s on average. Sheeted to 25 deg of attack its sail is "
                   "stalled: it cannot hold a close-hauled course, luffs towards the wind and stalls there, "
                   "and ArduPilot (no motor, no recovery from irons) tries the tack again every 5 s.")
    return out


def _figures(flights, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = list(dict.fromkeys(case.label for case, _, _ in flights))
    cols = 2
    nrows = math.ceil(len(labels) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(10, 4.2 * nrows), squeeze=False)
    for ax, label in zip(axes.ravel(), labels, strict=False):
        for case, _, flight in flights:
            if case.label != label or not flight.rows:
                continue
            east = [r["east"] for r in flight.rows]
            north = [r["north"] for r in flight.rows]
            ax.plot(east, north, lw=1.0, label=f"seed {case.seed}")
        first = next(f for c, _, f in flights if c.label == label)
        points = np.array(first.waypoints or flights[0][1].waypoints())
        ax.plot(points[:, 1], points[:, 0], "k--", lw=0.8)
        ax.plot(points[:2, 1], points[:2, 0], "ko", ms=5)
        ax.axvspan(points[0, 1] - 10, points[0, 1] + 10, color="0.9", zorder=0)
        ax.annotate("wind", xy=(0.88, 0.78), xytext=(0.88, 0.95), xycoords="axes fraction",
                    arrowprops={"arrowstyle": "->"}, ha="center")
        ax.set_title(label, fontsize=10)
        ax.set_xlabel("east (m)")
        ax.set_ylabel("north (m)")
        ax.set_aspect("equal", adjustable="datalim")
        ax.legend(fontsize=7, loc="lower right")
    for ax in axes.ravel()[len(labels):]:
        ax.set_visible(False)
    fig.suptitle("Tracks: the start to the mark 100 m upwind and back (grey: ArduPilot's 10 m cross-track "
                 "corridor)")
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    fig.savefig(out / "tracks.png", dpi=110)
    plt.close(fig)

    fig, axes = plt.subplots(len(labels), 1, figsize=(10, 1.5 * len(labels) + 0.8), sharey=True, squeeze=False)
    for ax, label in zip(axes[:, 0], labels, strict=True):
        first = next(f for c, _, f in flights if c.label == label)
        ax.plot([r["t"] for r in first.rows], [abs(r["roll"]) for r in first.rows], lw=0.6, color="tab:blue")
        ax.axhline(HEEL_MAX_DEG, color="k", ls="--", lw=0.8)
        ax.set_title(label, fontsize=9, loc="left")
        ax.set_ylabel("|roll| (deg)", fontsize=8)
    axes[-1, 0].set_xlabel("time from AUTO (s)")
    fig.suptitle("Heel, the first flight of each case (dashed: SAIL_HEEL_MAX)")
    fig.tight_layout(rect=(0, 0, 1, 0.98))
    fig.savefig(out / "heel.png", dpi=110)
    plt.close(fig)
