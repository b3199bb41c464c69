"""Roll stabilisation by the sail: Wille, Hassani & Sprenger (2016b), eqs. 60-71.

The sail law has three parts.

1. **Off-line look-up tables** (§2.1-2.2, eqs. 60-63). For the apparent-wind angle at the sail
   CE, beta_ws, on a 1 deg grid, every feasible sail angle lambda (eqs. 61-62, with lambda_sat)
   is traversed with *our* sail force model (:mod:`sailmujoco.forces.sail`, the same functions
   the physics kernel calls) for a unit apparent wind. This gives the relative surge force
   S_x'r = S_x' / V_ws^2 and relative roll moment S_phi_r = S_phi / V_ws^2. Stored per row:
   lambda_100 (maximum surge force) and lambda_67, lambda_33, lambda_0 (maximum surge force
   with a relative moment of at most 67 %, 33 %, 0 % of lambda_100's, the last "or as low as
   possible"), each found on the far side of the previous one (sign continuity).
2. **On-line inversion.** For a measured beta_ws the four solutions are interpolated linearly
   between the two neighbouring grid rows (unless a solution jumps between them, then the
   nearest row is used), and lambda is interpolated linearly in the relative moment between
   the four (moment, lambda) pairs.
3. **Roll LQR** (§4, eqs. 64-71) about phi_w = phi_d = 10 deg, with integral action,
   anti-windup, an on/off hysteresis and the mirrored controller for negative heel.

The tables are in :mod:`controllers.wille_sail_tables`, the LQR in
:mod:`controllers.wille_roll_lqr`, the law that joins them here; the names of all three are
importable from this module (``__all__``).

Readings chosen where the extracted text of the papers is garbled or silent
---------------------------------------------------------------------------
* The hysteresis band is not given: on above ``heel_on`` (10 deg, "only turned on when the
  heel angle is above 10 degrees"), off below ``heel_off`` (ours: 5 deg lower; with a 3 deg
  band the law switched off in every gust lull of a 13 m/s beam reach and the rate feedback
  then met each heel-up without its damping). The integral restarts from zero at each
  switch-on (ours).
* Anti-windup (§4): the integral is frozen while lambda_d = lambda_100 and the error would ask
  for still more moment (conditional integration: the step is taken, and undone if the command
  it gives is lambda_100). We also freeze it while lambda_d = lambda_0 and the error would ask
  for still less (ours, the same reasoning at the other end of the table).
* Eqs. 61-62 leave beta_ws = 0 (dead run) open, and lambda_100 flips from about -90 deg to
  +90 deg across it. Within ``gybe_margin`` (5 deg, ours) of a dead run the law keeps the side
  the sail is on, so that a gust does not make it chatter between the two.
* The tables give the force for a flow *at the CE*; the CE moves with lambda (eq. 26), so the
  flow measured at the present sail angle is used for the angle commanded (as in the paper).
* Eq. 57, F_U ~ -S_y' - R_y' (FRD), is in FLU F_U = F_y,sail + F_y,rudder. With
  ``side_force="wrench"`` (default) these come from ``true_state["sail_wrench"]`` and
  ``["rudder_wrench"]``; with ``"model"`` the sail's is computed from our sail model at the
  actual sail angle and the estimated wind and the rudder's is neglected; ``"none"`` leaves
  the keel moment to the integral action (the option §4 mentions). The keel's roll moment is
  -F_U h2 (§4), so eq. 70 adds F_U h2 (F_U < 0 for a wind from port) to the sail's demand.
  Note that ``"wrench"`` reads the true forces also in ``wind="mean"``.
* ``wind="mean_speed"`` (Table 1's sim 2, "only the average wind speed is known", read
  literally): the apparent wind *direction* at the CE is measured (a vane: the true
  ``apparent_wind_ce`` direction) and its *speed* is that of the ``"mean"`` estimate below.
* ``wind="mean"``: only the mean wind U_m10 and direction are known; the speed at the CE
  follows eq. 40 (log profile) at the CE height R[2] . r_CE (eq. 42's h1 cos(phi), plus the
  boom's sideways offset and the pitch; the hull's heave is neglected), and the velocity of the CE
  (eq. 26) uses u, v, p, r; the boom rate term (lambda_dot l2) and the pitch rate are
  neglected. ``wind="perfect"`` uses the true ``apparent_wind_ce``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sailmujoco import frames
from sailmujoco.boat.catalogue import wille_yacht
from sailmujoco.boat.params import BoatParams
from sailmujoco.forces.wind import log_profile
from sailmujoco.jit.ordered import mat_t_vec

from .base import scalar
from .wille_roll_lqr import PHI_D, Q_WEIGHTS, R_WEIGHT, RollLQR, roll_lqr
from .wille_sail_tables import (
    BETA_STEP,
    FRACTIONS,
    LAMBDA_STEP,
    MAX_JUMP,
    SOLUTIONS,
    SailCommand,
    SailTable,
    WilleSailTables,
    beta_ws_from_flow,
    build_sail_tables,
    feasible_sail_range,
    flow_from_beta_ws,
    pick_solutions,
    relative_sail_force,
    relative_surge_and_moment,
)

__all__ = [
    # the controller (this module)
    "GYBE_MARGIN", "HYSTERESIS", "K_I", "WIND_ESTIMATES", "RollStep", "WilleRollSail",
    # the roll LQR (controllers.wille_roll_lqr)
    "PHI_D", "Q_WEIGHTS", "R_WEIGHT", "RollLQR", "roll_lqr",
    # the sail tables (controllers.wille_sail_tables)
    "BETA_STEP", "FRACTIONS", "LAMBDA_STEP", "MAX_JUMP", "SOLUTIONS", "SailCommand", "SailTable",
    "WilleSailTables", "beta_ws_from_flow", "build_sail_tables", "feasible_sail_range",
    "flow_from_beta_ws", "pick_solutions", "relative_sail_force", "relative_surge_and_moment",
]

_solve_row = pick_solutions  # the table-row solver under the name tests/test_wille_roll.py imports

# ---- numbers of Wille (2016b) §4 and ours ----------------------------------------------------
K_I = 2500.0  # N m/(rad s), §4, integral gain
WIND_ESTIMATES = ("perfect", "mean", "mean_speed")  # WilleRollSail(wind=...), module docstring
HYSTERESIS = math.radians(5.0)  # rad, heel_on - heel_off (ours; the paper gives no band)
GYBE_MARGIN = math.radians(5.0)  # rad, dead-run band where the sail keeps its side (ours)


@dataclass(frozen=True, eq=False)
class RollStep:
    """What :class:`WilleRollSail` did at its last call (for studies and tests). Wille (2016b)'s
    equation numbers.

    Parameters
    ----------
    active : bool
        Whether the roll control acted.
    side : int
        0 when the roll control is off, else the sign of the heel it acts on.
    beta_ws : float
        Apparent-wind angle at the sail CE, rad.
    wind_speed : float
        Apparent wind speed at the sail CE, V_ws, m/s.
    u : float
        Eq. 70's desired sail roll moment, N m (nan when off).
    relative_moment : float
        u / V_ws^2, kg (nan when off).
    f_u : float
        Eq. 57's side force, N (nan when off).
    integral : float
        The heel error's integral, rad s.
    sail_angle : float
        The sail angle commanded, rad.
    lambda_100 : float
        The maximum-surge sail angle at ``beta_ws``, rad.
    saturation : int
        +1 at lambda_100 (also when off), -1 at lambda_0, else 0.
    """

    active: bool
    side: int
    beta_ws: float
    wind_speed: float
    u: float
    relative_moment: float
    f_u: float
    integral: float
    sail_angle: float
    lambda_100: float
    saturation: int


class WilleRollSail:
    """Sail law of Wille (2016b): roll stabilisation through the look-up tables.

    ``controller(observation) -> sail angle`` [rad] (a sail law for
    :class:`~controllers.base.Composite`), ``reset(seed)`` clears the integral and the on/off
    state. Reads ``heel``, ``roll_rate`` and ``true_state`` (``time``; ``apparent_wind_ce`` or
    ``wind_speed_10``/``wind_direction`` with ``u``, ``v``, ``w``, ``heel``, ``pitch``,
    ``yaw``, ``roll_rate``, ``yaw_rate``, ``sail``; ``sail_wrench``, ``rudder_wrench``).

    Eq. 70 for the positive side (phi_d = phi_w = +10 deg)::

        u = -K [phi - phi_d, p] - K_i int(phi - phi_d) dt + C_1 + F_U h_2

    and the mirrored controller for negative heel (phi_d, phi_w, C_1 change sign; K is the same
    because A depends on cos(2 phi_w)). u / V_ws^2 is the desired relative moment, inverted
    with the tables. Off (or with ``roll_control=False``, sim 1 of Table 1) the law returns
    lambda_100.

    Parameters
    ----------
    params : BoatParams, optional
        Boat (default the Wille yacht).
    wind : {"perfect", "mean_speed", "mean"}
        Wind estimate: the true apparent wind at the CE; its measured direction with the speed
        from the mean wind; or the mean true wind only (module docstring).
    roll_control : bool
        False: always lambda_100 ("roll control off").
    side_force : {"wrench", "model", "none"}
        Source of the sail and rudder side forces of eq. 57 (module docstring).
    heel_desired : float
        phi_d = phi_w [rad] (10 deg).
    heel_on, heel_off : float, optional
        Hysteresis [rad]: on when |phi| > heel_on (default phi_d), off when the heel on the
        active side falls below heel_off (default heel_on - 5 deg, at least 0).
    ki : float
        K_i [N m/(rad s)].
    q, r : LQR weights (eq. 71).
    dt : float, optional
        Control period [s]; default: the difference of ``true_state["time"]``.
    gybe_margin : float
        Within this |beta_ws| [rad] of a dead run the sail stays on its side (no chatter).
    tables : WilleSailTables, optional
        Precomputed tables (default :func:`build_sail_tables` of ``params``).
    """

    def __init__(self, params: BoatParams | None = None, *, wind: str = "perfect",
                 roll_control: bool = True, side_force: str = "wrench",
                 heel_desired: float = PHI_D, heel_on: float | None = None,
                 heel_off: float | None = None, ki: float = K_I,
                 q: tuple[float, float] = Q_WEIGHTS, r: float = R_WEIGHT,
                 dt: float | None = None, gybe_margin: float = GYBE_MARGIN,
                 tables: WilleSailTables | None = None):
        if wind not in WIND_ESTIMATES:
            raise ValueError(f"wind must be one of {WIND_ESTIMATES}, got {wind!r}")
        if side_force not in ("wrench", "model", "none"):
            raise ValueError(f"side_force must be 'wrench', 'model' or 'none', got {side_force!r}")
        self.params = wille_yacht() if params is None else params
        self.wind = wind
        self.roll_control = roll_control
        self.side_force = side_force
        self.heel_desired = float(heel_desired)
        self.heel_on = self.heel_desired if heel_on is None else float(heel_on)
        self.heel_off = max(self.heel_on - HYSTERESIS, 0.0) if heel_off is None else float(heel_off)
        if not 0.0 <= self.heel_off <= self.heel_on:
            raise ValueError("need 0 <= heel_off <= heel_on")
        if dt is not None and dt <= 0.0:
            raise ValueError(f"dt must be positive, got {dt}")
        self.ki = float(ki)
        self.gybe_margin = float(gybe_margin)
        self.dt = dt
        self.lqr = roll_lqr(self.params, phi_w=self.heel_desired, q=q, r=r)
        self.tables = build_sail_tables(self.params) if tables is None else tables
        self.keel_depth = -self.params.keel.z  # h2 [m]
        self.reset()

    # ---------------------------------------------------------------- state
    def reset(self, seed: int | None = None) -> None:
        """Roll control off, integral zero (deterministic: ``seed`` is unused).

        Parameters
        ----------
        seed : int, optional
            Unused: the law is deterministic.
        """
        self.side = 0
        self.integral = 0.0  # rad s, int (phi - phi_d) dt
        self._time = None
        self.last_step: RollStep | None = None

    @property
    def active(self) -> bool:
        """Whether the roll controller is on."""
        return self.side != 0

    # ---------------------------------------------------------------- wind
    def wind_estimate(self, observation: dict) -> np.ndarray:
        """Apparent wind at the sail CE, body FLU x-y (2,) [m/s] (air velocity relative to it).

        Parameters
        ----------
        observation : dict
            The observation (:mod:`controllers.base`).
        """
        state = observation["true_state"]
        if self.wind == "perfect":
            return np.asarray(state["apparent_wind_ce"], dtype=float).reshape(-1)[:2].copy()
        s = self.params.sail
        heel, pitch, yaw = (scalar(state, k) for k in ("heel", "pitch", "yaw"))
        rot = frames.matrix_from_euler(heel, pitch, yaw)  # body -> world (ENU)
        lam = scalar(state, "sail")
        r_ce = np.array([s.mast_x - s.ce_aft * math.cos(lam), s.ce_aft * math.sin(lam),
                         s.ce_height])
        # Wille (2016a) eq. 42: -h1 cos(phi) in NED
        height = float(rot[2, 0] * r_ce[0] + rot[2, 1] * r_ce[1] + rot[2, 2] * r_ce[2])
        speed = float(log_profile(height, scalar(state, "wind_speed_10")))  # eq. 40
        wind_body = mat_t_vec(rot, frames.wind_velocity(speed, scalar(state, "wind_direction")))
        velocity = np.array([scalar(state, "u"), scalar(state, "v"), scalar(state, "w")])
        omega = np.array([scalar(state, "roll_rate"), 0.0, scalar(state, "yaw_rate")])
        flow = wind_body - (velocity + np.cross(omega, r_ce))  # Wille (2016a) eq. 26 in FLU
        if self.wind == "mean_speed":  # the direction from the vane, the speed from the mean wind
            measured = np.asarray(state["apparent_wind_ce"], dtype=float).reshape(-1)[:2]
            norm = math.hypot(*measured)
            return measured * (math.hypot(*flow[:2]) / norm) if norm > 0.0 else flow[:2]
        return flow[:2]

    def _side_force(self, observation: dict, beta_ws: float, speed: float) -> float:
        """F_U [N] of Wille (2016a) eq. 57: F_U = -S_y' - R_y' (FRD) = F_y,sail + F_y,rudder (FLU)."""
        state = observation["true_state"]
        if self.side_force == "none":
            return 0.0
        if self.side_force == "wrench":
            sail = np.asarray(state["sail_wrench"], dtype=float).reshape(-1)
            rudder = np.asarray(state["rudder_wrench"], dtype=float).reshape(-1)
            return float(sail[1] + rudder[1])
        force = relative_sail_force(beta_ws, scalar(state, "sail"), self.params)
        return float(force[1]) * speed * speed  # rudder side force neglected

    # ---------------------------------------------------------------- law
    def _wind_side(self, beta_ws: float, sail_angle: float) -> int:
        """Which half of the table: sign(beta_ws), except within ``gybe_margin`` of a dead run.

        There eqs. 61-62 flip lambda_100 from about -90 deg to +90 deg as beta_ws changes sign;
        a gust or a roll oscillation would make the sail chatter between the two. Within the
        margin we keep the side the sail is on (+1 for lambda < 0), ours.
        """
        natural = 1 if beta_ws > 0.0 else (-1 if beta_ws < 0.0 else 0)
        if natural != 0 and abs(beta_ws) >= self.gybe_margin:
            return natural
        if sail_angle != 0.0:
            return 1 if sail_angle < 0.0 else -1
        return natural or 1

    def _update_side(self, heel: float) -> None:
        """On/off hysteresis and choice of the mirrored controller (§4)."""
        if self.side != 0 and self.side * heel < self.heel_off:
            self.side = 0
        if self.side == 0 and abs(heel) > self.heel_on:
            self.side = 1 if heel > 0.0 else -1
            self.integral = 0.0

    def __call__(self, observation: dict) -> float:
        """The sail angle for this observation: lambda_100, or eq. 70's moment inverted in the tables.

        Parameters
        ----------
        observation : dict
            The observation of :mod:`sailmujoco.controllers.base` (SI, our frames).

        Returns
        -------
        float
            Sail angle lambda, rad.
        """
        state = observation["true_state"]
        heel = scalar(observation, "heel")
        rate = scalar(observation, "roll_rate")
        now = scalar(state, "time") if self.dt is None else None
        if self.dt is not None:
            step = self.dt
        else:
            step = 0.0 if self._time is None else max(now - self._time, 0.0)
            self._time = now
        flow = self.wind_estimate(observation)
        speed = float(math.hypot(flow[0], flow[1]))
        beta = beta_ws_from_flow(flow)
        wind_side = self._wind_side(beta, scalar(state, "sail"))
        lam100 = self.tables.optimal_sail_angle(beta, wind_side)

        was_active = self.active
        if self.roll_control:
            self._update_side(heel)
        if not self.active or speed < 1e-3:  # off, or no wind to trim to: lambda_100
            self.last_step = RollStep(self.active, self.side, beta, speed, math.nan, math.nan,
                                      math.nan, self.integral, lam100, lam100, 1)
            return lam100

        side = self.side
        phi_d = side * self.heel_desired  # phi_d = phi_w, sign by the heel (§4)
        error = heel - phi_d
        f_u = self._side_force(observation, beta, speed)
        k = self.lqr.K
        # Wille (2016b) eq. 70 without the integral (C_1 of eq. 67 at phi_w = phi_d, odd)
        u_state = (-k[0] * error - k[1] * rate + self.lqr.c1(phi_d) + f_u * self.keel_depth)

        def command_for(integral):
            u = u_state - self.ki * integral  # Wille (2016b) eq. 70
            relative = u / (speed * speed)  # Wille (2016b) eq. 63
            return u, relative, self.tables.sail_command(beta, relative, wind_side)

        integral = self.integral + (error * step if was_active else 0.0)
        u, relative, command = command_for(integral)
        # anti-windup (§4): the integral may not grow while lambda_d = lambda_100 and the error
        # asks for still more moment (nor, ours, at lambda_0 asking for still less)
        if ((command.saturation > 0 and side * error < 0.0)
                or (command.saturation < 0 and side * error > 0.0)):
            integral = self.integral
            u, relative, command = command_for(integral)
        self.integral = integral
        self.last_step = RollStep(True, side, beta, speed, u, relative, f_u, self.integral,
                                  command.sail_angle, command.lambda_100, command.saturation)
        return command.sail_angle
