"""The moving sea of the videos: a height field that follows the waves' elevation around the boat."""

import math

import numpy as np
import pytest

from sailmujoco.boat.catalogue import get_boat
from sailmujoco.options import WaveConfig
from sailmujoco.video import SceneRenderer, Snapshot

GRAVITY = 9.81
FORCES = {name: np.array([200.0, 80.0, 0.0]) for name in ("sail", "keel", "rudder")}


def snap(time, position=(3.0, -2.0, 0.0)):
    return Snapshot(time=time, position=np.array(position, float), rotation=np.eye(3), rudder=0.05,
                    sail=0.4, speed=2.0, heel=0.0, awa=1.4, aws=5.0, wind=np.array([0.0, -5.0, 0.0]),
                    forces=FORCES)


@pytest.fixture(scope="module")
def boat():
    return get_boat("wille_yacht")


def renderer(boat, waves, **kw):
    try:
        return SceneRenderer(boat, 96, 64, overlay=False, forces=False, waves=waves, **kw)
    except Exception as err:  # no GL platform here
        pytest.skip(f"no offscreen rendering: {err}")


def test_heights_are_the_regular_wave_at_the_grid_points(boat):
    """A regular wave from the west (travelling east): eta = H/2 cos(k x - omega t), k = omega^2/g,
    after the ramp (3 T). MuJoCo stores h in [0, 1] and draws z = z_geom + size[2] h: the decoded
    heights match within 1e-6 of the range, and a ray from above meets the drawn surface there."""
    import mujoco

    H, T = 1.2, 5.0
    waves = WaveConfig(spectrum="regular", hs=H, tp=T, direction_from=1.5 * math.pi)  # from the west
    with renderer(boat, waves) as r:
        t = 4.0 * T + 1.3
        r.pose(snap(t, position=(41.0, -13.0, 0.0)))
        sea = r.sea
        assert r.model.geom_contype[sea.geom_id] == 0 and r.model.geom_conaffinity[sea.geom_id] == 0
        omega = 2.0 * math.pi / T
        k = omega**2 / GRAVITY
        x, y = sea.grid()
        expected = 0.5 * H * np.cos(k * x - omega * t)
        inside = sea.window == 1.0  # the faded outer tile excepted
        assert inside.sum() > 0.25 * inside.size
        range_ = r.model.hfield_size[sea.hfield_id][2]
        assert range_ == pytest.approx(H)  # 2 A, A = H/2
        error = np.abs(sea.heights() - expected)[inside].max()
        assert error < 1e-6 * range_
        # the boat is inside the exact region, a hull length or more from its edge
        half = sea.layout.half - sea.layout.tile
        assert abs(41.0 - sea.centre[0]) < half - boat.hull.length
        assert abs(-13.0 - sea.centre[1]) < half - boat.hull.length
        # where MuJoCo draws it: rays straight down onto a few grid points
        mujoco.mj_kinematics(r.model, r.data)
        rows, cols = np.nonzero(inside)
        for i in np.linspace(0, rows.size - 1, 7).astype(int):
            px, py = x[rows[i], cols[i]], y[rows[i], cols[i]]
            geomid = np.array([-1], np.int32)
            dist = mujoco.mj_ray(r.model, r.data, np.array([px, py, 10.0]), np.array([0.0, 0.0, -1.0]),
                                 None, 1, -1, geomid)
            assert geomid[0] == sea.geom_id
            assert 10.0 - dist == pytest.approx(expected[rows[i], cols[i]], abs=1e-4)


