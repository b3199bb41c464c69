"""MuJoCo's C functions called from compiled code, and the address of mjData.time.

The compiled step (:mod:`sailmujoco.step.native`) calls ``mj_step``, ``mj_step1``, ``mj_step2``
and ``mj_factorM``, the compiled closed loop (:mod:`sailmujoco.loop`) also ``mj_kinematics``,
``mj_comPos``, ``mj_comVel``, ``mj_objectVelocity`` and ``mju_quat2Mat``, of the C library the
Python bindings loaded (the same process-wide callbacks), and reads the simulation time from the
MjData struct. It reaches them through symbols it names, which LLVM resolves when it loads the
code: the machine code holds no address of this process, so numba caches it on disk like the
force kernels (compiling it costs several seconds per process otherwise).
"""

from __future__ import annotations

import ctypes
from pathlib import Path

import mujoco
import numba
import numpy as np
from llvmlite import binding as llvm
from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic

_LIB = ctypes.CDLL(str(next(Path(mujoco.__file__).parent.glob("libmujoco.so.*"))))

_SYMBOLS = {f"sailmujoco_{name}": ctypes.cast(getattr(_LIB, name), ctypes.c_void_p).value
            for name in ("mj_step", "mj_step1", "mj_step2", "mj_factorM", "mj_kinematics", "mj_comPos",
                         "mj_comVel", "mj_objectVelocity", "mju_quat2Mat")}
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


mj_step = _mujoco_call("sailmujoco_mj_step")
mj_step1 = _mujoco_call("sailmujoco_mj_step1")
mj_step2 = _mujoco_call("sailmujoco_mj_step2")
mj_factorM = _mujoco_call("sailmujoco_mj_factorM")
mj_kinematics = _mujoco_call("sailmujoco_mj_kinematics")
mj_comPos = _mujoco_call("sailmujoco_mj_comPos")
mj_comVel = _mujoco_call("sailmujoco_mj_comVel")


@intrinsic
def mj_objectVelocity(typingctx, m, d, objtype, objid, res, flg_local):
    """MuJoCo's ``mj_objectVelocity(m, d, objtype, objid, res, flg_local)`` from compiled code:
    ``res`` a C pointer to 6 doubles (``pointer(array.ctypes.data)``), the ints int64."""
    def codegen(context, builder, signature, args):
        i32 = ir.IntType(32)
        fnty = ir.FunctionType(ir.VoidType(), [cgutils.voidptr_t, cgutils.voidptr_t, i32, i32,
                                               cgutils.voidptr_t, i32])
        m_, d_, objtype_, objid_, res_, local_ = args
        builder.call(cgutils.get_or_insert_function(builder.module, fnty, "sailmujoco_mj_objectVelocity"),
                     [m_, d_, builder.trunc(objtype_, i32), builder.trunc(objid_, i32), res_,
                      builder.trunc(local_, i32)])
        return context.get_dummy_value()
    signature = types.void(types.voidptr, types.voidptr, types.int64, types.int64, types.voidptr, types.int64)
    return signature, codegen


@intrinsic
def mju_quat2Mat(typingctx, res, quat):
    """MuJoCo's ``mju_quat2Mat(res, quat)`` from compiled code: C pointers to 9 and 4 doubles."""
    def codegen(context, builder, signature, args):
        fnty = ir.FunctionType(ir.VoidType(), [cgutils.voidptr_t, cgutils.voidptr_t])
        builder.call(cgutils.get_or_insert_function(builder.module, fnty, "sailmujoco_mju_quat2Mat"), args)
        return context.get_dummy_value()
    return types.void(types.voidptr, types.voidptr), codegen


def symbol_address(symbol: str):
    """A compiled function returning the address a symbol resolves to (an int64).

    Parameters
    ----------
    symbol : str
        A symbol registered with ``llvmlite.binding.add_symbol`` (for example
        ``"sailmujoco_registry"``). The compiled code declares it as an external 64-bit global
        variable, so the address is resolved when LLVM loads the code (and the machine code,
        holding no address of this process, can be cached on disk).

    Returns
    -------
    numba intrinsic
        A function of no arguments, callable from compiled code only, that returns the
        symbol's address as an int64 (see :func:`pointer` to read through it).
    """
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
def pointer(typingctx, address):
    """The integer ``address`` as a C pointer (``void*``)."""
    def codegen(context, builder, signature, args):
        return builder.inttoptr(args[0], cgutils.voidptr_t)
    return types.voidptr(types.int64), codegen


@intrinsic
def address(typingctx, pointer):
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
_time_offset_cell = symbol_address("sailmujoco_time_offset")


@numba.njit(inline="always", cache=True)
def time_byte_offset():
    """Byte offset of mjData.time (read at run time: it may change with MuJoCo's version)."""
    return numba.carray(pointer(_time_offset_cell()), (1,), np.int64)[0]
