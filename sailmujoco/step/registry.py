"""The registry of the boats that step: one int64 row per boat, laid out from the kernel's arguments.

MuJoCo's control callback (:func:`sailmujoco.step.native.stage_callback`) knows a boat only by
its MjData, so each boat's arrays are found in one int64 array, :data:`REGISTRY`: a row per boat
*while it steps*, holding the address of its MjData, a status word, a stage counter and the
address and shape of every array the force kernel reads or writes. A row is filled when a step
starts and cleared when it ends: no row ever points at memory that was freed.

The row's layout follows the kernel's declared arguments
(:data:`sailmujoco.forces.kernel_arguments.KERNEL_ARRAYS`), and so does :func:`kernel_forces`, the
compiled call of the kernel on a row, whose source is written from that declaration.
"""

from __future__ import annotations

import threading

import numba
import numpy as np
from llvmlite import binding as llvm

from ..forces import boat as kernels
from ..forces.kernel_arguments import KERNEL_ARRAYS
from .mujoco_calls import pointer, symbol_address

# ---- layout ------------------------------------------------------------------------------------
# (name, dtype, dimensions) of each array of a row: the kernel's arrays in their declared order;
# then MuJoCo's qpos, qvel and qfrc_applied (for a 6-DOF boat the kernel's own qpos, qvel, qfrc;
# the 4-DOF boat's kernel sees a pseudo free joint instead) and the 4-DOF stage's own arrays
# (empty for 6 DOF, see native.forces_4dof); then two that are not kernel arguments: the actuator
# activations (saved and restored with qpos and qvel when a step is undone) and MuJoCo's warning
# counters (mjData.warning.number, C int)
_F, _I = np.float64, np.int64
FOUR_DOF_ARRAYS = (("a_diag", _F, 1), ("csr4", _I, 2), ("weight_arm", _F, 1), ("floating_heel", _F, 1),
                   ("floating_righting", _F, 1))
ARRAYS = (*((a.name, a.dtype, a.ndim) for a in KERNEL_ARRAYS),
          ("data_qpos", _F, 1), ("data_qvel", _F, 1), ("data_qfrc", _F, 1),
          *FOUR_DOF_ARRAYS, ("act", _F, 1), ("warnings", np.intc, 1))
_AT = {name: k for k, (name, _, _) in enumerate(ARRAYS)}  # an array's place in a row, by name
A_QPOS, A_QVEL, A_P, A_TERMS, A_QFRC8, A_MASS_CSR = (
    _AT[name] for name in ("qpos", "qvel", "P", "terms", "qfrc", "mass_csr"))  # qfrc: 4 DOF's pseudo
A_DATA_QPOS, A_DATA_QVEL, A_DATA_QFRC = _AT["data_qpos"], _AT["data_qvel"], _AT["data_qfrc"]
A_A_DIAG, A_CSR4, A_WEIGHT_ARM, A_FLOAT_HEEL, A_FLOAT_RIGHTING = (
    _AT[name] for name, _, _ in FOUR_DOF_ARRAYS)
