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
