"""Forces at every sub-step: the trajectory does not depend on the control step."""

import math

import numpy as np
import pytest
from conftest import gusty, load


@pytest.mark.parametrize("boat", ["wille_yacht", "saoud_robot"])
def test_trajectory_independent_of_substeps_per_control_step(boat):
    rng = np.random.default_rng(0)
    commands = rng.uniform(-0.5, 0.5, size=(20, 2))
    runs = []
    for substeps in (1, 4, 20):
        physics = load(boat, wind=gusty(8.0, seed=5))
        for command in commands:  # each command held 0.1 s = 20 physics steps
            physics.set_control(command)
            for _ in range(20 // substeps):
                physics.step(substeps)
        runs.append((physics.data.qpos.copy(), physics.data.qvel.copy()))
    for qpos, qvel in runs[1:]:
        assert np.array_equal(qpos, runs[0][0]) and np.array_equal(qvel, runs[0][1])


def test_forces_are_not_held_across_substeps():
    """Holding the first sub-step's forces for a whole control step gives a different answer."""
    import mujoco

    physics = load("wille_yacht", wind=gusty(8.0, seed=5))
    physics.set_control([0.2, 0.5])
    physics.step(200)
    held = physics.copy()
    physics.step(20)
    # the same 20 steps with forces frozen at the first one's values
    m, d = held.model.ptr, held.data.ptr
    mujoco.mj_step1(m, d)
    held._compute_forces()
    frozen = d.qfrc_applied.copy()
    for _ in range(20):
        mujoco.mj_step1(m, d)
        held._prepare(0.0)
        held._kernel(d.time, *held._args, True)  # added mass into M, as in a real step
        d.qfrc_applied[:] = frozen  # but the forces held from the first sub-step
        mujoco.mj_factorM(m, d)
        mujoco.mj_step2(m, d)
    assert not np.allclose(physics.data.qvel, held.data.qvel, rtol=1e-6, atol=1e-9)


def test_same_seed_same_trajectory_bit_for_bit():
    finals = []
    for _ in range(2):
        physics = load("saoud_robot", wind=gusty(6.0, seed=9))
        physics.set_control([0.1, math.radians(40)])
        physics.step(1000)
        finals.append(physics.data.qpos.copy())
    assert np.array_equal(finals[0], finals[1])
