"""The hull on a coarse regular grid: where the sea's pressure and the water's motion are summed.

The calm-water buoyancy integrates the canoe body on fine columns
(:func:`sailmujoco.boat.hull.column_quadrature`, 24 x 16 and more). The sea's part of the force
(the water's surface moved by the waves and its pressure's change with depth,
:mod:`sailmujoco.forces.sea_hull`) varies over a wavelength, tens of metres for the waves that
move a boat, so it is summed on a grid of a few columns, regular in body x and y, so that each
component's phase over the grid is a product of two step phasors (no cosine per column).

Each cell (x_i, y_p), uniform steps dx = L / nx along the hull and dy = 2 k b0 / ny across
its deck's widest half-breadth k b0, holds up to two vertical columns (rows 2c and 2c + 1 of
``columns`` for cell c = i ny + p), split where the waterline's edge b(x_i) crosses it
(:class:`sailmujoco.boat.hull.HullShape`):

* the canoe body's part, |y| < b(x_i): its area dx times the overlap, so the grid's waterplane
  is the hull's up to the midpoint rule along x and the waves' change of buoyancy, rho g times
  the waterplane's integral of eta, is right to first order; its bottom the half-ellipse
  section's at the overlap's centre y_c;
* the flared topside's part, b(x_i) < |y| < k b(x_i) (none for vertical sides): its bottom the
  topside's height at its centre, dry in calm water until a crest or a heel reaches it;
* both have the deck as their top, their lever arm at (x_i, y_c) and share the cell's phases,
  taken at the canoe part's centre (the flare part's own offset, tenths of a metre, is left
  out of its phase).

Parts outside the deck have zero area and are skipped.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .hull import HullShape

GRID_STATIONS = 8  # cells along the hull (error against the fine columns: docs/physics.md)
GRID_ROWS = 4  # cells across the deck


@dataclass(frozen=True)
class HullGrid:
    """A regular grid of columns over the hull, centred on CO.

    Parameters
    ----------
    columns : numpy.ndarray, shape (5, 2 nx ny)
        Rows (x, y_c, area, z_bottom, z_top), m and m^2: cell c = i ny + p's canoe part in
        column 2c, its flare part in 2c + 1.
    dx, dy : float
        The grid's steps along body x and y, m.
    nx, ny : int
        Stations along x and rows across y.
    """

    columns: np.ndarray
    dx: float
    dy: float
    nx: int
    ny: int

    @property
    def stations(self) -> np.ndarray:
        """Body x of each station, m (the phase's x for every cell of that station)."""
        return (np.arange(self.nx) - 0.5 * (self.nx - 1)) * self.dx

    @property
    def rows(self) -> np.ndarray:
        """Body y of each row's centre, m (the phase's y)."""
        return (np.arange(self.ny) - 0.5 * (self.ny - 1)) * self.dy


def hull_grid(h: HullShape, nx: int = GRID_STATIONS, ny: int = GRID_ROWS) -> HullGrid:
    """The hull's columns on a regular nx x ny grid (module docstring).

    Parameters
    ----------
    h : HullShape
        The canoe body.
    nx : int
        Stations along the hull.
    ny : int
        Rows across the deck.
    """
    dx, dy = h.length / nx, 2.0 * h.half_beam * h.flare / ny
    grid = HullGrid(np.zeros((5, 2 * nx * ny)), dx, dy, nx, ny)
    cols = grid.columns
    for i, x in enumerate(grid.stations):
        f = h.fullness(x)
        b, t = h.half_beam * f, h.canoe_draft * f
        for p, y in enumerate(grid.rows):
            lo, hi = y - 0.5 * dy, y + 0.5 * dy
            c = 2 * (i * ny + p)
            canoe = (max(lo, -b), min(hi, b))
            if canoe[1] > canoe[0]:
                yc = 0.5 * (canoe[0] + canoe[1])
                depth = t * np.sqrt(max(1.0 - (yc / b) ** 2, 0.0))
                cols[:, c] = (x, yc, dx * (canoe[1] - canoe[0]), -depth, h.freeboard)
            side = 1.0 if y > 0.0 else -1.0  # the flare band on the cell's side
            band = sorted((side * b, side * b * h.flare))
            flare = (max(lo, band[0]), min(hi, band[1]))
            if h.flare > 1.0 and flare[1] > flare[0]:
                yc = 0.5 * (flare[0] + flare[1])
                bottom = h.freeboard * (abs(yc) - b) / ((h.flare - 1.0) * b)
                cols[:, c + 1] = (x, yc, dx * (flare[1] - flare[0]), bottom, h.freeboard)
    return grid


def section_depths(h: HullShape, grid: HullGrid) -> np.ndarray:
    """Depth of each station's section centroid below the waterline, -4 t(x) / (3 pi), m
    (negative): where the water's acceleration is taken for the diffraction force.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    grid : HullGrid
        The grid whose stations are used.
    """
    return -4.0 * h.canoe_draft * h.fullness(grid.stations) / (3.0 * np.pi)


def section_weights(h: HullShape, grid: HullGrid) -> np.ndarray:
    """Each station's share of the hull's added mass, proportional to b(x)^2 dx (the strip
    theory's sectional added mass of a half-ellipse, rho pi b^2 / 2, :mod:`sailmujoco.boat.hull`),
    summing to 1.

    Parameters
    ----------
    h : HullShape
        The canoe body.
    grid : HullGrid
        The grid whose stations are used.
    """
    w = h.fullness(grid.stations) ** 2
    return w / w.sum()
