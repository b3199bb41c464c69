"""MuJoCo's C API called from compiled code: a whole control step in one call.

Each RK4 stage of :meth:`sailmujoco.physics.BoatPhysics.step` calls the force kernel (27
arrays) and ``mj_factorM``; from a Python callback that costs about 8 us per stage, 4 stages
per sub-step, 20 sub-steps per control step. Here the same work runs without Python:

* :func:`rk4_steps` calls ``mj_step`` n times from numba through the C library's own symbols;
  MuJoCo's control callback (``mjcb_control``, called at each of RK4's four stages) is a numba
  ``cfunc`` (:func:`stage_callback`), that finds the stepping boat's arrays in a registry (below), calls
  the force kernel with this stage's time and state, and refactorises the augmented mass matrix.
  It is MuJoCo's own RK4 and the same kernel on the same arrays as the Python callback, so the trajectory is
  the same to the last bit (tests/test_native_step.py).
* :func:`split_steps` does the same for the first-order integrators: ``mj_step1``, the kernel,
  ``mj_factorM``, ``mj_step2``.
* The 4-DOF boat (heave and pitch held) steps the same way: its row says so (``R_DOFS``), and
  its stage (:func:`_forces_4dof`) fills the kernel's pseudo free joint from MuJoCo's four hull
  joints, calls the kernel, adds the floating hydrostatics and maps the forces and the added
  mass back onto the joints, as the Python reference in :mod:`sailmujoco.step.four_dof` does.

The registry is one int64 array (:data:`REGISTRY`): a row per boat *while it steps*, holding the
address of its MjData, a status word, a stage counter and the address and shape of every array
the kernel reads or writes. The callback knows the boat only by its MjData, so a row is filled
when a step starts and cleared when it ends: no row ever points at memory that was freed.

The compiled functions hold the addresses of the C functions and of the registry, which
differ from process to process, so they are compiled when first used in a process (about 2 s,
the force kernel itself comes from numba's cache) and not cached on disk.
"""

from __future__ import annotations

import ctypes
import math
import threading
from pathlib import Path

import mujoco
import numba
import numpy as np
from llvmlite import binding as llvm
from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic

from ..forces import boat as kernels

# ---- the C library the Python bindings loaded (the same process-wide callbacks) -------------
# NUMBA_DISABLE_JIT=1 (the interpreted reference path of the kernels): no compiled loop
AVAILABLE = not numba.config.DISABLE_JIT
_LIB = ctypes.CDLL(str(next(Path(mujoco.__file__).parent.glob("libmujoco.so.*"))))

# The compiled code reaches MuJoCo's functions, the registry and the offset of mjData.time
# through symbols it names, which LLVM resolves when it loads the code: the machine code holds
# no address of this process, so numba caches it on disk like the force kernels (compiling it
# costs several seconds per process otherwise).
_SYMBOLS = {f"sailmujoco_{name}": ctypes.cast(getattr(_LIB, name), ctypes.c_void_p).value
            for name in ("mj_step", "mj_step1", "mj_step2", "mj_factorM")}
for _name, _value in _SYMBOLS.items():
    llvm.add_symbol(_name, _value)


def _mujoco_call(symbol: str):
    """A compiled call of MuJoCo's ``void fn(const mjModel*, mjData*)`` by its symbol."""
    @intrinsic
    def call(typingctx, m, d):
        def codegen(context, builder, signature, args):
            fnty = ir.FunctionType(ir.VoidType(), [cgutils.voidptr_t, cgutils.voidptr_t])
            builder.call(cgutils.get_or_insert_function(builder.module, fnty, symbol), args)
            return context.get_dummy_value()
        return types.void(types.voidptr, types.voidptr), codegen
    return call


_mj_step = _mujoco_call("sailmujoco_mj_step")
_mj_step1 = _mujoco_call("sailmujoco_mj_step1")
_mj_step2 = _mujoco_call("sailmujoco_mj_step2")
_mj_factorM = _mujoco_call("sailmujoco_mj_factorM")


