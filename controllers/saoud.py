"""The sail law of Saoud, Hua, Plumet, Ben Amar (2015), "Optimal sail angle computation for an
autonomous sailboat robot" (IEEE CDC 2015): :class:`SaoudSail` trims the sail to the optimal
angle of problem (5)/(14) at every call, :class:`SaoudController` pairs it with a rudder law.

The work is split by what each part holds:

* :mod:`controllers.saoud_model`: the reduced model, its frames and sign conventions, the
  equations (eqs. 3-13) and the solvers' tolerances;
* :mod:`controllers.saoud_optimum`: :func:`optimal_sail` (the paper's route) and
  :func:`brute_force_sail` (exhaustive search, the reference);
* :mod:`controllers.saoud_solver`: :func:`optimal_sail` compiled, bit for bit (the default
  solver of :class:`SaoudSail`);
* this module: the controllers and the apparent wind they read.

The names of the first two that callers use are importable from here as well (``__all__``).
"""

from __future__ import annotations

import math

import numpy as np

from sailmujoco.frames import saoud_theta_v

from .base import Composite, scalar
from .sail_laws import keep_side_at_dead_run
from .saoud_model import (
    TABLE_I,
    SailOptimum,
    SaoudParams,
    check_arguments,
    eq13_residual,
    fold_sail_angle,
    sail_angle_from_saoud,
    saoud_apparent_wind,
    saoud_from_sail_angle,
)
from .saoud_optimum import (
    brute_force_sail,
    eq13_roots,
    equilibrium_heels,
    optimal_sail,
    sail_cost,
    thrust_branch_residual,
    thrust_branch_roots,
)
from .saoud_solver import optimal_sail_compiled

__all__ = [
    # controllers (this module)
    "WIND_SOURCES", "SaoudController", "SaoudSail", "observed_apparent_wind",
    # the model (controllers.saoud_model)
    "SailOptimum", "SaoudParams", "check_arguments", "eq13_residual", "fold_sail_angle",
    "sail_angle_from_saoud", "saoud_apparent_wind", "saoud_from_sail_angle",
    # the optimum (controllers.saoud_optimum)
    "brute_force_sail", "eq13_roots", "equilibrium_heels", "optimal_sail", "sail_cost",
    "thrust_branch_residual", "thrust_branch_roots",
]

WIND_SOURCES = ("saoud_v", "ce", "masthead")


def observed_apparent_wind(observation: dict, source: str = "saoud_v") -> tuple[float, float]:
    """Saoud's (Theta_V [rad], |V| [m/s]) from an observation (see :mod:`controllers.base`).

    ``source="saoud_v"`` (default) builds Saoud's own V (§IV): V = R_z(psi)^T (v - v_w), the
    boat's ground ``velocity`` less the true wind at the sail (``true_state["true_wind"]``, both
    ENU) in the level heading frame of ``true_state["yaw"]`` -- no roll rate, no swing of the
    boom, no wind gradient between a sensor and the sail ("by neglecting the angular velocity
    of the rotating sail"). Measured readings include the boom's own swing, which on a dead run
    flips the apparent wind from side to side and makes a sail law gybe every step.
    ``source="ce"`` reads ``true_state["apparent_wind_ce"]``, the air velocity relative to the
    sail's centre of effort in body x-y (FLU). ``source="masthead"`` rebuilds the same body x-y
    flow from the anemometer's ``apparent_wind_angle`` and ``apparent_wind_speed`` (fx = -AWS
    cos AWA, fy = AWS sin AWA, the inverse of :func:`sailmujoco.frames.apparent_wind_angle`); the
    masthead sees a faster wind than the CE (wind gradient) and the roll rate's motion. The two
    measured readings are un-heeled by :func:`saoud_apparent_wind` with the observed ``heel``.

    Parameters
    ----------
    observation : dict
        The observation (:mod:`controllers.base`).
    source : {"saoud_v", "ce", "masthead"}
        Where the apparent wind comes from (above).

    Returns
    -------
    theta_v : float
        Theta_V [rad].
    speed : float
        |V| [m/s].
    """
    if source == "saoud_v":
        state = observation["true_state"]
        wind = np.asarray(state["true_wind"], dtype=float).reshape(2)
        velocity = np.asarray(observation["velocity"], dtype=float).reshape(2)
        air_e, air_n = float(wind[0]) - float(velocity[0]), float(wind[1]) - float(velocity[1])
        yaw = scalar(state, "yaw")  # air over the boat (ENU) in the level heading frame:
        c, s = math.cos(yaw), math.sin(yaw)
        level_x, level_y = c * air_e + s * air_n, -s * air_e + c * air_n
        return saoud_theta_v((level_x, level_y)), math.hypot(level_x, level_y)  # Saoud §IV
    heel = scalar(observation, "heel")
    if source == "ce":
        flow = np.asarray(observation["true_state"]["apparent_wind_ce"], dtype=float).reshape(2)
    elif source == "masthead":
        awa = scalar(observation, "apparent_wind_angle")
        aws = scalar(observation, "apparent_wind_speed")
        flow = np.array([-aws * math.cos(awa), aws * math.sin(awa)])
    else:
        raise ValueError(f"unknown wind source {source!r}; known: {', '.join(WIND_SOURCES)}")
    return saoud_apparent_wind(flow, heel)


