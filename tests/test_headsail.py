"""The headsail: the rig without interaction is the sum of its two sails alone, a headsail of zero
area changes no bit, the lumped vortices by hand, and the interaction's signs (Gentry 1971: the
main's upwash lifts the jib, the jib's downwash heads the main)."""

import hashlib
import math

import numpy as np
import pytest

from sailmujoco import suite
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.boat.params import Headsail, Sail
from sailmujoco.forces import headsail as hs
from sailmujoco.forces.boat_parameters import P_HEADSAIL_BLOCK, P_SIZE, pack_parameters
from sailmujoco.forces.wind import WindConfig
from sailmujoco.physics import BoatPhysics, ForceSwitches

# an 11:Metre-like jib on the Wille yacht: 15.2 m^2, head 8.5 m above the tack, 3.1 m aft of it
JIB = Headsail(area=15.2, luff_height=8.5, head_aft=3.1, tack_x=4.9, tack_height=0.8,
               min_angle=math.radians(9.0), max_angle=math.radians(60.0))


def _sail_terms(params, lam: float, switches: ForceSwitches, wind_from_deg: float = 40.0):
    """The sail row of the force terms of ``params`` at rest, level, heading east, the boom at ``lam``."""
    wind = WindConfig(speed=6.0, direction_from=math.radians(90.0 - wind_from_deg), gusts=False,
                      wander=False)
    physics = BoatPhysics.load(params=params, wind=wind, forces=switches)
    physics.data.qpos[physics.model.joint("sail").qposadr[0]] = lam
    physics._compute_forces()
    return physics.force_terms()["sail"].copy()


def test_the_rig_without_interaction_is_the_sum_of_its_sails_alone():
    """The jib alone is the same flat sail as a main standing where the jib does: its luff at the
    tack, its centroid ``ce_aft`` behind it at ``ce_height``, its area and aspect ratio."""
    yacht = get_boat("wille_yacht")
    two = yacht.with_(headsail=JIB)
    s = yacht.sail
    jib_as_main = yacht.with_(sail=Sail(area=JIB.area, aspect_ratio=JIB.aspect_ratio, mast_x=JIB.tack_x,
                                        ce_aft=JIB.ce_aft, ce_height=JIB.ce_height, mass=s.mass,
                                        max_angle=s.max_angle, time_constant=s.time_constant))
    off = ForceSwitches(rig_interaction="none")
    for lam in (math.radians(15.0), math.radians(-30.0)):  # within the trim rule's range: delta = lambda
        rig = _sail_terms(two, lam, off)
        parts = _sail_terms(yacht, lam, off) + _sail_terms(jib_as_main, lam, off)
        assert np.any(rig != 0.0)
        assert rig == pytest.approx(parts, rel=1e-12, abs=1e-9)
    # the rule: a main at 5 deg sets the jib at its lead's 9 deg
    rig = _sail_terms(two, math.radians(5.0), off)
    parts = _sail_terms(yacht, math.radians(5.0), off) + _sail_terms(jib_as_main, math.radians(9.0), off)
    assert rig == pytest.approx(parts, rel=1e-12, abs=1e-9)


def test_the_interaction_changes_the_rig_and_only_with_a_headsail():
    yacht = get_boat("wille_yacht")
    lam = math.radians(15.0)
    assert not np.allclose(_sail_terms(yacht.with_(headsail=JIB), lam, ForceSwitches()),
                           _sail_terms(yacht.with_(headsail=JIB), lam, ForceSwitches(rig_interaction="none")))
    assert np.array_equal(_sail_terms(yacht, lam, ForceSwitches()),
                          _sail_terms(yacht, lam, ForceSwitches(rig_interaction="none")))


def _trajectory_digest(params) -> str:
    env = suite.load(params, "heading_hold", seed=5)
    env.reset()
    digest = hashlib.sha256()
    for _ in range(60):
        env.step(np.array([0.05, 0.3]))
        digest.update(env.physics.data.qpos.tobytes() + env.physics.data.qvel.tobytes())
    return digest.hexdigest()


def test_a_headsail_of_zero_area_changes_no_bit():
    yacht = get_boat("wille_yacht")
    none = yacht.with_(headsail=Headsail(area=0.0, luff_height=8.5, head_aft=3.1, tack_x=4.9,
                                         tack_height=0.8, min_angle=0.1, max_angle=1.0))
    assert np.array_equal(pack_parameters(yacht), pack_parameters(none))
    assert _trajectory_digest(yacht) == _trajectory_digest(none)
    assert pack_parameters(yacht)[P_HEADSAIL_BLOCK:P_HEADSAIL_BLOCK + hs.HB_INTERACTION].sum() == 0.0
    assert P_HEADSAIL_BLOCK + hs.HEADSAIL_BLOCK_SIZE <= P_SIZE