A_ACT, A_WARNINGS = _AT["act"], _AT["warnings"]
R_DATA, R_STATUS, R_COUNT, R_DOFS = 0, 1, 2, 3
R_FIRST = 4  # then three words per array: address, shape[0], shape[1] (1 for a vector)
ROW = R_FIRST + 3 * len(ARRAYS)
# An open-addressed hash table on the MjData address (linear probing): a boat's row is found in
# O(1) from the callback, also with a thousand boats stepping at once. A row that ends its step
# becomes a tombstone (-1), cleared when nothing steps.
SLOTS = 4096
EMPTY, _TOMBSTONE = 0, -1
REGISTRY = np.zeros((SLOTS, ROW), dtype=np.int64)
llvm.add_symbol("sailmujoco_registry", REGISTRY.ctypes.data)
registry_address = symbol_address("sailmujoco_registry")
CHANGED = threading.Condition()  # held while the table or the control callback changes
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
        The boat's force-kernel arrays, in the order of
        :data:`sailmujoco.forces.kernel_arguments.KERNEL_ARRAYS`.
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
    for k, ((name, dtype, ndim), array) in enumerate(zip(ARRAYS, args, strict=True)):
        if name == "warnings":  # a strided view of the counters in the struct: (address, n, stride)
            if array.dtype != np.intc or array.ndim != 1 or array.strides[0] % array.itemsize:
                raise ValueError(f"warnings must be a 1-D view of C ints, got {array.dtype}")
            row[R_FIRST + 3 * k:R_FIRST + 3 * k + 3] = (array.ctypes.data, array.size,
                                                        array.strides[0] // array.itemsize)
            continue
        if array.dtype != dtype or array.ndim != ndim or not array.flags.c_contiguous:
            raise ValueError(f"kernel array {name} must be C-contiguous {dtype.__name__} with "
                             f"{ndim} dimension(s), got {array.dtype} {array.shape}")
        shape = (*array.shape, 1)[:2]
        row[R_FIRST + 3 * k:R_FIRST + 3 * k + 3] = (array.ctypes.data, *shape)
    return row


def insert(key: int, row: np.ndarray) -> int:
    """Put ``row`` in the table for MjData ``key`` (under CHANGED); returns its slot.

    Parameters
    ----------
    key : int
        The address of the boat's MjData (never 0): the table's key, written into the row's
        ``R_DATA`` word.
    row : numpy.ndarray of int64, shape (ROW,)
        The boat's :func:`registry_row`, copied into the slot.

    Returns
    -------
    int
        The slot (row index of :data:`REGISTRY`) the row went to; hand it to :func:`remove`.

    Raises
    ------
    RuntimeError
        When ``SLOTS // 2`` boats are stepping already, or this MjData is already stepping.
    """
    if _IN_TABLE[0] >= SLOTS // 2:
        raise RuntimeError(f"more than {SLOTS // 2} boats stepping at once")
    slot = _insert_row(REGISTRY, key, row)
    if slot < 0:
        raise RuntimeError("this MjData is already stepping")
    _IN_TABLE[0] += 1
    return slot


def remove(slot: int) -> None:
    """Free ``slot`` (under CHANGED); with nothing left stepping, clear the tombstones.

    Parameters
    ----------
    slot : int
        A slot :func:`insert` returned, whose boat has ended its step. Its ``R_DATA`` word
        becomes EMPTY (0) when it was the only row in use and no tombstone is left, otherwise
        a tombstone (-1) until nothing steps.
    """
    _IN_TABLE[0] -= 1
    if _IN_TABLE[0] == 0 and not _TOMBSTONES:  # the usual case: one boat stepping alone
        REGISTRY[slot, R_DATA] = EMPTY
        return
    REGISTRY[slot, R_DATA] = _TOMBSTONE
    _TOMBSTONES.append(slot)
    if _IN_TABLE[0] == 0:
        REGISTRY[_TOMBSTONES, R_DATA] = EMPTY
        _TOMBSTONES.clear()


# ---- compiled code ----------------------------------------------------------------------------
@numba.njit(inline="always", cache=True)
def home_slot(key):
    """The first slot probed for an MjData address (insert and lookup alike).

    Parameters
    ----------
    key : int64
        The MjData address. Its lowest 4 bits are dropped before it is reduced modulo the
        prime 4093.

    Returns
    -------
    int64
        The home slot, in [0, 4093); probing then goes on linearly modulo SLOTS.
    """
    return (key >> 4) % 4093


@numba.njit(cache=True)
def _insert_row(registry, key, row):
    """The table insert of :func:`insert`: probe from the home slot to a free one; -1 if
    ``key`` is already there."""
    slot = home_slot(key)
    for _ in range(SLOTS):
        found = registry[slot, R_DATA]
        if found == EMPTY or found == _TOMBSTONE:
            registry[slot, :] = row
            registry[slot, R_DATA] = key
            return slot
        if found == key:
            return -1
        slot = (slot + 1) % SLOTS
    return -2


@numba.njit(inline="always", cache=True)
def vector(row, k):
    """The ``k``-th array of a registry row as a float64 vector (no copy).

    Parameters
    ----------
    row : numpy.ndarray of int64, shape (ROW,)
        A boat's :func:`registry_row` (or its slot of :data:`REGISTRY`).
    k : int
        The array's place in :data:`ARRAYS` (for example ``A_QPOS``); its words are at
        ``R_FIRST + 3 * k``: address, shape[0], shape[1].

    Returns
    -------
    numpy.ndarray of float64, shape (shape[0],)
        A view of the array's memory at the row's address.
    """
    at = R_FIRST + 3 * k
    return numba.carray(pointer(row[at]), (row[at + 1],), np.float64)


@numba.njit(inline="always", cache=True)
def ints(row, k):
    """The ``k``-th array of a registry row as an int64 vector (no copy).

    Parameters
    ----------
    row : numpy.ndarray of int64, shape (ROW,)
        A boat's :func:`registry_row` (or its slot of :data:`REGISTRY`).
    k : int
        The array's place in :data:`ARRAYS`; its words are at ``R_FIRST + 3 * k``: address,
        shape[0], shape[1].

    Returns
    -------
    numpy.ndarray of int64, shape (shape[0],)
        A view of the array's memory at the row's address.
    """
    at = R_FIRST + 3 * k
    return numba.carray(pointer(row[at]), (row[at + 1],), np.int64)


@numba.njit(inline="always", cache=True)
def ints2(row, k):
    """The ``k``-th array of a registry row as a C-contiguous int64 matrix (no copy).

    Parameters
    ----------
    row : numpy.ndarray of int64, shape (ROW,)
        A boat's :func:`registry_row` (or its slot of :data:`REGISTRY`).
    k : int
        The array's place in :data:`ARRAYS` (for example ``A_CSR4``); its words are at
        ``R_FIRST + 3 * k``: address, shape[0], shape[1].

    Returns
    -------
    numpy.ndarray of int64, shape (shape[0], shape[1])
        A view of the array's memory at the row's address.
    """
    at = R_FIRST + 3 * k
    return numba.carray(pointer(row[at]), (row[at + 1], row[at + 2]), np.int64)


@numba.njit(inline="always", cache=True)
def matrix(row, k):
    """The ``k``-th array of a registry row as a C-contiguous float64 matrix (no copy).

    Parameters
    ----------
    row : numpy.ndarray of int64, shape (ROW,)
        A boat's :func:`registry_row` (or its slot of :data:`REGISTRY`).
    k : int
        The array's place in :data:`ARRAYS` (for example ``A_TERMS``); its words are at
        ``R_FIRST + 3 * k``: address, shape[0], shape[1].

    Returns
    -------
    numpy.ndarray of float64, shape (shape[0], shape[1])
        A view of the array's memory at the row's address.
    """
    at = R_FIRST + 3 * k
    return numba.carray(pointer(row[at]), (row[at + 1], row[at + 2]), np.float64)


# ---- the kernel on a row -----------------------------------------------------------------------
_boat_forces = kernels.boat_forces
_READERS = {(np.float64, 1): "vector", (np.float64, 2): "matrix", (np.int64, 1): "ints",
            (np.int64, 2): "ints2"}  # a row's array as numba sees it, by (dtype, dimensions)


def _forces_source() -> str:
    """The source of :func:`kernel_forces`: the kernel called on the row's arrays in declared order."""
    arrays = ", ".join(f"{_READERS[a.dtype, a.ndim]}(row, {k})" for k, a in enumerate(KERNEL_ARRAYS))
    return f"def kernel_forces(row, t, add_mass):\n    return _boat_forces(t, {arrays}, add_mass)\n"


_FORCES_DOC = """The force kernel (:func:`sailmujoco.forces.boat.boat_forces`) on a registry row.

    Parameters
    ----------
    row : numpy.ndarray of int64, shape (ROW,)
        A boat's :func:`registry_row` (or its slot of :data:`REGISTRY`): the address and
        shape of each kernel array, read in the order of ``KERNEL_ARRAYS``.
    t : float
        Time, s.
    add_mass : bool
        Whether to add the hull's added mass to MuJoCo's mass matrix (the row's
        ``mass_csr``); a value known only at run time (see the comment below).

    Returns
    -------
    int
        STATUS_OK, STATUS_NONFINITE or STATUS_CAPSIZED.
    """


# kernel_forces(row, t, add_mass): the force kernel on the registered arrays, adding the added mass to
# M if ``add_mass``. Compiled from the source above, with this file as its file, so numba caches
# and inlines it as any function of this module. ``add_mass`` must be a value known only at run
# time (``row[R_FIRST] != 0``: the qpos address is never 0): a literal True would compile the
# kernel a second time for the type Literal[bool], and a second signature takes every Python
# call of the kernel off its direct entry point (tests/test_fast_path.py).
_namespace: dict = {}
exec(compile(_forces_source(), __file__, "exec"), globals(), _namespace)
_namespace["kernel_forces"].__doc__ = _FORCES_DOC
kernel_forces = numba.njit(inline="always", cache=True)(_namespace.pop("kernel_forces"))
