"""The force kernel's arguments are declared once (sailmujoco/forces/kernel_arguments.py): the
kernel's signature, the Python call, the compiled step's registry row and the compiled call that
reads the row all follow that declaration; and every force switch has its slot in P."""

import inspect

import numpy as np

from sailmujoco.forces import boat
from sailmujoco.forces.boat_parameters import P_SIZE, SWITCH_SLOTS, pack_parameters
from sailmujoco.forces.kernel_arguments import (
    KERNEL_ARRAY_NAMES,
    KERNEL_ARRAYS,
    KERNEL_PARAMETERS,
    kernel_call,
)
from sailmujoco.options import FORCE_FIELDS, ForceSwitches, WaveConfig
from sailmujoco.physics import BoatPhysics
from sailmujoco.step import registry


def _python_function(fn):
    return getattr(fn, "py_func", fn)


def test_the_kernel_signature_is_the_declaration():
    parameters = tuple(inspect.signature(_python_function(boat.boat_forces)).parameters)
    assert parameters == KERNEL_PARAMETERS
    assert parameters == ("t", *(a.name for a in KERNEL_ARRAYS), "add_mass")
    assert len(set(KERNEL_ARRAY_NAMES)) == len(KERNEL_ARRAYS)
    doc = _python_function(boat.boat_forces).__doc__
    for name in KERNEL_PARAMETERS:  # the docstring's Parameters section, written from it
        assert f"\n    {name} : " in doc


def test_the_python_call_gives_each_array_under_its_declared_name():
    physics = BoatPhysics.load("saoud_robot", waves=WaveConfig(hs=0.5))
    physics.step(1)
    args = physics._args
    assert len(args) == len(KERNEL_ARRAYS)
    for array, declared in zip(args, KERNEL_ARRAYS, strict=True):
        assert array.dtype == declared.dtype and array.ndim == declared.ndim, declared.name
    by_name = dict(zip(KERNEL_ARRAY_NAMES, args, strict=True))
    assert by_name["P"] is physics._P and by_name["sea"] is physics._sea
    assert by_name["terms"] is physics._terms and by_name["work"] is physics._work
    assert by_name["wander"] is physics.wind.wander and by_name["mass_csr"].size == physics.model.nM
    assert kernel_call(by_name) == args


def test_a_missing_or_unknown_array_is_refused():
    arrays = dict.fromkeys(KERNEL_ARRAY_NAMES, np.zeros(1))
    del arrays["sea"]
    arrays["waves"] = np.zeros(1)
    try:
        kernel_call(arrays)
    except ValueError as err:
        assert str(err) == "the force kernel's arrays: missing ['sea'], unknown ['waves']"
    else:
        raise AssertionError("kernel_call took a wrong set of arrays")


def test_the_registry_row_follows_the_declaration():
    names = [name for name, _, _ in registry.ARRAYS[:len(KERNEL_ARRAYS)]]
    assert names == list(KERNEL_ARRAY_NAMES)
    for (_, dtype, ndim), declared in zip(registry.ARRAYS, KERNEL_ARRAYS, strict=False):
        assert (dtype, ndim) == (declared.dtype, declared.ndim)
    assert registry.ARRAYS[registry.A_QPOS][0] == "qpos" and registry.ARRAYS[registry.A_P][0] == "P"
    assert registry.ARRAYS[registry.A_MASS_CSR][0] == "mass_csr"
    physics = BoatPhysics.load("wille_yacht")
    physics.step(1)
    row = physics._row
    for k, array in enumerate(physics._args):  # each array's address and shape at its place
        at = registry.R_FIRST + 3 * k
        assert row[at] == array.ctypes.data, KERNEL_ARRAY_NAMES[k]
        assert tuple(row[at + 1:at + 3]) == (*array.shape, 1)[:2], KERNEL_ARRAY_NAMES[k]


def test_the_compiled_call_reads_the_row_in_declared_order():
    source = registry._forces_source()
    readers = {(np.float64, 1): "vector", (np.float64, 2): "matrix", (np.int64, 1): "ints",
               (np.int64, 2): "ints2"}
    expected = ", ".join(f"{readers[a.dtype, a.ndim]}(row, {k})" for k, a in enumerate(KERNEL_ARRAYS))
    assert f"_boat_forces(t, {expected}, add_mass)" in source


def test_every_force_switch_has_one_slot_in_p():
    assert set(SWITCH_SLOTS) == set(FORCE_FIELDS)
    slots = [slot for slot, _ in SWITCH_SLOTS.values()]
    assert len(set(slots)) == len(slots) and all(0 <= s < P_SIZE for s in slots)
    p = BoatPhysics.load("saoud_robot").params
    on = pack_parameters(p, ForceSwitches())
    off = pack_parameters(p, ForceSwitches(
        hydrostatics="off", sail=False, keel=False, rudder=False, damping=False, added_mass=False,
        sail_tangential=False, added_mass_coupling="kirchhoff", vertical_damping="body",
        restoring_axes="body", resistance="friction", foils="paper", keel_downwash=False,
        windage=False, wave_hull=False, wave_foil_flow=False, wave_diffraction=False,
        wave_damping="absolute", wave_pressure_decay=False, wave_reflection=False, rig_interaction="none"))
    changed = set(np.flatnonzero(on != off))
    assert changed == set(slots)  # every switch moves its slot, and nothing else
