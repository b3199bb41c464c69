"""The physics step: forces recomputed at every MuJoCo stage, added mass solved exactly.

:class:`BoatPhysics` is a ``dm_control.mujoco.Physics`` with named SI accessors. Every
evaluation of the equations of motion (each of the four stages of MuJoCo's RK4, the default
integrator) is::

    kinematics, mass matrix M, passive forces          (MuJoCo)
    boat_forces(t, qpos, qvel)    every force model, for this very stage's state
    qfrc_applied <- forces        (not held from an earlier stage or sub-step)
    M <- M + J^T M_A J            added mass of the hull, then M is re-factorised
    actuators, acceleration                            (MuJoCo)

so MuJoCo solves (M_RB + M_A) nu_dot = tau exactly inside the step: no force is built from
an earlier acceleration, and a heave added mass six times the hull's mass is as stable as
none. With RK4 the middle three lines run in MuJoCo's control callback (``mjcb_control``,
installed only while :meth:`BoatPhysics.step` runs), because ``mj_RungeKutta`` evaluates its
stages inside ``mj_step``. With a first-order integrator (Euler, implicit, implicit-fast, set
in ``model.opt.integrator``) a sub-step is ``mj_step1``, the same three lines, ``mj_step2``.
Why RK4: the semi-implicit first-order integrators treat the velocity-dependent forces
(Coriolis/centripetal terms of a CG far below CO, the added-mass Kirchhoff terms) explicitly
and the configuration-dependent mass matrix at the start of the step, so an undamped free
oscillation gains or loses energy in proportion to the step (-16 % / +17 % in 60 s for the
Saoud robot heeled 10 deg at 5 ms); RK4 at the same step changes it by under 1e-4
(tests/test_energy.py).
``step(n)`` runs n such sub-steps at the model's fixed timestep, so a trajectory does not
depend on how many sub-steps a control step has.
"""

from __future__ import annotations

import copy as _copy
import ctypes
import functools
import math
from dataclasses import dataclass

import mujoco
import numpy as np
from dm_control.mujoco import engine
from dm_control.mujoco.wrapper import core
from dm_control.rl import control

from . import frames, native, stability
from .forces import boat as kernels
from .forces.foil import naca0015
from .forces.wind import WANDER_DT, WindConfig, WindField
from .hull import column_quadrature, strip_quadrature
from .mjcf import compile_model
from .params import BoatParams, get_boat


@functools.lru_cache(maxsize=8)
def _floating_table(params: BoatParams) -> stability.FloatingTable:
    """The floating table of a boat, built once per process (about 0.25 s)."""
    return stability.floating_table(params)


def _csr(m, i: int, j: int) -> int:
    """Address of entry (i, j), j <= i, of MuJoCo's sparse lower-triangular mass matrix."""
    row = m.M_rowadr[i]
    cols = m.M_colind[row:row + m.M_rownnz[i]]
    return int(row + np.nonzero(cols == j)[0][0])


# MuJoCo's control callback is one per process. A boat steps in compiled code with a compiled
# callback (sailmujoco/native.py); with compiled_loop False (the Python reference) a boat installs
# this one while it steps with RK4 (native.callback_installed counts the users and puts back what
# it found). It finds the stepping boat by its MjData.
_RK4 = int(mujoco.mjtIntegrator.mjINT_RK4)  # an int: comparing with the enum costs 0.6 us
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


class SimulationStopped(RuntimeError):
    """The simulation left the valid state space; ``reason`` says how."""

    def __init__(self, reason: str, time: float):
        super().__init__(f"simulation stopped at t = {time:.3f} s: {reason}")
        self.reason = reason
        self.time = time


from .options import ForceSwitches  # noqa: E402  (re-exported: physics.ForceSwitches)


