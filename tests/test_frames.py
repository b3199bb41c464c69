"""Frame conversions round-trip; paper-frame quantities come back."""

import math

import numpy as np
import pytest

from sailmujoco import frames


def test_vector_round_trips(rng):
    v = rng.normal(size=3)
    assert frames.enu_from_ned(frames.ned_from_enu(v)) == pytest.approx(v)
    assert frames.enu_from_nwu(frames.nwu_from_enu(v)) == pytest.approx(v)
    assert frames.flu_from_frd(frames.frd_from_flu(v)) == pytest.approx(v)
    # north is x in NED and NWU, y in ENU
    assert frames.ned_from_enu([0.0, 1.0, 0.0]) == pytest.approx([1.0, 0.0, 0.0])
    assert frames.nwu_from_enu([-1.0, 0.0, 0.0]) == pytest.approx([0.0, 1.0, 0.0])  # west


def test_euler_round_trip(rng):
    for _ in range(50):
        heel, pitch, yaw = rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-3, 3)
        rot = frames.matrix_from_euler(heel, pitch, yaw)
        assert np.array(frames.euler_from_matrix(rot)) == pytest.approx([heel, pitch, yaw])
        q = frames.quat_from_euler(heel, pitch, yaw)
        from sailmujoco.forces.boat import rotation_from_quat

        out = np.zeros((3, 3))
        rotation_from_quat(q, out)
        assert out == pytest.approx(rot)


def test_heel_and_pitch_signs():
    # positive heel: starboard side (-y) goes down
    rot = frames.matrix_from_euler(0.3, 0.0, 0.0)
    assert (rot @ [0.0, -1.0, 0.0])[2] < 0
    # positive pitch: bow up
    rot = frames.matrix_from_euler(0.0, 0.2, 0.0)
    assert (rot @ [1.0, 0.0, 0.0])[2] > 0


def test_heading_and_wille_wind_direction():
    assert float(frames.heading_from_yaw(0.0)) == pytest.approx(math.pi / 2)  # east
    assert float(frames.yaw_from_heading(frames.heading_from_yaw(0.7))) == pytest.approx(0.7)
    # Wille's close-hauled case: beta_w = 130 deg (blowing towards SE) = from 310 deg
    from_ = frames.direction_from_wille_beta_w(math.radians(130.0))
    assert math.degrees(float(frames.wrap_angle(from_))) % 360 == pytest.approx(310.0)
    v = frames.wind_velocity(5.0, from_)
    ned = frames.ned_from_enu(v)
    assert math.degrees(math.atan2(ned[1], ned[0])) == pytest.approx(130.0)


def test_apparent_wind_angle_sign():
    # air moving from starboard to port across the boat: wind comes from starboard: AWA > 0
    assert frames.apparent_wind_angle([0.0, 5.0, 0.0]) == pytest.approx(math.pi / 2)
    assert frames.apparent_wind_angle([-5.0, 0.0, 0.0]) == pytest.approx(0.0)  # head to wind
