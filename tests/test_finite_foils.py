"""Finite-wing foils (``foils = "finite"``) and the keel's downwash at the rudder.

Expected values come from the published formulas written out here (Helmbold 1942, Viterna &
Corrigan 1982, Biot-Savart for the trailing vortices), from the Sheldahl & Klimas table as
printed in the source file, and from Saoud (2015) / Wille (2016a) for the paper forms.
"""

import math

import numpy as np
import pytest
from conftest import load

from sailmujoco.boat.catalogue import saoud_robot, wille_yacht
from sailmujoco.forces import boat, finite_wing, foil_sections, sail
from sailmujoco.forces.wind import WindConfig

TWO_PI = 2.0 * math.pi
# Sheldahl & Klimas (1981) NACA 0015, Re = 1e6, as printed in the source file:
# alpha 0/1/2/3/5 deg -> c_l 0.0000/0.1100/0.2200/0.3300/0.5500; c_d(0) = 0.0074, c_d(90 deg) = 1.8000
SK_SLOPE_1E6 = 0.11 * 180.0 / math.pi  # 1/rad, linear between 0 and 3 deg
SK_CL_5DEG_1E6 = 0.55


def helmbold(a0, aspect_ratio):
    """Helmbold (1942): a = a0 / (sqrt(1 + (a0/(pi A))^2) + a0/(pi A))."""
    k = a0 / (math.pi * aspect_ratio)
    return a0 / (math.sqrt(1.0 + k * k) + k)


def vc_cd_max(aspect_ratio):
    """Viterna & Corrigan (1982): C_D,max = 1.11 + 0.018 A."""
    return 1.11 + 0.018 * aspect_ratio


def table():
    t = foil_sections.naca0015()
    return t.alpha, t.log_re, t.cl, t.cd


# ---- the formulas ----------------------------------------------------------------------------

def test_helmbold_slope_limits_and_value_at_ar5():
    # lifting line a0 / (1 + a0/(pi A)) for large A, Jones' slender wing pi A / 2 for small A
    assert finite_wing.helmbold_lift_slope(TWO_PI, 200.0) == pytest.approx(TWO_PI / (1 + 2 / 200.0), rel=1e-4)
    assert finite_wing.helmbold_lift_slope(TWO_PI, 0.02) == pytest.approx(math.pi * 0.02 / 2, rel=1e-3)
    a5 = finite_wing.helmbold_lift_slope(TWO_PI, 5.0)
    assert a5 == pytest.approx(TWO_PI / (math.sqrt(1 + 0.4**2) + 0.4), rel=1e-14)
    assert 4.2 < a5 < TWO_PI / 1.4  # below lifting line's 4.49 /rad, well below Saoud's 7.15
    assert finite_wing.viterna_corrigan_cd_max(5.0) == pytest.approx(1.20)


def test_packed_constants_are_the_formulas():
    p = wille_yacht()
    block = finite_wing.pack_foil_block(p)
    assert block[finite_wing.FB_SAIL_SLOPE] == pytest.approx(helmbold(TWO_PI, 5.0), rel=1e-14)
    assert block[finite_wing.FB_SAIL_CD_MAX] == pytest.approx(1.20, rel=1e-14)
    # keel: Appendix A Asp_k = 1.75, doubled by the hull as an end plate
    assert block[finite_wing.FB_KEEL_AR] == pytest.approx(3.5)
    assert block[finite_wing.FB_KEEL_RATIO] == pytest.approx(helmbold(TWO_PI, 3.5) / TWO_PI, rel=1e-14)
    assert block[finite_wing.FB_KEEL_CD_MAX] == pytest.approx(vc_cd_max(3.5))
    # rudder: Asp_r = 2.97, no end plate
    assert block[finite_wing.FB_RUDDER_AR] == pytest.approx(2.97)
    assert block[finite_wing.FB_RUDDER_RATIO] == pytest.approx(helmbold(TWO_PI, 2.97) / TWO_PI, rel=1e-14)


