"""Windage: the air drag of the hull's topsides and of the mast (the sail is forces/sail.py).

Neither Wille's nor Saoud's model has it; Viel's has it as p1 a_tw^2 on the true wind (eqs.
4-5). Here it acts on the apparent wind at each element, with the drag areas taken from the
boat's dimensions:

* **Topsides** (a low bluff body, length L, height = freeboard, width = deck beam): the wind
  load of a ship in Fossen (2011), *Handbook of Marine Craft Hydrodynamics and Motion
  Control*, §8.1 (2021 edition §10.1), X = 1/2 rho_a V^2 C_X A_F, Y = 1/2 rho_a V^2 C_Y A_L,
  C_X = c_x cos(gamma), C_Y = c_y sin(gamma), gamma the relative wind's angle off the bow,
  with c_x in [0.50, 0.90] and c_y in [0.70, 0.95] for ships. With V cos(gamma) = V_x this is
  (per body axis, Hoerner's independence principle)

      F_x = 1/2 rho_a c_x A_F |V| V_x,   F_y = 1/2 rho_a c_y A_L |V| V_y

  where V is the air's velocity relative to the element's centroid, in the body x-y plane.
  We take the middle of Fossen's ranges, c_x = 0.7, c_y = 0.8 (guess: a yacht's rounded low
  topsides are no blunter than a ship's). A_L = L x freeboard (the hull's vertical topsides,
  sailmujoco/boat/hull.py), A_F = deck beam x freeboard; the force acts at the centroid of the
  topsides, (centre of the deck's length, 0, freeboard / 2). Fossen's yaw term C_N = c_n
  sin(2 gamma) (the centroid's shift with gamma, c_n 0.05-0.20) is left out: our topsides
  are fore-aft symmetric.
* **Mast**: a circular cylinder from the deck to the masthead in cross-flow,
  F = 1/2 rho_a C_D d h |V_n| V_n with V_n the flow normal to the mast (body x-y), C_D = 1.2
  (Hoerner 1965, *Fluid-Dynamic Drag*, ch. 3: circular cylinder below the critical Reynolds
  number, Re = V d / nu ~ 1e4-1e5 here), at mid-height. Diameter d = 1.2 % of the luff
  (guess: an 8-9 m cruiser's mast section is 0.12-0.15 m with a 10.7 m luff).

Rigging, crew and the boom are left out (small next to these two; say so where it matters).
Each element sees the wind at its own height (the log profile and gusts of forces/wind.py).
"""

from __future__ import annotations

import math

import numpy as np

from ..jit.kernel import kernel

C_X_TOPSIDES = 0.7  # -, Fossen (2011) §8.1: c_x in [0.50, 0.90]; middle of the range
C_Y_TOPSIDES = 0.8  # -, Fossen (2011) §8.1: c_y in [0.70, 0.95]; middle of the range
C_D_MAST = 1.2  # -, Hoerner (1965) ch. 3, subcritical circular cylinder
MAST_DIAMETER_PER_LUFF = 0.012  # -, guess (module docstring)

# offsets inside the P block forces/boat.py gives this module
(W_AREA_FRONT, W_AREA_SIDE, W_HULL_X, W_HULL_Z, W_CX, W_CY,
 W_MAST_AREA, W_MAST_X, W_MAST_Z, W_MAST_CD, W_SIZE) = range(11)


def windage_geometry(params) -> dict:
    """Drag areas (m^2) and centroids (body frame, m) of the topsides and the mast.

    Parameters
    ----------
    params : BoatParams
        The boat.
    """
    h = params.hull
    s = params.sail
    deck_half_beam = h.half_beam * h.flare  # the deck's midship half-breadth (hull.py)
    mast_length = s.masthead_height - h.freeboard
    diameter = MAST_DIAMETER_PER_LUFF * s.luff
    return {
        "front_area": 2.0 * deck_half_beam * h.freeboard,
        "side_area": h.length * h.freeboard,
        "hull_point": (0.0, 0.0, 0.5 * h.freeboard),
        "mast_area": diameter * mast_length,
        "mast_point": (s.mast_x, 0.0, h.freeboard + 0.5 * mast_length),
        "mast_diameter": diameter,
    }


def pack_windage(params, block: np.ndarray) -> None:
    """Fill the windage block of the packed parameter array.

    Parameters
    ----------
    params : BoatParams
        The boat.
    block : numpy.ndarray, shape (W_SIZE,)
        The block, filled in place (layout W_* above).
    """
    g = windage_geometry(params)
    block[W_AREA_FRONT], block[W_AREA_SIDE] = g["front_area"], g["side_area"]
    block[W_HULL_X], block[W_HULL_Z] = g["hull_point"][0], g["hull_point"][2]
    block[W_CX], block[W_CY] = C_X_TOPSIDES, C_Y_TOPSIDES
    block[W_MAST_AREA] = g["mast_area"]
    block[W_MAST_X], block[W_MAST_Z] = g["mast_point"][0], g["mast_point"][2]
    block[W_MAST_CD] = C_D_MAST


@kernel
def topsides_force(flow, rho_air, cx, cy, area_front, area_side, out):
    """Topsides' drag (body frame) for the relative air velocity ``flow`` at their centroid.

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        Velocity of the air relative to the element's centroid, body frame (FLU), m/s; only
        x and y are read.
    rho_air : float
        Air density, kg/m^3.
    cx, cy : float
        Fossen's c_x and c_y, dimensionless.
    area_front, area_side : float
        A_F and A_L, m^2.
    out : numpy.ndarray, shape (3,)
        Receives the force, body frame, N.
    """
    speed = math.sqrt(flow[0] * flow[0] + flow[1] * flow[1])
    q = 0.5 * rho_air * speed
    out[0] = q * cx * area_front * flow[0]
    out[1] = q * cy * area_side * flow[1]
    out[2] = 0.0


@kernel
def mast_force(flow, rho_air, cd, area, out):
    """Mast's cross-flow drag (body frame; the mast stands along body z).

    Parameters
    ----------
    flow : numpy.ndarray, shape (3,)
        Velocity of the air relative to the element's centroid, body frame (FLU), m/s; only
        x and y are read.
    rho_air : float
        Air density, kg/m^3.
    cd : float
        Drag coefficient of the mast section, dimensionless.
    area : float
        Diameter x length of the mast, m^2.
    out : numpy.ndarray, shape (3,)
        Receives the force, body frame, N.
    """
    speed = math.sqrt(flow[0] * flow[0] + flow[1] * flow[1])
    q = 0.5 * rho_air * cd * area * speed
    out[0] = q * flow[0]
    out[1] = q * flow[1]
    out[2] = 0.0
