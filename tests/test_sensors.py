"""Sensor models against first principles: each noise's standard deviation and correlation time
from long series, GNSS hold and latency, the masthead vane's kinematics and heeled plane, an
untilted compass's heeling error in closed form, and the true-wind triangle."""

import math

import numpy as np
import pytest

from sailmujoco.frames import matrix_from_euler, wind_velocity, yaw_from_heading
from sailmujoco.measurement.noise import AngleLowPass, GaussMarkov, LowPass, RandomWalk
from sailmujoco.measurement.sensors import (
    CEP_PER_SIGMA,
    Compass,
    Gnss,
    Gyro,
    MastheadVane,
    SpeedLog,
    earth_field,
    field_in_body,
    level_heading,
    masthead_flow,
    tilt_compensated_heading,
    untilted_heading,
    vane_reading,
)
from sailmujoco.measurement.true_wind import TrueWindEstimate, true_wind


def test_gauss_markov_has_its_sigma_and_its_correlation_time():
    sigma, tau, dt = 2.0, 5.0, 0.1
    process = GaussMarkov(sigma, tau, dt, np.random.default_rng(1), shape=(400,))  # 400 independent chains
    lag = int(round(tau / dt))
    series = np.array([process.step().copy() for _ in range(3000)])  # (time, chain)
    assert series.std() == pytest.approx(sigma, rel=0.03)
    correlation = np.mean(series[:-lag] * series[lag:]) / np.mean(series * series)
    assert correlation == pytest.approx(math.exp(-1.0), abs=0.02)  # exp(-lag / tau) at lag = tau


def test_random_walk_variance_grows_as_intensity_squared_times_time():
    sigma_rw, dt, steps = 0.3, 0.1, 50
    rng = np.random.default_rng(2)
    ends = []
    for _ in range(3000):
        walk = RandomWalk(sigma_rw, dt, rng)
        for _ in range(steps):
            walk.step()
        ends.append(walk.value)
    assert np.var(ends) == pytest.approx(sigma_rw ** 2 * steps * dt, rel=0.06)


def test_a_first_order_filter_reaches_one_minus_exp_minus_t_over_tau():
    lp = LowPass(tau=2.0, dt=0.1)
    lp.step(0.0)
    for _ in range(20):  # 2 s = one time constant
        out = lp.step(1.0)
    assert float(out) == pytest.approx(1.0 - math.exp(-1.0), rel=1e-12)
    angle = AngleLowPass(tau=1.0, dt=0.1)
    angle.step(math.pi - 0.01)
    assert abs(angle.step(-math.pi + 0.01)) > 3.0  # filtered across the seam, not through zero