def test_the_trim_rule():
    low, high = math.radians(9.0), math.radians(60.0)
    assert hs.headsail_angle(math.radians(20.0), 0.3, low, high) == (math.radians(20.0), 0.3)
    assert hs.headsail_angle(math.radians(-4.0), 0.3, low, high) == (-low, 0.0)
    assert hs.headsail_angle(math.radians(80.0), 0.3, low, high) == (high, 0.0)
    assert hs.headsail_angle(0.0, 0.3, low, high) == (low, 0.0)


def test_circulation_and_induced_velocity_by_hand():
    # air going +x at 5 m/s, lift +y of 120 N over a 6 m span at rho 1.2: L' = 20 N/m,
    # Gamma = -L' / (rho V) = -20 / 6 = -3.3333 m^2/s (clockwise, Kutta-Joukowski L' = rho V x Gamma)
    gamma = hs.circulation(np.array([3.0, 120.0, 0.0]), np.array([5.0, 0.0, 0.0]), 1.2, 6.0)
    assert gamma == pytest.approx(-20.0 / 6.0, rel=1e-12)  # the drag (x) drops out
    ahead = np.zeros(3)
    hs.add_induced(gamma, 0.0, 0.0, -2.0, 0.0, 0.5, ahead)  # 2 m upstream, core 0.5 m
    # Gamma z x d / (2 pi (|d|^2 + c^2)) with d = (-2, 0): (0, -2 Gamma) / (2 pi 4.25) = +0.24965 y
    assert ahead == pytest.approx([0.0, 2.0 * (20.0 / 6.0) / (2.0 * math.pi * 4.25), 0.0], rel=1e-12)
    behind = np.zeros(3)
    hs.add_induced(gamma, 0.0, 0.0, 2.0, 0.0, 0.5, behind)
    assert behind[1] == pytest.approx(-ahead[1], rel=1e-12)  # upwash ahead, downwash behind


def _angle_of_attack(flow, angle):
    """The angle between the air's path (where it goes) and a sail's chord from luff to leech,
    (-cos, sin) of its angle: the air meets the sail at the luff and leaves at the leech."""
    leech = np.array([-math.cos(angle), math.sin(angle), 0.0])
    return math.acos(float(flow @ leech) / float(np.linalg.norm(flow)))


def test_the_mains_upwash_lifts_the_jib_and_the_jibs_downwash_heads_the_main():
    """Close-hauled on starboard: the air from 30 deg off the bow (blowing aft and to port), both
    booms to port at 10 deg. The jib meets the air at a larger angle of attack with the main
    behind it, the main at a smaller one with the jib ahead of it."""
    p = get_boat("wille_yacht").with_(headsail=JIB)
    block = pack_parameters(p)[P_HEADSAIL_BLOCK:P_HEADSAIL_BLOCK + hs.HEADSAIL_BLOCK_SIZE]
    beta, lam = math.radians(30.0), math.radians(10.0)
    alone = np.array([-math.cos(beta), math.sin(beta), 0.0]) * 6.0
    main_flow, jib_flow = alone.copy(), alone.copy()
    work = [np.zeros(3) for _ in range(4)]
    slope = 2.0 * math.pi * 5.0 / 7.0
    main_point = np.array([p.sail.mast_x - p.sail.ce_aft * math.cos(lam), p.sail.ce_aft * math.sin(lam),
                           p.sail.ce_height])
    h = p.headsail
    jib_point = np.array([h.tack_x - h.ce_aft * math.cos(lam), h.ce_aft * math.sin(lam), h.ce_height])
    hs.interact(main_flow, jib_flow, lam, lam, main_point, jib_point, block, True, 0.3,
                math.radians(15.0), 0.005, 1.2, p.sail.area, slope, 1.5, *work)
    assert _angle_of_attack(jib_flow, lam) > _angle_of_attack(alone, lam) + math.radians(1.0)
    assert _angle_of_attack(main_flow, lam) < _angle_of_attack(alone, lam) - math.radians(1.0)


def test_the_paper_world_refuses_a_boat_with_a_headsail_in_one_line():
    message = ("boat 'eleven_metre' carries a headsail, and Wille's 4-DOF paper world has the main "
               "alone and no crew: sail it in the 'mujoco' world")
    with pytest.raises(ValueError, match=message):
        suite.load("eleven_metre", "heading_hold", "paper")
    assert ("eleven_metre", "heading_hold", "paper") not in suite.SUITE
    assert ("eleven_metre", "heading_hold", "mujoco") in suite.SUITE
    suite.load(get_boat("eleven_metre", headsail=False, crew=False), "heading_hold", "paper")  # main alone
