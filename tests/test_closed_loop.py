"""The compiled closed loop (sailmujoco.loop) is the Python path, to the last bit.

The Python path (``env.step(controller(timestep))`` until the last TimeStep) is the reference:
every record the task keeps, every reward, the world's state, the controller's memory and the
metrics must be the same bits when the episode runs through the compiled loop, including when
the loop hands a failing step back to Python mid-episode.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from sailmujoco.controllers import viel_loop
from sailmujoco.controllers.factories import Bounded
from sailmujoco.controllers.viel import VielController

from sailmujoco import suite
from sailmujoco.forces.wind import WindConfig
from sailmujoco.loop import episode
from sailmujoco.physics import BoatPhysics
from sailmujoco.sweep.controllers import make_controller
from sailmujoco.sweep.runs import execute
from sailmujoco.tasks.environment import SailEnvironment
from sailmujoco.tasks.position import PositionKeeping

GAINS = {"d_M": 14.0, "d_T": 7.0, "k_s": 5.0, "k_p": 1.0, "k_v": 8.0}


def _viel_pair(case=1, seed=0, start=(-30.0, 40.0), duration=30.0, params=None, target=None,
               boat="wille_yacht", world="paper", wind=None):
    if wind is None:
        env = suite.load(boat, "position_keeping", world, seed=seed, time_limit=duration,
                         control_timestep=0.01, case=case, start=start)
    else:  # a MuJoCo boat in a wind of the test's own (gusts, wander), built as the studies build theirs
        physics = BoatPhysics.load(boat, sail_mode="actuated", wind=wind)
        env = SailEnvironment(physics, PositionKeeping(seed=seed, case=case, start=start),
                              time_limit=duration, control_timestep=0.01, legacy_step=False)
    if params:
        env.physics.world.params = dataclasses.replace(env.physics.world.params, **params)
    if target is None:
        controller = make_controller("viel", env, **GAINS)
    else:
        spec = env.action_spec()
        controller = Bounded(VielController(target=target, dt=0.01, **GAINS), spec.minimum, spec.maximum)
    controller.reset(seed)
    return env, controller


def _python_steps(env, controller, timestep, rewards):
    while not timestep.last():
        timestep = env.step(controller(timestep))
        rewards.append(timestep.reward)
    return timestep


def _outcome(env, controller, timestep, rewards):
    """Everything the episode leaves, as exact bytes and reprs."""
    law, physics, task = controller.controller, env.physics, env.task
    records = [{k: (np.asarray(v).tobytes() if isinstance(v, np.ndarray) else repr(v)) for k, v in r.items()}
               for r in task._records]
    if isinstance(physics, BoatPhysics):
        d = physics.data.ptr
        state = (d.qpos.tobytes(), d.qvel.tobytes(), d.act.tobytes(), d.ctrl.tobytes(), repr(d.time),
                 repr(physics.stop_reason))
    else:
        state = (physics.world._state.tobytes(), repr(physics.world.time), physics.world._action.tobytes())
    return {"records": records, "rewards": repr(rewards), "state": state, "sail": repr(law.sail), "q": law.q,
            "v_previous": repr(law.v_previous), "info": repr(law.info), "metrics": repr(task.metrics()),
            "steps": env._step_count, "last": timestep.last(), "reward": repr(timestep.reward),
            "observation": repr(timestep.observation)}


def _python(**pair):
    env, controller = _viel_pair(**pair)
    rewards = []
    timestep = _python_steps(env, controller, env.reset(), rewards)
    return _outcome(env, controller, timestep, rewards), len(rewards)


def _compiled(n_steps=None, **pair):
    """The episode through the compiled loop for ``n_steps`` (all it can take by default), then Python."""
    env, controller = _viel_pair(**pair)
    env.reset()
    law, low, high = controller.controller, controller.low, controller.high
    compiled = viel_loop.compiled_episode(law, env, low, high, n_steps)
    assert compiled is not None
    rewards = [*compiled.rewards.tolist(), compiled.timestep.reward]
    timestep = _python_steps(env, controller, compiled.timestep, rewards)
    return _outcome(env, controller, timestep, rewards), compiled.steps


@pytest.mark.parametrize("pair", [
    dict(case=1, seed=0),  # steady wind
    dict(case=6, seed=3),  # speed and direction oscillating at 1 Hz (Viel case 6)
    dict(case=2, seed=1, start=(2.0, -3.0)),  # inside the target area from the start: steps 19-22
    dict(case=5, seed=2, target=(12.0, -8.0)),  # the controller's own target, not the task's
    dict(case=1, seed=0, boat="viel_boat", world="mujoco"),  # 6-DOF MuJoCo boats
    dict(case=6, seed=2, boat="saoud_robot", world="mujoco"),
    dict(case=1, seed=5, boat="wille_yacht",  # gusts and wander
         wind=WindConfig(speed=9.0, direction_from=2.0, seed=5)),
], ids=["case1", "case6", "inside", "own_target", "viel_boat", "saoud_robot", "yacht_gusts"])
def test_compiled_episode_is_the_python_episode(pair):
    reference, steps = _python(**pair)
    compiled, taken = _compiled(**pair)
    assert steps == 3000 and taken == steps  # 30 s at 100 Hz, all but the last half step compiled
    assert compiled == reference


def test_handing_over_midway_is_the_python_episode():
    """Compiled for 1234 steps, then the Python path: the objects were left as Python leaves them."""
    reference, _ = _python(case=5, seed=4)
    compiled, taken = _compiled(n_steps=1234, case=5, seed=4)
    assert taken == 1234
    assert compiled == reference


@pytest.mark.parametrize("params, stop_step", [
    ({"p10": 1.0}, 67),  # the yaw inertia 400 -> 1 kg m^2: the state overflows to inf at step 67
    ({"p10": 0.01}, 25),  # ... -> 0.01: the state runs away (cos of a huge angle) at step 25
])
def test_a_world_that_fails_mid_episode_fails_in_python_words(params, stop_step):
    """The loop stops before the failing step; the Python path takes it and stops the episode."""
    reference, steps = _python(case=6, seed=0, params=params)
    compiled, taken = _compiled(case=6, seed=0, params=params)
    assert steps == stop_step and taken == stop_step - 1
    assert "non-finite state (VielWorld: integration failed" in compiled["metrics"]
    assert compiled == reference


def test_a_capsize_stops_the_compiled_episode_as_the_python_one():
    """The yacht in a 40 m/s gusty wind capsizes in step 717: the loop ends with that step, the
    Python path gives its TimeStep (the stop's reward, the reason in the metrics)."""
    pair = dict(boat="wille_yacht", wind=WindConfig(speed=40.0, direction_from=2.0, seed=3), seed=0)
    reference, steps = _python(**pair)
    compiled, taken = _compiled(**pair)
    assert steps == taken == 717
    assert "capsized" in compiled["metrics"]
    assert compiled == reference


def test_an_observation_python_rejects_is_rejected_before_any_step():
    env, controller = _viel_pair(target=(math.nan, 0.0))
    env.reset()
    assert episode.run_compiled(env, controller) is None  # viel_view raises on the first step
    assert env._step_count == 0 and env.physics.world.time == 0.0 and env.task._records == []


def test_pairs_without_a_compiled_loop_step_in_python():
    def offered(env, controller):
        env.reset()
        compiled = episode.run_compiled(env, controller)
        untouched = env.task.metrics()["duration"] == 0.0 and env.physics.time() == 0.0
        return compiled is not None, untouched

    env = suite.load("saoud_robot", "position_keeping", seed=0, time_limit=1.0, control_timestep=0.01)
    assert offered(env, make_controller("viel", env))[0]  # the 6-DOF MuJoCo world: covered
    for options in ({"dofs": 4}, {"sensors": "typical"}, {"actuators": "typical"}):  # heave and pitch held,
        env = suite.load("saoud_robot", "position_keeping", seed=0, time_limit=1.0, control_timestep=0.01,
                         **options)  # instruments with noise, servos
        assert offered(env, make_controller("viel", env)) == (False, True), options
    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=1.0, control_timestep=0.01)
    assert offered(env, make_controller("viel", env)) == (False, True)  # another task
    env = suite.load("saoud_robot", "position_keeping", seed=0, time_limit=1.0, control_timestep=0.01)
    assert offered(env, make_controller("pid", env)) == (False, True)  # a controller that offers none