# ---- sail --------------------------------------------------------------------------------------

def test_finite_sail_slope_at_zero_incidence():
    slope = helmbold(TWO_PI, 5.0)
    h = 1e-6
    for tangential in (False, True):
        cp = sail.finite_sail_coefficients(h, tangential, 0.3, math.radians(15), 0.005, slope, 1.2)[0]
        cm = sail.finite_sail_coefficients(-h, tangential, 0.3, math.radians(15), 0.005, slope, 1.2)[0]
        assert (cp - cm) / (2 * h) == pytest.approx(slope, rel=1e-9)
    assert finite_wing.finite_sail_normal_coefficient(0.0, slope, math.radians(15), 1.2) == 0.0


def test_finite_sail_normal_force_at_90_deg_is_viterna_corrigan():
    slope = helmbold(TWO_PI, 5.0)
    c_n = finite_wing.finite_sail_normal_coefficient(1.0, slope, math.radians(15), vc_cd_max(5.0))
    assert c_n == pytest.approx(1.20, abs=1e-12)  # Hoerner's flat plate of AR 5: about 1.2
    assert finite_wing.finite_sail_normal_coefficient(-1.0, slope, math.radians(15), 1.2) == \
        pytest.approx(-1.20)


def test_finite_sail_stalls_and_is_continuous():
    slope, stall = helmbold(TWO_PI, 5.0), math.radians(15)
    x_s = math.sin(stall)
    below = finite_wing.finite_sail_normal_coefficient(x_s * (1 - 1e-9), slope, stall, 1.2)
    above = finite_wing.finite_sail_normal_coefficient(x_s * (1 + 1e-9), slope, stall, 1.2)
    assert below == pytest.approx(slope * x_s, rel=1e-8) and above == pytest.approx(below, rel=1e-6)
    # past the stall the normal force first falls (a stall), then rises to C_D,max
    assert finite_wing.finite_sail_normal_coefficient(math.sin(math.radians(25)), slope, stall, 1.2) < below
    xs = np.linspace(-1, 1, 2001)
    cn = np.array([finite_wing.finite_sail_normal_coefficient(x, slope, stall, 1.2) for x in xs])
    assert np.all(np.abs(np.diff(cn)) < 0.01)  # no jumps
    assert cn == pytest.approx(-cn[::-1], abs=1e-12)  # odd in sin(alpha)


def test_kernel_sail_force_slope_is_helmbold():
    """Finite differences of the kernel's sail force about zero incidence."""
    wind = WindConfig(speed=6.0, direction_from=math.radians(90.0), gusts=False, wander=False)
    physics = load("saoud_robot", wind=wind, hydrostatics="paper", keel=False, rudder=False,
                   sail_tangential=False, foils="finite")
    q_idx = physics._idx[2]
    area = physics.params.sail.area

    def normal_coefficient(lam):
        physics.data.ptr.qpos[q_idx] = lam
        physics._compute_forces()
        f = physics.force_term("sail")[:3]
        speed = physics._diag[boat.D_SPEED_SAIL]
        n = np.array([math.sin(lam), math.cos(lam), 0.0])
        return -(f @ n) / (0.5 * physics.params.rho_air * speed**2 * area), physics.angle_of_attack("sail")

    lam0 = 0.0
    for _ in range(3):  # find the sail angle of zero incidence (alpha moves one for one with lambda)
        _, alpha = normal_coefficient(lam0)
        lam0 -= alpha * (normal_coefficient(lam0 + 1e-3)[1] - alpha) / 1e-3
    (c1, a1), (c2, a2) = normal_coefficient(lam0 - 1e-5), normal_coefficient(lam0 + 1e-5)
    assert abs(a1) < 1e-4 and abs(a2) < 1e-4
    assert (c2 - c1) / (a2 - a1) == pytest.approx(helmbold(TWO_PI, 5.0), rel=1e-6)


# ---- keel and rudder -------------------------------------------------------------------------

