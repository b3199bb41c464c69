"""The reward: ending an episode early (capsize, leaving the area) is never worth more than
sailing on, and every step's reward is the sum of its named terms.

The floors below come from the reward's definition, not from the code: beam_reach_roll's speed
term max(u, -U10)/U10 is >= -1 and its heel term -(phi/10 deg)^2 >= -(90/10)^2 = -81 while the
boat is upright (|phi| > 90 deg ends the episode); heading_hold's heading term -(e/pi)^2 >= -1
and its rudder term -0.01 (sigma/0.6)^2 >= -0.01 (pi/0.6)^2 for any hinge angle.
"""

import math

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.gym import SailGymEnv

BEAM_REACH_FLOOR = -1.0 - 81.0
HEADING_HOLD_FLOOR = -1.0 - 0.01 * (math.pi / 0.6) ** 2


def _episode(env, action, seed=0):
    env.reset(seed=seed)
    rewards, infos = [], []
    while True:
        _, reward, terminated, truncated, info = env.step(np.asarray(action, dtype=np.float32))
        rewards.append(reward)
        infos.append(info)
        if terminated or truncated:
            return rewards, infos, terminated


def test_a_policy_that_capsizes_earns_less_than_one_that_sails_on():
    """The robot on a beam reach in 36 m/s of wind, 30 s (300 steps): with the sail eased to 90
    deg it capsizes within seconds; sheeted in, it heels past 60 deg and sails on, every step
    costing dearly (heel term down to -72). Sailing on still earns more: the capsize step costs
    (floor - 1) for itself and each of the steps the episode had left."""
    env = SailGymEnv("saoud_robot", "beam_reach_roll", wind_speed=36.0, time_limit=30.0)
    capsized, capsize_infos, terminated = _episode(env, [0.0, 0.5])  # sail +pi/2
    assert terminated and capsize_infos[-1]["metrics"]["stopped"].startswith("capsized")
    k = len(capsized)
    assert k < 60
    assert capsized[-1] == (300 - k + 1) * (BEAM_REACH_FLOOR - 1.0)
    assert capsize_infos[-1]["reward_terms"] == {"stopped": capsized[-1]}

    sailed, sail_infos, terminated = _episode(env, [0.0, 0.0])  # sail at 0: sheeted in
    assert not terminated and len(sailed) == 300
    assert sail_infos[-1]["metrics"]["stopped"] is None
    assert max(abs(i["reward_terms"]["heel"]) for i in sail_infos) > 30.0  # heeled past 55 deg
    assert min(sailed) >= BEAM_REACH_FLOOR
    assert sum(sailed) < 0.0
    assert sum(capsized) < sum(sailed)
    # even had the capsizing policy then sailed on at the floor it would have done better
    assert sum(capsized) < sum(capsized[:-1]) + (300 - k + 1) * BEAM_REACH_FLOOR


def test_the_dm_control_episode_carries_the_same_stop_reward():
    """suite.load's environment: a capsize forced by a heeling moment on the robot, heading_hold
    (600 steps); the last step's reward is the stop reward, no longer 0."""
    env = suite.load("saoud_robot", "heading_hold", seed=0)
    env.reset()
    env.physics.set_external_wrench([0.0, 0.0, 0.0, 500.0, 0.0, 0.0])
    steps = 0
    while True:
        timestep = env.step([0.0, 0.0])
        if timestep.last():
            break
        steps += 1
    assert timestep.discount == 0.0 and env.task.metrics()["stopped"].startswith("capsized")
    assert timestep.reward == pytest.approx((600 - steps) * (HEADING_HOLD_FLOOR - 1.0), rel=1e-12)


def test_leaving_the_area_ends_the_episode_with_the_stop_reward():
    """A sailing area 3 m either side of the start: the robot, sailing north, leaves it; the episode ends
    there (terminated), the last observation is clipped onto the area's edge."""
    env = SailGymEnv("saoud_robot", "speed_trial", area=3.0)
    rewards, infos, terminated = _episode(env, [0.0, 0.5])
    assert terminated and infos[-1]["metrics"]["stopped"].startswith("left the sailing area")
    k = len(rewards)
    assert k < 600
    assert rewards[-1] == (600 - k + 1) * (0.0 - 1.0)  # speed_trial's floor: |v| / U10 >= 0
    position = env.unwrapped_dm_env.task.last_observation["position"]
    assert np.abs(position).max() > 3.0  # outside; the observation handed out is on the edge


@pytest.mark.parametrize("boat,task,world,options", [
    ("saoud_robot", "heading_hold", "mujoco", {}),
    ("wille_yacht", "course_hold", "paper", {}),
    ("saoud_robot", "beam_reach_roll", "mujoco", {"wind_speed": 30.0}),
    ("saoud_robot", "speed_trial", "mujoco", {}),
    ("viel_boat", "position_keeping", "paper", {}),
])
def test_the_reward_is_the_sum_of_its_named_terms(boat, task, world, options):
    env = SailGymEnv(boat, task, world, time_limit=3.0, **options)
    rewards, infos, _ = _episode(env, [0.4, 0.5])
    for reward, info in zip(rewards, infos, strict=True):
        assert reward == sum(info["reward_terms"].values())
    names = set(infos[0]["reward_terms"])
    assert names == {"heading_hold": {"heading", "rudder"}, "course_hold": {"course"},
                     "beam_reach_roll": {"speed", "heel"}, "speed_trial": {"speed"},
                     "position_keeping": {"distance"}, "upwind_downwind": {"to_go"},
                     "precision_navigation": {"to_go"}, "station_keeping": {"box"},
                     "area_scanning": {"cells"}}[task]


def test_the_reward_floors_hold_their_definitions():
    """Each task's floor is the least its terms can sum to (the module docstring's derivation);
    position_keeping's distance term stops falling at 100 target radii."""
    floors = {}
    for task in suite.TASKS:
        env = suite.load("saoud_robot", task, "paper" if task == "position_keeping" else "mujoco")
        env.reset()
        floors[task] = env.task.reward_floor(env.physics)
    assert floors == {"heading_hold": pytest.approx(HEADING_HOLD_FLOOR, rel=1e-15), "course_hold": -1.0,
                      "beam_reach_roll": BEAM_REACH_FLOOR, "speed_trial": 0.0, "position_keeping": -100.0,
                      "upwind_downwind": -100.0, "precision_navigation": -100.0, "station_keeping": -100.0,
                      "area_scanning": 0.0}
    env = suite.load("viel_boat", "position_keeping", "paper", d_target=7.0)
    env.reset()
    far = {"position": np.array([1e4, 0.0])}
    assert env.task.reward_terms(env.physics, far) == {"distance": -100.0}
    near = {"position": np.array([3.0, 4.0])}
    assert env.task.reward_terms(env.physics, near) == {"distance": -5.0 / 7.0}
