"""Named controllers for the sweep engine and the CLI (``sailmujoco.controllers`` entry points).

Each factory takes the environment (for the boat's parameters and the control period) and
keyword options, and returns a controller (``reset(seed)``, ``__call__(timestep)``).
Angles in options end in ``_deg``.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from .base import Composite
from .pid import PIDHeading
from .sail_laws import FixedSail, LeewardSail

if TYPE_CHECKING:
    from sailmujoco.boat.params import BoatParams

    from .saoud_model import SaoudParams


class Bounded:
    """A controller whose action is clipped to the environment's action bounds (a controller
    designed for another boat may ask for more rudder than this one has).

    Parameters
    ----------
    controller : callable
        ``controller(timestep) -> action``, optionally with ``reset(seed)``.
    low, high : array_like
        The action bounds.
    """

    def __init__(self, controller, low, high):
        self.controller = controller
        self.low, self.high = np.asarray(low, dtype=float), np.asarray(high, dtype=float)

    def reset(self, seed: int | None = None) -> None:
        """Reset the wrapped controller.

        Parameters
        ----------
        seed : int, optional
            Passed to the controller's ``reset``.
        """
        if hasattr(self.controller, "reset"):
            self.controller.reset(seed)

    def __call__(self, timestep) -> np.ndarray:
        """The wrapped controller's action clipped to the bounds.

        Parameters
        ----------
        timestep : dm_env.TimeStep
            Passed to the wrapped controller.

        Returns
        -------
        numpy.ndarray, shape (2,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)].
        """
        return np.clip(self.controller(timestep), self.low, self.high)

    def compiled_episode(self, env):
        """The wrapped controller's compiled episode (:mod:`sailmujoco.loop.episode`) with this
        clip, or None if it offers none.

        Parameters
        ----------
        env : sailmujoco.tasks.environment.SailEnvironment
            The environment, reset.
        """
        offer = getattr(self.controller, "compiled_episode", None)
        return None if offer is None else offer(env, self.low, self.high)

    def __getattr__(self, name):
        # only for attributes not found on self; before __init__ or __setstate__ has set
        # ``controller`` (copy and pickle build the object bare) there is nothing to forward to
        if name == "controller":
            raise AttributeError(name)
        return getattr(self.controller, name)


class SheetFromAngle:
    """Drive a sheeted sail with an angle law: the sheet is let out to the angle's magnitude.

    A sheet only limits the boom (Wille 2016b §2.1): the wind sets the side, and an angle the
    wind cannot hold (to windward, or closer than the wind allows) is not reached.

    Parameters
    ----------
    law : callable
        ``law(observation) -> sail angle`` [rad], optionally with ``reset(seed)``.
    params : BoatParams
        The boat, for the sheet's geometry.
    """

    def __init__(self, law, params):
        self.law = law
        self.params = params

    def length(self, angle: float) -> float:
        """Sheet length [m] that lets the boom out to ``|angle|`` [rad].

        Parameters
        ----------
        angle : float
            Sail angle [rad]; its magnitude is used.
        """
        from sailmujoco.boat.mjcf import sheet_length

        return float(sheet_length(self.params, abs(angle)))

    def reset(self, seed: int | None = None) -> None:
        """Reset the angle law.

        Parameters
        ----------
        seed : int, optional
            Passed to the law's ``reset``.
        """
        if hasattr(self.law, "reset"):
            self.law.reset(seed)

    def __call__(self, observation) -> float:
        """The sheet length for the law's sail angle at this observation.

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base`, passed to the law.

        Returns
        -------
        float
            Sheet length, m.
        """
        return self.length(self.law(observation))


def _composite(env, rudder, sail):
    """Rudder + sail law; on a sheeted-sail boat the sail angle becomes a sheet length."""
    if getattr(env.physics, "sail_mode", "actuated") == "sheeted":
        sail = SheetFromAngle(sail, _boat(env))
    return Composite(rudder, sail)


def _boat(env):
    return getattr(env.physics, "params", None)


def _rudder(env, kp=1.0, ki=0.05, kd=2.0):
    """PID on the task's reference: desired heading, or the desired course as a heading."""
    key = "desired_heading" if "desired_heading" in env.observation_spec() else "desired_course"
    params = _boat(env)
    max_angle = params.rudder.max_angle if hasattr(params, "rudder") else math.radians(35.0)
    return PIDHeading(kp=kp, ki=ki, kd=kd, dt=env.control_timestep(), max_angle=max_angle,
                      reference_key=key)


def pid(env, kp: float = 1.0, ki: float = 0.05, kd: float = 2.0, fraction: float = 0.5) -> Composite:
    """PID heading controller with the leeward rule-of-thumb sail.

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    kp, ki, kd : float
        Gains of the heading PID (:class:`controllers.pid.PIDHeading`).
    fraction : float
        Sail angle as a fraction of the apparent-wind angle (:class:`controllers.sail_laws.LeewardSail`).

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    return _composite(env, _rudder(env, kp, ki, kd), LeewardSail(fraction=fraction))


def fixed_sail(env, sail_deg: float = 30.0, kp: float = 1.0, ki: float = 0.05,
               kd: float = 2.0) -> Composite:
    """PID heading controller with a fixed sail angle to leeward (brute-force searches).

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    sail_deg : float
        Sail angle to leeward [deg].
    kp, ki, kd : float
        Gains of the heading PID (:class:`controllers.pid.PIDHeading`).

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    return _composite(env, _rudder(env, kp, ki, kd), FixedSail(math.radians(sail_deg)))


def wille_heading(env, kp: float = 3e5, kd: float = 1e6, course: bool = False) -> Composite:
    """Wille (2016a) heading (or course) controller with the lambda100 sail of Wille (2016b).

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    kp : float
        Proportional gain of :class:`controllers.wille.WilleHeading`.
    kd : float
        Derivative gain of :class:`controllers.wille.WilleHeading`.
    course : bool
        Hold the course over ground (eqs. 52-59) instead of the heading.

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    from .wille import WilleHeading
    from .wille_roll import WilleRollSail

    params = _boat(env)
    return _composite(env, WilleHeading(params, kp=kp, kd=kd, course=course),
                      WilleRollSail(params, roll_control=False))


def wille_course(env, kp: float = 3e5, kd: float = 1e6) -> Composite:
    """Wille (2016a) course controller (eqs. 52-59) with the lambda100 sail.

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    kp, kd : float
        Gains of :class:`controllers.wille.WilleHeading`, as for :func:`wille_heading`.

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    return wille_heading(env, kp=kp, kd=kd, course=True)


def wille_roll(env, wind: str = "perfect", roll_control: bool = True,
               heel_desired_deg: float = 10.0) -> Composite:
    """Wille (2016b) roll stabilisation sail with a PID heading rudder (the paper's runs hold a
    beam-reach course).

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    wind : {"perfect", "mean_speed", "mean"}
        The sail law's wind estimate (:class:`controllers.wille_roll.WilleRollSail`).
    roll_control : bool
        False: always the sail angle of maximum surge force, lambda_100.
    heel_desired_deg : float
        Desired heel phi_d [deg].

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    from .wille_roll import WilleRollSail

    return _composite(env, _rudder(env), WilleRollSail(_boat(env), wind=wind, roll_control=roll_control,
                                                       heel_desired=math.radians(heel_desired_deg)))


def saoud_params(params: BoatParams) -> SaoudParams:
    """Saoud's Table I quantities for a boat: mass, sail area, air density and the heeling arm
    h_s (sail CE above the CG). For saoud_robot at l_phi = 0.1 m this is Table I itself; at
    l_phi = 1 m the 6-DOF robot's arm is 1.7 m (xml/saoud_robot/README.md).

    Parameters
    ----------
    params : BoatParams
        The boat.

    Returns
    -------
    SaoudParams
        The reduced model's parameters for that boat.
    """
    from .saoud import SaoudParams

    return SaoudParams(mass=params.mass, sail_area=params.sail.area, rho_air=params.rho_air,
                       h_s=params.sail.ce_height - params.cg_z)


def saoud(env, l_phi: float | None = None, phi_max_deg: float | None = 30.0,
          paper_numbers: bool = False, wind_source: str = "saoud_v") -> Composite:
    """Saoud (2015) optimal sail angle (eq. 13 / 14) with a PID heading rudder.

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    l_phi : float, optional
        Metacentric height in beta [m]; default the boat's GM_t.
    phi_max_deg : float or None
        Roll limit [deg] (problem 14); None for problem 5.
    paper_numbers : bool
        Keep Table I (h_s = 0.8 m) whatever the boat; by default the optimiser gets the
        boat's own mass, sail and heeling arm (:func:`saoud_params`).
    wind_source : {"saoud_v", "ce", "masthead"}
        Saoud's V (§IV), or a measured apparent wind ("ce", "masthead": they include the
        boom's swing); see :func:`controllers.saoud.observed_apparent_wind`.

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    from .saoud import SaoudParams, SaoudSail

    params = _boat(env)
    if l_phi is None:
        l_phi = params.gm_t
    phi_max = None if phi_max_deg is None else math.radians(phi_max_deg)
    table = SaoudParams() if paper_numbers else saoud_params(params)
    return _composite(env, _rudder(env), SaoudSail(l_phi=l_phi, phi_max=phi_max, params=table,
                                                   wind_source=wind_source))


def briere(env, wind_source: str = "saoud_v") -> Composite:
    """IBOAT/Briere sail trimming "Bm" (Saoud Fig. 5) with a PID heading rudder.

    Parameters
    ----------
    env : Environment
        The task environment (boat parameters, control period, observation keys).
    wind_source : {"saoud_v", "ce", "masthead"}
        Where the apparent wind comes from, as for :func:`saoud`.

    Returns
    -------
    Composite
        ``controller(timestep) -> [rudder, sail]``.
    """
    from .briere import BriereSail

    return _composite(env, _rudder(env), BriereSail(wind_source=wind_source))


def viel(env, d_M: float = 14.0, d_T: float = 7.0, k_s: float = 5.0, k_p: float = 1.0,
         k_v: float = 8.0, epsilon_deg: float = 5.0) -> Bounded:
    """Viel et al. position keeping (rudder 10-11, sail 12-17, speed 18, strategy 19-22).

    Parameters
    ----------
    env : Environment
        The task environment (action bounds, control period).
    d_M, d_T : float
        Radii of the pre-arrival and target areas [m] (§5.1: 14, 7).
    k_s : float
        Sail adaptation gain, eq. 13 [rad s/m] (§5.1: 5).
    k_p, k_v : float
        Velocity-control gains, eq. 18 [1/s^2, 1/s] (§5.1: 1, 8).
    epsilon_deg : float
        epsilon_delta_s, the sail margin of eq. 16 [deg] (§5.1: 5 deg); see
        :class:`controllers.viel.VielController`.

    Returns
    -------
    Bounded
        The controller, its action clipped to the environment's bounds.
    """
    from .viel import VielController

    spec = env.action_spec()
    return Bounded(VielController(d_M=d_M, d_T=d_T, k_s=k_s, k_p=k_p, k_v=k_v,
                                  epsilon_deg=epsilon_deg, dt=env.control_timestep()),
                   spec.minimum, spec.maximum)


def line_following(env, marks=None, leg: float = 200.0, r: float = 10.0, zeta_deg: float = 60.0,
                   gamma_inf_deg: float = 45.0, beta_deg: float = 45.0, rudder: str = "listing") -> Bounded:
    """Jaulin and Le Bars' line following with tacking, mark by mark
    (:class:`controllers.line_following.LineFollower`).

    Parameters
    ----------
    env : Environment
        The task environment (action bounds).
    marks : list of [float, float], optional
        The marks in order (east, north), m; None: a windward mark ``leg`` m upwind of the start,
        then back to the start.
    leg : float
        The windward leg without ``marks``, m.
    r : float
        Cut-off distance, m.
    zeta_deg, gamma_inf_deg, beta_deg : float
        Close-hauled angle, incidence angle, the sail's angle abeam, deg.
    rudder : str
        "listing" (the IRSC listing's sin rudder) or "sawtooth" (Jaulin's book form).

    Returns
    -------
    Bounded
        The controller, its action clipped to the environment's bounds.
    """
    from .line_following import LineFollower, LineFollowingGains

    spec = env.action_spec()
    gains = LineFollowingGains(r=r, zeta=math.radians(zeta_deg), gamma_inf=math.radians(gamma_inf_deg),
                               delta_r_max=float(spec.maximum[0]), beta=math.radians(beta_deg),
                               rudder=rudder)
    return Bounded(LineFollower(marks, leg, gains), spec.minimum, spec.maximum)