def test_gnss_is_held_between_fixes_and_late_by_its_latency():
    dt = 0.1
    gnss = Gnss(dt, np.random.default_rng(0), rate=2.0, latency=0.3)  # a fix every 5 steps, 3 steps late
    reported = [gnss.measure((float(k), 0.0), (0.0, float(k)))[0][0] for k in range(30)]
    for k, x in enumerate(reported):
        fix_step = 5 * (k // 5)
        assert x == max(fix_step - 3, 0)  # the truth 3 steps before the fix, held until the next


def test_gnss_cep_from_its_per_axis_sigma():
    cep = 2.5  # m, u-blox M8 datasheet
    gnss = Gnss(1.0, np.random.default_rng(3), rate=1.0, position_sigma=cep / CEP_PER_SIGMA, position_tau=2.0)
    errors = np.array([gnss.measure((0.0, 0.0), (0.0, 0.0))[0] for _ in range(40000)])
    assert np.median(np.hypot(errors[:, 0], errors[:, 1])) == pytest.approx(cep, rel=0.04)
    assert CEP_PER_SIGMA == pytest.approx(1.1774, abs=1e-4)


@pytest.mark.parametrize("heel_deg", [-20.0, 10.0, 25.0])
@pytest.mark.parametrize("heading_deg", [0.0, 45.0, 90.0, 200.0])
def test_untilted_compass_heeling_error_in_closed_form(heel_deg, heading_deg):
    dip, heel, heading = math.radians(66.0), math.radians(heel_deg), math.radians(heading_deg)
    rot = matrix_from_euler(heel, 0.0, float(yaw_from_heading(heading)))
    # The field north and dip below the horizon; the hull's athwartships axis, heeled by phi about
    # the fore-and-aft axis, picks up -sin(phi) of the vertical part: m_x = H cos psi,
    # m_y = H sin psi cos phi - Z sin phi, so psi_read = atan2(sin psi cos phi - tan(dip) sin phi, cos psi)
    across = math.sin(heading) * math.cos(heel) - math.tan(dip) * math.sin(heel)
    expected = math.atan2(across, math.cos(heading))
    assert untilted_heading(rot, dip) == pytest.approx(expected, abs=1e-12)


def test_untilted_compass_errs_16_74_degrees_heeled_10_at_dip_60_heading_north():
    rot = matrix_from_euler(math.radians(10.0), 0.0, math.pi / 2)  # heading north
    error = math.degrees(untilted_heading(rot, math.radians(60.0)))
    assert error == pytest.approx(-16.740, abs=0.001)  # -atan(tan 60 deg sin 10 deg)


def test_tilt_compensated_compass_with_a_perfect_inclinometer_reads_the_heading():
    compass = Compass(np.random.default_rng(0), dip=math.radians(66.0), tilt_compensated=True)
    for heel, pitch, heading in ((0.3, -0.1, 1.0), (-0.5, 0.2, -2.5), (0.0, 0.0, 0.1)):
        yaw = float(yaw_from_heading(heading))
        rot = matrix_from_euler(heel, pitch, yaw)
        reference = tilt_compensated_heading(rot, math.radians(66.0), heel, pitch)
        assert reference == pytest.approx(heading, abs=1e-12)
        assert compass.measure(heel, pitch, yaw) == pytest.approx(heading, abs=1e-12)


def test_the_compass_per_step_form_is_the_matrix_form():
    rng = np.random.default_rng(7)
    untilted = Compass(rng, dip=1.1, tilt_compensated=False)
    for heel, pitch, yaw, dip in rng.uniform((-1.0, -0.5, -3.1, -1.5), (1.0, 0.5, 3.1, 1.5), (200, 4)):
        rot = matrix_from_euler(heel, pitch, yaw)
        assert field_in_body(heel, pitch, yaw, dip) == pytest.approx(rot.T @ earth_field(dip), abs=1e-14)
        assert level_heading(field_in_body(heel, pitch, yaw, 1.1), 0.0, 0.0) == pytest.approx(
            untilted_heading(rot, 1.1), abs=1e-12)
        assert untilted.measure(heel, pitch, yaw) == pytest.approx(untilted_heading(rot, 1.1), abs=1e-12)


def test_compass_noise_and_deviation():
    compass = Compass(np.random.default_rng(4), dip=1.0, tilt_compensated=True, noise=math.radians(2.0),
                      deviation=math.radians(3.0))
    readings = np.array([compass.measure(0.0, 0.0, float(yaw_from_heading(0.5))) for _ in range(20000)]) - 0.5
    assert math.degrees(readings.mean()) == pytest.approx(3.0, abs=0.05)
    assert math.degrees(readings.std()) == pytest.approx(2.0, rel=0.03)


def test_gyro_noise_and_bias_walk():
    dt = 0.1
    gyro = Gyro(dt, np.random.default_rng(5), noise=0.01, bias_walk=0.0, bias=0.02)
    readings = np.array([gyro.measure((0.1, 0.0, -0.2)) for _ in range(20000)])
    assert readings.mean(axis=0) == pytest.approx([0.12, 0.02, -0.18], abs=5e-4)
    assert readings.std(axis=0) == pytest.approx([0.01] * 3, rel=0.03)


def test_masthead_vane_on_a_rolling_boat_in_still_air_reads_minus_omega_cross_r():
    height, roll_rate = 2.0, 0.5  # a 2 m mast rolling at 0.5 rad/s (starboard side going down)
    flow = masthead_flow(np.eye(3), np.zeros(3), (roll_rate, 0.0, 0.0), (0.0, 0.0, height), np.zeros(3))
    assert flow == pytest.approx([0.0, roll_rate * height, 0.0], abs=1e-15)  # -(omega x r)
    awa, aws = MastheadVane(0.1, np.random.default_rng(0)).measure(flow)
    assert aws == pytest.approx(1.0, abs=1e-15)  # the 1 m/s
    assert awa == pytest.approx(math.pi / 2, abs=1e-15)  # the masthead swings to starboard: air from there


@pytest.mark.parametrize("heel_deg", [0.0, 15.0, 30.0])
def test_masthead_vane_on_a_heeled_boat_reads_the_flow_in_the_mast_plane(heel_deg):
    heel, speed = math.radians(heel_deg), 8.0
    heading = 0.0  # north; the true wind from 060 deg, the boat at rest
    rot = matrix_from_euler(heel, 0.0, float(yaw_from_heading(heading)))
    wind = wind_velocity(speed, math.radians(60.0))
    awa, aws = vane_reading(masthead_flow(rot, np.zeros(3), np.zeros(3), (0.0, 0.0, 10.0), wind))
    along = -speed * math.cos(math.radians(60.0))  # the air's velocity forward (it blows aft)
    across = speed * math.sin(math.radians(60.0)) * math.cos(heel)  # to port, foreshortened by the heel
    assert aws == pytest.approx(math.hypot(along, across), rel=1e-12)
    assert awa == pytest.approx(math.atan2(across, -along), abs=1e-12)


def test_speed_log_scale_error_and_noise():
    log = SpeedLog(np.random.default_rng(6), scale_error=0.05, noise=0.02)
    readings = np.array([log.measure(3.0) for _ in range(20000)])
    assert readings.mean() == pytest.approx(3.15, abs=1e-3)
    assert readings.std() == pytest.approx(0.02, rel=0.03)


def test_true_wind_triangle_and_its_filter():
    heading = math.radians(30.0)
    boat = 2.0 * np.array([math.sin(heading), math.cos(heading), 0.0])  # 2 m/s on the heading
    wind = wind_velocity(6.0, 0.0)  # 6 m/s from the north
    rot = matrix_from_euler(0.0, 0.0, float(yaw_from_heading(heading)))
    awa, aws = vane_reading(masthead_flow(rot, boat, np.zeros(3), (0.0, 0.0, 5.0), wind))
    speed, direction = true_wind(awa, aws, heading, boat[:2])
    assert speed == pytest.approx(6.0, abs=1e-12) and direction == pytest.approx(0.0, abs=1e-12)
    estimate = TrueWindEstimate(dt=0.1, tau=3.0)
    estimate.update(awa, aws, heading, boat[:2])
    wind = wind_velocity(8.0, 0.0)  # a step to 8 m/s
    awa, aws = vane_reading(masthead_flow(rot, boat, np.zeros(3), (0.0, 0.0, 5.0), wind))
    for _ in range(150):  # 15 s = 5 tau
        speed, direction = estimate.update(awa, aws, heading, boat[:2])
    assert speed == pytest.approx(8.0 - 2.0 * math.exp(-5.0), abs=1e-9)
    assert direction == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("bad", [-1.0, float("nan"), "2"])
def test_bad_sensor_values_are_refused_in_one_line_naming_them(bad):
    with pytest.raises(ValueError, match="sigma must be a finite number >= 0"):
        GaussMarkov(bad, 1.0, 0.1, np.random.default_rng(0))


@pytest.mark.parametrize("awa_deg, expected_deg", [(30.0, 30.0 + 4.0 * math.cos(math.radians(30.0))),
                                                   (-30.0, -30.0 - 4.0 * math.cos(math.radians(30.0))),
                                                   (5.0, 5.0 + 4.0 * math.cos(math.radians(5.0))),
                                                   (90.0, 90.0), (135.0, 135.0), (-170.0, -170.0)])
def test_the_sails_upwash_turns_the_masthead_flow_away_from_the_bow(awa_deg, expected_deg):
    """4 deg of upwash close-hauled: the vane reads the flow turned away from the bow by
    4 cos(AWA) forward of the beam, on either tack, and unchanged abaft it; the speed unchanged."""
    vane = MastheadVane(0.1, np.random.default_rng(0), upwash=math.radians(4.0))
    awa = math.radians(awa_deg)
    flow = (-6.0 * math.cos(awa), 6.0 * math.sin(awa))  # the air's velocity at the masthead, body
    got_awa, got_aws = vane.measure(flow)
    assert math.degrees(got_awa) == pytest.approx(expected_deg, abs=1e-9)
    assert got_aws == pytest.approx(6.0, rel=1e-12)
