"""What a flight measures, from its record alone (:class:`.mission.Flight`), the same way for every
simulator: the time to the upwind mark and home, the tacks, the heel against ``SAIL_HEEL_MAX``
and the cross-track error.

* A **tack** is counted when the boat goes from sailing on one side of the wind to sailing on the
  other with its bow through the wind: its true wind angle passes from one band of
  ``TACK_BAND_DEG`` (20-90 deg off the wind on one side) to the other without the stern passing
  through the wind (that is a gybe). A tack begun and abandoned, or a boat lying head to wind, does
  not count; ArduPilot's own "Sailboat: Tacking" and "Tacking timed out" are counted beside.
* The **cross-track error** is the distance from the line of the leg being sailed (home to the
  mark, the mark to home), as ArduPilot's own ``SAIL_XTRACK_MAX`` corridor measures it.
"""

from __future__ import annotations

import math

import numpy as np

TACK_BAND_DEG = (20.0, 90.0)  # |true wind angle| of a boat sailing on one tack, deg
HEEL_MAX_DEG = 15.0  # ArduPilot's SAIL_HEEL_MAX default


def true_wind_angle(heading_deg, wind_from_deg: float) -> np.ndarray:
    """The true wind angle of each heading, deg in (-180, 180]: positive with the wind over the
    starboard side (the boat's heading to the left of the wind's bearing).

    Parameters
    ----------
    heading_deg : array_like
        Compass headings, deg.
    wind_from_deg : float
        The bearing the wind comes from, deg.
    """
    return (np.asarray(wind_from_deg, float) - np.asarray(heading_deg, float) + 180.0) % 360.0 - 180.0


def tacks(heading_deg, wind_from_deg: float) -> int:
    """Tacks completed: passes from one close-hauled-to-beam band to the other through the wind.

    Parameters
    ----------
    heading_deg : array_like
        Compass headings in time order, deg.
    wind_from_deg : float
        The bearing the wind comes from, deg.
    """
    low, high = TACK_BAND_DEG
    side, count = 0, 0
    for angle in true_wind_angle(heading_deg, wind_from_deg):
        magnitude = abs(angle)
        if magnitude > high:  # off the wind: a later change of side would be a gybe
            side = 0
        elif magnitude >= low:
            new = 1 if angle > 0 else -1
            if side and new != side:
                count += 1
            side = new
    return count


def cross_track(north, east, leg_start, leg_end) -> np.ndarray:
    """Distance of each point from the line through ``leg_start`` and ``leg_end``, m.

    Parameters
    ----------
    north, east : array_like
        The points, m from home.
    leg_start, leg_end : tuple of float
        (north, east) of the leg's ends, m.
    """
    (n0, e0), (n1, e1) = leg_start, leg_end
    dn, de = n1 - n0, e1 - e0
    length = math.hypot(dn, de)
    return np.abs((np.asarray(north, float) - n0) * de - (np.asarray(east, float) - e0) * dn) / length


def measure(flight, mission, heel_max_deg: float = HEEL_MAX_DEG) -> dict:
    """The numbers of one flight.

    Parameters
    ----------
    flight : Flight
        Its record.
    mission : Mission
        The course it sailed.
    heel_max_deg : float
        ArduPilot's ``SAIL_HEEL_MAX``, deg.
    """
    rows = flight.rows
    t = np.array([r["t"] for r in rows])
    north = np.array([r["north"] for r in rows])
    east = np.array([r["east"] for r in rows])
    heading = np.array([r["heading"] for r in rows])
    roll = np.abs(np.array([r["roll"] for r in rows], float))
    wp = np.array([r["wp"] for r in rows])
    speed = np.array([r["speed"] for r in rows], float)
    points = flight.waypoints or mission.waypoints()
    xte = np.zeros(len(rows))
    for k in range(1, len(points)):
        on = wp == k
        xte[on] = cross_track(north[on], east[on], points[k - 1], points[k])
    texts = [text for _, text in flight.events]
    finish = flight.reached.get(len(points) - 1, math.nan)
    sailed = t <= finish if math.isfinite(finish) else np.ones(len(rows), bool)
    return {
        "mark_s": flight.reached.get(1, math.nan),
        "home_s": finish,
        "finished": bool(math.isfinite(finish)),
        "tacks": tacks(heading[sailed], mission.wind_from_deg),
        "tacks_begun": sum(text.startswith("Sailboat: Tacking") and "timed out" not in text for text in texts),
        "tacks_timed_out": sum("Tacking timed out" in text for text in texts),
        "heel_max_deg": float(np.nanmax(roll[sailed])) if len(rows) else math.nan,
        "over_heel_max_pct": 100.0 * float(np.nanmean(roll[sailed] > heel_max_deg)) if len(rows) else math.nan,
        "xte_max_m": float(np.max(xte[sailed])) if len(rows) else math.nan,
        "xte_rms_m": float(np.sqrt(np.mean(xte[sailed] ** 2))) if len(rows) else math.nan,
        "mean_speed": float(np.nanmean(speed[sailed])) if len(rows) else math.nan,
        "sailed_s": float(t[sailed][-1]) if len(rows) else 0.0,
        "wall_s": flight.wall,
    }
