"""Static stability: righting moment against heel, geometric hull vs the papers' formulas.

``righting_curve`` heels the hull about its longitudinal axis, finds for each heel the heave
at which buoyancy equals weight (scipy brentq; trim is held level), and returns the righting
moment about the CG. The papers' formulas are Wille eq. 20, rho g V GM sin(phi) cos(phi), and
Saoud eq. 4, m g l_phi sin(phi); both are rho g V GM phi at small heel.
"""

from __future__ import annotations

import numpy as np
from scipy.optimize import brentq

from .constants import GRAVITY
from .forces.hydrostatics import submerged_volume
from .frames import matrix_from_euler
from .hull import column_quadrature
from .params import BoatParams


def _columns(p: BoatParams, nx: int, ntheta: int) -> np.ndarray:
    q = column_quadrature(p.hull, nx, ntheta)
    return np.ascontiguousarray(np.vstack([q.x, q.y, q.area, q.z_bottom, q.z_top]))


def equilibrium_heave(p: BoatParams, heel: float, columns: np.ndarray) -> float:
    """Height of CO (m) at which the heeled hull displaces its weight."""
    rot = matrix_from_euler(heel, 0.0, 0.0)
    target = p.displaced_volume
    span = p.hull.freeboard + p.hull.canoe_draft + p.hull.half_beam * 2

    def excess(z):
        return submerged_volume(z, rot, columns)[0] - target

    return brentq(excess, -span, span, xtol=1e-12)


def righting_moment(p: BoatParams, heel: float, columns: np.ndarray | None = None) -> float:
    """Geometric righting moment about the CG at ``heel`` (N m, positive restores)."""
    if columns is None:
        columns = _columns(p, 48, 48)
    rot = matrix_from_euler(heel, 0.0, 0.0)
    z = equilibrium_heave(p, heel, columns)
    vol, qx, qy, qz = submerged_volume(z, rot, columns)
    centroid = np.array([qx, qy, qz]) / vol
    lever = rot @ (centroid - np.array([p.cg_x, 0.0, p.cg_z]))  # world, from CG to B
    # buoyancy (0, 0, rho g V) at B: moment about world x = lever_y * F_z; restoring is -M_x
    return -p.rho_water * GRAVITY * vol * lever[1] * np.sign(np.cos(heel))


def righting_curve(p: BoatParams, heels) -> dict[str, np.ndarray]:
    """Righting moments (N m) over ``heels`` (rad): geometric, Wille eq. 20, Saoud eq. 4."""
    heels = np.asarray(heels, dtype=float)
    columns = _columns(p, 48, 48)
    stiffness = p.rho_water * GRAVITY * p.displaced_volume * p.gm_t
    return {
        "heel": heels,
        "geometric": np.array([righting_moment(p, h, columns) for h in heels]),
        "sin_cos": stiffness * np.sin(heels) * np.cos(heels),
        "sin": stiffness * np.sin(heels),
        "linear": stiffness * heels,
    }
