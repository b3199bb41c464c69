"""The 6-DOF boat in the sea: calm water untouched, long waves followed, a JONSWAP sea ridden.

Expected values from linear seakeeping theory (Newman 1977, ch. 6; Faltinsen 1990, ch. 2-3),
with the natural periods from the hull's closed forms (:mod:`sailmujoco.boat.hull`):

* heave, head seas, T >= 5 T_3 and a wave 15 hull lengths or longer: the pressure on the bottom
  is rho g a e^(-k d) and the dynamic amplification 1/(1 - (T_3/T)^2); for a floating body
  (m = rho V) the two cancel to first order but for the added mass, leaving
  1 + (T_3/T)^2 A33/(m + A33) <= 1.04: heave / a = 1 within 5 %.
* roll, beam seas, T = 5 T_4' (T_4' = 2 pi sqrt((I_G + A44) / C44), roll alone): the
  Froude-Krylov moment about G is C44 k a (the buoyancy tilted
  with the slope); the Froude-Krylov sway force rho g V k a drives the hull and its sway added
  mass A22, which sits at CO, |z_G| above G, and would pull the roll back by
  A22/(m + A22) |z_G|/GM of it, but the diffraction force, A22 times the water's acceleration
  (G. I. Taylor's long-wave term, ``wave_diffraction``), cancels that pull. Hence
  roll / (k a) = 1 / (1 - (T_4/T)^2), within 5 %, T_4 the free boat's roll period, roll coupled
  with the free sway: T_4^2 = T_4'^2 (1 + z_G^2 m A22 / (m + A22) / (I_G + A44)) (the keel's
  and rudder's lateral forces in the orbital flow, not in this estimate); with the diffraction
  switched off, the pull is back: (1 - A22/(m + A22) |z_G|/GM) / (1 - (T_4/T)^2), within 5 %.
* heave with the diffraction force and the damping on the motion relative to the water: the
  boat is carried by the long wave, (m + A33) z'' + B (z' - eta') + C z = C eta + (rho V + A33)
  eta'' gives z = eta exactly for m = rho V: heave / a = 1 within 3 %.
"""

import math

import numpy as np
import pytest

from sailmujoco import suite, sweep
from sailmujoco.boat import hull
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.forces.wind import WindConfig
from sailmujoco.options import PhysicsOptions, WaveConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

BOATS = ("wille_yacht", "saoud_robot", "viel_boat")
G = 9.81


def _trajectory(boat, compiled=True, steps=200, **load):
    wind = WindConfig(speed=6.0, direction_from=math.radians(50.0), seed=3)
    physics = BoatPhysics.load(boat, wind=wind, **load)
    physics.compiled_loop = compiled
    physics.place(yaw=0.3, surge=1.0)
    rows = []
    for k in range(steps):
        physics.set_control([0.1 * math.sin(0.05 * k), 0.5])
        physics.step(5)
        rows.append(np.concatenate([physics.data.qpos, physics.data.qvel]))
    return np.array(rows)


@pytest.mark.parametrize("boat", BOATS)
def test_calm_water_is_the_boat_without_a_sea_bit_for_bit(boat):
    plain = _trajectory(boat)
    assert np.array_equal(_trajectory(boat, waves=None), plain)
    assert np.array_equal(_trajectory(boat, waves=WaveConfig(hs=0.0)), plain)


@pytest.mark.parametrize("boat", BOATS)
def test_the_compiled_step_is_the_python_step_in_a_sea(boat):
    sea = WaveConfig(hs=0.3 * get_boat(boat).hull.length / 8.8, tp=4.0, seed=2, n_components=30)
    compiled = _trajectory(boat, True, 60, waves=sea)
    reference = _trajectory(boat, False, 60, waves=sea)
    calm = _trajectory(boat, True, 60)
    assert np.all(np.isfinite(reference)) and not np.allclose(reference, calm)  # it felt the sea
    assert np.array_equal(compiled, reference)


@pytest.mark.parametrize("boat", BOATS)
def test_the_hull_and_the_foils_are_the_seas_only_ways_into_the_boat(boat):
    """With the waves' forces on the hull and the orbital flow at the foils both off, the boat
    in a sea is the calm boat to the bit; with either on, it is not."""
    sea = WaveConfig(hs=0.3 * get_boat(boat).hull.length / 8.8, tp=4.0, seed=2, n_components=30)
    calm = _trajectory(boat, steps=60)
    off = ForceSwitches(wave_hull=False, wave_foil_flow=False)
    neither = _trajectory(boat, steps=60, waves=sea, forces=off)
    assert np.array_equal(neither, calm)
    for path in ("wave_hull", "wave_foil_flow"):
        alone = _trajectory(boat, steps=60, waves=sea, forces=ForceSwitches(**{path: False}))
        assert np.all(np.isfinite(alone)) and not np.allclose(alone, calm)


def _natural_periods(boat):
    p = get_boat(boat)
    h = p.hull
    heave = 2 * math.pi * math.sqrt((p.mass + hull.heave_added_mass(h, p.rho_water))
                                    / (p.rho_water * G * hull.waterplane_area(h)))
    roll = 2 * math.pi * math.sqrt((p.inertia[0] + p.added_mass_diagonal[3])
                                   / (p.rho_water * G * p.displaced_volume * p.gm_t))
    return p, heave, roll