@pytest.mark.parametrize("aspect_ratio", [1.75 * 2, 2.97, 2.2])
def test_hydrofoil_finite_slope_at_zero_incidence(aspect_ratio):
    """C_L slope = the table's 2-D slope times Helmbold's a/a0 (the table is linear to 3 deg)."""
    ratio = helmbold(TWO_PI, aspect_ratio) / TWO_PI
    h = math.radians(1.0)  # 3-D angle: the section angle h * ratio stays inside 0-3 deg
    cp = finite_wing.finite_hydrofoil_coefficients(h, 1e6, ratio, aspect_ratio, vc_cd_max(aspect_ratio),
                                            math.radians(20), 0.09, *table())[0]
    cm = finite_wing.finite_hydrofoil_coefficients(-h, 1e6, ratio, aspect_ratio, vc_cd_max(aspect_ratio),
                                            math.radians(20), 0.09, *table())[0]
    assert (cp - cm) / (2 * h) == pytest.approx(SK_SLOPE_1E6 * ratio, rel=1e-9)
    # the chosen formula with the table's 6.30 /rad in place of 2 pi: within 0.3 %
    assert (cp - cm) / (2 * h) == pytest.approx(helmbold(SK_SLOPE_1E6, aspect_ratio), rel=3e-3)


@pytest.mark.parametrize("re", [5e4, 1e6, 5e6])
def test_symmetric_hydrofoil_gives_no_lift_at_zero_and_is_odd(re):
    ratio = helmbold(TWO_PI, 3.5) / TWO_PI
    args = (re, ratio, 3.5, vc_cd_max(3.5), math.radians(20), 0.09, *table())
    assert finite_wing.finite_hydrofoil_coefficients(0.0, *args)[0] == 0.0
    for a in np.radians([2.0, 15.0, 40.0, 89.0, 120.0, 175.0]):
        p = finite_wing.finite_hydrofoil_coefficients(a, *args)
        m = finite_wing.finite_hydrofoil_coefficients(-a, *args)
        assert p[0] == pytest.approx(-m[0], abs=1e-12) and p[1] == pytest.approx(m[1], abs=1e-12)


def test_hydrofoil_post_stall_is_viterna_corrigan_not_the_2d_table():
    for aspect_ratio in (3.5, 2.97):
        ratio = helmbold(TWO_PI, aspect_ratio) / TWO_PI
        c_l, c_d = finite_wing.finite_hydrofoil_coefficients(math.pi / 2, 1e6, ratio, aspect_ratio,
                                                      vc_cd_max(aspect_ratio), math.radians(20), 0.09,
                                                      *table())
        assert c_l == pytest.approx(0.0, abs=1e-12)
        assert c_d == pytest.approx(1.11 + 0.018 * aspect_ratio, rel=1e-12)  # not the table's 1.80
    # continuous across the matching angle, the 90 deg mirror and the +-180 deg wrap
    ratio = helmbold(TWO_PI, 3.5) / TWO_PI
    args = (1e6, ratio, 3.5, vc_cd_max(3.5), math.radians(20), 0.09, *table())
    for a in (math.radians(20) / ratio, math.pi / 2, math.pi):
        lo = np.array(finite_wing.finite_hydrofoil_coefficients(a - 1e-9, *args))
        hi = np.array(finite_wing.finite_hydrofoil_coefficients(a + 1e-9, *args))
        assert np.max(np.abs(hi - lo)) < 1e-6


