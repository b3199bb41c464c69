"""Physics options: each set of choices defined once, suite.load's keywords sorted and checked,
and the same names refused the same way in the sweep and the controller factories."""

import copy
import dataclasses
import inspect
import pickle
import typing

import numpy as np
import pytest

from sailmujoco import options, suite, sweep
from sailmujoco.boat import mjcf
from sailmujoco.forces import boat_parameters as kernels
from sailmujoco.options import ForceSwitches, PhysicsOptions

# suite.load's physics defaults: the boat as built in the MuJoCo world
DEFAULTS = dict(sail_mode="actuated", dofs=6, paper_model="paper", hydrostatics="geometric",
                sail=True, keel=True, rudder=True, damping=True, added_mass=True,
                sail_tangential=True, added_mass_coupling="impulse", vertical_damping="world",
                restoring_axes="horizontal", resistance="dsyhs", foils="finite",
                keel_downwash=True, windage=True, wave_hull=True, wave_foil_flow=True, wave_diffraction=True,
                wave_damping="relative", wave_pressure_decay=True, wave_reflection=True,
                rig_interaction="lumped_vortex", boat_options={}, waves=None, timestep=None)


# ---- one definition of each set of choices --------------------------------------------------
def test_each_choice_set_is_one_literal():
    assert options.choices(options.Hydrostatics) == ("off", "paper", "geometric")
    assert options.choices(options.World) == ("mujoco", "paper")
    assert options.choices(options.Dofs) == (6, 4)
    literals = [v for v in vars(options).values() if typing.get_origin(v) is typing.Literal]
    assert len(literals) == 13  # with the sea's spectra (WaveConfig.spectrum)
    assert options.SPECTRA == options.choices(options.Spectrum)
    assert options.literal_fields(PhysicsOptions) == {
        "hydrostatics": options.choices(options.Hydrostatics),
        "added_mass_coupling": options.choices(options.AddedMassCoupling),
        "vertical_damping": options.choices(options.VerticalDamping),
        "restoring_axes": options.choices(options.RestoringAxes),
        "resistance": options.choices(options.Resistance),
        "foils": options.choices(options.Foils),
        "wave_damping": options.choices(options.WaveDamping),
        "rig_interaction": options.choices(options.RigInteraction),
        "sail_mode": options.choices(options.SailMode),
        "dofs": options.choices(options.Dofs),
        "paper_model": options.choices(options.PaperModel)}


def test_the_library_reads_the_choices_from_the_literals():
    # derived: the kernel's hydrostatics codes, the suite's worlds, the sweep's env. choices
    assert kernels.HYDROSTATIC_MODES is options.choices(options.Hydrostatics)
    assert suite.WORLDS == options.choices(options.World)
    assert sweep.env_choices() == options.literal_fields(PhysicsOptions)
    # the force kernel's and the MJCF builder's own lists hold the same values in the same order
    for literal, held in ((options.AddedMassCoupling, kernels.ADDED_MASS_COUPLINGS),
                          (options.VerticalDamping, kernels.VERTICAL_DAMPING_FORMS),
                          (options.RestoringAxes, kernels.RESTORING_AXES),
                          (options.Resistance, kernels.RESISTANCE_FORMS),
                          (options.Foils, kernels.FOIL_FORMS),
                          (options.SailMode, mjcf.SAIL_MODES)):
        assert held == options.choices(literal)


def test_the_command_lines_world_choices_are_the_literals():
    import argparse

    from sailmujoco.cli import main as cli

    def world_choices(parser):
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for sub in action.choices.values():
                    yield from world_choices(sub)
            elif action.dest == "world":
                yield tuple(action.choices)

    found = list(world_choices(cli.build_parser()))
    assert found and all(set(c) == set(options.choices(options.World)) for c in found)


def test_the_sweeps_env_options_are_the_physics_fields_and_the_control_step():
    names = set(sweep.env_options())
    assert names == (set(options.PHYSICS_FIELDS) - {"boat_options", "waves"}) | {"control_timestep"}
    assert sweep.env_options()["control_timestep"] == \
        inspect.signature(suite.load).parameters["control_timestep"].default


# ---- PhysicsOptions ------------------------------------------------------------------------
def test_defaults_are_the_boat_as_built():
    assert dataclasses.asdict(PhysicsOptions()) == DEFAULTS
    assert PhysicsOptions().forces == ForceSwitches()
    assert set(options.FORCE_FIELDS) < set(options.PHYSICS_FIELDS)


