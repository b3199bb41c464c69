"""The sea as the force kernel reads it: the components in one array, each stage's phases,
and the water's velocity at a foil.

The force kernel (:func:`sailmujoco.forces.boat.boat_forces`) takes the sea as one array ``sea``
of shape (SEA_ROWS, m), one column per component, largest amplitude first. Rows
0-5 are fixed: amplitude a_j (m), angular frequency omega_j (rad/s), wavenumber k_j (rad/m),
cos and sin of the direction beta_j it travels toward (from east counter-clockwise) and the
phase phi_j (rad) of :func:`sailmujoco.forces.waves.components`. :func:`sea_stage` fills rows
6-10 at every call: the ramped amplitude r(t) a_j, the phase theta_j at CO, and the body-frame
wavevector (kappa_x, kappa_y, kappa_z)_j, the phase's change per metre along each body axis
(k_j (cos beta_j, sin beta_j) . the horizontal part of that axis in the world), so that the
phase at a body point (x, y, z) is theta_j + kappa_x x + kappa_y y + kappa_z z. Rows 11 and 12
are :func:`foil_water_velocity`'s scratch.

A calm sea is
the array of shape (SEA_ROWS, 0): the kernel then runs calm water's arithmetic untouched.
The ramp r(t) = (1 - cos(pi t/T_r))/2, 0 before t = 0 and 1 after T_r = 3 Tp, is
:func:`sailmujoco.forces.waves.ramp` evaluated at the stage time inside the kernel.
"""

from __future__ import annotations

import math

import numpy as np

from ..boat.hull_grid import GRID_ROWS, HullGrid, hull_grid, section_depths, section_weights
from ..jit.kernel import kernel
from ..jit.ordered import elementwise
from ..options import WaveConfig
from .lane_math import exp, sincos
from .sea_hull import SCRATCH_ROWS
from .wave_reflection import waterline_array
from .waves import RAMP_PERIODS, components

SEA_ROWS = 13  # a, omega, k, cos beta, sin beta, phi; r(t) a, theta at CO, kappa_x, kappa_y, kappa_z;
#                a foil's phasor (cos, sin)
_M1, _M2, _M3, _M4, _M5, _M6, _M7 = (1.0 / math.factorial(n + 1) for n in range(1, 8))  # 1/(n+1)!
# The sea's block of P (forces/boat_parameters.py, P_SEA_BLOCK): the ramp T_r, the five switches
# of the sea's mechanisms (packed with the other force switches by pack_parameters), then the
# hull's grid (sailmujoco/boat/hull_grid.py): its steps and counts (pack_sea_block).
SB_RAMP, SB_HULL, SB_FOIL_FLOW, SB_DIFFRACTION, SB_RELATIVE_DAMPING, SB_PRESSURE_DECAY = range(6)
SB_DX, SB_DY, SB_NX, SB_NY = range(6, 10)


def sea_array(config: WaveConfig | None, depths=()) -> np.ndarray:
    """The kernel's sea array of the components the boat feels (module docstring): SEA_ROWS
    rows, then e^(k_j z_i) at the depths z_i of the hull's grid stations
    (:func:`sailmujoco.boat.hull_grid.section_depths`), then the hull's scratch rows
    (:func:`sailmujoco.forces.sea_hull.hull_sea_wrench`); m = 0 for None or ``hs = 0`` (calm).

    Parameters
    ----------
    config : WaveConfig or None
        The sea state.
    depths : sequence of float
        Depths (negative, m) where the diffraction force takes the water's acceleration.
    """
    depths = np.asarray(depths, dtype=float)
    rows = SEA_ROWS + depths.size + SCRATCH_ROWS + 2 * GRID_ROWS
    if config is None or config.hs == 0.0:
        return np.zeros((rows, 0))
    comp = components(config)
    felt = np.argsort(-comp.amplitude, kind="stable")  # largest first
    sea = np.zeros((rows, felt.size))
    sea[0], sea[1], sea[2] = comp.amplitude[felt], comp.omega[felt], comp.k[felt]
    # set up through the C library: numpy's sin, cos and exp pick a SIMD kernel by CPU
    to = comp.direction_to[felt]
    sea[3], sea[4] = elementwise(math.cos, to), elementwise(math.sin, to)
    sea[5] = comp.phase[felt]
    sea[SEA_ROWS:SEA_ROWS + depths.size] = elementwise(math.exp, np.outer(depths, sea[2]))
    return np.ascontiguousarray(sea)


def grid_array(grid: HullGrid, shares: np.ndarray) -> np.ndarray:
    """The kernel's ``grid`` array (6, 2 nx ny): the grid's columns (rows x, y, area, z_bottom,
    z_top) and in row 5 each station's share of the added mass.

    Parameters
    ----------
    grid : HullGrid
        The hull's coarse grid (:func:`sailmujoco.boat.hull_grid.hull_grid`).
    shares : numpy.ndarray, shape (nx,)
        Each station's share of the added mass (:func:`sailmujoco.boat.hull_grid.section_weights`).
    """
    out = np.zeros((6, max(grid.columns.shape[1], grid.nx)))
    out[:5] = grid.columns
    out[5, :grid.nx] = shares
    return np.ascontiguousarray(out)


def sea_arrays(hull, config: WaveConfig | None):
    """The kernel's ``sea``, ``grid`` and ``waterline`` arrays for a hull in a sea state
    (:func:`sea_array`, :func:`grid_array`,
    :func:`sailmujoco.forces.wave_reflection.waterline_array`).

    Parameters
    ----------
    hull : HullShape
        The canoe body.
    config : WaveConfig or None
        The sea state.
    """
    grid = hull_grid(hull)
    sea = sea_array(config, section_depths(hull, grid))
    return sea, grid_array(grid, section_weights(hull, grid)), waterline_array(hull, sea[0], sea[2])


