"""Delft residuary resistance (forces/resistance.py): published values, symmetry, the kernel,
and the terminal speed it sets.

The expected numbers come from the publications, typed in here, never from the module:

* the measured R_r / W of the parent hull of the Delft data set (Gerritsma, Onnink & Versluis
  1981, "Geometry, resistance and stability of the Delft Systematic Yacht Hull Series", ISP 28;
  the Delft "Yacht Hydrodynamics" data set, UCI repository, rows 1-14: LCB -2.3 %, C_p 0.568,
  L/V^(1/3) 4.78, B/T 3.99, L/B 3.17, the Sysser 1 parent form, R_r / W x 1e3 by Fn);
* the Keuning & Katgert (2008) coefficients at Fn 0.40 and 0.45 (Fossati 2009, Table 2.5);
* the Keuning & Sonnenberg (1998) heel-increment coefficients at Fn 0.40 and its 6 phi^1.7 law.
"""

import math

import numpy as np
import pytest
from conftest import load
from scipy.optimize import brentq

from sailmujoco import frames
from sailmujoco.boat import hull as hull_geometry
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.constants import GRAVITY
from sailmujoco.forces import boat as kernels
from sailmujoco.forces import resistance as rs
from sailmujoco.forces.damping import surge_resistance

# Gerritsma et al. (1981) / Delft data set rows 10, 12, 14: the parent hull, R_r / W x 1e3
SYSSER1_MEASURED = {0.35: 7.16, 0.40: 20.11, 0.45: 49.49}


def sysser1(waterplane_coefficient, midship, lcf_fraction):
    """The parent hull from its published ratios; A_w, C_m and LCF are not in the data set and
    are estimated (typical of the series: C_w 0.68-0.72, C_m 0.70-0.75, LCF 53-55 % aft of FP)."""
    length = 1.0
    volume = (length / 4.78) ** 3
    beam = length / 3.17
    draft = beam / 3.99
    return rs.DelftHull(length=length, beam=beam, draft=draft, volume=volume,
                        lcb=(0.5 + 0.023) * length, lcf=lcf_fraction * length, prismatic=0.568,
                        midship=midship, waterplane_area=waterplane_coefficient * length * beam)


@pytest.mark.parametrize("estimate", [(0.70, 0.72, 0.53), (0.68, 0.70, 0.54), (0.72, 0.75, 0.55)])
@pytest.mark.parametrize("froude", sorted(SYSSER1_MEASURED))
def test_parent_hull_matches_the_towing_tank(froude, estimate):
    # the regression's own scatter on the series is ~10 %; the estimated A_w, C_m, LCF add a few
    predicted = 1e3 * rs.residuary_coefficient(sysser1(*estimate), froude)
    assert predicted == pytest.approx(SYSSER1_MEASURED[froude], rel=0.15)


def wille_delft():
    return rs.delft_hull(get_boat("wille_yacht").hull)


def test_canoe_body_parameters_are_those_of_the_hull_shape():
    h = get_boat("wille_yacht").hull
    d = rs.delft_hull(h)
    assert d.prismatic == pytest.approx(8.0 / 15.0)  # section area (1 - s^2)^2 along x
    assert d.midship == pytest.approx(math.pi / 4.0)  # half-ellipse section
    assert d.lcb == pytest.approx(h.length / 2) and d.lcf == pytest.approx(h.length / 2)
    assert d.volume == pytest.approx(0.5 * math.pi * h.half_beam * h.canoe_draft * h.length * 8 / 15)
    assert d.lcb_percent == pytest.approx(0.0)


def test_zero_at_rest_and_odd_astern():
    d = wille_delft()
    assert rs.residuary_resistance(d, 0.0, heel=0.3) == 0.0
    for u in (0.5, 2.0, 4.0, 6.0, 9.0):
        for heel in (0.0, 0.2, -0.4):
            ahead = rs.residuary_resistance(d, u, heel)
            assert ahead < 0.0  # opposes the motion
            assert rs.residuary_resistance(d, -u, heel) == -ahead


def test_below_the_table_it_fades_like_u_squared():
    d = wille_delft()
    sqrt_gl = math.sqrt(GRAVITY * d.length)
    r15 = rs.residuary_resistance(d, 0.15 * sqrt_gl)
    assert rs.residuary_resistance(d, 0.075 * sqrt_gl) == pytest.approx(r15 / 4.0, rel=1e-12)
    # continuous at the first tabulated Froude number
    assert rs.residuary_resistance(d, 0.15 * sqrt_gl * (1 - 1e-9)) == pytest.approx(r15, rel=1e-6)


def test_above_the_table_the_coefficient_is_held():
    d = wille_delft()
    assert rs.residuary_coefficient(d, 0.9) == rs.residuary_coefficient(d, 0.75)
    assert rs.residuary_coefficient(d, 1.2, 0.3) == rs.residuary_coefficient(d, 0.75, 0.3)


def test_upright_polynomial_at_a_tabulated_froude_number():
    d = wille_delft()
    # Keuning & Katgert (2008), Fossati (2009) Table 2.5, column Fn = 0.45: a0..a7
    a = (-0.0218, -0.5261, -0.2945, 0.2485, -0.2428, 0.6293, 0.0081, 0.2086)
    s = d.volume ** (1 / 3) / d.length
    expected = a[0] + s * (a[1] * d.lcb / d.length + a[2] * d.prismatic
                           + a[3] * d.volume ** (2 / 3) / d.waterplane_area + a[4] * d.beam / d.length
                           + a[5] * d.lcb / d.lcf + a[6] * d.beam / d.draft + a[7] * d.midship)
    assert rs.residuary_coefficient(d, 0.45) == pytest.approx(expected, rel=1e-12)