def _regular(boat, period, direction_from, **switches):
    """(heave, heel) over the 7th and 8th periods of a regular wave 2 % of the hull long."""
    p = get_boat(boat)
    height = 0.02 * p.hull.length
    waves = WaveConfig(spectrum="regular", hs=height, tp=period, direction_from=direction_from)
    physics = BoatPhysics.load(boat, wind=WindConfig(speed=0.0), waves=waves,
                               forces=ForceSwitches(**switches))
    z, heel = [], []
    while physics.data.time < 8 * period:
        physics.step(20)
        if physics.data.time > 6 * period:
            z.append(physics.data.qpos[2])
            heel.append(physics.heel())
    return height / 2, np.ptp(z) / 2, np.ptp(heel) / 2


@pytest.mark.parametrize("boat", BOATS)
def test_in_long_head_seas_the_boat_heaves_with_the_wave(boat):
    p, heave_period, _ = _natural_periods(boat)
    long_wave = math.sqrt(2 * math.pi * 15 * p.hull.length / G)  # lambda = 15 L
    period = max(5 * heave_period, long_wave)
    amplitude, heave, _ = _regular(boat, period, math.pi / 2)  # from the east
    assert heave / amplitude == pytest.approx(1.0, abs=0.03)
    # without the diffraction force the added mass lags: 1 + (T_3/T)^2 A33/(m + A33)
    a33 = hull.heave_added_mass(p.hull, p.rho_water)
    lag = 1 + (heave_period / period) ** 2 * a33 / (p.mass + a33)
    amplitude, heave, _ = _regular(boat, period, math.pi / 2, wave_diffraction=False)
    assert heave / amplitude == pytest.approx(lag, abs=0.03)


@pytest.mark.parametrize("boat", BOATS)
@pytest.mark.parametrize("diffraction", [True, False])
def test_in_long_beam_seas_the_boat_rolls_with_the_wave_slope(boat, diffraction):
    p, _, roll_period = _natural_periods(boat)
    period = 5 * roll_period
    amplitude, _, roll = _regular(boat, period, 0.0, wave_diffraction=diffraction)  # on the port beam
    slope = (2 * math.pi / period) ** 2 / G * amplitude
    a22 = p.added_mass_diagonal[1]
    pull = 0.0 if diffraction else a22 / (p.mass + a22) * abs(p.cg_z) / p.gm_t
    sway = p.cg_z**2 * p.mass * a22 / (p.mass + a22)  # the free sway's share of roll inertia
    t4 = roll_period * math.sqrt(1 + sway / (p.inertia[0] + p.added_mass_diagonal[3]))
    expected = (1 - pull) / (1 - (t4 / period) ** 2)
    assert roll / slope == pytest.approx(expected, rel=0.05)


def _heave_std(boat, hs):
    sea = WaveConfig(spectrum="jonswap", hs=hs, tp=6.0, seed=4)
    physics = BoatPhysics.load(boat, wind=WindConfig(speed=0.0), waves=sea)
    z = []
    while physics.data.time < 60.0:
        physics.step(20)
        z.append(physics.data.qpos[2])
    z = np.array(z[len(z) // 3:])  # after the ramp (3 Tp = 18 s)
    assert np.all(np.isfinite(physics.data.qpos)) and physics.stop_reason is None
    assert abs(physics.heel()) < math.radians(60) and np.max(np.abs(z)) < 2 * hs  # afloat, upright
    return np.std(z)


@pytest.mark.parametrize("boat", BOATS)
def test_a_jonswap_sea_is_ridden_for_a_minute_and_heave_grows_with_hs(boat):
    low, high = _heave_std(boat, 0.5), _heave_std(boat, 1.0)
    assert 0.02 < low and 1.7 < high / low < 2.3  # linear: the same sea twice as high


def test_the_sea_is_a_physics_option_and_a_sweep_namespace():
    options = PhysicsOptions(waves={"hs": 1.0, "tp": 5.0, "direction_from_deg": 90.0})
    assert options.waves == WaveConfig(hs=1.0, tp=5.0, direction_from=math.pi / 2)
    env = suite.load("wille_yacht", "heading_hold", seed=0, waves={"hs": 0.5})
    assert env.physics.waves == WaveConfig(hs=0.5)
    with pytest.raises(ValueError, match="waves need the 6-DOF boat"):
        suite.load("wille_yacht", "heading_hold", seed=0, dofs=4, waves={"hs": 0.5})
    with pytest.raises(ValueError, match="height"):
        PhysicsOptions(waves={"height": 1.0})
    spec = sweep.validate({"boat": "saoud_robot", "task": "heading_hold", "controller": "pid",
                           "duration": 1.0, "options": {"waves.tp": 3.0},
                           "grid": {"waves.hs": [0.1, 0.2]}})
    runs = sweep.expand(spec)
    assert [r["waves_options"] for r in runs] == [{"hs": 0.1, "tp": 3.0}, {"hs": 0.2, "tp": 3.0}]
    assert len({r["run_id"] for r in runs}) == 2
    calm = sweep.expand(sweep.validate({"boat": "saoud_robot", "task": "heading_hold",
                                        "controller": "pid", "duration": 1.0}))
    assert "waves_options" not in calm[0]  # a calm run's id as without the namespace
    with pytest.raises(sweep.SweepError) as err:
        sweep.validate(dict(spec, grid={"waves.height": [1.0]}))
    assert "waves option" in str(err.value) and "\n" not in str(err.value)
