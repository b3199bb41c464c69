"""Every controller runs its own task in both worlds for 60 s without error."""

import numpy as np
import pytest

from sailmujoco import suite, sweep

OWN_TASK = [
    ("pid", "wille_yacht", "heading_hold"),
    ("wille_heading", "wille_yacht", "course_hold"),
    ("wille_course", "wille_yacht", "course_hold"),
    ("wille_roll", "wille_yacht", "beam_reach_roll"),
    ("saoud", "saoud_robot", "speed_trial"),
    ("briere", "saoud_robot", "speed_trial"),
    ("viel", "saoud_robot", "position_keeping"),
]


@pytest.mark.parametrize("world", ["mujoco", "paper"])
@pytest.mark.parametrize("controller,boat,task", OWN_TASK)
def test_controller_runs_its_task(controller, boat, task, world):
    env = suite.load(boat, task, world, seed=0, time_limit=60.0)
    policy = sweep.make_controller(controller, env)
    policy.reset(0)
    timestep = env.reset()
    spec = env.action_spec()
    steps = 0
    while not timestep.last():
        action = policy(timestep)
        assert np.all(np.isfinite(action)) and action.shape == (2,)
        assert np.all(action >= spec.minimum - 1e-5) and np.all(action <= spec.maximum + 1e-5)
        timestep = env.step(action)
        steps += 1
    metrics = env.task.metrics()
    assert metrics["stopped"] is None
    assert metrics["duration"] == pytest.approx(60.0)
    assert steps == 600
    # it sailed: the boat moved more than a few metres from where it started
    position = timestep.observation["position"]
    start = env.task.start if task == "position_keeping" else np.zeros(2)
    assert np.linalg.norm(position - start) > 5.0
