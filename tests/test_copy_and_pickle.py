"""Environments, physics (MuJoCo and paper worlds) and controllers survive ``copy.deepcopy``,
``pickle`` and ``physics.copy()``: the copy then steps bit for bit like the original, and
neither moves the other (Dask ships them between processes, RL code forks them)."""

import copy
import math
import pickle
from importlib.metadata import entry_points

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.measurement.observation import measure
from sailmujoco.physics import BoatPhysics, SimulationStopped

BEFORE, AFTER = 4, 4  # control steps before the copy, and compared after it


def _leaves(observation):
    """Every number of a nested observation, in a fixed order, as one float64 array."""
    out = []
    for key in sorted(observation):
        value = observation[key]
        out.append(_leaves(value) if isinstance(value, dict)
                   else np.asarray(value, dtype=np.float64).ravel())
    return np.concatenate(out)


def _actions(env, rng, n):
    spec = env.action_spec()
    return [rng.uniform(spec.minimum, spec.maximum) for _ in range(n)]


def _round_trips(thing):
    return {"deepcopy": copy.deepcopy(thing), "pickle": pickle.loads(pickle.dumps(thing))}


def _bits(arrays):
    return b"".join(np.ascontiguousarray(a).tobytes() for a in arrays)


ENV_CASES = ([(boat, task, world, {}) for boat, task, world in suite.SUITE if task == "heading_hold"]
             + [("viel_boat", "position_keeping", "mujoco", {}),
                ("viel_boat", "position_keeping", "paper", {}),
                ("saoud_robot", "beam_reach_roll", "mujoco", {"dofs": 4}),
                ("wille_yacht", "course_hold", "mujoco", {"sail_mode": "sheeted"})])


@pytest.mark.parametrize("boat,task,world,options", ENV_CASES)
def test_environment_copies_step_identically(boat, task, world, options):
    env = suite.load(boat, task, world, seed=5, **options)
    rng = np.random.default_rng(11)
    env.reset()
    for action in _actions(env, rng, BEFORE):
        env.step(action)
    copies = _round_trips(env)
    later = _actions(env, rng, AFTER)
    expected = [_leaves(env.step(a).observation) for a in later]
    assert env.physics.time() == pytest.approx((BEFORE + AFTER) * env.control_timestep())
    for how, other in copies.items():
        got = [_leaves(other.step(a).observation) for a in later]
        assert _bits(got) == _bits(expected), f"{how}: the copy stepped differently"
    # the copies do not share the original's state: stepped after it, they are not a step ahead
    assert copies["pickle"].physics.time() == env.physics.time()


def _world_state(physics):
    return _leaves(physics.observation() if hasattr(physics, "observation") else measure(physics))


@pytest.mark.parametrize("boat,task,world,options", ENV_CASES)
def test_physics_copy_steps_identically(boat, task, world, options):
    env = suite.load(boat, task, world, seed=2, **options)
    env.reset()
    rng = np.random.default_rng(4)
    for action in _actions(env, rng, BEFORE):
        env.step(action)
    physics = env.physics
    copies = {"copy": physics.copy(), **_round_trips(physics)}
    if isinstance(physics, BoatPhysics):
        copies["copy(share_model=True)"] = physics.copy(share_model=True)
    n_sub = round(env.control_timestep() / physics.timestep())
    later = _actions(env, rng, AFTER)
    expected = []
    for action in later:
        physics.set_control(action)
        physics.step(n_sub)
        expected.append(_world_state(physics))
    for how, other in copies.items():
        got = []
        for action in later:
            other.set_control(action)
            other.step(n_sub)
            got.append(_world_state(other))
        assert _bits(got) == _bits(expected), f"{how}: the copy stepped differently"


def test_copy_of_a_stopped_boat_stays_stopped():
    """A capsized boat's copy refuses to step, as the original does (the stop travels along)."""
    physics = BoatPhysics.load("saoud_robot")
    physics.set_external_wrench([0.0, 0.0, 0.0, 500.0, 0.0, 0.0])  # 500 N m heeling a 15 kg robot
    with pytest.raises(SimulationStopped, match="capsized"):
        for _ in range(2000):
            physics.step(10)
    assert abs(physics.heel()) > math.pi / 2
    for other in (physics.copy(), *_round_trips(physics).values()):
        with pytest.raises(SimulationStopped, match="capsized"):
            other.step(1)
        assert other.time() == physics.time()


@pytest.mark.parametrize("method", ["from_xml_path", "from_xml_string"])
def test_boat_physics_from_mjcf_says_how_to_build_one(method):
    with pytest.raises(ValueError, match=r"BoatPhysics\.load") as info:
        getattr(BoatPhysics, method)("xml/wille_yacht/scene.xml")
    assert "\n" not in str(info.value)


def _controller_cases():
    """Every named controller on a task it is made for, plus the sheeted-sail adapter and
    Saoud's composite controller built directly."""
    task_of = {"viel": "position_keeping", "wille_roll": "beam_reach_roll", "wille_course": "course_hold"}
    names = sorted(e.name for e in entry_points(group="sailmujoco.controllers"))
    cases = [(name, task_of.get(name, "heading_hold"), "actuated") for name in names]
    return cases + [("pid", "heading_hold", "sheeted"), ("saoud_controller", "heading_hold", "actuated")]


def _build(name, env):
    if name == "saoud_controller":
        from sailmujoco.controllers.pid import PIDHeading
        from sailmujoco.controllers.saoud import SaoudController

        return SaoudController(PIDHeading(dt=env.control_timestep()), l_phi=0.1, phi_max=0.5)
    (entry,) = entry_points(group="sailmujoco.controllers", name=name)
    return entry.load()(env)


@pytest.mark.parametrize("name,task,sail_mode", _controller_cases())
def test_controller_copies_act_identically(name, task, sail_mode):
    boat = "saoud_robot" if name.startswith("saoud") else "wille_yacht"
    env = suite.load(boat, task, "mujoco", seed=1, sail_mode=sail_mode)
    controller = _build(name, env)
    controller.reset(1)
    timestep = env.reset()
    for _ in range(BEFORE):
        timestep = env.step(controller(timestep))
    copies = _round_trips(controller)
    timesteps, expected = [], []
    for _ in range(AFTER):
        timesteps.append(timestep)
        expected.append(controller(timestep))
        timestep = env.step(expected[-1])
    for how, other in copies.items():
        got = [other(ts) for ts in timesteps]
        assert _bits(got) == _bits(expected), f"{how}: the copy acted differently"


def test_controller_copy_carries_its_state():
    """The PID's integral travels with the copy: against a fresh controller fed the same
    observation, the copy's rudder differs by exactly k_i * sum(e_k dt) over the steps before."""
    env = suite.load("wille_yacht", "heading_hold", "mujoco", seed=1)
    controller = _build("pid", env)  # k_i = 0.05, dt = 0.1 s, unsaturated here
    controller.reset(1)
    timestep = env.reset()
    errors = []
    for _ in range(BEFORE):
        obs = timestep.observation
        errors.append(float(obs["heading"] - obs["desired_heading"]))
        timestep = env.step(controller(timestep))
    restored = pickle.loads(pickle.dumps(controller))
    fresh = _build("pid", env)
    fresh.reset(1)
    original, copied, new = controller(timestep), restored(timestep), fresh(timestep)
    assert copied[0] == original[0]
    assert abs(sum(errors)) > 1e-3  # rad: the integral is not negligible
    assert copied[0] - new[0] == pytest.approx(0.05 * 0.1 * sum(errors), rel=1e-9, abs=1e-15)
