"""Hull geometry: the canoe body that floats, and the quadratures the force models integrate over.

The canoe body is deliberately simple so that every hydrostatic quantity has a closed form
the tests can check the numerical integration against:

* planform (waterline half-breadth) b(x) = b0 (1 - (2x/L)^2), x in [-L/2, L/2];
* sections are half-ellipses of half-breadth b(x) and depth t(x) = t0 (1 - (2x/L)^2)
  below the design waterline;
* topsides are ruled straight from the waterline edge (b(x), 0) up to the deck edge
  (k b(x), freeboard), k = ``deck_half_beam / half_beam`` >= 1: vertical when k = 1 (the
  default), flared outward when k > 1 (a modern yacht's maximum beam is at the deck);
* a flat deck at height ``freeboard``.

Everything below the waterline is the canoe body, so the upright closed forms below (and the
strip-theory added mass, radiation damping and wetted surface built on them) do not depend on
the flare; the flare only adds volume once a deck edge goes toward the water at large heel.

Keel and rudder volumes are neglected in the buoyancy (a few per cent of the displacement,
stated in each boat's xml README).

Closed forms (s = 2x/L, integrals of (1 - s^2)^k over s in [-1, 1] times L/2):

* volume            V   = (pi/2) b0 t0 L (8/15)
* centre of buoyancy z_B = -(4 / 3pi) t0 (16/35)/(8/15) = -(8 / 7pi) t0
* waterplane area   A_wp = (4/3) b0 L
* transverse inertia I_T = (2/3) b0^3 L (16/35) = (32/105) b0^3 L
* longitudinal inertia I_L = b0 L^3 / 15
* strip-theory added mass (half-ellipse section, high-frequency limit, Faltinsen 1990 ch. 2):
  heave a33 = rho (pi/2) int b^2 dx = rho (pi/2) b0^2 L (8/15);
  pitch a55 = rho (pi/2) int b^2 x^2 dx = rho (pi/2) b0^2 (2 L^3 / 105).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..jit.ordered import elementwise, gauss_legendre


@dataclass(frozen=True)
class HullShape:
    """Canoe body and topside dimensions, metres.

    Parameters
    ----------
    length : float
        L, waterline length, m.
    half_beam : float
        b0, maximum waterline half-breadth (midship), m.
    canoe_draft : float
        t0, maximum depth of the canoe body below the waterline, m.
    freeboard : float
        Height of the flat deck above the waterline, m.
    deck_half_beam : float or None
        Midship deck half-breadth, m, >= ``half_beam``; None: equal to ``half_beam`` (no flare).
    """

    length: float
    half_beam: float
    canoe_draft: float
    freeboard: float
    deck_half_beam: float | None = None

    def __post_init__(self):
        for name in ("length", "half_beam", "canoe_draft", "freeboard"):
            value = getattr(self, name)
            if not np.isfinite(value) or value <= 0.0:
                raise ValueError(f"hull {name} must be a positive finite length in m, got {value!r}")
        deck = self.deck_half_beam
        if deck is not None and (not np.isfinite(deck) or deck < self.half_beam):
            raise ValueError(f"hull deck_half_beam must be >= half_beam ({self.half_beam!r} m), "
                             f"got {deck!r}")

    @property
    def flare(self) -> float:
        """k = deck half-breadth / waterline half-breadth at every station (1: vertical sides)."""
        return 1.0 if self.deck_half_beam is None else self.deck_half_beam / self.half_beam

    def fullness(self, x):
        """1 - (2x/L)^2: the waterline half-breadth b(x) and the section depth t(x) at body x
        over their midship values b0 and t0.

        Parameters
        ----------
        x : float or numpy.ndarray
            Body x from midship, m.
        """
        return 1.0 - (2.0 * x / self.length) ** 2


def volume(h: HullShape) -> float:
    """Displaced volume at the design waterline, m^3.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    return 0.5 * np.pi * h.half_beam * h.canoe_draft * h.length * 8.0 / 15.0


def centre_of_buoyancy_z(h: HullShape) -> float:
    """Height of the centre of buoyancy above the waterline (negative: below), m.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    return -8.0 / (7.0 * np.pi) * h.canoe_draft


def waterplane_area(h: HullShape) -> float:
    """Waterplane area A_wp, m^2.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    return 4.0 / 3.0 * h.half_beam * h.length