@pytest.mark.parametrize("field,value,message", [
    ("hydrostatics", "wavy", "unknown hydrostatics 'wavy'; choose one of ('off', 'paper', 'geometric')"),
    ("dofs", 5, "unknown dofs 5; choose one of (6, 4)"),
    ("dofs", True, "unknown dofs True; choose one of (6, 4)"),
    ("sail_mode", "wing", "unknown sail_mode 'wing'; choose one of ('actuated', 'sheeted')"),
    ("paper_model", "flat", "unknown paper_model 'flat'; choose one of ('paper', 'rigid')"),
    ("windage", "yes", "windage must be True or False, got 'yes'"),
    ("boat_options", [1], "boat_options must be a mapping of option names to values, got [1]"),
])
def test_a_bad_value_is_one_line_naming_the_option_and_what_it_accepts(field, value, message):
    with pytest.raises(ValueError) as err:
        PhysicsOptions(**{field: value})
    assert str(err.value) == message


def test_from_value():
    assert PhysicsOptions.from_value(None, "here") == PhysicsOptions()
    given = PhysicsOptions(dofs=4)
    assert PhysicsOptions.from_value(given, "here") is given
    assert PhysicsOptions.from_value({"dofs": 4, "boat_options": {"l_phi": 0.1}}, "here") == \
        PhysicsOptions(dofs=4, boat_options={"l_phi": 0.1})
    with pytest.raises(ValueError) as err:
        PhysicsOptions.from_value({"hydrostatic": "paper"}, "here")
    assert str(err.value).startswith("unknown option 'hydrostatic' in here; did you mean 'hydrostatics'?")
    with pytest.raises(ValueError, match="must be a PhysicsOptions or a dict"):
        PhysicsOptions.from_value("paper", "here")


def test_options_copy_pickle_and_hash():
    value = PhysicsOptions(hydrostatics="paper", boat_options={"l_phi": 0.1})
    for twin in (copy.deepcopy(value), pickle.loads(pickle.dumps(value))):
        assert twin == value and hash(twin) == hash(value)
    with pytest.raises(dataclasses.FrozenInstanceError):
        value.dofs = 4


# ---- suite.load -----------------------------------------------------------------------------
def test_load_has_at_most_eight_named_parameters():
    parameters = inspect.signature(suite.load).parameters.values()
    named = [p for p in parameters if p.kind is not p.VAR_KEYWORD]
    assert len(named) <= 8
    assert [p.name for p in named] == ["boat", "task", "world", "seed", "time_limit",
                                       "control_timestep", "physics", "flat_observation"]


@pytest.mark.parametrize("task", list(suite.TASKS))
def test_task_options_and_physics_fields_are_disjoint(task):
    assert suite.task_options(task)
    assert not set(suite.task_options(task)) & set(options.PHYSICS_FIELDS)
    assert not set(suite.task_options(task)) & {"forces", "params", "physics"}


def test_unknown_keyword_names_the_nearest_and_suite_load():
    for given, nearest in (("hydrostatic", "hydrostatics"), ("wind_sped", "wind_speed"),
                           ("dof", "dofs")):
        with pytest.raises(ValueError) as err:
            suite.load("saoud_robot", "heading_hold", **{given: 1})
        message = str(err.value)
        assert f"unknown option {given!r} in suite.load; did you mean {nearest!r}?" in message
        assert "\n" not in message


@pytest.mark.parametrize("kwargs,message", [
    (dict(forces=ForceSwitches(), hydrostatics="paper"),
     "suite.load: give the force switches once, in forces= or as hydrostatics=, not both"),
    (dict(forces=ForceSwitches(), physics={"hydrostatics": "paper"}),
     "suite.load: give forces= or physics=, not both (physics= holds the force switches too)"),
    (dict(forces=ForceSwitches(), physics=PhysicsOptions()),
     "suite.load: give forces= or physics=, not both (physics= holds the force switches too)"),
    (dict(physics={"dofs": 4}, hydrostatics="paper"),
     "suite.load: give the physics options once, in physics= or as keywords (hydrostatics), not both"),
    (dict(forces=PhysicsOptions()), "forces must be a ForceSwitches (physics options go in physics=)"),
])
def test_a_physics_option_given_twice_is_refused(kwargs, message):
    with pytest.raises(ValueError) as err:
        suite.load("saoud_robot", "heading_hold", **kwargs)
    assert str(err.value).startswith(message)


def test_boat_parameters_as_the_boat():
    from sailmujoco.boat.catalogue import get_boat

    params = get_boat("saoud_robot", l_phi=0.2)
    env = suite.load(params, "heading_hold", seed=0)
    assert env.physics.params is params
    with pytest.raises(ValueError, match="give either params or boat_options, not both"):
        suite.load(params, "heading_hold", boat_options={"l_phi": 0.1})


