"""Viel et al. (2019) Fig. 3, the measures of one run: after entry, before it, after the stop.

From a run's samples (2 Hz): where the boat stops in the target area and how far it goes after
(:func:`after_entry`, the reading of the paper's 6.4 m), what it did before entering
(:func:`behaviour`) and how it drifts once stopped (:func:`drift_after_stop`).
"""

from __future__ import annotations

import math

import numpy as np

from .scenario import IRONS_AWA_DEG, IRONS_SURGE, PAPER_D_T, PAPER_MAX_M


def drift_after_stop(t: np.ndarray, x: np.ndarray, y: np.ndarray, samples: dict, stopped_at: float,
                     direction_from: float) -> dict:
    """How the boat moves once it has stopped in the target area: its mean velocity over ground
    (displacement / time from the stop to the end) and the part of it downwind [m/s], and its
    mean surge, mean |sway| [m/s] and mean |sail command| [deg] over that time. nan if it never
    stopped.

    Parameters
    ----------
    t, x, y : numpy.ndarray
        Sample times [s] and positions east, north [m].
    samples : dict
        ``surge``, ``sway`` [m/s] and ``sail`` (command, rad) at times ``t``.
    stopped_at : float
        The stop [s] (:func:`after_entry`), nan if none.
    direction_from : float
        Where the wind comes from [rad, compass].
    """
    nan = float("nan")
    keys = ("drift_speed", "drift_downwind", "surge_after_stop", "sway_after_stop", "sail_after_stop_deg")
    if not math.isfinite(stopped_at) or t.size < 2:
        return dict.fromkeys(keys, nan)
    after = t >= stopped_at - 1e-9
    if after.sum() < 2:
        return dict.fromkeys(keys, nan)
    ta, xa, ya = t[after], x[after], y[after]
    elapsed = ta[-1] - ta[0]
    vx, vy = (xa[-1] - xa[0]) / elapsed, (ya[-1] - ya[0]) / elapsed
    downwind = (-math.sin(direction_from), -math.cos(direction_from))  # where the wind blows to
    return {"drift_speed": float(math.hypot(vx, vy)), "drift_downwind": float(vx * downwind[0] + vy * downwind[1]),
            "surge_after_stop": float(np.mean(np.asarray(samples["surge"])[after])),
            "sway_after_stop": float(np.mean(np.abs(np.asarray(samples["sway"])[after]))),
            "sail_after_stop_deg": math.degrees(float(np.mean(np.abs(np.asarray(samples["sail"])[after]))))}


def behaviour(t: np.ndarray, samples: dict, entered_at: float, rudder_max: float) -> dict:
    """What the boat did before it entered the target area (the whole run if it never did).

    Returns ``irons_fraction`` (head to wind, |AWA| < 35 deg, and surge < 0.5 m/s),
    ``rudder_stop_fraction`` (rudder within 1 deg of its stop), the mean surge [m/s], the largest
    |heel| [deg] and the controller mode most often in use.

    Parameters
    ----------
    t : numpy.ndarray
        Sample times [s].
    samples : dict
        ``surge`` [m/s], ``awa`` (apparent wind angle, rad), ``rudder`` [rad], ``heel`` [rad] and
        ``mode`` (the controller's), at times ``t``.
    entered_at : float
        When the boat entered the target area [s], nan if never.
    rudder_max : float
        The rudder's stop [rad].
    """
    nan = float("nan")
    if t.size == 0:
        return {"irons_fraction": nan, "rudder_stop_fraction": nan, "surge_mean": nan, "heel_max_deg": nan,
                "main_mode": ""}
    before = t < entered_at if math.isfinite(entered_at) else np.ones(t.size, dtype=bool)
    if not before.any():
        before = np.ones(t.size, dtype=bool)
    surge = np.asarray(samples["surge"])[before]
    awa = np.abs(np.asarray(samples["awa"]))[before]
    rudder = np.abs(np.asarray(samples["rudder"]))[before]
    modes = [m for m, b in zip(samples["mode"], before, strict=True) if b]
    return {"irons_fraction": float(np.mean((awa < math.radians(IRONS_AWA_DEG)) & (surge < IRONS_SURGE))),
            "rudder_stop_fraction": float(np.mean(rudder > rudder_max - math.radians(1.0))),
            "surge_mean": float(surge.mean()),
            "heel_max_deg": math.degrees(float(np.max(np.abs(np.asarray(samples["heel"])[before])))),
            "main_mode": max(set(modes), key=modes.count) if modes else ""}


def after_entry(t: np.ndarray, d: np.ndarray, entered_at: float, d_t: float = PAPER_D_T) -> dict:
    """What the boat does once in the target area, from sampled distances ``d`` [m] at ``t`` [s].

    The boat enters at d = d_T, so the task's ``max_distance_after_entry`` is never below
    ~d_T whatever follows. The paper's "stays below 6.4 m after entering" can only mean the
    excursions after the approach, so we also measure from the *stop*: the first local minimum
    of d after entry (``stopped_at`` [s], ``stop_distance`` [m]), and from there
    ``max_after_stop`` [m], the time to the first d >= 6.4 m (scaled with d_T) and to the first
    exit from the target area (``to_paper_bound_s``, ``to_first_exit_s``, nan when it does not
    happen), and the number of exits after entry.

    Parameters
    ----------
    t : numpy.ndarray
        Sample times [s].
    d : numpy.ndarray
        Distances to the target [m] at times ``t``.
    entered_at : float
        When the boat entered the target area [s], nan if never.
    d_t : float
        The target area's radius [m].
    """
    nan = float("nan")
    out = {"stopped_at": nan, "stop_distance": nan, "max_after_stop": nan, "to_paper_bound_s": nan,
           "to_first_exit_s": nan, "exits": 0}
    if not math.isfinite(entered_at) or t.size == 0:
        return out
    after = t >= entered_at - 1e-9
    ta, da = t[after], d[after]
    if ta.size < 2:
        return out
    rising = np.flatnonzero(np.diff(da) > 0.0)
    i = int(rising[0]) if rising.size else ta.size - 1
    out.update(stopped_at=float(ta[i]), stop_distance=float(da[i]), max_after_stop=float(da[i:].max()))
    bound = PAPER_MAX_M * d_t / PAPER_D_T
    hit = np.flatnonzero(da[i:] >= bound)
    if hit.size:
        out["to_paper_bound_s"] = float(ta[i + hit[0]] - ta[i])
    outside = da >= d_t
    if outside.any():
        out["to_first_exit_s"] = float(ta[np.argmax(outside)] - ta[i])
        out["exits"] = int(np.count_nonzero(outside[1:] & ~outside[:-1]) + (1 if outside[0] else 0))
    return out
