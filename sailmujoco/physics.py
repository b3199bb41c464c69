"""The physics step: forces recomputed at every MuJoCo stage, added mass solved exactly.

:class:`BoatPhysics` is a ``dm_control.mujoco.Physics`` with named SI accessors. Every
evaluation of the equations of motion (each of the four stages of MuJoCo's RK4, the default
integrator) is::

    kinematics, mass matrix M, passive forces          (MuJoCo)
    boat_forces(t, qpos, qvel)    every force model, for this very stage's state
    qfrc_applied <- forces        (not held from an earlier stage or sub-step)
    M <- M + J^T M_A J            added mass of the hull, then M is re-factorised
    actuators, acceleration                            (MuJoCo)

so MuJoCo solves (M_RB + M_A) nu_dot = tau exactly inside the step: no force is built from an earlier
acceleration, and a heave added mass six times the hull's mass is as stable as none. With RK4 the middle
three lines run in MuJoCo's control callback (``mjcb_control``, installed only while
:meth:`BoatPhysics.step` runs), because ``mj_RungeKutta`` evaluates its stages inside ``mj_step``. With
a first-order integrator (Euler, implicit, implicit-fast, set in ``model.opt.integrator``) a sub-step is
``mj_step1``, the same three lines, ``mj_step2``. Why RK4: the semi-implicit first-order integrators
treat the velocity-dependent forces (Coriolis/centripetal terms of a CG far below CO, the added-mass
Kirchhoff terms) explicitly and the configuration-dependent mass matrix at the start of the step, so an
undamped free oscillation gains or loses energy in proportion to the step (-16 % / +17 % in 60 s for the
Saoud robot heeled 10 deg at 5 ms); RK4 at the same step changes it by under 1e-4
(tests/test_energy.py). ``step(n)`` runs n such sub-steps at the model's fixed timestep (the
``timestep`` option), so a trajectory does not depend on how many sub-steps a control step has.
"""

from __future__ import annotations

import copy as _copy
import ctypes

import mujoco
import numpy as np
from dm_control.rl import control

from .boat.catalogue import get_boat
from .boat.hull import column_quadrature, strip_quadrature
from .boat.mjcf import compile_model
from .boat.params import BoatParams
from .errors import SimulationStopped
from .forces import boat as kernels
from .forces.boat_parameters import pack_parameters
from .forces.foil_sections import naca0015
from .forces.kernel_arguments import kernel_call
from .forces.sea_kernels import sea_arrays
from .forces.wind import WANDER_DT, WindConfig, WindField
from .gl_platform import import_dm_control_mujoco
from .jit.kernel import entry_point
from .measurement.accessors import BoatAccessors
from .options import ForceSwitches, WaveConfig, check_sea  # re-exported: physics.ForceSwitches
from .step import native, registry, timing
from .step.four_dof import FourDofStage, csr_address

_dm = import_dm_control_mujoco()  # dm_control with no GL library loaded until a render asks
engine, core = _dm.engine, _dm.wrapper.core

# MuJoCo's control callback is one per process. A boat steps in compiled code with a compiled
# callback (sailmujoco/step/native.py); with compiled_loop False (the Python reference) a boat installs
# this one while it steps with RK4 (native.callback_installed counts the users and puts back what
# it found). It finds the stepping boat by its MjData.
RK4 = int(mujoco.mjtIntegrator.mjINT_RK4)  # MuJoCo's RK4, an int: comparing with the enum costs 0.6 us
_RK4_STEPPING: dict = {}  # MjData address -> the stepping boat's stage function


def _rk4_stage(m, d) -> None:
    """mjcb_control: forces into qfrc_applied and added mass into M for this RK4 stage."""
    stage = _RK4_STEPPING.get(d._address)
    if stage is None:
        previous = native.replaced_callback()
        if callable(previous) and not isinstance(previous, ctypes._CFuncPtr):
            previous(m, d)  # a Python callback (a native one, e.g. ours, is not callable on m, d)
        return
    stage(m, d)


# per-instance attributes bound to one MjData or one process: rebuilt, never copied
_REBUILT = ("_kernel", "_args", "_bound", "_bound_wander", "_row", "_bound_4dof")


# the compiled control steps, called past numba's type dispatch (one signature each)
_RK4_STEPS = entry_point(native.rk4_steps)
_SPLIT_STEPS = entry_point(native.split_steps)