def _trajectory(steps=5, **kwargs):
    env = suite.load("saoud_robot", "heading_hold", seed=2, **kwargs)
    timestep = env.reset()
    states = [np.concatenate([env.physics.data.qpos, env.physics.data.qvel])]
    for _ in range(steps):
        timestep = env.step(np.array([0.1, 0.3]))
        states.append(np.concatenate([env.physics.data.qpos, env.physics.data.qvel]))
    assert not timestep.last()
    return env, np.array(states)


def test_physics_dict_flat_keywords_and_forces_give_the_same_trajectory_bit_for_bit():
    flat_env, flat = _trajectory(hydrostatics="paper", dofs=4, windage=False,
                                 boat_options={"l_phi": 0.5})
    assert flat_env.physics.dofs == 4 and flat_env.physics.switches.hydrostatics == "paper"
    assert flat_env.physics.params.gm_t == 0.5
    given = dict(hydrostatics="paper", dofs=4, windage=False, boat_options={"l_phi": 0.5})
    _, as_dict = _trajectory(physics=given)
    _, as_object = _trajectory(physics=PhysicsOptions(**given))
    _, as_forces = _trajectory(forces=ForceSwitches(hydrostatics="paper", windage=False), dofs=4,
                               boat_options={"l_phi": 0.5})
    for other in (as_dict, as_object, as_forces):
        assert np.array_equal(other, flat)
    _, default = _trajectory()
    assert not np.array_equal(default[-1], flat[-1])  # the options took effect


def test_paper_world_reads_paper_model_from_the_options():
    env = suite.load("wille_yacht", "heading_hold", "paper", physics={"paper_model": "rigid"})
    assert env.physics.world.model == "rigid"


# ---- the same refusals in the sweep and the controller factories ---------------------------
def test_make_controller_names_the_nearest_controller_and_option():
    env = suite.load("saoud_robot", "heading_hold", seed=0)
    with pytest.raises(sweep.SweepError) as err:
        sweep.make_controller("pdi", env)
    assert "unknown controller 'pdi'" in str(err.value) and "did you mean 'pid'?" in str(err.value)
    with pytest.raises(sweep.SweepError) as err:
        sweep.make_controller("pid", env, kpp=1.0)
    assert str(err.value) == ("unknown option 'kpp' in controller 'pid'; did you mean 'kp'? "
                              "(accepted: fraction, kd, ki, kp)")
    assert sweep.make_controller("pid", env, kp=2.0) is not None


HEAD = 'boat = "saoud_robot"\ntask = "heading_hold"\ncontroller = "pid"\nduration = 1.0\n'


@pytest.mark.parametrize("body,expected", [
    (HEAD + "seed = [0]\n", "unknown key 'seed' in sweep file {path!r}; did you mean 'seeds'?"),
    (HEAD + '[grid]\n"env.hydrostatic" = ["paper"]\n',
     "unknown env option 'hydrostatic' in [grid] key 'env.hydrostatic' of sweep file {path!r}; "
     "did you mean 'hydrostatics'?"),
    (HEAD + '[options]\n"evn.dofs" = 4\n',
     "unknown namespace 'evn' in [options] key 'evn.dofs' of sweep file {path!r}; "
     "did you mean 'env'?"),
    (HEAD + '[zip]\n"controller.kd_" = [1.0]\n',
     "unknown controller option 'kd_' in [zip] key 'controller.kd_' of sweep file {path!r}; "
     "did you mean 'kd'?"),
])
def test_a_misspelt_sweep_key_names_the_nearest(tmp_path, body, expected):
    path = tmp_path / "bad.toml"
    path.write_text(body)
    with pytest.raises(sweep.SweepError) as err:
        sweep.load_spec(path)
    assert str(err.value).startswith(expected.format(path=str(path)))
    assert "\n" not in str(err.value)


def test_a_sweep_takes_every_physics_option_as_env():
    spec = sweep.validate({"boat": "saoud_robot", "task": "heading_hold", "controller": "pid",
                           "duration": 1.0, "options": {"env.sail": False, "env.dofs": 4},
                           "grid": {"env.resistance": ["friction", "dsyhs"]}})
    runs = sweep.expand(spec)
    assert [r["env_options"] for r in runs] == [
        {"dofs": 4, "resistance": "friction", "sail": False},
        {"dofs": 4, "resistance": "dsyhs", "sail": False}]
    with pytest.raises(sweep.SweepError, match=r"env.foils = 'wing' is not one of \('paper', 'finite'\)"):
        sweep.validate(dict(spec, grid={"env.foils": ["wing"]}))
