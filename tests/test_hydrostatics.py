"""Hydrostatics against closed forms: design draft, small-heel moment, roll period."""

import math

import mujoco
import numpy as np
import pytest
from conftest import BOATS, CALM, hull_solid_below_water, load, only_hull

from sailmujoco import frames
from sailmujoco.boat import hull
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.constants import GRAVITY
from sailmujoco.forces import stability
from sailmujoco.forces.hydrostatics import paper_restoring
from sailmujoco.physics import BoatPhysics, ForceSwitches


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
    depth = np.clip(0.0 - cols.z_bottom, 0.0, None)  # flared-topside columns are dry upright
    volume = np.sum(cols.area * depth)
    assert volume == pytest.approx(hull.volume(p.hull), rel=1e-6)
    assert volume == pytest.approx(p.displaced_volume, rel=1e-6)
    centroid_z = np.sum(cols.area * depth * -0.5 * depth) / volume
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


@pytest.mark.parametrize("mode", ["paper", "geometric"])
def test_undamped_roll_free_decay_period(mode):
    """T = 2 pi sqrt((Ixx - K_pdot) / (rho g V GM_t)) within 3 %, Wille yacht (CG 0.575 m
    below CO)."""
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


@pytest.mark.parametrize("boat", ["wille_yacht", "saoud_robot", "viel_boat"])
def test_heave_with_added_mass_larger_than_the_hull_is_stable_and_right(boat):
    """Heave added mass larger than the boat's own (about 6x the yacht's): the free heave period
    is 2 pi sqrt((m + a33) / (rho g A_wp)) for each boat."""
    physics = only_hull(boat, hydrostatics="geometric")
    p = physics.params
    a33 = -p.added_mass[2]
    assert a33 > p.mass
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


def _paper_restoring(heel_deg, pitch_deg, yaw_deg, body_axes=False):
    p = get_boat("wille_yacht")
    rot = frames.matrix_from_euler(*np.radians([heel_deg, pitch_deg, yaw_deg]))
    k = p.rho_water * GRAVITY * p.displaced_volume * p.gm_t
    out = np.zeros(6)
    paper_restoring(0.0, rot, p.mass * GRAVITY, k, False, 5.0e5, 5.0e5, 0.3, -0.2, body_axes, out)
    return rot, rot @ out[3:], k, rot @ out[:3]


@pytest.mark.parametrize("yaw_deg", [0.0, 37.0, -120.0])
def test_paper_restoring_is_a_couple_of_vertical_forces(yaw_deg):
    """Zero world-vertical moment at heel 20 deg, pitch 5 deg (Wille eq. 20 is buoyancy and
    weight, both vertical); the generalised force on the heel angle (the moment about the
    CG's body x axis, the axis heel turns about) is eq. 20's, and on the pitch angle k sin."""
    rot, moment_world, k, force_world = _paper_restoring(20.0, 5.0, yaw_deg)
    heading = np.array([rot[0, 0], rot[1, 0], 0.0]) / np.hypot(rot[0, 0], rot[1, 0])
    roll = moment_world @ heading
    assert abs(moment_world[2]) < 1e-9 * abs(roll)
    # about the CG (0.3, 0, -0.2): the vertical force's lever arm is taken out
    cg_world = rot @ np.array([0.3, 0.0, -0.2])
    assert force_world[:2] == pytest.approx([0.0, 0.0], abs=1e-9)
    about_cg = moment_world - np.cross(cg_world, force_world)
    heel, pitch = math.radians(20.0), math.radians(5.0)
    assert about_cg @ rot[:, 0] == pytest.approx(-k * math.sin(heel) * math.cos(heel), rel=1e-12)
    # pitch: about -y1 (the axis pitch turns about, bow up), -k_theta sin(theta)
    y1 = np.cross([0.0, 0.0, 1.0], heading)
    assert about_cg @ -y1 == pytest.approx(-5.0e5 * math.sin(pitch), rel=1e-12)
    # the body-axes form has a yaw part: the switch keeps it measurable
    _, old, _, _ = _paper_restoring(20.0, 5.0, yaw_deg, body_axes=True)
    assert abs(old[2]) > 0.01 * abs(roll)


