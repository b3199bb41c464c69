"""MuJoCo's C API called from compiled code: a whole control step in one call.

Each RK4 stage of :meth:`sailmujoco.physics.BoatPhysics.step` calls the force kernel and
``mj_factorM``; from a Python callback that costs about 8 us per stage, 4 stages per sub-step,
20 sub-steps per control step. Here the same work runs without Python:

* :func:`rk4_steps` calls ``mj_step`` n times from numba through the C library's own symbols;
  MuJoCo's control callback (``mjcb_control``, called at each of RK4's four stages) is a numba
  ``cfunc`` (:func:`stage_callback`), that finds the stepping boat's arrays in the registry
  (below), calls the force kernel with this stage's time and state, and refactorises the
  augmented mass matrix. It is MuJoCo's own RK4 and the same kernel on the same arrays as the
  Python callback, so the trajectory is the same to the last bit (tests/test_native_step.py).
* :func:`split_steps` does the same for the first-order integrators: ``mj_step1``, the kernel,
  ``mj_factorM``, ``mj_step2``.
* The 4-DOF boat (heave and pitch held) steps the same way: its row says so (``R_DOFS``), and
  its stage (:func:`_forces_4dof`) fills the kernel's pseudo free joint from MuJoCo's four hull
  joints, calls the kernel, adds the floating hydrostatics and maps the forces and the added
  mass back onto the joints, as the Python reference in :mod:`sailmujoco.step.four_dof` does.

The callback finds a boat's arrays by its MjData in the registry
(:mod:`sailmujoco.step.registry`); MuJoCo's C functions are reached through
:mod:`sailmujoco.step.mujoco_calls`.

The compiled functions name the C functions and the registry by symbols, which LLVM resolves
when it loads them, so numba caches them on disk like the force kernels.
"""

from __future__ import annotations

import math

import mujoco
import numba
import numpy as np
from numba import types

from ..forces import boat as kernels
from ..forces.boat_parameters import P_G
from ..jit.ordered import mat_mat, mat_t_vec, mat_vec
from .mujoco_calls import address, mj_factorM, mj_step, mj_step1, mj_step2, pointer, time_byte_offset
from .registry import (
    A_A_DIAG,
    A_ACT,
    A_CSR4,
    A_DATA_QFRC,
    A_DATA_QPOS,
    A_DATA_QVEL,
    A_FLOAT_HEEL,
    A_FLOAT_RIGHTING,
    A_MASS_CSR,
    A_P,
    A_QFRC8,
    A_QPOS,
    A_QVEL,
    A_TERMS,
    A_WARNINGS,
    A_WEIGHT_ARM,
    CHANGED,
    EMPTY,
    R_COUNT,
    R_DATA,
    R_DOFS,
    R_FIRST,
    R_STATUS,
    ROW,
    SLOTS,
    home_slot,
    insert,
    ints2,
    kernel_forces,
    matrix,
    registry_address,
    remove,
    vector,
)

# NUMBA_DISABLE_JIT=1 (the interpreted reference path of the kernels): no compiled loop
AVAILABLE = not numba.config.DISABLE_JIT
_USERS = [0, None, None]  # steps under way, the callback they installed, the one it replaced


