"""Bad input gives one clear error; a state gone wrong stops the run with its reason."""

import math

import numpy as np
import pytest
from conftest import gusty, load

from sailmujoco import frames
from sailmujoco.params import Foil, get_boat, saoud_robot
from sailmujoco.physics import BoatPhysics, SimulationStopped


def test_unknown_boat():
    known = "saoud_robot, viel_boat, wille_yacht"
    with pytest.raises(ValueError, match=f"unknown boat 'catamaran'; known boats: {known}"):
        BoatPhysics.load("catamaran")


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