class BoatPhysics(BoatAccessors, FourDofStage, engine.Physics):
    """A boat in MuJoCo with our force models. Build it with :meth:`load`."""

    # all sub-steps of step(n) in one compiled call (sailmujoco/step/native.py). False runs the same
    # MuJoCo step with the stage work called from Python: the reference the compiled loop is
    # tested against (bit for bit).
    compiled_loop = native.AVAILABLE

    # ------------------------------------------------------------------ construction
    @classmethod
    def load(cls, boat: str = "wille_yacht", *, params: BoatParams | None = None,
             sail_mode: str = "actuated", wind: WindConfig | None = None,
             forces: ForceSwitches | None = None, dofs: int = 6,
             waves: WaveConfig | None = None, timestep: float | None = None, **boat_options) -> BoatPhysics:
        """Compile ``boat`` (or ``params``) and attach wind and force models.

        Parameters
        ----------
        boat : str or os.PathLike
            A registered boat (:data:`sailmujoco.boat.catalogue.BOATS`) or a boat file
            (:mod:`sailmujoco.boat.file`), used when ``params`` is None.
        params : BoatParams, optional
            The boat's parameters, instead of a registered name (then no ``boat_options``).
        sail_mode : {"actuated", "sheeted"}
            The sail's second actuator: a position servo on the sail angle (rad) or a sheet (m).
        wind : WindConfig, optional
            The wind field; default ``WindConfig()``.
        forces : ForceSwitches, optional
            Which force models act and in which form; default ``ForceSwitches()``.
        dofs : {6, 4}
            ``dofs=4`` holds heave and pitch (the reduced models' assumption); see
            :func:`sailmujoco.boat.mjcf.boat_spec`.
        waves : WaveConfig, optional
            The sea (docs/physics.md, "The boat in the sea"), 6 DOF only; None: calm water.
        timestep : float, optional
            The physics step, s, > 0 (:mod:`sailmujoco.step.timing`); None: the boat's, 0.005 s.
        **boat_options
            Keyword arguments of the boat's parameter factory (e.g. ``l_phi`` for saoud_robot).

        Returns
        -------
        BoatPhysics
            Reset to the ``home`` keyframe.
        """
        if params is None:
            params = get_boat(boat, **boat_options)
        elif boat_options:
            raise ValueError("give either params or boat options, not both")
        check_sea(waves, dofs)
        model = compile_model(params, sail_mode, dofs, timing.check_timestep(timestep))
        physics = cls.from_model(core.MjModel(model))
        physics._setup(params, sail_mode, wind or WindConfig(), forces or ForceSwitches(), dofs, waves)
        physics.reset()
        return physics

    @classmethod
    def _from_mjcf(cls, *args, **kwargs):
        """Refused: a BoatPhysics is built from the boat's parameters (:meth:`load`).

        dm_control's ``from_xml_string``, ``from_xml_path``, ``from_byte_string`` and
        ``from_binary_path`` all raise a ValueError that says so.

        Parameters
        ----------
        *args
            dm_control's positional arguments (ignored).
        **kwargs
            dm_control's keyword arguments (ignored).
        """
        raise ValueError("a BoatPhysics is built from the boat's parameters, which its force models "
                         "need: use BoatPhysics.load(boat, ...) (xml/<boat>/ is generated from them), "
                         "or dm_control.mujoco.Physics for the bare MJCF")

    from_xml_string = from_xml_path = from_byte_string = from_binary_path = _from_mjcf

    def _setup(self, params, sail_mode, wind, forces, dofs=6, waves=None):
        before = set(vars(self))
        self.waves = waves
        self.params = params
        self.dofs = dofs
        self.sail_mode = sail_mode
        self.switches = forces
        self.wind_config = wind
        self.wind = WindField(wind)
        self._P = pack_parameters(params, forces, wind=wind, wander_dt=WANDER_DT, waves=waves)
        self._sea, self._grid, self._waterline = sea_arrays(params.hull, waves)
        self._columns = column_quadrature(params.hull).array()
        self._strips = np.ascontiguousarray(np.vstack(strip_quadrature(params.hull)))
        table = naca0015()
        self._table = (table.alpha, table.log_re, table.cl, table.cd)
        m = self.model.ptr
        names = ("rudder", "sail")
        self._idx = np.array([v for n in names for v in
                              (m.jnt_qposadr[m.joint(n).id], m.jnt_dofadr[m.joint(n).id])],
                             dtype=np.int64)
        self._terms = np.zeros((len(kernels.TERMS), 6))
        self._diag = np.zeros(kernels.D_SIZE)
        self._madd = np.zeros((3, 3))
        self._work = np.zeros(kernels.WORK_SIZE)
        self._external = np.zeros(6)
        self._saved = np.zeros(m.nq + m.nv + m.na)  # the state before a step, to undo it
        if dofs == 6:
            # CSR addresses in MuJoCo's mass matrix of the hull's translational block (lower
            # triangle of rows/cols 0-2) and of the rotational diagonal (3, 4, 5)
            addr = [csr_address(m, i, j) for i in range(3) for j in range(i + 1)]
            addr += [csr_address(m, i, i) for i in (3, 4, 5)]
            self._csr_addr = np.array(addr, dtype=np.int64)
            self._kidx = self._idx
        else:  # the kernel sees the hull as if free: see sailmujoco/step/four_dof.py
            self._setup_4dof(params, forces, m)
        self._kernel = entry_point(kernels.boat_forces)
        self._stage_status = kernels.STATUS_OK
        self._stage_start = None
        self._bound = None
        self._status = kernels.STATUS_OK
        self._fresh = True
        self.stop_reason: str | None = None
        # what a copy or a pickle carries beside dm_control's MjData (see __getstate__)
        self._boat_keys = tuple(sorted(set(vars(self)) - before - set(_REBUILT)))

    def _bind(self):
        """Hold the arrays the kernel reads and writes (MuJoCo's buffers are stable per MjData)."""
        d = self.data.ptr
        w = self.wind
        self._bound = d
        self._bound_wander = w.wander
        if self.dofs == 6:
            qpos, qvel, qfrc = d.qpos, d.qvel, d.qfrc_applied
        else:
            qpos, qvel, qfrc = self._q7, self._v6, self._qfrc8
        alpha_grid, log_re_grid, cl_table, cd_table = self._table
        self._args = kernel_call(dict(  # the force kernel's arrays by name (forces/kernel_arguments.py)
            qpos=qpos, qvel=qvel, idx=self._kidx, P=self._P, columns=self._columns, strips=self._strips,
            alpha_grid=alpha_grid, log_re_grid=log_re_grid, cl_table=cl_table, cd_table=cd_table,
            oscillation=w.oscillation, gust_f=w.gust_frequency, gust_phase=w.gust_phase,
            gust_amp=w.gust_amplitude, log_z=w.log_z, wander=w.wander, gust_cos=w.gust_cos,
            external=self._external, terms=self._terms, diag=self._diag, qfrc=qfrc, madd=self._madd,
            mass_csr=d.M, csr_addr=self._csr_addr, work=self._work, sea=self._sea, grid=self._grid,
            waterline=self._waterline))
        if self.dofs == 6:
            self._row = registry.registry_row(self._args, d.act, self._warnings)
        else:
            self._row = self._four_dof_row(d)

    def _prepare(self, horizon: float) -> None:
        """Make sure the wind covers the next ``horizon`` seconds and the arguments are bound."""
        d = self.data.ptr
        self.wind.ensure(d.time + horizon + 1.0)
        if self._bound is not d or self._bound_wander is not self.wind.wander:
            self._bind()

    # ------------------------------------------------------------------ copy and pickle
    # dm_control's Physics pickles only its MjData, and its copy() builds a bare Physics around a
    # copy of it: the boat's force models, wind field, external wrench and stop state travel
    # here too, so that a copy (deepcopy, pickle, copy()) steps bit for bit like the original.
    def _boat_state(self) -> dict:
        return {key: getattr(self, key) for key in self._boat_keys}

    def _attach(self, state: dict) -> None:
        self.__dict__.update(state)
        self._kernel = entry_point(kernels.boat_forces)
        self._bound = self._bound_wander = None  # rebound to this MjData on the next step

    def __getstate__(self):
        return self.data, self._boat_state()

    def __setstate__(self, state):
        data, boat = state
        super().__setstate__(data)
        self._attach(boat)

    def copy(self, share_model=False):
        """An independent copy in the same state.

        Parameters
        ----------
        share_model : bool
            Share the MjModel with this physics rather than copy it.
        """
        new = super().copy(share_model=share_model)
        new._attach(_copy.deepcopy(self._boat_state()))
        return new

    def reset(self, keyframe_id=None):
        """Reset to the ``home`` keyframe (upright at the design waterline).

        Parameters
        ----------
        keyframe_id : int, optional
            Keyframe to reset to; None: 0, ``home``.
        """
        super().reset(0 if keyframe_id is None else keyframe_id)
        if hasattr(self, "_P"):
            self.stop_reason = None
            self._compute_forces()

    # ------------------------------------------------------------------ stepping
    def set_control(self, control):
        """Set the actuator commands; a non-finite command is refused with a clear message.

        Parameters
        ----------
        control : array_like, shape (nu,)
            [rudder angle (rad), sail angle (rad) or sheet length (m)], in :attr:`actuator_names` order.
        """
        control = np.asarray(control, dtype=float)
        if control.shape != (self.model.nu,):
            raise ValueError(f"control must have shape ({self.model.nu},) "
                             f"for actuators {self.actuator_names}, got {control.shape}")
        if not np.isfinite(control).all():  # the method: 0.9 us, np.all() 1.8 us, every control step
            raise ValueError(f"non-finite control {control.tolist()} for actuators "
                             f"{self.actuator_names}")
        super().set_control(control)

    @property
    def actuator_names(self) -> list[str]:
        return [self.model.ptr.actuator(i).name for i in range(self.model.nu)]

    def set_external_wrench(self, wrench_body) -> None:
        """A constant extra body-frame wrench (Fx, Fy, Fz, Mx, My, Mz) about CO (tests, thrust).

        Parameters
        ----------
        wrench_body : array_like, shape (6,)
            Force (N) and moment (N m) in the body frame (x forward, y port, z up), about CO.
        """
        wrench_body = np.asarray(wrench_body, dtype=float)
        if wrench_body.shape != (6,) or not np.all(np.isfinite(wrench_body)):
            raise ValueError("external wrench must be 6 finite numbers (N, N m)")
        self._external[:] = wrench_body

    def action_bounds(self) -> tuple[np.ndarray, np.ndarray]:
        """(low, high) of the actuator commands (the model's control ranges), rad or m."""
        low, high = np.asarray(self.model.actuator_ctrlrange).T
        return low.astype(float), high.astype(float)

    def compute_forces(self) -> int:
        """Evaluate every force model for the current state now (writes qfrc_applied).

        Returns
        -------
        int
            The force kernel's status (:data:`sailmujoco.forces.boat.STATUS_OK` when valid).
        """
        return self._compute_forces()

    def _compute_forces(self, add_mass: bool = False) -> int:
        """Evaluate every force model for the current state (writes qfrc_applied)."""
        self._prepare(0.0)
        if self.dofs == 4:
            self._status = self._forces_4dof(add_mass)
        else:
            self._status = self._kernel(self.data.ptr.time, *self._args, add_mass)
        return self._status

    def step(self, nstep: int = 1) -> None:
        """Advance ``nstep`` physics sub-steps, recomputing every force before each stage.

        Parameters
        ----------
        nstep : int
            Number of sub-steps of ``model.opt.timestep`` seconds each.
        """
        m, d = self.model.ptr, self.data.ptr
        if self.stop_reason is not None:
            raise SimulationStopped(self.stop_reason, d.time)
        self._prepare(nstep * m.opt.timestep)
        try:
            if self.compiled_loop:
                self._step_native(nstep, m.opt.integrator == RK4)
            elif m.opt.integrator == RK4:
                self._step_rk4(nstep)
            else:
                self._step_split(nstep)
        except control.PhysicsError as err:  # MuJoCo's own check: a NaN or a huge acceleration
            self._record_stop(kernels.STATUS_NONFINITE, f"non-finite or out-of-range state ({err})")
            raise SimulationStopped(self.stop_reason, d.time) from None
        self._fresh = False

    def _record_stop(self, status: int, reason: str | None = None) -> None:
        """Mark the run stopped with ``status`` (and ``reason``, default the status's own)."""
        self._status = status
        self.stop_reason = reason or ("non-finite state" if status == kernels.STATUS_NONFINITE
                                      else "capsized: |heel| > 90 deg")

    def _stop(self, status: int) -> None:
        self._record_stop(status)
        raise SimulationStopped(self.stop_reason, self.data.ptr.time)

    def _step_native(self, nstep: int, rk4: bool) -> None:
        """All ``nstep`` sub-steps in one compiled call (sailmujoco/step/native.py): MuJoCo's RK4 with
        the forces and added mass at each stage, or mj_step1, forces, mj_factorM, mj_step2."""
        m, d = self.model.ptr, self.data.ptr
        np.copyto(self._warnings_before, self._warnings)
        if rk4:
            with native.Stepping(d._address, self._row) as slots:
                status, _, warned = _RK4_STEPS(m._address, d._address, nstep,
                                               registry.REGISTRY[slots[0]], self._saved)
        else:  # no callback: mj_step1 would call it, and forces come after mj_step1 here
            status, _, warned = _SPLIT_STEPS(m._address, d._address, nstep, self._row)
        if status != kernels.STATUS_OK:  # before the warnings, as inside check_invalid_state
            self._stop(status)
        if warned and self._warnings_cause_exception:
            raise control.PhysicsError(self._warnings_message())

    def begin_batch_step(self, nstep: int) -> np.ndarray:
        """Get ready for ``nstep`` sub-steps taken by :class:`sailmujoco.batch.BoatBatch`.

        Parameters
        ----------
        nstep : int
            Sub-steps the batch will take.

        Returns
        -------
        numpy.ndarray
            The boat's registry row (:func:`sailmujoco.step.registry.registry_row`).
        """
        self._prepare(nstep * self.model.ptr.opt.timestep)
        np.copyto(self._warnings_before, self._warnings)
        return self._row

    def end_batch_step(self, status: int, warned: bool) -> None:
        """Take in the outcome of a batch's step: the stop it met, as :meth:`step` would.

        Parameters
        ----------
        status : int
            The compiled step's status (a ``STATUS_*`` of :mod:`sailmujoco.forces.boat`).
        warned : bool
            Whether MuJoCo counted a new warning during the step.
        """
        self._fresh = False
        if status != kernels.STATUS_OK:
            self._record_stop(status)
        elif warned and self._warnings_cause_exception:  # as step()'s PhysicsError
            self._record_stop(kernels.STATUS_NONFINITE, "non-finite or out-of-range state "
                              f"({self._warnings_message()})")

    def _warnings_message(self) -> str:
        """dm_control's check_invalid_state message for the warnings MuJoCo counted since
        ``_warnings_before`` (checked here without that context manager's cost on every call)."""
        new = np.compress(self._warnings > self._warnings_before,
                          list(mujoco.mjtWarning.__members__))
        return engine._INVALID_PHYSICS_STATE.format(warning_names=", ".join(new))

    def _step_split(self, nstep: int) -> None:
        """First-order integrators from Python (``compiled_loop`` False, the reference):
        mj_step1, forces and added mass, mj_step2."""
        m, d = self.model.ptr, self.data.ptr
        kernel, args = self._kernel, self._args
        four = self.dofs == 4
        step1, step2, factor = mujoco.mj_step1, mujoco.mj_step2, mujoco.mj_factorM
        with self.check_invalid_state():
            for _ in range(nstep):
                step1(m, d)
                # forces for this very state into qfrc_applied; added mass into M
                status = kernel(d.time, *args, True) if four is False else self._forces_4dof(True)
                if status != kernels.STATUS_OK:
                    self._stop(status)
                factor(m, d)
                step2(m, d)

    def _rk4_stage_function(self):
        """The work of one RK4 stage (MuJoCo's control callback calls it): forces, added mass,
        refactorisation. Bound once per ``step`` call; a stage costs one kernel call.

        Only the first stage's status stops the run: the state at the start of the step, which
        the first-order path checks too; the step is then undone.
        """
        kernel, args, factor, ok = self._kernel, self._args, mujoco.mj_factorM, kernels.STATUS_OK
        four = self.dofs == 4
        count = [0]

        def stage(m, d):
            status = kernel(d.time, *args, True) if four is False else self._forces_4dof(True)
            count[0] += 1
            if status != ok and count[0] == 1:
                self._stage_status = status
                self._stage_start = (d.time, d.qpos.copy(), d.qvel.copy(), d.act.copy())
            factor(m, d)

        return stage, count

    def _step_rk4(self, nstep: int) -> None:
        """MuJoCo's RK4 with the stage work in Python (``compiled_loop``
        False): each stage with that stage's forces and added mass."""
        m, d = self.model.ptr, self.data.ptr
        step, ok = mujoco.mj_step, kernels.STATUS_OK
        stage, count = self._rk4_stage_function()
        key = d._address
        _RK4_STEPPING[key] = stage
        try:
            with native.callback_installed(_rk4_stage), self.check_invalid_state():
                for _ in range(nstep):
                    count[0] = 0
                    step(m, d)
                    if self._stage_status != ok:
                        status, self._stage_status = self._stage_status, ok
                        d.time, d.qpos[:], d.qvel[:], d.act[:] = self._stage_start
                        self._stop(status)
        finally:
            _RK4_STEPPING.pop(key, None)

    def _ensure_fresh(self) -> None:
        """After a step, MuJoCo's derived quantities and our forces describe an earlier state
        (the one before the last integration, or RK4's last stage); bring kinematics and forces
        up to the current state."""
        if self._fresh:
            return
        m, d = self.model.ptr, self.data.ptr
        mujoco.mj_kinematics(m, d)
        mujoco.mj_comPos(m, d)
        mujoco.mj_comVel(m, d)
        self._compute_forces()
        self._fresh = True
