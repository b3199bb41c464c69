"""The sea as the force kernel reads it: the components in one array, the ramp, the hull's
Froude-Krylov wrench and the water's velocity at a foil.

The force kernel (:func:`sailmujoco.forces.boat.boat_forces`) takes the sea as one array
``sea`` of shape (6, n): rows amplitude a_j (m), angular frequency omega_j (rad/s), wavenumber
k_j (rad/m), direction travelled toward beta_j (rad, from east counter-clockwise), phase phi_j
(rad) of :func:`sailmujoco.forces.waves.components`, and a sixth row the kernel fills at each
call with the ramped amplitudes r(t) a_j. A calm sea is the array of shape (6, 0): the kernel
then runs the calm-water arithmetic untouched. The ramp r(t) = (1 - cos(pi t/T_r))/2, 0 before
t = 0 and 1 after T_r = 3 Tp, is :func:`sailmujoco.forces.waves.ramp` evaluated at the stage
time inside the kernel.
"""

from __future__ import annotations

import math

import numpy as np

from .._jit import kernel
from .wave_pressure import froude_krylov
from .waves import RAMP_PERIODS, WaveConfig, components

SEA_ROWS = 6  # amplitude, omega, k, direction_to, phase, ramped amplitude
# The sea's mechanisms (physics options, sailmujoco.options.ForceSwitches), each packed as 1.0 (on)
# or 0.0 in this order after the ramp in the sea's block of P (forces/boat_parameters.py,
# P_SEA_BLOCK); wave_damping packs 1.0 for "relative":
SEA_SWITCHES = ("wave_foil_flow", "wave_diffraction", "wave_damping", "wave_pressure_decay")
SB_RAMP, SB_FOIL_FLOW, SB_DIFFRACTION, SB_RELATIVE_DAMPING, SB_PRESSURE_DECAY = range(5)


def check_sea(config, dofs: int) -> None:
    """One line unless ``config`` is None or a WaveConfig the boat can feel (``hs > 0``: 6 DOF).

    Parameters
    ----------
    config : object
        The ``waves`` given.
    dofs : int
        The boat's degrees of freedom (6, or 4 with heave and pitch held).
    """
    if config is not None and not isinstance(config, WaveConfig):
        raise ValueError(f"waves must be a WaveConfig or None, got {config!r}")
    if config is not None and config.hs > 0.0 and dofs != 6:
        raise ValueError("waves need the 6-DOF boat (dofs=6): dofs=4 holds heave and pitch")


def sea_array(config: WaveConfig | None) -> np.ndarray:
    """The kernel's sea array (6, n) of a sea state; (6, 0) for None or ``hs = 0`` (calm).

    Parameters
    ----------
    config : WaveConfig or None
        The sea state.
    """
    if config is None or config.hs == 0.0:
        return np.zeros((SEA_ROWS, 0))
    comp = components(config)
    sea = np.zeros((SEA_ROWS, comp.amplitude.shape[0]))
    sea[0], sea[1], sea[2] = comp.amplitude, comp.omega, comp.k
    sea[3], sea[4] = comp.direction_to, comp.phase
    return np.ascontiguousarray(sea)


def ramp_duration(config: WaveConfig | None) -> float:
    """T_r = 3 Tp, s, the ramp's length (0 for no sea).

    Parameters
    ----------
    config : WaveConfig or None
        The sea state.
    """
    return 0.0 if config is None else RAMP_PERIODS * config.tp


@kernel
def ramp_amplitudes(t, duration, sea):
    """Fill ``sea``'s sixth row with r(t) a_j (:func:`sailmujoco.forces.waves.ramp`).

    Parameters
    ----------
    t : float
        Time, s.
    duration : float
        The ramp's length T_r, s (> 0).
    sea : numpy.ndarray, shape (6, n)
        The sea array (module docstring); row 5 receives the ramped amplitudes, m.
    """
    s = min(max(t / duration, 0.0), 1.0)
    r = 0.5 * (1.0 - math.cos(math.pi * s))
    for j in range(sea.shape[1]):
        sea[5, j] = r * sea[0, j]


@kernel
def sea_buoyancy(t, pos, rot, columns, sea, rho, g, out):
    """Buoyancy and Froude-Krylov wave force on the hull's columns, cut at the local surface.

    :func:`sailmujoco.forces.wave_pressure.froude_krylov` with the ramped amplitudes (row 5 of
    ``sea``, filled by :func:`ramp_amplitudes`).

    Parameters
    ----------
    t : float
        Time, s.
    pos : numpy.ndarray, shape (3,)
        World position of CO, m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world.
    columns : numpy.ndarray, shape (5, n)
        The hull's columns (:func:`sailmujoco.hull.column_quadrature`).
    sea : numpy.ndarray, shape (6, m)
        The sea array, ramped.
    rho, g : float
        Water density (kg/m^3) and gravitational acceleration (m/s^2).
    out : numpy.ndarray, shape (6,)
        Receives the wrench (body frame, about CO), N and N m.

    Returns
    -------
    float
        The wet volume, m^3.
    """
    return froude_krylov(pos, rot, columns, sea[5], sea[1], sea[2], sea[3], sea[4], t, rho, g, out)


@kernel
def foil_water_velocity(t, pos, rot, x, z, sea, current_b, out):
    """The water's velocity at the body point (x, 0, z): current plus orbital velocity, body frame.

    The orbital velocity of :func:`sailmujoco.forces.waves.orbital_velocity` (vertically
    stretched, z_s = min(z - eta, 0), eta at the point's horizontal position), with the ramped
    amplitudes, turned world -> body by R^T and added to the current. One point per foil: the
    velocity varies along the span as e^(k z_s), which a single point at the centre of pressure
    averages only to first order in k times the span.

    Parameters
    ----------
    t : float
        Time, s.
    pos : numpy.ndarray, shape (3,)
        World position of CO, m.
    rot : numpy.ndarray, shape (3, 3)
        Rotation body -> world.
    x, z : float
        The point in the body frame (on the centre plane), m.
    sea : numpy.ndarray, shape (6, m)
        The sea array, ramped (:func:`ramp_amplitudes`).
    current_b : numpy.ndarray, shape (3,)
        The current, body frame, m/s.
    out : numpy.ndarray, shape (3,)
        Receives the water's velocity, body frame, m/s.
    """
    px = pos[0] + rot[0, 0] * x + rot[0, 2] * z
    py = pos[1] + rot[1, 0] * x + rot[1, 2] * z
    pz = pos[2] + rot[2, 0] * x + rot[2, 2] * z
    eta = 0.0
    for j in range(sea.shape[1]):
        theta = sea[2, j] * (px * math.cos(sea[3, j]) + py * math.sin(sea[3, j])) - sea[1, j] * t + sea[4, j]
        eta += sea[5, j] * math.cos(theta)
    z_s = min(pz - eta, 0.0)
    ue, un, uz = 0.0, 0.0, 0.0
    for j in range(sea.shape[1]):
        cb, sb = math.cos(sea[3, j]), math.sin(sea[3, j])
        theta = sea[2, j] * (px * cb + py * sb) - sea[1, j] * t + sea[4, j]
        speed = sea[5, j] * sea[1, j] * math.exp(sea[2, j] * z_s)
        horizontal = speed * math.cos(theta)
        ue += horizontal * cb
        un += horizontal * sb
        uz += speed * math.sin(theta)
    for i in range(3):
        out[i] = current_b[i] + rot[0, i] * ue + rot[1, i] * un + rot[2, i] * uz
