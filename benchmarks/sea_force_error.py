"""The error of the sea's quadrature: the hull's wave force on the coarse grid against the fine
reference, for each boat in a 1.5 m JONSWAP sea.

Run: python benchmarks/sea_force_error.py [--hs 1.5] [--tp 6] [--states 300] [--heel-deg 11]

The kernel's hull force in a sea is calm water's buoyancy on the fine columns plus the sea's
part on a coarse grid (``forces/sea_hull.py``: 8 x 4 cells, the pressure's e^(kz) as a
third-order series). The reference is ``forces/wave_pressure.py: froude_krylov`` on the fine
columns (24 x 16 and the flare's) with the exact exponential, for the same components. Over
random states (position, heave 2 cm, heel with a standard deviation of ``--heel-deg``, pitch 2
deg, any heading, t after the ramp), it prints each wrench component's RMS error divided by the
RMS of the reference's wave part (reference minus calm water): the error relative to what the
sea adds. The diffraction force is off here (the reference has none).

A second table measures the number of components against a sea of ``--fine-components`` (256)
in the same spectrum: for the hull held upright at rest, each wrench component's standard
deviation in the sea, sqrt(sum_j a_j^2 |F_j|^2 / 2) with F_j the reference's force per metre of
component j alone (two phases a quarter period apart, 1 cm high: linear), its ratio to the fine
sea's minus 1, as the mean and the largest over ``--seeds`` seeds. It is the error of the
spectrum's quadrature in the force; each seed's own realisation scatters about it further.
"""

from __future__ import annotations

import argparse
import math
from dataclasses import replace

import numpy as np

from sailmujoco.boat.catalogue import BUILT_IN, get_boat
from sailmujoco.boat.hull import column_quadrature
from sailmujoco.forces import sea_hull, sea_kernels
from sailmujoco.forces.boat_parameters import P_SEA_BLOCK, pack_parameters
from sailmujoco.forces.hydrostatics import geometric_buoyancy
from sailmujoco.forces.wave_pressure import froude_krylov
from sailmujoco.forces.waves import components
from sailmujoco.frames import matrix_from_euler
from sailmujoco.options import WaveConfig

G = 9.81


def relative_errors(boat: str, sea: WaveConfig, states: int, heel_sd: float, seed: int = 1):
    """RMS error / RMS wave part of each wrench component (Fx, Fy, Fz, Mx, My, Mz)."""
    p = get_boat(boat)
    comp = components(sea)
    fine = column_quadrature(p.hull).array()
    P = pack_parameters(p, waves=sea)  # the sea's block: the hull's grid steps and counts
    sea_rows, grid, _ = sea_kernels.sea_arrays(p.hull, sea)
    b = P_SEA_BLOCK
    dx, dy, nx, ny = P[b + sea_kernels.SB_DX], P[b + sea_kernels.SB_DY], int(P[b + sea_kernels.SB_NX]), \
        int(P[b + sea_kernels.SB_NY])
    rows = sea_kernels.SEA_ROWS
    rng = np.random.default_rng(seed)
    errors, parts = [], []
    for _ in range(states):
        t = rng.uniform(5 * sea.tp, 300.0)
        pos = np.array([rng.uniform(-50, 50), rng.uniform(-50, 50), rng.normal(0.0, 0.02)])
        rot = matrix_from_euler(rng.normal(0.0, heel_sd), rng.normal(0.0, math.radians(2)),
                                rng.uniform(-math.pi, math.pi))
        calm, reference, part = np.zeros(6), np.zeros(6), np.zeros(6)
        geometric_buoyancy(pos[2], rot, fine, p.rho_water, G, calm)
        froude_krylov(pos, rot, fine, comp.amplitude, comp.omega, comp.k, comp.direction_to,
                      comp.phase, t, p.rho_water, G, reference)
        sea_kernels.sea_stage(t, 1e-9, pos, rot, sea_rows)
        sea_hull.hull_sea_wrench(pos, rot, sea_rows, sea_rows[rows:rows + nx], sea_rows[rows + nx:],
                                 grid, dx, dy, nx, ny, 0.0, np.zeros(3), True, False, p.rho_water, G,
                                 np.zeros(sea_hull.SMALL_SIZE), part, np.zeros(2))
        errors.append(calm + part - reference)
        parts.append(reference - calm)
    return np.sqrt(np.mean(np.square(errors), axis=0)) / np.sqrt(np.mean(np.square(parts), axis=0))