def centre_of_flotation_x(h: HullShape) -> float:
    """Centroid of the upright waterplane forward of CO, m: 0, the planform is fore-aft symmetric.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    return 0.0


def bm_transverse(h: HullShape) -> float:
    """Transverse metacentric radius BM = I_T / V, m.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    return 32.0 / 105.0 * h.half_beam**3 * h.length / volume(h)


def bm_longitudinal(h: HullShape) -> float:
    """Longitudinal metacentric radius BM_L = I_L / V, m.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    """
    return h.half_beam * h.length**3 / 15.0 / volume(h)


def gm_transverse(h: HullShape, z_g: float) -> float:
    """Transverse metacentric height GM_t = z_B + BM - z_G, m.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    z_g : float
        Height of the centre of gravity above the waterline (body z), m.
    """
    return centre_of_buoyancy_z(h) + bm_transverse(h) - z_g


def gm_longitudinal(h: HullShape, z_g: float) -> float:
    """Longitudinal metacentric height GM_L = z_B + BM_L - z_G, m.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    z_g : float
        Height of the centre of gravity above the waterline (body z), m.
    """
    return centre_of_buoyancy_z(h) + bm_longitudinal(h) - z_g


def heave_added_mass(h: HullShape, rho: float) -> float:
    """Strip-theory heave added mass a33 = -Z_wdot, kg.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    rho : float
        Water density, kg/m^3.
    """
    return rho * 0.5 * np.pi * h.half_beam**2 * h.length * 8.0 / 15.0


def pitch_added_inertia(h: HullShape, rho: float) -> float:
    """Strip-theory pitch added inertia a55 = -M_qdot, kg m^2.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    rho : float
        Water density, kg/m^3.
    """
    return rho * 0.5 * np.pi * h.half_beam**2 * 2.0 * h.length**3 / 105.0


def wetted_surface(h: HullShape, n: int = 200) -> float:
    """Wetted surface of the canoe body (half-ellipse perimeters integrated along x), m^2.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    n : int
        Number of Gauss-Legendre stations along x.
    """
    x, w = gauss_legendre(n)
    x = 0.5 * h.length * x
    f = h.fullness(x)
    a, b = h.half_beam * f, h.canoe_draft * f
    # Ramanujan's second approximation of the ellipse perimeter, halved.
    hh = ((a - b) / (a + b)) ** 2
    half_perimeter = 0.5 * np.pi * (a + b) * (1.0 + 3.0 * hh / (10.0 + np.sqrt(4.0 - 3.0 * hh)))
    return float(np.sum(w * half_perimeter) * 0.5 * h.length)


def design_for(length: float, displaced_volume: float, gm: float, z_g: float,
               freeboard: float, flare: float = 1.0) -> HullShape:
    """The hull of given length and displacement whose transverse GM equals ``gm``.

    Solves V = (4 pi / 15) b0 t0 L and GM_t(b0, t0) = gm for (b0, t0) with brentq. ``flare``
    (deck half-breadth / waterline half-breadth, >= 1) shapes the topsides only: it leaves the
    upright V, z_B, BM and so GM unchanged.

    Parameters
    ----------
    length : float
        Waterline length L, m.
    displaced_volume : float
        Displaced volume V at the design waterline, m^3.
    gm : float
        Transverse metacentric height wanted, m.
    z_g : float
        Height of the centre of gravity above the waterline (body z), m.
    freeboard : float
        Height of the deck above the waterline, m.
    flare : float
        Deck half-breadth / waterline half-breadth, >= 1 (1: vertical topsides).

    Returns
    -------
    HullShape
    """
    area = displaced_volume / (4.0 * np.pi / 15.0 * length)  # b0 * t0

    def gm_error(b0):
        return gm_transverse(HullShape(length, b0, area / b0, freeboard), z_g) - gm

    b0 = brentq(gm_error, 0.02 * length, 0.5 * length, xtol=1e-12)
    return HullShape(length, b0, area / b0, freeboard,
                     deck_half_beam=None if flare == 1.0 else flare * b0)


