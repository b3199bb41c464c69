"""The force kernel's arguments, declared once.

:func:`sailmujoco.forces.boat.boat_forces` is called as ``boat_forces(t, *arrays, add_mass)``:
the time t (s, float), then the arrays of :data:`KERNEL_ARRAYS` in their order, then
``add_mass`` (bool: add the hull's added mass to ``mass_csr``). Everything that hands the
kernel its arrays reads their order, dtypes and dimensions from here: the Python call
(:func:`kernel_call`, used by :class:`sailmujoco.physics.BoatPhysics`), the compiled step's
registry row and the compiled call that reads it back (:mod:`sailmujoco.step.registry`).
tests/test_kernel_arguments.py checks the kernel's signature against this declaration.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class KernelArray:
    """One array argument of the force kernel.

    Parameters
    ----------
    name : str
        The kernel's parameter name.
    dtype : type
        ``numpy.float64`` or ``numpy.int64``.
    ndim : int
        1 or 2; every array is C-contiguous.
    shape : str
        Its shape, in words.
    holds : str
        What it holds (units, frames and its writer or reader).
    """

    name: str
    dtype: type
    ndim: int
    shape: str
    holds: str


F, I64 = np.float64, np.int64
KERNEL_ARRAYS = (
    KernelArray("qpos", F, 1, "(nq,)", "generalised position: free joint (CO's world ENU position m, "
                "quaternion body FLU -> world), then the rudder and sail hinges (rad)"),
    KernelArray("qvel", F, 1, "(nv,)", "generalised velocity: world velocity of CO (m/s), body angular "
                "velocity (rad/s), then the hinge rates (rad/s)"),
    KernelArray("idx", I64, 1, "(4,)", "qpos index of the rudder hinge, its dof, qpos index of the sail "
                "hinge, its dof"),
    KernelArray("P", F, 1, "(P_SIZE,)", "the packed parameters and switches "
                "(sailmujoco.forces.boat_parameters.pack_parameters)"),
    KernelArray("columns", F, 2, "(5, n)", "the hull's columns (forces.hydrostatics.submerged_volume)"),
    KernelArray("strips", F, 2, "(3, n)", "the cross-flow strips: body x (m), weights (m), drafts (m)"),
    KernelArray("alpha_grid", F, 1, "(na,)", "the section table's angles of attack, rad "
                "(forces.foil_sections.SectionTable)"),
    KernelArray("log_re_grid", F, 1, "(nr,)", "the section table's log Reynolds numbers"),
    KernelArray("cl_table", F, 2, "(nr, na)", "the section table's lift coefficients"),
    KernelArray("cd_table", F, 2, "(nr, na)", "the section table's drag coefficients"),
    KernelArray("oscillation", F, 1, "(3,)", "the wind's modulation: speed (m/s), direction (rad), "
                "frequency (Hz)"),
    KernelArray("gust_f", F, 1, "(ng,)", "the wind field's gust frequencies (WindField.gust_frequency)"),
    KernelArray("gust_phase", F, 1, "(ng,)", "the gusts' phases (WindField.gust_phase)"),
    KernelArray("gust_amp", F, 2, "(nz, ng)", "the gusts' amplitudes at the heights of log_z "
                "(WindField.gust_amplitude)"),
    KernelArray("log_z", F, 1, "(nz,)", "the log heights of the gusts' table (WindField.log_z)"),
    KernelArray("wander", F, 1, "(nw,)", "the wind's direction wander series (WindField.wander)"),
    KernelArray("gust_cos", F, 1, "(ng + 1,)", "the gusts' cosines' cache: (time, cos_1 .. cos_n) "
                "(WindField.gust_cos)"),
    KernelArray("external", F, 1, "(6,)", "an external wrench, body frame about CO, N and N m"),
    KernelArray("terms", F, 2, "(len(TERMS), 6)", "receives each term's body-frame wrench about CO"),
    KernelArray("diag", F, 1, "(D_SIZE,)", "receives the diagnostics, laid out by the D_* indices"),
    KernelArray("qfrc", F, 1, "(nv,)", "receives the generalised forces: world force on CO (N), body "
                "torque (N m), hinge moments (N m)"),
    KernelArray("madd", F, 2, "(3, 3)", "receives the world-frame translational added mass, kg"),
    KernelArray("mass_csr", F, 1, "(nM,)", "MuJoCo's sparse mass matrix (qM); with add_mass the hull's "
                "added mass is added"),
    KernelArray("csr_addr", I64, 1, "(9,)", "addresses in mass_csr of the translational block's lower "
                "triangle ((0,0), (1,0), (1,1), (2,0), (2,1), (2,2)), then the rotational diagonal"),
    KernelArray("work", F, 1, "(WORK_SIZE,)", "scratch, so the kernel allocates nothing"),
    KernelArray("sea", F, 2, "(rows, m)", "the sea (forces.sea_kernels.sea_array); m = 0: calm water"),
    KernelArray("grid", F, 2, "(6, n)", "the hull's coarse grid for the sea (forces.sea_kernels.grid_array)"),
    KernelArray("waterline", F, 2, "(7 + m, n)", "the waterline's stations and each component's "
                "reflection coefficients (forces.wave_reflection.waterline_array)"),
)
KERNEL_ARRAY_NAMES = tuple(a.name for a in KERNEL_ARRAYS)
KERNEL_PARAMETERS = ("t", *KERNEL_ARRAY_NAMES, "add_mass")  # boat_forces' signature


def kernel_call(arrays: dict) -> tuple:
    """The kernel's arrays in their order, from a mapping of them by name.

    Parameters
    ----------
    arrays : dict
        Every array of :data:`KERNEL_ARRAYS` by its name, and nothing else.

    Returns
    -------
    tuple of numpy.ndarray
        The arrays in :data:`KERNEL_ARRAYS` order (the call is ``boat_forces(t, *them, add_mass)``).
    """
    if arrays.keys() != set(KERNEL_ARRAY_NAMES):
        missing = sorted(set(KERNEL_ARRAY_NAMES) - arrays.keys())
        extra = sorted(arrays.keys() - set(KERNEL_ARRAY_NAMES))
        raise ValueError(f"the force kernel's arrays: missing {missing}, unknown {extra}")
    return tuple(arrays[name] for name in KERNEL_ARRAY_NAMES)


def with_parameters(fn):
    """``fn`` with the kernel's "Parameters" section, written from the declaration, put into
    its docstring before "Returns" (so the kernel's docstring lists no argument by hand).

    Parameters
    ----------
    fn : function
        The force kernel's Python function, before it is compiled.

    Returns
    -------
    function
        ``fn`` itself, its ``__doc__`` completed.
    """
    def entry(name: str, kind: str, text: str) -> str:
        body = textwrap.fill(text[0].upper() + text[1:] + ".", 96, initial_indent=" " * 8,
                             subsequent_indent=" " * 8)
        return f"    {name} : {kind}\n{body}\n"

    lines = [entry("t", "float", "time, s")]
    lines += [entry(a.name, f"numpy.ndarray of {np.dtype(a.dtype).name}, shape {a.shape}", a.holds)
              for a in KERNEL_ARRAYS]
    lines.append(entry("add_mass", "bool", "whether to add the hull's added mass to mass_csr"))
    section = "    Parameters\n    ----------\n" + "".join(lines) + "\n"
    head, returns = fn.__doc__.split("    Returns\n", 1)
    fn.__doc__ = head + section + "    Returns\n" + returns
    return fn
