"""Bad input gives one clear error; a state gone wrong stops the run with its reason."""

import math

import numpy as np
import pytest
from conftest import gusty, load

from sailmujoco import frames
from sailmujoco.boat.catalogue import get_boat, saoud_robot
from sailmujoco.boat.params import Foil
from sailmujoco.physics import BoatPhysics, SimulationStopped


def test_unknown_boat():
    known = "eleven_metre, saoud_robot, viel_boat, wille_yacht"
    with pytest.raises(ValueError, match=rf"unknown boat 'catamaran' .*\(accepted: {known}\)"):
        BoatPhysics.load("catamaran")
    with pytest.raises(ValueError, match="did you mean 'wille_yacht'"):
        BoatPhysics.load("wile_yacht")


def test_negative_area():
    with pytest.raises(ValueError, match="Foil.area must be a positive finite number"):
        Foil(area=-0.3, aspect_ratio=3.0, thickness_ratio=0.15, x=0.0, z=-0.5)
    p = get_boat("wille_yacht")
    with pytest.raises(ValueError, match="Sail.area must be a positive finite number"):
        p.with_(sail=p.sail.__class__(**{**p.sail.__dict__, "area": -1.0}))


def test_bad_boat_option():
    with pytest.raises(ValueError, match="l_phi"):
        saoud_robot(l_phi=-0.1)
    with pytest.raises(ValueError, match="bad option for boat 'wille_yacht'"):
        get_boat("wille_yacht", l_phi=1.0)


def test_nan_command_is_refused():
    physics = load("wille_yacht")
    with pytest.raises(ValueError, match="non-finite control"):
        physics.set_control([float("nan"), 0.0])
    with pytest.raises(ValueError, match="control must have shape"):
        physics.set_control([0.0])


def test_non_finite_state_stops_the_simulation():
    physics = load("wille_yacht")
    physics.data.qvel[0] = np.inf
    with pytest.raises(SimulationStopped, match="non-finite state"):
        physics.step(1)
    assert physics.stop_reason == "non-finite state"
    with pytest.raises(SimulationStopped):  # and it stays stopped
        physics.step(1)


def test_capsize_stops_the_simulation():
    physics = load("saoud_robot", hydrostatics="geometric", wind=gusty(2.0))
    with physics.reset_context():
        physics.data.qpos[3:7] = frames.quat_from_euler(math.radians(95.0), 0.0, 0.0)
    with pytest.raises(SimulationStopped, match="capsized"):
        physics.step(1)


def test_unknown_modes():
    with pytest.raises(ValueError, match="unknown hydrostatics 'wavy'"):
        load("wille_yacht", hydrostatics="wavy")
    for option in ("added_mass_coupling", "vertical_damping", "restoring_axes"):
        with pytest.raises(ValueError, match=f"unknown {option} 'x'; choose one of"):
            load("wille_yacht", **{option: "x"})
    with pytest.raises(ValueError, match="unknown sail mode 'wing'"):
        load("wille_yacht", sail_mode="wing")
    physics = load("wille_yacht")
    with pytest.raises(ValueError, match="unknown force term"):
        physics.force_term("engine")


# ---- episode options at suite.load: one line naming the option and the accepted range ------
@pytest.mark.parametrize("options,message", [
    ({"time_limit": 0}, "time_limit must be a finite number > 0 s, got 0"),
    ({"time_limit": -1.0}, "time_limit must be a finite number > 0 s, got -1.0"),
    ({"time_limit": float("nan")}, "time_limit must be a finite number > 0 s, got nan"),
    ({"time_limit": "10"}, "time_limit must be a finite number > 0 s, got '10'"),
    ({"desired_heading_deg": float("nan")}, "desired_heading_deg must be a finite number, got nan"),
    ({"heading_jitter_deg": -30}, "heading_jitter_deg must be a finite number >= 0 and <= 180, got -30"),
    ({"seed": -1}, "seed must be None or an integer >= 0, got -1"),
    ({"seed": 1.5}, "seed must be None or an integer >= 0, got 1.5"),
    ({"wind_speed": 1e6}, "wind_speed must be a finite number >= 0 and <= 100 m/s, got 1000000.0"),
    ({"steady_window": 0}, "steady_window must be a finite number > 0 s, got 0"),
])
def test_episode_options_are_checked_at_load(options, message):
    from sailmujoco import suite

    with pytest.raises(ValueError) as err:
        suite.load("saoud_robot", "heading_hold", **options)
    assert str(err.value) == message