@dataclass(frozen=True)
class ColumnQuadrature:
    """Vertical prisms (columns along body z) that tile the hull's waterplane footprint.

    Column k stands at body (x[k], y[k]) with footprint area ``area[k]`` and spans body z from
    ``z_bottom[k]`` (the canoe-body bottom, or the flared topside outboard of the waterline) to
    ``z_top[k]`` (the deck). The buoyancy of each column is integrated exactly along its axis;
    only (x, y) is discretised.

    Parameters
    ----------
    x, y : numpy.ndarray
        Body position (x forward, y port) of each column, m.
    area : numpy.ndarray
        Footprint area of each column (quadrature weight), m^2.
    z_bottom, z_top : numpy.ndarray
        Body z of each column's bottom and top, m (z up, 0 on the design waterline).
    """

    x: np.ndarray
    y: np.ndarray
    area: np.ndarray
    z_bottom: np.ndarray
    z_top: np.ndarray

    def array(self) -> np.ndarray:
        """The columns as the force kernels take them: shape (5, n), C-contiguous, rows x, y,
        area, z_bottom, z_top."""
        return np.ascontiguousarray(np.vstack([self.x, self.y, self.area, self.z_bottom, self.z_top]))


def column_quadrature(h: HullShape, nx: int = 24, ntheta: int = 16,
                      nflare: int | None = None) -> ColumnQuadrature:
    """Gauss-Legendre in x, y = b(x) sin(theta) with the midpoint rule in theta.

    The substitution makes the half-ellipse depth t cos(theta) and the strip width
    b cos(theta) dtheta smooth, so the upright volume is integrated exactly.

    With flared topsides (``h.flare > 1``) each side gets ``nflare`` more columns per station
    (default ntheta // 2) over the band b(x) < |y| < k b(x), midpoint rule in |y|: their bottom
    is the topside, z = freeboard (|y| - b) / ((k - 1) b), taken at the column's centre, which
    integrates the linear topside exactly wherever a column is wholly wet or dry.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    nx : int
        Gauss-Legendre stations along x.
    ntheta : int
        Midpoint-rule columns across each station's canoe body.
    nflare : int or None
        Columns per side per station over the flare band; None: ``ntheta // 2``.

    Returns
    -------
    ColumnQuadrature
    """
    xg, wg = gauss_legendre(nx)
    x1 = 0.5 * h.length * xg
    wx = 0.5 * h.length * wg
    f = h.fullness(x1)
    dtheta = np.pi / ntheta
    theta = -0.5 * np.pi + (np.arange(ntheta) + 0.5) * dtheta
    b = (h.half_beam * f)[:, None]
    t = (h.canoe_draft * f)[:, None]
    x = np.broadcast_to(x1[:, None], (nx, ntheta))
    sin, cos = elementwise(math.sin, theta), elementwise(math.cos, theta)  # numpy's vary by CPU
    y = b * sin[None, :]
    area = wx[:, None] * b * cos[None, :] * dtheta
    z_bottom = -t * cos[None, :]
    z_top = np.full((nx, ntheta), h.freeboard)
    parts = [(x, y, area, z_bottom, z_top)]
    if h.flare > 1.0:
        nf = ntheta // 2 if nflare is None else nflare
        u = (np.arange(nf) + 0.5) / nf  # fraction of the way from the waterline to the deck edge
        band = (h.flare - 1.0) * b  # (nx, 1): width of the flare band
        xf = np.broadcast_to(x1[:, None], (nx, nf))
        yf = b + u[None, :] * band
        af = wx[:, None] * band / nf * np.ones((1, nf))
        zf = np.broadcast_to(h.freeboard * u[None, :], (nx, nf))
        tf = np.full((nx, nf), h.freeboard)
        parts += [(xf, yf, af, zf, tf), (xf, -yf, af, zf, tf)]
    return ColumnQuadrature(*(np.ascontiguousarray(
        np.concatenate([np.ravel(part[i]) for part in parts]), dtype=float) for i in range(5)))


def strip_quadrature(h: HullShape, n: int = 16):
    """Gauss-Legendre stations along the hull for the cross-flow strip integrals.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    n : int
        Number of stations.

    Returns
    -------
    x : numpy.ndarray
        Station positions along body x, m.
    weight : numpy.ndarray
        Quadrature weights, m.
    draft : numpy.ndarray
        Draft T(x) = t(x), the canoe-body depth at each station, m.
    """
    xg, wg = gauss_legendre(n)
    x = 0.5 * h.length * xg
    w = 0.5 * h.length * wg
    draft = h.canoe_draft * h.fullness(x)
    return x, w, draft