def _symbol_address(symbol: str):
    """A compiled function returning the address a symbol resolves to (an int64)."""
    @intrinsic
    def address(typingctx):
        def codegen(context, builder, signature, args):
            variable = builder.module.globals.get(symbol)
            if variable is None:
                variable = ir.GlobalVariable(builder.module, ir.IntType(64), symbol)
                variable.linkage = "external"
            return builder.ptrtoint(variable, ir.IntType(64))
        return types.int64(), codegen
    return address


@intrinsic
def _pointer(typingctx, address):
    """The integer ``address`` as a C pointer (``void*``)."""
    def codegen(context, builder, signature, args):
        return builder.inttoptr(args[0], cgutils.voidptr_t)
    return types.voidptr(types.int64), codegen


@intrinsic
def _address(typingctx, pointer):
    """A C pointer as an integer."""
    def codegen(context, builder, signature, args):
        return builder.ptrtoint(args[0], cgutils.intp_t)
    return types.int64(types.voidptr), codegen


def _time_offset() -> int:
    """Byte offset of ``time`` in MuJoCo's mjData struct, found by writing known values to it.

    The Python bindings do not expose field offsets; reading the struct up to the field (it
    comes after the solver statistics, about 100 kB in) never reads past the struct.
    """
    model = mujoco.MjModel.from_xml_string("<mujoco/>")
    data = mujoco.MjData(model)
    base = data._address
    probes = (1234567.890625, -7654321.03125)
    data.time = probes[0]
    chunk, start = 64, 0
    while start < 1 << 22:
        values = np.frombuffer(ctypes.string_at(base + start, 8 * chunk), dtype=np.float64)
        hits = np.flatnonzero(values == probes[0])
        if hits.size:
            offset = start + 8 * int(hits[0])
            data.time = probes[1]
            if np.frombuffer(ctypes.string_at(base + offset, 8), dtype=np.float64)[0] != probes[1]:
                break
            return offset
        start += 8 * chunk
    raise RuntimeError("could not find mjData.time; this MuJoCo's struct layout is unexpected")


TIME_OFFSET = _time_offset()
_TIME_OFFSET = np.array([TIME_OFFSET], dtype=np.int64)  # read by compiled code (symbol below)
llvm.add_symbol("sailmujoco_time_offset", _TIME_OFFSET.ctypes.data)
_time_offset_cell = _symbol_address("sailmujoco_time_offset")

# ---- registry layout ---------------------------------------------------------------------------
# the kernel's array arguments in order (after t), with their dimensions; then MuJoCo's qpos,
# qvel and qfrc_applied (for a 6-DOF boat the kernel's own qpos, qvel, qfrc; the 4-DOF boat's
# kernel sees a pseudo free joint instead) and the 4-DOF stage's own arrays (empty for 6 DOF,
# see forces_4dof); then two that are not kernel arguments: the actuator activations (saved and
# restored with qpos and qvel when a step is undone) and MuJoCo's warning counters
# (mjData.warning.number, C int)
KERNEL_ARRAYS = (
    ("qpos", 1), ("qvel", 1), ("idx", 1), ("P", 1), ("columns", 2), ("strips", 2),
    ("alpha_grid", 1), ("log_re_grid", 1), ("cl_table", 2), ("cd_table", 2), ("oscillation", 1),
    ("gust_f", 1), ("gust_phase", 1), ("gust_amp", 2), ("log_z", 1), ("wander", 1),
    ("gust_cos", 1), ("external", 1), ("terms", 2), ("diag", 1), ("qfrc", 1), ("madd", 2),
    ("mass_csr", 1), ("csr_addr", 1), ("work", 1), ("sea", 2), ("grid", 2))
FOUR_DOF_ARRAYS = (("a_diag", 1), ("csr4", 2), ("weight_arm", 1), ("floating_heel", 1),
                   ("floating_righting", 1))
ARRAYS = (*KERNEL_ARRAYS, ("data_qpos", 1), ("data_qvel", 1), ("data_qfrc", 1),
          *FOUR_DOF_ARRAYS, ("act", 1), ("warnings", 1))
