"""Hydrostatics against closed forms: design draft, small-heel moment, roll period."""

import math

import numpy as np
import pytest
from conftest import BOATS, load, only_hull

from sailmujoco import frames, hull, stability
from sailmujoco.constants import GRAVITY
from sailmujoco.params import get_boat


@pytest.mark.parametrize("boat", BOATS)
def test_geometric_hull_floats_at_design_draft(boat):
    physics = load(boat, hydrostatics="geometric")
    p = physics.params
    weight = p.mass * GRAVITY
    # at the home pose (design waterline, upright) buoyancy equals the weight
    assert physics.force_term("hydrostatics")[2] == pytest.approx(weight, rel=0.005)
    # and left alone in calm water it stays there
    physics.step(2000)
    assert physics.position()[2] == pytest.approx(0.0, abs=0.002 * p.hull.canoe_draft + 1e-4)
    buoyancy = np.linalg.norm(physics.force_term("hydrostatics")[:3])
    assert buoyancy == pytest.approx(weight, rel=0.005)


@pytest.mark.parametrize("boat", BOATS)
def test_hull_closed_forms_match_column_integration(boat):
    p = get_boat(boat)
    cols = hull.column_quadrature(p.hull)
    volume = np.sum(cols.area * (0.0 - cols.z_bottom))
    assert volume == pytest.approx(hull.volume(p.hull), rel=1e-6)
    assert volume == pytest.approx(p.displaced_volume, rel=1e-6)
    centroid_z = np.sum(cols.area * -cols.z_bottom * 0.5 * cols.z_bottom) / volume
    assert centroid_z == pytest.approx(hull.centre_of_buoyancy_z(p.hull), rel=1e-3)


@pytest.mark.parametrize("boat", BOATS)
@pytest.mark.parametrize("mode", ["paper", "geometric"])
def test_small_heel_restoring_moment(boat, mode):
    """Restoring moment = rho g V GM_t phi within 2 % at phi = 2 deg."""
    p = get_boat(boat)
    heel = math.radians(2.0)
    expected = p.rho_water * GRAVITY * p.displaced_volume * p.gm_t * heel
    if mode == "geometric":
        moment = stability.righting_moment(p, heel)
    else:
        physics = load(boat, hydrostatics="paper")
        with physics.reset_context():
            physics.data.qpos[3:7] = frames.quat_from_euler(heel, 0.0, 0.0)
            # keep the CG at its design height, as the reduced models do
            physics.data.qpos[2] = p.cg_z - p.cg_z * math.cos(heel)
        physics._compute_forces()
        rot = frames.matrix_from_euler(heel, 0.0, 0.0)
        wrench = physics._terms[3]
        cg = np.array([p.cg_x, 0.0, p.cg_z])
        moment_body = wrench[3:] - np.cross(cg, wrench[:3])  # about the CG
        moment = -(rot @ moment_body)[0]
    assert moment == pytest.approx(expected, rel=0.02)


def test_geometric_righting_curve_departs_from_sin_cos_at_large_heel():
    p = get_boat("wille_yacht")
    curve = stability.righting_curve(p, np.radians([2.0, 10.0, 30.0, 60.0]))
    ratio = curve["geometric"] / curve["sin_cos"]
    assert ratio[0] == pytest.approx(1.0, abs=0.02)
    assert abs(ratio[2] - 1.0) > 0.2 and abs(ratio[3] - 1.0) > 0.2


@pytest.mark.parametrize("mode", ["paper", "geometric"])
def test_undamped_roll_free_decay_period(mode):
    """T = 2 pi sqrt((Ixx - K_pdot) / (rho g V GM_t)) within 3 %, Wille yacht (CG = CO)."""
    physics = only_hull("wille_yacht", hydrostatics=mode)
    p = physics.params
    heel0 = math.radians(3.0)
    with physics.reset_context():
        physics.data.qpos[3:7] = frames.quat_from_euler(heel0, 0.0, 0.0)
    times, heels = [], []
    for _ in range(3000):  # 15 s
        physics.step(1)
        times.append(physics.data.time)
        heels.append(physics.heel())
    heels = np.array(heels)
    times = np.array(times)
    # upward zero crossings, linearly interpolated
    idx = np.nonzero((heels[:-1] < 0) & (heels[1:] >= 0))[0]
    crossings = times[idx] - heels[idx] * (times[idx + 1] - times[idx]) / (heels[idx + 1] - heels[idx])
    period = np.mean(np.diff(crossings))
    ixx = p.inertia[0]
    expected = 2 * math.pi * math.sqrt((ixx - p.added_mass[3])
                                       / (p.rho_water * GRAVITY * p.displaced_volume * p.gm_t))
    assert len(crossings) >= 4
    assert period == pytest.approx(expected, rel=0.03)
    # undamped: the amplitude is kept
    assert np.max(np.abs(heels[-400:])) == pytest.approx(heel0, rel=0.05)


def test_heave_with_added_mass_larger_than_the_hull_is_stable_and_right():
    """Heave added mass ~6x the hull's: the free heave period is 2 pi sqrt((m + a33)/k)."""
    physics = only_hull("wille_yacht", hydrostatics="geometric")
    p = physics.params
    a33 = -p.added_mass[2]
    assert a33 > 5 * p.mass
    with physics.reset_context():
        physics.data.qpos[2] = 0.02
    z = []
    for _ in range(2000):
        physics.step(1)
        z.append(physics.position()[2])
    z = np.array(z)
    k = p.rho_water * GRAVITY * hull.waterplane_area(p.hull)
    expected = 2 * math.pi * math.sqrt((p.mass + a33) / k)
    t = np.arange(1, z.size + 1) * physics.timestep()
    idx = np.nonzero((z[:-1] < 0) & (z[1:] >= 0))[0]
    period = np.mean(np.diff(t[idx]))
    assert period == pytest.approx(expected, rel=0.03)
    assert np.max(np.abs(z)) < 0.021  # bounded: no energy growth