def test_heel_increment_at_20_degrees_is_the_published_form():
    d = wille_delft()
    # Keuning & Sonnenberg (1998), column Fn = 0.40: u0..u5, times 1e-3
    u = (-0.8659, -0.0354, 0.2226, 0.0188, -0.5800, -0.1133)
    bt, lcb = d.beam / d.draft, 100 * (0.5 - d.lcb / d.length)
    expected = 1e-3 * (u[0] + u[1] * d.length / d.beam + u[2] * bt + u[3] * bt**2 + u[4] * lcb
                       + u[5] * lcb**2)
    phi = math.radians(20.0)
    increment = rs.residuary_coefficient(d, 0.40, phi) - rs.residuary_coefficient(d, 0.40)
    assert increment == pytest.approx(expected * 6.0 * phi**1.7, rel=1e-12)
    assert 6.0 * phi**1.7 == pytest.approx(1.0, abs=0.005)  # the law returns the table at 20 deg
    # and scales as phi^1.7 at other heels
    for deg in (5.0, 10.0, 30.0):
        other = rs.residuary_coefficient(d, 0.40, math.radians(deg)) - rs.residuary_coefficient(d, 0.40)
        assert other / increment == pytest.approx((deg / 20.0) ** 1.7, rel=1e-12)


def test_kernel_equals_the_function(rng):
    p = get_boat("wille_yacht")
    d = rs.delft_hull(p.hull)
    block = rs.pack_resistance(d, p.rho_water)
    assert block.size <= kernels.RESISTANCE_BLOCK_SIZE
    for u, heel in zip(rng.uniform(-12.0, 12.0, 300), rng.uniform(-1.6, 1.6, 300), strict=True):
        expected = rs.residuary_resistance(d, u, heel, p.rho_water)
        assert rs.residuary_surge_force(u, heel, block) == pytest.approx(expected, rel=1e-12, abs=1e-12)


def test_boat_kernel_adds_it_to_the_damping_term_only_when_switched_on():
    friction = load("wille_yacht", hydrostatics="geometric", resistance="friction")
    dsyhs = load("wille_yacht", hydrostatics="geometric", resistance="dsyhs")
    p = friction.params
    d = rs.delft_hull(p.hull)
    heel, u = 0.3, 4.2
    for physics in (friction, dsyhs):
        data = physics.data.ptr
        data.qpos[3:7] = frames.quat_from_euler(heel, 0.0, 0.7)
        rot = frames.matrix_from_euler(heel, 0.0, 0.7)
        data.qvel[0:3] = rot @ np.array([u, 0.1, 0.0])  # body surge u through still water
        physics._compute_forces()
    a, b = friction._terms, dsyhs._terms
    expected = rs.residuary_resistance(d, u, heel, p.rho_water)
    assert b[kernels.T_DAMP, 0] - a[kernels.T_DAMP, 0] == pytest.approx(expected, rel=1e-9)
    b_rest = b.copy()
    b_rest[kernels.T_DAMP, 0] = a[kernels.T_DAMP, 0]
    assert np.array_equal(a, b_rest)  # nothing else changes


def test_terminal_speed_under_constant_thrust():
    thrust = 700.0  # N: lands the hull between Fn 0.40 and 0.45, on the wave-making wall
    physics = load("wille_yacht", hydrostatics="geometric", sail=False, keel=False, rudder=False,
                   added_mass=False, resistance="dsyhs", windage=False)  # as test_terminal_speed
    p = physics.params
    h = p.hull
    physics.set_external_wrench([thrust, 0, 0, 0, 0, 0])
    physics.step(30000)  # 150 s
    u_sim = physics.body_velocity()[0]

    # the published upright formula (Fossati 2009 Table 2.5, columns Fn 0.40 and 0.45), with
    # the hull's parameters from hull.py, linearly interpolated between the two columns
    columns = {0.40: (-0.0064, -0.4034, -0.1250, 0.0273, -0.1341, 0.3578, 0.0045, 0.1115),
               0.45: (-0.0218, -0.5261, -0.2945, 0.2485, -0.2428, 0.6293, 0.0081, 0.2086)}
    volume = hull_geometry.volume(h)
    length, beam, draft = h.length, 2 * h.half_beam, h.canoe_draft
    ratios = (1.0, 0.5, 8 / 15, volume ** (2 / 3) / hull_geometry.waterplane_area(h), beam / length,
              1.0, beam / draft, math.pi / 4)  # LCB = LCF = midship; half-ellipse C_m
    s = volume ** (1 / 3) / length

    def rr_over_w(a):
        return a[0] + s * sum(ai * ri for ai, ri in zip(a[1:], ratios[1:], strict=True))

    def balance(u):
        fn = u / math.sqrt(GRAVITY * length)
        f = (fn - 0.40) / 0.05
        rr_w = (1 - f) * rr_over_w(columns[0.40]) + f * rr_over_w(columns[0.45])
        rr = p.rho_water * GRAVITY * volume * rr_w
        friction = -surge_resistance(u, p.rho_water, p.wetted_surface, p.form_factor, length, p.nu_water)
        return thrust - p.linear_damping[0] * u - friction - rr

    sqrt_gl = math.sqrt(GRAVITY * length)
    u_expected = brentq(balance, 0.40 * sqrt_gl, 0.45 * sqrt_gl)
    assert u_sim == pytest.approx(u_expected, rel=0.01)
    # without the wave-making wall the same thrust would drive the hull much faster
    u_friction = brentq(lambda u: thrust - p.linear_damping[0] * u + surge_resistance(
        u, p.rho_water, p.wetted_surface, p.form_factor, length, p.nu_water), 0.1, 50.0)
    assert u_friction > 1.2 * u_expected
