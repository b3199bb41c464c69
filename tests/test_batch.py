"""Boats stepped together (sailmujoco/batch.py) follow the trajectories they follow alone.

The batch runs the boats in numba threads through one compiled call; each boat's forces come
from its own arrays (found by its MjData), so every boat must match its solo run exactly:
``np.array_equal``, no tolerance.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from sailmujoco.batch import BoatBatch
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

FLEET = [("saoud_robot", "geometric", 0), ("saoud_robot", "paper", 1), ("wille_yacht", "geometric", 2),
         ("viel_boat", "paper", 3), ("wille_yacht", "paper", 4),
         ("wille_yacht", "geometric", 5, 4), ("saoud_robot", "paper", 6, 4)]  # the last two: 4 DOF


def _boat(boat, hydrostatics, seed, dofs=6):
    wind = WindConfig(speed=3.0 + seed, direction_from=0.7 * seed, seed=seed)
    physics = BoatPhysics.load(boat, wind=wind, forces=ForceSwitches(hydrostatics=hydrostatics),
                               dofs=dofs)
    physics.place(yaw=0.3 * seed, surge=0.5)
    return physics


def _controls(k):
    return np.array([[0.12 * math.sin(0.2 * k + i), 0.5 + 0.2 * math.cos(0.1 * k)]
                     for i in range(len(FLEET))])


def test_every_boat_of_a_batch_follows_its_solo_trajectory_bit_for_bit():
    alone = [_boat(*b) for b in FLEET]
    batch = BoatBatch([_boat(*b) for b in FLEET])
    for k in range(25):
        controls = _controls(k)
        for physics, row in zip(alone, controls, strict=True):
            physics.set_control(row)
            physics.step(20)
        batch.set_controls(controls)
        assert batch.step(20).all()
    for solo, together in zip(alone, batch.boats, strict=True):
        assert solo.data.time == together.data.time == pytest.approx(25 * 0.1)
        assert np.array_equal(solo.data.qpos, together.data.qpos)
        assert np.array_equal(solo.data.qvel, together.data.qvel)
        assert np.array_equal(solo.force_term("sail"), together.force_term("sail"))
    # the boats did different things (so equality is not of identical runs)
    assert len({round(float(b.data.qpos[0]), 6) for b in batch.boats}) == len(FLEET)


def test_a_boat_that_capsizes_stops_alone_and_the_others_go_on():
    """A 20 kN m heeling moment lays the 15 kg robot flat within a second; in the batch it
    stops where it stops alone, and the boats beside it keep matching their solo runs."""
    def fleet():
        boats = [_boat(*b) for b in FLEET[:3]]
        boats[1].set_external_wrench([0.0, 0.0, 0.0, 2.0e4, 0.0, 0.0])
        return boats

    alone, batch = fleet(), BoatBatch(fleet())
    for k in range(15):
        controls = _controls(k)[:3]
        for physics, row in zip(alone, controls, strict=True):
            if physics.stop_reason is None:
                physics.set_control(row)
                try:
                    physics.step(20)
                except Exception:  # noqa: BLE001 (SimulationStopped; the reason is checked below)
                    pass
        batch.set_controls(controls)
        batch.step(20)
    assert batch.stop_reasons == [None, "capsized: |heel| > 90 deg", None]
    assert list(batch.running) == [True, False, True]
    for solo, together in zip(alone, batch.boats, strict=True):
        assert solo.stop_reason == together.stop_reason
        assert solo.data.time == together.data.time
        assert np.array_equal(solo.data.qpos, together.data.qpos)


@pytest.mark.parametrize("boats,message", [
    (lambda: [], "at least one boat"),
    (lambda: [BoatPhysics.load("saoud_robot"), object()], "boat 1: a batch holds BoatPhysics only"),
    (lambda: [BoatPhysics.load("saoud_robot")] * 2, "appears twice"),
])
def test_a_batch_refuses_what_it_cannot_step_in_one_line(boats, message):
    with pytest.raises(ValueError, match=message):
        BoatBatch(boats())


def test_controls_need_one_row_per_boat():
    batch = BoatBatch([_boat(*FLEET[0]), _boat(*FLEET[1])])
    with pytest.raises(ValueError, match=r"one row per boat \(2\)"):
        batch.set_controls([[0.0, 0.5]])


def test_a_boat_mujoco_warns_about_stops_in_the_batch_as_alone():
    """A yaw rate of 1e8 rad/s makes MuJoCo warn of a huge acceleration in the first sub-step
    (tests/test_native_step.py); the boat stops with the message it stops with alone, its
    neighbour goes on."""
    alone = BoatPhysics.load("saoud_robot")
    alone.data.qvel[5] = 1.0e8
    with pytest.raises(Exception, match="mjWARN_BADQACC"):
        alone.step(1)
    boats = [BoatPhysics.load("saoud_robot"), BoatPhysics.load("saoud_robot")]
    boats[0].data.qvel[5] = 1.0e8
    batch = BoatBatch(boats)
    assert list(batch.step(1)) == [False, True]
    assert batch.stop_reasons[0] == alone.stop_reason


def _observations_equal(a, b) -> bool:
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_observations_equal(a[k], b[k]) for k in a)
    return np.array_equal(np.asarray(a), np.asarray(b))


@pytest.mark.parametrize("world,common,batched", [("mujoco", {}, True), ("mujoco", {"dofs": 4}, True),
                                                 ("paper", {}, False)])
def test_a_batch_of_environments_gives_each_the_timesteps_it_gives_alone(world, common, batched):
    """Four seeds of the robot's speed trial with Saoud's controller, 0.5 s episodes: the batch
    steps past an episode's end (each environment resets on its next step, as alone) and every
    TimeStep (type, reward, discount, observation) equals the solo run's."""
    from sailmujoco import suite, sweep

    seeds, options = [0, 1, 2, 3], [{}, {"wind_speed": 3.0}, {}, {"heading_jitter_deg": 20.0}]
    batch = suite.load_batch("saoud_robot", "speed_trial", world, seeds=seeds, options=options,
                             time_limit=0.5, **common)
    assert batch.batched is batched and len(batch) == 4
    solo = [suite.load("saoud_robot", "speed_trial", world, seed=s, time_limit=0.5, **common, **o)
            for s, o in zip(seeds, options, strict=True)]
    policies = [sweep.make_controller("saoud", env) for env in solo]
    twins = [sweep.make_controller("saoud", env) for env in batch.envs]
    steps_a, steps_b = [env.reset() for env in solo], batch.reset()
    seen = []
    for _ in range(8):  # 5 steps end the episode; the 6th resets
        actions = [policy(ts) for policy, ts in zip(twins, steps_b, strict=True)]
        steps_a = [env.step(policy(ts)) for env, policy, ts in zip(solo, policies, steps_a, strict=True)]
        steps_b = batch.step(actions)
        for a, b in zip(steps_a, steps_b, strict=True):
            assert (a.step_type, a.reward, a.discount) == (b.step_type, b.reward, b.discount)
            assert _observations_equal(a.observation, b.observation)
        seen.append(steps_b[0].step_type.name)
    assert seen == ["MID"] * 4 + ["LAST", "FIRST", "MID", "MID"]