class callback_installed:
    """Context manager: ``callback`` is MuJoCo's control callback while the block runs.

    MuJoCo has one control callback per process. Steps of several boats in threads share it
    (counted); a step that needs another callback (the 4-DOF model's Python one) waits until
    those have ended. On the way out the callback found on the way in is put back.

    Parameters
    ----------
    callback : callable or ctypes function pointer
        The control callback to install.
    """

    def __init__(self, callback):
        self.callback = callback

    def __enter__(self):
        with CHANGED:
            while _USERS[0] and _USERS[1] is not self.callback:
                CHANGED.wait()
            if _USERS[0] == 0:
                current = mujoco.get_mjcb_control()
                if current is not self.callback:
                    _USERS[2] = current
                    mujoco.set_mjcb_control(self.callback)
                _USERS[1] = self.callback
            _USERS[0] += 1
        return self

    def __exit__(self, *exc) -> None:
        with CHANGED:
            _USERS[0] -= 1
            if _USERS[0] == 0:
                # put back what was there; the compiled stage callback may stay where there was
                # none (it leaves MjData that is not stepping alone, and setting it costs 1 us a
                # step), a Python one may not (MuJoCo calls it on MjData the bindings do not know,
                # e.g. while compiling the next model, and fails). _STAGE is empty in a process
                # where only the 4-DOF model has stepped.
                ours = bool(_STAGE) and self.callback is _STAGE[0]
                if _USERS[2] is not None or not ours:
                    mujoco.set_mjcb_control(_USERS[2])
                _USERS[1] = _USERS[2] = None
                CHANGED.notify_all()


def replaced_callback():
    """The control callback that was installed before the steps under way installed theirs."""
    return _USERS[2]


class Stepping:
    """Context manager: the boats' rows in the registry and our stage callback, while they step.

    ``data_addresses`` and ``rows``: one MjData address and
    :func:`~sailmujoco.step.registry.registry_row` per boat (or a single address and row).
    Entering gives the slots (an int64 array).

    Parameters
    ----------
    data_addresses : int or list of int
        The MjData address of each boat.
    rows : numpy.ndarray or list of numpy.ndarray
        Each boat's :func:`~sailmujoco.step.registry.registry_row`.
    """

    def __init__(self, data_addresses, rows):
        if isinstance(data_addresses, int):
            data_addresses, rows = [data_addresses], [rows]
        self.keys = list(data_addresses)
        self.rows = rows
        self.slots = np.empty(len(self.keys), dtype=np.int64)
        self._callback = callback_installed(stage_callback())

    def __enter__(self) -> np.ndarray:
        done = 0
        try:
            with CHANGED:
                for done, (key, row) in enumerate(zip(self.keys, self.rows, strict=True)):
                    self.slots[done] = insert(key, row)
                done = len(self.keys)
            self._callback.__enter__()
        except BaseException:
            self._release(done)
            raise
        return self.slots

    def __exit__(self, *exc) -> None:
        self._callback.__exit__(*exc)
        self._release(len(self.keys))

    def _release(self, count: int) -> None:
        with CHANGED:
            for slot in self.slots[:count]:
                remove(int(slot))


_OK = kernels.STATUS_OK


def _stage(m, d):
    """mjcb_control: this RK4 stage's forces into qfrc_applied, added mass into M, refactorise.

    Only the first stage's status stops the run (the state at the start of the step, which the
    first-order path checks too); :func:`rk4_steps` then undoes the step. MjData that is not
    stepping through :class:`Stepping` (model compilation, a bare MjData) is left alone.
    """
    registry = numba.carray(pointer(registry_address()), (SLOTS, ROW), np.int64)
    key = address(d)
    slot = home_slot(key)
    for _ in range(SLOTS):
        found = registry[slot, R_DATA]
        if found == EMPTY:
            return
        if found == key:
            row = registry[slot]
            t = numba.carray(pointer(key + time_byte_offset()), (1,), np.float64)[0]
            status = _stage_forces(row, t)
            row[R_COUNT] += 1
            if status != _OK and row[R_COUNT] == 1:
                row[R_STATUS] = status
            mj_factorM(m, d)
            return
        slot = (slot + 1) % SLOTS


_STAGE = []


def stage_callback():
    """The compiled stage callback as a ctypes function (compiled on first use in a process)."""
    if not _STAGE:
        compiled = numba.cfunc(types.void(types.voidptr, types.voidptr), nopython=True,
                              cache=True)(_stage)
        _STAGE.extend((compiled.ctypes, compiled))
    return _STAGE[0]


