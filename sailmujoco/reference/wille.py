"""Wille's 4-DOF sailboat model, the "paper world" of Wille, Hassani & Sprenger (2016a).

Equations 1-43 in the paper's own frames (NED world, FRD body, SNAME), integrated with
classical RK4 in steps of at most ``max_step`` (default ``RK4_MAX_STEP``; the Table 1 metrics agree with
scipy's adaptive RK45, ``integrator="rk45"``, to 1e-4 deg at half its time). Every force
term calls the same force functions as the 6-DOF MuJoCo boat (:mod:`sailmujoco.forces`):
one foil model, one wind model, one damping model.

State ``(x_N, y_E, phi, psi, u, v, p, r, sigma, lambda)``:

    eta_dot = J(phi, psi) nu                                              eq. 4
    (M_RB + M_A) nu_dot = S + K + R - C_RB(nu) nu - C_A(nu_r) nu_r - D(nu_r) - g(eta)   eq. 3
    sigma_dot = (sat(sigma_d) - sigma) / T_sigma, lambda_dot = (sat(lambda_d) - lambda) / T_lambda

Readings chosen where the extraction is garbled or silent:

* Eq. 9 (C_RB) is missing from the extraction. With the CG at CO and w = q = 0 the rigid-body
  Coriolis forces are m (omega x v): C_RB(nu) nu = (-m r v, m r u, 0, 0) (Fossen 2011 §3.3);
  the roll and yaw rows of omega x (I omega) vanish or fall on pitch, which is held.
* Eq. 4 prints psi_dot = r cos(phi), Fossen's 4-DOF form that sets the body pitch rate q to
  zero. ``model="rigid"`` instead integrates a rigid hull whose heave and pitch *angle* are
  held (the MuJoCo 4-DOF boat): q = r tan(phi), psi_dot = r / cos(phi) (as Saoud §III
  writes), and the torque that holds the pitch angle acts about the yawed, level y axis,
  (0, cos phi, -sin phi) in body axes. Eliminating it from the pitch row leaves in the yaw row

      (I_zz + A_66 + I_yy tan^2 phi) r_dot = N + tan(phi) M - tan(phi) I_yy p r / cos^2(phi)
                                           - gyroscopic terms,

  where M is the body pitch moment the paper drops: a heeled sail's drive, acting high up,
  turns the boat to windward (weather helm) by tan(phi) M. The roll row gains the
  omega_3^2 tan(phi) term Saoud §III neglects. ``model="paper"`` (default) is eq. 3-4 as
  printed.
* The sail force uses the AR 5 flat sail (Saoud's C_N, our C_T) in place of Marchaj's
  coefficients, as the 6-DOF boat does.

The interface mirrors :class:`sailmujoco.physics.BoatPhysics` (set_control, step, time,
and the named SI accessors in OUR frames: world ENU, body FLU) so a task can run on either.

The equations are compiled (:mod:`sailmujoco.reference.wille_model`): one call per control
period runs all its RK4 stages.
"""

from __future__ import annotations

import math

import numpy as np

from .. import frames
from ..boat.catalogue import get_boat
from ..boat.hull import strip_quadrature
from ..boat.params import BoatParams
from ..errors import SimulationStopped  # the same stop as in 6 DOF
from ..forces.foil_sections import naca0015
from ..forces.wind import WANDER_DT, WindConfig, WindField
from ..jit.ordered import mat_t_vec, mat_vec, solve
from ..measurement.observation import Truth, observation_and_record, wrench_rows
from ..options import PaperModel, choices
from ..physics import ForceSwitches  # the same switches as in 6 DOF
from . import wille_model
from .integrators import DOMAIN_ERROR, INTEGRATORS, MESSAGES, STATUS_RAN_AWAY, integrate, steps_for
from .wille_model import TERMS

