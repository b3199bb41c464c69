"""The cambered sail: the lift its camber adds by thin-aerofoil theory (2 a f, normal to the flow,
on the loaded side), filled over the first 2 f of incidence and faded past the stall, held at the
rig's largest lift; a flat sail (camber 0) gets nothing, and the shipped boats are flat."""

import math

import numpy as np
import pytest

from sailmujoco.boat.catalogue import BUILT_IN, get_boat
from sailmujoco.forces import sail_camber as sc

AR = 5.0
A0 = 2.0 * math.pi
# Helmbold (1942): a = a0 / (sqrt(1 + (a0 / (pi A))^2) + a0 / (pi A)) = 4.2527 /rad at A = 5
SLOPE = A0 / (math.sqrt(1.0 + (A0 / (math.pi * AR)) ** 2) + A0 / (math.pi * AR))


def _added(alpha_deg: float, camber: float, flat_lift: float = 0.0):
    """The camber's force on a sail along +x (chord (1, 0, 0), normal (0, 1, 0)) with the air
    coming at alpha from ahead; ``flat_lift`` the flat sail's lift coefficient already in ``out``."""
    a = math.radians(alpha_deg)
    flow = np.array([-math.cos(a), math.sin(a), 0.0]) * 6.0  # the air goes aft, turned by alpha
    chord, normal = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    up = np.array([-flow[1], flow[0], 0.0]) / 6.0  # normal to the flow
    side = up if up @ -normal * np.sign(a) > 0 else -up  # the loaded side: that of -sign(alpha) n
    q_area = 0.5 * 1.2 * 36.0 * 20.0
    out = flat_lift * q_area * side
    before = out.copy()
    sc.add_camber_lift(flow, chord, normal, a, 6.0, camber, SLOPE, math.radians(15.0), 1.2, 20.0, out)
    return (out - before) / q_area, side


def test_a_partly_filled_sail_adds_its_share_of_2_a_f_normal_to_the_flow():
    added, side = _added(5.0, 0.10)
    filled = math.radians(5.0) / 0.2  # 5 deg of the 2 f = 0.2 rad it takes to fill
    assert added == pytest.approx(2.0 * SLOPE * 0.10 * filled * side, rel=1e-12)


def test_a_filled_sail_adds_2_a_f_and_past_the_stall_it_fades():
    added, side = _added(12.0, 0.10)  # 12 deg > 2 f = 11.46 deg: filled
    assert added == pytest.approx(2.0 * SLOPE * 0.10 * side, rel=1e-12)
    added, side = _added(22.5, 0.10)  # half way from the stall (15 deg) to twice it
    assert added == pytest.approx(0.5 * 2.0 * SLOPE * 0.10 * side, rel=1e-12)
    assert np.all(_added(31.0, 0.10)[0] == 0.0)


def test_the_loaded_side_follows_the_incidence():
    plus, side_plus = _added(8.0, 0.10)
    minus, side_minus = _added(-8.0, 0.10)
    assert plus[1] < 0.0 < minus[1]  # alpha > 0 loads -n (-y), as the flat sail's normal force
    assert np.linalg.norm(plus) == pytest.approx(np.linalg.norm(minus), rel=1e-12)


def test_the_rig_is_held_at_its_largest_lift():
    added, side = _added(12.0, 0.10, flat_lift=1.4)
    assert added == pytest.approx((sc.MAX_LIFT - 1.4) * side, rel=1e-9)
    assert np.all(_added(12.0, 0.10, flat_lift=1.6)[0] == 0.0)  # never takes lift away


def test_a_flat_sail_gets_nothing_and_the_shipped_paper_boats_are_flat():
    assert np.all(_added(8.0, 0.0)[0] == 0.0)
    for name in ("wille_yacht", "saoud_robot", "viel_boat"):
        assert name in BUILT_IN and get_boat(name).sail.camber == 0.0
    assert get_boat("eleven_metre").sail.camber == 0.10
    assert get_boat("eleven_metre", camber=0.0).sail.camber == 0.0
