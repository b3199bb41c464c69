"""Heave and pitch radiation damping of the canoe bodies at their natural frequencies, from a
3-D panel method (Capytaine): the source of :data:`sailmujoco.boat.catalogue.RADIATION_DAMPING`.

Run: python benchmarks/radiation_damping.py [--boats wille_yacht saoud_robot viel_boat] [--panels N]

Needs Capytaine beside sailmujoco (``pip install capytaine``; the catalogue's numbers came from
Capytaine 3.0.0). A full run of the three boats takes about two minutes on one core,
most of it for wille_yacht's 4800 panels.

What it computes, per boat (zero forward speed, infinite depth, the boat's ``rho_water`` and
:data:`sailmujoco.constants.GRAVITY`):

* the heave natural frequency omega_3 = sqrt(k33 / (M + A33(omega_3))), k33 = rho g A_wp,
  M the boat's mass, and the radiation damping B33(omega_3);
* the pitch natural frequency about the centre of gravity,
  omega_5 = sqrt(k55 / (I_yy + A55(omega_5))), k55 = rho g V BM_L (V the design displacement),
  I_yy the boat's pitch inertia about its CG, and B55(omega_5) about the CG (the free hull,
  with no surge restoring, pitches about its CG);
* the fractions of critical damping zeta = B / (2 sqrt(k (M + A))) at those frequencies.

A_wp, BM_L and the hull's shape come from :mod:`sailmujoco.boat.hull`. Each natural frequency is
a secant root-find on omega - sqrt(k / (M + A(omega))), started from the package's strip-theory
added mass, one panel solve per step.

The mesh is the canoe body below the still waterline at its design draft (keel, rudder and
topsides left out, as in the package's strip formulas): half-elliptic sections of half-breadth
b(x) and depth t(x) = t0 b(x) / b0, quadrilaterals on stations spaced closer toward the pointed
ends (triangles at the tips). One quarter (x >= 0, y >= 0) is built and mirrored with
Capytaine's two reflection symmetries (the planes y = 0 and x = 0). A lid in the waterplane
z = 0, with about half as many panels as the hull, removes the irregular frequencies. Axes: x
forward from midship, z up from the still waterline; pitch rotates about the y axis through the
CG (cg_x, 0, cg_z).

``--panels N`` sets the hull's panel count of the whole body (nx = 2 ntheta stations per half
length, N = 4 nx ntheta; the lid adds N / 2); by default 3200 for wille_yacht and 1568 for the
two small hulls, the meshes the catalogue's numbers come from (each within 1.5 % of the mesh with
half as many panels at these frequencies).

It prints, per boat and mode: k, M (or I_yy), the natural frequency, A and B there, zeta, the
number of panel solves, the package's d33 or d55 (``RADIATION_DAMPING[name]``) and the ratio
BEM / package; then the largest departure of that ratio from 1.
"""

from __future__ import annotations

import argparse
import math
import time

import capytaine as cpt
import numpy as np
from capytaine.meshes.symmetric_meshes import ReflectionSymmetricMesh
from capytaine.tools.block_circulant_matrices import NestedBlockCirculantMatrix

from sailmujoco.boat import hull as hull_geometry
from sailmujoco.boat.catalogue import RADIATION_DAMPING, get_boat
from sailmujoco.boat.hull import HullShape
from sailmujoco.constants import GRAVITY

BOATS = ("wille_yacht", "saoud_robot", "viel_boat")
PANELS = {"wille_yacht": 3200, "saoud_robot": 1568, "viel_boat": 1568}
DEFAULT_PANELS = 3200


def stations(length: float, nx: int) -> np.ndarray:
    """Quarter-body station positions from midship to the bow, closer together toward the bow.

    Parameters
    ----------
    length : float
        Waterline length L, m.
    nx : int
        Number of station intervals over x in [0, L/2].

    Returns
    -------
    numpy.ndarray
        ``nx + 1`` positions x = (L/2) (s + sin(pi s / 2)) / 2, s = i / nx; the last is L/2.
    """
    s = np.arange(nx + 1) / nx
    return 0.25 * length * (s + np.sin(0.5 * np.pi * s))


