"""Viel's 3-DOF model (eqs. 1-9) as compiled kernels, its parameters and its frames.

What :class:`sailmujoco.reference.viel.VielWorld` integrates: :class:`VielParams` (Table 1
and the actuator limits), the conversions between our frames and Viel's (the only place they
are done), and the equations written once as numba kernels, from the apparent wind to a whole
control period of RK4 steps (:func:`advance`). The conventions, signs and readings of the
printed text are set out in :mod:`sailmujoco.reference.viel`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from ..forces.wind import wind_velocity
from ..frames import wrap_angle
from ..jit.kernel import kernel
from .hypot import hypot
from .integrators import DOMAIN_ERROR, STATUS_RAN_AWAY, final_status, rk4_stage, rk4_update

STATE_NAMES = ("x", "y", "theta", "v", "u", "omega")
RK4_MAX_STEP = 0.01  # s, the longest RK4 step (Viel §5.1's dt)
RUDDER_LAWS = ("linear", "printed")  # Viel eqs. 7-8: read linear in the speed, or as printed


@dataclass(frozen=True)
class VielParams:
    """Viel et al. (2019) Table 1 (from Melin 2015) and the actuator limits of §2.1. SI units.

    Parameters
    ----------
    p1 : drift coefficient, hull wind force ``p1 a_tw^2`` [kg/m]
    p2 : tangential friction, ``p2 v|v|`` and ``p2 u|u|`` [kg/m]
    p3 : angular friction, ``p3 omega v`` [kg m]
    p4 : sail lift, ``g_s = p4 a_aw sin(delta_s - psi_aw)`` [kg/s]
    p5 : rudder lift, ``g_rv = p5 v sin(delta_r)`` [kg/s] (eq. 7 read linear, :func:`rudder_forces`)
    p6 : distance from the mast to the sail's centre of effort [m]
    p7 : distance from G to the mast [m]
    p8 : distance from G to the rudder [m]
    p9 : mass of the boat [kg]
    p10 : moment of inertia about the vertical axis [kg m^2]
    p11 : rudder brake coefficient [-]
    rudder_max : |delta_r| limit [rad]
    sail_max : |delta_s| limit [rad]
    rudder_law : "linear" (default) or "printed": how eqs. 7-8 are read, see :func:`rudder_forces`
    """

    p1: float = 0.03  # kg/m, Viel Table 1 "drift coefficient" (unit not printed)
    p2: float = 40.0  # kg/m, Viel Table 1 "tangential friction" (printed kg/s, see module doc)
    p3: float = 6000.0  # kg m, Viel Table 1 "angular friction"
    p4: float = 200.0  # kg/s, Viel Table 1 "sail lift"
    p5: float = 1500.0  # kg/s, Viel Table 1 "rudder lift" (kg/m with eq. 7's printed v^2)
    p6: float = 0.5  # m, Viel Table 1 "distance to sail" (mast to centre of effort)
    p7: float = 0.5  # m, Viel Table 1 "distance to mast" (G to mast)
    p8: float = 2.0  # m, Viel Table 1 "distance to rudder"
    p9: float = 300.0  # kg, Viel Table 1 "mass of boat"
    p10: float = 400.0  # kg m^2, Viel Table 1 "moment of inertia"
    p11: float = 0.2  # -, Viel Table 1 "rudder break coefficient"
    rudder_max: float = math.pi / 4.0  # rad, Viel §2.1 delta_r,max
    sail_max: float = math.pi / 2.0  # rad, Viel §2.1 delta_s,max
    rudder_law: str = "linear"  # Viel eqs. 7-8: "linear" (Table 1's kg/s, Jaulin) or "printed" (v^2)

    def __post_init__(self):
        if self.rudder_law not in RUDDER_LAWS:
            raise ValueError(f"VielParams.rudder_law must be one of {RUDDER_LAWS}, got {self.rudder_law!r}")
        for f in fields(self):
            if f.name == "rudder_law":
                continue
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ValueError(f"VielParams.{f.name} must be a finite number, got {value!r}")
        for name in ("p2", "p4", "p5", "p8", "p9", "p10"):
            if getattr(self, name) <= 0.0:
                raise ValueError(f"VielParams.{name} must be > 0, got {getattr(self, name)}")
        for name in ("p1", "p3", "p6", "p7", "p11"):
            if getattr(self, name) < 0.0:
                raise ValueError(f"VielParams.{name} must be >= 0, got {getattr(self, name)}")
        if not 0.0 < self.rudder_max <= math.pi / 2.0:
            raise ValueError(f"VielParams.rudder_max must be in (0, pi/2] rad, got {self.rudder_max}")
        if not 0.0 < self.sail_max <= math.pi:
            raise ValueError(f"VielParams.sail_max must be in (0, pi] rad, got {self.sail_max}")


# --- frame conversions: ours <-> Viel's, the only place they are done -------------------------


def viel_from_action(action) -> tuple[float, float]:
    """(delta_r, delta_s) in Viel's sign (trailing edge to starboard) from our ``[rudder, sail]``.

    Parameters
    ----------
    action : array_like, shape (2,)
        Ours, [rudder, sail] rad, positive trailing edge to port.
    """
    rudder, sail = np.asarray(action, dtype=float).reshape(2).tolist()
    return -rudder, -sail


def action_from_viel(delta_r: float, delta_s: float) -> np.ndarray:
    """Our action ``[rudder, sail]`` (trailing edge to port, rad) from Viel's (delta_r, delta_s).

    Parameters
    ----------
    delta_r, delta_s : float
        Viel's rudder and sail angles, rad, positive trailing edge to starboard.
    """
    return np.array([-float(delta_r), -float(delta_s)])


def psi_tw_from_direction(direction_from: float) -> float:
    """Viel's psi_tw (blows towards, ccw from east) from our compass 'comes from' bearing [rad].

    Parameters
    ----------
    direction_from : float
        Compass bearing the true wind comes from, rad.
    """
    return float(wrap_angle(-0.5 * math.pi - direction_from))


def direction_from_psi_tw(psi_tw: float) -> float:
    """Our compass 'comes from' bearing from Viel's psi_tw [rad] (the same involution).

    Parameters
    ----------
    psi_tw : float
        Viel's true wind direction (blows towards, ccw from east), rad.
    """
    return float(wrap_angle(-0.5 * math.pi - psi_tw))


def psi_aw_from_awa(awa: float) -> float:
    """Viel's psi_aw (apparent wind blows towards, ccw from the bow) from our AWA [rad].

    Parameters
    ----------
    awa : float
        Our apparent wind angle (comes from, positive from starboard), rad.
    """
    return float(wrap_angle(math.pi - awa))


def awa_from_psi_aw(psi_aw: float) -> float:
    """Our AWA (comes from, positive from starboard) from Viel's psi_aw [rad].

    Parameters
    ----------
    psi_aw : float
        Viel's apparent wind direction (blows towards, ccw from the bow), rad.
    """
    return float(wrap_angle(math.pi - psi_aw))


# --- the model --------------------------------------------------------------------------------


@kernel
def apparent_wind(a_tw: float, psi_tw: float, theta: float, v: float) -> tuple[float, float]:
    """Apparent wind (a_aw [m/s], psi_aw [rad]) in the body frame, Viel §2.3.

    ``W_c,aw = [a_tw cos(psi_tw - theta) - |v|, a_tw sin(psi_tw - theta)]`` (the paper's
    ``|v|`` is kept, see the module docstring), ``psi_aw = atan2(W_c,aw)``: where the apparent
    wind blows towards, ccw from the bow.

    Parameters
    ----------
    a_tw, psi_tw : float
        True wind speed (m/s) and direction psi_tw (where it blows towards, ccw from east, rad).
    theta : float
        Heading, ccw from east, rad.
    v : float
        Surge speed, m/s.
    """
    wx = a_tw * math.cos(psi_tw - theta) - abs(v)  # Viel §2.3
    wy = a_tw * math.sin(psi_tw - theta)  # Viel §2.3
    return hypot(wx, wy), math.atan2(wy, wx)


def rudder_forces(params: VielParams, v: float, u: float, delta_r: float) -> tuple[float, float]:
    """(g_rv, g_ru) [N], the rudder (and keel) forces of Viel eqs. 7-8.

    Eq. 7 prints ``g_rv = p5 v^2 sin(delta_r)`` and eq. 8 ``g_ru = p5 u|u| cos(delta_r)``, but
    Table 1 gives p5 in kg/s, which makes a force only of ``p5 v``: the unit and the value
    (1500) are those of Jaulin's rudder law ``p5 v sin(delta_r)`` in the model Table 1 is taken
    from (Melin 2015 after Jaulin; p1-p11 are Jaulin's). We read the printed squares as the error
    and use the law linear in the speed for both (``rudder_law="linear"``, the default):
    ``g_rv = p5 v sin(delta_r)``, ``g_ru = p5 u cos(delta_r)``. ``rudder_law="printed"`` keeps
    eqs. 7-8 as printed (then p5 is in kg/m); the viel_fig3 study reports both. Measured: with
    the printed squares the rudder has no authority once the boat has stopped in the target area
    (g_rv ~ v^2), and the hull wind p1 a_tw^2 turns and pushes it out of the area.

    Parameters
    ----------
    params : VielParams
        Viel's Table 1 parameters and rudder law.
    v, u : float
        Surge (forward) and sway (to port) speed, m/s.
    delta_r : float
        Rudder angle in Viel's sign, rad, positive trailing edge to starboard.
    """
    return _rudder_forces(params.p5, params.rudder_law == "printed", float(v), float(u), float(delta_r))


@kernel
def _rudder_forces(p5, printed, v, u, delta_r):
    """:func:`rudder_forces` for p5 and the law (``printed`` True: eqs. 7-8 as printed)."""
    if printed:
        return (p5 * v * v * math.sin(delta_r),  # Viel eq. 7 as printed
                p5 * u * abs(u) * math.cos(delta_r))  # Viel eq. 8 as printed
    return (p5 * v * math.sin(delta_r),  # Viel eq. 7, read linear in v (Table 1's kg/s)
            p5 * u * math.cos(delta_r))  # Viel eq. 8, read linear in u (Table 1's kg/s)


# the packed parameters the kernels read: VielParams' p1..p11, then the rudder law (1.0: printed)
P1, P2, P3, P4, P5, P6, P7, P8, P9, P10, P11, PRINTED = range(12)
FORCE_NAMES = ("g_s", "g_rv", "g_ru", "a_aw", "psi_aw", "hull_wind", "surge", "sway", "yaw")


def pack_parameters(params: VielParams) -> np.ndarray:
    """The flat float64 array of ``params`` the kernels read (indices ``P1`` ... ``PRINTED``).

    Parameters
    ----------
    params : VielParams
        Viel's Table 1 parameters and rudder law.
    """
    return np.array([params.p1, params.p2, params.p3, params.p4, params.p5, params.p6, params.p7,
                     params.p8, params.p9, params.p10, params.p11, float(params.rudder_law == "printed")])


@kernel
def forces_kernel(P, state, delta_r, delta_s, a_tw, psi_tw, out):
    """The Viel eq. 4-9 terms into ``out`` in the order of ``FORCE_NAMES`` (see :func:`model_forces`).

    Returns False where the Python model raised ValueError (theta infinite: math.cos(inf)).

    Parameters
    ----------
    P : numpy.ndarray, shape (12,)
        The parameters as packed by :func:`pack_parameters`, laid out by ``P1`` ... ``PRINTED``.
    state : array_like, shape (6,)
        Viel's state (x, y, theta, v, u, omega): world position x east, y north (m), heading
        theta ccw from east (rad), surge v forward and sway u to port (m/s), yaw rate omega
        (rad/s, ccw).
    delta_r, delta_s : float
        Rudder and sail angles in Viel's sign, rad, positive trailing edge to starboard.
    a_tw, psi_tw : float
        True wind speed (m/s) and direction psi_tw (where it blows towards, ccw from east, rad).
    out : numpy.ndarray, shape (9,)
        Receives the terms, N, N m, m/s and rad as in :func:`model_forces`.
    """
    theta, v, u, omega = state[2], state[3], state[4], state[5]
    if math.isinf(theta):
        return False
    a_aw, psi_aw = apparent_wind(a_tw, psi_tw, theta, v)
    g_rv, g_ru = _rudder_forces(P[P5], P[PRINTED] != 0.0, v, u, delta_r)  # Viel eqs. 7-8 (rudder_forces)
    g_s = P[P4] * a_aw * math.sin(delta_s - psi_aw)  # Viel eq. 9
    hull_wind = P[P1] * a_tw * a_tw
    surge = (g_s * math.sin(delta_s) - g_rv * P[P11] * math.sin(delta_r) - P[P2] * v * abs(v)
             + hull_wind * math.cos(psi_tw - theta))  # Viel eq. 4
    sway = (-g_ru * P[P11] * math.cos(delta_r) - P[P2] * u * abs(u)
            + hull_wind * math.sin(psi_tw - theta))  # Viel eq. 5
    yaw = (g_s * (P[P6] - P[P7] * math.cos(delta_s)) - g_rv * P[P8] * math.cos(delta_r)
           - P[P3] * omega * v)  # Viel eq. 6
    out[0], out[1], out[2], out[3], out[4] = g_s, g_rv, g_ru, a_aw, psi_aw
    out[5], out[6], out[7], out[8] = hull_wind, surge, sway, yaw
    return True


@kernel
def rates_kernel(P, state, delta_r, delta_s, a_tw, psi_tw, forces, out):
    """d/dt (x, y, theta, v, u, omega) into ``out``, Viel eqs. 1-6.

    Returns False where the Python model raised ValueError (see :func:`forces_kernel`).

    Parameters
    ----------
    P : numpy.ndarray, shape (12,)
        The parameters as packed by :func:`pack_parameters`, laid out by ``P1`` ... ``PRINTED``.
    state : array_like, shape (6,)
        Viel's state (x, y, theta, v, u, omega): world position x east, y north (m), heading
        theta ccw from east (rad), surge v forward and sway u to port (m/s), yaw rate omega
        (rad/s, ccw).
    delta_r, delta_s : float
        Rudder and sail angles in Viel's sign, rad, positive trailing edge to starboard.
    a_tw, psi_tw : float
        True wind speed (m/s) and direction psi_tw (where it blows towards, ccw from east, rad).
    forces : numpy.ndarray, shape (9,)
        Work space for :func:`forces_kernel`.
    out : numpy.ndarray, shape (6,)
        Receives the rates.
    """
    theta, v, u, omega = state[2], state[3], state[4], state[5]
    if not forces_kernel(P, state, delta_r, delta_s, a_tw, psi_tw, forces):
        return False
    c, s = math.cos(theta), math.sin(theta)
    out[0] = v * c - u * s  # Viel eq. 1
    out[1] = v * s + u * c  # Viel eq. 2
    out[2] = omega  # Viel eq. 3
    out[3] = forces[6] / P[P9]  # Viel eq. 4
    out[4] = forces[7] / P[P9]  # Viel eq. 5
    out[5] = forces[8] / P[P10]  # Viel eq. 6
    return True


@kernel
def stage_rates(t, y, P, delta_r, delta_s, z, speed10, direction_from, oscillation, frequency, phase,
                amplitude, log_z, wander_dt, wander, work, out):
    """:func:`rates_kernel` in the wind at time ``t``, height ``z``.

    Parameters
    ----------
    t : float
        Time, s.
    y : numpy.ndarray, shape (6,)
        The state, as ``state`` of :func:`rates_kernel`.
    P : numpy.ndarray, shape (12,)
        The parameters as packed by :func:`pack_parameters`, laid out by ``P1`` ... ``PRINTED``.
    delta_r, delta_s : float
        Rudder and sail angles in Viel's sign, rad, positive trailing edge to starboard.
    z : float
        Height above the water where the wind is taken, m.
    speed10, direction_from : float
        Mean wind speed at 10 m (m/s) and the compass bearing it comes from (rad).
    oscillation : numpy.ndarray, shape (3,)
        The wind's modulation: speed (m/s), direction (rad), frequency (Hz).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`~sailmujoco.forces.wind.WindField`: f_k (Hz), Y_k (rad), the
        amplitudes sqrt(2 S df) (m/s), shape (m, n), at the heights whose ln (m) is ``log_z`` (m,).
    wander_dt : float
        Time step of ``wander``, s.
    wander : numpy.ndarray
        The direction wander (rad) at ``k wander_dt`` seconds (Wille (2016a) eq. 43).
    work : numpy.ndarray, shape (2, 9) or more rows
        Work space: row 0 the world wind (ENU, m/s), row 1 the force terms.
    out : numpy.ndarray, shape (6,)
        Receives the rates.
    """
    wind = work[0]
    wind_velocity(t, z, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z, wander_dt,
                  wander, wind)
    a_tw, psi_tw = hypot(wind[0], wind[1]), math.atan2(wind[1], wind[0])
    return rates_kernel(P, y, delta_r, delta_s, a_tw, psi_tw, work[1], out)


@kernel
def advance(t0, y, dt, n, P, delta_r, delta_s, z, speed10, direction_from, oscillation, frequency, phase,
            amplitude, log_z, wander_dt, wander, work):
    """``n`` RK4 steps of ``dt / n`` of Viel eqs. 1-9 from (t0, y), y in place.

    In the wind of :func:`stage_rates`; returns a status of :mod:`.integrators`.

    Parameters
    ----------
    t0 : float
        Start time, s.
    y : numpy.ndarray, shape (6,)
        The state, as ``state`` of :func:`rates_kernel`; advanced in place.
    dt : float
        The time to advance, s.
    n : int
        Number of RK4 steps.
    P : numpy.ndarray, shape (12,)
        The parameters as packed by :func:`pack_parameters`, laid out by ``P1`` ... ``PRINTED``.
    delta_r, delta_s : float
        Rudder and sail angles in Viel's sign, rad, positive trailing edge to starboard.
    z : float
        Height above the water where the wind is taken, m.
    speed10, direction_from : float
        Mean wind speed at 10 m (m/s) and the compass bearing it comes from (rad).
    oscillation : numpy.ndarray, shape (3,)
        The wind's modulation: speed (m/s), direction (rad), frequency (Hz).
    frequency, phase, amplitude, log_z : numpy.ndarray
        The gust tables of :class:`~sailmujoco.forces.wind.WindField`: f_k (Hz), Y_k (rad), the
        amplitudes sqrt(2 S df) (m/s), shape (m, n), at the heights whose ln (m) is ``log_z`` (m,).
    wander_dt : float
        Time step of ``wander``, s.
    wander : numpy.ndarray
        The direction wander (rad) at ``k wander_dt`` seconds (Wille (2016a) eq. 43).
    work : numpy.ndarray, shape (7, 9)
        Work space (rows 0-1 for :func:`stage_rates`, 2-6 for k1..k4 and a stage's state).
    """
    h = dt / n
    k1, k2, k3, k4, ys = work[2], work[3], work[4], work[5], work[6]
    wind = (z, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z, wander_dt, wander)
    for i in range(n):
        t = t0 + i * h
        if not stage_rates(t, y, P, delta_r, delta_s, *wind, work, k1):
            return STATUS_RAN_AWAY
        rk4_stage(y, 0.5 * h, k1, ys)
        if not stage_rates(t + 0.5 * h, ys, P, delta_r, delta_s, *wind, work, k2):
            return STATUS_RAN_AWAY
        rk4_stage(y, 0.5 * h, k2, ys)
        if not stage_rates(t + 0.5 * h, ys, P, delta_r, delta_s, *wind, work, k3):
            return STATUS_RAN_AWAY
        rk4_stage(y, h, k3, ys)
        if not stage_rates(t + h, ys, P, delta_r, delta_s, *wind, work, k4):
            return STATUS_RAN_AWAY
        rk4_update(y, h, k1, k2, k3, k4)
    return final_status(y)


def model_forces(params: VielParams, state, delta_r: float, delta_s: float, a_tw: float,
                 psi_tw: float) -> dict:
    """The force terms of Viel eqs. 4-9 (Viel signs), N and N m.

    Parameters
    ----------
    params : VielParams
        Viel's Table 1 parameters and rudder law.
    state : array_like, shape (6,)
        Viel's state (x, y, theta, v, u, omega): world position x east, y north (m), heading
        theta ccw from east (rad), surge v forward and sway u to port (m/s), yaw rate omega
        (rad/s, ccw).
    delta_r, delta_s : float
        Rudder and sail angles in Viel's sign, rad, positive trailing edge to starboard.
    a_tw, psi_tw : float
        True wind speed (m/s) and direction psi_tw (where it blows towards, ccw from east, rad).

    Returns
    -------
    dict
        ``g_s``, ``g_rv``, ``g_ru`` (eqs. 7-9, N), ``a_aw`` (m/s), ``psi_aw`` (rad),
        ``hull_wind`` (N), and the right-hand sides ``surge`` (= p9 dv/dt, eq. 4), ``sway``
        (= p9 du/dt, eq. 5), ``yaw`` (= p10 domega/dt, eq. 6).
    """
    out = np.empty(len(FORCE_NAMES))
    if not forces_kernel(pack_parameters(params), np.asarray(state, dtype=float), float(delta_r),
                         float(delta_s), float(a_tw), float(psi_tw), out):
        raise ValueError(DOMAIN_ERROR)
    return dict(zip(FORCE_NAMES, out.tolist(), strict=True))


def model_rates(params: VielParams, state, delta_r: float, delta_s: float, a_tw: float,
                psi_tw: float) -> np.ndarray:
    """d/dt (x, y, theta, v, u, omega), Viel eqs. 1-6 (Viel signs for delta_r, delta_s).

    Parameters
    ----------
    params : VielParams
        Viel's Table 1 parameters and rudder law.
    state : array_like, shape (6,)
        Viel's state (x, y, theta, v, u, omega): world position x east, y north (m), heading
        theta ccw from east (rad), surge v forward and sway u to port (m/s), yaw rate omega
        (rad/s, ccw).
    delta_r, delta_s : float
        Rudder and sail angles in Viel's sign, rad, positive trailing edge to starboard.
    a_tw, psi_tw : float
        True wind speed (m/s) and direction psi_tw (where it blows towards, ccw from east, rad).
    """
    out = np.empty(6)
    if not rates_kernel(pack_parameters(params), np.asarray(state, dtype=float), float(delta_r),
                        float(delta_s), float(a_tw), float(psi_tw), np.empty(len(FORCE_NAMES)), out):
        raise ValueError(DOMAIN_ERROR)
    return out
