"""The ROS 2 messages' fields against values computed by hand (REP-103/145 frames, WGS84)."""

import math

import numpy as np
import pytest

from sailmujoco.constants import GRAVITY
from sailmujoco.frames import apparent_wind_angle, matrix_from_euler, quat_from_euler, yaw_from_heading
from sailmujoco.ros2 import geodesy, messages

OSLO_FJORD = geodesy.Origin(latitude=59.9, longitude=10.7)


def test_heading_030_heeled_10_to_starboard_gives_the_hand_quaternion():
    # heading 030 (compass) is ENU yaw 60 deg; heel to starboard is +10 deg about body x (FLU):
    # q = q_z(60) q_x(10) = (cos 30 cos 5, cos 30 sin 5, sin 30 sin 5, sin 30 cos 5) as (w, x, y, z)
    yaw = yaw_from_heading(math.radians(30.0))
    q = quat_from_euler(math.radians(10.0), 0.0, yaw)
    fields = messages.imu(q, (0.0, 0.0, 0.0), (0.0, 0.0, GRAVITY))["orientation"]
    c30, s30, c5, s5 = math.cos(math.radians(30)), 0.5, math.cos(math.radians(5)), math.sin(math.radians(5))
    assert (fields["w"], fields["x"], fields["y"], fields["z"]) == pytest.approx(
        (c30 * c5, c30 * s5, s30 * s5, s30 * c5), abs=1e-12)


def test_an_accelerometer_at_rest_reads_gravity_up_and_heeled_tilts_it_to_port():
    level = messages.specific_force((0.0, 0.0, 0.0), np.eye(3))
    assert level == pytest.approx((0.0, 0.0, GRAVITY), abs=1e-12)
    heel = math.radians(10.0)  # starboard down: the port side (+y) is up, and reads g sin(heel)
    heeled = messages.specific_force((0.0, 0.0, 0.0), matrix_from_euler(heel, 0.0, 1.0))
    assert heeled == pytest.approx((0.0, GRAVITY * math.sin(heel), GRAVITY * math.cos(heel)), abs=1e-12)


def test_a_kilometre_north_and_east_moves_the_fix_by_the_ellipsoids_radii():
    lat = math.radians(OSLO_FJORD.latitude)
    w = 1.0 - geodesy.WGS84_E2 * math.sin(lat) ** 2
    meridian = geodesy.WGS84_A * (1.0 - geodesy.WGS84_E2) / w**1.5  # radius of curvature M
    prime = geodesy.WGS84_A / math.sqrt(w)  # N
    north = messages.nav_sat_fix((0.0, 1000.0, 0.0), OSLO_FJORD)
    assert north["latitude"] - OSLO_FJORD.latitude == pytest.approx(math.degrees(1000.0 / meridian), rel=1e-5)
    assert north["longitude"] == pytest.approx(OSLO_FJORD.longitude, abs=1e-12)
    # the tangent plane rises off the ellipsoid by d^2 / 2M
    assert north["altitude"] == pytest.approx(1000.0**2 / (2.0 * meridian), rel=1e-3)
    east = messages.nav_sat_fix((1000.0, 0.0, 0.0), OSLO_FJORD)
    assert east["longitude"] - OSLO_FJORD.longitude == pytest.approx(
        math.degrees(1000.0 / (prime * math.cos(lat))), rel=1e-5)


def test_enu_and_geodetic_round_trip_to_a_micrometre():
    for enu in ((0.0, 0.0, 0.0), (1234.5, -678.9, 3.2), (-20000.0, 15000.0, -1.0)):
        back = geodesy.enu_from_geodetic(*geodesy.geodetic_from_enu(enu, OSLO_FJORD), OSLO_FJORD)
        assert back == pytest.approx(enu, abs=1e-6)


def test_the_fix_states_its_covariance_only_when_the_receivers_error_is_known():
    unknown = messages.nav_sat_fix((0.0, 0.0, 0.0), OSLO_FJORD)
    assert unknown["position_covariance_type"] == messages.COVARIANCE_TYPE_UNKNOWN
    known = messages.nav_sat_fix((0.0, 0.0, 0.0), OSLO_FJORD, sigma_horizontal=2.5, sigma_vertical=5.0)
    assert known["position_covariance_type"] == messages.COVARIANCE_TYPE_DIAGONAL_KNOWN
    assert known["position_covariance"] == [6.25, 0, 0, 0, 6.25, 0, 0, 0, 25.0]


@pytest.mark.parametrize("awa_deg", [30.0, -45.0, 135.0, 180.0])
def test_the_apparent_wind_vector_reads_back_as_the_vanes_angle_and_speed(awa_deg):
    v = messages.apparent_wind(math.radians(awa_deg), 7.0)
    vector = (v["x"], v["y"], v["z"])
    assert math.hypot(*vector) == pytest.approx(7.0, rel=1e-12)
    assert math.degrees(apparent_wind_angle(vector)) == pytest.approx(awa_deg if awa_deg != 180.0 else 180.0)
    if awa_deg == 30.0:  # from the starboard bow: the air streams aft and to port
        assert vector[0] < 0.0 and vector[1] > 0.0


def test_an_origin_off_the_globe_is_one_line():
    with pytest.raises(ValueError, match=r"^origin latitude must be in \[-90, 90\] deg, got 91$"):
        geodesy.Origin(latitude=91, longitude=0.0)