STATE = ("x", "y", "phi", "psi", "u", "v", "p", "r", "sigma", "lam")
_WRENCH_KEYS, _WRENCH_ROWS = wrench_rows(TERMS)
_N_TERMS = len(TERMS)
_WRENCH_INDEX = _WRENCH_ROWS.tolist()  # rows of the terms array (a row of zeros after them)
RK4_MAX_STEP = 0.05  # s, the longest RK4 step: a quarter of the fastest lag (the rudder's T_sigma 0.2 s)


class Wille4DOF:
    """The 4-DOF paper world for a boat's parameters (default: Wille's yacht).

    Parameters
    ----------
    boat : str
        A registered boat (:func:`sailmujoco.boat.catalogue.get_boat`), used when ``params`` is None.
    params : BoatParams, optional
        Boat parameters (``get_boat(boat)`` if not given).
    wind : WindConfig
        Wind and current (our one wind model).
    switches : object with the fields of :class:`sailmujoco.physics.ForceSwitches`
        Which force models act. ``hydrostatics`` is ignored: the restoring is always the paper's
        (eq. 20, or Saoud's eq. 4 for a boat whose ``paper_righting`` is ``"sin"``).
    model : {"paper", "rigid"}
        Eqs. 3-4 as printed, or the rigid hull with heave and pitch angle held (see above).
    timestep : float
        Base time step (s) that ``step(n)`` multiplies; the integrator picks its own steps.
    integrator : {"rk4", "rk45"}
        Classical RK4 in steps of at most ``RK4_MAX_STEP``, or scipy's adaptive RK45 with
        ``rtol``/``atol``.
    rtol, atol : float
        Tolerances of the RK45 integration.
    max_step : float
        The longest RK4 step (and RK45's), s, > 0: the ``timestep`` option of the suite.
    """

    def __init__(self, boat: str = "wille_yacht", *, params: BoatParams | None = None,
                 wind: WindConfig | None = None, switches=None, model: str = "paper",
                 timestep: float = 0.005, integrator: str = "rk4", rtol: float = 1e-6, atol: float = 1e-8,
                 max_step: float = RK4_MAX_STEP):
        if model not in choices(PaperModel):
            raise ValueError(f"model must be one of {choices(PaperModel)}, got {model!r}")
        if integrator not in INTEGRATORS:
            raise ValueError(f"integrator must be one of {INTEGRATORS}, got {integrator!r}")
        self.integrator = integrator
        self.params = params if params is not None else get_boat(boat)
        self.wind_config = wind or WindConfig()
        self.wind = WindField(self.wind_config)
        self.switches = switches or ForceSwitches()
        self.model = model
        self._dt = timestep
        self._rtol, self._atol = rtol, atol
        if not (math.isfinite(max_step) and max_step > 0.0):
            raise ValueError(f"max_step must be a time > 0 in s, got {max_step!r}")
        self.max_step = float(max_step)
        p = self.params
        self._table = naca0015()
        self._strips = strip_quadrature(p.hull)
        self._a = p.added_mass_diagonal
        ixx, _, izz = p.inertia
        self._mass_matrix = np.array([  # eq. 7 + eq. 8 (diagonal, §2.1)
            [p.mass + self._a[0], 0.0, 0.0, 0.0],
            [0.0, p.mass + self._a[1], 0.0, 0.0],
            [0.0, 0.0, ixx + self._a[3], -p.inertia_xz],
            [0.0, 0.0, -p.inertia_xz, izz + self._a[5]],
        ])
        # constant in the paper's model; solved column by column in a written order (LAPACK's inverse
        # takes its kernels, and its last bits, from the CPU)
        self._mass_inverse = np.column_stack([solve(self._mass_matrix, e) for e in np.eye(4)])
        self.external = np.zeros(4)  # extra (X, Y, K, N) in FRD, for tests
        self._terms = np.zeros((len(TERMS), 5))  # work space of the kernels
        self._work = np.zeros((7, 6))
        self._stages = np.zeros((5, len(STATE)))
        self._packed_for = None
        self.reset()

    # ------------------------------------------------------------------ state
    def reset(self, state=None) -> None:
        """Reset to ``state`` (the paper's variables) or to the MuJoCo boat's home pose: at the
        origin, upright, at rest, heading east (ENU yaw 0 = compass heading 90 deg).

        Parameters
        ----------
        state : array_like, shape (10,), optional
            The paper's state :data:`STATE` (NED, FRD, SI).
        """
        if state is None:
            state = np.zeros(len(STATE))
            state[3] = math.pi / 2
        self.state = np.asarray(state, float).copy()
        self._time = 0.0
        self.set_control(np.zeros(2))
        self.stop_reason = None

    def set_state_ours(self, *, position=(0.0, 0.0), yaw=0.0, heel=0.0, u=0.0, v=0.0, p=0.0,
                       r=0.0, rudder=0.0, sail=0.0) -> None:
        """Set the state from our conventions (ENU position and yaw, FLU velocities).

        Parameters
        ----------
        position : tuple of float
            World (east, north), m.
        yaw : float
            ENU yaw, rad, counter-clockwise from east.
        heel : float
            Heel, rad, positive starboard down.
        u, v : float
            Body velocity forward and to port, m/s.
        p, r : float
            Roll rate about body x and yaw rate about body z (up), rad/s.
        rudder, sail : float
            Rudder and sail angles, rad.
        """
        self.state[:] = [position[1], position[0], heel, frames.heading_from_yaw(yaw), u, -v, p,
                         -r, rudder, sail]

    def time(self) -> float:
        return self._time

    def timestep(self) -> float:
        return self._dt

    def action_bounds(self):
        """(low, high) of [rudder, sail] commands, rad (the saturations of §2.1)."""
        p = self.params
        high = np.array([p.rudder.max_angle, p.sail.max_angle])
        return -high, high

    def set_control(self, control) -> None:
        """Set the commands [rudder, sail] (rad) held over the next step; saturated.

        Parameters
        ----------
        control : array_like, shape (2,)
            Rudder and sail angles, rad, positive trailing edge to port; finite.
        """
        control = np.asarray(control, dtype=float)
        if control.shape != (2,) or not np.isfinite(control).all():
            raise ValueError(f"control must be 2 finite numbers [rudder, sail] (rad), got {control}")
        self.control = control.copy()
        p = self.params
        self._commands = (min(max(float(control[0]), -p.rudder.max_angle), p.rudder.max_angle),
                          min(max(float(control[1]), -p.sail.max_angle), p.sail.max_angle))

    def step(self, nstep: int = 1) -> None:
        """Advance ``nstep`` base time steps holding the control (one integrator call).

        Parameters
        ----------
        nstep : int
            Number of base time steps.
        """
        if self.stop_reason is not None:
            raise SimulationStopped(self.stop_reason, self._time)
        t0, t1 = self._time, self._time + nstep * self._dt
        self.wind.ensure(t1 + 1.0)
        if self.integrator == "rk4":  # one compiled call
            new = np.array(self.state, dtype=float)
            status = wille_model.advance(t0, new, t1 - t0, steps_for(t1 - t0, self.max_step), *self._model(),
                                         self._mass_matrix, self._mass_inverse, self._terms, self._work,
                                         self._stages)
            if status == STATUS_RAN_AWAY:  # as integrate(): the state it ran away from
                new = self.state
            message = MESSAGES[status]
        else:
            new, message = integrate(self._rhs, t0, self.state, t1 - t0, self.integrator, self.max_step,
                                     self._rtol, self._atol)
        if message:
            self.stop_reason = f"integration failed: {message}"
            raise SimulationStopped(self.stop_reason, self._time)
        self.state = np.array(new, dtype=float)
        self._time = t1
        if abs(self.state[2]) > math.pi / 2:
            self.stop_reason = "capsized: |heel| > 90 deg"
            raise SimulationStopped(self.stop_reason, self._time)

    # ------------------------------------------------------------------ the model
    def _packed(self) -> np.ndarray:
        """Boat, switches and model as the kernels read them, packed again only when one changes."""
        key = (self.params, self.switches, self.model)
        if self._packed_for is None or any(a is not b for a, b in zip(key, self._packed_for, strict=True)):
            self._P, self._packed_for = wille_model.pack_parameters(*key), key
        return self._P

    def _model(self) -> tuple:
        """The arguments of the kernels after (t, state): parameters, commands, tables, wind (its
        wander series grows: call ``self.wind.ensure`` first)."""
        w = self.wind
        sigma_d, lam_d = self._saturated_commands()
        table = self._table
        return (self._packed(), sigma_d, lam_d, np.ascontiguousarray(self.external, dtype=float), self._a,
                *self._strips, table.alpha, table.log_re, table.cl, table.cd, w.current,
                float(w.config.speed), float(w.config.direction_from), w.oscillation, w.gust_frequency,
                w.gust_phase, w.gust_amplitude, w.log_z, WANDER_DT, w.wander)

    def forces(self, t: float, state) -> dict[str, np.ndarray]:
        """Every (X, Y, K, N, M) term in FRD at (t, state), signs as on the right of eq. 3.

        M, the pitch moment, is not in the paper's model; only ``model="rigid"`` uses it.

        Parameters
        ----------
        t : float
            Time, s.
        state : array_like, shape (10,)
            The paper's state :data:`STATE`: x north, y east (m), phi, psi (rad, NED), u, v (m/s,
            FRD), p, r (rad/s, FRD), sigma, lam (rad).
        """
        return dict(zip(TERMS, self.terms_and_sail_flow(t, state)[0], strict=True))

    def _sail_flow(self, t: float, state) -> tuple[float, float]:
        """V_ws, the air velocity relative to the sail CE in FRD, eq. 26 (wind at eq. 42's height)."""
        return self.terms_and_sail_flow(t, state, terms=False)[1]

    def terms_and_sail_flow(self, t: float, state, terms: bool = True):
        """(the (len(TERMS), 5) array of :meth:`forces` or None, :meth:`_sail_flow`) at (t, state):
        one packing of the kernels' arguments for both (the task's measurement needs both).

        Parameters
        ----------
        t : float
            Time, s.
        state : array_like, shape (10,)
            The paper's state :data:`STATE`: x north, y east (m), phi, psi (rad, NED), u, v (m/s,
            FRD), p, r (rad/s, FRD), sigma, lam (rad).
        terms : bool
            Compute the terms too (False: None in their place).
        """
        self.wind.ensure(t + 1.0)
        model = self._model()
        t, state = float(t), np.ascontiguousarray(state, dtype=float)
        out = None
        if terms:
            out = np.zeros((len(TERMS), 5))
            if not wille_model.force_terms(t, state, *model, np.zeros((7, 6)), out):
                raise ValueError(DOMAIN_ERROR)
        return out, wille_model.sail_flow(t, state, model[0], model[2], np.zeros(3), *model[13:])

    def _saturated_commands(self):
        """The commands after the actuator saturations |sigma| <= sigma_sat, |lambda| <= lambda_sat."""
        return self._commands

    def _rhs(self, t, state):
        """d/dt of the state (eqs. 3-4 and the actuator lags); ValueError where the state ran away."""
        self.wind.ensure(t + 1.0)
        out = np.zeros(len(STATE))
        if not wille_model.rates(float(t), np.ascontiguousarray(state, dtype=float), *self._model(),
                                 self._mass_matrix, self._mass_inverse, np.zeros((len(TERMS), 5)),
                                 np.zeros((7, 6)), out):
            raise ValueError(DOMAIN_ERROR)
        return out

    # ------------------------------------------------------------------ accessors (our frames)
    def position(self) -> np.ndarray:
        """World position of CO (x east, y north, z up), m."""
        return np.array([self.state[1], self.state[0], 0.0])

    def heel(self) -> float:
        return float(self.state[2])

    def pitch(self) -> float:
        return 0.0

    def heading(self) -> float:
        return float(frames.wrap_angle(self.state[3]))

    def yaw(self) -> float:
        return float(frames.yaw_from_heading(self.state[3]))

    def rotation(self) -> np.ndarray:
        return frames.matrix_from_euler(self.heel(), 0.0, self.yaw())

    def body_velocity(self) -> np.ndarray:
        """(u, v, w) in FLU, m/s."""
        return np.array([self.state[4], -self.state[5], 0.0])

    def angular_velocity(self) -> np.ndarray:
        """(p, q, r) in FLU, rad/s (q from the yaw kinematics)."""
        phi, pr, r = self.state[2], self.state[6], -self.state[7]
        q = r * math.tan(phi) if self.model == "rigid" else 0.0
        return np.array([pr, q, r])

    def surge_speed(self) -> float:
        return float(self.state[4])

    def sway_speed(self) -> float:
        return float(-self.state[5])

    def roll_rate(self) -> float:
        return float(self.state[6])

    def yaw_rate(self) -> float:
        return float(-self.state[7])

    def ground_velocity(self) -> np.ndarray:
        """World (east, north) velocity of CO, m/s (eq. 4)."""
        _, _, phi, psi, u, v = self.state[:6]
        cphi, cpsi, spsi = math.cos(phi), math.cos(psi), math.sin(psi)
        return np.array([spsi * u + cpsi * cphi * v, cpsi * u - spsi * cphi * v])

    def course(self) -> float:
        ve, vn = self.ground_velocity()
        return float(math.atan2(vn, ve))

    def speed_over_ground(self) -> float:
        return math.hypot(*self.ground_velocity())

    def drift_angle(self) -> float:
        """beta = atan2(v cos(phi), u), Wille eq. 45, in our sign (positive to port)."""
        return float(math.atan2(self.sway_speed() * math.cos(self.heel()), self.surge_speed()))

    def rudder_angle(self) -> float:
        return float(self.state[8])

    def sail_angle(self) -> float:
        return float(self.state[9])

    def force_terms(self) -> dict[str, np.ndarray]:
        """Body wrenches (Fx, Fy, Fz, Mx, My, Mz) in FLU about CO, as the 6-DOF boat reports."""
        out = {}
        for name, (x, y, k, n, m) in self.forces(self._time, self.state).items():
            out[name] = np.array([x, -y, 0.0, k, -m, -n])
        return out

    def true_wind(self, height: float | None = None) -> np.ndarray:
        """World (ENU) true wind velocity now, m/s.

        Parameters
        ----------
        height : float, optional
            Height above the water, m; default the masthead's, h cos(phi).
        """
        if height is None:
            height = self.params.sail.masthead_height * math.cos(self.heel())
        return self.wind.velocity(self._time, height)

    def place(self, position=(0.0, 0.0), yaw: float = 0.0, surge: float = 0.0) -> None:
        """Upright at ``position`` (m, ENU), heading ``yaw`` (ENU, rad), surging at ``surge``.

        Parameters
        ----------
        position : tuple of float
            World (east, north), m.
        yaw : float
            ENU yaw, rad.
        surge : float
            Speed ahead, m/s.
        """
        self.set_state_ours(position=position, yaw=yaw, u=surge, rudder=self.state[8],
                            sail=self.state[9])

    def sail_wind(self) -> np.ndarray:
        """World wind velocity at the sail CE (height h1 cos(phi), eq. 42), m/s."""
        return self.wind.velocity(self._time, self.params.sail.ce_height * math.cos(self.heel()))

    def apparent_wind_ce(self) -> np.ndarray:
        """Air velocity relative to the sail CE (eq. 26), body x-y in FLU, m/s."""
        vws_u, vws_v = self._sail_flow(self._time, self.state)
        return np.array([vws_u, -vws_v])

    def apparent_wind_masthead(self) -> np.ndarray:
        """Air velocity relative to the masthead in body FLU (x, y, z), m/s (4-DOF kinematics)."""
        return self.masthead_flow(self.rotation(), self.body_velocity(), self.angular_velocity())

    def masthead_flow(self, rot, body, rates) -> np.ndarray:
        """:meth:`apparent_wind_masthead` from this state's :meth:`rotation`, :meth:`body_velocity`
        and :meth:`angular_velocity` (the task's measurement has them already).

        Parameters
        ----------
        rot : numpy.ndarray, shape (3, 3)
            Body (FLU) to world (ENU) rotation.
        body : numpy.ndarray, shape (3,)
            Body velocity of CO, FLU, m/s.
        rates : numpy.ndarray, shape (3,)
            Angular velocity, body frame, rad/s.
        """
        p = self.params
        top = np.array([p.sail.mast_x, 0.0, p.sail.masthead_height])
        (wx, wy, wz), (tx, _, tz) = rates, top
        vel = mat_vec(rot, body + np.array([wy * tz, wz * tx - wx * tz, -wy * tx]))  # v + w x r
        air = self.true_wind(float(mat_vec(rot, top)[2])) - vel
        return mat_t_vec(rot, air)

    def apparent_wind_angle(self) -> float:
        return frames.apparent_wind_angle(self.apparent_wind_masthead())

    def apparent_wind_speed(self) -> float:
        return math.hypot(*self.apparent_wind_masthead()[:2])

    # ------------------------------------------------------------------ the task's measurement
    def truth(self) -> Truth:
        """The world's true state now (:class:`~sailmujoco.measurement.observation.Truth`): the
        accessors' values bit for bit (:func:`~sailmujoco.measurement.observation.accessor_truth`),
        from one rotation, one masthead flow and one packing of the kernels' arguments."""
        state, t, wind = self.state, self._time, self.wind
        heel = float(state[2])  # heel(); pitch() is 0
        yaw = float(frames.wrap_angle(math.pi / 2.0 - state[3]))  # yaw(): frames.yaw_from_heading
        heading = float(frames.wrap_angle(state[3]))  # heading()
        rot = frames.matrix_from_euler(heel, 0.0, yaw)  # rotation()
        body = self.body_velocity()
        rates = self.angular_velocity()
        current = wind.current
        current_body = mat_t_vec(rot, current)
        flow = self.masthead_flow(rot, body, rates)  # apparent_wind_masthead()
        awa = math.atan2(float(flow[1]), -float(flow[0]))  # frames.apparent_wind_angle
        aws = math.hypot(*flow[:2])
        true_wind = wind.velocity(t, self.params.sail.ce_height * math.cos(heel))  # sail_wind()
        frd, (vws_u, vws_v) = self.terms_and_sail_flow(t, state)  # forces(), _sail_flow()
        # force_terms(): FRD (X, Y, K, N, M) -> FLU (Fx, Fy, Fz, Mx, My, Mz), a row of zeros after
        terms = np.zeros((_N_TERMS + 1, 6))
        terms[:_N_TERMS, 0] = frd[:, 0]
        terms[:_N_TERMS, 1] = -frd[:, 1]
        terms[:_N_TERMS, 3] = frd[:, 2]
        terms[:_N_TERMS, 4] = -frd[:, 4]
        terms[:_N_TERMS, 5] = -frd[:, 3]
        return Truth._make((  # in the order of its fields
            t, np.array([state[1], state[0]]), self.ground_velocity(), body, current_body, rates, yaw, heel,
            0.0, heading, state[8], state[9], awa, aws, np.asarray(true_wind[:2], dtype=np.float64),
            np.array([vws_u, -vws_v]), wind.config.speed, wind.direction_from(t),
            np.array(wind.current[:2], dtype=np.float64),
            dict(zip(_WRENCH_KEYS, map(terms.__getitem__, _WRENCH_INDEX), strict=True))))

    def measure(self) -> tuple[dict, dict]:
        """(observation, record) of the world now
        (:func:`~sailmujoco.measurement.observation.observation_and_record`)."""
        return observation_and_record(self)

    def diagnostic_record(self) -> dict:
        """The assumption study's per-step diagnostics: none for a paper world.

        Returns
        -------
        dict
            Empty (the MuJoCo boat's :meth:`~sailmujoco.measurement.accessors.BoatAccessors.diagnostic_record`
            measures what this model holds fixed).
        """
        return {}

