"""Wind: NORSOK spectrum, log profile, wander, seeds, wind files."""

import math

import numpy as np
import pytest
from scipy.signal import welch

from sailmujoco.forces.wind import WindConfig, WindField, log_profile, norsok_spectrum


def test_gusts_match_the_norsok_spectrum():
    config = WindConfig(speed=10.0, seed=4, n_frequencies=400)
    field = WindField(config)
    z = 5.2
    fs = 2.0
    t = np.arange(0.0, 8 * 3600.0, 1.0 / fs)
    gust = field.gust(t, z)
    f, pxx = welch(gust, fs=fs, nperseg=4096, detrend=False)
    band = (f >= 0.01) & (f <= 0.4)
    expected = norsok_spectrum(f[band], z, 10.0)
    ratio = pxx[band] / expected
    # band averages over ~10 Welch bins to beat the estimator's variance
    chunks = np.array_split(ratio, 8)
    for chunk in chunks:
        assert np.mean(chunk) == pytest.approx(1.0, abs=0.2)
    # nothing above 0.4 Hz (the simulated band)
    assert np.max(pxx[f > 0.45]) < 1e-3 * np.max(pxx[band])


def test_same_seed_same_series_bit_for_bit():
    a = WindField(WindConfig(speed=8.0, seed=11))
    b = WindField(WindConfig(speed=8.0, seed=11))
    c = WindField(WindConfig(speed=8.0, seed=12))
    t = np.linspace(0, 300, 1001)
    va = np.array([a.velocity(ti, 5.0) for ti in t])
    vb = np.array([b.velocity(ti, 5.0) for ti in t])
    vc = np.array([c.velocity(ti, 5.0) for ti in t])
    assert np.array_equal(va, vb)
    assert not np.array_equal(va, vc)


def test_wander_does_not_depend_on_how_far_ahead_it_was_asked():
    a = WindField(WindConfig(speed=5.0, seed=1))
    b = WindField(WindConfig(speed=5.0, seed=1))
    b.ensure(5000.0)
    a.ensure(1000.0)
    a.ensure(5000.0)
    assert np.array_equal(a.wander[:40000], b.wander[:40000])


def test_log_profile_eq_40():
    assert float(log_profile(10.0, 7.0)) == pytest.approx(7.0)
    assert float(log_profile(5.2, 10.0)) < 10.0
    assert float(log_profile(1e-4, 10.0)) == 0.0


def test_direction_wander_saturates_at_five_degrees():
    field = WindField(WindConfig(speed=5.0, seed=2, wander_intensity=math.radians(3.0)))
    field.ensure(3600.0)
    assert np.max(np.abs(field.wander)) == pytest.approx(math.radians(5.0))


def test_wind_comes_from_its_direction():
    field = WindField(WindConfig(speed=6.0, direction_from=math.radians(90.0), gusts=False,
                                 wander=False))
    v = field.velocity(0.0, 10.0)
    assert v == pytest.approx([-6.0, 0.0, 0.0], abs=1e-12)  # from the east, blowing west


def test_bad_wind_file_gives_one_clear_error(tmp_path):
    bad = tmp_path / "wind.toml"
    bad.write_text("speed = [unclosed\n")
    with pytest.raises(ValueError, match="does not parse as TOML"):
        WindConfig.from_toml(bad)
    unknown = tmp_path / "unknown.toml"
    unknown.write_text("[wind]\nspeeed = 3\n")
    with pytest.raises(ValueError, match="unknown key 'speeed'"):
        WindConfig.from_toml(unknown)
    negative = tmp_path / "neg.toml"
    negative.write_text("speed = -3\n")
    with pytest.raises(ValueError, match="speed must be between 0 and 100 m/s"):
        WindConfig.from_toml(negative)
    good = tmp_path / "good.toml"
    good.write_text("[wind]\nspeed = 5\ndirection_from_deg = 130\nseed = 3\n")
    assert WindConfig.from_toml(good).direction_from == pytest.approx(math.radians(130))
    with pytest.raises(ValueError, match="does not exist"):
        WindConfig.from_toml(tmp_path / "missing.toml")


def test_wind_at_three_heights_is_each_height_alone():
    """The kernel's one evaluation for the sail, topsides and mast gives, for each
    height, the bits of the one-height evaluation, and both agree with eqs. 39-41 written out
    here with numpy (mean log profile + sum of cosines with amplitudes linear in ln z)."""
    from sailmujoco.forces.wind import WANDER_DT, wind_velocity
    from sailmujoco.forces.wind_kernels import wind_velocities

    config = WindConfig(speed=7.0, direction_from=0.6, seed=3, speed_oscillation=1.5,
                        direction_oscillation=0.2, oscillation_frequency=0.05)
    field = WindField(config)
    field.ensure(40.0)
    args = (config.speed, config.direction_from, field.oscillation, field.gust_frequency,
            field.gust_phase, field.gust_amplitude, field.log_z, WANDER_DT, field.wander)
    rng = np.random.default_rng(5)
    heights = [0.001, 0.05, 0.4, 1.3, 3.0, 9.0, 25.0, 400.0]  # from below z0 to above the table
    for _ in range(60):
        t = float(rng.uniform(0.0, 35.0))
        picked = rng.choice(heights, 3) if rng.random() < 0.5 else rng.uniform(0.1, 12.0, 3)
        zs = [float(z) for z in picked]
        alone = np.zeros((3, 3))
        for i, z in enumerate(zs):
            wind_velocity(t, z, *args, alone[i])
        for count in (1, 2, 3):
            together = np.zeros(9)
            cache = np.full(field.gust_frequency.size + 1, np.nan)
            wind_velocities(t, zs[0], zs[1], zs[2], count, *args, cache, together)
            assert np.array_equal(together[:3 * count], alone[:count].ravel())
        for i, z in enumerate(zs):  # eqs. 39-41 by hand
            s = math.sin(2.0 * math.pi * field.oscillation[2] * t)
            mean = (config.speed + field.oscillation[0] * s) * float(log_profile(z, 1.0))
            lz = np.clip(math.log(z), field.log_z[0], field.log_z[-1])
            amp = np.array([np.interp(lz, field.log_z, field.gust_amplitude[:, k])
                            for k in range(field.gust_frequency.size)])
            gust = np.sum(amp * np.cos(2.0 * math.pi * field.gust_frequency * t + field.gust_phase))
            bearing = field.direction_from(t)
            speed = mean + gust
            expected = [-speed * math.sin(bearing), -speed * math.cos(bearing), 0.0]
            np.testing.assert_allclose(alone[i], expected, rtol=1e-10, atol=1e-10)


def test_the_gust_cosines_are_the_c_library_s_to_two_units_in_the_last_place():
    """The step's gust cosines (a polynomial on vector lanes) against math.cos, over an hour of
    gusts: within 2 units in the last place of each cosine."""
    from sailmujoco.forces.wind_kernels import gust_cosines

    rng = np.random.default_rng(5)
    frequency, phase = rng.uniform(0.001, 0.5, 100), rng.uniform(0.0, 2 * math.pi, 100)
    cache = np.full(101, np.nan)
    for t in np.linspace(0.0, 3600.0, 97):
        gust_cosines(t, frequency, phase, cache)
        exact = np.array([math.cos(2.0 * math.pi * t * f + p) for f, p in zip(frequency, phase, strict=True)])
        assert np.all(np.abs(cache[1:] - exact) <= 2 * np.spacing(np.maximum(np.abs(exact), 1e-300)) + 1e-300)
