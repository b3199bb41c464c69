"""Added resistance in regular head waves, measured on the 6-DOF boat as a towing tank would.

The boat sails with no sail and no windage, its rudder holding the heading (a PD law), pushed
by a surge force at CO (the towing carriage's force, or a propeller's thrust) that a slow
speed loop adjusts until the mean speed equals the speed asked for. The added resistance is
the mean thrust in the waves minus the thrust in calm water at the same mean speed,

    R_aw = <T>_waves - T_calm(U),     sigma_aw = R_aw / (rho g zeta_a^2 B^2 / L),

the non-dimensional form of the towing-tank literature (Gerritsma & Beukelman 1972; ITTC
7.5-04-01-01.1), with L and B the waterline length and beam. Heave and pitch are free, so the
mean force is everything the force models give: the hull's wave pressure, its diffraction, the
damping relative to the water, the added mass's terms, the foils' orbital flow and, when on,
the short-wave reflection term.

The speed loop is a PI law on the speed averaged over one encounter period, with a natural
period of ``LOOP_PERIOD`` (40 s) and a damping ratio of 0.7: far slower than the encounter
periods (0.9-4 s for lambda/L 0.5-3 on a 9 m yacht), so that it sets the mean and leaves the
motions alone. The thrust's mean is taken over whole encounter periods once it has settled.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, field, replace

import numpy as np

from ..constants import GRAVITY
from ..forces.waves import elevation
from ..forces.wind import WindConfig
from ..options import ForceSwitches, WaveConfig

CONTROL_DT = 0.1  # s, the loops' period
LOOP_PERIOD = 40.0  # s, natural period of the speed loop
HEADING_GAINS = (1.0, 2.0)  # rudder rad per rad of yaw error, per rad/s of yaw rate
K_ZETA = 0.03  # k zeta_a of the measurement waves: H/lambda = 1/105, in the linear range


@dataclass(frozen=True)
class AddedResistance:
    """One measured point.

    Parameters
    ----------
    wavelength_ratio, froude : float
        lambda / L and U / sqrt(g L), -.
    sigma_aw : float
        R_aw / (rho g zeta_a^2 B^2 / L), -.
    added_resistance, calm_resistance : float
        R_aw and T_calm(U), N.
    speed : float
        The mean speed over the averaging window, m/s.
    heave, pitch : float
        The first harmonic at the encounter frequency of the heave over zeta_a and of the pitch
        over k zeta_a, -.
    motion : numpy.ndarray, shape (2,), complex
        Heave (m) and pitch (rad, bow up) as complex amplitudes at the encounter frequency,
        relative to the wave's elevation at CO (its phase is 0).
    stations, water : numpy.ndarray, shape (n,)
        Stations along the hull (m, toward the bow) and the wave's elevation there as complex
        amplitudes on the same phase (m).
    wavenumber, encounter_frequency : float
        k (rad/m) and omega_e = omega + k U (rad/s).
    """

    wavelength_ratio: float
    froude: float
    sigma_aw: float
    added_resistance: float
    calm_resistance: float
    speed: float
    heave: float
    pitch: float
    motion: np.ndarray = field(repr=False, default=None)
    stations: np.ndarray = field(repr=False, default=None)
    water: np.ndarray = field(repr=False, default=None)
    wavenumber: float = 0.0
    encounter_frequency: float = 0.0


def head_waves(length: float, wavelength_ratio: float, k_zeta: float = K_ZETA) -> WaveConfig:
    """A regular deep-water wave of length ``wavelength_ratio * length`` from the east.

    Parameters
    ----------
    length : float
        The waterline length L, m.
    wavelength_ratio : float
        lambda / L, -.
    k_zeta : float
        The wave steepness k zeta_a, -.
    """
    k = 2.0 * math.pi / (wavelength_ratio * length)
    period = 2.0 * math.pi / math.sqrt(GRAVITY * k)
    return WaveConfig(spectrum="regular", hs=2.0 * k_zeta / k, tp=period,
                      direction_from=math.pi / 2.0)


STATIONS = 20  # stations along the hull where the water's elevation is kept


def first_harmonic(t, x, omega) -> complex:
    """The complex amplitude X of x(t) ~ x0 + Re(X e^(i omega t)), by least squares.

    Parameters
    ----------
    t : numpy.ndarray
        Times, s.
    x : numpy.ndarray
        Samples, shape (len(t),) or (len(t), n) (then one amplitude per column).
    omega : float
        Angular frequency, rad/s.
    """
    a = np.column_stack([np.ones_like(t), np.cos(omega * t), np.sin(omega * t)])
    coef = np.linalg.lstsq(a, x, rcond=None)[0]
    return coef[1] - 1j * coef[2]


def hold_heading(physics) -> None:
    """Set the rudder of the PD law that holds ``physics`` heading east, the sail at 0.

    Parameters
    ----------
    physics : BoatPhysics
        The boat; its rudder command is clipped to the rudder's range.
    """
    low, high = physics.action_bounds()[0][0], physics.action_bounds()[1][0]
    # a positive rudder angle turns the bow to port (yaw up): steer against the yaw error
    rudder = -(HEADING_GAINS[0] * physics.yaw() + HEADING_GAINS[1] * physics.yaw_rate())
    physics.set_control([min(max(rudder, low), high), 0.0])


def tow(physics, speed: float, seconds: float, encounter_period: float, average: float):
    """Sail east at mean ``speed`` for ``seconds``; returns the window's mean thrust (N), mean
    speed (m/s) and its log, columns (t, z, pitch, x, y, yaw), the window being the last
    ``average`` seconds rounded to whole encounter periods.

    Parameters
    ----------
    physics : BoatPhysics
        The boat, sail off (it is placed upright at the origin heading east).
    speed : float
        The mean speed asked for, m/s.
    seconds : float
        Simulated time, s.
    encounter_period : float
        The encounter period (s): the speed loop averages over it, and the window is whole ones.
    average : float
        The averaging window, s.
    """
    p = physics.params
    steps = max(1, int(round(CONTROL_DT / physics.model.opt.timestep)))
    dt = steps * physics.model.opt.timestep
    mass = p.mass + p.added_mass_diagonal[0]
    omega_n = 2.0 * math.pi / LOOP_PERIOD
    ki = mass * omega_n**2
    kp = 2.0 * 0.7 * mass * omega_n
    physics.place(yaw=0.0, surge=speed)
    drag = sum(w[0] for name, w in physics.force_terms().items() if name != "external")
    thrust0, integral = -drag, 0.0
    recent = deque(maxlen=max(1, int(round(encounter_period / dt))))
    n = int(round(seconds / dt))
    log = np.empty((n, 8))
    for i in range(n):
        u = physics.surge_speed()
        recent.append(u)
        integral += (speed - u) * dt
        thrust = thrust0 + kp * (speed - sum(recent) / len(recent)) + ki * integral
        physics.set_external_wrench([thrust, 0.0, 0.0, 0.0, 0.0, 0.0])
        hold_heading(physics)
        physics.step(steps)
        x, y, z = physics.position()
        log[i] = (thrust, physics.surge_speed(), physics.data.time, z, physics.pitch(), x, y,
                  physics.yaw())
    periods = max(1, int(average / encounter_period))
    w = log[-int(round(periods * encounter_period / dt)):]
    return float(w[:, 0].mean()), float(w[:, 1].mean()), w[:, 2:]


def measure(boat: str, wavelength_ratio: float, froude: float, *, forces: ForceSwitches | None = None,
            k_zeta: float = K_ZETA, seconds: float = 160.0, average: float = 60.0,
            calm_resistance: float | None = None) -> AddedResistance:
    """sigma_aw of ``boat`` at one wavelength and Froude number (module docstring).

    Parameters
    ----------
    boat : str
        A registered boat or a boat file.
    wavelength_ratio, froude : float
        lambda / L and U / sqrt(g L), -.
    forces : ForceSwitches, optional
        The force switches (the sail and windage are switched off here); default: as built.
    k_zeta : float
        The wave steepness k zeta_a, -.
    seconds, average : float
        Simulated time of each run and the averaging window at its end, s.
    calm_resistance : float, optional
        T_calm(U) from an earlier calm run with the same switches (N); measured when None.
    """
    from ..boat.catalogue import get_boat
    from ..physics import BoatPhysics

    forces = replace(forces or ForceSwitches(), sail=False, windage=False)
    calm = WindConfig(speed=0.0, gusts=False, wander=False)
    p = get_boat(boat)
    length, beam = p.hull.length, 2.0 * p.hull.half_beam
    speed = froude * math.sqrt(GRAVITY * length)
    waves = head_waves(length, wavelength_ratio, k_zeta)
    omega = 2.0 * math.pi / waves.tp
    k = omega**2 / GRAVITY
    omega_e = omega + k * speed
    period_e = 2.0 * math.pi / omega_e
    if calm_resistance is None:
        calm_resistance = tow(BoatPhysics.load(boat, wind=calm, forces=forces), speed, seconds, period_e,
                              average)[0]
    physics = BoatPhysics.load(boat, wind=calm, forces=forces, waves=waves)
    thrust, mean_speed, log = tow(physics, speed, seconds, period_e, average)
    t, z, pitch, x, y, yaw = log.T
    stations = (np.arange(STATIONS) + 0.5) * length / STATIONS - 0.5 * length
    eta = elevation(waves, t[:, None], x[:, None] + np.cos(yaw)[:, None] * stations,
                    y[:, None] + np.sin(yaw)[:, None] * stations)
    water = first_harmonic(t, eta, omega_e)
    centre = first_harmonic(t, elevation(waves, t, x, y), omega_e)
    turn = abs(centre) / centre  # the phase that puts the wave's elevation at CO at 0
    motion = np.array([first_harmonic(t, z, omega_e), first_harmonic(t, pitch, omega_e)]) * turn
    zeta = 0.5 * waves.hs
    r_aw = thrust - calm_resistance
    return AddedResistance(
        wavelength_ratio=wavelength_ratio, froude=froude,
        sigma_aw=r_aw / (p.rho_water * GRAVITY * zeta**2 * beam**2 / length),
        added_resistance=r_aw, calm_resistance=calm_resistance, speed=mean_speed,
        heave=abs(motion[0]) / zeta, pitch=abs(motion[1]) / (k * zeta), motion=motion,
        stations=stations, water=water * turn, wavenumber=k, encounter_frequency=omega_e)