def test_the_sweep_runner_gives_the_same_record_either_way(monkeypatch):
    run = {"run_id": "x", "boat": "wille_yacht", "task": "position_keeping", "world": "paper", "seed": 1,
           "duration": 20.0, "boat_options": {}, "env_options": {"control_timestep": 0.01},
           "task_options": {"case": 3, "start": [-20.0, 25.0]}, "controller": "viel",
           "controller_options": dict(GAINS), "trajectory_rate": 3.0}
    fast = execute(run)
    monkeypatch.setenv("SAILMUJOCO_PYTHON_LOOP", "1")
    slow = execute(run)
    assert fast["status"] == slow["status"] == "ok"
    assert len(fast["trajectory"]) == int(20.0 * 3.0)
    assert repr(fast["metrics"]) == repr(slow["metrics"])
    assert repr(fast["trajectory"]) == repr(slow["trajectory"])


@pytest.mark.parametrize("boat, world", [("wille_yacht", "paper"), ("saoud_robot", "mujoco")])
def test_rollout_gives_the_same_rows_either_way(monkeypatch, boat, world):
    """suite.rollout's default rows (every step's state, heel in degrees, speed over ground ...)."""
    def frame():
        env = suite.load(boat, "position_keeping", world, seed=2, time_limit=5.0, control_timestep=0.01,
                         case=4)
        controller = make_controller("viel", env)
        offer = controller.compiled_episode
        controller.compiled_episode = lambda env: covered.append(offer(env)) or covered[-1]
        return suite.rollout(env, controller), env.task.metrics()

    covered = []

    fast, fast_metrics = frame()
    monkeypatch.setenv("SAILMUJOCO_PYTHON_LOOP", "1")
    slow, slow_metrics = frame()
    assert len(covered) == 1 and covered[0] is not None  # only the first run took the compiled loop
    assert len(fast) == 501 and list(fast.columns) == list(slow.columns)
    assert fast.to_numpy().tobytes() == slow.to_numpy().tobytes()
    assert repr(fast_metrics) == repr(slow_metrics)

