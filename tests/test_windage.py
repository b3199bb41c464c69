"""Windage of topsides and mast against the hand formula (forces/windage.py).

The expected forces are written out here from the boat's dimensions: drag areas L x
freeboard, beam x freeboard, mast diameter (1.2 % of the luff) x height above the deck;
Fossen's (2011) c_x = 0.7, c_y = 0.8 and Hoerner's cylinder C_D = 1.2; the wind at each
centroid's height from Wille (2016a) eq. 40, U(z) = U10 ln(z / z0) / ln(10 / z0).
"""

import math

import numpy as np
import pytest

from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

KAPPA = 0.0026  # Wille (2016a) eq. 40
Z0 = 10.0 * math.exp(-2.0 / (5.0 * math.sqrt(KAPPA)))


def log_wind(u10, z):
    return u10 * math.log(z / Z0) / math.log(10.0 / Z0)


def hand(params, u10, along):
    """(F, moment arm heights) of topsides and mast for a steady wind along body ``along``."""
    h, s = params.hull, params.sail
    f = h.freeboard
    mast_h = s.masthead_height - f
    mast_d = 0.012 * s.luff
    z_hull, z_mast = 0.5 * f, f + 0.5 * mast_h
    if along == "y":
        hull_area, c = h.length * f, 0.8
    else:
        hull_area, c = 2.0 * h.half_beam * h.flare * f, 0.7
    rho = params.rho_air
    f_hull = 0.5 * rho * c * hull_area * log_wind(u10, z_hull) ** 2
    f_mast = 0.5 * rho * 1.2 * mast_d * mast_h * log_wind(u10, z_mast) ** 2
    return f_hull, f_mast, z_hull, z_mast


def windage_at_rest(boat, direction_from, on=True):
    wind = WindConfig(speed=10.0, direction_from=direction_from, gusts=False, wander=False)
    physics = BoatPhysics.load(boat, wind=wind, forces=ForceSwitches(windage=on))
    physics._compute_forces()
    return physics, physics.force_terms()["windage"]


@pytest.mark.parametrize("boat", ["wille_yacht", "saoud_robot"])
def test_beam_wind_equals_hand_formula(boat):
    # home pose: body x east, y north; a wind from the north blows along -y (to starboard)
    physics, wrench = windage_at_rest(boat, direction_from=0.0)
    f_hull, f_mast, z_hull, z_mast = hand(physics.params, 10.0, "y")
    assert wrench[1] == pytest.approx(-(f_hull + f_mast), rel=1e-9)
    assert wrench[0] == pytest.approx(0.0, abs=1e-9 * f_hull)
    # heeling moment about CO, each force at its own centroid's height: -z F_y > 0, which
    # (about +x, forward) puts the starboard side down, away from the wind
    assert wrench[3] == pytest.approx(f_hull * z_hull + f_mast * z_mast, rel=1e-9)
    # the mast stands at mast_x: its side force turns the bow away from the wind
    assert wrench[5] == pytest.approx(-f_mast * physics.params.sail.mast_x, rel=1e-9, abs=1e-12)


def test_head_wind_equals_hand_formula():
    # a wind from the east meets the bow head on: drag astern, -x
    physics, wrench = windage_at_rest("wille_yacht", direction_from=math.pi / 2)
    f_hull, f_mast, z_hull, z_mast = hand(physics.params, 10.0, "x")
    assert wrench[0] == pytest.approx(-(f_hull + f_mast), rel=1e-9)
    assert wrench[1] == pytest.approx(0.0, abs=1e-9 * f_hull)


def test_motion_through_still_air_is_drag():
    # no wind, boat moving ahead at 5 m/s: both elements feel a 5 m/s head wind
    physics = BoatPhysics.load("wille_yacht", wind=WindConfig(speed=0.0, gusts=False, wander=False),
                               forces=ForceSwitches(windage=True))
    physics.data.ptr.qvel[0] = 5.0
    physics._compute_forces()
    p = physics.params
    h, s = p.hull, p.sail
    area = 0.7 * 2.0 * h.half_beam * h.flare * h.freeboard \
        + 1.2 * 0.012 * s.luff * (s.masthead_height - h.freeboard)
    assert physics.force_terms()["windage"][0] == pytest.approx(-0.5 * p.rho_air * area * 25.0, rel=1e-9)


def test_switch_off_is_zero_and_changes_nothing_else():
    _, off = windage_at_rest("wille_yacht", 0.0, on=False)
    assert np.all(off == 0.0)
    physics_on, _ = windage_at_rest("wille_yacht", 0.0, on=True)
    physics_off, _ = windage_at_rest("wille_yacht", 0.0, on=False)
    for name in ("sail", "keel", "rudder", "hydrostatics", "damping"):
        assert np.array_equal(physics_on.force_terms()[name], physics_off.force_terms()[name])


def test_windage_without_the_sail_is_the_same_force():
    """The kernel evaluates the wind for the sail and the windage points in one call:
    with the sail switched off (topsides and mast only) the windage is the same to the bit, in
    gusty, wandering wind on a heeled, moving boat."""
    wind = WindConfig(speed=9.0, direction_from=1.1, seed=4)
    terms = []
    for sail in (True, False):
        physics = BoatPhysics.load("wille_yacht", wind=wind, forces=ForceSwitches(sail=sail))
        physics.data.qpos[3:7] = [math.cos(0.1), math.sin(0.1), 0.0, 0.0]  # heeled 11.5 deg
        physics.data.qvel[:6] = [1.5, -0.3, 0.05, 0.1, 0.02, -0.05]
        physics.data.time = 7.3
        physics._compute_forces()
        terms.append(physics.force_terms()["windage"].copy())
    assert np.any(terms[0] != 0.0)
    assert np.array_equal(terms[0], terms[1])
