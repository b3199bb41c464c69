"""The Gymnasium adapter: registered ids for every boat and task, Gymnasium's episode contract
(reset before step, and again after the end), observations inside their declared bounds, and
the normalised action space mapped linearly onto the actuators' range."""

import math
import subprocess
import sys

import gymnasium
import numpy as np
import pytest
from gymnasium.error import ResetNeeded
from gymnasium.utils.env_checker import check_env

from sailmujoco import suite
from sailmujoco.gym import SailGymEnv, gym_ids
from sailmujoco.params import BOATS, get_boat


def test_every_boat_and_task_has_a_registered_id():
    ids = gym_ids()
    assert len(ids) == len(set(ids)) == len(BOATS) * len(suite.TASKS) == 15
    assert "sailmujoco/WilleYacht-HeadingHold-v0" in ids
    assert "sailmujoco/SaoudRobot-BeamReachRoll-v0" in ids
    assert "sailmujoco/VielBoat-PositionKeeping-v0" in ids
    for boat in BOATS:
        for task in suite.TASKS:
            camel = "".join(w[0].upper() + w[1:] for w in boat.split("_")), \
                "".join(w[0].upper() + w[1:] for w in task.split("_"))
            env_id = f"sailmujoco/{camel[0]}-{camel[1]}-v0"
            assert gymnasium.spec(env_id).kwargs == {"boat": boat, "task": task}
    for env_id, boat, task in (("sailmujoco/WilleYacht-CourseHold-v0", "wille_yacht", "course_hold"),
                               ("sailmujoco/SaoudRobot-BeamReachRoll-v0", "saoud_robot", "beam_reach_roll"),
                               ("sailmujoco/VielBoat-PositionKeeping-v0", "viel_boat", "position_keeping")):
        env = gymnasium.make(env_id, time_limit=0.2)
        dm_env = env.unwrapped.unwrapped_dm_env
        assert (dm_env.physics.params.name, dm_env.task.name) == (boat, task)
        observation, _ = env.reset(seed=0)
        assert env.observation_space.contains(observation)


def test_world_and_options_pass_through_make():
    env = gymnasium.make("sailmujoco/WilleYacht-HeadingHold-v0", world="paper", time_limit=0.2)
    assert type(env.unwrapped.unwrapped_dm_env.physics).__name__ == "PaperPhysics"


