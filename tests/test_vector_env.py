"""The Gymnasium VectorEnv over the batch: each sub-environment is the SailGymEnv of its seed;
make_vec reaches it through the ids' vector_entry_point; its infos follow Gymnasium's vector
convention (an array per key, a boolean ``_key`` mask of the environments that have it)."""

from __future__ import annotations

import gymnasium
import numpy as np
import pytest

from sailmujoco.gym import SailGymEnv, SailVectorEnv


def test_each_sub_environment_is_the_single_env_of_its_seed_with_next_step_autoreset():
    """Three seeds of the robot's 0.3 s speed trial under the same random actions: rewards and
    observations equal the single environments' (seeds 5, 6, 7); the episode ends after 3
    steps (truncated: the time limit), and the 4th step returns the reset state with reward 0."""
    vector = SailVectorEnv("saoud_robot", "speed_trial", num_envs=3, time_limit=0.3,
                           include_true_state=True)
    singles = [SailGymEnv("saoud_robot", "speed_trial", time_limit=0.3, include_true_state=True)
               for _ in range(3)]
    obs, _ = vector.reset(seed=5)
    firsts = [env.reset(seed=5 + i)[0] for i, env in enumerate(singles)]
    for i, first in enumerate(firsts):
        assert obs["heading"][i] == first["heading"]
    rng = np.random.default_rng(0)
    for k in range(4):
        actions = np.column_stack([rng.uniform(-0.3, 0.3, 3), rng.uniform(0.0, 1.0, 3)])
        obs, rewards, terminated, truncated, info = vector.step(actions)
        if k < 3:
            for i, env in enumerate(singles):
                o, r, te, tr, single_info = env.step(actions[i])
                assert rewards[i] == r and terminated[i] == te and truncated[i] == tr
                assert np.array_equal(obs["position"][i], o["position"])
                assert np.array_equal(obs["true_state_sail_wrench"][i], o["true_state_sail_wrench"])
                assert info["reward_terms"]["speed"][i] == single_info["reward_terms"]["speed"]
            assert info["_reward_terms"].all() and info["reward_terms"]["_speed"].all()
        assert list(truncated) == ([True] * 3 if k == 2 else [False] * 3)
        assert not terminated.any()
        if k == 2:  # every episode ended: its metrics, masked in
            assert info["_metrics"].all() and info["metrics"]["_max_heel"].all()
            for i, env in enumerate(singles):
                assert info["metrics"]["max_heel"][i] == env.unwrapped_dm_env.task.metrics()["max_heel"]
        else:
            assert "metrics" not in info
    # the step after the end: the first observation again, reward 0, no flag, no info
    assert np.all(rewards == 0.0) and np.all(obs["true_state_time"] == 0.0)
    assert info == {}


def test_make_vec_reaches_the_native_vector_env():
    """vectorization_mode="vector_entry_point" builds a SailVectorEnv; the id's
    max_episode_steps, or a smaller one given, truncates its episodes."""
    vector = gymnasium.make_vec("sailmujoco/SaoudRobot-SpeedTrial-v0", num_envs=2,
                                vectorization_mode="vector_entry_point", max_episode_steps=4)
    assert isinstance(vector.unwrapped, SailVectorEnv)
    assert vector.metadata["autoreset_mode"] == gymnasium.vector.AutoresetMode.NEXT_STEP
    assert vector.single_action_space == gymnasium.spaces.Box(-1.0, 1.0, (2,), np.float32)
    vector.reset(seed=0)
    ends = [vector.step(np.zeros((2, 2)))[3].tolist() for _ in range(4)]
    assert ends == [[False, False]] * 3 + [[True, True]]
    default = gymnasium.make_vec("sailmujoco/SaoudRobot-SpeedTrial-v0", num_envs=2,
                                 vectorization_mode="vector_entry_point")
    assert all(env.max_steps() == 600 for env in default.unwrapped.batch.envs)


def test_the_vector_env_refuses_bad_sizes_in_one_line():
    with pytest.raises(ValueError, match="num_envs must be an integer >= 1"):
        SailVectorEnv("saoud_robot", "speed_trial", num_envs=0)
    with pytest.raises(ValueError, match=r"seeds must be one per environment \(2\)"):
        SailVectorEnv("saoud_robot", "speed_trial", num_envs=2, seeds=[1])
    vector = SailVectorEnv("saoud_robot", "speed_trial", num_envs=2)
    vector.reset()
    with pytest.raises(ValueError, match=r"actions must have shape \(2, 2\)"):
        vector.step(np.zeros((3, 2)))