INT_ARRAYS = ("idx", "csr_addr", "csr4")
_AT = {name: k for k, (name, _) in enumerate(ARRAYS)}  # an array's place in a row, by name
A_QPOS, A_QVEL, A_P, A_TERMS, A_QFRC8, A_MASS_CSR = (
    _AT[name] for name in ("qpos", "qvel", "P", "terms", "qfrc", "mass_csr"))  # qfrc: 4 DOF's pseudo
A_DATA_QPOS, A_DATA_QVEL, A_DATA_QFRC = _AT["data_qpos"], _AT["data_qvel"], _AT["data_qfrc"]
A_A_DIAG, A_CSR4, A_WEIGHT_ARM, A_FLOAT_HEEL, A_FLOAT_RIGHTING = (_AT[name] for name, _ in FOUR_DOF_ARRAYS)
A_ACT, A_WARNINGS = _AT["act"], _AT["warnings"]
R_DATA, R_STATUS, R_COUNT, R_DOFS = 0, 1, 2, 3
R_FIRST = 4  # then three words per array: address, shape[0], shape[1] (1 for a vector)
ROW = R_FIRST + 3 * len(ARRAYS)
# An open-addressed hash table on the MjData address (linear probing): a boat's row is found in
# O(1) from the callback, also with a thousand boats stepping at once. A row that ends its step
# becomes a tombstone (-1), cleared when nothing steps.
SLOTS = 4096
_EMPTY, _TOMBSTONE = 0, -1
REGISTRY = np.zeros((SLOTS, ROW), dtype=np.int64)
llvm.add_symbol("sailmujoco_registry", REGISTRY.ctypes.data)
_registry_address = _symbol_address("sailmujoco_registry")
_CHANGED = threading.Condition()
_USERS = [0, None, None]  # steps under way, the callback they installed, the one it replaced
_IN_TABLE = [0]  # rows in use
_TOMBSTONES: list[int] = []  # rows freed since the table was last empty