def test_kernel_keel_lift_slope_and_side_force_at_90_deg():
    """The kernel's keel force: slope of C_L at zero leeway, and broadside C_D,max."""
    physics = load("wille_yacht", hydrostatics="paper", sail=False, rudder=False, foils="finite")
    p = physics.params
    u = 1e6 * p.nu_water / p.keel.chord  # chord Reynolds number 1e6
    q_area = 0.5 * p.rho_water * u * u * p.keel.area

    def keel_force(beta):
        physics.data.ptr.qvel[0:3] = [u * math.cos(beta), u * math.sin(beta), 0.0]
        physics._compute_forces()
        return physics.force_term("keel")[:3]

    def lift_coefficient(beta):
        w_hat = -np.array([math.cos(beta), math.sin(beta), 0.0])  # water relative to the keel
        lift_dir = np.cross([0.0, 0.0, 1.0], w_hat)
        return keel_force(beta) @ lift_dir / q_area

    h = math.radians(0.5)
    slope = (lift_coefficient(h) - lift_coefficient(-h)) / (2 * h)  # alpha = beta (forces/foil_geometry.py)
    assert slope == pytest.approx(SK_SLOPE_1E6 * helmbold(TWO_PI, 2 * 1.75) / TWO_PI, rel=1e-9)
    # broadside: pure drag, Viterna-Corrigan's C_D,max of the keel's effective aspect ratio
    f = keel_force(math.pi / 2)
    assert f[1] == pytest.approx(-q_area * vc_cd_max(3.5), rel=1e-9)  # against the motion
    assert f[0] == pytest.approx(0.0, abs=1e-9 * q_area)


# ---- the paper forms are untouched -----------------------------------------------------------

def test_paper_sail_force_is_saoud_polynomial():
    """flat_sail_force as the paper worlds call it: F.n = -q A C_N with Saoud's coefficients."""
    chord, normal, out = np.zeros(3), np.zeros(3), np.zeros(3)
    for alpha_deg in (3.0, 20.0, 70.0):
        flow = -5.0 * np.array([math.cos(math.radians(alpha_deg)), -math.sin(math.radians(alpha_deg)), 0.0])
        speed, alpha, c_n, c_t = sail.flat_sail_force(flow, 0.0, False, 0.3, 0.26, 0.005, 1.225, 2.0,
                                                      chord, normal, out)
        x = abs(math.sin(alpha))
        assert x == pytest.approx(math.sin(math.radians(alpha_deg)))
        expected = 7.15 * x - 23.07 * x**2 + 39.45 * x**3 - 33.79 * x**4 + 11.52 * x**5  # §VII-A
        expected = math.copysign(expected, alpha)  # odd in sin(alpha), properties (2)
        assert c_n == pytest.approx(expected, rel=1e-12) and c_t == 0.0
        assert out @ normal == pytest.approx(-0.5 * 1.225 * 25.0 * 2.0 * expected, rel=1e-12)
        # sail_force with no finite slope is the same call, bit for bit
        again = np.zeros(3)
        assert sail.sail_force(flow, 0.0, False, 0.3, 0.26, 0.005, 1.225, 2.0, 0.0, 1.2, chord, normal,
                               again) == (speed, alpha, c_n, c_t)
        assert np.array_equal(again, out)


def test_paper_keel_lift_is_eq_23_in_the_kernel():
    physics = load("wille_yacht", hydrostatics="paper", sail=False, rudder=False, foils="paper")
    p = physics.params
    u = 1e6 * p.nu_water / p.keel.chord
    beta = math.radians(5.0)  # sliding to port: alpha = 5 deg, a grid point of the table
    physics.data.ptr.qvel[0:3] = [u * math.cos(beta), u * math.sin(beta), 0.0]
    physics._compute_forces()
    w_hat = -np.array([math.cos(beta), math.sin(beta), 0.0])
    q_area = 0.5 * p.rho_water * u * u * p.keel.area
    c_l = physics.force_term("keel")[:3] @ np.cross([0, 0, 1], w_hat) / q_area
    assert c_l == pytest.approx(SK_CL_5DEG_1E6 / (1 + 2 / 1.75), rel=1e-9)  # Wille (2016a) eq. 23


# ---- the keel's downwash at the rudder -------------------------------------------------------

def downwash_state(physics, leeway_deg=4.0, speed=3.0):
    beta = math.radians(leeway_deg)  # sliding to port: alpha = leeway
    physics.data.ptr.qvel[0:3] = [speed * math.cos(beta), speed * math.sin(beta), 0.0]
    physics._compute_forces()