def test_quarter_period_apart_the_water_moves(boat):
    T = 6.0
    waves = WaveConfig(spectrum="regular", hs=1.5, tp=T, direction_from=0.5 * math.pi)
    camera = (np.array([3.0, -2.0, 0.5]), 25.0, 60.0, -25.0)
    with renderer(boat, waves) as r:
        a = r.render(snap(20.0), camera=camera).astype(float)
        b = r.render(snap(20.0 + 0.25 * T), camera=camera).astype(float)
        c = r.render(snap(20.0 + T), camera=camera).astype(float)
    water = slice(a.shape[0] // 2, None)  # the lower half: water only
    assert np.abs(a[water] - b[water]).mean() > 2.0  # grey levels
    assert np.abs(a[water] - c[water]).mean() < 0.25 * np.abs(a[water] - b[water]).mean()


def test_without_a_sea_the_flat_surface_is_drawn(boat):
    """waves=None, calm water and no keyword draw the same frame: the flat plane, no height field."""
    frames = []
    for kw in ({}, {"waves": None}, {"waves": WaveConfig(hs=0.0)}):
        with renderer(boat, kw.get("waves")) if kw else SceneRenderer(
                boat, 96, 64, overlay=False, forces=False) as r:
            assert r.sea is None and r.model.nhfield == 0
            assert r.model.geom("sea_surface").id >= 0
            frames.append(r.render(snap(20.0)))
    assert np.array_equal(frames[0], frames[1]) and np.array_equal(frames[0], frames[2])


# ----------------------------------------------------------------------------- a video in a sea
def test_a_video_in_a_sea_draws_the_moving_elevation(boat, tmp_path, monkeypatch):
    """record() in a JONSWAP sea: between two frames the stored heights change by a good part of
    the sea's height, and at grid points inside the exact region each frame's heights are the
    elevation at that frame's time, evaluated point by point."""
    pytest.importorskip("imageio_ffmpeg")
    from sailmujoco import video
    from sailmujoco.forces.waves import elevation
    from sailmujoco.video import recording

    waves = WaveConfig(spectrum="jonswap", hs=1.0, tp=4.0, direction_from=0.3, n_components=6, seed=5)
    seen = []  # (time, heights, grid) of each frame drawn

    class Here:
        """record()'s ChildRenderer, drawing in this process so that the sea can be read."""

        def open(self, *args, **kwargs):
            self.scene = video.SceneRenderer(*args, **kwargs)
            self.width, self.height = self.scene.width, self.scene.height
            return self

        def render(self, snap, *args, **kwargs):
            frame = self.scene.render(snap, *args, **kwargs)
            x, y = self.scene.sea.grid()
            sea = self.scene.sea
            seen.append((snap.time, sea.heights().copy(), x.copy(), y.copy(), sea.window))
            return frame

        def close(self):
            self.scene.close()

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.close()

    monkeypatch.setattr(recording, "ChildRenderer", Here)
    try:
        rec = video.record("wille_yacht", "beam_reach_roll", "wille_roll", tmp_path / "sea.mp4",
                           seconds=14.0, fps=0.5, width=96, height=64, overlay=False, waves=waves)
    except video.RenderingUnavailable as err:
        pytest.skip(f"no offscreen rendering: {err}")
    assert rec.frames == 7 and len(seen) == 7
    (t1, h1, *_), (t2, h2, *_) = seen[-2], seen[-1]
    assert t2 - t1 == pytest.approx(2.0)  # both after the ramp (3 Tp = 12 s) or at its end
    assert np.abs(h2 - h1).mean() > 0.1 * waves.hs
    rng = np.random.default_rng(1)
    for time, heights, x, y, window in seen[-3:]:
        rows, cols = np.nonzero(window == 1.0)
        for i in rng.choice(rows.size, 5, replace=False):
            r, c = rows[i], cols[i]
            expected = float(elevation(waves, time, float(x[r, c]), float(y[r, c])))
            assert heights[r, c] == pytest.approx(expected, abs=1e-6 * 2 * waves.hs)


# ----------------------------------------------------------------------------- the command line
def cli_video(tmp_path, *waves_arguments):
    from sailmujoco.cli.main import main

    return main(["video", "wille_yacht", "beam_reach_roll", "--controller", "wille_roll",
                 "--seconds", "0.4", "--fps", "5", "--width", "64", "--height", "48",
                 "--no-overlay", "--no-progress", "--out", str(tmp_path / "sea.mp4"),
                 *[a for pair in waves_arguments for a in ("--waves", pair)]])


def test_cli_sea_comes_from_the_wind_unless_given(tmp_path, monkeypatch, capsys):
    """--waves KEY=VALUE builds the sea; without direction_from_deg it comes from the bearing of
    the wind the task's physics is loaded with (read here from a separately loaded run)."""
    from sailmujoco import suite
    from sailmujoco.cli import video as command

    given = []
    record = command.record

    def spy(*args, **kwargs):
        given.append(kwargs["waves"])
        return record(*args, **kwargs)

    monkeypatch.setattr(command, "record", spy)
    try:
        code = cli_video(tmp_path, "hs=0.8", "tp=5", "n_components=4", "seed=2")
    except Exception as err:  # no GL platform here
        pytest.skip(f"no offscreen rendering: {err}")
    out = capsys.readouterr().out
    assert code == 0 and "2 frames" in out and (tmp_path / "sea.mp4").stat().st_size > 0
    wind = suite.load("wille_yacht", "beam_reach_roll", seed=0).physics.wind.config
    sea = given[0]
    assert (sea.spectrum, sea.hs, sea.tp, sea.n_components, sea.seed) == ("jonswap", 0.8, 5, 4, 2)
    assert sea.direction_from == pytest.approx(wind.direction_from, abs=1e-12)
    code = cli_video(tmp_path, "hs=0.8", "n_components=4", "spectrum=regular", "direction_from_deg=45")
    assert code == 0
    assert given[1].spectrum == "regular" and given[1].direction_from == pytest.approx(math.pi / 4)


@pytest.mark.parametrize("pair, message", [
    ("hs=-1", "--waves hs must be >= 0 m, got -1"),
    ("tp=0", "--waves tp must be > 0 s"),
    ("spectrum=jonswp", "did you mean 'jonswap'"),
    ("gamma=9", "--waves gamma must be in [1, 7]"),
    ("n_components=0", "--waves n_components must be an integer >= 1"),
    ("height=2", "unknown sea option 'height' in --waves"),
])
def test_cli_bad_sea_is_one_line_and_exit_2(tmp_path, capsys, pair, message):
    code = cli_video(tmp_path, pair)
    err = capsys.readouterr().err
    assert code == 2 and message in err and len(err.strip().splitlines()) == 1, err
    assert "Traceback" not in err and not (tmp_path / "sea.mp4").exists()


def test_cli_paper_world_refuses_a_sea(tmp_path, capsys):
    from sailmujoco.cli.main import main

    code = main(["video", "wille_yacht", "beam_reach_roll", "--controller", "wille_roll", "--world",
                 "paper", "--waves", "hs=1", "--out", str(tmp_path / "x.mp4")])
    err = capsys.readouterr().err
    assert code == 2 and "--waves" in err and "--world mujoco" in err and len(err.splitlines()) == 1


def test_video_help_shows_the_sea_with_an_example(capsys):
    from sailmujoco.cli.main import main

    for command in ("video", "view"):
        with pytest.raises(SystemExit):
            main([command, "--help"])
        out = capsys.readouterr().out
        assert "--waves KEY=VALUE" in out and "--waves hs=1.5" in out


# ----------------------------------------------------------------------------- the waves in a still
def test_the_sun_stands_low_over_the_bearing_the_waves_come_from(boat):
    """Waves from the south-west (225 deg) travel north-east: the sun's light goes that way,
    10 deg or so down, so that a slope facing the waves' origin is lit and its back is not."""
    waves = WaveConfig(spectrum="regular", hs=1.0, tp=5.0, direction_from=math.radians(225.0))
    with renderer(boat, waves) as r:
        light = r.model.light_dir[r.model.light("sun").id]
        light = light / np.linalg.norm(light)
    assert light[0] == pytest.approx(light[1]) and light[0] > 0.0  # toward the north-east
    assert 5.0 < math.degrees(math.asin(-light[2])) < 20.0  # low over the horizon


def test_a_still_from_above_shows_the_crests_where_the_elevation_has_them(boat):
    """A regular wave from the west seen straight down: along the image's rows the brightness
    repeats at the wavelength g T^2/(2 pi) and follows the slope d eta/dx (the side facing the
    low western sun is lit); calm water under the same camera is flat."""
    H, T = 0.6, 3.0
    wavelength = GRAVITY * T**2 / (2.0 * math.pi)  # 14.05 m
    waves = WaveConfig(spectrum="regular", hs=H, tp=T, direction_from=1.5 * math.pi)
    centre, extent, (w, h) = (0.0, 22.0), 14.0, (160, 120)  # inside the exact region, boat not in view
    kw = dict(camera="top", top_center=centre, top_extent=extent)
    t = 10.0 * T + 0.7
    try:
        with SceneRenderer(boat, w, h, overlay=False, forces=False, waves=waves, **kw) as r:
            sea = r.render(snap(t, position=(0.0, 0.0, 0.0))).astype(float).mean(axis=2)
        with SceneRenderer(boat, w, h, overlay=False, forces=False, **kw) as r:
            calm = r.render(snap(t, position=(0.0, 0.0, 0.0))).astype(float).mean(axis=2)
    except Exception as err:  # no GL platform here
        pytest.skip(f"no offscreen rendering: {err}")
    profile, flat = sea.mean(axis=0), calm.mean(axis=0)
    assert flat.std() < 0.2 * profile.std()
    x = centre[0] + (np.arange(w) + 0.5 - 0.5 * w) * (2.0 * extent / h)  # m, each column's east
    lengths = np.linspace(0.5, 2.0, 301) * wavelength
    power = [abs(np.sum((profile - profile.mean()) * np.exp(-2j * math.pi * x / L))) for L in lengths]
    assert lengths[int(np.argmax(power))] == pytest.approx(wavelength, rel=0.05)
    k, omega = 2.0 * math.pi / wavelength, 2.0 * math.pi / T
    slope = -0.5 * H * k * np.sin(k * x - omega * t)  # d eta/dx of eta = H/2 cos(k x - omega t)
    assert np.corrcoef(profile, slope)[0, 1] > 0.7
