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

The laws and the readings of the paper's garbled text are in :mod:`controllers.viel_law`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sailmujoco.frames import wrap_angle
from sailmujoco.reference.viel_model import action_from_viel

from .base import scalar
from .viel_law import (
    GO_DIRECT,
    GO_ROUND,
    TACK,
    UPWIND_DRIVE,
    UPWIND_STOP,
    adaptive_sail,
    desired_acceleration,
    go_round,
    optimal_sail,
    rudder_law,
    sail_limit,
    sign,
    tack,
)


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

    def compiled_episode(self, env, low=None, high=None):
        """The episode of ``env`` (just reset) by the compiled closed loop of
        :mod:`controllers.viel_loop` (the same steps as calling this controller, to the bit), or
        None where it does not cover the pair (:mod:`sailmujoco.loop.episode`).

        Parameters
        ----------
        env : sailmujoco.tasks.environment.SailEnvironment
            The environment, reset.
        low, high : array_like, optional
            A clip of the command (the suite's ``Bounded``); none by default.
        """
        from .viel_loop import compiled_episode

        return compiled_episode(self, env, low, high)

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
                sail = -sign(s.psi_aw) * sail_limit(s.psi_aw, self.sail_max)  # Viel eq. 20 (bounded)
            else:
                mode = UPWIND_DRIVE
                theta_bar = s.psi_tw + math.pi - self.delta * sign(s.u)  # Viel eq. 21
                lim = max(sail_limit(s.psi_aw, self.sail_max) - self.epsilon_sail, 0.0)
                sail = -sign(s.psi_aw) * min(abs(optimal_sail(s.psi_tw, theta_bar)), lim)  # Viel eq. 22
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
