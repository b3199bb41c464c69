"""The Gymnasium adapter: registered ids for every boat and task, Gymnasium's checker silent on
every one, Gymnasium's episode contract (reset before step, and again after the end),
observations inside their declared finite bounds, and the normalised action space mapped
linearly onto the actuators' range."""

import math
import subprocess
import sys
import warnings

import gymnasium
import numpy as np
import pytest
from gymnasium.error import ResetNeeded
from gymnasium.utils.env_checker import check_env

from sailmujoco import suite
from sailmujoco.boat.catalogue import BOATS, get_boat
from sailmujoco.gym import SailGymEnv, gym_ids


def test_every_boat_and_task_has_a_registered_id():
    ids = gym_ids()
    assert len(ids) == len(set(ids)) == len(BOATS) * len(suite.TASKS) == 36
    assert "sailmujoco/WilleYacht-HeadingHold-v0" in ids
    assert "sailmujoco/SaoudRobot-BeamReachRoll-v0" in ids
    assert "sailmujoco/VielBoat-PositionKeeping-v0" in ids
    assert "sailmujoco/ElevenMetre-UpwindDownwind-v0" in ids
    for boat in BOATS:
        for task in suite.TASKS:
            camel = "".join(w[0].upper() + w[1:] for w in boat.split("_")), \
                "".join(w[0].upper() + w[1:] for w in task.split("_"))
            env_id = f"sailmujoco/{camel[0]}-{camel[1]}-v0"
            spec = gymnasium.spec(env_id)
            assert spec.kwargs == {"boat": boat, "task": task}
            # the task's duration at 0.1 s a step: 60 s -> 600, 200 s -> 2000, 300 s -> 3000, 600 s -> 6000
            assert spec.max_episode_steps == {"heading_hold": 600, "speed_trial": 600,
                                              "course_hold": 2000, "position_keeping": 2000,
                                              "beam_reach_roll": 3000, "upwind_downwind": 6000,
                                              "precision_navigation": 6000, "station_keeping": 6000,
                                              "area_scanning": 9000}[task]
            assert spec.vector_entry_point == "sailmujoco.gym:SailVectorEnv"
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


@pytest.mark.parametrize("env_id", gym_ids())
def test_gymnasium_checker_is_silent_on_every_id(env_id):
    """check_env with every warning an error, the rgb_array render check included; the episode
    length the id registers is the environment's own."""
    env = gymnasium.make(env_id)
    assert env.unwrapped.unwrapped_dm_env.max_steps() == env.spec.max_episode_steps
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)
    space = env.observation_space
    for key, box in space.spaces.items():
        assert box.dtype == np.float32 and np.isfinite(box.low).all() and np.isfinite(box.high).all(), key
        assert len(box.shape) == 1, key  # no 0-d Box: SB3 reads every key as a 1-D vector
    assert not any(key.startswith("true_state") for key in space.spaces)


def test_gymnasium_checker_is_silent_with_the_true_state():
    """The privileged state's keys are flat, 1-D and bounded too (SB3 refuses nested Dicts)."""
    env = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", include_true_state=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_env(env.unwrapped)
    for key, box in env.observation_space.spaces.items():
        assert isinstance(box, gymnasium.spaces.Box) and len(box.shape) == 1, key
        assert np.isfinite(box.low).all() and np.isfinite(box.high).all(), key


@pytest.mark.parametrize("boat,task,world,options", [
    ("wille_yacht", "heading_hold", "mujoco", {}),
    ("saoud_robot", "beam_reach_roll", "mujoco", {"dofs": 4}),
    ("saoud_robot", "speed_trial", "paper", {}),
    ("viel_boat", "position_keeping", "paper", {}),
])
def test_observations_stay_in_the_declared_space(boat, task, world, options):
    env = SailGymEnv(boat, task, world, time_limit=8.0, include_true_state=True, **options)
    space = env.observation_space
    assert (space["heading"].low, space["heading"].high) == (np.float32(-math.pi), np.float32(math.pi))
    assert space["apparent_wind_speed"].low == 0.0 and space["true_state_time"].low == 0.0
    # the wind's accepted range, one limit for the tasks and the wind model
    assert space["true_state_wind_speed_10"].high == 100.0
    assert (space["position"].low == -5000.0).all() and (space["position"].high == 5000.0).all()
    # a force wrench is bounded by twice the water's dynamic pressure at 50 m/s on the hull's
    # length squared, a moment by that force times the length
    length = get_boat(boat).hull.length  # 8.8, 1.5 and 4 m
    force = 1025.0 * 50.0**2 * length**2
    np.testing.assert_allclose(space["true_state_sail_wrench"].high, [force] * 3 + [force * length] * 3,
                               rtol=1e-6)
    for key, box in space.spaces.items():  # every key bounded, none 0-d, none nested
        assert len(box.shape) == 1 and np.isfinite(box.low).all() and np.isfinite(box.high).all(), key
    env.action_space.seed(7)
    observation, _ = env.reset(seed=3)
    observations = [observation]
    done = False
    while not done:
        observation, _, terminated, truncated, info = env.step(env.action_space.sample())
        observations.append(observation)
        done = terminated or truncated
    # Viel's 3-DOF model spins up when random rudder drives it backwards (its yaw damping turns
    # destabilising at negative surge): that episode leaves the rates' bound and ends there,
    # its last observation clipped onto the bound
    stopped = info["metrics"]["stopped"]
    if (boat, world) == ("viel_boat", "paper"):
        assert terminated and stopped.startswith("left the observation bounds (yaw_rate")
        assert abs(observations[-1]["yaw_rate"][0]) == np.float32(25.0)
    else:
        assert truncated and stopped is None and len(observations) == 81
    assert len(observations) > 10
    for observation in observations:
        assert space.contains(observation)
    # the episode did wander: the bounded angles are not all at one value
    assert np.ptp([o["apparent_wind_angle"][0] for o in observations]) > 0.05


