"""The 11:Metre, made from its class dimensions, held against ORC's polar of the class; the Wille
yacht as built beside it; the canoe body's residuary resistance against the Delft tank.

**The polar.** Every point is a `heading_hold` run on heading 0 in a steady wind (no gusts, no
wander, no start jitter: one deterministic run per point, so N = 1 and no interval) from TWA off
the starboard bow, under a fixed sail angle, with ORC's 350 kg crew on the weather rail; the
point's speed is the mean over the last 20 s of 60 s at its best trim, found in two passes: the
sail angles 10, 20, ... 60 deg at full sail, then the best of them -5, -2.5, +2.5 and +5 deg
(the speed changes by up to 9 % between sail angles 5 deg apart near the best). Where the boat
heels more than 10 deg at full sail, the second pass also tries the depowering of
`sailmujoco.boat.trim` at the best angle and 2.5 and 5 deg either side: the main reefed to 0.85
of its luff (`boat.reef`), the rig's camber flattened to 0.62 of it (`boat.flat`, ORC's lowest
flat), and both; below 10 deg of heel there is nothing to depower. "Full sail" is the same boat
at its best sail angle with neither reef nor flattening. The wind speed is ORC's TWS at 10 m,
which is the height of every task's wind. ORC's fixed angles 52, 60, 75 and 90 deg at TWS 6, 10
and 16 kn, and the beat as the best VMG over our upwind angles (33, 36, 39, 42 and 45 deg and the fixed
ones) against ORC's beat; ORC's polar from 110 deg assumes a spinnaker, which no boat here
carries, so the reaches and runs are left out.

**The switches** (at TWS 6 and 16 kn, TWA 52 and 90 deg, and for flat sails and for ORC's areas
without surge damping at every angle of those winds, beat included; each at full sail against the
boat at full sail): the two sails each in its own flow (`rig_interaction="none"`), the main alone
(`boat.headsail=False`), flat-plate sails (`boat.camber=0`, the papers' form), the hull's friction
alone (`resistance="friction"`, no wave-making), the papers' sail coefficients
(`foils="paper"`), no crew (`boat.crew=False`), ORC's measured sail areas, the main's roach
counted (`boat.areas="orc"`: main 29.43 m2 and genoa 13.96 m2 against the class's 22.83 and
15.22), no linear surge damping (`boat.surge_damping=False`: the resistance a VPP has, friction
and wave-making alone), and the last two together.

**The tank.** For each of the Delft Series-1 hulls (Gerritsma, Onnink & Versluis 1981), the canoe
body of this project (parabolic planform, half-elliptic sections) of that hull's slenderness
L/V^(1/3) and length-beam ratio L/B; its residuary resistance by the boat's own model
(`sailmujoco.forces.resistance`, Keuning & Katgert 2008) at the tank's Froude numbers against
the tank's measurement. The canoe body's form fixes the rest: B/T follows from the two (its block
coefficient is 2 pi / 15), its prismatic coefficient is 8/15 = 0.533 and its LCB is midship (the
tank's hulls: Cp 0.53-0.60, LCB 0 to 5 % of L aft).
"""

from __future__ import annotations

import math
from importlib import resources

import numpy as np
import pandas as pd

from sailmujoco.boat.hull import HullShape
from sailmujoco.constants import GRAVITY
from sailmujoco.design import polar
from sailmujoco.design.reference_polar import KNOT, read_reference_polar
from sailmujoco.forces.resistance import delft_hull, pack_resistance, residuary_surge_force
from sailmujoco.study import Results, Runs

NAME = "real_boats"
TITLE = "Real boats: the 11:Metre made from its class dimensions against ORC's polar, and the Delft tank"
BOAT = "eleven_metre"
VIDEO = {"boat": BOAT, "task": "heading_hold", "controller": "fixed_sail", "seconds": 60.0,
         "wind_speed": 10 * KNOT, "wind_from_deg": 60.0, "gusts": False, "wander": False}
