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

import numpy as np

from ..forces.wind import WANDER_DT, WindConfig, WindField
from ..frames import heading_from_yaw, wrap_angle
from ..measurement.observation import Truth, observe
from .integrators import DOMAIN_ERROR, INTEGRATORS, MESSAGES, STATUS_RAN_AWAY, integrate, steps_for
from .viel_model import (
    FORCE_NAMES,
    RK4_MAX_STEP,
    STATE_NAMES,
    VielParams,
    advance,
    apparent_wind,
    awa_from_psi_aw,
    forces_kernel,
    pack_parameters,
    rates_kernel,
    viel_from_action,
)

_G_S, _G_RV, _G_RU, _HULL_WIND = (FORCE_NAMES.index(name) for name in ("g_s", "g_rv", "g_ru", "hull_wind"))


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
        ``"rk4"`` (classical Runge-Kutta, steps of at most ``max_step``) or ``"rk45"``
        (:func:`scipy.integrate.solve_ivp`, adaptive).
    rtol, atol : float
        Tolerances of the RK45 integration.
    max_step : float
        The longest RK4 step (and RK45's), s, > 0: the ``timestep`` option of the suite.

    The action of :meth:`step` is ours, ``[rudder, sail]`` [rad], positive when the trailing
    edge swings to port, saturated at ``params.rudder_max`` and ``params.sail_max`` and held
    over the step; the wind and forces are re-evaluated at every integrator stage.
    """

    def __init__(self, params: VielParams | None = None, wind: WindConfig | WindField | None = None,
                 wind_height: float = 10.0, integrator: str = "rk4", rtol: float = 1e-7,
                 atol: float = 1e-9, max_step: float = RK4_MAX_STEP):
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
        if not (math.isfinite(max_step) and max_step > 0.0):
            raise ValueError(f"max_step must be a time > 0 in s, got {max_step!r}")
        self.max_step = float(max_step)
        self._state = np.zeros(6)
        self._time = 0.0
        self._action = np.zeros(2)
        self.reset()

    # -- state ------------------------------------------------------------------------------
    def reset(self, state=None, time: float = 0.0) -> np.ndarray:
        """Set the state ``(x, y, theta, v, u, omega)`` (default: at rest at the origin facing
        east) and the time [s]; the action is set to zero. Returns a copy of the state.

        Parameters
        ----------
        state : array_like, shape (6,), optional
            (x, y [m], theta [rad], v, u [m/s], omega [rad/s]).
        time : float
            Time, s.
        """
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
        """(a_tw [m/s], psi_tw [rad], Viel's blows-towards angle) at time t (default: now).

        Parameters
        ----------
        t : float, optional
            Time, s; default now.
        """
        w = self.wind.velocity(self._time if t is None else t, self.wind_height)
        return math.hypot(w[0], w[1]), math.atan2(w[1], w[0])

    def rates(self, state=None, action=None, t: float | None = None) -> np.ndarray:
        """Time derivative of the state (eqs. 1-6) for our action [rad] (default: current).

        Parameters
        ----------
        state : array_like, shape (6,), optional
            Viel's state (x, y [m], theta [rad], v, u [m/s], omega [rad/s]); default the current one.
        action : array_like, shape (2,), optional
            Ours, [rudder, sail] rad, positive trailing edge to port; default the current one.
        t : float, optional
            Time, s; default now.
        """
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
        :meth:`true_wind` at ``t`` if the caller has it.

        Parameters
        ----------
        state : array_like, shape (6,), optional
            Viel's state (x, y [m], theta [rad], v, u [m/s], omega [rad/s]); default the current one.
        action : array_like, shape (2,), optional
            Ours, [rudder, sail] rad, positive trailing edge to port; default the current one.
        t : float, optional
            Time, s; default now.
        true_wind : tuple of float, optional
            (a_tw [m/s], psi_tw [rad]) as :meth:`true_wind` gives it, if the caller has it.
        """
        state = self._state if state is None else np.asarray(state, dtype=float)
        action = self._action if action is None else self._checked_action(action)
        delta_r, delta_s = viel_from_action(action)
        a_tw, psi_tw = self.true_wind(t) if true_wind is None else true_wind
        return dict(zip(FORCE_NAMES, self._forces(state, delta_r, delta_s, a_tw, psi_tw), strict=True))

    def step(self, action, dt: float) -> np.ndarray:
        """Hold ``action`` (ours, [rad]) for ``dt`` [s]; integrate eqs. 1-9. Returns the state.

        Parameters
        ----------
        action : array_like, shape (2,)
            Ours, [rudder, sail] rad, positive trailing edge to port; saturated.
        dt : float
            Time held, s, > 0.
        """
        applied = self._checked_action(action)
        if not (math.isfinite(dt) and dt > 0.0):
            raise ValueError(f"dt must be a positive finite time in s, got {dt}")
        delta_r, delta_s = viel_from_action(applied)
        wind, z, P = self.wind, self.wind_height, self._packed()
        if self.integrator == "rk4" and type(wind).velocity is WindField.velocity:  # one compiled call
            wind.ensure(self._time + dt + 1.0)
            new = self._state.copy()
            status = advance(self._time, new, float(dt), steps_for(dt, self.max_step), P, delta_r, delta_s, z,
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

            new, message = integrate(rhs, self._time, self._state, dt, self.integrator, self.max_step,
                                     self.rtol, self.atol)
        if message:
            raise FloatingPointError(
                f"VielWorld: integration failed at t={self._time:.3f} s ({message}); "
                f"state {dict(zip(STATE_NAMES, new, strict=True))}, action {applied}")
        new = new.copy()
        new[2] = (float(new[2]) + math.pi) % (2.0 * math.pi) - math.pi  # frames.wrap_angle's value, in floats
        self._state, self._time, self._action = new, self._time + dt, applied
        return new.copy()

    def loop_ready(self) -> bool:
        """Whether a compiled closed loop can step this world: RK4 (:func:`advance`) in the wind
        of :class:`~sailmujoco.forces.wind.WindField` itself (not a subclass's)."""
        return self.integrator == "rk4" and type(self.wind) is WindField

    def loop_arguments(self, dt: float, seconds: float) -> tuple:
        """What a compiled closed loop (:mod:`sailmujoco.loop.worlds`) steps this world with.

        Parameters
        ----------
        dt : float
            The control step, s (each one integrated as :meth:`step` integrates it).
        seconds : float
            The time the loop may cover, s: the wind's wander is drawn for it up front (the same
            values as drawn on the way).

        Returns
        -------
        tuple
            (time s, state (6,), applied action (2,), numbers: the packed parameters, then
            ``dt``, its RK4 steps, delta_r,max, delta_s,max and the wind's height).
        """
        self.wind.ensure(self._time + seconds + 1.0)
        p = self.params
        steps = float(steps_for(dt, self.max_step))
        numbers = np.concatenate([self._packed(),
                                  [float(dt), steps, p.rudder_max, p.sail_max, self.wind_height]])
        return float(self._time), self._state.copy(), self._action.copy(), numbers

    def loop_ended(self, state, time: float, action) -> None:
        """Take the state, time and applied action a compiled closed loop reached.

        Parameters
        ----------
        state : numpy.ndarray, shape (6,)
            Viel's state (x, y, theta wrapped, v, u, omega).
        time : float
            Time, s.
        action : numpy.ndarray, shape (2,)
            The applied (saturated) action, ours, rad.
        """
        self._state, self._time = np.array(state, dtype=np.float64), float(time)
        self._action = np.array(action, dtype=np.float64)

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
        :meth:`true_wind` now, if the caller has it).

        Parameters
        ----------
        true_wind : tuple of float, optional
            (a_tw [m/s], psi_tw [rad]) as :meth:`true_wind` gives it, if the caller has it.
        """
        a_tw, psi_tw = self.true_wind() if true_wind is None else true_wind
        return apparent_wind(a_tw, psi_tw, self._state[2], self._state[3])

    def wind_direction(self) -> float:
        """Compass bearing the true wind comes from now [rad] (mean, schedule, oscillation, wander)."""
        return float(wrap_angle(self.wind.direction_from(self._time)))

    def truth(self) -> Truth:
        """The world's true state now, for :mod:`sailmujoco.measurement.observation`.

        Planar world: heel, pitch, roll and pitch rates, ``w`` are zero; no current (the
        water is at rest: ``u_r = u``); the apparent wind is Viel's §2.3 one, at the sail
        and at the masthead alike (no masthead height in the model); ``wind_speed_10`` is the
        WindConfig's mean speed at 10 m.

        Returns
        -------
        Truth
            The world's true state.
        """
        state, t, wind = self._state, self._time, self.wind
        x, y, theta, v, u, omega = state.tolist()
        a_tw, psi_tw = self.true_wind()  # once: apparent wind and wrenches take it
        a_aw, psi_aw = apparent_wind(a_tw, psi_tw, theta, v)  # apparent_wind()
        rudder, sail = self._action.tolist()
        f = self._forces(state, -rudder, -sail, a_tw, psi_tw)  # viel_from_action's deltas
        c, s = math.cos(theta), math.sin(theta)  # velocity(), eqs. 1-2
        return Truth._make((  # in the order of its fields
            t, np.array([x, y]), np.array([v * c - u * s, v * s + u * c]), np.array([v, u, 0.0]), np.zeros(3),
            np.array([0.0, 0.0, omega]), theta, 0.0, 0.0, float(heading_from_yaw(state[2])), rudder, sail,
            awa_from_psi_aw(psi_aw), a_aw, np.array([a_tw * math.cos(psi_tw), a_tw * math.sin(psi_tw)]),
            np.array([a_aw * math.cos(psi_aw), a_aw * math.sin(psi_aw)]),  # blows to
            wind.config.speed, wind.direction_from(t), np.zeros(2),
            self._wrench_arrays(f, theta, v, u, omega, -rudder, -sail, psi_tw)))

    def _forces(self, state, delta_r: float, delta_s: float, a_tw: float, psi_tw: float) -> list:
        """The values of :meth:`forces` (in the order of ``FORCE_NAMES``) at ``state`` now."""
        out = np.empty(len(FORCE_NAMES))
        if not forces_kernel(self._packed(), np.ascontiguousarray(state, dtype=float), delta_r, delta_s, a_tw,
                             psi_tw, out):
            raise ValueError(DOMAIN_ERROR)
        return out.tolist()

    def wrenches(self, true_wind=None) -> dict:
        """Body (FLU) wrenches (Fx, Fy, Fz, Mx, My, Mz) [N, N m] of the eq. 4-6 terms, now.

        ``sail_wrench``: the sail terms (eq. 4 thrust, eq. 6 moment; eq. 5 has no sail term,
        Viel: "compensated by the keel"); ``rudder_wrench``: the g_rv, g_ru terms;
        ``damping_wrench``: p2 and p3 frictions; ``hull_wind_wrench``: p1 a_tw^2. ``true_wind``:
        :meth:`true_wind` now, if the caller has it.

        Parameters
        ----------
        true_wind : tuple of float, optional
            (a_tw [m/s], psi_tw [rad]) as :meth:`true_wind` gives it, if the caller has it.
        """
        a_tw, psi_tw = self.true_wind() if true_wind is None else true_wind
        delta_r, delta_s = viel_from_action(self._action)
        _, _, theta, v, u, omega = self._state
        f = self._forces(self._state, delta_r, delta_s, a_tw, psi_tw)
        return self._wrench_arrays(f, theta, v, u, omega, delta_r, delta_s, psi_tw)

    def _wrench_arrays(self, f: list, theta, v, u, omega, delta_r: float, delta_s: float,
                       psi_tw: float) -> dict:
        """:meth:`wrenches` from the forces ``f`` (:meth:`_forces`) of the state (theta, v, u, omega)."""
        p = self.params
        g_s, g_rv, g_ru, hull_wind = f[_G_S], f[_G_RV], f[_G_RU], f[_HULL_WIND]
        zero = np.zeros(6)
        sail = np.array([g_s * math.sin(delta_s), 0, 0, 0, 0, g_s * (p.p6 - p.p7 * math.cos(delta_s))])
        rudder = np.array([-g_rv * p.p11 * math.sin(delta_r), -g_ru * p.p11 * math.cos(delta_r),
                           0, 0, 0, -g_rv * p.p8 * math.cos(delta_r)])
        damping = np.array([-p.p2 * v * abs(v), -p.p2 * u * abs(u), 0, 0, 0, -p.p3 * omega * v])
        hull = hull_wind * np.array([math.cos(psi_tw - theta), math.sin(psi_tw - theta), 0, 0, 0, 0])
        return dict(sail_wrench=sail, keel_wrench=zero.copy(), rudder_wrench=rudder, damping_wrench=damping,
                    added_mass_wrench=zero.copy(), restoring_wrench=zero.copy(), hull_wind_wrench=hull)


def observation_from_world(world: VielWorld, target=None) -> dict:
    """The observation of :mod:`sailmujoco.controllers.base` from a :class:`VielWorld`:
    :func:`~sailmujoco.measurement.observation.observe` of its :meth:`~VielWorld.truth`.

    ``target`` (x east, y north) [m], if given, becomes ``target_position``.

    Parameters
    ----------
    world : VielWorld
        The world.
    target : array_like, shape (2,), optional
        Target position (x east, y north), m.
    """
    obs = observe(world.truth())
    if target is not None:
        obs["target_position"] = np.asarray(target, dtype=float).reshape(2).copy()
    return obs
