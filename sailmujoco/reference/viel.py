"""The paper world of Viel, Vautier, Wan and Jaulin (2019), "Position keeping control of an
autonomous sailboat": their 3-DOF sailboat model (eqs. 1-9, Table 1 from Melin 2015 / Jaulin),
integrated with classical fourth-order Runge-Kutta at steps of at most 0.01 s (the paper's dt),
or adaptively with :func:`scipy.integrate.solve_ivp` (``integrator="rk45"``; the two agree to
micrometres over a minute, ``tests/test_viel.py``). The fixed step is the default because the
world is stepped every 0.01 s, where solve_ivp's set-up per call cost more than the model.

Viel's planar frame
    x east, y north (the x-y plane of our ENU world, :mod:`sailmujoco.frames`); the state is
    ``(x, y, theta, v, u, omega)``: position of the boat [m], orientation ``theta`` counter-
    clockwise from east [rad] (our ENU ``yaw``), forward speed ``v`` and sway speed ``u`` in
    the body frame [m/s] (eqs. 1-2: ``u`` points 90 deg counter-clockwise of the bow, i.e. to
    port: Viel's body frame is our FLU frame, ``v`` = our surge, ``u`` = our sway), and the
    yaw rate ``omega`` [rad/s], positive counter-clockwise (our ``yaw_rate``).

Wind angles (Viel §2.3, Jaulin's convention)
    ``psi_tw`` is the direction the true wind blows **towards**, counter-clockwise from east;
    ``psi_aw`` the direction the apparent wind blows towards in the body frame, counter-
    clockwise from the bow. Evidence: eq. 4's hull-wind term ``p1 a_tw^2 cos(psi_tw - theta)``
    pushes the boat forward when ``theta = psi_tw``, and eq. 19 "orients the boat front the
    wind" with ``theta = psi_tw + pi``. Ours is a compass bearing the wind comes *from*, so
    ``psi_tw = -pi/2 - direction_from`` (the map is its own inverse), and from the apparent
    wind angle (AWA, from the bow, positive from starboard) ``psi_aw = pi - AWA``.

Rudder and sail signs (derived from eqs. 4-6 and 9)
    Eq. 6 gives the rudder moment ``-p8 g_rv cos(delta_r)`` with ``g_rv = p5 v sin(delta_r)``:
    a positive ``delta_r`` turns the boat clockwise (to starboard), so the rudder lift pushes
    the stern to port and the trailing edge points to starboard. For the sail, eqs. 4, 6 and 9
    are reproduced exactly by a boom pointing aft along ``(-cos delta_s, -sin delta_s)`` from a
    mast ``p7`` ahead of G, the centre of effort ``p6`` along the boom, and the normal force
    ``g_s (sin delta_s, -cos delta_s)`` with ``g_s = p4 (W_aw . n)``: the moment about G is
    then ``g_s (p6 - p7 cos delta_s)`` (eq. 6) and the thrust ``g_s sin delta_s`` (eq. 4).
    So a positive ``delta_s`` also swings the trailing edge (boom end) to **starboard**.
    Our action is positive to port, hence ``delta_r = -rudder`` and ``delta_s = -sail``
    (:func:`viel_from_action`, :func:`action_from_viel`, the only place this is done).
    Check: a free sail (``g_s = 0``, stable) settles at ``delta_s = psi_aw - sign(psi_aw) pi``,
    the boundary of Viel's eq. 12, i.e. to leeward; the tests verify both signs physically.

Readings of the text (the paper's own model, kept as printed unless marked)
    * §2.3 writes the apparent wind with ``-|v|``: kept (the paper world), although for a boat
      going astern (``v < 0``, which Viel's step 4 allows) the physical term is ``-v``.
    * Eqs. 7-8 print ``p5 v^2`` and ``p5 u|u|`` with p5 in kg/s: read linear in the speed
      (Jaulin's law, which Table 1's p5 belongs to), see :func:`rudder_forces`; the printed
      squares are ``VielParams(rudder_law="printed")``. Eq. 6's ``-p3 omega v`` becomes an
      anti-damping for ``v < 0``; kept as printed, only slow astern motion occurs in practice.
    * Eq. 5 has ``-g_ru p11 cos(delta_r)`` while the proof (A.7) drops ``p11``; eq. 5 is used.
    * Table 1 gives p2 in kg/s too, but eq. 4's friction ``p2 v|v|`` is quadratic in Jaulin's
      model as well (the unit is his mislabel): kept quadratic, p2 in kg/m.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from .._jit import kernel
from ..forces.wind import WANDER_DT, WindConfig, WindField, wind_velocity
from ..frames import heading_from_yaw, wrap_angle
from .hypot import hypot
from .integrators import (
    DOMAIN_ERROR,
    INTEGRATORS,
    MESSAGES,
    STATUS_RAN_AWAY,
    final_status,
    integrate,
    rk4_stage,
    rk4_update,
    steps_for,
)

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
    """(delta_r, delta_s) in Viel's sign (trailing edge to starboard) from our ``[rudder, sail]``."""
    rudder, sail = np.asarray(action, dtype=float).reshape(2).tolist()
    return -rudder, -sail


