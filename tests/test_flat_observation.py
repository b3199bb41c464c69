"""dm_control's flat observation: ``dm_control.rl.control.flatten_observation`` flattens the
suite's observation, ``flat_observation=True`` gives it at every step (a stop included), and
``include_true_state=False`` leaves the privileged state out; the full-state controllers still
read ``true_state`` by name."""

import numpy as np
import pytest
from dm_control.rl.control import flatten_observation

from sailmujoco import suite
from sailmujoco.forces.wind import MAX_SPEED, WindConfig
from sailmujoco.measurement.observation import TrueState

# heading_hold: position 2, velocity 2, six scalars, desired_heading; true_state: 13 scalars,
# true wind 2, wind speed and direction, apparent wind at the CE 2, current 2, time, 6 wrenches of 6
SENSED = 2 + 2 + 6 + 1
FULL = 13 + 2 + 2 + 2 + 2 + 1 + 6 * 6


def _by_hand(observation) -> np.ndarray:
    """dm_control's layout, built independently: keys sorted (a plain dict), each entry raveled,
    true_state's entries in its own order."""
    parts = []
    for key in sorted(observation):
        value = observation[key]
        if isinstance(value, dict):
            parts.extend(np.ravel(np.asarray(v, dtype=float)) for v in value.values())
        else:
            parts.append(np.ravel(np.asarray(value, dtype=float)))
    return np.concatenate(parts)


@pytest.mark.parametrize("world", ["mujoco", "paper"])
def test_flatten_observation_flattens_the_suite_observation(world):
    env = suite.load("saoud_robot", "heading_hold", world, seed=0, time_limit=1.0)
    timestep = env.reset()
    timestep = env.step([0.1, 0.4])
    flat = flatten_observation(timestep.observation)
    assert list(flat) == ["observations"]
    assert flat["observations"].shape == (SENSED + FULL,)
    np.testing.assert_array_equal(flat["observations"], _by_hand(timestep.observation))
    state = timestep.observation["true_state"]
    assert isinstance(state, TrueState) and float(state["u"]) == float(state.ravel()[state.layout()["u"]][0])


def test_flat_observation_at_every_step_including_a_capsize():
    """flat_observation=True: the same numbers as flattening by hand, every step, and a single
    'observations' spec of their length; the capsize's last step too."""
    flat_env = suite.load("saoud_robot", "heading_hold", seed=2, flat_observation=True)
    env = suite.load("saoud_robot", "heading_hold", seed=2)
    spec = flat_env.observation_spec()
    assert list(spec) == ["observations"] and spec["observations"].shape == (SENSED + FULL,)
    a, b = flat_env.reset(), env.reset()
    np.testing.assert_array_equal(a.observation["observations"], _by_hand(b.observation))
    for e in (flat_env, env):
        e.physics.set_external_wrench([0.0, 0.0, 0.0, 500.0, 0.0, 0.0])
    while not a.last():
        a, b = flat_env.step([0.0, 0.0]), env.step([0.0, 0.0])
        np.testing.assert_array_equal(a.observation["observations"], _by_hand(b.observation))
    assert a.discount == 0.0 and flat_env.task.metrics()["stopped"].startswith("capsized")


def test_include_true_state_false_leaves_it_out_of_the_dm_control_observation():
    env = suite.load("viel_boat", "position_keeping", "paper", seed=0, include_true_state=False,
                     flat_observation=True)
    # position 2, velocity 2, six scalars, target_position 2
    assert env.reset().observation["observations"].shape == (2 + 2 + 6 + 2,)
    plain = suite.load("viel_boat", "position_keeping", "paper", seed=0, include_true_state=False)
    assert "true_state" not in plain.reset().observation
    with pytest.raises(ValueError, match="include_true_state must be True or False"):
        suite.load("viel_boat", "position_keeping", "paper", include_true_state="no")


def test_the_wind_limit_is_one_number():
    """The tasks accept every wind the wind model does, up to MAX_SPEED = 100 m/s, and refuse
    more in one line naming the option."""
    assert MAX_SPEED == 100.0
    WindConfig(speed=100.0)
    env = suite.load("saoud_robot", "speed_trial", wind_speed=100.0, time_limit=0.1)
    assert float(env.reset().observation["true_state"]["wind_speed_10"]) == 100.0
    with pytest.raises(ValueError, match=r"^wind_speed must be a finite number >= 0 and <= 100 m/s"):
        suite.load("saoud_robot", "speed_trial", wind_speed=100.5)
    with pytest.raises(ValueError, match="between 0 and 100 m/s"):
        WindConfig(speed=100.5)
