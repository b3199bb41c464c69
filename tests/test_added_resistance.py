"""The sea's mean force on the hull: the short-wave reflection term against its published formula,
the references' own numbers, and the yacht's added resistance and long-wave motions in head
waves, measured as a towing tank would (:mod:`sailmujoco.design.added_resistance`)."""

import math

import numpy as np
import pytest
from scipy import special

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.design.added_resistance import measure
from sailmujoco.design.wave_references import gerritsma_beukelman, stawave2
from sailmujoco.forces import wave_reflection
from sailmujoco.forces.sea_kernels import SEA_ROWS
from sailmujoco.options import ForceSwitches

RHO, G = 1025.0, 9.81


def _sea(amplitude, omega, direction):
    """A one-component sea array as the kernel reads it after its stage: the wave travelling
    toward ``direction`` (rad, body frame), fully ramped."""
    sea = np.zeros((SEA_ROWS, 1))
    k = omega**2 / G
    sea[0, 0], sea[1, 0], sea[2, 0], sea[6, 0] = amplitude, omega, k, amplitude
    sea[8, 0], sea[9, 0] = k * math.cos(direction), k * math.sin(direction)
    return sea


def _waterline(x, b, slope, dx, amplitude):
    """A hand-built waterline array with a fully reflecting side (alpha = 1)."""
    out = np.zeros((wave_reflection.WL_ROWS + 1, len(x)))
    out[:wave_reflection.WL_ROWS] = wave_reflection.station_rows(x, b, slope, np.full(len(x), dx))
    out[wave_reflection.WL_ROWS] = 0.5 * amplitude**2
    return out


def test_reflection_off_a_wedge_bow_in_head_seas_is_faltinsens():
    """A wall-sided wedge bow of half-angle E and beam B in short head waves: Faltinsen et al.
    (1980) give R = 1/2 rho g a^2 B sin^2(E) (1 + 2 omega U / g)."""
    a, omega, speed, beam, entrance = 0.05, 4.0, 2.0, 2.0, 4.0  # m, rad/s, m/s, m, m
    n = 40
    dx = entrance / n
    x = (np.arange(n) + 0.5) * dx  # the bow, from midship forward
    b = 0.5 * beam * (1.0 - x / entrance)
    slope = np.full(n, -0.5 * beam / entrance)
    out = np.zeros(6)
    wave_reflection.reflection_wrench(_sea(a, omega, math.pi), _waterline(x, b, slope, dx, a),
                                      speed, RHO, G, out)
    sin2 = math.sin(math.atan(0.5 * beam / entrance)) ** 2
    expected = -0.5 * RHO * G * a**2 * beam * sin2 * (1.0 + 2.0 * omega * speed / G)
    assert out[0] == pytest.approx(expected, rel=1e-9)
    assert out[1] == pytest.approx(0.0, abs=1e-9) and out[5] == pytest.approx(0.0, abs=1e-9)
    # the bow is in the shadow of waves from astern; at rest, a stern that is the bow's mirror
    # image takes the mirror-image force
    out_astern = np.zeros(6)
    wave_reflection.reflection_wrench(_sea(a, omega, 0.0), _waterline(x, b, slope, dx, a),
                                      0.0, RHO, G, out_astern)
    assert np.all(out_astern == 0.0)
    wave_reflection.reflection_wrench(_sea(a, omega, 0.0), _waterline(-x, b, -slope, dx, a),
                                      0.0, RHO, G, out_astern)
    assert out_astern[0] == pytest.approx(0.5 * RHO * G * a**2 * beam * sin2, rel=1e-9)


def test_reflection_off_a_wall_in_beam_seas_is_the_full_reflection():
    """A flat side of length L across the waves reflects them whole: F = 1/2 rho g a^2 L
    (1 + 2 omega U / g) (Faltinsen's bracket at theta = 0, beta = 90 deg), pushing the hull
    along the waves, with no yaw moment for a side centred on CO."""
    a, omega, speed, length = 0.05, 3.0, 1.5, 6.0
    n = 30
    dx = length / n
    x = (np.arange(n) + 0.5) * dx - 0.5 * length
    out = np.zeros(6)
    wave_reflection.reflection_wrench(_sea(a, omega, -math.pi / 2), _waterline(
        x, np.full(n, 1.0), np.zeros(n), dx, a), speed, RHO, G, out)
    assert out[1] == pytest.approx(-0.5 * RHO * G * a**2 * length * (1 + 2 * omega * speed / G), rel=1e-9)
    assert out[0] == pytest.approx(0.0, abs=1e-9) and out[5] == pytest.approx(0.0, abs=1e-6)