def action_from_viel(delta_r: float, delta_s: float) -> np.ndarray:
    """Our action ``[rudder, sail]`` (trailing edge to port, rad) from Viel's (delta_r, delta_s)."""
    return np.array([-float(delta_r), -float(delta_s)])


def psi_tw_from_direction(direction_from: float) -> float:
    """Viel's psi_tw (blows towards, ccw from east) from our compass 'comes from' bearing [rad]."""
    return float(wrap_angle(-0.5 * math.pi - direction_from))


def direction_from_psi_tw(psi_tw: float) -> float:
    """Our compass 'comes from' bearing from Viel's psi_tw [rad] (the same involution)."""
    return float(wrap_angle(-0.5 * math.pi - psi_tw))


def psi_aw_from_awa(awa: float) -> float:
    """Viel's psi_aw (apparent wind blows towards, ccw from the bow) from our AWA [rad]."""
    return float(wrap_angle(math.pi - awa))


def awa_from_psi_aw(psi_aw: float) -> float:
    """Our AWA (comes from, positive from starboard) from Viel's psi_aw [rad]."""
    return float(wrap_angle(math.pi - psi_aw))


# --- the model --------------------------------------------------------------------------------


@kernel
def apparent_wind(a_tw: float, psi_tw: float, theta: float, v: float) -> tuple[float, float]:
    """Apparent wind (a_aw [m/s], psi_aw [rad]) in the body frame, Viel §2.3.

    ``W_c,aw = [a_tw cos(psi_tw - theta) - |v|, a_tw sin(psi_tw - theta)]`` (the paper's
    ``|v|`` is kept, see the module docstring), ``psi_aw = atan2(W_c,aw)``.
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
    """The flat float64 array of ``params`` the kernels read (indices ``P1`` ... ``PRINTED``)."""
    return np.array([params.p1, params.p2, params.p3, params.p4, params.p5, params.p6, params.p7,
                     params.p8, params.p9, params.p10, params.p11, float(params.rudder_law == "printed")])


@kernel
def forces_kernel(P, state, delta_r, delta_s, a_tw, psi_tw, out):
    """The eq. 4-9 terms into ``out`` in the order of ``FORCE_NAMES`` (see :func:`model_forces`).
    Returns False where the Python model raised ValueError (theta infinite: math.cos(inf))."""
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
    """d/dt (x, y, theta, v, u, omega) into ``out`` (eqs. 1-6); ``forces`` (9,) is work space.
    Returns False where the Python model raised ValueError (see :func:`forces_kernel`)."""
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
    """:func:`rates_kernel` in the wind at time ``t``, height ``z`` (``work``: (2, 9))."""
    wind = work[0]
    wind_velocity(t, z, speed10, direction_from, oscillation, frequency, phase, amplitude, log_z, wander_dt,
                  wander, wind)
    a_tw, psi_tw = hypot(wind[0], wind[1]), math.atan2(wind[1], wind[0])
    return rates_kernel(P, y, delta_r, delta_s, a_tw, psi_tw, work[1], out)


@kernel
def advance(t0, y, dt, n, P, delta_r, delta_s, z, speed10, direction_from, oscillation, frequency, phase,
            amplitude, log_z, wander_dt, wander, work):
    """``n`` RK4 steps of ``dt / n`` of eqs. 1-9 from (t0, y), y in place, in the wind of
    :func:`stage_rates`; returns a status of :mod:`.integrators`. ``work``: (7, 9)."""
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
    """The force terms of eqs. 4-9 (Viel signs), N and N m.

    Returns a dict with ``g_s``, ``g_rv``, ``g_ru`` (eqs. 7-9), ``a_aw``, ``psi_aw``, and the
    right-hand sides ``surge`` (= p9 dv/dt, eq. 4), ``sway`` (= p9 du/dt, eq. 5),
    ``yaw`` (= p10 domega/dt, eq. 6).
    """
    out = np.empty(len(FORCE_NAMES))
    if not forces_kernel(pack_parameters(params), np.asarray(state, dtype=float), float(delta_r),
                         float(delta_s), float(a_tw), float(psi_tw), out):
        raise ValueError(DOMAIN_ERROR)
    return dict(zip(FORCE_NAMES, out.tolist(), strict=True))


def model_rates(params: VielParams, state, delta_r: float, delta_s: float, a_tw: float,
                psi_tw: float) -> np.ndarray:
    """d/dt (x, y, theta, v, u, omega), Viel eqs. 1-6 (Viel signs for delta_r, delta_s)."""
    out = np.empty(6)
    if not rates_kernel(pack_parameters(params), np.asarray(state, dtype=float), float(delta_r),
                        float(delta_s), float(a_tw), float(psi_tw), np.empty(len(FORCE_NAMES)), out):
        raise ValueError(DOMAIN_ERROR)
    return out


class VielWorld:
    """Viel's 3-DOF sailboat (eqs. 1-9) in a wind from :class:`~sailmujoco.forces.wind.WindField`.

    Parameters
    ----------
    params : VielParams
        Table 1 and the actuator limits.
    wind : WindConfig or WindField
        The true wind; ``WindField(config).velocity(t, wind_height)`` gives (a_tw, psi_tw).
        A WindField instance (or subclass) is used as given. Default: Viel §5.1 case 1,
        10 m/s blowing north (from the south), no gusts, no wander.
    wind_height : float
        Height at which the wind is sampled [m] (the model has no height; 10 m is the
        reference height of ``WindConfig.speed``).
    integrator : str
        ``"rk4"`` (classical Runge-Kutta, steps of at most ``RK4_MAX_STEP``) or ``"rk45"``
        (:func:`scipy.integrate.solve_ivp`, adaptive).
    rtol, atol : float
        Tolerances of the RK45 integration.

    The action of :meth:`step` is ours, ``[rudder, sail]`` [rad], positive when the trailing
    edge swings to port, saturated at ``params.rudder_max`` and ``params.sail_max`` and held
    over the step; the wind and forces are re-evaluated at every integrator stage.
    """

    def __init__(self, params: VielParams | None = None, wind: WindConfig | WindField | None = None,
                 wind_height: float = 10.0, integrator: str = "rk4", rtol: float = 1e-7,
                 atol: float = 1e-9):
        self.params = VielParams() if params is None else params
        if not isinstance(self.params, VielParams):
            raise TypeError(f"params must be a VielParams, got {type(self.params).__name__}")
        if wind is None:
            wind = WindConfig(speed=10.0, direction_from=math.pi, gusts=False, wander=False)
        if isinstance(wind, WindConfig):
            wind = WindField(wind)
        if not isinstance(wind, WindField):
            raise TypeError(f"wind must be a WindConfig or WindField, got {type(wind).__name__}")
        self.wind = wind
        self._work = np.zeros((7, len(FORCE_NAMES)))  # the compiled RK4's stages and forces
        self._P, self._packed_params = pack_parameters(self.params), self.params
        if not (math.isfinite(wind_height) and wind_height > 0.0):
            raise ValueError(f"wind_height must be a positive finite height in m, got {wind_height}")
        self.wind_height = float(wind_height)
        if integrator not in INTEGRATORS:
            raise ValueError(f"integrator must be one of {INTEGRATORS}, got {integrator!r}")
        self.integrator = integrator
        self.rtol, self.atol = float(rtol), float(atol)
        self._state = np.zeros(6)
        self._time = 0.0
        self._action = np.zeros(2)
        self.reset()

    # -- state ------------------------------------------------------------------------------
    def reset(self, state=None, time: float = 0.0) -> np.ndarray:
        """Set the state ``(x, y, theta, v, u, omega)`` (default: at rest at the origin facing
        east) and the time [s]; the action is set to zero. Returns a copy of the state."""
        new = np.zeros(6) if state is None else np.asarray(state, dtype=float).copy()
        if new.shape != (6,):
            raise ValueError(f"state must have the 6 entries {STATE_NAMES}, got shape {new.shape}")
        if not np.all(np.isfinite(new)):
            raise ValueError(f"state must be finite, got {dict(zip(STATE_NAMES, new, strict=True))}")
        if not math.isfinite(time):
            raise ValueError(f"time must be finite, got {time}")
        new[2] = float(wrap_angle(new[2]))
        self._state, self._time, self._action = new, float(time), np.zeros(2)
        return self._state.copy()

    def _checked_action(self, action) -> np.ndarray:
        a = np.asarray(action, dtype=float)
        if a.shape != (2,):
            raise ValueError(f"action must be [rudder, sail] in rad, got shape {a.shape}")
        rudder, sail = a.tolist()
        if not (math.isfinite(rudder) and math.isfinite(sail)):
            raise ValueError(f"action must be finite, got {a}")
        p = self.params  # np.clip's values below, without its cost
        return np.array([min(max(rudder, -p.rudder_max), p.rudder_max),
                         min(max(sail, -p.sail_max), p.sail_max)])

    def _packed(self) -> np.ndarray:
        """The parameters as the kernels read them (:func:`pack_parameters`), packed once."""
        if self._packed_params is not self.params:
            self._P, self._packed_params = pack_parameters(self.params), self.params
        return self._P

    def true_wind(self, t: float | None = None) -> tuple[float, float]:
        """(a_tw [m/s], psi_tw [rad], Viel's blows-towards angle) at time t (default: now)."""
        w = self.wind.velocity(self._time if t is None else t, self.wind_height)
        return math.hypot(w[0], w[1]), math.atan2(w[1], w[0])

    def rates(self, state=None, action=None, t: float | None = None) -> np.ndarray:
        """Time derivative of the state (eqs. 1-6) for our action [rad] (default: current)."""
        state = self._state if state is None else np.asarray(state, dtype=float)
        action = self._action if action is None else self._checked_action(action)
        delta_r, delta_s = viel_from_action(action)
        a_tw, psi_tw = self.true_wind(t)
        out = np.empty(6)
        if not rates_kernel(self._packed(), np.ascontiguousarray(state, dtype=float), delta_r, delta_s, a_tw,
                            psi_tw, np.empty(len(FORCE_NAMES)), out):
            raise ValueError(DOMAIN_ERROR)
        return out

    def forces(self, state=None, action=None, t: float | None = None, true_wind=None) -> dict:
        """The terms of eqs. 4-9 (see :func:`model_forces`) for our action [rad]; ``true_wind``:
        :meth:`true_wind` at ``t`` if the caller has it."""
        state = self._state if state is None else np.asarray(state, dtype=float)
        action = self._action if action is None else self._checked_action(action)
        delta_r, delta_s = viel_from_action(action)
        a_tw, psi_tw = self.true_wind(t) if true_wind is None else true_wind
        out = np.empty(len(FORCE_NAMES))
        if not forces_kernel(self._packed(), np.ascontiguousarray(state, dtype=float), delta_r, delta_s, a_tw,
                             psi_tw, out):
            raise ValueError(DOMAIN_ERROR)
        return dict(zip(FORCE_NAMES, out.tolist(), strict=True))

    def step(self, action, dt: float) -> np.ndarray:
        """Hold ``action`` (ours, [rad]) for ``dt`` [s]; integrate eqs. 1-9. Returns the state."""
        applied = self._checked_action(action)
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt must be a positive finite time in s, got {dt}")
        delta_r, delta_s = viel_from_action(applied)
        wind, z, P = self.wind, self.wind_height, self._packed()
        if self.integrator == "rk4" and type(wind).velocity is WindField.velocity:  # one compiled call
            wind.ensure(self._time + dt + 1.0)
            new = self._state.copy()
            status = advance(self._time, new, float(dt), steps_for(dt, RK4_MAX_STEP), P, delta_r, delta_s, z,
                             float(wind.config.speed), float(wind.config.direction_from), wind.oscillation,
                             wind.gust_frequency, wind.gust_phase, wind.gust_amplitude, wind.log_z, WANDER_DT,
                             wind.wander, self._work)
            if status == STATUS_RAN_AWAY:  # as integrate(): the state it ran away from
                new = self._state
            message = MESSAGES[status]
        else:  # RK45, or a wind whose velocity is not WindField's: the same kernels stage by stage
            work = np.empty(len(FORCE_NAMES))

            def rhs(t, y):
                w = wind.velocity(t, z)
                out = np.empty(6)
                if not rates_kernel(P, np.ascontiguousarray(y, dtype=float), delta_r, delta_s,
                                    math.hypot(w[0], w[1]), math.atan2(w[1], w[0]), work, out):
                    raise ValueError(DOMAIN_ERROR)
                return out

            new, message = integrate(rhs, self._time, self._state, dt, self.integrator, RK4_MAX_STEP,
                                     self.rtol, self.atol)
        if message:
            raise FloatingPointError(
                f"VielWorld: integration failed at t={self._time:.3f} s ({message}); "
                f"state {dict(zip(STATE_NAMES, new, strict=True))}, action {applied}")
        new = new.copy()
        new[2] = (float(new[2]) + math.pi) % (2.0 * math.pi) - math.pi  # frames.wrap_angle's value, in floats
        self._state, self._time, self._action = new, self._time + dt, applied
        return new.copy()

    # -- accessors ----------------------------------------------------------------------------
    @property
    def time(self) -> float:
        """Simulation time [s]."""
        return self._time

    @property
    def state(self) -> np.ndarray:
        """Copy of ``(x, y, theta, v, u, omega)`` [m, m, rad, m/s, m/s, rad/s], Viel's frame."""
        return self._state.copy()

    @property
    def action(self) -> np.ndarray:
        """The last applied (saturated) action, ours: ``[rudder, sail]`` [rad]."""
        return self._action.copy()

    def position(self) -> np.ndarray:
        """(x east, y north) [m]."""
        return self._state[:2].copy()

    def yaw(self) -> float:
        """Viel's theta = our ENU yaw, ccw from east [rad]."""
        return float(self._state[2])

    def heading(self) -> float:
        """Compass heading, clockwise from north [rad]."""
        return float(heading_from_yaw(self._state[2]))

    def forward_speed(self) -> float:
        """Viel's v, along the bow [m/s]."""
        return float(self._state[3])

    def sway_speed(self) -> float:
        """Viel's u, to port [m/s]."""
        return float(self._state[4])

    def yaw_rate(self) -> float:
        """omega, counter-clockwise [rad/s]."""
        return float(self._state[5])

    def velocity(self) -> np.ndarray:
        """Ground velocity (east, north) [m/s], eqs. 1-2 (kinematics only: no forces needed)."""
        _, _, theta, v, u, _ = self._state
        c, s = math.cos(theta), math.sin(theta)
        return np.array([v * c - u * s, v * s + u * c])

    def apparent_wind(self, true_wind=None) -> tuple[float, float]:
        """(a_aw [m/s], psi_aw [rad], Viel's body blows-towards angle), §2.3 (``true_wind``:
        :meth:`true_wind` now, if the caller has it)."""
        a_tw, psi_tw = self.true_wind() if true_wind is None else true_wind
        return apparent_wind(a_tw, psi_tw, self._state[2], self._state[3])

    def wind_direction(self) -> float:
        """Compass bearing the true wind comes from now [rad] (mean, schedule, oscillation, wander)."""
        return float(wrap_angle(self.wind.direction_from(self._time)))

    def wrenches(self, true_wind=None) -> dict:
        """Body (FLU) wrenches (Fx, Fy, Fz, Mx, My, Mz) [N, N m] of the eq. 4-6 terms, now.

        ``sail_wrench``: the sail terms (eq. 4 thrust, eq. 6 moment; eq. 5 has no sail term,
        Viel: "compensated by the keel"); ``rudder_wrench``: the g_rv, g_ru terms;
        ``damping_wrench``: p2 and p3 frictions; ``hull_wind_wrench``: p1 a_tw^2. ``true_wind``:
        :meth:`true_wind` now, if the caller has it.
        """
        a_tw, psi_tw = true_wind = self.true_wind() if true_wind is None else true_wind
        f = self.forces(true_wind=true_wind)
        p, (_, _, theta, v, u, omega) = self.params, self._state
        delta_r, delta_s = viel_from_action(self._action)
        zero = np.zeros(6)
        sail = np.array([f["g_s"] * math.sin(delta_s), 0, 0, 0, 0,
                         f["g_s"] * (p.p6 - p.p7 * math.cos(delta_s))])
        rudder = np.array([-f["g_rv"] * p.p11 * math.sin(delta_r), -f["g_ru"] * p.p11 * math.cos(delta_r),
                           0, 0, 0, -f["g_rv"] * p.p8 * math.cos(delta_r)])
        damping = np.array([-p.p2 * v * abs(v), -p.p2 * u * abs(u), 0, 0, 0, -p.p3 * omega * v])
        hull = f["hull_wind"] * np.array([math.cos(psi_tw - theta), math.sin(psi_tw - theta), 0, 0, 0, 0])
        return dict(sail_wrench=sail, keel_wrench=zero.copy(), rudder_wrench=rudder, damping_wrench=damping,
                    added_mass_wrench=zero.copy(), restoring_wrench=zero.copy(), hull_wind_wrench=hull)


def observation_from_world(world: VielWorld, target=None) -> dict:
    """The observation dict of :mod:`sailmujoco.controllers.base` from a :class:`VielWorld`.

    Planar world: ``heel``, ``pitch``, roll and pitch rates, ``w`` are zero; no current
    (``u_r = u``); the apparent wind is Viel's §2.3 one (no masthead height in the model);
    ``wind_speed_10`` is the WindConfig's mean speed at 10 m and ``wind_direction`` the
    compass bearing the wind comes from (as in :mod:`sailmujoco.tasks.base`).
    ``target`` (x east, y north) [m], if given, becomes ``target_position``.
    """
    x, y, theta, v, u, omega = world.state
    a_tw, psi_tw = wind = world.true_wind()  # once: apparent wind and wrenches take it
    a_aw, psi_aw = world.apparent_wind(wind)
    flow_body = np.array([a_aw * math.cos(psi_aw), a_aw * math.sin(psi_aw)])  # where it blows to
    true_wind = np.array([a_tw * math.cos(psi_tw), a_tw * math.sin(psi_tw)])
    action = world.action
    heading = world.heading()
    true_state = dict(
        u=np.array(v), v=np.array(u), w=np.array(0.0), u_r=np.array(v), v_r=np.array(u),
        yaw=np.array(theta), heel=np.array(0.0), pitch=np.array(0.0), roll_rate=np.array(0.0),
        pitch_rate=np.array(0.0), yaw_rate=np.array(omega), rudder=np.array(action[0]),
        sail=np.array(action[1]), true_wind=true_wind, wind_speed_10=np.array(world.wind.config.speed),
        wind_direction=np.array(world.wind_direction()), apparent_wind_ce=flow_body,
        current=np.zeros(2), time=np.array(world.time), **world.wrenches(wind))
    obs = dict(
        position=np.array([x, y]), velocity=world.velocity(), heading=np.array(heading),
        heel=np.array(0.0), roll_rate=np.array(0.0), yaw_rate=np.array(omega),
        apparent_wind_angle=np.array(awa_from_psi_aw(psi_aw)), apparent_wind_speed=np.array(a_aw),
        true_state=true_state)
    if target is not None:
        obs["target_position"] = np.asarray(target, dtype=float).reshape(2).copy()
    return obs
