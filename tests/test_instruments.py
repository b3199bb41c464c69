"""A boat's instruments as one set: presets, one-line errors, seeded streams of their own, and
the typical set's readings against its figures."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from sailmujoco.boat.fitted import SENSOR_PRESETS as PRESETS
from sailmujoco.boat.fitted import SensorOptions, sensor_options
from sailmujoco.measurement.instruments import Instruments


def _truth(t=0.0, heading_deg=30.0):
    heading = math.radians(heading_deg)
    return SimpleNamespace(time=t, position=np.array([100.0, -50.0]), velocity=np.array([1.0, 1.7320508]),
                           heel=0.1, pitch=0.0, yaw=math.pi / 2 - heading, rates=np.array([0.0, 0.0, 0.0]),
                           apparent_wind_angle=0.6, apparent_wind_speed=7.0,
                           body_velocity=np.array([2.0, 0.0, 0.0]), current_body=np.zeros(3))


def test_presets_and_their_names():
    assert sensor_options(None) == PRESETS["perfect"] and PRESETS["perfect"].perfect
    assert not sensor_options("typical").perfect
    mine = sensor_options({"preset": "typical", "compass_noise_deg": 4.0})
    assert mine.compass_noise_deg == 4.0 and mine.gnss_cep == PRESETS["typical"].gnss_cep
    assert not sensor_options({"gnss_cep": 1.0}).perfect  # a figure given: no longer perfect


@pytest.mark.parametrize(("given", "message"), [
    ("exact", "sensors must be one of ['perfect', 'typical']"),
    ({"gnss_cap": 1.0}, "sensors.gnss_cap is not a sensor figure"),
    ({"gnss_cep": -1.0}, "sensors.gnss_cep must be a finite number >= 0"),
    ({"gnss_rate_hz": 0.0}, "sensors.gnss_rate_hz must be a finite number > 0"),
    ({"dip_deg": 95.0}, "sensors.dip_deg must be within -90 to 90"),
    ({"compass_tilt_compensated": "yes"}, "sensors.compass_tilt_compensated must be true or false"),
])
def test_bad_figures_are_refused_in_one_line_naming_the_key(given, message):
    with pytest.raises(ValueError, match=message.replace("[", r"\[").replace("]", r"\]")):
        sensor_options(given)


def test_the_same_seed_reads_the_same_and_each_instrument_has_its_own_stream():
    typical = PRESETS["typical"]
    a, b = Instruments(typical, 0.1, seed=3), Instruments(typical, 0.1, seed=3)
    c = Instruments(SensorOptions(**{**typical.__dict__, "compass_noise_deg": 4.0}), 0.1, seed=3)
    for k in range(30):
        ra, rb, rc = (i.read(_truth(0.1 * k)) for i in (a, b, c))
        assert ra["heading"] == rb["heading"] and np.array_equal(ra["position"], rb["position"])
        assert np.array_equal(ra["position"], rc["position"])  # the compass's figures leave the GNSS alone
    assert ra["heading"] != rc["heading"]
    other = Instruments(typical, 0.1, seed=4).read(_truth())
    assert not np.array_equal(other["position"], Instruments(typical, 0.1, seed=3).read(_truth())["position"])


def test_typical_gnss_error_has_its_cep_and_the_log_its_calibration():
    figures = sensor_options({"preset": "typical", "gnss_tau": 0.5})  # a short correlation time ...
    instruments = Instruments(figures, 1.0, seed=0)  # ... and a fix per 1 s step: nearly independent draws
    readings = [instruments.read(_truth(float(k))) for k in range(20000)]
    errors = np.array([r["position"] for r in readings]) - [100.0, -50.0]
    assert np.median(np.hypot(errors[:, 0], errors[:, 1])) == pytest.approx(2.5, rel=0.05)
    assert np.mean([r["speed_through_water"] for r in readings]) == pytest.approx(2.1, abs=2e-3)