class SaoudSail:
    """Sail law of Saoud (2015): our sail angle from the optimal delta_s* of problem (5)/(14).

    ``law(observation) -> sail angle`` [rad], positive when the boom swings to port
    (:mod:`controllers.base`), recomputed at every call from the observed apparent wind.

    Parameters
    ----------
    l_phi : float
        Metacentric height used in beta [m].
    phi_max : float, optional
        Roll limit [rad] (problem 14); None for problem 5. Saoud's Fig. 7 uses 30 deg.
    params : SaoudParams
        Mass, sail area, g, rho_air, h_s of the reduced model.
    wind_source : {"saoud_v", "ce", "masthead"}
        Where the apparent wind comes from (:func:`observed_apparent_wind`); default Saoud's V.
    min_speed : float
        Below this apparent speed [m/s] (Assumption 3, |V| > 0, fails) the last command is held.
    compiled : bool
        Solve with :func:`controllers.saoud_solver.optimal_sail_compiled` (default), or with
        the readable :func:`optimal_sail` it equals bit for bit (the tests' reference).

    Attributes
    ----------
    last_optimum : SailOptimum or None
        The last solution, in Saoud's frames (for logging phi*, alpha*).
    """

    def __init__(self, *, l_phi: float, phi_max: float | None = None, params: SaoudParams = TABLE_I,
                 wind_source: str = "saoud_v", min_speed: float = 0.1, compiled: bool = True):
        if wind_source not in WIND_SOURCES:
            raise ValueError(f"unknown wind source {wind_source!r}; known: {', '.join(WIND_SOURCES)}")
        if not l_phi > 0.0:
            raise ValueError(f"l_phi (metacentric height) must be positive, got {l_phi!r}")
        self.l_phi, self.phi_max, self.params = l_phi, phi_max, params
        self.wind_source, self.min_speed = wind_source, min_speed
        self.compiled = compiled
        self._solve = optimal_sail_compiled if compiled else optimal_sail
        self.reset()

    def reset(self, seed: int | None = None) -> None:
        """Forget the last command (the law is otherwise memoryless; ``seed`` is unused).

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.last_sail_angle = 0.0
        self.last_optimum: SailOptimum | None = None

    def __call__(self, observation: dict) -> float:
        """The optimal sail angle for this observation; held while the apparent wind is below ``min_speed``.

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Sail angle, rad, positive trailing edge to port.
        """
        theta_v, speed = observed_apparent_wind(observation, self.wind_source)
        if speed < self.min_speed:
            return self.last_sail_angle
        self.last_optimum = self._solve(theta_v, speed, self.l_phi, self.phi_max, self.params)
        self.last_sail_angle = keep_side_at_dead_run(sail_angle_from_saoud(self.last_optimum.delta),
                                                     self.last_sail_angle, theta_v)
        return self.last_sail_angle


class SaoudController(Composite):
    """A rudder law with Saoud's optimal sail: ``controller(timestep) -> [rudder, sail]`` [rad].

    Parameters
    ----------
    rudder_law : callable
        ``rudder_law(observation) -> rudder angle``, e.g. :class:`controllers.pid.PIDHeading`
        (Saoud §VII-B holds a zero heading with "a heading controller").
    phi_max, l_phi, params, **sail_options
        Passed to :class:`SaoudSail`.
    """

    def __init__(self, rudder_law, *, l_phi: float, phi_max: float | None = None,
                 params: SaoudParams = TABLE_I, **sail_options):
        super().__init__(rudder_law, SaoudSail(l_phi=l_phi, phi_max=phi_max, params=params, **sail_options))
