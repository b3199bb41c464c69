"""What a frame shows: a camera that sees the sail's face, a panel that never covers the scene,
a map whose scale bar and fit follow from its geometry, a sea texture that tiles, and a scene
file whose physics the pictures leave alone."""

from __future__ import annotations

import math

import numpy as np
import pytest

from sailmujoco import suite, sweep, video
from sailmujoco.boat import catalogue, mjcf
from sailmujoco.video import panel, water
from sailmujoco.video.camera import OFF_NORMAL, SIDE_HYSTERESIS


@pytest.mark.parametrize("boom_deg", [-85, -60, -40, -20, -8, 8, 20, 40, 60, 85])
def test_follow_camera_sees_the_sail_face_from_the_side_away_from_the_boom(boom_deg):
    """Horizontal geometry in the boat's frame (x forward, y port): the sail's plane holds the
    boom, at 180 deg - boom from the bow (counter-clockwise); the camera at bearing b looks
    back along b + 180 deg. The line of sight must meet the sail at 45 deg or more."""
    camera = video.FollowCamera(distance=10.0, height=2.0, lag=0.0)
    boom = math.radians(boom_deg)
    bearing = camera.bearing_for(boom)
    sail = np.array([-math.cos(boom), math.sin(boom)])  # from the mast to the boom's end
    sight = -np.array([math.cos(bearing), math.sin(bearing)])  # from the camera to the boat
    meets = math.degrees(math.asin(abs(sail[0] * sight[1] - sail[1] * sight[0])))
    assert meets >= 45.0 - 1e-9
    assert math.degrees(math.pi / 2 - OFF_NORMAL) == pytest.approx(45.0)
    if abs(boom_deg) < 45:  # not dead astern: on the side away from the boom (port is y > 0)
        assert math.sin(bearing) * boom < 0.0


def test_follow_camera_changes_side_only_past_the_hysteresis():
    camera = video.FollowCamera(distance=10.0, height=2.0, lag=0.0)
    port = camera.bearing_for(math.radians(20.0))  # boom to port: camera to starboard
    assert math.sin(port) < 0.0
    small = 0.5 * SIDE_HYSTERESIS
    assert camera.bearing_for(-small) == pytest.approx(math.pi + (math.pi / 2 - small - OFF_NORMAL))
    assert math.sin(camera.bearing_for(-2.0 * SIDE_HYSTERESIS)) > 0.0  # now to port


def test_boom_angle_of_the_display_model_follows_the_sail_joint():
    """The boom hinges about -z (mjcf): a positive sail angle swings it to port."""
    p = catalogue.get_boat("saoud_robot")
    renderer = video.SceneRenderer(p, offscreen=False)
    snap = video.Snapshot(time=0.0, position=np.zeros(3), rotation=np.eye(3), rudder=0.0,
                          sail=math.radians(30.0), speed=0.0, heel=0.0, awa=0.0, aws=0.0,
                          wind=np.array([0.0, -5.0, 0.0]))
    renderer.pose(snap)
    xpos = renderer.data.site_xpos
    ends = xpos[renderer.model.site("mast_step").id], xpos[renderer.model.site("boom_end").id]
    assert math.degrees(video.boom_angle(snap.rotation, *ends)) == pytest.approx(30.0, abs=1e-6)


def _beam_reach_snapshot():
    env = suite.load("wille_yacht", "heading_hold", seed=0, time_limit=1.0)
    policy = sweep.make_controller("pid", env)
    policy.reset(0)
    timestep = env.reset()
    while not timestep.last():
        timestep = env.step(policy(timestep))
    return env, video.snapshot_physics(env.physics, env.task.references(env.physics))


def test_panel_leaves_the_scene_untouched():
    """The frame with the panel, left of the panel, is the scene drawn alone at that width."""
    env, snap = _beam_reach_snapshot()
    width, height = 320, 240
    with video.SceneRenderer(env.physics.params, width, height, overlay=True, follow_lag=0.0) as full:
        framed = full.render(snap)
        scene_width = width - full.panel
    assert full.panel == panel.panel_width(width) > 0
    with video.SceneRenderer(env.physics.params, scene_width, height, overlay=False, follow_lag=0.0) as bare:
        alone = bare.render(snap)
    np.testing.assert_array_equal(framed[:, :scene_width], alone)
    assert framed.shape == (height, width, 3)
    assert (framed[:, scene_width:] == panel.BACKGROUND).all(axis=2).mean() > 0.3  # the panel's own band


def test_panel_text_names_heading_reference_and_true_wind():
    _, snap = _beam_reach_snapshot()
    lines = panel.text_lines(snap, snap.references)
    # heading_hold: desired heading 000; the wind from 090 deg by default at 6 m/s
    assert any(line.endswith("desired 000°") for line in lines)
    wind = [line for line in lines if line.startswith("true wind")][0]
    speed = math.hypot(*snap.wind[:2])
    from_deg = math.degrees(math.atan2(-snap.wind[0], -snap.wind[1])) % 360
    assert wind == f"true wind {speed:.1f} m/s from {round(from_deg) % 360:03d}°"


