"""The compiled control step (sailmujoco/step/native.py) is the Python-driven step, bit for bit.

The reference is the same MuJoCo step with the stage work (force kernel, added mass,
refactorisation) called from Python, ``BoatPhysics.compiled_loop = False``. Equality is exact
(``np.array_equal``), not a tolerance: the compiled loop calls the same C functions and the
same kernel on the same arrays.
"""

from __future__ import annotations

import math
import subprocess
import sys

import mujoco
import numpy as np
import pytest

from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches, SimulationStopped
from sailmujoco.step import native

EULER = mujoco.mjtIntegrator.mjINT_EULER


def _run(boat, hydrostatics, compiled, integrator=None, steps=30, dofs=6, **switches):
    wind = WindConfig(speed=7.0, direction_from=math.radians(60.0), seed=5, current_east=0.2)
    physics = BoatPhysics.load(boat, wind=wind, dofs=dofs,
                               forces=ForceSwitches(hydrostatics=hydrostatics, **switches))
    physics.compiled_loop = compiled
    if integrator is not None:
        physics.model.opt.integrator = integrator
    physics.place(yaw=0.4, surge=1.0)
    rows = []
    for k in range(steps):
        physics.set_control([0.15 * math.sin(0.2 * k), 0.6 + 0.3 * math.cos(0.1 * k)])
        physics.step(7 if k % 3 else 20)  # control periods of different lengths
        rows.append(np.concatenate([[physics.data.time], physics.data.qpos, physics.data.qvel,
                                    *physics.force_terms().values()]))
    return np.array(rows)


@pytest.mark.parametrize("boat,hydrostatics", [("wille_yacht", "geometric"),
                                               ("saoud_robot", "paper"),
                                               ("viel_boat", "geometric")])
def test_the_compiled_rk4_loop_is_the_python_driven_step_bit_for_bit(boat, hydrostatics):
    compiled = _run(boat, hydrostatics, True)
    reference = _run(boat, hydrostatics, False)
    assert np.all(np.isfinite(reference)) and np.ptp(reference[:, 1]) > 0.5  # it sailed
    assert np.array_equal(compiled, reference)


@pytest.mark.parametrize("boat,hydrostatics,integrator", [("wille_yacht", "geometric", None),
                                                          ("saoud_robot", "paper", None),
                                                          ("wille_yacht", "paper", EULER)])
def test_the_compiled_4dof_forces_are_the_python_ones_bit_for_bit(boat, hydrostatics, integrator):
    """The heave-and-pitch-held boat: native.forces_4dof (pseudo free joint, force kernel,
    floating hydrostatics, mapping onto the joints, added mass) against its Python reference."""
    compiled = _run(boat, hydrostatics, True, integrator, dofs=4)
    reference = _run(boat, hydrostatics, False, integrator, dofs=4)
    assert np.all(np.isfinite(reference)) and np.ptp(reference[:, 1]) > 0.5  # it sailed
    assert np.array_equal(compiled, reference)


@pytest.mark.parametrize("boat,hydrostatics", [("wille_yacht", "geometric"), ("saoud_robot", "paper")])
def test_the_compiled_4dof_stage_at_random_states(boat, hydrostatics):
    """One stage's qfrc_applied, added mass in M and force terms at 200 random states (heels to
    80 deg, either sign, fast turns): the compiled stage against the Python one, bit for bit."""
    rng = np.random.default_rng(11)
    physics = BoatPhysics.load(boat, dofs=4, wind=WindConfig(speed=9.0, seed=2),
                               forces=ForceSwitches(hydrostatics=hydrostatics))
    assert physics._a_diag[4] != physics._a_diag[5]  # the added-mass rate term acts
    d = physics.data
    for _ in range(200):
        d.ptr.time = rng.uniform(0.0, 100.0)
        d.qpos[:] = [*rng.normal(0.0, 20.0, 2), rng.uniform(-4.0, 4.0), rng.uniform(-1.4, 1.4),
                     *rng.uniform(-0.5, 0.5, d.qpos.size - 4)]
        d.qvel[:] = rng.normal(0.0, 1.0, d.qvel.size)
        mujoco.mj_forward(physics.model.ptr, d.ptr)
        out = []
        for compiled in (True, False):
            physics.compiled_loop = compiled
            mujoco.mj_forward(physics.model.ptr, d.ptr)  # M without added mass
            status = physics._forces_4dof(True)
            out.append((status, d.qfrc_applied.copy(), d.ptr.M.copy(), physics._terms.copy(),
                        physics._q7.copy(), physics._v6.copy()))
        for new, ref in zip(*out, strict=True):
            assert np.array_equal(new, ref)
    assert np.any(out[1][3] != 0.0)


def test_the_compiled_first_order_loop_is_the_python_driven_step_bit_for_bit():
    compiled = _run("saoud_robot", "geometric", True, integrator=EULER, keel_downwash=False)
    reference = _run("saoud_robot", "geometric", False, integrator=EULER, keel_downwash=False)
    assert np.array_equal(compiled, reference)


