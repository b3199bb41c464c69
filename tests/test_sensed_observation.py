"""The instruments in the loop: with ``perfect`` sensors the observation is the truth, bit for bit;
with ``typical`` ones the measured keys are the instruments' while the physics, the true state and
the record (the metrics) stay the truth's; the true-wind estimate converges in steady sailing."""

import math

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.frames import wrap_angle

MEASURED = ("position", "velocity", "heading", "heel", "roll_rate", "yaw_rate", "apparent_wind_angle",
            "apparent_wind_speed")


def _run(sensors, steps=60, seed=2, world="mujoco"):
    env = suite.load("saoud_robot", "heading_hold", world, seed=seed, wind_speed=6.0, gusts=False,
                     wander=False, **({} if sensors is None else {"sensors": sensors}))
    timesteps = [env.reset()]
    for k in range(steps):
        timesteps.append(env.step(np.array([0.05 * math.sin(0.1 * k), 0.6])))
    return env, timesteps


@pytest.mark.parametrize("world", ["mujoco", "paper"])
def test_perfect_sensors_are_the_observation_as_before_bit_for_bit(world):
    _, plain = _run(None, world=world)
    env, perfect = _run("perfect", world=world)
    assert env.task._instruments is None  # a perfect set reads nothing
    for a, b in zip(plain, perfect, strict=True):
        assert list(a.observation) == list(b.observation)
        for key in MEASURED:
            assert np.asarray(a.observation[key]).tobytes() == np.asarray(b.observation[key]).tobytes()


def test_typical_sensors_change_what_is_read_and_nothing_that_happens():
    _, perfect = _run("perfect")
    env, typical = _run("typical")
    for a, b in zip(perfect[1:], typical[1:], strict=True):  # the same commands: the same boat
        for key, value in a.observation["true_state"].items():
            assert np.asarray(value).tobytes() == np.asarray(b.observation["true_state"][key]).tobytes(), key
        assert a.reward == b.reward
    heading_error = [float(wrap_angle(b.observation["heading"] - a.observation["heading"]))
                     for a, b in zip(perfect[1:], typical[1:], strict=True)]
    assert 0.005 < np.std(heading_error) < 0.1  # 2 deg of compass noise (0.035 rad) and the tilt's error
    gnss = np.array([b.observation["position"] - a.observation["position"]
                     for a, b in zip(perfect, typical, strict=True)])
    assert np.all(np.abs(gnss) < 15.0) and np.any(gnss != 0.0)  # metres, a 2.5 m CEP receiver
    assert {"speed_through_water", "true_wind_estimate"} <= set(typical[-1].observation)
    assert env.task.metrics()["steady_speed"] == pytest.approx(
        _run("perfect")[0].task.metrics()["steady_speed"], abs=0.0)  # the metrics are the truth's


def test_the_same_seed_reads_the_same_and_a_new_episode_new_noise():
    _, first = _run("typical", steps=10)
    _, again = _run("typical", steps=10)
    headings = [t.observation["heading"].tobytes() for t in first]
    assert headings == [t.observation["heading"].tobytes() for t in again]
    env, _ = _run("typical", steps=10)
    second = env.reset()
    assert second.observation["position"].tobytes() != first[0].observation["position"].tobytes()


def test_true_wind_estimate_converges_in_steady_sailing():
    # steady wind from 080 deg, the boat sailing; the vane reads the air at the masthead (below
    # the 10 m reference, where the wind's profile is slower), and the triangle neglects the heel
    # and the mast's motion (as ArduPilot's does), a few per cent at the robot's heel: within
    # 3 % of the wind at the masthead and 3 deg of its direction
    env, timesteps = _run("typical", steps=600)
    physics = env.physics
    masthead = float(physics.data.site("masthead").xpos[2])
    wind = physics.wind.velocity(physics.time(), masthead)
    speed, direction = timesteps[-1].observation["true_wind_estimate"]
    assert speed == pytest.approx(math.hypot(wind[0], wind[1]), rel=0.03)
    assert speed < 6.0  # the 10 m wind is not what the masthead feels
    assert abs(math.degrees(float(wrap_angle(direction - math.radians(80.0))))) < 3.0


def test_a_bad_sensor_option_is_one_line():
    with pytest.raises(ValueError, match="sensors must be one of"):
        suite.load("saoud_robot", "heading_hold", sensors="exact")
    with pytest.raises(ValueError, match="sensors.gnss_cep must be a finite number >= 0"):
        suite.load("saoud_robot", "heading_hold", sensors={"gnss_cep": -2.0})


def test_gymnasium_takes_the_instruments_and_declares_their_keys():
    import gymnasium
    from gymnasium.utils.env_checker import check_env

    import sailmujoco.gym  # noqa: F401  (registers the ids)

    env = gymnasium.make("sailmujoco/SaoudRobot-HeadingHold-v0", sensors="typical")
    check_env(env.unwrapped, skip_render_check=True)
    observation, _ = env.reset(seed=1)
    assert observation["true_wind_estimate"].shape == (2,)
    assert observation["speed_through_water"].shape == (1,)
    assert env.observation_space.contains(observation)


def test_a_sweep_takes_the_figures_as_namespaces():
    from sailmujoco.sweep.errors import SweepError
    from sailmujoco.sweep.runs import execute
    from sailmujoco.sweep.spec import expand, validate

    base = {"name": "s", "boat": "saoud_robot", "task": "heading_hold", "controller": "saoud",
            "duration": 3.0}
    plain = expand(validate(base))[0]
    run = expand(validate({**base, "options": {"sensors.preset": "typical", "sensors.compass_noise_deg": 4.0,
                                               "actuators.preset": "typical"}}))[0]
    assert run["task_options"] == {"sensors": {"preset": "typical", "compass_noise_deg": 4.0},
                                   "actuators": {"preset": "typical"}}
    assert "sensors_options" not in plain and plain["task_options"] == {}  # a plain run: as before
    record = execute(run)
    assert record["status"] == "ok", record["error"]
    with pytest.raises(SweepError, match="give the sensors once"):
        validate({**base, "options": {"sensors.preset": "typical", "task.sensors": "typical"}})