def test_map_fits_track_and_target_and_scale_bar_is_round():
    target = {"position": (0.0, 0.0), "radii": (7.0, 14.0), "start": (-30.0, 40.0)}
    view = panel.MapView(track=np.array([[-30.0, 40.0], [-20.0, 30.0]]), position=np.array([-20.0, 30.0]),
                         heading=0.0, wind=np.array([0.0, 5.0]), hull_length=4.0, references={},
                         target=target)
    centre, half = panel.map_frame(view)
    np.testing.assert_array_equal(centre, view.position)  # centred on the boat
    for point in ([-30.0, 40.0], [-14.0, -14.0], [14.0, 14.0]):  # start, the outer circle's box
        assert np.all(np.abs(np.asarray(point) - centre) <= half)
    assert [panel.nice_length(x) for x in (7.3, 10.0, 0.031, 49.0)] == [5.0, 10.0, 0.02, 20.0]
    assert panel.compass(math.radians(-10.0)) == "350°"
    assert math.degrees(panel.wind_from([0.0, 5.0])) == pytest.approx(180.0)  # blows north: from south


def test_sea_texture_tiles_without_a_seam():
    tex = water.wave_texture(128).astype(float)
    inside = np.abs(np.diff(tex, axis=0)).mean()
    seam = np.abs(tex[0] - tex[-1]).mean()
    assert seam < 1.5 * inside
    assert tex[..., 2].mean() > tex[..., 0].mean() + 40  # blue water


def test_display_sea_is_see_through_over_deep_water():
    p = catalogue.get_boat("viel_boat")
    model = video.display_model(p)
    sea = model.material("sea").id
    assert model.mat_rgba[sea, 3] == pytest.approx(water.SEA_ALPHA)
    assert model.mat_texrepeat[sea, 0] == pytest.approx(1.0 / (water.TILE_HULLS * p.hull.length))
    deep = model.geom("deep_water")
    foils = p.hull.canoe_draft + max(p.keel.span, p.rudder.span)
    assert -model.geom_pos[deep.id][2] > foils  # below the tips of the keel and the rudder


@pytest.mark.parametrize("boat", ["wille_yacht", "saoud_robot", "viel_boat"])
def test_scene_pictures_leave_the_physics_alone(boat):
    """The simulated model's sea is drawn only: no contact, no mass, one plane."""
    model = mjcf.compile_model(catalogue.get_boat(boat))
    sea = model.geom("sea_surface").id
    assert model.geom_contype[sea] == 0 and model.geom_conaffinity[sea] == 0
    assert model.body_mass[model.geom_bodyid[sea]] == 0.0  # the world body


def test_the_panel_sets_the_instruments_readings_beside_the_truth():
    """A GNSS fix 3 m east and 4 m north of the boat is 5 m off; a compass reading 2.5 deg to
    starboard of the true heading errs +2.5 deg; the vane's own numbers are printed; and the
    fixes are drawn on the map in their own colour, where perfect sensors draw none."""
    from sailmujoco.frames import heading_from_yaw
    from sailmujoco.video.camera import yaw_of

    _, snap = _beam_reach_snapshot()
    heading = float(heading_from_yaw(yaw_of(snap.rotation)))
    snap.measured = {"position": snap.position[:2] + [3.0, 4.0], "heading": heading + math.radians(2.5),
                     "awa": math.radians(-41.0), "aws": 5.25}
    lines = panel.text_lines(snap, snap.references)
    assert "GNSS 5.0 m off, compass +2.5°" in lines and "vane 5.2 m/s, AWA -41°" in lines
    track = np.array([snap.position[:2] - [0.0, 10.0], snap.position[:2]])
    fixes = track + [3.0, 4.0]
    pictures = {}
    for name, drawn in (("measured", fixes), ("perfect", None)):
        view = panel.MapView(track=track, position=snap.position[:2], heading=heading, wind=snap.wind[:2],
                             hull_length=1.5, references={}, fixes=drawn)
        frame = np.zeros((480, 640, 3), np.uint8)
        pictures[name] = panel.draw_panel(frame, np.zeros((480, 640 - 206, 3), np.uint8), "", lines, [], view)
    pink = [(p == panel.FIXES).all(axis=2).sum() for p in (pictures["measured"], pictures["perfect"])]
    assert pink[0] > 20 and pink[1] == 0
    # the map reaches the fixes as it reaches the track
    centre, half = panel.map_frame(panel.MapView(track=track, position=track[-1], heading=0.0,
                                                 wind=np.zeros(2), hull_length=0.1, references={},
                                                 fixes=fixes + [30.0, 0.0]))
    assert np.all(np.abs(fixes + [30.0, 0.0] - centre) <= half)


def test_measured_of_reads_the_instruments_and_nothing_from_perfect_sensors():
    perfect = suite.load("saoud_robot", "heading_hold", seed=0).reset().observation
    assert panel.measured_of(perfect) is None
    sensed = suite.load("saoud_robot", "heading_hold", seed=0, sensors="typical").reset().observation
    got = panel.measured_of(sensed)
    np.testing.assert_array_equal(got["position"], sensed["position"])
    assert got["heading"] == sensed["heading"] and got["aws"] == sensed["apparent_wind_speed"]
