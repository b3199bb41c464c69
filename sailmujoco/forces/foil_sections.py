"""Section (2-D) coefficients of the keel and rudder: the NACA 0015 table and Wille's hydrofoil.

The Sheldahl & Klimas (1981, SAND80-2114) NACA 0015 table through 180 deg at eleven Reynolds
numbers, its bilinear lookup in (alpha, log10 Re), and the finite-span C_L, C_D that Wille
(2016a) eqs. 23-24 build from it. The foil frame and the sign of alpha are those of
:mod:`sailmujoco.forces.foil_geometry`.
"""

from __future__ import annotations

import math
from functools import lru_cache
from importlib import resources

import numpy as np

from ..frames import wrap_angle
from ..jit.kernel import kernel
from .damping import ittc_friction_coefficient


class SectionTable:
    """NACA 0015 section coefficients through 180 deg (Sheldahl & Klimas 1981, SAND80-2114).

    Attributes are plain arrays so they can be handed to compiled kernels.

    Parameters
    ----------
    alpha : array_like, shape (n_alpha,)
        Section angles of attack, rad, ascending, shared by every Reynolds number (the foil
        frame of :mod:`sailmujoco.forces.foil_geometry`).
    log_re : array_like, shape (n_re,)
        log10 of the Reynolds number of each table, ascending.
    cl, cd : array_like, shape (n_re, n_alpha)
        Section lift and drag coefficients c_l, c_d, one row per Reynolds number.

    Attributes
    ----------
    alpha, log_re, cl, cd : numpy.ndarray
        The parameters as contiguous float arrays.
    """

    def __init__(self, alpha, log_re, cl, cd):
        self.alpha = np.ascontiguousarray(alpha, dtype=float)
        self.log_re = np.ascontiguousarray(log_re, dtype=float)
        self.cl = np.ascontiguousarray(cl, dtype=float)
        self.cd = np.ascontiguousarray(cd, dtype=float)

    @property
    def reynolds(self) -> np.ndarray:
        return 10.0**self.log_re


def parse_section_table(text: str) -> SectionTable:
    """Parse the CACTUS-format NACA 0015 file shipped in ``sailmujoco/data``.

    Parameters
    ----------
    text : str
        The file's text: one ``Reynolds Number: <Re>`` header per table, each followed by rows of
        alpha (deg), c_l, c_d; every table on the same alpha grid.

    Returns
    -------
    SectionTable
        The tables, alpha converted to radians.
    """
    blocks: list[tuple[float, list[list[float]]]] = []
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("Reynolds Number:"):
            blocks.append((float(s.split(":", 1)[1]), []))
        elif blocks and s and (s[0].isdigit() or s[0] == "-"):
            blocks[-1][1].append([float(v) for v in s.split()])
    if not blocks:
        raise ValueError("no 'Reynolds Number:' blocks in the section table")
    alpha_deg = np.array(blocks[0][1])[:, 0]
    for re_, rows in blocks:
        if not np.array_equal(np.array(rows)[:, 0], alpha_deg):
            raise ValueError(f"section table at Re={re_:g} has a different alpha grid")
    cl = np.array([np.array(rows)[:, 1] for _, rows in blocks])
    cd = np.array([np.array(rows)[:, 2] for _, rows in blocks])
    log_re = np.log10([re_ for re_, _ in blocks])
    return SectionTable(np.radians(alpha_deg), log_re, cl, cd)


@lru_cache(maxsize=1)
def naca0015() -> SectionTable:
    """The shipped Sheldahl & Klimas NACA 0015 table (11 Reynolds numbers, 1e4 to 1e7)."""
    text = resources.files("sailmujoco.data").joinpath("naca0015_sheldahl_klimas.dat").read_text()
    return parse_section_table(text)