SEEDS = 1  # the polar's runs are deterministic (steady wind, fixed start): one run per point
TWS_KN = (6.0, 10.0, 16.0)
FIXED_TWA_DEG = (52.0, 60.0, 75.0, 90.0)
BEAT_TWA_DEG = (33.0, 36.0, 39.0, 42.0, 45.0)
SAILS_DEG = (10.0, 20.0, 30.0, 40.0, 50.0, 60.0)  # the first pass, at full sail
FINER_DEG = (-5.0, -2.5, 2.5, 5.0)  # the second pass: around the first pass's best
# the depowered trims (reef, flat) the second pass tries where the boat heels beyond DEPOWER_HEEL_DEG
DEPOWERED = ((0.85, 1.0), (1.0, 0.62), (0.85, 0.62))
DEPOWER_HEEL_DEG = 10.0
FULL_SAIL = {"boat.reef": 1.0, "boat.flat": 1.0}
DURATION_S = 60.0
CHECK_TWS_KN = (6.0, 16.0)
CHECK_TWA_DEG = (52.0, 90.0)
# case -> (boat, sweep options, what it changes)
CASES = {
    "as built": (BOAT, {}, "the 11:Metre as made from its dimensions, at its best trim"),
    "each sail alone": (BOAT, {"env.rig_interaction": "none"}, "no interaction between the sails"),
    "main alone": (BOAT, {"boat.headsail": False}, "no jib"),
    "friction only": (BOAT, {"env.resistance": "friction"}, "no wave-making resistance"),
    "flat sails": (BOAT, {"boat.camber": 0.0}, "flat-plate sails, the papers' form"),
    "paper sail": (BOAT, {"env.foils": "paper"}, "Saoud's sail C_N and the papers' foils"),
    "no crew": (BOAT, {"boat.crew": False}, "no crew on the rail"),
    "ORC's sail areas": (BOAT, {"boat.areas": "orc"}, "ORC's measured sail areas, the roach counted"),
    "no surge damping": (BOAT, {"boat.surge_damping": False}, "no linear surge damping (a VPP's resistance)"),
    "ORC's areas, no surge damping": (BOAT, {"boat.areas": "orc", "boat.surge_damping": False},
                                      "ORC's sail areas and no linear surge damping"),
    "wille_yacht": ("wille_yacht", {}, "the Wille yacht as built (main only)"),
}
# the switches that sail every angle of the lightest and strongest winds, beat included, so that each
# point outside 10 % can be held against them
CAUSES = ("flat sails", "ORC's areas, no surge damping")
TANK_FILE = "dsyhs_series1_residuary_resistance.csv"
ORC = "orc:eleven_metre"


def axes(case: str, smoke: bool) -> tuple[tuple, tuple, tuple, float]:
    """(TWS kn, TWA deg, sail angles deg, duration s) sailed in ``case``.

    Parameters
    ----------
    case : str
        A key of :data:`CASES`.
    smoke : bool
        The short pass.
    """
    if smoke:
        return (10.0,), (52.0, 90.0), (20.0, 40.0), 30.0
    if case == "as built":
        return TWS_KN, BEAT_TWA_DEG + FIXED_TWA_DEG, SAILS_DEG, DURATION_S
    if case == "wille_yacht":
        return TWS_KN, FIXED_TWA_DEG, SAILS_DEG, DURATION_S
    if case in CAUSES:
        return CHECK_TWS_KN, BEAT_TWA_DEG + FIXED_TWA_DEG, SAILS_DEG, DURATION_S
    return CHECK_TWS_KN, CHECK_TWA_DEG, SAILS_DEG, DURATION_S


def slug(case: str) -> str:
    """``case`` as a file name: letters and digits, anything else an underscore.

    Parameters
    ----------
    case : str
        A key of :data:`CASES` (or "full sail").
    """
    return "".join(ch if ch.isalnum() else "_" for ch in case)


def folder(case: str) -> str:
    """The sweep folder of ``case``.

    Parameters
    ----------
    case : str
        A key of :data:`CASES`.
    """
    return "sweep-" + slug(case)


def runs(smoke: bool, seeds=(0,)) -> Runs:
    """The first pass: every case's polar as one sweep, every TWS x TWA x sail angle at full sail.

    Parameters
    ----------
    smoke : bool
        The short pass (one wind, two angles, two sail angles, 30 s).
    seeds : sequence of int
        Unused: the runs are deterministic (one per point).
    """
    sweeps = []
    for case, (boat, options, _) in CASES.items():
        if smoke and case not in ("as built", "each sail alone"):
            continue
        tws, twa, sails, duration = axes(case, smoke)
        spec = polar.polar_spec(boat, "fixed_sail", [s * KNOT for s in tws], twa, duration=duration,
                                controller_grid={"controller.sail_deg": list(sails)}, options=dict(options))
        spec["name"] = f"{NAME}-{folder(case)}"
        sweeps.append((spec, folder(case)))
    return Runs(sweeps=tuple(sweeps), label=f"{NAME} polars")