def wrench_sd(boat: str, sea: WaveConfig, small: float = 0.01) -> np.ndarray:
    """Each wrench component's standard deviation in ``sea`` for the hull held upright at rest."""
    p = get_boat(boat)
    fine = column_quadrature(p.hull).array()
    pos, rot = np.zeros(3), np.eye(3)
    calm, out = np.zeros(6), np.zeros(6)
    geometric_buoyancy(0.0, rot, fine, p.rho_water, G, calm)
    comp = components(sea)
    variance = np.zeros(6)
    for j in range(comp.amplitude.size):
        for phase in (0.0, 0.5 * math.pi):
            froude_krylov(pos, rot, fine, np.array([small]), comp.omega[j:j + 1], comp.k[j:j + 1],
                          comp.direction_to[j:j + 1], np.array([phase]), 0.0, p.rho_water, G, out)
            variance += 0.5 * (comp.amplitude[j] * (out - calm) / small) ** 2
    return np.sqrt(variance)


def count_errors(boat: str, sea: WaveConfig, fine_components: int, seeds: int):
    """(mean, largest by magnitude) over seeds of sd(sea) / sd(fine sea) - 1, each component."""
    fine = wrench_sd(boat, replace(sea, n_components=fine_components))
    ratios = np.array([wrench_sd(boat, replace(sea, seed=s)) / fine - 1.0 for s in range(seeds)])
    return ratios.mean(axis=0), ratios[np.abs(ratios).argmax(axis=0), range(6)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--hs", type=float, default=1.5, help="significant wave height, m")
    parser.add_argument("--tp", type=float, default=6.0, help="peak period, s")
    parser.add_argument("--states", type=int, default=300, help="random states per boat")
    parser.add_argument("--heel-deg", type=float, default=11.0, help="heel's standard deviation, deg")
    parser.add_argument("--fine-components", type=int, default=256, help="components of the fine sea")
    parser.add_argument("--seeds", type=int, default=8, help="seeds of the component-count table")
    args = parser.parse_args()
    sea = WaveConfig(spectrum="jonswap", hs=args.hs, tp=args.tp, direction_from=0.7)
    print(f"hull wave force, coarse grid against the fine reference: RMS error / RMS wave part; "
          f"JONSWAP hs {args.hs:g} m, tp {args.tp:g} s, {sea.n_components} components, "
          f"heel sd {args.heel_deg:g} deg")
    print(f"{'boat':12s} " + " ".join(f"{n:>6s}" for n in ("Fx", "Fy", "Fz", "Mx", "My", "Mz")))
    for boat in BUILT_IN:
        e = relative_errors(boat, sea, args.states, math.radians(args.heel_deg))
        print(f"{boat:12s} " + " ".join(f"{v:6.3f}" for v in e))
    print(f"\nthe hull's wave force, {sea.n_components} components against {args.fine_components}: "
          f"sd / fine sd - 1, mean (largest) over {args.seeds} seeds")
    print(f"{'boat':12s} " + " ".join(f"{n:>15s}" for n in ("Fx", "Fy", "Fz", "Mx", "My", "Mz")))
    for boat in BUILT_IN:
        mean, largest = count_errors(boat, sea, args.fine_components, args.seeds)
        print(f"{boat:12s} " + " ".join(f"{m:+6.3f} ({w:+6.3f})" for m, w in zip(mean, largest, strict=True)))


if __name__ == "__main__":
    main()
