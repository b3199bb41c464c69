"""Jaulin and Le Bars' line following against cases worked by hand in Jaulin's frame (x east,
y north, angles counter-clockwise from east, the wind's direction where it blows to)."""

import math

import pytest
from sailmujoco.controllers.line_following import LineFollowingGains, line_following, sawtooth

G = LineFollowingGains()  # r 10 m, zeta pi/3, gamma_inf pi/4, beta pi/4
EAST_LINE = ((0.0, 0.0), (100.0, 0.0))
NORTH_LINE = ((0.0, 0.0), (0.0, 100.0))


def test_on_the_line_with_the_wind_abeam_it_steers_the_line_and_eases_the_sheet_to_beta():
    delta_r, delta_s, theta_bar, q = line_following((50.0, 0.0), 0.0, math.pi / 2, *EAST_LINE, 1)
    assert theta_bar == 0.0 and delta_r == 0.0 and q == 1
    assert delta_s == pytest.approx(G.beta, abs=1e-15)  # abeam: beta, by the law's construction


def test_beyond_the_cut_off_it_heads_back_at_the_incidence_angles_share():
    """20 m left of an eastward line, the wind blowing south: theta* = -(2 gamma_inf / pi)
    atan(20 / 10) = -atan(2) / 2, 58 deg off the wind's eye downwind, out of the no-go cone."""
    delta_r, _, theta_bar, q = line_following((50.0, 20.0), 0.0, -math.pi / 2, *EAST_LINE, -1)
    assert theta_bar == pytest.approx(-0.5 * math.atan(2.0), abs=1e-15)
    assert q == 1  # |e| = 20 > r/2: the tack follows the side
    # heading east, the wanted heading is to the right (clockwise): Jaulin's rudder is positive
    assert delta_r == pytest.approx(G.delta_r_max * math.sin(0.5 * math.atan(2.0)), abs=1e-15)  # step 10


@pytest.mark.parametrize("theta, expected", [
    (math.radians(100.0), 1.0),  # 100 deg left of the line's heading: cos < 0, full rudder clockwise (11)
    (math.radians(-135.0), -1.0),  # 135 deg right of it: full rudder the other way
    (math.radians(-90.0), -1.0),  # cos(-90 deg) is 6e-17 >= 0: step 10, sin(-90 deg) = -1, as full
])
def test_beyond_ninety_degrees_off_the_heading_the_rudder_is_full(theta, expected):
    """On an eastward line with the wind abeam, theta_bar = 0: the error is theta itself."""
    delta_r, _, theta_bar, _ = line_following((50.0, 0.0), theta, math.pi / 2, *EAST_LINE, 1)
    assert theta_bar == 0.0 and delta_r == pytest.approx(expected * G.delta_r_max, abs=1e-15)


def test_the_books_sawtooth_rudder_is_a_third_of_the_listings_gain_near_the_heading():
    """(delta_r_max / pi) sawtooth(0.2) against delta_r_max sin(0.2), and 170 deg off: 17/18 of
    the largest angle against all of it."""
    book = LineFollowingGains(rudder="sawtooth")
    for theta, listing in ((0.2, G.delta_r_max * math.sin(0.2)), (math.radians(170.0), G.delta_r_max)):
        delta_r, *_ = line_following((50.0, 0.0), theta, math.pi / 2, *EAST_LINE, 1, book)
        assert delta_r == pytest.approx(G.delta_r_max / math.pi * theta, abs=1e-15)
        assert line_following((50.0, 0.0), theta, math.pi / 2, *EAST_LINE, 1)[0] == pytest.approx(listing,
                                                                                              abs=1e-15)


def test_an_unknown_rudder_law_is_refused_in_one_line():
    with pytest.raises(ValueError, match=r"rudder must be one of listing, sawtooth, got 'sine'"):
        LineFollowingGains(rudder="sine")


@pytest.mark.parametrize("q, expected", [(1, math.pi / 6), (-1, 5 * math.pi / 6)])
def test_a_line_straight_upwind_is_sailed_close_hauled_on_the_kept_tack(q, expected):
    """Wind blowing south (psi = -pi/2) along a northward line: theta* = pi/2 is in the no-go cone
    (cos(-pi) + cos(pi/3) < 0), so theta_bar = pi + psi - q zeta = pi/2 - q pi/3."""
    _, delta_s, theta_bar, kept = line_following((0.0, 50.0), math.pi / 2, -math.pi / 2, *NORTH_LINE, q)
    assert kept == q and theta_bar == pytest.approx(expected, abs=1e-15)
    # close-hauled, 60 deg off the wind: (pi/2) (cos(120 deg) + 1)/2 = pi/8
    assert delta_s == pytest.approx(math.pi / 8, abs=1e-15)