def test_module_prefixed_id_works_without_importing_the_adapter():
    code = ("import gymnasium\n"
            "env = gymnasium.make('sailmujoco.gym:sailmujoco/SaoudRobot-SpeedTrial-v0', time_limit=0.2)\n"
            "env.reset(seed=0)\nprint(env.unwrapped.unwrapped_dm_env.task.name)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "speed_trial"


def test_step_before_reset_raises():
    with pytest.raises(ResetNeeded, match="reset"):
        SailGymEnv("saoud_robot", "heading_hold", time_limit=1.0).step(np.zeros(2))
    with pytest.raises(ResetNeeded):  # gymnasium.make's order-enforcing wrapper says it first
        gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0").step(np.zeros(2))


@pytest.mark.parametrize("make", [
    lambda: SailGymEnv("saoud_robot", "heading_hold", time_limit=0.25),
    lambda: gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", time_limit=0.25),
])
def test_step_after_truncation_raises_until_reset(make):
    env = make()
    env.reset(seed=0)
    ends = [env.step(np.zeros(2))[2:4] for _ in range(3)]  # 0.25 s at 0.1 s a step: 3 steps
    assert ends == [(False, False), (False, False), (False, True)]
    with pytest.raises(ResetNeeded, match="terminated or truncated"):
        env.step(np.zeros(2))
    env.reset()
    assert env.step(np.zeros(2))[2:4] == (False, False)


def test_step_after_termination_raises():
    env = SailGymEnv("saoud_robot", "heading_hold", time_limit=60.0)
    env.reset(seed=0)
    # 500 N m of heeling moment on a 15 kg robot: it capsizes within seconds
    env.unwrapped_dm_env.physics.set_external_wrench([0.0, 0.0, 0.0, 500.0, 0.0, 0.0])
    for _ in range(600):
        _, _, terminated, truncated, info = env.step(np.zeros(2))
        if terminated or truncated:
            break
    assert terminated and not truncated
    assert info["metrics"]["stopped"].startswith("capsized")
    with pytest.raises(ResetNeeded):
        env.step(np.zeros(2))


@pytest.mark.parametrize("boat,task,world,options", [
    ("wille_yacht", "heading_hold", "mujoco", {}),
    ("saoud_robot", "beam_reach_roll", "mujoco", {"dofs": 4}),
    ("saoud_robot", "speed_trial", "paper", {}),
    ("viel_boat", "position_keeping", "paper", {}),
])
def test_observations_stay_in_the_declared_space(boat, task, world, options):
    env = SailGymEnv(boat, task, world, time_limit=8.0, normalize_action=True, **options)
    space = env.observation_space
    assert (space["heading"].low, space["heading"].high) == (-math.pi, math.pi)
    assert space["apparent_wind_speed"].low == 0.0 and space["true_state"]["time"].low == 0.0
    assert space["true_state"]["wind_speed_10"].high == 100.0
    # heel is an Euler angle in MuJoCo; the paper worlds integrate it unwrapped: no bound there
    assert np.isinf(space["heel"].high) == (world == "paper")
    assert np.isinf(space["position"].low).all()
    env.action_space.seed(7)
    observation, _ = env.reset(seed=3)
    observations = [observation]
    done = False
    while not done:
        observation, _, terminated, truncated, _ = env.step(env.action_space.sample())
        observations.append(observation)
        done = terminated or truncated
    assert len(observations) > 60
    for observation in observations:
        assert space.contains(observation)
    # the episode did wander: the bounded angles are not all at one value
    assert np.ptp([float(o["apparent_wind_angle"]) for o in observations]) > 0.05


def test_normalised_action_maps_onto_the_actuator_range():
    env = SailGymEnv("wille_yacht", "heading_hold", normalize_action=True, time_limit=5.0)
    assert (env.action_space.low.tolist(), env.action_space.high.tolist()) == ([-1, -1], [1, 1])
    # the actuators' range is the boat's rudder and sail limits (MJCF keeps 6 digits of them)
    rudder_max, sail_max = env.unwrapped_dm_env.physics.model.actuator_ctrlrange[:, 1]
    assert rudder_max == pytest.approx(get_boat("wille_yacht").rudder.max_angle, rel=1e-5)
    assert sail_max == pytest.approx(get_boat("wille_yacht").sail.max_angle, rel=1e-5)
    env.reset(seed=0)
    ctrl = env.unwrapped_dm_env.physics.data.ctrl
    for action, expected in (([-1.0, 1.0], [-rudder_max, sail_max]), ([1.0, -1.0], [rudder_max, -sail_max]),
                             ([0.0, 0.0], [0.0, 0.0]), ([0.5, -0.25], [rudder_max / 2, -sail_max / 4]),
                             ([3.0, -7.0], [rudder_max, -sail_max])):  # outside [-1, 1]: clipped
        env.step(np.array(action))
        np.testing.assert_allclose(ctrl, expected, rtol=1e-15, atol=1e-15)
    # Viel's paper boat: |delta_r| <= pi/4, |delta_s| <= pi/2 (Viel 2019 §2.1)
    viel = SailGymEnv("viel_boat", "position_keeping", "paper", normalize_action=True)
    viel.reset(seed=0)
    observation = viel.step(np.array([-1.0, 1.0]))[0]["true_state"]
    assert (float(observation["rudder"]), float(observation["sail"])) == pytest.approx(
        (-math.pi / 4, math.pi / 2), abs=1e-15)


def test_sheeted_sail_normalised_spans_the_sheet():
    env = SailGymEnv("wille_yacht", "heading_hold", sail_mode="sheeted", normalize_action=True)
    raw = SailGymEnv("wille_yacht", "heading_hold", sail_mode="sheeted")
    low, high = raw.action_space.low, raw.action_space.high
    assert high[1] > low[1] > 0.0  # a sheet length, m
    np.testing.assert_array_equal(env.actuator_command([-1.0, -1.0]), low)
    np.testing.assert_array_equal(env.actuator_command([1.0, 1.0]), high)


def test_normalize_action_must_be_a_bool():
    with pytest.raises(ValueError, match="normalize_action must be True or False, got 'yes'"):
        SailGymEnv(normalize_action="yes")


def test_gymnasium_checker_passes_with_normalised_actions():
    env = SailGymEnv("wille_yacht", "course_hold", normalize_action=True, time_limit=2.0)
    check_env(env, skip_render_check=True)


def test_physics_options_reach_the_environment_and_a_reset_changes_one():
    """physics= (or a field by name) goes to suite.load; reset(options=...) with one physics
    field keeps the others given in physics=."""
    env = SailGymEnv("saoud_robot", "heading_hold", physics={"dofs": 4, "windage": False})
    physics = env.unwrapped_dm_env.physics
    assert physics.dofs == 4 and not physics.switches.windage
    env.reset(seed=1, options={"hydrostatics": "paper"})
    physics = env.unwrapped_dm_env.physics
    assert (physics.dofs, physics.switches.windage, physics.switches.hydrostatics) == (4, False, "paper")
    flat = SailGymEnv("saoud_robot", "heading_hold", dofs=4)
    flat.reset(options={"hydrostatics": "paper"})
    assert flat.unwrapped_dm_env.physics.dofs == 4
    assert flat.unwrapped_dm_env.physics.switches.hydrostatics == "paper"
