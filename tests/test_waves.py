"""The sea state against linear wave theory, the spectra's own integrals and the seeds.

Expected values come from deep-water Airy theory (k = omega^2/g, c = omega/k, orbital speed
a omega e^(kz)), from the spectral formulas integrated here with scipy, and from the wind-sea
relations of Pierson & Moskowitz (1964) and Hasselmann et al. (1973) worked by hand.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import minimize_scalar
from scipy.signal import welch

from sailmujoco.constants import GRAVITY as G
from sailmujoco.constants import RHO_WATER
from sailmujoco.forces.wave_spectra import spectrum_density
from sailmujoco.forces.waves import (
    components,
    dynamic_pressure,
    elevation,
    orbital_velocity,
    ramp,
)
from sailmujoco.forces.wind import WindConfig, WindField
from sailmujoco.frames import wind_velocity
from sailmujoco.options import N_COMPONENTS, WaveConfig

H, T = 1.0, 6.0  # m, s: the regular wave
FROM = math.radians(240.0)  # it comes from WSW, so it travels toward bearing 60 deg
TRAVEL = np.array([math.sin(math.radians(60.0)), math.cos(math.radians(60.0))])  # ENU unit
REGULAR = WaveConfig(spectrum="regular", hs=H, tp=T, direction_from=FROM)
OMEGA = 2.0 * math.pi / T
K = OMEGA**2 / G  # deep-water dispersion
AFTER = 20.0 * T  # s, well past the ramp


def _along(s, origin=(3.0, -2.0), direction=TRAVEL):
    """World (x, y) of the points origin + s * direction."""
    s = np.asarray(s, dtype=float)
    return origin[0] + s * direction[0], origin[1] + s * direction[1]


def test_regular_wave_amplitude_is_half_the_height_and_period_is_t():
    t = AFTER + np.linspace(0.0, T, 4001)
    eta = elevation(REGULAR, t, 3.0, -2.0)
    assert eta.max() == pytest.approx(H / 2, abs=1e-6)
    assert eta.min() == pytest.approx(-H / 2, abs=1e-6)
    assert elevation(REGULAR, t + T, 3.0, -2.0) == pytest.approx(eta, abs=1e-12)
    assert elevation(REGULAR, t + T / 2, 3.0, -2.0) == pytest.approx(-eta, abs=1e-12)


def test_regular_wavelength_is_g_t_squared_over_two_pi_along_the_travel_direction():
    length = G * T**2 / (2.0 * math.pi)  # 56.2 m
    s = np.linspace(0.0, length, 101)
    t = AFTER + 1.3
    eta = elevation(REGULAR, t, *_along(s))
    assert np.ptp(eta) > 0.9 * H  # a full wave along the line
    assert elevation(REGULAR, t, *_along(s + length)) == pytest.approx(eta, abs=1e-9)
    assert elevation(REGULAR, t, *_along(s + length / 2)) == pytest.approx(-eta, abs=1e-9)
    crest_line = np.array([-TRAVEL[1], TRAVEL[0]])  # along the crests nothing changes
    x, y = _along(s)
    assert elevation(REGULAR, t, x + 37.0 * crest_line[0], y + 37.0 * crest_line[1]) == \
        pytest.approx(eta, abs=1e-9)


def _crest(config, t, direction, start, length):
    """Position s (m) of the highest point on [start, start + length) along ``direction``."""
    s = start + np.linspace(0.0, length, 200001, endpoint=False)
    return s[np.argmax(elevation(config, t, *_along(s, (0.0, 0.0), direction)))]


def test_regular_crest_moves_at_omega_over_k():
    length = G * T**2 / (2.0 * math.pi)
    s0 = _crest(REGULAR, AFTER, TRAVEL, 0.0, length)
    s1 = _crest(REGULAR, AFTER + 2.0, TRAVEL, s0, length)
    assert (s1 - s0) / 2.0 == pytest.approx(OMEGA / K, rel=1e-4)  # g T / 2 pi = 9.37 m/s


@pytest.mark.parametrize("bearing, moves", [(0.0, (0.0, -1.0)), (math.pi / 2, (-1.0, 0.0))])
def test_waves_from_a_bearing_travel_away_from_it(bearing, moves):
    config = WaveConfig(spectrum="regular", hs=H, tp=T, direction_from=bearing)
    length = G * T**2 / (2.0 * math.pi)
    s0 = _crest(config, AFTER, np.array(moves), 0.0, length)
    s1 = _crest(config, AFTER + 1.0, np.array(moves), s0, length)
    assert s1 - s0 == pytest.approx(OMEGA / K, rel=1e-3)  # toward -y from the north, -x from the east
    air = wind_velocity(1.0, bearing)[:2]  # the wind from the same bearing blows the same way
    assert air == pytest.approx(moves, abs=1e-12)


def test_regular_orbits_are_circles_of_speed_omega_a_e_kz():
    a = H / 2
    x, y = _along(0.0)
    t = AFTER + np.linspace(0.0, T, 721)
    for depth in (0.0, -1.0, -4.0):  # below the local surface
        z = depth + elevation(REGULAR, t, x, y)
        u = orbital_velocity(REGULAR, t, x, y, z)
        along, across, up = u @ np.append(TRAVEL, 0.0), u @ [-TRAVEL[1], TRAVEL[0], 0.0], u[:, 2]
        speed = OMEGA * a * math.exp(K * depth)
        assert np.hypot(along, up) == pytest.approx(speed, rel=1e-12)
        assert np.abs(across).max() < 1e-12 * speed
        angle = np.unwrap(np.arctan2(up, along))
        assert np.diff(angle) == pytest.approx(-OMEGA * np.diff(t), rel=1e-9)  # uniform turning
    # where the surface crosses still water, a fixed depth z is z below the surface
    t0 = AFTER + 0.75 * T  # theta = -3 pi/2 at the point s = 0 along the travel line from (0, 0)
    x0, y0 = _along(0.0, (0.0, 0.0))
    assert float(elevation(REGULAR, t0, x0, y0)) == pytest.approx(0.0, abs=1e-12)
    for z in (-1.0, -3.0, -10.0):
        u = orbital_velocity(REGULAR, t0, x0, y0, z)
        assert np.linalg.norm(u) == pytest.approx(OMEGA * a * math.exp(K * z), rel=1e-12)


SEAS = [
    REGULAR,
    WaveConfig(spectrum="jonswap", hs=2.0, tp=7.0, direction_from=1.0, spreading=4.0, seed=3),
]


@pytest.mark.parametrize("config", SEAS, ids=["regular", "short_crested"])
def test_vertical_velocity_at_the_surface_is_the_surface_rise_rate(config):
    rng = np.random.default_rng(0)
    t = AFTER + rng.uniform(0.0, 100.0, 50)
    x, y = rng.uniform(-50.0, 50.0, (2, 50))
    h = 1e-4
    deta_dt = (elevation(config, t + h, x, y) - elevation(config, t - h, x, y)) / (2.0 * h)
    w = orbital_velocity(config, t, x, y, elevation(config, t, x, y))[:, 2]
    assert w == pytest.approx(deta_dt, abs=1e-7)


def _divergence_ratio(config):
    """rms(div u) / rms(dw/dz) at random points below the surface, by central differences."""
    rng = np.random.default_rng(1)
    t = AFTER + rng.uniform(0.0, 60.0, 40)
    x, y = rng.uniform(-30.0, 30.0, (2, 40))
    z = rng.uniform(-4.0, -0.1, 40)
    h = 1e-3
    point = np.array([x, y, z])
    div = np.zeros(40)
    for i in range(3):
        step = h * np.eye(3)[i][:, None]
        div += (orbital_velocity(config, t, *(point + step))[:, i]
                - orbital_velocity(config, t, *(point - step))[:, i]) / (2.0 * h)
    dw_dz = (orbital_velocity(config, t, x, y, z + h)[:, 2]
             - orbital_velocity(config, t, x, y, z - h)[:, 2]) / (2.0 * h)
    return np.sqrt(np.mean(div**2) / np.mean(dw_dz**2))


@pytest.mark.parametrize("spectrum, tp, spreading", [("regular", T, None), ("pm", 5.0, 2.0)],
                         ids=["regular", "short_crested"])
def test_the_flow_is_divergence_free_to_first_order(spectrum, tp, spreading):
    """div u = 0 for each Airy component; the stretching to the local surface leaves a residue
    of second order: relative to the terms it is of the order of the steepness a k."""
    gentle = WaveConfig(spectrum=spectrum, hs=0.01, tp=tp, direction_from=2.0,
                        spreading=spreading, seed=1)
    ten_times = WaveConfig(spectrum=spectrum, hs=0.1, tp=tp, direction_from=2.0,
                           spreading=spreading, seed=1)
    assert _divergence_ratio(gentle) < 2e-3  # a k ~ 6e-4 (regular) .. 8e-4 (pm at the peak)
    assert _divergence_ratio(ten_times) / _divergence_ratio(gentle) == pytest.approx(10.0, rel=0.1)


@pytest.mark.parametrize("config", SEAS, ids=["regular", "short_crested"])
def test_total_pressure_is_zero_at_the_surface(config):
    """p = -rho g z + p_d vanishes at z = eta: to first order in linear theory, exactly here
    because the depth is stretched to the local surface."""
    rng = np.random.default_rng(2)
    t = AFTER + rng.uniform(0.0, 100.0, 50)
    x, y = rng.uniform(-50.0, 50.0, (2, 50))
    eta = elevation(config, t, x, y)
    assert np.ptp(eta) > 0.5  # the surface really moves
    total = -RHO_WATER * G * eta + dynamic_pressure(config, t, x, y, eta)
    assert np.abs(total).max() < 1e-9 * RHO_WATER * G
    deep = dynamic_pressure(config, t, x, y, -1000.0)  # e^(k z) has died out, even at 0.5 omega_p
    assert np.abs(deep).max() < 1e-6 * RHO_WATER * G


def test_a_crest_never_evaluates_above_the_water():
    config = WaveConfig(spectrum="regular", hs=2.0, tp=T)  # from the north, crest at the origin
    t = AFTER  # a whole number of periods: theta = 0 at the origin
    a = 1.0
    assert float(elevation(config, t, 0.0, 0.0)) == pytest.approx(a, abs=1e-12)
    surface = orbital_velocity(config, t, 0.0, 0.0, a)
    assert surface == pytest.approx([0.0, -a * OMEGA, 0.0], abs=1e-9)  # a omega, not a omega e^(k a)
    above = orbital_velocity(config, t, 0.0, 0.0, a + 3.0)
    assert above == pytest.approx(surface, abs=1e-12)
    steep = WaveConfig(spectrum="jonswap", hs=8.0, tp=10.0, spreading=3.0)
    u = orbital_velocity(steep, AFTER + np.arange(0.0, 300.0, 0.5), 0.0, 0.0, 20.0)
    comp = components(steep)
    assert np.all(np.isfinite(u))
    assert np.linalg.norm(u, axis=-1).max() <= np.sum(comp.amplitude * comp.omega)


def test_the_ramp_starts_from_calm_water():
    config = WaveConfig(spectrum="jonswap", hs=2.0, tp=8.0, seed=4)
    duration = 3.0 * config.tp
    assert float(ramp(config, 0.0)) == 0.0
    assert float(ramp(config, -5.0)) == 0.0
    assert float(ramp(config, duration / 2)) == pytest.approx(0.5, abs=1e-15)
    assert float(ramp(config, duration)) == 1.0
    assert float(ramp(config, 10.0 * duration)) == 1.0
    assert np.all(np.diff(ramp(config, np.linspace(0.0, duration, 500))) > 0.0)
    x = np.linspace(-100.0, 100.0, 21)
    assert np.all(elevation(config, 0.0, x, 7.0) == 0.0)
    assert np.all(orbital_velocity(config, 0.0, x, 7.0, -1.0) == 0.0)
    later = AFTER + np.arange(0.0, 100.0)
    assert np.array_equal(elevation(config, later, 1.0, 2.0),
                          elevation(config, later, 1.0, 2.0) * ramp(config, later))


@pytest.mark.parametrize("spectrum", ["regular", "pm", "jonswap"])
def test_calm_water_is_still(spectrum):
    config = WaveConfig(spectrum=spectrum, hs=0.0, tp=7.0, seed=9)
    rng = np.random.default_rng(3)
    t = rng.uniform(0.0, 1000.0, 30)
    x, y, z = rng.uniform(-100.0, 0.0, (3, 30))
    assert np.all(elevation(config, t, x, y) == 0.0)
    assert np.all(orbital_velocity(config, t, x, y, z) == 0.0)
    assert np.all(dynamic_pressure(config, t, x, y, z) == 0.0)


def test_spectral_formulas_integrate_to_hs_squared_over_16_and_peak_at_omega_p():
    hs, tp = 2.0, 8.0
    wp = 2.0 * math.pi / tp
    pm = WaveConfig(spectrum="pm", hs=hs, tp=tp)
    js = WaveConfig(spectrum="jonswap", hs=hs, tp=tp, gamma=3.3)
    s_pm = 5.0 / 16.0 * hs**2 / wp * math.exp(-1.25)  # (5/16) Hs^2 wp^4 wp^-5 e^(-5/4)
    assert float(spectrum_density(pm, wp)) == pytest.approx(s_pm, rel=1e-12)
    assert float(spectrum_density(js, wp)) == pytest.approx((1 - 0.287 * math.log(3.3)) * 3.3 * s_pm,
                                                            rel=1e-12)
    for config, rel in ((pm, 1e-6), (js, 5e-3)):  # A_gamma is DNV's approximation
        m0 = quad(lambda w, config=config: float(spectrum_density(config, w)), 0.05 * wp, 100 * wp,
                  points=[wp], limit=400)[0]
        assert m0 == pytest.approx(hs**2 / 16.0, rel=rel)
        grid = np.linspace(0.5 * wp, 2.0 * wp, 30001)
        assert grid[np.argmax(spectrum_density(config, grid))] == pytest.approx(wp, abs=1e-4)


@pytest.mark.parametrize("spectrum", ["pm", "jonswap"])
def test_components_carry_the_spectrum_energy(spectrum):
    hs = 2.5
    comp = components(WaveConfig(spectrum=spectrum, hs=hs, tp=8.0, seed=2))
    assert np.sum(comp.amplitude**2 / 2.0) == pytest.approx(hs**2 / 16.0, rel=0.01)
    assert comp.k == pytest.approx(comp.omega**2 / G, rel=1e-15)
    for array in (comp.amplitude, comp.omega, comp.k, comp.direction_to, comp.phase):
        assert array.dtype == np.float64 and array.shape == (N_COMPONENTS,) and array.flags.c_contiguous


def _dnv_spectrum(f, hs, fp, gamma):
    """JONSWAP (Pierson-Moskowitz at gamma = 1) per hertz, DNV-RP-C205 eqs. 3.5.5.1-3.5.5.4."""
    w, wp = 2.0 * math.pi * f, 2.0 * math.pi * fp
    pm = 5.0 / 16.0 * hs**2 * wp**4 * w**-5 * np.exp(-1.25 * (w / wp) ** -4)
    sigma = np.where(w <= wp, 0.07, 0.09)
    peak = gamma ** np.exp(-((w - wp) ** 2) / (2.0 * sigma**2 * wp**2))
    return 2.0 * math.pi * (1.0 - 0.287 * math.log(gamma)) * pm * peak


def _hour(config, dt=0.25):
    """Elevation at a point over one hour after the ramp, and the times."""
    t = 3.0 * config.tp + np.arange(0.0, 3600.0, dt)
    return t, elevation(config, t, 12.0, -7.0)


@pytest.mark.parametrize("spectrum", ["pm", "jonswap"])
def test_an_hour_of_sea_has_four_std_equal_to_hs_and_its_peak_at_one_over_tp(spectrum):
    hs, tp = 2.0, 8.0
    # 100 components: lines closer than the periodogram's 1/256 Hz bins blend into the spectrum
    # (the default's lines, 1/57 Hz apart, are checked for their energy above)
    config = WaveConfig(spectrum=spectrum, hs=hs, tp=tp, seed=7, n_components=100)
    t, eta = _hour(config)
    assert 4.0 * eta.std() == pytest.approx(hs, rel=0.03)
    f, pxx = welch(eta, fs=4.0, nperseg=1024, detrend=False)  # 256 s segments
    fit = (f > 0.7 / tp) & (f < 3.0 / tp)
    gamma = 1.0 if spectrum == "pm" else 3.3

    def misfit(fp):  # the DNV form written out here, in Hz: S(f) = 2 pi S(omega)
        return np.sum((np.log(pxx[fit]) - np.log(_dnv_spectrum(f[fit], 4.0 * eta.std(), fp, gamma)))**2)

    peak = minimize_scalar(misfit, bounds=(0.5 / tp, 2.0 / tp), method="bounded").x
    assert peak == pytest.approx(1.0 / tp, rel=0.03)
    band = (f > 0.6 / tp) & (f < 3.0 / tp)
    expected = _dnv_spectrum(f[band], hs, 1.0 / tp, gamma)
    for chunk_pxx, chunk_s in zip(np.array_split(pxx[band], 6), np.array_split(expected, 6), strict=True):
        assert np.mean(chunk_pxx) == pytest.approx(np.mean(chunk_s), rel=0.25)


def test_the_sea_does_not_repeat_after_two_pi_over_the_bin_width():
    """On a grid of bin centres every component is back in phase after tau = 2 pi / d_omega, so
    the sea repeats: its correlation with itself tau later is 1. Jittered inside its bin, the
    component j is off by 2 pi u_j there (u_j uniform over the bin), so that correlation,
    sum_j a_j^2 cos(2 pi u_j) / sum_j a_j^2, has mean 0 over seeds."""
    d_omega = (5.0 - 0.5) * (2.0 * math.pi / 8.0) / N_COMPONENTS  # the band over the default bins
    lag = 2.0 * math.pi / d_omega  # the repeat period an unjittered grid would have
    dt = 0.25
    t = 3.0 * 8.0 + np.arange(0.0, 3600.0 + lag + 1.0, dt)
    n, m = int(3600.0 / dt), int(round(lag / dt))
    x, y = 12.0, -7.0
    grid, jittered = [], []
    for seed in range(8):
        config = WaveConfig(spectrum="jonswap", hs=2.0, tp=8.0, seed=seed)
        comp = components(config)
        theta = (comp.k * (x * np.cos(comp.direction_to) + y * np.sin(comp.direction_to))
                 - np.outer(t, comp.omega) + comp.phase)
        centre = np.round(comp.omega / d_omega) * d_omega  # the bin's grid frequency
        on_grid = np.cos(theta - np.outer(t, centre - comp.omega)) @ comp.amplitude
        series = elevation(config, t, x, y)
        grid.append(np.corrcoef(on_grid[:n], on_grid[m:m + n])[0, 1])
        jittered.append(np.corrcoef(series[:n], series[m:m + n])[0, 1])
    assert min(grid) > 0.99  # the control: a grid sea repeats
    assert abs(np.mean(jittered)) < 0.3


@pytest.mark.parametrize("s", [2.0, 10.0])
def test_spreading_follows_the_cos_2s_distribution(s):
    bearing = math.radians(135.0)  # from the south-east: travelling toward the north-west
    config = WaveConfig(spectrum="pm", hs=1.0, tp=6.0, direction_from=bearing, spreading=s,
                        n_components=20000, seed=8)
    offsets = components(config).direction_to - math.atan2(-math.cos(bearing), -math.sin(bearing))
    mean = math.atan2(np.mean(np.sin(offsets)), np.mean(np.cos(offsets)))
    assert mean == pytest.approx(0.0, abs=0.03)
    density = lambda th: math.cos(th / 2.0) ** (2.0 * s)  # noqa: E731
    norm = quad(density, -math.pi, math.pi)[0]
    r = quad(lambda th: math.cos(th) * density(th), -math.pi, math.pi)[0] / norm
    assert r == pytest.approx(s / (s + 1.0), rel=1e-9)  # the closed form of the same integral
    assert np.mean(np.cos(offsets)) == pytest.approx(r, abs=0.015)
    long_crested = components(WaveConfig(spectrum="pm", hs=1.0, tp=6.0, direction_from=bearing,
                                         n_components=20000, seed=8))
    assert np.ptp(long_crested.direction_to) == 0.0


def test_the_same_seed_repeats_bit_for_bit_and_another_differs():
    t = AFTER + np.arange(0.0, 200.0, 0.5)
    config = WaveConfig(spectrum="jonswap", hs=2.0, tp=7.0, spreading=5.0, seed=11)
    first = elevation(config, t, 4.0, 5.0), orbital_velocity(config, t, 4.0, 5.0, -2.0)
    components.cache_clear()  # draw the components again
    again = elevation(config, t, 4.0, 5.0), orbital_velocity(config, t, 4.0, 5.0, -2.0)
    assert np.array_equal(first[0], again[0]) and np.array_equal(first[1], again[1])
    other = WaveConfig(spectrum="jonswap", hs=2.0, tp=7.0, spreading=5.0, seed=12)
    assert not np.allclose(elevation(other, t, 4.0, 5.0), first[0])


def test_the_wind_draws_the_same_whether_or_not_there_is_a_sea():
    t = np.linspace(0.0, 300.0, 601)
    wind = WindConfig(speed=8.0, seed=5)
    before = WindField(wind)
    gust_before, wander_before = before.gust(t, 5.0), before.wander.copy()
    global_state = np.random.get_state()[1].copy()
    sea = WaveConfig.from_wind(8.0, direction_from=wind.direction_from, spreading=3.0, seed=5)
    components.cache_clear()
    elevation(sea, t, 0.0, 0.0)
    after = WindField(wind)
    assert np.array_equal(after.gust(t, 5.0), gust_before)
    assert np.array_equal(after.wander, wander_before)
    assert np.array_equal(np.random.get_state()[1], global_state)  # no global draws either
    assert np.intersect1d(components(sea).phase, after.gust_phase).size == 0  # its own stream


def test_a_wind_raises_the_sea_of_pierson_moskowitz_and_hasselmann():
    # U10 10 m/s: U19.5 = 10.26 m/s, Hs = 0.21 * 10.26^2 / 9.81, Tp = 2 pi 10.26 / (0.877 * 9.81)
    full = WaveConfig.from_wind(10.0, direction_from=0.5)
    assert (full.spectrum, full.direction_from) == ("pm", 0.5)
    assert full.hs == pytest.approx(2.25343, rel=1e-5)
    assert full.tp == pytest.approx(7.49305, rel=1e-5)
    # 20 km fetch: chi = 9.81 * 20000 / 100 = 1962; Hs = 1.6e-3 * 1962^0.5 * 100 / 9.81,
    # Tp = 0.2857 * 1962^(1/3) * 10 / 9.81
    young = WaveConfig.from_wind(10.0, "fetch_limited", fetch=20000.0)
    assert (young.spectrum, young.gamma) == ("jonswap", 3.3)
    assert young.hs == pytest.approx(0.722438, rel=1e-5)
    assert young.tp == pytest.approx(3.64592, rel=1e-5)
    # 1000 km of fetch would outgrow a fully developed sea: held at it
    old = WaveConfig.from_wind(10.0, "fetch_limited", fetch=1e6)
    assert (old.hs, old.tp) == pytest.approx((full.hs, full.tp), rel=1e-12)
    assert WaveConfig.from_wind(0.0).hs == 0.0


@pytest.mark.parametrize("kwargs, message", [
    (dict(hs=-1.0), "WaveConfig.hs must be >= 0 m, got -1.0"),
    (dict(tp=0.0), "WaveConfig.tp must be > 0 s, got 0.0"),
    (dict(spectrum="jonswop"), "unknown spectrum 'jonswop' in WaveConfig.spectrum; did you mean 'jonswap'?"),
    (dict(gamma=0.5), "WaveConfig.gamma must be in [1, 7], got 0.5"),
    (dict(spreading=-2.0), "WaveConfig.spreading must be > 0 or None, got -2.0"),
    (dict(spectrum="regular", spreading=2.0), "WaveConfig.spreading must be None for spectrum 'regular'"),
    (dict(n_components=0), "WaveConfig.n_components must be an integer >= 1, got 0"),
    (dict(seed=1.5), "WaveConfig.seed must be an integer >= 0, got 1.5"),
    (dict(hs=float("nan")), "WaveConfig.hs must be a finite number (m), got nan"),
])
def test_bad_sea_states_are_refused_in_one_line(kwargs, message):
    with pytest.raises(ValueError) as err:
        WaveConfig(**kwargs)
    assert str(err.value).startswith(message) and "\n" not in str(err.value)


@pytest.mark.parametrize("kwargs, message", [
    (dict(u10=-3.0), "WaveConfig.from_wind: u10 must be in [0, 100] m/s, got -3.0"),
    (dict(u10=10.0, kind="fetch_limited"), "WaveConfig.from_wind: fetch must be > 0 m"),
    (dict(u10=10.0, fetch=1000.0), "WaveConfig.from_wind: fetch must be None"),
    (dict(u10=10.0, kind="developed"), "unknown kind 'developed' in WaveConfig.from_wind"),
])
def test_bad_winds_are_refused_in_one_line(kwargs, message):
    with pytest.raises(ValueError, match=None) as err:
        WaveConfig.from_wind(**kwargs)
    assert str(err.value).startswith(message)


@pytest.mark.parametrize("sign, name", [(+1.0, "head seas"), (-1.0, "following seas")])
def test_a_moving_point_sees_the_encounter_frequency(sign, name):
    """A point moving at U into a regular wave (head seas) sees the elevation oscillate at
    omega_e = omega + k U, k = omega^2/g; moving with it (following seas), omega - k U. The waves
    come from the compass bearing 30 deg, so they travel toward 210 deg: the unit vector
    (east, north) = (sin 210 deg, cos 210 deg). The frequency is measured from the upward zero
    crossings (interpolated) over about 150 encounter periods after the ramp."""
    T, U = 5.0, 3.0  # s, m/s
    omega = 2.0 * math.pi / T
    k = omega**2 / G
    expected = omega + sign * k * U
    waves = WaveConfig(spectrum="regular", hs=1.0, tp=T, direction_from=math.radians(30.0))
    travel = np.array([math.sin(math.radians(210.0)), math.cos(math.radians(210.0))])
    t = np.arange(0.0, 150.0 * 2.0 * math.pi / expected, 0.01) + 4.0 * T  # after the 3 T ramp
    x0, y0 = 12.0, -7.0
    x = x0 - sign * U * (t - t[0]) * travel[0]
    y = y0 - sign * U * (t - t[0]) * travel[1]
    eta = elevation(waves, t, x, y)
    up = np.nonzero((eta[:-1] < 0.0) & (eta[1:] >= 0.0))[0]
    crossings = t[up] - eta[up] * (t[up + 1] - t[up]) / (eta[up + 1] - eta[up])
    measured = 2.0 * math.pi * (crossings.size - 1) / (crossings[-1] - crossings[0])
    assert measured == pytest.approx(expected, rel=0.01), name
    assert abs(measured - omega) > 0.3 * omega  # the encounter shifts it well beyond 1 %