def _hull_volume_below_water(p, heave, trim, heel):
    """Displaced volume by the midpoint grid over the hull solid (conftest), independent of the
    column quadrature the physics integrates."""
    return hull_solid_below_water(p, heave, trim, heel)[0]


@pytest.mark.parametrize("boat", BOATS)
@pytest.mark.parametrize("heel_deg", [10.0, 20.0, 30.0])
def test_four_dof_geometric_boat_floats_at_its_weight(boat, heel_deg):
    """Heave and pitch held, the hydrostatics come from the hull floating at this heel: its
    displacement is the weight's volume within 1 % (the held pose would give +34 % at 20
    deg), and its righting moment is the freely floating hull's (stability.righting_moment)."""
    physics = load(boat, hydrostatics="geometric", dofs=4)
    p = physics.params
    heel = math.radians(heel_deg)
    with physics.reset_context():
        physics.data.qpos[3] = heel
    physics._compute_forces()
    heave, trim = physics.floating_pose()
    assert _hull_volume_below_water(p, heave, trim, heel) == pytest.approx(p.displaced_volume, rel=0.01)
    assert physics.submerged_volume() == pytest.approx(p.displaced_volume, rel=0.01)
    rot = physics.rotation()
    wrench = physics.force_term("hydrostatics")
    cg = np.array([p.cg_x, 0.0, p.cg_z])
    righting = -(rot @ (wrench[3:] - np.cross(cg, wrench[:3])))[0]
    assert righting == pytest.approx(stability.righting_moment(p, heel), rel=0.01)
    assert (rot @ wrench[:3])[2] == pytest.approx(p.mass * GRAVITY, rel=1e-9)


@pytest.mark.parametrize("heel_deg", [10.0, 20.0, 30.0])
def test_four_dof_paper_restoring_is_saouds_eq4_with_a_low_cg(heel_deg):
    """Heave and pitch held, CG 0.84 m below CO (robot, l_phi = 1 m): hydrostatics and gravity
    together give m g l_phi sin(phi) about the roll joint (Saoud eq. 4), nothing more."""
    physics = BoatPhysics.load("saoud_robot", wind=CALM, dofs=4, l_phi=1.0,
                               forces=ForceSwitches(hydrostatics="paper", sail=False, keel=False,
                                                    rudder=False, damping=False, added_mass=False))
    p = physics.params
    heel = math.radians(heel_deg)
    m, d = physics.model.ptr, physics.data.ptr
    d.qpos[3] = heel
    mujoco.mj_forward(m, d)
    physics._compute_forces()
    # roll joint: qfrc_applied from our forces plus MuJoCo's gravity (-qfrc_bias at rest)
    roll = d.qfrc_applied[3] - d.qfrc_bias[3]
    assert roll == pytest.approx(-p.mass * GRAVITY * 1.0 * math.sin(heel), rel=1e-6)


@pytest.mark.parametrize("boat", BOATS)
def test_the_step_s_vector_lane_volume_is_the_ordered_column_sum(boat):
    """The force kernel's hull volume (its column sums on vector lanes, no branches) equals the
    ordered column integration to rounding (1e-12 of the volume) at every attitude, upside down
    included (there it is the ordered sum itself)."""
    from sailmujoco.forces.hydrostatics import submerged_volume, upright_submerged_volume

    p = get_boat(boat)
    columns = hull.column_quadrature(p.hull).array()
    draft = p.hull.canoe_draft
    for heel_deg, pitch_deg, z in [(0, 0, 0.0), (25, 3, 0.1 * draft), (-60, -8, -0.3 * draft),
                                   (89, 0, 0.0), (120, 5, 0.0), (180, 0, 0.5 * draft)]:
        rot = frames.matrix_from_euler(math.radians(heel_deg), math.radians(pitch_deg), 0.3)
        ordered = np.array(submerged_volume(z, rot, columns))
        lanes = np.array(upright_submerged_volume(z, rot, columns))
        scale = np.array([1.0, p.hull.length, p.hull.length, p.hull.length]) * max(ordered[0], 1e-9)
        assert np.all(np.abs(lanes - ordered) <= 1e-12 * scale), (heel_deg, pitch_deg, z)