def pack_sea_block(hull, config: WaveConfig | None, block: np.ndarray) -> None:
    """The sea's block of ``P`` but its switches: the ramp T_r and the hull's grid (steps, counts).

    Parameters
    ----------
    hull : HullShape
        The canoe body.
    config : WaveConfig or None
        The sea state.
    block : numpy.ndarray
        The sea's block of ``P`` (``P[P_SEA_BLOCK:]``), written in place at the SB_* offsets.
    """
    grid = hull_grid(hull)
    block[SB_RAMP] = ramp_duration(config)
    block[SB_DX], block[SB_DY] = grid.dx, grid.dy
    block[SB_NX], block[SB_NY] = grid.nx, grid.ny


def ramp_duration(config: WaveConfig | None) -> float:
    """T_r = 3 Tp, s, the ramp's length (0 for no sea).

    Parameters
    ----------
    config : WaveConfig or None
        The sea state.
    """
    return 0.0 if config is None else RAMP_PERIODS * config.tp


@kernel
def sea_stage(t, duration, pos, rot, sea):
    """Fill ``sea``'s rows 6-10 for this stage: r(t) a_j, theta_j at CO and the body-frame
    wavevector (module docstring).

    Parameters
    ----------
    t : float
        Time, s.
    duration : float
        The ramp's length T_r, s (> 0).
    pos : numpy.ndarray, shape (3,)
        World position of CO, m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world.
    sea : numpy.ndarray, shape (SEA_ROWS, m)
        The sea array.
    """
    s = min(max(t / duration, 0.0), 1.0)
    r = 0.5 * (1.0 - math.cos(math.pi * s))
    for j in range(sea.shape[1]):
        k, cb, sb = sea[2, j], sea[3, j], sea[4, j]
        sea[6, j] = r * sea[0, j]
        sea[7, j] = k * (pos[0] * cb + pos[1] * sb) - sea[1, j] * t + sea[5, j]
        sea[8, j] = k * (cb * rot[0, 0] + sb * rot[1, 0])
        sea[9, j] = k * (cb * rot[0, 1] + sb * rot[1, 1])
        sea[10, j] = k * (cb * rot[0, 2] + sb * rot[1, 2])


@kernel
def foil_water_velocity(pos, rot, x, z, span, sea, current_b, out):
    """The water's velocity at a foil, body frame: the current plus the orbital velocity
    averaged over the foil's span.

    The foil stands at body (x, 0, z), its span ``span`` centred there along body z. The phases
    are those at (x, 0, z) (the span's horizontal offset at a heel is left out); each
    component's speed a_j omega_j e^(k_j z_s) is averaged over the span's stretched heights
    z_s (:func:`sailmujoco.forces.waves.orbital_velocity`; z_s = min(z - eta, 0), eta at the
    foil): exactly, (e^(k z_top) - e^(k z_bottom)) / (k d) for a span reaching from z_top down
    over the height d, which is the limit of many points along the span (the keel's flow falls
    to about 0.45 of its top value down a 1.3 m span in a 10 m wave). The phasors go through
    the sea's rows 11 and 12 (:data:`SEA_ROWS`).

    Parameters
    ----------
    pos : numpy.ndarray, shape (3,)
        World position of CO, m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world.
    x, z : float
        The foil's centre of pressure in the body frame (on the centre plane), m.
    span : float
        The foil's span, m.
    sea : numpy.ndarray, shape (SEA_ROWS, m)
        The sea array with this stage's rows (:func:`sea_stage`).
    current_b : numpy.ndarray, shape (3,)
        The current, body frame, m/s.
    out : numpy.ndarray, shape (3,)
        Receives the water's velocity, body frame, m/s.
    """
    m = sea.shape[1]
    for j in range(m):
        sea[11, j], sea[12, j] = sincos(sea[7, j] + sea[8, j] * x + sea[10, j] * z)
    eta = 0.0
    for j in range(m):
        eta += sea[6, j] * sea[11, j]
    height = rot[2, 2] * span  # the span's world height
    z_top = min(pos[2] + rot[2, 0] * x + rot[2, 2] * (z + 0.5 * span) - eta, 0.0)
    for j in range(m):  # each component's flow, into rows 11 (horizontal) and 12 (vertical)
        k = sea[2, j]
        q = k * height
        top = exp(k * z_top)
        # the span's mean of e^(k z_s) / e^(k z_top) = (1 - e^(-q)) / q; its series below q = 0.05
        # (the difference of exponentials would lose digits there)
        series = 1.0 - q * (_M1 - q * (_M2 - q * (_M3 - q * (_M4 - q * (_M5 - q * (_M6 - q * _M7))))))
        mean = top * series if q < 0.05 else (top - exp(k * (z_top - height))) / q
        speed = sea[6, j] * sea[1, j] * mean
        sea[11, j] = speed * sea[11, j]
        sea[12, j] = speed * sea[12, j]
    # the sums apart from the loop above, which then has no sum in it and runs on vector lanes
    ue, un, uz = 0.0, 0.0, 0.0
    for j in range(m):
        ue += sea[11, j] * sea[3, j]
        un += sea[11, j] * sea[4, j]
        uz += sea[12, j]
    for i in range(3):
        out[i] = current_b[i] + rot[0, i] * ue + rot[1, i] * un + rot[2, i] * uz
