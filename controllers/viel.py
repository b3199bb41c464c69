"""Position keeping of Viel, Vautier, Wan and Jaulin (2019): reach a target and stay there.

Laws, all written in Viel's planar frame (:mod:`sailmujoco.reference.viel`: theta ccw from
east, psi_tw/psi_aw the directions the wind blows *towards*, rudder/sail positive with the
trailing edge to starboard). The observation is converted to that frame in one place,
:func:`viel_view`, and the action back with :func:`~sailmujoco.reference.viel_model.action_from_viel`.

* rudder, eqs. 10-11, steering the course phi when it is within epsilon_theta of the heading;
* sail, eqs. 12-17: the sail angle is moved at a rate set by the error between the desired
  and the measured acceleration, between the optimal angle (15) and the luffing limit (12);
* velocity, eq. 18: desired acceleration from the distance to the target;
* orientation, §4.3 steps 1-4: direct path, go round the target area to arrive from
  downwind, one tack to go upwind, and head to wind inside the target area (19-22).

Readings of garbled or inconsistent text (each marked where it is used):

* Eqs. 13-14 mix ``sign(delta_s)`` in the rate with ``|delta_s|`` in the update, and the
  branches "delta_s* dot < 0: speed up" only make sense for a rate of the *magnitude*
  ``|delta_s|``: with the literal sign the law would flip on the port tack. We use the
  magnitude rate ``-k_s (vdot* - vdot)`` (equal to the printed one for delta_s > 0).
* Eq. 18 writes ``v0 = max(0, u tan(theta - hat theta))``; hat theta is never defined. The proof
  (A.2, A.5) uses ``tilde theta = atan(y/x)``, the bearing from the target to the boat
  (= theta* + pi), which we use.
* Step 3: "q is used to select and keep the closer tack", but with q = 1 when theta* is
  nearer ``psi_tw + pi - delta`` the printed ``psi_tw + pi + q delta`` is the *farther* tack,
  and makes the boat tack back and forth on the layline. We use ``psi_tw + pi - q delta``
  (the closer tack, one tack as the text says).
* ε: §5.1 gives only ``epsilon_delta_s = pi/36`` (5 deg, the sail margin of eq. 16);
  epsilon_theta of eq. 10 is not given; its default here is 5 deg too (a guess).
* Eq. 20 is not bounded by delta_s,max; we bound it (the luffing angle head to wind is small).
* "this strategy is maintained only if v >= 0" (end of step 4) is read as the two cases
  (19-20) for v > 0 and (21-22) for v <= 0 as printed.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba.extending import register_jitable

from sailmujoco.frames import wrap_angle
from sailmujoco.reference.viel_model import action_from_viel

from .base import scalar

# Modes reported in ``VielController.info["mode"]``: step 1, step 2, step 3, step 4 (eqs. 19-20, 21-22).
GO_DIRECT, GO_ROUND, TACK = "direct", "go_round", "tack"
UPWIND_STOP, UPWIND_DRIVE = "upwind_v>0", "upwind_v<=0"


@register_jitable
def _sign(x: float) -> float:
    """np.sign on a float: -1, 0 or 1, NaN for NaN."""
    return 1.0 if x > 0.0 else (-1.0 if x < 0.0 else (0.0 if x == 0.0 else math.nan))


def _pair(value) -> tuple[float, float]:
    """A (2,) observation as two floats."""
    if type(value) is np.ndarray and value.shape == (2,):
        return float(value[0]), float(value[1])
    x, y = (float(a) for a in np.asarray(value, dtype=float).reshape(2))
    return x, y


@dataclass(frozen=True)
class VielView:
    """The observation in Viel's frame: SI, radians.

    Parameters
    ----------
    x, y : float
        Position, x east, y north, m.
    theta : float
        Heading, rad, counter-clockwise from east.
    phi : float
        Course over ground, rad, counter-clockwise from east.
    v : float
        Speed forward, m/s.
    u : float
        Speed to port, m/s.
    omega : float
        Yaw rate, counter-clockwise, rad/s.
    a_aw : float
        Apparent wind speed, m/s.
    psi_aw : float
        Apparent wind direction (blows towards), counter-clockwise from the bow, rad.
    psi_tw : float
        True wind direction (blows towards), counter-clockwise from east, rad.
    x_T, y_T : float
        Target position, m.
    """

    x: float
    y: float
    theta: float
    phi: float
    v: float
    u: float
    omega: float
    a_aw: float
    psi_aw: float
    psi_tw: float
    x_T: float
    y_T: float


def viel_view(observation: dict, target=None) -> VielView:
    """Convert the observation (:mod:`controllers.base`) to Viel's frame: the one place it is done.

    Reads ``position``, ``velocity``, ``heading``, ``yaw_rate``, ``apparent_wind_angle``,
    ``apparent_wind_speed``, ``true_state["wind_direction"]`` (the true wind, which the paper
    assumes known) and ``target_position`` when ``target`` is None.

    Parameters
    ----------
    observation : dict
        The observation (:mod:`controllers.base`).
    target : array_like, optional
        Target (x east, y north) [m]; None reads ``observation["target_position"]``.
    """
    x, y = _pair(observation["position"])
    vx, vy = _pair(observation["velocity"])
    # frames.yaw_from_heading, reference.viel_model.psi_aw_from_awa and psi_tw_from_direction on
    # floats: the same operations (numpy's remainder is fmod-based, as Python's %)
    theta = wrap_angle(np.pi / 2.0 - scalar(observation, "heading"))
    c, s = math.cos(theta), math.sin(theta)
    if target is None:
        if "target_position" not in observation:
            raise ValueError("VielController: no target: pass target=(x, y) or give "
                             "observation['target_position']")
        target = observation["target_position"]
    x_T, y_T = _pair(target)
    values = dict(
        x=x, y=y, theta=theta, phi=math.atan2(vy, vx), v=vx * c + vy * s, u=-vx * s + vy * c,
        omega=scalar(observation, "yaw_rate"), a_aw=scalar(observation, "apparent_wind_speed"),
        psi_aw=wrap_angle(math.pi - scalar(observation, "apparent_wind_angle")),
        psi_tw=wrap_angle(-0.5 * math.pi - scalar(observation["true_state"], "wind_direction")),
        x_T=x_T, y_T=y_T)
    for name, value in values.items():
        if not math.isfinite(value):
            raise ValueError(f"VielController: observation gives a non-finite {name} = {value}")
    return VielView(**values)


# --- the laws, Viel signs ---------------------------------------------------------------------


@register_jitable
def rudder_law(theta: float, phi: float, theta_bar: float, rudder_max: float, epsilon_theta: float) -> float:
    """delta_r [rad] (Viel sign: positive turns clockwise), eqs. 10-11.

    Steers the course phi when ``cos(theta - phi) >= cos(epsilon_theta)``, else the heading theta.

    Parameters
    ----------
    theta : float
        Heading, ccw from east [rad].
    phi : float
        Course over ground, ccw from east [rad].
    theta_bar : float
        Desired heading, ccw from east [rad].
    rudder_max : float
        delta_r,max [rad].
    epsilon_theta : float
        Course/heading switch of eq. 10 [rad].
    """
    big_theta = phi if math.cos(theta - phi) - math.cos(epsilon_theta) >= 0.0 else theta  # Viel §3.1
    e = big_theta - theta_bar
    if math.cos(e) >= 0.0:
        return rudder_max * math.sin(e)  # Viel eq. 10
    return rudder_max * _sign(math.sin(e))  # Viel eq. 11


@register_jitable
def sail_limit(psi_aw: float, sail_max: float) -> float:
    """delta_s,M = min(|pi - |psi_aw||, delta_s,max) [rad], eq. 12 (the luffing angle).

    Parameters
    ----------
    psi_aw : float
        Direction the apparent wind blows towards, ccw from the bow [rad].
    sail_max : float
        delta_s,max [rad].
    """
    return min(abs(math.pi - abs(psi_aw)), sail_max)  # Viel eq. 12


@register_jitable
def optimal_sail(psi_tw: float, theta_bar: float) -> float:
    """delta_s^opt = (pi/2) (cos(psi_tw - theta_bar) + 1) / 2 [rad], eq. 15.

    Parameters
    ----------
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    theta_bar : float
        Desired heading, ccw from east [rad].
    """
    return 0.5 * math.pi * (math.cos(psi_tw - theta_bar) + 1.0) / 2.0  # Viel eq. 15


@register_jitable
def adaptive_sail(sail_previous: float, vdot_star: float, vdot: float, psi_aw: float, psi_tw: float,
                  theta_bar: float, k_s: float, dt: float, epsilon_sail: float, sail_max: float) -> float:
    """delta_s [rad] (Viel sign), eqs. 13-14, 16-17.

    ``sail_previous`` is the last delta_s; ``vdot_star``, ``vdot`` the desired and measured
    accelerations [m/s^2]. The rate acts on |delta_s| (see the module docstring).

    Parameters
    ----------
    sail_previous : float
        Last delta_s [rad] (Viel sign).
    vdot_star : float
        Desired acceleration [m/s^2] (eq. 18).
    vdot : float
        Measured acceleration [m/s^2].
    psi_aw : float
        Direction the apparent wind blows towards, ccw from the bow [rad].
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    theta_bar : float
        Desired heading, ccw from east [rad].
    k_s : float
        Sail adaptation gain, eq. 13 [rad s/m].
    dt : float
        Control period [s].
    epsilon_sail : float
        epsilon_delta_s, the sail margin of eq. 16 [rad].
    sail_max : float
        delta_s,max [rad].
    """
    rate = -k_s * (vdot_star - vdot)  # Viel eq. 13, as the rate of |delta_s| (reading, see above)
    star = max(abs(sail_previous) + rate * dt, 0.0)  # Viel eq. 14
    limit = sail_limit(psi_aw, sail_max)  # Viel eq. 12
    side = -_sign(psi_aw)  # Viel eq. 12: to leeward
    if rate < 0.0:  # speed up
        lim = max(limit - epsilon_sail, 0.0)  # Viel, below eq. 16: delta_s^lim
        return side * max(star, min(abs(optimal_sail(psi_tw, theta_bar)), lim))  # Viel eq. 16
    return side * min(star, limit)  # Viel eq. 17 (slow down)


@register_jitable
def desired_acceleration(v: float, u: float, theta: float, theta_tilde: float, distance: float,
                         k_v: float, k_p: float) -> float:
    """vdot* = -k_v (v - v0) + k_p d_ST [m/s^2], v0 = max(0, u tan(theta - theta_tilde)), eq. 18.

    Parameters
    ----------
    v : float
        Forward speed [m/s].
    u : float
        Speed to port [m/s].
    theta : float
        Heading, ccw from east [rad].
    theta_tilde : float
        Bearing from the target to the boat, ccw from east [rad].
    distance : float
        Distance to the target d_ST [m].
    k_v : float
        Velocity gain [1/s].
    k_p : float
        Distance gain [1/s^2].
    """
    v0 = max(0.0, u * math.tan(theta - theta_tilde))  # Viel eq. 18 (hat theta read as tilde theta)
    return -k_v * (v - v0) + k_p * distance  # Viel eq. 18


@register_jitable
def go_round(theta_star: float, alpha: float, psi_tw: float, distance: float, d_T: float,
             d_M: float) -> tuple[float, bool]:
    """Step 2: (theta*, turned) — turn theta* by +-pi/2 in the pre-arrival area when the direct
    path would arrive downwind. ``alpha`` is the bearing from the target to the boat [rad].

    Parameters
    ----------
    theta_star : float
        Direct-path heading theta* [rad].
    alpha : float
        Bearing from the target to the boat [rad].
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    distance : float
        Distance to the target [m].
    d_T : float
        Radius of the target area [m].
    d_M : float
        Radius of the pre-arrival area [m].
    """
    if d_T <= distance <= d_M and math.cos(theta_star - psi_tw) > 0.0:  # Viel §4.3 step 2
        if math.cos(alpha - (psi_tw + 0.5 * math.pi)) > math.cos(alpha - (psi_tw - 0.5 * math.pi)):
            return theta_star + 0.5 * math.pi, True
        return theta_star - 0.5 * math.pi, True
    return theta_star, False


@register_jitable
def tack(theta_star: float, psi_tw: float, delta: float, q: int) -> tuple[float, int, bool]:
    """Step 3: (theta_bar, q, in_dead_area). q in {-1, 1}; 0 means not chosen yet.

    Parameters
    ----------
    theta_star : float
        Heading theta* of steps 1-2 [rad].
    psi_tw : float
        Direction the true wind blows towards, ccw from east [rad].
    delta : float
        Hauled angle of the dead area [rad].
    q : int
        The tack kept so far: -1, 1, or 0 for none yet.
    """
    nearer_minus = math.cos(theta_star - (psi_tw + math.pi - delta)) > math.cos(
        theta_star - (psi_tw + math.pi + delta))
    if math.cos(psi_tw - theta_star) + math.cos(delta) > 0.0:  # Viel §4.3 step 3: outside the dead area
        return theta_star, (1 if nearer_minus else -1), False
    if q == 0:  # entering with no history: take the closer tack
        q = 1 if nearer_minus else -1
    return psi_tw + math.pi - q * delta, q, True  # Viel step 3 (sign of q delta: reading, see above)


class VielController:
    """Viel et al. (2019) position keeping: a plain controller object.

    Parameters
    ----------
    target : (2,) array or None
        Target (x east, y north) [m]; None reads ``observation["target_position"]``.
    d_M, d_T : float
        Radii of the pre-arrival and target areas [m] (§5.1: 14, 7).
    k_s : float
        Sail adaptation gain, eq. 13 [rad s/m] (§5.1: 5).
    k_p, k_v : float
        Velocity-control gains, eq. 18 [1/s^2, 1/s] (§5.1: 1, 8).
    epsilon_deg : float
        epsilon_delta_s, the sail margin of eq. 16 [deg] (§5.1: pi/36 = 5 deg).
    dt : float
        Control period [s] (eq. 14 and the finite-difference acceleration).
    epsilon_theta_deg : float
        epsilon_theta of eq. 10 [deg] (not given in the paper; guess).
    delta_deg : float
        Hauled angle delta of the dead area [deg] (§2.1: pi/4).
    rudder_max_deg, sail_max_deg : float
        delta_r,max, delta_s,max [deg] (§2.1: 45, 90).

    Action: ``[rudder, sail]`` [rad], ours (trailing edge to port positive).
    The measured acceleration is the finite difference of v over ``dt`` (zero on the first call
    after :meth:`reset`); the sail angle of eq. 14 is the controller's own last command.
    After each call ``self.info`` holds the mode, theta_bar, vdot*, vdot, q (Viel frame).
    """

    def __init__(self, target=None, d_M: float = 14.0, d_T: float = 7.0, k_s: float = 5.0,
                 k_p: float = 1.0, k_v: float = 8.0, epsilon_deg: float = 5.0, dt: float = 0.1,
                 epsilon_theta_deg: float = 5.0, delta_deg: float = 45.0, rudder_max_deg: float = 45.0,
                 sail_max_deg: float = 90.0):
        numbers = dict(d_M=d_M, d_T=d_T, k_s=k_s, k_p=k_p, k_v=k_v, epsilon_deg=epsilon_deg, dt=dt,
                       epsilon_theta_deg=epsilon_theta_deg, delta_deg=delta_deg,
                       rudder_max_deg=rudder_max_deg, sail_max_deg=sail_max_deg)
        for name, value in numbers.items():
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise ValueError(f"VielController: {name} must be a finite number, got {value!r}")
        for name in ("d_T", "k_s", "k_p", "k_v", "dt", "delta_deg", "rudder_max_deg", "sail_max_deg"):
            if numbers[name] <= 0.0:
                raise ValueError(f"VielController: {name} must be > 0, got {numbers[name]}")
        if d_M < d_T:
            raise ValueError(f"VielController: d_M ({d_M} m) must be >= d_T ({d_T} m)")
        if not 0.0 <= epsilon_theta_deg < 90.0:
            raise ValueError(f"VielController: epsilon_theta_deg must be in [0, 90), got {epsilon_theta_deg}")
        if epsilon_deg < 0.0:
            raise ValueError(f"VielController: epsilon_deg must be >= 0, got {epsilon_deg}")
        self.target = None if target is None else np.asarray(target, dtype=float).reshape(2).copy()
        self.d_M, self.d_T = float(d_M), float(d_T)
        self.k_s, self.k_p, self.k_v = float(k_s), float(k_p), float(k_v)
        self.epsilon_sail = math.radians(epsilon_deg)
        self.epsilon_theta = math.radians(epsilon_theta_deg)
        self.delta = math.radians(delta_deg)
        self.rudder_max = math.radians(rudder_max_deg)
        self.sail_max = math.radians(sail_max_deg)
        self.dt = float(dt)
        self.reset()

    def reset(self, seed: int | None = None) -> None:
        """Forget the sail angle, the previous speed and the tack (deterministic: no randomness).

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.sail = 0.0  # last delta_s, Viel sign [rad]
        self.v_previous: float | None = None
        self.q = 0
        self.info: dict = {}

    def __call__(self, timestep) -> np.ndarray:
        """The action for this time step: Viel's strategy, rudder and sail laws.

        Parameters
        ----------
        timestep : dm_env.TimeStep
            Its ``observation`` is the dict of :mod:`sailmujoco.controllers.base`.

        Returns
        -------
        numpy.ndarray, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)].
        """
        s = viel_view(timestep.observation, self.target)
        vdot = 0.0 if self.v_previous is None else (s.v - self.v_previous) / self.dt
        self.v_previous = s.v
        dx, dy = s.x_T - s.x, s.y_T - s.y
        distance = math.hypot(dx, dy)
        vdot_star = float("nan")
        if distance < self.d_T:  # Viel §4.3 step 4: upwind strategy in the target area
            if s.v > 0.0:
                mode = UPWIND_STOP
                theta_bar = s.psi_tw + math.pi  # Viel eq. 19
                sail = -_sign(s.psi_aw) * sail_limit(s.psi_aw, self.sail_max)  # Viel eq. 20 (bounded)
            else:
                mode = UPWIND_DRIVE
                theta_bar = s.psi_tw + math.pi - self.delta * _sign(s.u)  # Viel eq. 21
                lim = max(sail_limit(s.psi_aw, self.sail_max) - self.epsilon_sail, 0.0)
                sail = -_sign(s.psi_aw) * min(abs(optimal_sail(s.psi_tw, theta_bar)), lim)  # Viel eq. 22
        else:
            theta_star = math.atan2(dy, dx)  # Viel step 1: direct path
            alpha = math.atan2(-dy, -dx)  # bearing target -> boat (Viel's alpha, = tilde theta)
            theta_star, turned = go_round(theta_star, alpha, s.psi_tw, distance, self.d_T, self.d_M)
            theta_bar, self.q, dead = tack(theta_star, s.psi_tw, self.delta, self.q)
            mode = GO_ROUND if turned else (TACK if dead else GO_DIRECT)
            vdot_star = desired_acceleration(s.v, s.u, s.theta, alpha, distance, self.k_v, self.k_p)
            sail = adaptive_sail(self.sail, vdot_star, vdot, s.psi_aw, s.psi_tw, theta_bar, self.k_s,
                                 self.dt, self.epsilon_sail, self.sail_max)
        theta_bar = wrap_angle(theta_bar)
        rudder = rudder_law(s.theta, s.phi, theta_bar, self.rudder_max, self.epsilon_theta)
        self.sail = sail
        self.info = dict(mode=mode, theta_bar=theta_bar, vdot_star=vdot_star, vdot=vdot, q=self.q,
                         distance=distance)
        return action_from_viel(rudder, sail)