def _entry_point(dispatcher):
    """The compiled entry point of a one-signature kernel (skips numba's type dispatch).

    Falls back to the dispatcher (or, with NUMBA_DISABLE_JIT, the plain function).
    """
    if not hasattr(dispatcher, "overloads"):
        return dispatcher
    return _LazyEntry(dispatcher)


class _LazyEntry:
    """Calls through the dispatcher once, then through the compiled entry point."""

    def __init__(self, dispatcher):
        self._dispatcher = dispatcher
        self._entry = None

    def __call__(self, *args):
        if self._entry is None:
            result = self._dispatcher(*args)
            if len(self._dispatcher.signatures) == 1:
                self._entry = self._dispatcher.overloads[self._dispatcher.signatures[0]].entry_point
            return result
        return self._entry(*args)


# the compiled control steps, called past numba's type dispatch (one signature each)
_RK4_STEPS = _entry_point(native.rk4_steps)
_SPLIT_STEPS = _entry_point(native.split_steps)
_FORCES_4DOF = _entry_point(native.forces_4dof)


class BoatPhysics(engine.Physics):
    """A boat in MuJoCo with our force models. Build it with :meth:`load`."""

    # 6 DOF: all sub-steps of step(n) in one compiled call (sailmujoco/native.py). False runs
    # the same MuJoCo step with the stage work called from Python, the path up to issue 18,
    # kept as the reference the compiled loop is tested against (bit for bit).
    compiled_loop = native.AVAILABLE

    # ------------------------------------------------------------------ construction
    @classmethod
    def load(cls, boat: str = "wille_yacht", *, params: BoatParams | None = None,
             sail_mode: str = "actuated", wind: WindConfig | None = None,
             forces: ForceSwitches | None = None, dofs: int = 6,
             **boat_options) -> BoatPhysics:
        """Compile ``boat`` (or ``params``) and attach wind and force models.

        ``boat_options`` go to the boat's parameter factory (e.g. ``l_phi`` for saoud_robot).
        ``dofs=4`` holds heave and pitch (the reduced models' assumption); see
        :func:`sailmujoco.mjcf.boat_spec`.
        """
        if params is None:
            params = get_boat(boat, **boat_options)
        elif boat_options:
            raise ValueError("give either params or boat options, not both")
        model = compile_model(params, sail_mode, dofs)
        physics = cls.from_model(core.MjModel(model))
        physics._setup(params, sail_mode, wind or WindConfig(), forces or ForceSwitches(), dofs)
        physics.reset()
        return physics

    @classmethod
    def _from_mjcf(cls, *args, **kwargs):
        raise ValueError("a BoatPhysics is built from the boat's parameters, which its force models "
                         "need: use BoatPhysics.load(boat, ...) (xml/<boat>/ is generated from them), "
                         "or dm_control.mujoco.Physics for the bare MJCF")

    from_xml_string = from_xml_path = from_byte_string = from_binary_path = _from_mjcf

    def _setup(self, params, sail_mode, wind, forces, dofs=6):
        before = set(vars(self))
        self.params = params
        self.dofs = dofs
        self.sail_mode = sail_mode
        self.switches = forces
        self.wind_config = wind
        self.wind = WindField(wind)
        self._P = kernels.pack_parameters(
            params, hydrostatics=forces.hydrostatics, sail=forces.sail, keel=forces.keel,
            rudder=forces.rudder, damping=forces.damping, added_mass=forces.added_mass,
            sail_tangential=forces.sail_tangential, wind=wind, wander_dt=WANDER_DT,
            added_mass_coupling=forces.added_mass_coupling,
            vertical_damping=forces.vertical_damping, restoring_axes=forces.restoring_axes,
            resistance=forces.resistance, foils=forces.foils, keel_downwash=forces.keel_downwash,
            windage=forces.windage)
        cols = column_quadrature(params.hull)
        self._columns = np.ascontiguousarray(
            np.vstack([cols.x, cols.y, cols.area, cols.z_bottom, cols.z_top]))
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
            addr = [_csr(m, i, j) for i in range(3) for j in range(i + 1)]
            addr += [_csr(m, i, i) for i in (3, 4, 5)]
            self._csr_addr = np.array(addr, dtype=np.int64)
            self._kidx = self._idx
        else:
            # the kernel sees the hull as if free (pseudo qpos/qvel); forces and added mass
            # are mapped onto the x, y, yaw, roll joints here
            self._csr_addr = np.zeros(9, dtype=np.int64)
            self._csr4 = [(i, j, _csr(m, i, j)) for i in range(4) for j in range(i + 1)]
            self._q7 = np.zeros(9)
            self._q7[3] = 1.0
            self._v6 = np.zeros(8)
            self._qfrc8 = np.zeros(8)
            self._kidx = np.array([7, 6, 8, 7], dtype=np.int64)
            self._a_diag = params.added_mass_diagonal if forces.added_mass else np.zeros(6)
            self._floating = None
            if forces.hydrostatics == "geometric":
                # the held pose (heave 0, trim 0) over-displaces the heeled hull; the 4-DOF
                # boat floats at every heel: its hydrostatics come from the freely floating
                # hull at the current heel (stability.FloatingTable), added in _forces_4dof
                self._floating = _floating_table(params)
                self._P[kernels.P_HYDRO_MODE] = kernels.HYDROSTATIC_MODES.index("off")
            elif forces.hydrostatics == "paper":
                # the joints hold CO's height, not the CG's: heeled, a CG off the waterline
                # moves by z_G (cos(phi) - 1) and the heave spring, acting through the CG, would
                # add a roll moment k_z z_G^2 (1 - cos(phi)) sin(phi) (+26 % of eq. 4 at 10 deg
                # on the robot with l_phi = 1 m, 3.3x at 30 deg). The reduced models hold the
                # CG's height: buoyancy = weight through the CG, eq. 20 / eq. 4 alone.
                self._P[kernels.P_K_HEAVE] = 0.0
        self._kernel = _entry_point(kernels.boat_forces)
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
        self._args = (qpos, qvel, self._kidx, self._P, self._columns, self._strips,
                      *self._table, w.oscillation, w.gust_frequency, w.gust_phase, w.gust_amplitude,
                      w.log_z,
                      w.wander, w.gust_cos, self._external, self._terms, self._diag, qfrc,
                      self._madd, d.M, self._csr_addr, self._work)
        if self.dofs == 6:
            self._row = native.registry_row(self._args, d.act, self._warnings)
        else:  # MuJoCo's arrays and the 4-DOF stage's own (native.forces_4dof)
            table = self._floating
            self._bound_4dof = (  # held: the registry row holds only their addresses
                np.ascontiguousarray(self._a_diag, dtype=float),
                np.array(self._csr4, dtype=np.int64).reshape(-1, 3),
                np.array([self.params.mass, self.params.cg_x, self.params.cg_z], dtype=float),
                np.zeros(0) if table is None else np.ascontiguousarray(table.heel, dtype=float),
                np.zeros(0) if table is None else np.ascontiguousarray(table.righting, dtype=float))
            self._row = native.registry_row(self._args, d.act, self._warnings,
                                            (d.qpos, d.qvel, d.qfrc_applied), self._bound_4dof)

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
        self._kernel = _entry_point(kernels.boat_forces)
        self._bound = self._bound_wander = None  # rebound to this MjData on the next step

    def __getstate__(self):
        return self.data, self._boat_state()

    def __setstate__(self, state):
        data, boat = state
        super().__setstate__(data)
        self._attach(boat)

    def copy(self, share_model=False):
        """An independent copy in the same state (``share_model``: share the MjModel)."""
        new = super().copy(share_model=share_model)
        new._attach(_copy.deepcopy(self._boat_state()))
        return new

    def reset(self, keyframe_id=None):
        """Reset to the ``home`` keyframe (upright at the design waterline)."""
        super().reset(0 if keyframe_id is None else keyframe_id)
        if hasattr(self, "_P"):
            self.stop_reason = None
            self._compute_forces()

    # ------------------------------------------------------------------ stepping
    def set_control(self, control):
        """Set the actuator commands; a non-finite command is refused with a clear message."""
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
        """A constant extra body-frame wrench (Fx, Fy, Fz, Mx, My, Mz) about CO (tests, thrust)."""
        wrench_body = np.asarray(wrench_body, dtype=float)
        if wrench_body.shape != (6,) or not np.all(np.isfinite(wrench_body)):
            raise ValueError("external wrench must be 6 finite numbers (N, N m)")
        self._external[:] = wrench_body

    def _compute_forces(self, add_mass: bool = False) -> int:
        """Evaluate every force model for the current state (writes qfrc_applied)."""
        self._prepare(0.0)
        if self.dofs == 4:
            self._status = self._forces_4dof(add_mass)
        else:
            self._status = self._kernel(self.data.ptr.time, *self._args, add_mass)
        return self._status

    def _fill_pseudo(self) -> np.ndarray:
        """4-DOF model: the hull's pose and velocity in free-joint layout; returns R."""
        d = self.data.ptr
        x, y, yaw, roll = d.qpos[0:4]
        xd, yd, yawd, rolld = d.qvel[0:4]
        cy, sy, cr, sr = math.cos(yaw), math.sin(yaw), math.cos(roll), math.sin(roll)
        rot = np.array([[cy, -sy * cr, sy * sr], [sy, cy * cr, -cy * sr], [0.0, sr, cr]])
        q7, v6 = self._q7, self._v6
        q7[0], q7[1], q7[2] = x, y, 0.0
        # quaternion of Rz(yaw) Rx(roll)
        q7[3:7] = (math.cos(yaw / 2) * math.cos(roll / 2), math.cos(yaw / 2) * math.sin(roll / 2),
                   math.sin(yaw / 2) * math.sin(roll / 2), math.sin(yaw / 2) * math.cos(roll / 2))
        q7[7], q7[8] = d.qpos[4], d.qpos[5]
        v6[0], v6[1], v6[2] = xd, yd, 0.0
        v6[3:6] = rot.T @ np.array([0.0, 0.0, yawd]) + np.array([rolld, 0.0, 0.0])
        v6[6], v6[7] = d.qvel[4], d.qvel[5]
        return rot

    def _floating_hydrostatics(self, rot) -> None:
        """4-DOF geometric mode: the hydrostatic wrench of the hull floating freely at this heel.

        Buoyancy equal to the weight, vertical through the CG, plus the righting moment of the
        hull at the heave and trim that float it (quasi-static), about the horizontal heading
        axis, which in 4 DOF is body x. Added to the term and to the pseudo free-joint forces.
        """
        table, p = self._floating, self.params
        heel = float(self.data.ptr.qpos[3])
        righting = float(np.interp(heel, table.heel, table.righting))
        force_b = p.mass * self._P[kernels.P_G] * rot[2, :]  # the weight, world vertical, body axes
        # (cg_x, 0, cg_z) x force_b, the products and differences np.cross forms (bit for bit;
        # np.cross itself costs 10 us, a third of this stage)
        (fx, fy, fz), cx, cz = force_b, p.cg_x, p.cg_z
        wrench = np.array([fx, fy, fz, 0.0 * fz - cz * fy, cz * fx - cx * fz, cx * fy - 0.0 * fx])
        wrench[3] -= righting
        self._terms[kernels.T_HYDRO] = wrench
        self._qfrc8[0:3] += rot @ force_b
        self._qfrc8[3:6] += wrench[3:]

    def _forces_4dof(self, add_mass: bool) -> int:
        """Forces (and added mass) of the heave-and-pitch-held model on its x, y, yaw, roll joints:
        compiled (native.forces_4dof), or with ``compiled_loop`` False the Python reference."""
        if not self.compiled_loop:
            return self._forces_4dof_python(add_mass)
        return _FORCES_4DOF(self.data.ptr.time, self._row, add_mass)

    def _forces_4dof_python(self, add_mass: bool) -> int:
        """The reference of native.forces_4dof: the same operations in Python and numpy."""
        d = self.data.ptr
        rot = self._fill_pseudo()
        status = self._kernel(d.time, *self._args, False)
        if status != kernels.STATUS_OK:
            return status
        if self._floating is not None:
            self._floating_hydrostatics(rot)
        f = self._qfrc8
        torque_world = rot @ f[3:6]
        qfrc = d.qfrc_applied
        qfrc[0], qfrc[1], qfrc[2], qfrc[3] = f[0], f[1], torque_world[2], f[3]
        qfrc[4], qfrc[5] = f[6], f[7]
        a = self._a_diag
        if a[4] != a[5]:
            # the rotational added-mass rate term the pseudo free-joint kernel cannot see: with
            # omega_b = (roll_dot, sin(phi) yaw_dot, cos(phi) yaw_dot), d(omega_b)/dt has the
            # part (0, cos(phi), -sin(phi)) roll_dot yaw_dot beyond J q_ddot; -A2 times it, on
            # the yaw joint: (a66 - a55) sin(phi) cos(phi) roll_dot yaw_dot (Lagrange's equation
            # of T = 1/2 omega^T A2 omega gives the same; nothing on the roll joint).
            heel = d.qpos[3]
            qfrc[2] += (a[5] - a[4]) * math.sin(heel) * math.cos(heel) * d.qvel[3] * d.qvel[2]
        if add_mass:
            # J maps (xd, yd, yawd, rolld) to the body velocity (u, v, w, p, q, r) at CO
            jac = np.zeros((6, 4))
            jac[0:3, 0:2] = rot.T[:, 0:2]
            jac[3:6, 2] = rot.T[:, 2]
            jac[3, 3] = 1.0
            added = jac.T @ (self._a_diag[:, None] * jac)
            for i, j, a in self._csr4:
                d.M[a] += added[i, j]
        return status

    def step(self, nstep: int = 1) -> None:
        """Advance ``nstep`` physics sub-steps, recomputing every force before each stage."""
        m, d = self.model.ptr, self.data.ptr
        if self.stop_reason is not None:
            raise SimulationStopped(self.stop_reason, d.time)
        self._prepare(nstep * m.opt.timestep)
        try:
            if self.compiled_loop:
                self._step_native(nstep, m.opt.integrator == _RK4)
            elif m.opt.integrator == _RK4:
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
        """All ``nstep`` sub-steps in one compiled call (sailmujoco/native.py): MuJoCo's RK4 with
        the forces and added mass at each stage, or mj_step1, forces, mj_factorM, mj_step2."""
        m, d = self.model.ptr, self.data.ptr
        np.copyto(self._warnings_before, self._warnings)
        if rk4:
            with native.Stepping(d._address, self._row) as slots:
                status, _, warned = _RK4_STEPS(m._address, d._address, nstep,
                                               native.REGISTRY[slots[0]], self._saved)
        else:  # no callback: mj_step1 would call it, and forces come after mj_step1 here
            status, _, warned = _SPLIT_STEPS(m._address, d._address, nstep, self._row)
        if status != kernels.STATUS_OK:  # before the warnings, as inside check_invalid_state
            self._stop(status)
        if warned and self._warnings_cause_exception:
            raise control.PhysicsError(self._warnings_message())

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

    # ------------------------------------------------------------------ accessors (SI)
    def _free_state(self):
        """(qpos, qvel) of the hull in free-joint layout: pos, quat, world velocity, body rates."""
        if self.dofs == 6:
            return self.data.ptr.qpos, self.data.ptr.qvel
        self._fill_pseudo()
        return self._q7, self._v6

    def rotation(self) -> np.ndarray:
        """Body->world rotation of the hull (3x3)."""
        out = np.empty(9)
        mujoco.mju_quat2Mat(out, self._free_state()[0][3:7])
        return out.reshape(3, 3)

    def _euler(self):
        return frames.euler_from_matrix(self.rotation())

    def position(self) -> np.ndarray:
        """World position (x east, y north, z up) of CO, m."""
        return self._free_state()[0][0:3].copy()

    def heel(self) -> float:
        """Heel (roll) angle phi, rad, positive starboard down."""
        return float(self._euler()[0])

    def pitch(self) -> float:
        """Pitch angle, rad, positive bow up."""
        return float(self._euler()[1])

    def yaw(self) -> float:
        """ENU yaw, rad, counter-clockwise from east."""
        return float(self._euler()[2])

    def heading(self) -> float:
        """Compass heading, rad, clockwise from north (Wille's psi)."""
        return float(frames.heading_from_yaw(self.yaw()))

    def body_velocity(self) -> np.ndarray:
        """Body-frame linear velocity of CO (u, v, w), m/s."""
        return self.rotation().T @ self._free_state()[1][0:3]

    def angular_velocity(self) -> np.ndarray:
        """Body-frame angular velocity (p, q, r), rad/s."""
        return self._free_state()[1][3:6].copy()

    def surge_speed(self) -> float:
        return float(self.body_velocity()[0])

    def sway_speed(self) -> float:
        return float(self.body_velocity()[1])

    def roll_rate(self) -> float:
        return float(self.angular_velocity()[0])

    def yaw_rate(self) -> float:
        return float(self.angular_velocity()[2])

    def drift_angle(self) -> float:
        """Drift angle beta = atan2(v cos(phi), u), Wille eq. 45 (FLU sign: positive to port)."""
        u, v, _ = self.body_velocity()
        return float(math.atan2(v * math.cos(self.heel()), u))

    def ground_velocity(self) -> np.ndarray:
        """World (east, north) velocity of CO, m/s."""
        return self._free_state()[1][0:2].copy()

    def place(self, position=(0.0, 0.0), yaw: float = 0.0, surge: float = 0.0) -> None:
        """Put the boat upright on its waterline at ``position`` (m), heading ``yaw`` (ENU, rad),
        moving ahead at ``surge`` (m/s); the rudder and sail keep their angles."""
        d = self.data.ptr
        d.qvel[:] = 0.0
        if self.dofs == 6:
            d.qpos[0:3] = (position[0], position[1], 0.0)
            d.qpos[3:7] = (math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2))
            d.qvel[0:2] = (surge * math.cos(yaw), surge * math.sin(yaw))
        else:
            d.qpos[0:4] = (position[0], position[1], yaw, 0.0)
            d.qvel[0:2] = (surge * math.cos(yaw), surge * math.sin(yaw))
        mujoco.mj_forward(self.model.ptr, d)
        self._fresh = False
        self._ensure_fresh()

    def sail_wind(self) -> np.ndarray:
        """World wind velocity at the sail's centre of effort, m/s."""
        self._ensure_fresh()
        return self._diag[kernels.D_WIND_X:kernels.D_WIND_Z + 1].copy()

    def apparent_wind_ce(self) -> np.ndarray:
        """Air velocity relative to the sail CE, body x-y (FLU), m/s."""
        self._ensure_fresh()
        return self._diag[kernels.D_SAIL_FLOW_X:kernels.D_SAIL_FLOW_Y + 1].copy()

    def course(self) -> float:
        """Course over ground: ENU direction of the horizontal velocity of CO, rad."""
        vx, vy = self._free_state()[1][0:2]
        return float(math.atan2(vy, vx))

    def speed_over_ground(self) -> float:
        return float(np.hypot(*self._free_state()[1][0:2]))

    def rudder_angle(self) -> float:
        return float(self.data.ptr.qpos[self._idx[0]])

    def sail_angle(self) -> float:
        return float(self.data.ptr.qpos[self._idx[2]])

    def true_wind(self, height: float | None = None) -> np.ndarray:
        """World wind velocity (m/s) at the current time, at ``height`` (default: masthead)."""
        self._ensure_fresh()
        if height is None:
            height = float(self.data.ptr.site_xpos[self.model.ptr.site("masthead").id][2])
        return self.wind.velocity(self.data.ptr.time, height)

    def apparent_wind_masthead(self) -> np.ndarray:
        """Apparent wind velocity at the masthead in the body frame, m/s (air relative to it)."""
        self._ensure_fresh()
        m, d = self.model.ptr, self.data.ptr
        site = m.site("masthead").id
        vel = np.zeros(6)
        mujoco.mj_objectVelocity(m, d, mujoco.mjtObj.mjOBJ_SITE, site, vel, 0)
        air = self.wind.velocity(d.time, float(d.site_xpos[site][2])) - vel[3:]
        return self.rotation().T @ air

    def apparent_wind_angle(self) -> float:
        """AWA at the masthead, rad, positive when the wind comes from starboard."""
        return frames.apparent_wind_angle(self.apparent_wind_masthead())

    def apparent_wind_speed(self) -> float:
        """Apparent wind speed at the masthead in the body x-y plane, m/s."""
        return float(np.hypot(*self.apparent_wind_masthead()[:2]))

    def angle_of_attack(self, foil: str) -> float:
        """Angle of attack (rad) of 'sail', 'keel' or 'rudder' now."""
        index = {"sail": kernels.D_ALPHA_SAIL, "keel": kernels.D_ALPHA_KEEL,
                 "rudder": kernels.D_ALPHA_RUDDER}
        if foil not in index:
            raise ValueError(f"unknown foil {foil!r}; choose one of {sorted(index)}")
        self._ensure_fresh()
        return float(self._diag[index[foil]])

    def force_term(self, name: str) -> np.ndarray:
        """Body-frame wrench (Fx, Fy, Fz, Mx, My, Mz) about CO of one force model, N and N m."""
        if name not in kernels.TERMS:
            raise ValueError(f"unknown force term {name!r}; choose one of {kernels.TERMS}")
        self._ensure_fresh()
        return self._terms[kernels.TERMS.index(name)].copy()

    def force_terms(self) -> dict[str, np.ndarray]:
        self._ensure_fresh()
        return {name: self._terms[i].copy() for i, name in enumerate(kernels.TERMS)}

    def floating_pose(self) -> tuple[float, float]:
        """(height of CO in m, trim in rad) at which the hydrostatics are evaluated: the hull's
        own in 6 DOF; in 4 DOF with geometric hydrostatics, the heave and trim that float the
        hull at the current heel (the held joints stay at 0)."""
        if self.dofs == 4 and self._floating is not None:
            heel, table = float(self.data.ptr.qpos[3]), self._floating
            return (float(np.interp(heel, table.heel, table.heave)),
                    float(np.interp(heel, table.heel, table.trim)))
        return float(self.position()[2]), self.pitch()

    def submerged_volume(self) -> float:
        """Submerged volume (geometric hydrostatics only), m^3; in 4 DOF, at the floating pose."""
        self._ensure_fresh()
        if self.dofs == 4 and self._floating is not None:
            table = self._floating
            return float(np.interp(self.data.ptr.qpos[3], table.heel, table.volume))
        return float(self._diag[kernels.D_SUBMERGED])

    def sail_coefficients(self) -> tuple[float, float]:
        """(C_N, C_T) of the sail at the last force evaluation."""
        self._ensure_fresh()
        return float(self._diag[kernels.D_CN]), float(self._diag[kernels.D_CT])