@pytest.mark.parametrize("foils", ["finite", "paper"])
def test_downwash_turns_the_rudder_inflow_by_epsilon(foils):
    kw = dict(hydrostatics="paper", sail=False, foils=foils)
    off, on = load("wille_yacht", keel_downwash=False, **kw), load("wille_yacht", keel_downwash=True, **kw)
    for physics in (off, on):
        downwash_state(physics)
    p = on.params
    # the keel's C_L from its force in this state
    w_hat = -on.data.ptr.qvel[0:3] / np.linalg.norm(on.data.ptr.qvel[0:3])
    speed = np.linalg.norm(on.data.ptr.qvel[0:3])
    c_l_keel = on.force_term("keel")[:3] @ np.cross([0, 0, 1], w_hat) / (0.5 * p.rho_water * speed**2
                                                                        * p.keel.area)
    # epsilon = k C_L / (pi A_e), k = 1 + x / sqrt(x^2 + s^2), s = (pi/4) keel span (its image
    # in the hull doubles the span), x = keel CP to rudder CP: 0.66 + 3.7 m (Appendix A, l3 + l4)
    x, s = 0.66 + 3.7, 0.25 * math.pi * math.sqrt(1.75 * 0.93)
    k = 1 + x / math.sqrt(x * x + s * s)
    assert 1.9 < k < 2.0  # four keel chords behind: nearly the far wake
    epsilon = k * c_l_keel / (math.pi * 2 * 1.75)
    assert epsilon > math.radians(1.0)
    assert on.angle_of_attack("rudder") == pytest.approx(off.angle_of_attack("rudder") - epsilon, abs=1e-12)
    assert np.array_equal(on.force_term("keel"), off.force_term("keel"))
    # less lift on the rudder, roll and yaw shares fall
    assert abs(on.force_term("rudder")[1]) < abs(off.force_term("rudder")[1])


def test_downwash_off_or_without_keel_leaves_the_rudder_as_before():
    """With the switch off the rudder force is the paper's: eq. 23 at the geometric inflow."""
    physics = load("wille_yacht", hydrostatics="paper", sail=False, foils="paper", keel_downwash=False)
    downwash_state(physics)
    p = physics.params
    speed = 3.0
    t = foil_sections.naca0015()
    c_l, c_d = foil_sections.hydrofoil_coefficients(math.radians(4.0), speed * p.rudder.chord / p.nu_water,
                                           2.97, 0.15, t.alpha, t.log_re, t.cl, t.cd)
    w_hat = -physics.data.ptr.qvel[0:3] / speed
    q_area = 0.5 * p.rho_water * speed**2 * p.rudder.area
    f = physics.force_term("rudder")[:3]
    assert physics.angle_of_attack("rudder") == pytest.approx(math.radians(4.0), abs=1e-12)
    assert f @ np.cross([0, 0, 1], w_hat) == pytest.approx(q_area * c_l, rel=1e-12)
    assert f @ w_hat == pytest.approx(q_area * c_d, rel=1e-12)
    # switch on but no keel: no keel lift, no downwash
    a = load("wille_yacht", hydrostatics="paper", sail=False, keel=False, keel_downwash=True,
             foils="paper")
    downwash_state(a)
    assert np.array_equal(a.force_term("rudder"), physics.force_term("rudder"))


def test_robot_downwash_factor():
    p = saoud_robot()
    x, s = p.keel.x - p.rudder.x, 0.25 * math.pi * p.keel.span
    assert finite_wing.downwash_factor(x, p.keel.span) == pytest.approx(1 + x / math.hypot(x, s))
    assert finite_wing.downwash_factor(0.0, 1.0) == 1.0  # Prandtl: at the lifting line, half the far wake
    assert finite_wing.downwash_factor(1e6, 1.0) == pytest.approx(2.0)