def registry_row(args, act, warnings, data=None, four_dof=None) -> np.ndarray:
    """The registry words of a boat's kernel arguments (``BoatPhysics._args``), its actuator
    activations ``act`` and warning counters; the MjData word is left 0.

    A 4-DOF boat also gives ``data``, MuJoCo's (qpos, qvel, qfrc_applied), and ``four_dof``, the
    arrays of :data:`FOUR_DOF_ARRAYS` in order; a 6-DOF boat's are its kernel's qpos, qvel, qfrc.

    Parameters
    ----------
    args : tuple of numpy.ndarray
        The boat's force-kernel arrays, in :data:`KERNEL_ARRAYS` order.
    act : numpy.ndarray
        The actuator activations (MjData ``act``).
    warnings : numpy.ndarray of C int
        A 1-D view of MuJoCo's warning counters.
    data : tuple of numpy.ndarray, optional
        A 4-DOF boat's MuJoCo (qpos, qvel, qfrc_applied).
    four_dof : tuple of numpy.ndarray, optional
        A 4-DOF boat's arrays of :data:`FOUR_DOF_ARRAYS`; None for a 6-DOF boat.

    Returns
    -------
    numpy.ndarray of int64
    """
    if len(args) != len(KERNEL_ARRAYS):
        raise ValueError(f"expected {len(KERNEL_ARRAYS)} kernel arrays, got {len(args)}")
    dofs = 6 if four_dof is None else 4
    if data is None:
        data = (args[A_QPOS], args[A_QVEL], args[A_QFRC8])
    if four_dof is None:
        four_dof = (np.zeros(0), np.zeros((0, 3), dtype=np.int64), np.zeros(0), np.zeros(0),
                    np.zeros(0))
    args = (*args, *data, *four_dof, act, warnings)
    row = np.zeros(ROW, dtype=np.int64)
    row[R_DOFS] = dofs
    for k, ((name, ndim), array) in enumerate(zip(ARRAYS, args, strict=True)):
        if name == "warnings":  # a strided view of the counters in the struct: (address, n, stride)
            if array.dtype != np.intc or array.ndim != 1 or array.strides[0] % array.itemsize:
                raise ValueError(f"warnings must be a 1-D view of C ints, got {array.dtype}")
            row[R_FIRST + 3 * k:R_FIRST + 3 * k + 3] = (array.ctypes.data, array.size,
                                                        array.strides[0] // array.itemsize)
            continue
        dtype = np.int64 if name in INT_ARRAYS else np.float64
        if array.dtype != dtype or array.ndim != ndim or not array.flags.c_contiguous:
            raise ValueError(f"kernel array {name} must be C-contiguous {dtype.__name__} with "
                             f"{ndim} dimension(s), got {array.dtype} {array.shape}")
        shape = (*array.shape, 1)[:2]
        row[R_FIRST + 3 * k:R_FIRST + 3 * k + 3] = (array.ctypes.data, *shape)
    return row


def _insert(key: int, row: np.ndarray) -> int:
    """Put ``row`` in the table for MjData ``key`` (under _CHANGED); returns its slot."""
    if _IN_TABLE[0] >= SLOTS // 2:
        raise RuntimeError(f"more than {SLOTS // 2} boats stepping at once")
    slot = _insert_row(REGISTRY, key, row)
    if slot < 0:
        raise RuntimeError("this MjData is already stepping")
    _IN_TABLE[0] += 1
    return slot


def _remove(slot: int) -> None:
    """Free ``slot`` (under _CHANGED); with nothing left stepping, clear the tombstones."""
    _IN_TABLE[0] -= 1
    if _IN_TABLE[0] == 0 and not _TOMBSTONES:  # the usual case: one boat stepping alone
        REGISTRY[slot, R_DATA] = _EMPTY
        return
    REGISTRY[slot, R_DATA] = _TOMBSTONE
    _TOMBSTONES.append(slot)
    if _IN_TABLE[0] == 0:
        REGISTRY[_TOMBSTONES, R_DATA] = _EMPTY
        _TOMBSTONES.clear()


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
        with _CHANGED:
            while _USERS[0] and _USERS[1] is not self.callback:
                _CHANGED.wait()
            if _USERS[0] == 0:
                current = mujoco.get_mjcb_control()
                if current is not self.callback:
                    _USERS[2] = current
                    mujoco.set_mjcb_control(self.callback)
                _USERS[1] = self.callback
            _USERS[0] += 1
        return self

    def __exit__(self, *exc) -> None:
        with _CHANGED:
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
                _CHANGED.notify_all()


def replaced_callback():
    """The control callback that was installed before the steps under way installed theirs."""
    return _USERS[2]


class Stepping:
    """Context manager: the boats' rows in the registry and our stage callback, while they step.

    ``data_addresses`` and ``rows``: one MjData address and :func:`registry_row` per boat (or a
    single address and row). Entering gives the slots (an int64 array).

    Parameters
    ----------
    data_addresses : int or list of int
        The MjData address of each boat.
    rows : numpy.ndarray or list of numpy.ndarray
        Each boat's :func:`registry_row`.
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
            with _CHANGED:
                for done, (key, row) in enumerate(zip(self.keys, self.rows, strict=True)):
                    self.slots[done] = _insert(key, row)
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
        with _CHANGED:
            for slot in self.slots[:count]:
                _remove(int(slot))


# ---- compiled code -------------------------------------------------------------------------------
@numba.njit(inline="always", cache=True)
def _home(key):
    """The first slot probed for an MjData address (insert and lookup alike)."""
    return (key >> 4) % 4093


@numba.njit(cache=True)
def _insert_row(registry, key, row):
    """The table insert of :func:`_insert`: probe from the home slot to a free one; -1 if
    ``key`` is already there."""
    slot = _home(key)
    for _ in range(SLOTS):
        found = registry[slot, R_DATA]
        if found == _EMPTY or found == _TOMBSTONE:
            registry[slot, :] = row
            registry[slot, R_DATA] = key
            return slot
        if found == key:
            return -1
        slot = (slot + 1) % SLOTS
    return -2


@numba.njit(inline="always", cache=True)
def _offset():
    """Byte offset of mjData.time (read at run time: it may change with MuJoCo's version)."""
    return numba.carray(_pointer(_time_offset_cell()), (1,), np.int64)[0]


@numba.njit(inline="always", cache=True)
def _vector(row, k):
    at = R_FIRST + 3 * k
    return numba.carray(_pointer(row[at]), (row[at + 1],), np.float64)


@numba.njit(inline="always", cache=True)
def _ints(row, k):
    at = R_FIRST + 3 * k
    return numba.carray(_pointer(row[at]), (row[at + 1],), np.int64)


@numba.njit(inline="always", cache=True)
def _ints2(row, k):
    at = R_FIRST + 3 * k
    return numba.carray(_pointer(row[at]), (row[at + 1], row[at + 2]), np.int64)


@numba.njit(inline="always", cache=True)
def _matrix(row, k):
    at = R_FIRST + 3 * k
    return numba.carray(_pointer(row[at]), (row[at + 1], row[at + 2]), np.float64)


_boat_forces = kernels.boat_forces
_OK = kernels.STATUS_OK


@numba.njit(inline="always", cache=True)
def _forces(row, t, add_mass):
    """The force kernel on the registered arrays, adding the added mass to M if ``add_mass``.

    ``add_mass`` must be a value known only at run time (``row[R_FIRST] != 0``: the qpos
    address is never 0): a literal True would compile the kernel a second time for the type
    Literal[bool], and a second signature takes every Python call of the kernel off its direct
    entry point (tests/test_fast_path.py).
    """
    return _boat_forces(
        t, _vector(row, 0), _vector(row, 1), _ints(row, 2), _vector(row, 3), _matrix(row, 4),
        _matrix(row, 5), _vector(row, 6), _vector(row, 7), _matrix(row, 8), _matrix(row, 9),
        _vector(row, 10), _vector(row, 11), _vector(row, 12), _matrix(row, 13), _vector(row, 14),
        _vector(row, 15), _vector(row, 16), _vector(row, 17), _matrix(row, 18), _vector(row, 19),
        _vector(row, 20), _matrix(row, 21), _vector(row, 22), _ints(row, 23), _vector(row, 24),
        _matrix(row, 25), _matrix(row, 26), add_mass)


def _stage(m, d):
    """mjcb_control: this RK4 stage's forces into qfrc_applied, added mass into M, refactorise.

    Only the first stage's status stops the run (the state at the start of the step, which the
    first-order path checks too); :func:`rk4_steps` then undoes the step. MjData that is not
    stepping through :class:`Stepping` (model compilation, a bare MjData) is left alone.
    """
    registry = numba.carray(_pointer(_registry_address()), (SLOTS, ROW), np.int64)
    key = _address(d)
    slot = _home(key)
    for _ in range(SLOTS):
        found = registry[slot, R_DATA]
        if found == _EMPTY:
            return
        if found == key:
            row = registry[slot]
            t = numba.carray(_pointer(key + _offset()), (1,), np.float64)[0]
            status = _stage_forces(row, t)
            row[R_COUNT] += 1
            if status != _OK and row[R_COUNT] == 1:
                row[R_STATUS] = status
            _mj_factorM(m, d)
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
    return numba.carray(_pointer(row[at]), (count * stride,), np.intc)[::stride].sum()


@numba.njit(nogil=True, cache=True)
def _rk4_one(model_address, data_address, nstep, row, saved):
    m, d = _pointer(model_address), _pointer(data_address)
    time = numba.carray(_pointer(data_address + _offset()), (1,), np.float64)
    qpos, qvel, act = _vector(row, A_DATA_QPOS), _vector(row, A_DATA_QVEL), _vector(row, A_ACT)
    nq, nv, na = qpos.shape[0], qvel.shape[0], act.shape[0]
    before = _warning_count(row)
    for step in range(nstep):
        t0 = time[0]
        saved[:nq] = qpos
        saved[nq:nq + nv] = qvel
        saved[nq + nv:nq + nv + na] = act
        row[R_STATUS] = 0
        row[R_COUNT] = 0
        _mj_step(m, d)
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
    m, d = _pointer(model_address), _pointer(data_address)
    time = numba.carray(_pointer(data_address + _offset()), (1,), np.float64)
    before = _warning_count(row)
    for step in range(nstep):
        _mj_step1(m, d)
        status = _stage_forces(row, time[0])
        if status != _OK:
            return status, step, _warning_count(row) != before
        _mj_factorM(m, d)
        _mj_step2(m, d)
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
        The boat's :func:`registry_row`: the addresses and sizes of its kernel arguments.
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
        The boat's :func:`registry_row`: the addresses and sizes of its kernel arguments.
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
    registry = numba.carray(_pointer(_registry_address()), (SLOTS, ROW), np.int64)
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
_T_HYDRO, _P_G = kernels.T_HYDRO, kernels.P_G


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
        The boat's :func:`registry_row`: the addresses and sizes of its kernel arguments.
    add_mass : bool
        Whether to add the added mass to MuJoCo's mass matrix.
    """
    return _forces_4dof(row, t, add_mass)


@numba.njit(inline="always", cache=True)
def _stage_forces(row, t):
    """One stage's forces and added mass, for a 6-DOF or a 4-DOF row (``add_mass`` True, known
    only at run time: see :func:`_forces`)."""
    if row[R_DOFS] == 4:
        return _forces_4dof(row, t, row[R_FIRST] != 0)
    return _forces(row, t, row[R_FIRST] != 0)


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
    q7, v6 = _vector(row, A_QPOS), _vector(row, A_QVEL)
    qpos, qvel, qfrc = _vector(row, A_DATA_QPOS), _vector(row, A_DATA_QVEL), _vector(row, A_DATA_QFRC)
    a_diag, csr4, weight_arm = _vector(row, A_A_DIAG), _ints2(row, A_CSR4), _vector(row, A_WEIGHT_ARM)
    floating_heel, floating_righting = _vector(row, A_FLOAT_HEEL), _vector(row, A_FLOAT_RIGHTING)
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
    omega = rot.T @ spin
    v6[3], v6[4], v6[5] = omega[0] + rolld, omega[1] + 0.0, omega[2] + 0.0
    v6[6], v6[7] = qvel[4], qvel[5]

    status = _forces(row, t, row[R_FIRST] == 0)  # no added mass from the kernel (False)
    if status != _OK:
        return status
    f = _vector(row, A_QFRC8)
    if floating_heel.shape[0] > 0:  # BoatPhysics._floating_hydrostatics
        righting = np.interp(qpos[3], floating_heel, floating_righting)
        force_b = weight_arm[0] * _vector(row, A_P)[_P_G] * rot[2, :]
        fx, fy, fz, cx, cz = force_b[0], force_b[1], force_b[2], weight_arm[1], weight_arm[2]
        terms = _matrix(row, A_TERMS)
        terms[_T_HYDRO, 0], terms[_T_HYDRO, 1], terms[_T_HYDRO, 2] = fx, fy, fz
        terms[_T_HYDRO, 3] = (0.0 * fz - cz * fy) - righting
        terms[_T_HYDRO, 4] = cz * fx - cx * fz
        terms[_T_HYDRO, 5] = cx * fy - 0.0 * fx
        push = rot @ force_b
        for k in range(3):
            f[k] += push[k]
            f[3 + k] += terms[_T_HYDRO, 3 + k]
    torque_world = rot @ f[3:6].copy()
    qfrc[0], qfrc[1], qfrc[2], qfrc[3] = f[0], f[1], torque_world[2], f[3]
    qfrc[4], qfrc[5] = f[6], f[7]
    if a_diag[4] != a_diag[5]:  # the rotational added-mass rate term (see _forces_4dof_python)
        heel = qpos[3]
        qfrc[2] += (a_diag[5] - a_diag[4]) * math.sin(heel) * math.cos(heel) * qvel[3] * qvel[2]
    if add_mass:
        mass_csr = _vector(row, A_MASS_CSR)
        jac = np.zeros((6, 4))
        jac[0:3, 0:2] = rot.T[:, 0:2]
        jac[3:6, 2] = rot.T[:, 2]
        jac[3, 3] = 1.0
        added = jac.T @ (a_diag.reshape((6, 1)) * jac)
        for k in range(csr4.shape[0]):
            mass_csr[csr4[k, 2]] += added[csr4[k, 0], csr4[k, 1]]
    return status