@kernel
def section_coefficients(alpha, reynolds, alpha_grid, log_re_grid, cl_table, cd_table):
    """Section (2-D) c_l, c_d at ``alpha`` (rad) and Reynolds number, bilinear in (alpha, log Re).

    Re is clamped to the table's range (1e4 to 1e7): the Reynolds number is picked from the
    flow at every call.

    Parameters
    ----------
    alpha : float
        Angle of attack, rad, in the foil frame of :mod:`sailmujoco.forces.foil_geometry`; wrapped to
        [-pi, pi).
    reynolds : float
        Reynolds number on the chord, -.
    alpha_grid, log_re_grid : numpy.ndarray, shapes (n_alpha,) and (n_re,)
        The table's angles (rad, ascending) and log10 Reynolds numbers (:class:`SectionTable`'s
        ``alpha`` and ``log_re``).
    cl_table, cd_table : numpy.ndarray, shape (n_re, n_alpha)
        The table's c_l and c_d (:class:`SectionTable`'s ``cl`` and ``cd``).

    Returns
    -------
    c_l, c_d : float
        Section lift and drag coefficients.
    """
    a = wrap_angle(alpha)
    n = alpha_grid.shape[0]
    i = np.searchsorted(alpha_grid, a) - 1
    i = min(max(i, 0), n - 2)
    ta = (a - alpha_grid[i]) / (alpha_grid[i + 1] - alpha_grid[i])
    lr = math.log10(max(reynolds, 1.0))
    m = log_re_grid.shape[0]
    if lr <= log_re_grid[0]:
        j, tr = 0, 0.0
    elif lr >= log_re_grid[m - 1]:
        j, tr = m - 2, 1.0
    else:
        j = np.searchsorted(log_re_grid, lr) - 1
        j = min(max(j, 0), m - 2)
        tr = (lr - log_re_grid[j]) / (log_re_grid[j + 1] - log_re_grid[j])
    cl_lo = cl_table[j, i] + ta * (cl_table[j, i + 1] - cl_table[j, i])
    cl_hi = cl_table[j + 1, i] + ta * (cl_table[j + 1, i + 1] - cl_table[j + 1, i])
    cd_lo = cd_table[j, i] + ta * (cd_table[j, i + 1] - cd_table[j, i])
    cd_hi = cd_table[j + 1, i] + ta * (cd_table[j + 1, i + 1] - cd_table[j + 1, i])
    return cl_lo + tr * (cl_hi - cl_lo), cd_lo + tr * (cd_hi - cd_lo)


@kernel
def hydrofoil_coefficients(alpha, reynolds, aspect_ratio, thickness_ratio,
                           alpha_grid, log_re_grid, cl_table, cd_table):
    """Finite-span C_L, C_D of the keel or rudder, Wille (2016a) eqs. 23-24.

    * Lift: Wille (2016a) eq. 23 with Asp_0 = infinity, because the Sheldahl & Klimas data are
      2-D section data: C_L = c_l / (1 + 2/Asp).
    * Drag: eq. 24, C_D = C_Di + 2 (1 + 2 t/c) C_F(Re). The paper says the table drag is the
      "induced" drag; a 2-D table holds no induced drag, so we read C_Di as the lift-dependent
      drag: the table's pressure drag above its zero-lift value, c_d(alpha) - c_d(0), plus the
      finite-span induced drag C_L^2 / (pi Asp). Eq. 24's friction term replaces the table's
      zero-lift drag, which is also how the thinner NACA 0009 keel differs from the 0015 table
      it borrows (no NACA 0009 table through 180 deg is available; the 0015 table stands in).

    Parameters
    ----------
    alpha : float
        Angle of attack, rad, in the foil frame of :mod:`sailmujoco.forces.foil_geometry`.
    reynolds : float
        Reynolds number on the chord, -.
    aspect_ratio : float
        Geometric aspect ratio Asp of the foil, -.
    thickness_ratio : float
        Thickness over chord t/c, -.
    alpha_grid, log_re_grid, cl_table, cd_table : numpy.ndarray
        The section table, as for :func:`section_coefficients`.

    Returns
    -------
    c_lift, c_drag : float
        C_L and C_D on the foil's planform area.
    """
    cl, cd = section_coefficients(alpha, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    _, cd0 = section_coefficients(0.0, reynolds, alpha_grid, log_re_grid, cl_table, cd_table)
    c_lift = cl / (1.0 + 2.0 / aspect_ratio)  # eq. 23
    c_friction = 2.0 * (1.0 + 2.0 * thickness_ratio) * ittc_friction_coefficient(reynolds)  # eq. 24
    c_drag = (cd - cd0) + c_lift * c_lift / (math.pi * aspect_ratio) + c_friction
    return c_lift, c_drag
