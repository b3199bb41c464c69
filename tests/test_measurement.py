"""The lean observation of a MuJoCo boat, and of Wille's paper world, equals the accessor-built
one, bit for bit; every world meets the World protocol.

``BoatPhysics.measure`` (one rotation, the physics' arrays) against
:func:`sailmujoco.measurement.observation.measure` (the named accessors, the definition of the observation)
and the record against the record built from the accessors (kept here), on
real trajectories: heeled and moving in gusts, with a current, 4 and 6 DOF, both
hydrostatics, a sheeted sail, and the states the tasks' own episodes pass through.
"""

import math

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.forces.wind import WindConfig
from sailmujoco.measurement.observation import measure
from sailmujoco.physics import BoatPhysics, ForceSwitches
from sailmujoco.reference.viel import VielWorld
from sailmujoco.reference.wille import Wille4DOF
from sailmujoco.tasks.world import PaperPhysics, VielPhysics, World


def assert_identical(new, ref, path="observation"):
    """Same keys in the same order, same types, shapes, dtypes and bytes (NaN equal to NaN)."""
    if isinstance(ref, dict):
        assert isinstance(new, dict), path
        assert list(new) == list(ref), path
        for key in ref:
            assert_identical(new[key], ref[key], f"{path}[{key!r}]")
    elif isinstance(ref, np.ndarray):
        assert isinstance(new, np.ndarray), path
        assert (new.dtype, new.shape) == (ref.dtype, ref.shape), path
        assert new.tobytes() == ref.tobytes(), f"{path}: {new!r} != {ref!r}"
    else:
        assert type(new) is type(ref), path
        assert new == ref or (new != new and ref != ref), f"{path}: {new!r} != {ref!r}"


def accessor_record(physics) -> dict:
    """The task's record built from the named accessors (the reference)."""
    body = physics.body_velocity()
    return {"t": physics.time(), "position": np.array(physics.position()[:2]),
            "heading": physics.heading(), "heel": physics.heel(),
            "roll_rate": float(physics.angular_velocity()[0]), "surge": float(body[0]),
            "course": physics.course(), "speed": physics.speed_over_ground()}


def check_now(physics):
    """The lean measurement of the current state against the accessors, twice: on a state
    whose forces are stale (right after a step) and on the refreshed one."""
    observation, record = physics.measure()
    physics._fresh = False
    assert_identical(observation, measure(physics))
    assert_identical(record, accessor_record(physics), "record")


@pytest.mark.parametrize("boat,dofs,hydrostatics,sail_mode", [
    ("wille_yacht", 6, "geometric", "actuated"), ("saoud_robot", 6, "paper", "actuated"),
    ("wille_yacht", 4, "geometric", "actuated"), ("saoud_robot", 4, "paper", "actuated"),
    ("viel_boat", 6, "geometric", "sheeted")])
def test_boat_states(boat, dofs, hydrostatics, sail_mode):
    """Heeled, moving, turning in a gusty, wandering wind over a current."""
    wind = WindConfig(speed=11.0, direction_from=math.radians(70.0), seed=3, current_east=0.4,
                      current_north=-0.25)
    physics = BoatPhysics.load(boat, wind=wind, dofs=dofs, sail_mode=sail_mode,
                               forces=ForceSwitches(hydrostatics=hydrostatics))
    physics.place((3.0, -2.0), 0.7, 1.5)
    low, high = physics.model.actuator_ctrlrange.T
    rng = np.random.default_rng(7)
    check_now(physics)
    heels = []
    for _ in range(40):
        physics.set_control(rng.uniform(low, high))
        physics.step(int(rng.integers(1, 30)))
        check_now(physics)
        heels.append(abs(physics.heel()))
    assert max(heels) > math.radians(3.0)  # the states were heeled, not only upright
    assert physics.speed_over_ground() > 0.3


@pytest.mark.parametrize("boat,task,options", [
    ("saoud_robot", "speed_trial", {}), ("wille_yacht", "beam_reach_roll", {}),
    ("wille_yacht", "heading_hold", {"dofs": 4}), ("viel_boat", "position_keeping", {"case": 5}),
    ("wille_yacht", "heading_hold", {"world": "paper"}),
    ("wille_yacht", "beam_reach_roll", {"world": "paper"})])