def test_the_true_state_is_left_out_unless_asked_for():
    """By default the observation is what the boat's sensors give (10 numbers and the task's
    reference); include_true_state adds the 58 numbers of the full state."""
    plain = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0")
    full = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", include_true_state=True)
    assert not any(key.startswith("true_state") for key in plain.observation_space.spaces)
    assert full.observation_space["true_state_sail_wrench"].shape == (6,)
    assert full.observation_space["true_state_u"].shape == (1,)
    flat_plain = gymnasium.wrappers.FlattenObservation(plain)
    flat_full = gymnasium.wrappers.FlattenObservation(full)
    # position 2, velocity 2, heading, heel, roll and yaw rates, apparent wind angle and speed;
    # desired_heading
    assert flat_plain.observation_space.shape == (10 + 1,)
    # 13 scalars, true wind 2, wind speed and direction, apparent wind 2, current 2, time,
    # six wrenches of 6
    assert flat_full.observation_space.shape == (11 + 13 + 2 + 2 + 2 + 2 + 1 + 36,)
    first_plain, _ = flat_plain.reset(seed=4)
    first_full, _ = flat_full.reset(seed=4)
    assert flat_plain.observation_space.contains(first_plain)
    # the same episode: the sensors' numbers are the same with or without the true state
    a = plain.unwrapped.unwrapped_dm_env.task.last_observation
    b = full.unwrapped.unwrapped_dm_env.task.last_observation
    assert float(a["heading"]) == float(b["heading"])


def test_angle_references_are_wrapped_into_their_bounds():
    """A desired heading of 270 deg is handed out as -90 deg (its bounds are [-pi, pi])."""
    env = SailGymEnv("saoud_robot", "heading_hold", desired_heading_deg=270.0, time_limit=0.3)
    observation, _ = env.reset(seed=0)
    assert observation["desired_heading"][0] == pytest.approx(-math.pi / 2, abs=1e-6)
    assert env.observation_space.contains(observation)


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
    viel.step(np.array([-1.0, 1.0]))
    observation = viel.unwrapped_dm_env.task.last_observation["true_state"]  # float64
    assert (float(observation["rudder"]), float(observation["sail"])) == pytest.approx(
        (-math.pi / 4, math.pi / 2), abs=1e-15)


def test_sheeted_sail_normalised_spans_the_sheet():
    env = SailGymEnv("wille_yacht", "heading_hold", sail_mode="sheeted", normalize_action=True)
    raw = SailGymEnv("wille_yacht", "heading_hold", sail_mode="sheeted", normalize_action=False)
    spec = raw.unwrapped_dm_env.action_spec()
    low, high = spec.minimum, spec.maximum
    assert high[1] > low[1] > 0.0  # a sheet length, m
    assert raw.action_space.high[1] == np.float32(high[1])
    np.testing.assert_array_equal(env.actuator_command([-1.0, -1.0]), low)
    np.testing.assert_array_equal(env.actuator_command([1.0, 1.0]), high)


def test_normalize_action_must_be_a_bool():
    with pytest.raises(ValueError, match="normalize_action must be True or False, got 'yes'"):
        SailGymEnv(normalize_action="yes")


def test_the_default_action_space_is_normalised():
    env = gymnasium.make("sailmujoco/WilleYacht-CourseHold-v0")
    assert env.action_space == gymnasium.spaces.Box(-1.0, 1.0, (2,), np.float32)
    raw = gymnasium.make("sailmujoco/WilleYacht-CourseHold-v0", normalize_action=False)
    rudder_max = get_boat("wille_yacht").rudder.max_angle
    assert raw.action_space.high[0] == pytest.approx(rudder_max, rel=1e-6)


def test_options_that_shape_the_spaces_are_fixed_at_construction():
    env = SailGymEnv("saoud_robot", "heading_hold", time_limit=1.0)
    with pytest.raises(ValueError, match="cannot change time_limit"):
        env.reset(options={"time_limit": 5.0})


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
