"""Static stability: righting moment against heel, geometric hull vs the papers' formulas.

``righting_curve`` heels the hull about its longitudinal axis, finds for each heel the heave
at which buoyancy equals weight (scipy brentq; trim is held level), and returns the righting
moment about the CG. The papers' formulas are Wille eq. 20, rho g V GM sin(phi) cos(phi), and
Saoud eq. 4, m g l_phi sin(phi); both are rho g V GM phi at small heel.

``FloatingTable`` is what the 4-DOF mode (heave and pitch held) uses with geometric
hydrostatics: for each heel, the heave *and* trim at which the hull floats freely (weight
displaced, centre of buoyancy on the vertical through the CG; Newton's method), and the
righting moment there. Evaluating the buoyancy of the held pose instead (z = 0, trim 0) would
over-displace the heeled hull (+34 % at 20 deg on the yacht), which no floating boat does.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from ..boat.hull import column_quadrature
from ..boat.params import BoatParams
from ..constants import GRAVITY
from ..frames import matrix_from_euler
from ..jit.ordered import elementwise, least_squares_2x2, mat_vec
from .hydrostatics import submerged_volume


def _columns(p: BoatParams, nx: int, ntheta: int) -> np.ndarray:
    return column_quadrature(p.hull, nx, ntheta).array()


def equilibrium_heave(p: BoatParams, heel: float, columns: np.ndarray) -> float:
    """Height of CO (m) at which the heeled hull displaces its weight (trim level).

    Parameters
    ----------
    p : BoatParams
        The boat.
    heel : float
        Heel (rad).
    columns : ndarray
        The hull's column quadrature, (5, n): x, y, area, z_bottom, z_top of each column.
    """
    rot = matrix_from_euler(heel, 0.0, 0.0)
    target = p.displaced_volume
    span = p.hull.freeboard + p.hull.canoe_draft + 2 * p.hull.half_beam * p.hull.flare

    def excess(z):
        return submerged_volume(z, rot, columns)[0] - target

    return brentq(excess, -span, span, xtol=1e-12)


def righting_moment(p: BoatParams, heel: float, columns: np.ndarray | None = None) -> float:
    """Geometric righting moment about the CG at ``heel`` (N m, positive restores).

    Parameters
    ----------
    p : BoatParams
        The boat.
    heel : float
        Heel (rad).
    columns : ndarray
        The hull's column quadrature, (5, n): x, y, area, z_bottom, z_top of each column;
        default 48 x 48 columns.
    """
    vol, lever = _buoyancy_lever(p, heel, columns)
    # buoyancy (0, 0, rho g V) at B: moment about world x = lever_y * F_z; restoring is -M_x
    return -p.rho_water * GRAVITY * vol * lever[1] * np.sign(math.cos(heel))


def righting_arm(p: BoatParams, heel: float, columns: np.ndarray | None = None) -> float:
    """Righting arm GZ (m) at any heel in [0, pi], trim level, floating at its weight.

    GZ is the horizontal distance from the CG to the line of action of the buoyancy, positive
    where the moment turns the boat back upright, so that past 90 deg a negative GZ pushes it
    on toward inverted (its angle of vanishing stability is where GZ falls through zero).

    Parameters
    ----------
    p : BoatParams
        The boat.
    heel : float
        Heel (rad).
    columns : ndarray
        The hull's column quadrature, (5, n): x, y, area, z_bottom, z_top of each column;
        default 48 x 48 columns.
    """
    _, lever = _buoyancy_lever(p, heel, columns)
    return float(-lever[1])


def _buoyancy_lever(p: BoatParams, heel: float, columns) -> tuple[float, np.ndarray]:
    """(V, lever): the volume the boat displaces at ``heel`` (trim level, floating at its
    weight) and the world vector from its CG to the centre of buoyancy B."""
    if columns is None:
        columns = _columns(p, 48, 48)
    rot = matrix_from_euler(heel, 0.0, 0.0)
    vol, qx, qy, qz = submerged_volume(equilibrium_heave(p, heel, columns), rot, columns)
    centroid = np.array([qx, qy, qz]) / vol
    return vol, mat_vec(rot, centroid - np.array([p.cg_x, 0.0, p.cg_z]))  # world, from CG to B


def righting_curve(p: BoatParams, heels) -> dict[str, np.ndarray]:
    """Righting moments (N m) over ``heels`` (rad): geometric, Wille eq. 20, Saoud eq. 4.

    Parameters
    ----------
    p : BoatParams
        The boat.
    heels : array_like
        Heels (rad).

    Returns
    -------
    dict
        ``heel``, ``geometric``, ``sin_cos`` (Wille eq. 20), ``sin`` (Saoud eq. 4) and ``linear``
        (rho g V GM_t phi).
    """
    heels = np.asarray(heels, dtype=float)
    columns = _columns(p, 48, 48)
    stiffness = p.rho_water * GRAVITY * p.displaced_volume * p.gm_t
    return {
        "heel": heels,
        "geometric": np.array([righting_moment(p, h, columns) for h in heels]),
        "sin_cos": stiffness * elementwise(math.sin, heels) * elementwise(math.cos, heels),
        "sin": stiffness * elementwise(math.sin, heels),
        "linear": stiffness * heels,
    }


def floating_pose(p: BoatParams, heel: float, columns: np.ndarray,
                  guess: tuple[float, float] = (0.0, 0.0)) -> tuple[float, float]:
    """(height of CO, trim) in m and rad at which the hull heeled by ``heel`` floats freely.

    Two conditions: submerged volume = m / rho, and no pitch moment about the CG (the centre of
    buoyancy lies on the vertical through the CG). Newton's method from ``guess``.

    Parameters
    ----------
    p : BoatParams
        The boat.
    heel : float
        Heel (rad).
    columns : ndarray
        The hull's column quadrature, (5, n): x, y, area, z_bottom, z_top of each column.
    guess : tuple of float
        (height of CO, trim) to start from (m, rad).
    """
    target = p.displaced_volume
    cg = np.array([p.cg_x, 0.0, p.cg_z])
    length = p.hull.length

    def residual(x):
        z, trim = x
        rot = matrix_from_euler(heel, trim, 0.0)
        vol, qx, qy, qz = submerged_volume(z, rot, columns)
        if vol <= 0.0:
            return [-1.0, trim]
        lever = mat_vec(rot, np.array([qx, qy, qz]) / vol - cg)  # world, from CG to B
        return [vol / target - 1.0, lever[0] / length]

    # Newton with a fixed-step difference Jacobian (m, rad). scipy's hybr scales its first
    # steps by |x|, which is ~1e-16 at the upright solution, and stalls there.
    x = np.asarray(guess, dtype=float)
    f = np.asarray(residual(x))
    for _ in range(30):
        if np.max(np.abs(f)) < 1e-12:
            break
        step = 1e-7
        jac = np.column_stack([(np.asarray(residual(x + d)) - f) / step
                               for d in (np.array([step, 0.0]), np.array([0.0, step]))])
        # lstsq, not solve: near 90 deg heel the columns lie almost level, each wholly wet or
        # dry, and then no column's cut moves with trim (a zero Jacobian column); the minimum-
        # norm step leaves the trim where it is
        x = x - least_squares_2x2(jac, f)  # lstsq's, in a written order
        f = np.asarray(residual(x))
    if abs(f[0]) > 1e-9 and abs(f[1]) <= 1e-9:
        # there the volume is steep where a column is cut and flat between (continuous but
        # nearly a staircase in the heave), which Newton can cycle on: bracket it instead
        span = p.hull.freeboard + p.hull.canoe_draft + 2 * p.hull.half_beam * p.hull.flare
        x[0] = brentq(lambda z: residual((z, x[1]))[0], -span, span, xtol=1e-13, rtol=1e-15)
        f = np.asarray(residual(x))
    if np.max(np.abs(f)) > 1e-9:
        raise RuntimeError(f"{p.name}: no floating pose found at heel {np.degrees(heel):.1f} deg "
                           f"(residual {f})")
    return float(x[0]), float(x[1])


@dataclass(frozen=True)
class FloatingTable:
    """Heave, trim, displaced volume and righting moment of the freely floating hull per heel.

    Parameters
    ----------
    heel : numpy.ndarray
        Heel, rad, ascending over [-max, max].
    heave : numpy.ndarray
        Height of CO above the water surface, m.
    trim : numpy.ndarray
        Trim, rad, bow up.
    volume : numpy.ndarray
        Displaced volume, m^3.
    righting : numpy.ndarray
        Righting moment about the CG, about the horizontal heading axis, N m, positive restoring.
    """

    heel: np.ndarray
    heave: np.ndarray
    trim: np.ndarray
    volume: np.ndarray
    righting: np.ndarray


def floating_table(p: BoatParams, max_heel: float = np.radians(89.0),
                   step: float = np.radians(0.25)) -> FloatingTable:
    """The :class:`FloatingTable` of ``p`` on a uniform heel grid.

    Linear interpolation between nodes 0.25 deg apart changes the righting moment by < 1e-5 of its
    value.

    Parameters
    ----------
    p : BoatParams
        The boat.
    max_heel : float
        Largest heel of the grid (rad); the table mirrors it to -max_heel.
    step : float
        Heel between nodes (rad).
    """
    columns = _columns(p, 24, 16)  # the quadrature the physics step integrates
    n = int(round(max_heel / step))
    heels = np.arange(0, n + 1) * step
    heave, trim, volume, righting = (np.zeros(n + 1) for _ in range(4))
    guess = (0.0, 0.0)
    cg = np.array([p.cg_x, 0.0, p.cg_z])
    for i, h in enumerate(heels):
        guess = floating_pose(p, h, columns, guess)
        rot = matrix_from_euler(h, guess[1], 0.0)
        vol, qx, qy, qz = submerged_volume(guess[0], rot, columns)
        lever = mat_vec(rot, np.array([qx, qy, qz]) / vol - cg)
        heave[i], trim[i], volume[i] = guess[0], guess[1], vol
        righting[i] = -p.rho_water * GRAVITY * vol * lever[1]  # restoring: -M_x
    # the hull is port-starboard symmetric: mirror the starboard-down half
    return FloatingTable(np.concatenate([-heels[:0:-1], heels]),
                         np.concatenate([heave[:0:-1], heave]),
                         np.concatenate([trim[:0:-1], trim]),
                         np.concatenate([volume[:0:-1], volume]),
                         np.concatenate([-righting[:0:-1], righting]))


WILLE_WORKING_HEEL = np.radians(10.0)  # rad, phi_w of Wille (2016b) §4 (+-10 deg)


def gz_curves(p: BoatParams, heels, working_heels=(WILLE_WORKING_HEEL,)) -> dict[str, np.ndarray]:
    """Righting arms GZ (m) over ``heels``: geometric hull, Wille (2016a) eq. 20, Wille (2016b) eq. 66.

    The geometric hull floats freely (:func:`floating_table`); eq. 20 is GM_t sin(phi) cos(phi);
    eq. 66 is taken about each working heel phi_w in ``working_heels``.

    Eq. 66 is printed as rho g V GM_t ((1 - 2 sin^2 phi_w) phi + C_1) with eq. 67
    C_1 = rho g V GM_t cos(phi_w) sin(phi_w); read as the tangent of eq. 20 at phi_w (the
    printed form doubles rho g V GM_t in C_1 and drops phi_w from phi - phi_w):
    GZ = GM_t ((1 - 2 sin^2 phi_w) (phi - phi_w) + sin(phi_w) cos(phi_w)).

    Parameters
    ----------
    p : BoatParams
        The boat.
    heels : array_like
        Heels (rad, >= 0).
    working_heels : iterable of float
        Working heels phi_w of eq. 66 (rad).

    Returns
    -------
    dict
        ``geometric``, ``eq20`` and ``eq66_<phi_w in deg>`` (m).
    """
    heels = np.asarray(heels, dtype=float)
    table = floating_table(p, max_heel=max(float(heels.max()), np.radians(1.0)),
                           step=np.radians(0.5))
    weight = p.rho_water * GRAVITY * p.displaced_volume
    out = {"heel": heels,
           "geometric": np.interp(heels, table.heel, table.righting) / weight,
           "eq20": p.gm_t * elementwise(math.sin, heels) * elementwise(math.cos, heels)}
    for w in working_heels:
        out[f"eq66_{np.degrees(w):g}"] = p.gm_t * ((1.0 - 2.0 * math.sin(w) ** 2) * (heels - w)
                                                   + math.sin(w) * math.cos(w))
    return out


def gz_figure(path, boat: str = "wille_yacht", compare: BoatParams | None = None,
              working_heels_deg=(10.0, 25.0)) -> None:
    """Write the GZ-curve figure (PNG) of ``boat``: ours vs eq. 20 vs eq. 66.

    ``python -m sailmujoco.forces.stability --gz-figure PATH``.

    Parameters
    ----------
    path : path
        The PNG written.
    boat : str
        A registered boat.
    compare : BoatParams, optional
        Another hull of the same boat, drawn dashed.
    working_heels_deg : iterable of float
        Working heels of eq. 66 (deg).
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from ..boat.catalogue import get_boat

    p = get_boat(boat)
    heels = np.radians(np.arange(0.0, 89.01, 1.0))  # at 90 deg the columns lie level
    c = gz_curves(p, heels, np.radians(working_heels_deg))
    deg = np.degrees(heels)
    fig, ax = plt.subplots(figsize=(6.0, 3.6), dpi=100, layout="tight")
    ax.plot(deg, c["geometric"], "k", lw=2, label="geometric hull (ours, floating freely)")
    if compare is not None:
        ax.plot(deg, gz_curves(compare, heels, ())["geometric"], "k--", lw=1,
                label="geometric hull, CG on the waterline, vertical topsides")
    ax.plot(deg, c["eq20"], "C0", label="Wille (2016a) eq. 20: GM sin cos")
    for w, colour in zip(working_heels_deg, ("C1", "C2"), strict=False):
        ax.plot(deg, c[f"eq66_{w:g}"], colour, lw=1,
                label=f"Wille (2016b) eq. 66, $\\phi_w$ = {w:g} deg")
    ax.set_xlim(0, 90)
    ax.set_ylim(0, 1.6 * max(c["eq20"].max(), c["geometric"].max()) / 1.3)
    ax.set_xlabel("heel (deg)")
    ax.set_ylabel("righting arm GZ (m)")
    ax.set_title(f"{p.name}: GM_t = {p.gm_t:g} m, CG {p.cg_z:+.3f} m from the waterline",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower center")
    fig.savefig(path)
    plt.close(fig)


def _waterline_cg_hull() -> BoatParams:
    """The yacht with its CG on the waterline and vertical topsides, drawn dashed beside the
    yacht to show what the CG height and the flare change in its GZ curve."""
    from ..boat.catalogue import wille_yacht
    from ..boat.hull import design_for

    p = wille_yacht()
    return p.with_(cg_z=0.0, hull=design_for(p.hull.length, p.displaced_volume, p.gm_t, 0.0,
                                             p.hull.freeboard))


if __name__ == "__main__":  # python -m sailmujoco.forces.stability --gz-figure PATH [--boat NAME]
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--gz-figure", required=True, metavar="PATH", help="PNG to write")
    parser.add_argument("--boat", default="wille_yacht")
    args = parser.parse_args()
    gz_figure(args.gz_figure, args.boat,
              compare=_waterline_cg_hull() if args.boat == "wille_yacht" else None)
    print(f"wrote {args.gz_figure}")
