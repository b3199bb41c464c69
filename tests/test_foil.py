"""Foil coefficients and forces: tables, symmetry, aspect ratio, the sail's C_N and C_T."""

import hashlib
import math
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from conftest import load

from sailmujoco.forces import foil_geometry, foil_sections, sail
from sailmujoco.forces.damping import ittc_friction_coefficient

SHARED = Path(__file__).resolve().parents[2] / "shared" / "data" / "naca0015_sheldahl_klimas.dat"


def test_table_reproduces_sheldahl_klimas_points():
    """Every (alpha, Re) grid point of the shipped table comes back exactly."""
    table = foil_sections.naca0015()
    assert table.cl.shape == (11, 117)
    assert table.reynolds[0] == pytest.approx(1e4) and table.reynolds[-1] == pytest.approx(1e7)
    for j, re in enumerate(table.reynolds):
        for i, alpha in enumerate(table.alpha):
            cl, cd = foil_sections.section_coefficients(alpha, re, table.alpha, table.log_re, table.cl,
                                               table.cd)
            assert cl == pytest.approx(table.cl[j, i], abs=1e-12)
            assert cd == pytest.approx(table.cd[j, i], abs=1e-12)
    # spot values read by eye from the source file (Re = 1e6): 10 deg -> CL 1.0141
    cl, cd = foil_sections.section_coefficients(math.radians(10.0), 1e6, table.alpha, table.log_re,
                                       table.cl, table.cd)
    assert cl == pytest.approx(1.0141, abs=1e-4)


# sha256 of Sheldahl & Klimas (1981) NACA 0015 file as the project received it (../shared/data): the
# shipped copy must stay byte-identical to it, with or without ../shared beside us.
SOURCE_SHA256 = "463b92ae2609c94b4c5b9e50f6aa1696be2c24d3856049475e860cd996ce0c93"


def test_shipped_table_has_the_source_checksum():
    """The package ships the Sheldahl & Klimas file unchanged: its recorded checksum."""
    data = resources.files("sailmujoco.data").joinpath("naca0015_sheldahl_klimas.dat").read_bytes()
    assert hashlib.sha256(data).hexdigest() == SOURCE_SHA256


@pytest.mark.skipif(not SHARED.exists(), reason="../shared/data is not beside this clone "
                    "(the checksum test above covers the shipped file)")
def test_shipped_table_is_the_shared_data():
    """Where ../shared/data is present, the shipped table equals it value for value."""
    shipped = foil_sections.naca0015()
    source = foil_sections.parse_section_table(SHARED.read_text())
    assert np.array_equal(shipped.cl, source.cl) and np.array_equal(shipped.cd, source.cd)


def test_reynolds_interpolation_is_between_tables():
    t = foil_sections.naca0015()
    a = math.radians(12.0)
    lo = foil_sections.section_coefficients(a, 1e6, t.alpha, t.log_re, t.cl, t.cd)[0]
    hi = foil_sections.section_coefficients(a, 2e6, t.alpha, t.log_re, t.cl, t.cd)[0]
    mid = foil_sections.section_coefficients(a, math.sqrt(2.0) * 1e6, t.alpha, t.log_re, t.cl, t.cd)[0]
    assert mid == pytest.approx(0.5 * (lo + hi), rel=1e-12)


@pytest.mark.parametrize("re", [5e4, 1e6, 5e6])
def test_symmetric_foil_at_zero_incidence_gives_no_lift(re):
    t = foil_sections.naca0015()
    c_l, c_d = foil_sections.hydrofoil_coefficients(0.0, re, 2.97, 0.15, t.alpha, t.log_re, t.cl, t.cd)
    assert c_l == 0.0
    assert c_d == pytest.approx(2 * (1 + 2 * 0.15) * ittc_friction_coefficient(re))  # eq. 24
    # odd lift, even drag
    for a in np.radians([3.0, 15.0, 60.0, 150.0]):
        p = foil_sections.hydrofoil_coefficients(a, re, 2.97, 0.15, t.alpha, t.log_re, t.cl, t.cd)
        m = foil_sections.hydrofoil_coefficients(-a, re, 2.97, 0.15, t.alpha, t.log_re, t.cl, t.cd)
        assert p[0] == pytest.approx(-m[0], abs=1e-12) and p[1] == pytest.approx(m[1], abs=1e-12)