def test_draft_factor_is_fujii_and_takahashis():
    """alpha(1.5 k T) = pi^2 I1^2 / (pi^2 I1^2 + K1^2): 1 for a deep side, 0 for none, and at
    1.5 k T = 1 the tabulated Bessel values I1(1) = 0.565159, K1(1) = 0.601907 (Abramowitz and
    Stegun, Table 9.8) give 0.8969."""
    assert wave_reflection.draft_factor(1.0 / 1.5, 1.0) == pytest.approx(
        math.pi**2 * 0.565159**2 / (math.pi**2 * 0.565159**2 + 0.601907**2), rel=1e-5)
    assert wave_reflection.draft_factor(1.0 / 1.5, 1.0) == pytest.approx(0.8969, abs=1e-4)
    assert wave_reflection.draft_factor(10.0, 5.0) == pytest.approx(1.0, abs=1e-9)
    assert wave_reflection.draft_factor(1.0, 1e-6) < 1e-9
    assert special.i1(1.0) == pytest.approx(0.565159, abs=1e-6)  # the table, not the code


def test_stawave2_reflection_part_alone_for_a_deep_slow_hull():
    """With the motion part gone (very short waves: omega_bar >> 1 kills it) STAwave-2 is its
    reflection part, sigma = (L / 2B) alpha_1, alpha_1 -> f1 = 0.692 (U / sqrt(g T))^0.769 +
    1.81 C_B^6.95 for a deep hull (the ITTC annex's formula)."""
    length, beam, draft, block, speed = 100.0, 15.0, 30.0, 0.8, 5.0
    sigma = stawave2(length, beam, draft, block, 0.25, speed, 0.02)
    f1 = 0.692 * (speed / math.sqrt(G * draft)) ** 0.769 + 1.81 * block**6.95
    assert sigma == pytest.approx(0.5 * length / beam * f1, rel=1e-3)


def test_gerritsma_beukelman_of_a_uniform_prism_is_its_closed_form():
    """A prism of length L with uniform sectional damping N' and relative velocity V, no forward
    speed: R = k / (2 omega) N' V^2 L."""
    n, length = 50, 8.0
    x = (np.arange(n) + 0.5) * length / n - 0.5 * length
    r = gerritsma_beukelman(x, np.full(n, 0.3), np.full(n, 500.0), np.zeros(n), 0.0, 0.7, 3.0)
    assert r == pytest.approx(0.7 / 6.0 * 500.0 * 0.09 * length, rel=1e-12)


def test_in_long_head_waves_at_speed_the_yacht_heaves_and_pitches_with_the_wave():
    """lambda = 8 L at Froude 0.2: the heave is the wave's and the pitch the wave's slope, within
    5 % (the encounter period, 4.3 s, is 1.8 times the pitch period: the dynamic amplification
    1 / (1 - 0.31) of an undamped pitch is held near 1 by the damping relative to the water).
    The unbounded-fluid form's pitch Munk moment, a negative pitch stiffness a33 U^2, takes the
    pitch well below the wave's slope: the reason it is not the default."""
    point = measure("wille_yacht", 8.0, 0.2, seconds=100.0, average=40.0)
    assert point.heave == pytest.approx(1.0, abs=0.05)
    assert point.pitch == pytest.approx(1.0, abs=0.05)
    kirchhoff = measure("wille_yacht", 8.0, 0.2, seconds=100.0, average=40.0,
                        forces=ForceSwitches(added_mass_coupling="kirchhoff"))
    assert kirchhoff.pitch < 0.85


def test_added_resistance_peak_is_the_size_and_wavelength_of_the_reference():
    """sigma_aw of the yacht in head waves at Froude 0.2 peaks between lambda/L 1.0 and 1.25,
    within 30 % of STAwave-2's peak for its L, B, canoe-body draft, C_B and pitch gyradius
    (3.34 at lambda/L 1.18; an empirical fit to ships, the yacht outside its range: a scale).
    The manoeuvring form, which leaves the added mass's surge term -a33 w q out, adds its mean,
    a33 <w q>: half as much again at the peak."""
    p = get_boat("wille_yacht")
    length = p.hull.length
    # the canoe body's closed forms (boat/hull.py): C_B = (pi/4)(8/15) for half-ellipse sections
    hull = dict(length=length, beam=2.0 * p.hull.half_beam, draft=p.hull.canoe_draft,
                block=2.0 * math.pi / 15.0, gyradius=math.sqrt(p.inertia[1] / p.mass) / length)
    speed = 0.2 * math.sqrt(G * length)
    fine = np.linspace(0.8, 1.6, 161)
    reference = stawave2(**hull, speed=speed, wavelength_ratio=fine)
    assert reference.max() == pytest.approx(3.34, abs=0.01)
    assert fine[reference.argmax()] == pytest.approx(1.18, abs=0.01)
    calm = None
    sigma = []
    for ratio in (1.0, 1.1, 1.25):
        point = measure("wille_yacht", ratio, 0.2, calm_resistance=calm)
        calm = point.calm_resistance
        sigma.append(point.sigma_aw)
    assert sigma[1] > sigma[0] and sigma[1] > sigma[2]  # the peak lies between 1.0 and 1.25
    assert max(sigma) == pytest.approx(reference.max(), rel=0.3)
    manoeuvring = measure("wille_yacht", 1.1, 0.2, forces=ForceSwitches(added_mass_coupling="manoeuvring"))
    assert manoeuvring.sigma_aw > 1.4 * sigma[1]
