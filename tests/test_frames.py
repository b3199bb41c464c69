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


def test_wrap_angle_into_minus_pi_to_pi():
    pi = math.pi
    # the half-open interval: +pi, -pi and every odd multiple of pi land on -pi
    for angle in (pi, -pi, 3.0 * pi, -3.0 * pi, 5.0 * pi):
        assert frames.wrap_angle(angle) == -pi
    assert frames.wrap_angle(0.0) == 0.0
    assert frames.wrap_angle(-1e-3) == pytest.approx(-1e-3, abs=1e-15)
    assert frames.wrap_angle(2.0 * pi + 0.5) == pytest.approx(0.5, abs=1e-14)
    assert frames.wrap_angle(-0.5 - 4.0 * pi) == pytest.approx(-0.5, abs=1e-14)
    assert type(frames.wrap_angle(1.0)) is float
    array = np.array([[pi, 3.5 * pi], [-2.5 * pi, 0.25]])
    wrapped = frames.wrap_angle(array)
    assert isinstance(wrapped, np.ndarray) and wrapped.shape == array.shape
    assert wrapped == pytest.approx(np.array([[-pi, -0.5 * pi], [-0.5 * pi, 0.25]]), abs=1e-14)


def _random_angles(rng):
    pi = math.pi
    edges = [pi, -pi, 3 * pi, -3 * pi, 2 * pi, -2 * pi, 0.0, -0.0, np.nextafter(pi, 0.0),
             np.nextafter(-pi, 0.0), 1e-300, -5e-324, 1e12, -1e12]
    return np.concatenate([rng.uniform(-4.0, 4.0, 20000), rng.uniform(-60.0, 60.0, 20000),
                           rng.normal(0.0, 1e6, 2000), edges])


def test_wrap_angle_on_floats_arrays_and_in_a_kernel_gives_the_written_bits(rng):
    """The wrap returns the bits of the expression written out, on Python floats, on numpy
    arrays and compiled in a numba kernel (the kernels' flags of sailmujoco.jit.kernel)."""
    import numba

    angles = _random_angles(rng)
    as_floats = np.array([(a + math.pi) % (2.0 * math.pi) - math.pi for a in angles.tolist()])
    as_array = (angles + np.pi) % (2.0 * np.pi) - np.pi
    assert np.all((as_array >= -math.pi) & (as_array < math.pi))

    def bits(x):
        return np.asarray(x, dtype=np.float64).view(np.int64)

    assert np.array_equal(bits(as_floats), bits(as_array))  # Python's % and numpy's agree
    assert np.array_equal(bits([frames.wrap_angle(a) for a in angles.tolist()]), bits(as_floats))
    assert np.array_equal(bits(frames.wrap_angle(angles)), bits(as_array))
    assert np.array_equal(bits([frames.wrap_angle(a) for a in angles]), bits(as_array))  # numpy scalars

    flags = dict(nogil=True, error_model="numpy")

    @numba.njit(**flags)
    def written(a, out):
        for i in range(a.shape[0]):
            out[i] = (a[i] + math.pi) % (2.0 * math.pi) - math.pi

    @numba.njit(**flags)
    def called(a, out):
        for i in range(a.shape[0]):
            out[i] = frames.wrap_angle(a[i])

    @numba.njit(**flags)
    def on_array(a):
        return frames.wrap_angle(a)

    expected, got = np.empty_like(angles), np.empty_like(angles)
    written(angles, expected)
    called(angles, got)
    assert np.array_equal(bits(got), bits(expected))
    assert np.array_equal(bits(got), bits(as_array))
    assert np.array_equal(bits(on_array(angles)), bits(as_array))