def test_aspect_ratio_correction_eq_23():
    t = foil_sections.naca0015()
    a = math.radians(5.0)
    cl2d = foil_sections.section_coefficients(a, 1e6, t.alpha, t.log_re, t.cl, t.cd)[0]
    for ar in (1.75, 2.97, 10.0):
        c_l = foil_sections.hydrofoil_coefficients(a, 1e6, ar, 0.15, t.alpha, t.log_re, t.cl, t.cd)[0]
        assert c_l == pytest.approx(cl2d / (1 + 2 / ar))


def test_keel_at_zero_leeway_gives_no_side_force():
    physics = load("wille_yacht", hydrostatics="paper", sail=False, rudder=False)
    physics.data.qvel[0] = 3.0  # heading east at 3 m/s, no leeway
    physics._compute_forces()
    keel = physics._terms[1]
    assert keel[1] == pytest.approx(0.0, abs=1e-9)
    assert keel[0] < 0.0  # drag only
    # leeway to starboard (-y): the keel pushes back to port
    physics.data.qvel[1] = -0.3
    physics._compute_forces()
    assert physics._terms[1][1] > 0.0


def test_saoud_normal_coefficient_polynomial():
    # Saoud (2015) §VII-A: p5..p1 = 11.52, -33.79, 39.45, -23.07, 7.15
    for x in (0.1, 0.5, 1.0):
        expected = 11.52 * x**5 - 33.79 * x**4 + 39.45 * x**3 - 23.07 * x**2 + 7.15 * x
        assert sail.saoud_normal_coefficient(x) == pytest.approx(expected)
        assert sail.saoud_normal_coefficient(-x) == pytest.approx(-expected)
    assert sail.saoud_normal_coefficient(0.0) == 0.0


def test_sail_tangential_coefficient_small_but_not_zero():
    alphas = np.radians(np.linspace(-180, 180, 721))
    cn = np.array([sail.sail_coefficients(a, True, 0.3, math.radians(15), 0.005)[0] for a in alphas])
    ct = np.array([sail.sail_coefficients(a, True, 0.3, math.radians(15), 0.005)[1] for a in alphas])
    assert np.max(np.abs(ct)) < 0.05 * np.max(np.abs(cn))  # Assumption 4 holds on the model
    assert np.max(np.abs(ct)) > 1e-3  # but it is not zero by construction
    assert ct == pytest.approx(ct[::-1], abs=1e-12)  # even in alpha
    off = [sail.sail_coefficients(a, False, 0.3, math.radians(15), 0.005)[1] for a in alphas]
    assert np.all(np.array(off) == 0.0)


def test_ct_switch_off_makes_the_sail_force_exactly_normal():
    from conftest import gusty

    for tangential in (False, True):
        physics = load("saoud_robot", wind=gusty(6.0, direction_deg=30.0), hydrostatics="paper",
                       keel=False, rudder=False, sail_tangential=tangential)
        physics.set_control([0.0, 0.6])
        physics.step(400)
        lam = physics.sail_angle()
        chord = np.array([math.cos(lam), -math.sin(lam), 0.0])  # sail chord, body frame
        force = physics.force_term("sail")[:3]
        along = abs(force @ chord) / np.linalg.norm(force)
        if tangential:
            assert along > 1e-4
        else:
            assert along < 1e-12


def test_lift_perpendicular_to_flow_and_drag_along_it():
    chord = np.array([1.0, 0.0, 0.0])
    normal = np.array([0.0, 1.0, 0.0])
    flow = np.array([-3.0, 0.5, 0.7])  # spanwise part is dropped
    wc, wn, speed, alpha = foil_geometry.section_flow(flow, chord, normal)
    assert speed == pytest.approx(math.hypot(3.0, 0.5))
    fc, fn = foil_geometry.lift_drag_components(wc, wn, speed, 1.0, 1.0, 0.0)  # pure lift
    assert fc * wc + fn * wn == pytest.approx(0.0, abs=1e-12)
    fc, fn = foil_geometry.lift_drag_components(wc, wn, speed, 1.0, 0.0, 1.0)  # pure drag
    assert np.array([fc, fn]) == pytest.approx(np.array([wc, wn]) / speed)
    # flow from the +n side (alpha > 0) pushes the foil to -n
    assert alpha < 0  # here the fluid comes from -n (w_n > 0 flows towards +n)
