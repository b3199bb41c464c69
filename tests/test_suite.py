"""Every (boat, task, world) of the suite: specs, finite observations, determinism by seed,
no constant observation, randomised initial state; rewards are the sum of their terms."""

import numpy as np
import pytest
from dm_env import StepType

from sailmujoco import suite

STEPS = 6


def _flat(observation, prefix=""):
    for key, value in observation.items():
        if isinstance(value, dict):
            yield from _flat(value, prefix + key + ".")
        else:
            yield prefix + key, value if hasattr(value, "dtype") and not isinstance(
                value, np.ndarray) else np.asarray(value, dtype=float)


def _run(boat, task, world, seed):
    env = suite.load(boat, task, world, seed=seed, time_limit=(STEPS - 0.5) * 0.1)
    spec = env.action_spec()
    action = np.clip([0.05, -0.4], spec.minimum, spec.maximum)
    timesteps = [env.reset()]
    while not timesteps[-1].last():
        timesteps.append(env.step(action))
    return env, timesteps


@pytest.mark.parametrize("boat,task,world", suite.SUITE)
def test_environment(boat, task, world):
    env, timesteps = _run(boat, task, world, seed=3)
    assert timesteps[0].step_type == StepType.FIRST
    assert timesteps[-1].step_type == StepType.LAST
    assert len(timesteps) == STEPS + 1
    # observations match their spec and are finite
    spec = dict(_flat(env.observation_spec()))
    for ts in timesteps:
        flat = dict(_flat(ts.observation))
        assert flat.keys() == spec.keys()
        for key, value in flat.items():
            assert value.shape == spec[key].shape, key
            assert np.all(np.isfinite(value)), key
    # the reward is the sum of its named terms
    terms = env.task.reward_terms(env.physics, timesteps[-1].observation)
    assert timesteps[-1].reward == pytest.approx(sum(terms.values()))
    # something moves: position and time are not constant
    first, last = dict(_flat(timesteps[1].observation)), dict(_flat(timesteps[-1].observation))
    assert not np.allclose(first["position"], last["position"])
    assert not np.allclose(first["true_state.time"], last["true_state.time"])
    # same seed, same episode bit for bit; another seed, another initial state
    _, again = _run(boat, task, world, seed=3)
    for a, b in zip(timesteps, again, strict=True):
        for (ka, va), (kb, vb) in zip(_flat(a.observation), _flat(b.observation), strict=True):
            assert ka == kb and np.array_equal(va, vb), ka
    _, other = _run(boat, task, world, seed=4)
    assert dict(_flat(other[0].observation))["heading"] != dict(_flat(timesteps[0].observation))["heading"]
    assert env.task.metrics()["duration"] > 0


def test_unknown_names():
    with pytest.raises(ValueError, match="unknown task 'regatta'"):
        suite.load("wille_yacht", "regatta")
    with pytest.raises(ValueError, match="unknown world 'lake'"):
        suite.load("wille_yacht", "heading_hold", world="lake")
    with pytest.raises(ValueError, match="unknown boat 'dinghy'"):
        suite.load("dinghy", "heading_hold")
    with pytest.raises(ValueError, match="case must be one of"):
        suite.load("wille_yacht", "position_keeping", case=9)


def test_nan_action_is_refused():
    env = suite.load("wille_yacht", "heading_hold", seed=0)
    env.reset()
    with pytest.raises(ValueError, match="finite"):
        env.step(np.array([np.nan, 0.0]))


def test_gymnasium_checker_passes():
    from gymnasium.utils.env_checker import check_env

    from sailmujoco.gym import SailGymEnv

    for world in ("mujoco", "paper"):
        env = SailGymEnv("saoud_robot", "heading_hold", world, time_limit=2.0)
        check_env(env, skip_render_check=True)
        observation, _ = env.reset(seed=1)
        assert env.observation_space.contains(observation)


def test_rollout_records_each_step_with_the_action_that_led_to_it():
    """``record`` sees the reset (step 0, no action), then every step with the action just taken,
    before the controller sees it; its None rows are left out, and the episode is the default one."""

    class Counting:
        def __init__(self):
            self.calls, self.seed = 0, None

        def reset(self, seed):
            self.seed = seed

        def __call__(self, timestep):
            self.calls += 1
            return np.array([0.01 * self.calls, -0.3])

    seen = []

    def record(step, timestep, action):
        seen.append((step, controller.calls, None if action is None else float(action[0])))
        return None if step % 2 else {"step": step, "t": float(timestep.observation["true_state"]["time"])}

    env = suite.load("saoud_robot", "heading_hold", seed=3, time_limit=(STEPS - 0.5) * 0.1)
    controller = Counting()
    rows = suite.rollout(env, controller, record=record)
    assert controller.seed == 3
    n = len(seen)  # the reset and every step
    assert n > 4 and seen == [(k, k, None if k == 0 else 0.01 * k) for k in range(n)]
    assert rows["step"].tolist() == list(range(0, n, 2))
    default = suite.rollout(env, Counting())
    assert len(default) == n
    assert rows["t"].tolist() == default["t"].iloc[::2].tolist()