@pytest.mark.parametrize("options,message", [
    ({"d_target": 0}, "d_target must be a finite number > 0 m, got 0"),
    ({"d_target": 7.0, "d_prearrival": 5.0},
     "d_prearrival must be a finite number > 7 m (more than d_target), got 5.0"),
])
def test_position_keeping_radii_are_checked_at_load(options, message):
    from sailmujoco import suite

    with pytest.raises(ValueError) as err:
        suite.load("saoud_robot", "position_keeping", **options)
    assert str(err.value) == message


def test_valid_episode_options_still_load():
    from sailmujoco import suite

    env = suite.load("saoud_robot", "heading_hold", seed=3, time_limit=0.5, heading_jitter_deg=0,
                     wind_speed=0.0, desired_heading_deg=-720)
    assert env.reset().observation is not None


def test_a_wind_beyond_the_models_range_is_refused():
    from sailmujoco.forces.wind import WindConfig

    with pytest.raises(ValueError) as err:
        WindConfig(speed=1e6)
    assert str(err.value) == "wind: speed must be between 0 and 100 m/s, got 1000000.0"


def test_a_blown_up_state_stops_as_non_finite_not_as_capsized():
    """MuJoCo's own check (a huge acceleration) ends the run with that reason, as a
    SimulationStopped the task records, not as a capsize or a PhysicsError traceback."""
    from sailmujoco.physics import BoatPhysics, SimulationStopped

    physics = BoatPhysics.load("saoud_robot")
    physics.data.ptr.qvel[0] = 1e200  # finite, far out of range: the drag overflows the step
    with pytest.raises(SimulationStopped) as err:
        physics.step(1)
    assert "non-finite" in err.value.reason and "capsized" not in err.value.reason
    assert physics.stop_reason == err.value.reason


@pytest.mark.parametrize("sail_mode,name", [("actuated", "rudder_rad,sail_rad"),
                                            ("sheeted", "rudder_rad,sheet_m")])
def test_action_spec_names_its_units(sail_mode, name):
    """The sheeted sail's second command is a sheet length in metres, not an angle."""
    from sailmujoco import suite
    from sailmujoco.boat import mjcf

    env = suite.load("saoud_robot", "heading_hold", sail_mode=sail_mode)
    spec = env.action_spec()
    assert spec.name == name
    if sail_mode == "sheeted":  # the bounds are the sheet's lengths at 0 and at the sail limit
        p = env.physics.params
        assert spec.maximum[1] == pytest.approx(float(mjcf.sheet_length(p, p.sail.max_angle)), rel=1e-5)


def test_terminal_observation_after_a_capsize_is_the_state_it_stopped_in():
    """A 60 m/s beam wind on a sheeted-in robot capsizes it within a second; the terminal
    observation is measured at the stop (time and heel of that state), not the previous step's."""
    import math

    import numpy as np

    from sailmujoco import suite

    env = suite.load("saoud_robot", "heading_hold", seed=0, wind_speed=60.0, time_limit=20.0,
                     gusts=False, wander=False)
    timestep = env.reset()
    while not timestep.last():
        timestep = env.step(np.array([0.0, 0.0]))
    assert env.task.metrics()["stopped"].startswith("capsized")
    observation = timestep.observation
    assert float(observation["true_state"]["time"]) == pytest.approx(env.physics.data.time, abs=1e-12)
    assert abs(math.degrees(float(observation["heel"]))) > 80.0  # heeled over, not last step's heel


@pytest.mark.parametrize("option, value",
                         [("keel_downwash", "no"), ("windage", 1), ("sail_tangential", "off")])
def test_on_off_force_switches_take_true_or_false_only(option, value):
    """'no' is refused in one line naming the option, not handed to numpy as a float."""
    from sailmujoco import suite

    with pytest.raises(ValueError) as err:
        suite.load("saoud_robot", "heading_hold", **{option: value})
    assert str(err.value) == f"{option} must be True or False, got {value!r}"


def test_set_takes_tomls_true_and_false():
    from sailmujoco.cli.arguments import setting

    assert setting("windage=false") == ("windage", False)
    assert setting("keel_downwash=True") == ("keel_downwash", True)
    assert setting("case=3") == ("case", 3)


@pytest.mark.parametrize("command", ["video", "view"])
def test_set_refuses_an_unknown_key_with_the_nearest_name(command, capsys):
    """A misspelt --set key ends before anything is built: one line naming it, where it was
    given and the nearest option the task and the physics take."""
    from sailmujoco.cli.main import main

    argv = [command, "saoud_robot", "heading_hold", "--controller", "pid", "--set", "wind_sped=3"]
    if command == "video":
        argv += ["--out", "never.mp4"]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "unknown option 'wind_sped' in --set; did you mean 'wind_speed'?" in err
