"""Wille (2016a) heading and course controllers: the equations, then closed loop."""

import math

import numpy as np
import pytest
from sailmujoco.controllers.base import Composite
from sailmujoco.controllers.wille import WilleHeading, lift_slope

from sailmujoco import suite
from sailmujoco.params import get_boat


def _observation(**true_state):
    ts = {"u": 3.0, "v": 0.0, "u_r": 3.0, "v_r": 0.0, "roll_rate": 0.0, "yaw_rate": 0.0,
          "sail_wrench": np.zeros(6), "keel_wrench": np.zeros(6), "rudder_wrench": np.zeros(6),
          "added_mass_wrench": np.zeros(6)}
    ts.update(true_state)
    return {"heading": 0.0, "heel": 0.0, "true_state": ts, "desired_heading": 0.0,
            "desired_course": 0.0}


def test_eq_51_inverts_the_linearised_rudder_moment():
    """With sigma from eq. 51 the linearised rudder yaw moment (eq. 50) is the desired one."""
    p = get_boat("wille_yacht")
    law = WilleHeading(p)
    obs = _observation()
    obs["heading"] = math.radians(2.0)  # 2 deg to starboard of the desired heading
    sigma = law(obs)
    desired = -law.kp * math.radians(2.0)  # eq. 48 with S = K = C_A = 0 and r = 0
    speed2 = 3.0**2
    moment = 3.7 * 0.5 * p.rho_water * p.rudder.area * law.cl0_rudder * sigma * speed2 * math.cos(math.pi)
    assert moment == pytest.approx(desired, rel=1e-9)
    assert sigma > 0  # heading too far right: positive rudder turns to port


def test_lift_slopes_are_those_of_the_foil_model():
    p = get_boat("wille_yacht")
    # thin-aerofoil 2 pi reduced by Wagner's aspect-ratio factor, eq. 23 (the table is ~1.9 pi)
    assert lift_slope(p.rudder) == pytest.approx(2 * math.pi / (1 + 2 / 2.97), rel=0.15)
    assert lift_slope(p.keel) < lift_slope(p.rudder)  # lower aspect ratio


def test_course_correction_sign_and_limit():
    p = get_boat("wille_yacht")
    law = WilleHeading(p, course=True)
    # sail pushing to starboard (FLU -y): the keel must hold it, the boat crabs to starboard,
    # so it must point to port of the course: beta_b > 0 and psi_d = chi_d - beta_b
    obs = _observation(sail_wrench=np.array([0, -300.0, 0, 0, 0, 0]))
    beta = law.correction({"u": 3.0, "v": 0.0, "phi": 0.0, "Y_sail": 300.0, "Y_rudder": 0.0})
    expected = 2 * 300.0 / (p.rho_water * p.keel.area * law.cl0_keel * 9.0)  # eqs. 58-59
    assert beta == pytest.approx(expected)
    law(obs)
    assert law.last_beta_b == pytest.approx(expected)
    huge = law.correction({"u": 0.5, "v": 0.0, "phi": 0.0, "Y_sail": 5000.0, "Y_rudder": 0.0})
    assert huge == pytest.approx(math.radians(10.0))
    assert law.correction({"u": 0.0, "v": 0.0, "phi": 0.0, "Y_sail": 5000.0, "Y_rudder": 0.0}) == 0.0


def _sail_to_leeward(observation):
    awa = float(observation["apparent_wind_angle"])
    return math.copysign(max(math.radians(10), min(abs(awa) / 2, math.radians(80))), awa)


@pytest.mark.parametrize("world", ["mujoco", "paper"])
def test_course_controller_drifts_less_than_heading_controller(world):
    """Close-hauled (Wille §4 case, 100 s here): the correction term cuts the drift error."""
    errors = {}
    for course in (False, True):
        env = suite.load("wille_yacht", "course_hold", world, seed=0, time_limit=100.0)
        controller = Composite(WilleHeading(course=course), _sail_to_leeward)
        ts = env.reset()
        while not ts.last():
            ts = env.step(controller(ts))
        errors[course] = env.task.metrics()["drift_error"]
        assert env.task.metrics()["north"] > 80.0  # it sails north, close-hauled
    assert math.degrees(errors[False]) > 2.0
    assert errors[True] < 0.6 * errors[False]
