"""Wille (2016a) heading and course controllers: the equations, then closed loop."""

import math

import numpy as np
import pytest
from sailmujoco.controllers.base import Composite
from sailmujoco.controllers.wille import WilleHeading, lift_slope

from sailmujoco import suite
from sailmujoco.boat.catalogue import get_boat


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


DRIFT_SEEDS = (0, 1, 2, 3)  # gust realisations averaged by the drift test
DRIFT_MEAN_RATIO = 0.8  # course / heading controller drift error, mean over DRIFT_SEEDS


def _drift(world: str, seed: int, course: bool) -> tuple[float, float]:
    """(drift error in rad, distance north in m) of a 100 s close-hauled run."""
    env = suite.load("wille_yacht", "course_hold", world, seed=seed, time_limit=100.0)
    controller = Composite(WilleHeading(course=course), _sail_to_leeward)
    ts = env.reset()
    while not ts.last():
        ts = env.step(controller(ts))
    metrics = env.task.metrics()
    return metrics["drift_error"], metrics["north"]


@pytest.mark.parametrize("world", ["mujoco", "paper"])
def test_course_controller_drifts_less_than_heading_controller(world):
    """Close-hauled (Wille §4 case, 100 s here): the correction term cuts the drift error.

    Wille (2016a) §4 claims the course controller reduces the drift of the heading controller
    (by 93 % in its 200 s run). One run is one gust realisation, and a change in the last bit of
    a force sum moves the ratio course / heading error by about half as much as a change of
    realisation does (seed 0, MuJoCo world: 0.584 here; a 1e-15 change in a hull sum moved it
    by 0.036).
    Measured over seeds 0-11 (100 s, 10 Hz, this sail law), the ratio per seed is
    MuJoCo 0.46-0.70 (mean 0.575, sd 0.076) and paper world 0.19-0.54 (mean 0.326, sd 0.108).
    So the test averages seeds 0-3 (MuJoCo 0.621, paper 0.270; the sd of a mean of four is
    0.038 / 0.054) and asks for a mean below 0.8: the course controller removes at least a fifth
    of the heading controller's drift, 4.7 sd of the mean above the MuJoCo world's value; and
    for every seed less drift than the heading controller (ratio < 1, about 4 sd above the
    highest single-seed ratio measured).
    """
    ratios = []
    for seed in DRIFT_SEEDS:
        (heading, north_h), (course, north_c) = _drift(world, seed, False), _drift(world, seed, True)
        assert north_h > 80.0 and north_c > 80.0  # it sails north, close-hauled
        assert math.degrees(heading) > 2.0  # the heading controller drifts by degrees (3.0-4.1)
        assert course < heading
        ratios.append(course / heading)
    assert np.mean(ratios) < DRIFT_MEAN_RATIO