@numba.njit(inline="always", cache=True)
def _warning_count(row):
    at = R_FIRST + 3 * A_WARNINGS
    count, stride = row[at + 1], row[at + 2]
    return numba.carray(pointer(row[at]), (count * stride,), np.intc)[::stride].sum()


@numba.njit(nogil=True, cache=True)
def _rk4_one(model_address, data_address, nstep, row, saved):
    m, d = pointer(model_address), pointer(data_address)
    time = numba.carray(pointer(data_address + time_byte_offset()), (1,), np.float64)
    qpos, qvel, act = vector(row, A_DATA_QPOS), vector(row, A_DATA_QVEL), vector(row, A_ACT)
    nq, nv, na = qpos.shape[0], qvel.shape[0], act.shape[0]
    before = _warning_count(row)
    for step in range(nstep):
        t0 = time[0]
        saved[:nq] = qpos
        saved[nq:nq + nv] = qvel
        saved[nq + nv:nq + nv + na] = act
        row[R_STATUS] = 0
        row[R_COUNT] = 0
        mj_step(m, d)
        status = row[R_STATUS]
        if status != _OK:
            time[0] = t0
            qpos[:] = saved[:nq]
            qvel[:] = saved[nq:nq + nv]
            act[:] = saved[nq + nv:nq + nv + na]
            return status, step, _warning_count(row) != before
    return _OK, nstep, _warning_count(row) != before


@numba.njit(nogil=True, cache=True)
def _split_one(model_address, data_address, nstep, row):
    m, d = pointer(model_address), pointer(data_address)
    time = numba.carray(pointer(data_address + time_byte_offset()), (1,), np.float64)
    before = _warning_count(row)
    for step in range(nstep):
        mj_step1(m, d)
        status = _stage_forces(row, time[0])
        if status != _OK:
            return status, step, _warning_count(row) != before
        mj_factorM(m, d)
        mj_step2(m, d)
    return _OK, nstep, _warning_count(row) != before


@numba.njit(nogil=True, cache=True)
def rk4_steps(model_address, data_address, nstep, row, saved):
    """``nstep`` calls of MuJoCo's mj_step (RK4) with :func:`stage_callback` as the control callback.

    For the boat whose registry row is ``row`` (in the table, see :class:`Stepping`). On a bad
    first-stage status the step is undone (time, qpos, qvel, act as before it) and the status
    returned.

    Parameters
    ----------
    model_address, data_address : int
        Addresses of the boat's MjModel and MjData (the C structs).
    nstep : int
        Number of sub-steps.
    row : numpy.ndarray, shape (ROW,), int64
        The boat's :func:`~sailmujoco.step.registry.registry_row`: the addresses and sizes of
        its kernel arguments.
    saved : numpy.ndarray, shape (nq + nv + na,)
        Scratch for the state before a step, to undo it.

    Returns
    -------
    status, steps, warned : int, int, bool
        The force kernel's status, the steps done, and whether MuJoCo counted a new warning.
    """
    return _rk4_one(model_address, data_address, nstep, row, saved)


@numba.njit(nogil=True, cache=True)
def split_steps(model_address, data_address, nstep, row):
    """``nstep`` first-order sub-steps: mj_step1, forces and added mass, mj_factorM, mj_step2.

    Stops before integrating a state whose forces are not OK; returns what :func:`rk4_steps`
    returns. Needs no callback (``row`` need not be in the table).

    Parameters
    ----------
    model_address, data_address : int
        Addresses of the boat's MjModel and MjData (the C structs).
    nstep : int
        Number of sub-steps.
    row : numpy.ndarray, shape (ROW,), int64
        The boat's :func:`~sailmujoco.step.registry.registry_row`: the addresses and sizes of
        its kernel arguments.
    """
    return _split_one(model_address, data_address, nstep, row)


