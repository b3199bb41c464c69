"""Every boat compiles, sails 60 s in gusty wind with random commands, stays finite."""

import math

import mujoco
import numpy as np
import pytest
from conftest import BOATS, gusty, load

from sailmujoco.boat import geometry as boat_geometry
from sailmujoco.boat import mjcf
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.forces.wind import WindConfig


@pytest.mark.parametrize("boat", BOATS)
@pytest.mark.parametrize("hydrostatics", ["paper", "geometric"])
def test_sixty_seconds_gusty_random_commands(boat, hydrostatics):
    physics = load(boat, wind=gusty(10.0, seed=3), hydrostatics=hydrostatics)
    rng = np.random.default_rng(7)
    low, high = physics.model.actuator_ctrlrange.T
    warnings_before = physics.data.warning.number.copy()
    heels, speeds = [], []
    while physics.data.time < 60.0 - 1e-9:
        physics.set_control(rng.uniform(low, high))
        physics.step(100)  # 0.5 s
        heels.append(physics.heel())
        speeds.append(physics.speed_over_ground())
    assert np.all(physics.data.warning.number == warnings_before), "MuJoCo warned"
    assert np.all(np.isfinite(physics.data.qpos)) and np.all(np.isfinite(physics.data.qvel))
    assert physics.data.time == pytest.approx(60.0)
    # the wind does something: the boat heels and moves, but stays upright
    assert 2.0 < math.degrees(max(np.abs(heels))) < 90.0
    assert max(speeds) > 0.05


@pytest.mark.parametrize("boat", BOATS)
@pytest.mark.parametrize("sail_mode", mjcf.SAIL_MODES)
def test_model_structure(boat, sail_mode):
    p = get_boat(boat)
    model = mjcf.compile_model(p, sail_mode)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key("home").id)
    mujoco.mj_forward(model, data)
    # composite rigid body equals the paper's mass, CG and inertia
    assert model.body_subtreemass[model.body("hull").id] == pytest.approx(p.mass, rel=1e-12)
    assert data.subtree_com[model.body("hull").id] == pytest.approx([p.cg_x, 0.0, p.cg_z], abs=1e-6)
    full = np.zeros((model.nv, model.nv))
    mujoco.mj_fullM(model, data, full)
    # rotational block of the free joint about CO = inertia about CG + m r^2 (CG on the z axis)
    ixx, iyy, izz = p.inertia
    # the MJCF text (MjSpec.to_xml) keeps 6 significant digits: the hull body's diaginertia of
    # ~156 kg m^2 (viel_boat) is written to +-5e-4, i.e. up to 3e-6 of the boat's Ixx
    assert full[3, 3] == pytest.approx(ixx + p.mass * p.cg_z**2, rel=5e-6)
    assert full[5, 5] == pytest.approx(izz, rel=5e-6)
    for site in ("sail_ce", "keel_cp", "rudder_cp", "masthead", "sheet_block", "boom_end"):
        model.site(site)
    assert model.ncam >= 2 + 1  # two on the boat, one in the scene
    assert model.nu == 2
    names = [model.actuator(i).name for i in range(model.nu)]
    assert names == (["rudder", "sail"] if sail_mode == "actuated" else ["rudder", "sheet"])
    # the sail CE site sits where the parameters say (Wille eq. 26 for the yacht)
    ce = data.site_xpos[model.site("sail_ce").id]
    assert ce == pytest.approx([p.sail.mast_x - p.sail.ce_aft, 0.0, p.sail.ce_height], abs=1e-6)


@pytest.mark.parametrize("boat", BOATS)
def test_committed_xml_is_generated_from_params(boat):
    committed = mjcf.xml_root().joinpath(boat, f"{boat}.xml").read_text()
    assert committed == mjcf.boat_xml(get_boat(boat)), (
        "xml is stale: run `python -m sailmujoco.boat.mjcf xml`")


def test_wille_foil_positions_follow_eqs_26_30_34():
    p = get_boat("wille_yacht")
    # eq. 26: mast at -l1 = +1.82 m, CE l2 = 1.35 m behind it, h1 = 5.2 m up
    assert (p.sail.mast_x, p.sail.ce_aft, p.sail.ce_height) == (1.82, 1.35, 5.2)
    # eq. 30: keel CP at -l3 = 0.66 m, h2 = 0.95 m down; eq. 34: rudder at -l4 = -3.7 m
    assert (p.keel.x, p.keel.z, p.rudder.x, p.rudder.z) == (0.66, -0.95, -3.7, -0.7)


def test_sheeted_sail_is_limited_by_the_sheet():
    """A sheeted sail weathervanes out until the sheet stops it; a longer sheet lets it further."""
    angles = []
    for angle_deg in (20.0, 50.0):
        # boat heads east; steady wind from 240 deg: from the starboard quarter
        wind = WindConfig(speed=6.0, direction_from=math.radians(240.0), gusts=False,
                          wander=False)
        physics = load("wille_yacht", wind=wind, sail_mode="sheeted", hydrostatics="paper")
        p = physics.params
        length = float(mjcf.sheet_length(p, math.radians(angle_deg)))
        physics.set_control([0.0, length])
        physics.step(2000)  # 10 s
        angles.append(abs(math.degrees(physics.sail_angle())))
        assert abs(math.degrees(physics.sail_angle())) == pytest.approx(angle_deg, abs=1.5)
    assert angles[1] > angles[0]


def test_sheet_length_and_angle_are_inverse():
    p = get_boat("saoud_robot")
    angles = np.linspace(0.0, math.pi * 0.95, 20)
    lengths = boat_geometry.sheet_length(p, angles)
    assert boat_geometry.sheet_angle(p, lengths) == pytest.approx(angles, abs=1e-9)


@pytest.mark.parametrize("boat", BOATS)
def test_hull_mesh_is_closed_and_wound_outward(boat):
    """Positive signed volume (outward faces, what back-face culling needs) equal to the canoe
    body plus the topsides up to the deck."""
    from sailmujoco.boat import hull

    p = get_boat(boat)
    verts, faces = boat_geometry.hull_mesh(p)
    v, f = verts.reshape(-1, 3), faces.reshape(-1, 3)
    signed = np.sum(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]]))) / 6.0
    # topsides: every section's trapezoid of height freeboard between half-breadths b and k b
    topsides = hull.waterplane_area(p.hull) * p.hull.freeboard * 0.5 * (1.0 + p.hull.flare)
    expected = hull.volume(p.hull) + topsides
    assert signed == pytest.approx(expected, rel=0.03)
