"""The crew as movable ballast, and the depowering trims (reef, flat), from first principles."""

import hashlib
import math

import mujoco
import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.boat.mjcf import boat_spec
from sailmujoco.boat.params import Crew
from sailmujoco.boat.trim import flattened, reefed
from sailmujoco.constants import GRAVITY
from sailmujoco.forces.crew import crew_target


@pytest.mark.parametrize("heel_deg", [0.0, 15.0, 30.0, 45.0])
def test_the_crew_on_the_rail_rights_the_boat_by_m_g_arm_cos_heel(heel_deg):
    boat = get_boat("eleven_metre")
    c = boat.crew
    model = boat_spec(boat).compile()
    data = mujoco.MjData(model)
    phi = math.radians(heel_deg)
    roll = []
    for y in (0.0, c.arm):  # the crew on the centreline, then on the rail (its slide: the last joint)
        mujoco.mj_resetData(model, data)
        data.qpos[3:7] = (math.cos(phi / 2), math.sin(phi / 2), 0.0, 0.0)
        data.qpos[-1] = y
        mujoco.mj_forward(model, data)
        roll.append(-data.qfrc_bias[3])  # gravity's moment about the body x axis (bias = -applied)
    assert roll[0] - roll[1] == pytest.approx(c.mass * GRAVITY * c.arm * math.cos(phi), rel=1e-9)


def test_the_crew_sits_opposite_the_boom():
    arm = 0.9
    assert crew_target(0.4, arm) == -arm  # boom to port: the crew to starboard, the weather side
    assert crew_target(-0.4, arm) == arm
    assert crew_target(0.0, arm) == 0.0  # head to wind: on the centreline
    assert crew_target(math.radians(2.5), arm) == pytest.approx(-arm / 2)  # half of the 5 deg band


def test_the_crew_crosses_in_its_shift_time_when_the_boom_crosses():
    env = suite.load("eleven_metre", "heading_hold", seed=3, wind_speed=8.0)
    c = env.physics.params.crew
    env.reset()
    for _ in range(150):  # 15 s with the boom to port: the crew settles to starboard
        env.step(np.array([0.0, 0.35]))
    q = env.physics.data.qpos
    assert q[-1] == pytest.approx(-c.arm, abs=0.01)  # held on the rail at heel within a centimetre
    track = []
    for _ in range(100):  # the boom to starboard: the crew crosses
        env.step(np.array([0.0, -0.35]))
        track.append((env.physics.data.time, env.physics.data.qpos[-1]))
    t, y = np.array(track).T
    start = t[np.argmax(y > -c.arm + 0.05)]
    end = t[np.argmax(y > c.arm - 0.05)]
    walk = 2.0 * c.arm / c.shift_time
    assert (2.0 * c.arm - 0.1) / (end - start) == pytest.approx(walk, rel=0.1)  # its steady walk
    assert y[-1] == pytest.approx(c.arm, abs=0.01)


def _hash(boat):
    env = suite.load(boat, "heading_hold", seed=3, wind_speed=6.0)
    env.reset()
    h = hashlib.sha256()
    for _ in range(60):
        env.step(np.array([0.05, 0.35]))
        h.update(env.physics.data.qpos.tobytes() + env.physics.data.qvel.tobytes())
    return h.hexdigest()


def test_a_crew_of_no_mass_leaves_the_boat_bit_for_bit():
    alone = get_boat("eleven_metre", crew=False)
    nobody = alone.with_(crew=Crew(mass=0.0, arm=1.0, height=1.0, x=0.0, shift_time=4.0))
    assert _hash(nobody) == _hash(alone)
    assert _hash(get_boat("eleven_metre")) != _hash(alone)


def test_the_four_dof_hull_refuses_a_crew_in_one_line():
    with pytest.raises(ValueError, match="carries a crew, whose slide needs the free hull: dofs=6"):
        boat_spec(get_boat("eleven_metre"), dofs=4)


def test_a_reefed_main_is_the_top_of_the_full_triangle():
    boat = get_boat("eleven_metre")
    s = boat.sail
    r = reefed(boat, 0.8).sail
    assert r.area == pytest.approx(0.64 * s.area, rel=1e-12)  # a similar triangle: area x r^2
    assert r.luff == pytest.approx(0.8 * s.luff, rel=1e-12)
    assert r.foot == pytest.approx(0.8 * s.foot, rel=1e-12)
    assert r.boom_height == pytest.approx(s.boom_height, rel=1e-12)  # the boom stays
    assert r.ce_height == pytest.approx(s.boom_height + 0.8 * s.luff / 3.0, rel=1e-12)
    assert reefed(boat, 1.0) is boat and flattened(boat, 1.0) is boat


def test_flattening_scales_the_camber():
    boat = get_boat("eleven_metre")
    assert flattened(boat, 0.62).sail.camber == pytest.approx(0.62 * boat.sail.camber, rel=1e-12)
    assert flattened(boat, 0.0).sail.camber == 0.0  # the flat plate


@pytest.mark.parametrize("name, call", [("reef", lambda b: reefed(b, 0.3)),
                                        ("flat", lambda b: flattened(b, 1.5))])
def test_a_trim_out_of_range_is_one_line(name, call):
    with pytest.raises(ValueError, match=rf"^{name} must be a number in \["):
        call(get_boat("eleven_metre"))


def test_boat_check_states_the_crews_moment():
    from sailmujoco.design.check import crew_summary  # the line `boat check` prints

    boat = get_boat("eleven_metre")
    line = crew_summary(boat)
    moment = 350.0 * GRAVITY * 0.95 / 1e3  # m g arm upright, kN m: 3.26
    assert line.startswith("350 kg on the weather rail, 0.95 m off the centreline")
    assert line.endswith(f"{moment:.2f} kN m upright")
    assert crew_summary(get_boat("eleven_metre", crew=False)) == ""