@numba.njit(nogil=True, parallel=True, cache=True)
def batch_steps(models, datas, nstep, slots, rk4, saved, status, done, warned):
    """``nstep`` sub-steps of every boat i in parallel threads.

    Per boat, what :func:`rk4_steps` returns goes into ``status``, ``done`` and ``warned``. A
    boat whose ``status`` is not OK on entry is skipped.

    Parameters
    ----------
    models, datas : numpy.ndarray, shape (n,), int64
        Addresses of each boat's MjModel and MjData.
    nstep : int
        Number of sub-steps.
    slots : numpy.ndarray, shape (n,), int64
        Each boat's slot in the registry (:class:`Stepping`).
    rk4 : bool
        MuJoCo's RK4 (:func:`rk4_steps`) or the first-order split step (:func:`split_steps`).
    saved : numpy.ndarray, shape (n, nq + nv + na)
        Per boat, scratch for the state before a step.
    status, done, warned : numpy.ndarray, shape (n,)
        Per boat: the kernel status (in: skip if not OK; out), the steps done, and whether MuJoCo
        counted a new warning.
    """
    registry = numba.carray(pointer(registry_address()), (SLOTS, ROW), np.int64)
    for i in numba.prange(slots.shape[0]):
        if status[i] != _OK:
            done[i] = 0
            continue
        row = registry[slots[i]]
        if rk4:
            s, k, w = _rk4_one(models[i], datas[i], nstep, row, saved[i])
        else:
            s, k, w = _split_one(models[i], datas[i], nstep, row)
        status[i], done[i], warned[i] = s, k, w


# ---- the 4-DOF model's forces ----------------------------------------------------------------
_T_HYDRO, _P_G = kernels.T_HYDRO, P_G


@numba.njit(nogil=True, cache=True)
def forces_4dof(t, row, add_mass):
    """The forces of the 4-DOF boat (heave and pitch held) on its x, y, yaw and roll joints.

    With ``add_mass`` also its added mass in MuJoCo's M; returns the kernel status. (Called
    from Python; in the compiled loop the stage callback does the same.)

    Parameters
    ----------
    t : float
        Time, s.
    row : numpy.ndarray, shape (ROW,), int64
        The boat's :func:`~sailmujoco.step.registry.registry_row`: the addresses and sizes of
        its kernel arguments.
    add_mass : bool
        Whether to add the added mass to MuJoCo's mass matrix.
    """
    return _forces_4dof(row, t, add_mass)


@numba.njit(inline="always", cache=True)
def _stage_forces(row, t):
    """One stage's forces and added mass, for a 6-DOF or a 4-DOF row (``add_mass`` True, known
    only at run time: see :func:`kernel_forces`)."""
    if row[R_DOFS] == 4:
        return _forces_4dof(row, t, row[R_FIRST] != 0)
    return kernel_forces(row, t, row[R_FIRST] != 0)