def test_task_episodes(boat, task, options):
    """Each step's observation and record through suite.load(...).step() against the accessors
    (with the task's references), MuJoCo boats and the paper worlds."""
    env = suite.load(boat, task, seed=2, **options)
    if options.get("world") == "paper":
        assert isinstance(env.physics, PaperPhysics)
    timestep = env.reset()
    rng = np.random.default_rng(1)
    spec = env.action_spec()
    for _ in range(25):
        timestep = env.step(rng.uniform(spec.minimum, spec.maximum))
        physics = env.physics
        reference = measure(physics)
        for key, value in env.task.references(physics).items():
            reference[key] = np.asarray(value, dtype=np.float64)
        assert_identical(timestep.observation, reference)
        assert_identical(env.task._records[-1], accessor_record(physics), "record")


def test_every_scalar_is_its_own_array():
    """The 0-d arrays are distinct objects (as measure's were): writing one changes no other."""
    physics = BoatPhysics.load("saoud_robot")
    observation, _ = physics.measure()
    observation["heel"][...] = 99.0
    assert float(observation["true_state"]["heel"]) != 99.0
    scalars = [v for v in (*observation.values(), *observation["true_state"].values())
               if isinstance(v, np.ndarray) and v.ndim == 0]
    assert len({id(v) for v in scalars}) == len(scalars) == 22


@pytest.mark.parametrize("boat,model", [("wille_yacht", "paper"), ("wille_yacht", "rigid"),
                                        ("saoud_robot", "paper")])
def test_wille_paper_world_states(boat, model):
    """Wille's 4-DOF world (heeled, turning, in a gusty wandering wind over a current, with an
    external wrench): its measure() against the accessors of the world behind PaperPhysics."""
    wind = WindConfig(speed=11.0, direction_from=math.radians(70.0), seed=3, current_east=0.4,
                      current_north=-0.25)
    world = Wille4DOF(boat, wind=wind, model=model)
    world.place((3.0, -2.0), 0.7, 1.5)
    world.external[:] = [20.0, -15.0, 30.0, -10.0]
    low, high = world.action_bounds()
    rng = np.random.default_rng(7)
    physics = PaperPhysics(world)
    heels = []
    for k in range(41):
        if k:
            world.set_control(rng.uniform(low, high))
            world.step(int(rng.integers(1, 30)))
        observation, record = world.measure()
        assert_identical(observation, measure(physics))
        assert_identical(record, accessor_record(physics), "record")
        heels.append(abs(world.heel()))
    assert max(heels) > math.radians(3.0)  # heeled states, not only upright ones
    assert world.speed_over_ground() > 0.3
    assert np.any(observation["true_state"]["sail_wrench"] != 0.0)


def test_every_world_meets_the_protocol():
    """The MuJoCo boat and both paper worlds are Worlds: a task drives them all alike."""
    worlds = [BoatPhysics.load("saoud_robot"), PaperPhysics(Wille4DOF("wille_yacht")),
              VielPhysics(VielWorld())]
    for world in worlds:
        assert isinstance(world, World), type(world).__name__
        observation, record = world.measure()
        assert set(record) == {"t", "position", "heading", "heel", "roll_rate", "surge",
                               "course", "speed"}
        assert "true_state" in observation
    assert worlds[0].diagnostic_record()["restoring"] == worlds[0].diagnostic_record()["restoring"]
    assert worlds[1].diagnostic_record() == worlds[2].diagnostic_record() == {}


@pytest.mark.parametrize("task,world", [("heading_hold", "mujoco"), ("heading_hold", "paper"),
                                        ("position_keeping", "paper")])
def test_the_fast_observation_is_the_tables_observation(task, world):
    """observe()'s written-out path for the built-in tables gives what reading every entry of
    TRUE_STATE and OBSERVATION gives (the definition), key for key and bit for bit: a key added
    to the tables and not to the fast path fails here."""
    from sailmujoco.measurement import observation as module

    env = suite.load("saoud_robot", task, world, seed=3)
    env.reset()
    for _ in range(5):
        env.step(np.array([0.1, 0.4]))
        truth = env.physics.truth()
        fast = module._observe_builtin(truth)
        assert fast is not None  # the world's truth takes the fast path
        assert_identical(fast, module._observe_tables(truth))