@pytest.mark.parametrize("x, q_in, q_out", [(-4.0, -1, -1), (-4.0, 1, 1),  # inside r/2: kept
                                            (-6.0, -1, 1), (6.0, 1, -1)])  # beyond: the side's
def test_the_tack_changes_only_beyond_half_the_cut_off(x, q_in, q_out):
    """e = det((0, 1), (x, 50)) = -x for the northward line."""
    _, _, theta_bar, q = line_following((x, 50.0), math.pi / 2, -math.pi / 2, *NORTH_LINE, q_in)
    assert q == q_out and theta_bar == pytest.approx(math.pi / 2 - q_out * math.pi / 3, abs=1e-15)


@pytest.mark.parametrize("x, expected", [
    (-8.0, math.pi / 2 - math.pi / 6),  # |e| = 8 < r: step 6, close-hauled on tack q = 1
    (-12.0, math.pi / 2 - math.atan(1.2)),  # |e| = 12 >= r: theta* itself, outside the cone
])
def test_near_an_upwind_line_the_line_itself_keeps_the_boat_close_hauled(x, expected):
    """Book form (gamma_inf = pi/2) with zeta = 30 deg along the northward line, wind blowing
    south: theta* = pi/2 - atan(e/r) leaves the no-go cone once e/r > tan 30 deg; within r of
    the line step 6 still sends the boat close-hauled (without it theta_bar = pi/2 - atan(0.8))."""
    gains = LineFollowingGains(gamma_inf=math.pi / 2, zeta=math.pi / 6)
    _, _, theta_bar, q = line_following((x, 50.0), math.pi / 2, -math.pi / 2, *NORTH_LINE, -1, gains)
    assert q == 1 and theta_bar == pytest.approx(expected, abs=1e-15)


def test_the_sail_law_gives_beta_abeam_and_pi_over_2_before_the_wind():
    gains = LineFollowingGains(beta=math.pi / 6)  # exponent log 3 / log 2, so (1/2)^it = 1/3
    for psi, expected in ((math.pi / 2, math.pi / 6), (0.0, math.pi / 2)):
        _, delta_s, theta_bar, _ = line_following((50.0, 0.0), 0.0, psi, *EAST_LINE, 1, gains)
        assert theta_bar == 0.0 and delta_s == pytest.approx(expected, abs=1e-15)


def test_sawtooth_wraps_to_minus_pi_pi():
    assert sawtooth(3 * math.pi / 2) == pytest.approx(-math.pi / 2)
    assert sawtooth(-math.pi) == math.pi and sawtooth(0.1) == pytest.approx(0.1, abs=1e-15)


def test_the_line_follower_beats_to_a_windward_mark_with_tacks_and_runs_back_past_the_start():
    """The 11:Metre in a steady 5.6 m/s northerly, calm water: a mark 200 m dead upwind of the
    start cannot be fetched, so the boat tacks (the apparent wind crosses the bow, counted from
    the run's table, not the law's state), rounds it and sails back past the start."""
    import numpy as np
    from sailmujoco.controllers.factories import line_following as factory

    from sailmujoco import suite

    env = suite.load("eleven_metre", "heading_hold", seed=0, wind_from_deg=0.0, gusts=False, wander=False,
                     time_limit=400.0)
    controller = factory(env)
    table = suite.rollout(env, controller)
    start_y = table["y"].iloc[0]
    rounded = int(np.argmax(table["y"].to_numpy() > start_y + 200.0))
    assert rounded > 0  # beyond the square line through the windward mark
    upwind = table.iloc[:rounded]
    awa = upwind["awa"].to_numpy()
    ahead = np.abs(awa) < math.pi / 2
    tacks = np.sum((np.sign(awa[1:]) != np.sign(awa[:-1])) & ahead[1:] & ahead[:-1])
    assert tacks >= 2
    assert (table["y"].iloc[rounded:] < start_y).any()  # back past the start
    # it beat within the corridor: never more than a few cut-offs (r = 10 m) off the line x = x0
    assert np.abs(upwind["x"] - table["x"].iloc[0]).max() < 40.0