@pytest.mark.parametrize("integrator,dofs", [(None, 6), (EULER, 6), (None, 4), (EULER, 4)])
def test_a_capsize_stops_both_paths_in_the_same_state(integrator, dofs):
    """A heeling moment of 20 kN m lays the robot (15 kg) flat within a second: both paths stop
    with the same reason, at the same time, in the state before the offending step."""
    stopped = []
    for compiled in (True, False):
        physics = BoatPhysics.load("saoud_robot", dofs=dofs)
        physics.compiled_loop = compiled
        if integrator is not None:
            physics.model.opt.integrator = integrator
        physics.set_external_wrench([0.0, 0.0, 0.0, 2.0e4, 0.0, 0.0])
        with pytest.raises(SimulationStopped) as err:
            for _ in range(100):
                physics.step(20)
        stopped.append((err.value.reason, physics.data.time, physics.data.qpos.copy()))
    assert stopped[0][0] == stopped[1][0] == "capsized: |heel| > 90 deg"
    assert stopped[0][1] == stopped[1][1] < 2.0
    assert np.array_equal(stopped[0][2], stopped[1][2])


def test_the_control_callback_found_before_a_step_is_there_after_it():
    calls = []

    def mine(m, d):
        calls.append(d.time)

    # (MuJoCo calls a Python callback on MjData the bindings do not know while compiling a
    # model, which fails: everything is built before it is installed)
    physics = BoatPhysics.load("saoud_robot")
    model = mujoco.MjModel.from_xml_string("<mujoco><worldbody><body><freejoint/>"
                                           "<geom size='.1'/></body></worldbody></mujoco>")
    data = mujoco.MjData(model)
    mujoco.set_mjcb_control(mine)
    try:
        physics.step(5)
        assert mujoco.get_mjcb_control() is mine
        mujoco.mj_step(model, data)
        assert calls == [0.0]  # the bare MjData still gets the user's callback
    finally:
        mujoco.set_mjcb_control(None)


def test_a_python_stage_first_in_a_process_leaves_no_callback_behind():
    """In a fresh process (a sweep worker) whose first step runs the stage in Python (here the
    4-DOF boat with ``compiled_loop`` False), the Python stage callback is put back to none after
    the step; left installed, the next model's compilation fails inside MuJoCo ("Python
    exception raised": it was so for the 4-DOF boat in 'study wille_roll_table1'). A fresh
    interpreter, because this process has compiled our stage callback already."""
    script = ("import mujoco\n"
              "from sailmujoco.physics import BoatPhysics\n"
              "four = BoatPhysics.load('wille_yacht', dofs=4)\n"
              "four.compiled_loop = False\n"
              "four.step(3)\n"
              "assert mujoco.get_mjcb_control() is None, mujoco.get_mjcb_control()\n"
              "six = BoatPhysics.load('wille_yacht')\n"
              "six.step(3)\n"
              "four.step(3)\n"
              "print(six.data.time / six.model.opt.timestep, four.data.time / four.model.opt.timestep)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert [round(float(x), 9) for x in done.stdout.split()] == [3.0, 6.0]  # both kept stepping


def test_a_bare_model_stepped_while_a_boat_steps_is_untouched():
    """While a boat steps, MuJoCo's callback is ours; another MjData must see no force from it.
    A free sphere falls 1/2 g t^2 (semi-implicit Euler: g h^2 n(n+1)/2 after n steps) whatever the
    boats around it do."""
    physics = BoatPhysics.load("saoud_robot")
    physics.step(1)
    model = mujoco.MjModel.from_xml_string("<mujoco><option timestep='0.001' integrator='Euler'/>"
                                           "<worldbody><body><freejoint/><geom size='.1'/>"
                                           "</body></worldbody></mujoco>")
    data = mujoco.MjData(model)
    with native.Stepping(physics.data.ptr._address, physics._row):
        assert mujoco.get_mjcb_control() is native.stage_callback()
        for _ in range(100):
            mujoco.mj_step(model, data)
    g, h, n = 9.81, 0.001, 100
    assert data.qpos[2] == pytest.approx(-g * h * h * n * (n + 1) / 2, rel=1e-9)
    assert np.all(data.qfrc_applied == 0.0)


def test_a_mujoco_warning_stops_both_paths_with_the_same_reason():
    """A yaw rate of 1e8 rad/s (finite, so the force kernel runs) puts a hull damping moment of
    order 1e16 N m on the robot: MuJoCo warns of a huge acceleration (mjWARN_BADQACC) and both
    paths stop on that warning, with dm_control's message."""
    reasons = []
    for compiled in (True, False):
        physics = BoatPhysics.load("saoud_robot")
        physics.compiled_loop = compiled
        physics.data.qvel[5] = 1.0e8
        with pytest.raises(SimulationStopped):
            physics.step(1)
        reasons.append(physics.stop_reason)
    assert reasons[0] == reasons[1]
    assert reasons[0].startswith("non-finite or out-of-range state") and "mjWARN_BADQACC" in reasons[0]