@numba.njit(inline="always", cache=True)
def _forces_4dof(row, t, add_mass):
    """:meth:`sailmujoco.physics.BoatPhysics._forces_4dof_python` compiled, operation for
    operation (the same products, sums and library calls in the same order, numpy's BLAS for
    the matrix products), so bit for bit (tests/test_native_step.py). The force kernel sees the
    hull as if free: its qpos and qvel (``row``'s first two arrays) are filled here from
    MuJoCo's, and its forces (the kernel's ``qfrc``) are mapped here onto MuJoCo's
    qfrc_applied. The row's 4-DOF arrays: ``a_diag`` (added-mass diagonal), ``csr4`` (rows
    (i, j, address in M) of the lower triangle of the four hull joints), ``weight_arm`` (mass,
    cg_x, cg_z), ``floating_heel``/``floating_righting`` (the geometric mode's floating table,
    empty otherwise).
    """
    q7, v6 = vector(row, A_QPOS), vector(row, A_QVEL)
    qpos, qvel, qfrc = vector(row, A_DATA_QPOS), vector(row, A_DATA_QVEL), vector(row, A_DATA_QFRC)
    a_diag, csr4, weight_arm = vector(row, A_A_DIAG), ints2(row, A_CSR4), vector(row, A_WEIGHT_ARM)
    floating_heel, floating_righting = vector(row, A_FLOAT_HEEL), vector(row, A_FLOAT_RIGHTING)
    # the hull's pose and velocity in free-joint layout (BoatPhysics._fill_pseudo)
    x, y, yaw, roll = qpos[0], qpos[1], qpos[2], qpos[3]
    xd, yd, yawd, rolld = qvel[0], qvel[1], qvel[2], qvel[3]
    cy, sy, cr, sr = math.cos(yaw), math.sin(yaw), math.cos(roll), math.sin(roll)
    rot = np.empty((3, 3))
    rot[0, 0], rot[0, 1], rot[0, 2] = cy, -sy * cr, sy * sr
    rot[1, 0], rot[1, 1], rot[1, 2] = sy, cy * cr, -cy * sr
    rot[2, 0], rot[2, 1], rot[2, 2] = 0.0, sr, cr
    q7[0], q7[1], q7[2] = x, y, 0.0
    c2, s2, cr2, sr2 = math.cos(yaw / 2), math.sin(yaw / 2), math.cos(roll / 2), math.sin(roll / 2)
    q7[3], q7[4], q7[5], q7[6] = c2 * cr2, c2 * sr2, s2 * sr2, s2 * cr2
    q7[7], q7[8] = qpos[4], qpos[5]
    v6[0], v6[1], v6[2] = xd, yd, 0.0
    spin = np.zeros(3)
    spin[2] = yawd
    omega = mat_t_vec(rot, spin)
    v6[3], v6[4], v6[5] = omega[0] + rolld, omega[1] + 0.0, omega[2] + 0.0
    v6[6], v6[7] = qvel[4], qvel[5]

    status = kernel_forces(row, t, row[R_FIRST] == 0)  # no added mass from the kernel (False)
    if status != _OK:
        return status
    f = vector(row, A_QFRC8)
    if floating_heel.shape[0] > 0:  # BoatPhysics._floating_hydrostatics
        righting = np.interp(qpos[3], floating_heel, floating_righting)
        force_b = weight_arm[0] * vector(row, A_P)[_P_G] * rot[2, :]
        fx, fy, fz, cx, cz = force_b[0], force_b[1], force_b[2], weight_arm[1], weight_arm[2]
        terms = matrix(row, A_TERMS)
        terms[_T_HYDRO, 0], terms[_T_HYDRO, 1], terms[_T_HYDRO, 2] = fx, fy, fz
        terms[_T_HYDRO, 3] = (0.0 * fz - cz * fy) - righting
        terms[_T_HYDRO, 4] = cz * fx - cx * fz
        terms[_T_HYDRO, 5] = cx * fy - 0.0 * fx
        push = mat_vec(rot, force_b)
        for k in range(3):
            f[k] += push[k]
            f[3 + k] += terms[_T_HYDRO, 3 + k]
    torque_world = mat_vec(rot, f[3:6].copy())
    qfrc[0], qfrc[1], qfrc[2], qfrc[3] = f[0], f[1], torque_world[2], f[3]
    qfrc[4], qfrc[5] = f[6], f[7]
    if a_diag[4] != a_diag[5]:  # the rotational added-mass rate term (see _forces_4dof_python)
        heel = qpos[3]
        qfrc[2] += (a_diag[5] - a_diag[4]) * math.sin(heel) * math.cos(heel) * qvel[3] * qvel[2]
    if add_mass:
        mass_csr = vector(row, A_MASS_CSR)
        jac = np.zeros((6, 4))
        jac[0:3, 0:2] = rot.T[:, 0:2]
        jac[3:6, 2] = rot.T[:, 2]
        jac[3, 3] = 1.0
        added = mat_mat(jac.T, a_diag.reshape((6, 1)) * jac)
        for k in range(csr4.shape[0]):
            mass_csr[csr4[k, 2]] += added[csr4[k, 0], csr4[k, 1]]
    return status