def quarter_panels(hull: HullShape, nx: int, profile: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and faces of a quarter surface swept along the stations to the bow tip.

    At station x the section points are ``profile * fullness(x)`` (so the surface closes to a
    single point at x = L/2, where the last interval's panels become triangles).

    Parameters
    ----------
    hull : HullShape
        The canoe body.
    nx : int
        Number of station intervals over x in [0, L/2].
    profile : numpy.ndarray
        (n, 2) midship section points (y, z), m, ordered from the centreline outward.

    Returns
    -------
    vertices : numpy.ndarray
        (nv, 3) points, m.
    faces : numpy.ndarray
        (nf, 4) vertex indices; a triangle repeats its tip vertex.
    """
    xs = stations(hull.length, nx)
    n = len(profile)
    rows = []
    for x in xs[:-1]:
        f = hull.fullness(x)
        rows.append(np.column_stack([np.full(n, x), f * profile[:, 0], f * profile[:, 1]]))
    tip = nx * n
    vertices = np.vstack(rows + [[[0.5 * hull.length, 0.0, 0.0]]])
    faces = []
    for i in range(nx):
        for j in range(n - 1):
            a, b = i * n + j, i * n + j + 1
            if i + 1 < nx:
                faces.append([a, a + n, b + n, b])
            else:
                faces.append([a, tip, tip, b])
    return vertices, np.array(faces)


def doubly_symmetric(vertices: np.ndarray, faces: np.ndarray) -> ReflectionSymmetricMesh:
    """The whole body's mesh from its quarter x >= 0, y >= 0, mirrored in y = 0 and x = 0.

    The faces are turned, if need be, so that their normals point down on average.

    Parameters
    ----------
    vertices, faces : numpy.ndarray
        The quarter's vertices (nv, 3) and faces (nf, 4).

    Returns
    -------
    capytaine.meshes.symmetric_meshes.ReflectionSymmetricMesh
        The full mesh, stored as its quarter.
    """
    # normals out of the hull into the water, and down through the lid, as Capytaine wants:
    # both point down on average
    normals = cpt.Mesh(vertices, faces, auto_check=False)
    if np.sum(normals.faces_normals[:, 2] * normals.faces_areas) > 0.0:
        faces = faces[:, ::-1]
    quarter = cpt.Mesh(vertices, faces)
    return ReflectionSymmetricMesh(ReflectionSymmetricMesh(quarter, plane="xOz"), plane="yOz")


def canoe_body(params, panels: int) -> cpt.FloatingBody:
    """The boat's canoe body with its waterplane lid, heave and pitch about the CG as its dofs.

    Parameters
    ----------
    params : BoatParams
        The boat (its hull, CG).
    panels : int
        Hull panels of the whole body (module docstring).

    Returns
    -------
    capytaine.FloatingBody
        Dofs ``"Heave"`` and ``"Pitch"`` (about (cg_x, 0, cg_z)).
    """
    hull = params.hull
    ntheta = max(2, round(math.sqrt(panels / 8.0)))
    nx, nlid = 2 * ntheta, max(2, ntheta // 2)
    theta = 0.5 * np.pi * np.arange(ntheta + 1) / ntheta  # 0 at the keel, pi/2 at the waterline
    section = np.column_stack([hull.half_beam * np.sin(theta), -hull.canoe_draft * np.cos(theta)])
    eta = np.arange(nlid + 1) / nlid
    lid = np.column_stack([hull.half_beam * eta, np.zeros_like(eta)])
    cg = np.array([params.cg_x, 0.0, params.cg_z])
    return cpt.FloatingBody(mesh=doubly_symmetric(*quarter_panels(hull, nx, section)),
                            lid_mesh=doubly_symmetric(*quarter_panels(hull, nx, lid)),
                            dofs=cpt.rigid_body_dofs(only=["Heave", "Pitch"], rotation_center=cg),
                            center_of_mass=cg)


def radiation(solver, body, dof: str, omega: float, rho: float) -> tuple[float, float]:
    """Added mass and radiation damping of one dof at one frequency.

    Parameters
    ----------
    solver : capytaine.BEMSolver
    body : capytaine.FloatingBody
    dof : str
        ``"Heave"`` or ``"Pitch"``.
    omega : float
        Radian frequency, rad/s.
    rho : float
        Water density, kg/m^3.

    Returns
    -------
    tuple of float
        (A, B): kg and N s/m for heave, kg m^2 and N m s/rad for pitch.
    """
    problem = cpt.RadiationProblem(body=body, radiating_dof=dof, omega=omega, rho=rho, g=GRAVITY,
                                   water_depth=np.inf)
    result = solver.solve(problem, keep_details=False)
    # Capytaine 3.0.0 caches every frequency's symmetric matrices here (GBs within tens of solves)
    NestedBlockCirculantMatrix.to_BlockCirculantMatrix.cache_clear()
    return float(result.added_masses[dof]), float(result.radiation_dampings[dof])


def natural_frequency(solver, body, dof: str, stiffness: float, inertia: float, a_guess: float,
                      rho: float, rtol: float = 1e-5) -> tuple[float, float, float, int]:
    """Root omega of omega - sqrt(k / (M + A(omega))) by the secant method.

    Parameters
    ----------
    solver : capytaine.BEMSolver
    body : capytaine.FloatingBody
    dof : str
        ``"Heave"`` or ``"Pitch"``.
    stiffness : float
        Hydrostatic restoring k (N/m or N m/rad).
    inertia : float
        The boat's mass or pitch inertia M (kg or kg m^2).
    a_guess : float
        Added mass for the first guess omega_0 = sqrt(k / (M + a_guess)).
    rho : float
        Water density, kg/m^3.
    rtol : float
        Relative step in omega at which to stop.

    Returns
    -------
    tuple
        (omega, A(omega), B(omega), number of panel solves).
    """
    def residual(omega):
        a, b = radiation(solver, body, dof, omega, rho)
        return omega - math.sqrt(stiffness / (inertia + a)), a, b

    w0 = math.sqrt(stiffness / (inertia + a_guess))
    r0, a, b = residual(w0)
    w1 = w0 - r0  # one fixed-point step gives the second point
    for solves in range(2, 30):
        r1, a, b = residual(w1)
        if abs(w1 - w0) < rtol * w1:
            return w1, a, b, solves
        w0, w1, r0 = w1, w1 - r1 * (w1 - w0) / (r1 - r0), r1
    raise RuntimeError(f"{dof}: no natural frequency found (last omega {w1:.4f} rad/s)")


def boat_report(name: str, panels: int | None) -> list[tuple[str, str, float]]:
    """Solve and print one boat's heave and pitch at their natural frequencies.

    Parameters
    ----------
    name : str
        Registered boat name.
    panels : int or None
        Hull panels of the whole body; None: the boat's default (module docstring).

    Returns
    -------
    list of tuple
        (boat, mode, BEM / package) for each mode with a package value.
    """
    params = get_boat(name)
    hull, rho = params.hull, params.rho_water
    start = time.perf_counter()
    body = canoe_body(params, panels or PANELS.get(name, DEFAULT_PANELS))
    solver = cpt.BEMSolver()
    shortest = body.minimal_computable_wavelength
    omega_max = math.sqrt(2.0 * math.pi * GRAVITY / shortest)
    print(f"{name}: hull {body.mesh.nb_faces} + lid {body.lid_mesh.nb_faces} panels, valid for "
          f"omega <= {omega_max:.2f} rad/s (wavelengths >= {shortest:.2f} m)")
    print(f"  {'mode':5s} {'k':>9s} {'M':>7s} {'omega_n':>8s} {'A':>9s} {'B':>9s} {'zeta':>6s} "
          f"{'solves':>6s} {'package d':>10s} {'BEM/package':>11s}")
    k33 = rho * GRAVITY * hull_geometry.waterplane_area(hull)
    k55 = rho * GRAVITY * params.displaced_volume * hull_geometry.bm_longitudinal(hull)
    package = RADIATION_DAMPING.get(name, (math.nan, math.nan))
    modes = (("heave", "Heave", k33, params.mass, hull_geometry.heave_added_mass(hull, rho), package[0]),
             ("pitch", "Pitch", k55, params.inertia[1], hull_geometry.pitch_added_inertia(hull, rho),
              package[1]))
    ratios = []
    for mode, dof, k, inertia, a_guess, d in modes:
        omega, a, b, solves = natural_frequency(solver, body, dof, k, inertia, a_guess, rho)
        zeta = b / (2.0 * math.sqrt(k * (inertia + a)))
        line = (f"  {mode:5s} {k:9.0f} {inertia:7.1f} {omega:8.3f} {a:9.1f} {b:9.1f} {zeta:6.3f} "
                f"{solves:6d} {d:10.0f} {b / d:11.4f}")
        if math.isfinite(d):
            ratios.append((name, mode, b / d))
        if omega > omega_max:
            line += "  beyond the mesh's frequency limit"
        print(line)
    print(f"  ({time.perf_counter() - start:.1f} s)")
    return ratios


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--boats", nargs="+", default=list(BOATS), help="registered boat names")
    parser.add_argument("--panels", type=int, default=None,
                        help="hull panels of the whole body (default: per boat, module docstring)")
    args = parser.parse_args()
    print(f"Capytaine {cpt.__version__}: zero speed, deep water, g = {GRAVITY} m/s^2; pitch about the CG.\n"
          "omega_n rad/s; heave: k N/m, M and A kg, B and d N s/m; pitch: k N m/rad, M = I_yy and A "
          "kg m^2, B and d N m s/rad;\nzeta = B / (2 sqrt(k (M + A))); package d: RADIATION_DAMPING\n")
    start = time.perf_counter()
    ratios = []
    for name in args.boats:
        ratios += boat_report(name, args.panels)
    if ratios:
        boat, mode, worst = max(ratios, key=lambda r: abs(r[2] - 1.0))
        print(f"largest |BEM/package - 1| = {100 * abs(worst - 1.0):.2f} % ({boat} {mode})")
    print(f"total {time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