def more_runs(results: Results, smoke: bool) -> Runs:
    """The second pass: around each point's best first-pass sail angle, the finer angles at full
    sail and, where the boat heeled beyond :data:`DEPOWER_HEEL_DEG`, the depowered trims (the
    Wille yacht keeps its first pass: ORC is only its ceiling).

    Parameters
    ----------
    results : sailmujoco.study.Results
        The first pass's tables.
    smoke : bool
        The short pass (the angles 2.5 deg either side; the depowered trims at the best angle).
    """
    finer = (-2.5, 2.5) if smoke else FINER_DEG
    around = (0.0,) if smoke else (0.0, *FINER_DEG)
    sweeps = []
    for case, (boat, options, _) in CASES.items():
        if case == "wille_yacht" or folder(case) not in results.sweeps:
            continue
        table = results.sweeps[folder(case)]
        ok = table[table["status"] == "ok"]
        best = ok.loc[ok.groupby(["task.wind_speed", "task.wind_from_deg"])["steady_speed"].idxmax()]
        keys = ["task.wind_speed", "task.wind_from_deg", "controller.sail_deg"]
        trims = case == "as built"
        if trims:
            keys += ["boat.reef", "boat.flat"]
        rows = []  # one per run, the values of ``keys``
        for _, r in best.iterrows():
            tws, twa, sail = (float(r[key]) for key in keys[:3])
            rows += [(tws, twa, sail + d, 1.0, 1.0) for d in finer if sail + d > 0.0]
            if trims and abs(math.degrees(r["steady_heel"])) > DEPOWER_HEEL_DEG:
                rows += [(tws, twa, sail + d, reef, flat) for reef, flat in DEPOWERED
                         for d in around if sail + d > 0.0]
        if rows:
            spec = polar.polar_spec(boat, "fixed_sail", [], [], duration=axes(case, smoke)[3],
                                    options=dict(options))
            spec["zip"] = {key: [row[k] for row in rows] for k, key in enumerate(keys)}
            spec["name"] = f"{NAME}-{folder(case)}-finer"
            sweeps.append((spec, f"{folder(case)}/finer"))
    return Runs(sweeps=tuple(sweeps), label=f"{NAME} finer sail angles and depowered trims")


def reference():
    """ORC's polar of the 11:Metre (the package's copy)."""
    return read_reference_polar(ORC)


def tank() -> pd.DataFrame:
    """The Delft Series-1 tank data (the package's copy, its header the source)."""
    path = resources.files("sailmujoco.data").joinpath(TANK_FILE)
    return pd.read_csv(path, comment="#")


def canoe_body(l_over_volume: float, l_over_b: float, length: float = 10.0) -> HullShape:
    """This project's canoe body of slenderness L/V^(1/3) and length-beam ratio L/B.

    V = (4 pi / 15) b0 t0 L, b0 = L / (2 L/B): t0 = V / ((4 pi / 15) b0 L).

    Parameters
    ----------
    l_over_volume, l_over_b : float
        The two ratios.
    length : float
        L, m (the residuary resistance per weight at a Froude number does not depend on it).
    """
    volume = (length / l_over_volume) ** 3
    half_beam = 0.5 * length / l_over_b
    return HullShape(length=length, half_beam=half_beam,
                     canoe_draft=volume / (4.0 * math.pi / 15.0 * half_beam * length), freeboard=0.1 * length)


def tank_comparison(rho: float = 1025.0) -> pd.DataFrame:
    """Per tank hull and Froude number: the tank's R_r / (rho g V) x 1000 and ours, and our hull's B/T.

    Parameters
    ----------
    rho : float
        Water density, kg/m^3 (it cancels).
    """
    data = tank()
    rows = []
    for (lcb, cp, lv, bt, lb), group in data.groupby(["lcb", "cp", "l_over_displ13", "b_over_t", "l_over_b"],
                                                     sort=False):
        h = canoe_body(lv, lb)
        d = delft_hull(h)
        block = pack_resistance(d, rho, GRAVITY)
        weight = rho * GRAVITY * d.volume
        for fn, measured in zip(group["fn"], group["rr_per_weight_x1000"], strict=True):
            u = fn * math.sqrt(GRAVITY * h.length)
            ours = -residuary_surge_force(u, 0.0, block) / weight * 1000.0
            rows.append({"lcb": lcb, "cp": cp, "l_over_displ13": lv, "b_over_t": bt, "l_over_b": lb,
                         "our_b_over_t": d.beam / d.draft, "fn": fn, "tank": measured, "ours": ours})
    table = pd.DataFrame(rows)
    table["ratio"] = np.where(table["tank"] > 0, table["ours"] / table["tank"].where(table["tank"] > 0), np.nan)
    return table
