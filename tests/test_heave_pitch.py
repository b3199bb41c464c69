"""Free heave and pitch of the 6-DOF yacht under way.

A displacement yacht towed at constant speed keeps a small, steady trim: towing tanks run them
to Froude 0.75 (Delft series) without pitch divergence. With the unbounded-fluid Kirchhoff
terms the pitch Munk moment -a33 U^2 theta outgrew the hydrostatic pitch stiffness above about
7.4 m/s and the yacht reared up.
"""

import math

import numpy as np
import pytest
from conftest import CALM

from sailmujoco import frames, suite, sweep
from sailmujoco.physics import BoatPhysics, ForceSwitches


def towed(speed, coupling="manoeuvring", hydrostatics="geometric", seconds=60.0):
    """Tow the yacht (no sail, rudder amidships) at ``speed``: a surge force at CO equal to the
    drag at that speed, then a 1 deg bow-up kick. Returns (pitch_deg, surge) at 10 Hz."""
    physics = BoatPhysics.load("wille_yacht", wind=CALM, forces=ForceSwitches(
        sail=False, hydrostatics=hydrostatics, added_mass_coupling=coupling))
    physics.place(surge=speed)
    drag = sum(w[0] for name, w in physics.force_terms().items() if name != "external")
    physics.set_external_wrench([-drag, 0, 0, 0, 0, 0])
    physics.data.qpos[3:7] = frames.quat_from_euler(0.0, math.radians(1.0), 0.0)  # the kick
    physics.forward()
    pitch, surge = [], []
    for _ in range(int(seconds * 10)):
        physics.step(20)
        pitch.append(math.degrees(physics.pitch()))
        surge.append(physics.surge_speed())
        if abs(pitch[-1]) > 20:
            break
    return np.array(pitch), np.array(surge)


@pytest.mark.parametrize("hydrostatics", ["geometric", "paper"])
@pytest.mark.parametrize("speed", [2.0, 4.0, 6.0, 8.0])
def test_towed_yacht_keeps_a_small_trim_after_a_pitch_kick(speed, hydrostatics):
    pitch, surge = towed(speed, hydrostatics=hydrostatics)
    assert pitch.size == 600
    assert np.max(np.abs(pitch)) <= 1.5
    assert np.max(np.abs(pitch[-100:])) < 0.2  # settled: the kick has decayed
    assert surge[-1] == pytest.approx(speed, rel=0.02)  # towed at the speed asked for


def test_kirchhoff_pitch_munk_moment_rears_the_towed_yacht_up():
    """The switch keeps the old form, and it fails the same check at 8 m/s (bow up past 20 deg)."""
    pitch, _ = towed(8.0, coupling="kirchhoff")
    assert np.max(np.abs(pitch)) > 10.0


def _wille_sim1(dofs):
    env = suite.load("wille_yacht", "beam_reach_roll", "mujoco", seed=1, dofs=dofs)
    controller = sweep.make_controller("wille_roll", env, roll_control=False, wind="perfect")
    controller.reset(1)
    timestep = env.reset()
    trim = []
    while not timestep.last():
        timestep = env.step(controller(timestep))
        if env.physics.data.time >= 250.0:
            trim.append(env.physics.pitch())
    return env.task.metrics(), np.array(trim)


def test_free_heave_and_pitch_cost_no_speed_in_wille_sim1():
    """Wille (2016b) sim 1 (gusty 10 m/s beam reach, seed 1, lambda_100 sail, roll control off),
    last 50 s: the free yacht sails within 5 % of the heave-and-pitch-held one and trims < 3 deg."""
    free, trim = _wille_sim1(6)
    held, _ = _wille_sim1(4)
    assert free["stopped"] is None and held["stopped"] is None
    assert free["mean_surge"] == pytest.approx(held["mean_surge"], rel=0.05)
    assert np.mean(np.abs(np.degrees(trim))) < 3.0
