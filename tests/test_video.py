"""Offscreen video: frames at the video rate, a moving boat, an untouched trajectory, and one
clear error where no OpenGL platform loads.

Rendering runs through MUJOCO_GL=egl (sailmujoco's default): Mesa's llvmpipe on a CPU machine
(Debian: libegl1 libegl-mesa0 libgl1-mesa-dri). Frames are small to keep the file under a
minute on two cores.
"""

from __future__ import annotations

import ctypes.util
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

imageio = pytest.importorskip("imageio.v3")
pytest.importorskip("imageio_ffmpeg")

from sailmujoco import suite, sweep, video  # noqa: E402
from sailmujoco.cli.video import main as video_main  # noqa: E402

FPS = 25
SECONDS = 2.0
W, H = 160, 120


def read_frames(path, height: int = H, width: int = W) -> np.ndarray:
    frames = imageio.imread(path, plugin="FFMPEG", index=None)
    assert frames.dtype == np.uint8 and frames.shape[1:] == (height, width, 3)
    return frames


def boat_pixels(frame: np.ndarray) -> np.ndarray:
    """(row, col) of the white hull and the sail against the blue sea."""
    r, g, b = (frame[..., i].astype(int) for i in range(3))
    return np.argwhere((r > 170) & (g > 170) & (b > 150) & (b - r < 40))  # not the cyan wind arrow


@pytest.fixture(scope="module")
def follow_video(tmp_path_factory):
    """2 s of heading_hold under the PID controller, follow camera, force arrows on."""
    envs = []

    def factory(env):
        envs.append(env)
        return sweep.make_controller("pid", env)

    path = tmp_path_factory.mktemp("video") / "follow.mp4"
    rec = video.record("wille_yacht", "heading_hold", factory, path, seconds=SECONDS, fps=FPS,
                       width=W, height=H, camera="follow", overlay=False, seed=3)
    return rec, envs[0]


def test_frame_count_matches_video_rate_not_control_rate(follow_video):
    rec, env = follow_video
    assert env.control_timestep() == pytest.approx(0.1)  # 10 Hz control, 25 Hz video
    frames = read_frames(rec.path)
    assert abs(len(frames) - SECONDS * FPS) <= 1
    assert rec.frames == round(SECONDS * FPS)
    assert rec.metrics["stopped"] is None


def test_frames_change_and_the_sea_grid_moves_under_the_follow_camera(follow_video):
    frames = read_frames(follow_video[0].path).astype(float)
    assert frames.std(axis=0).mean() > 1.0  # not a constant video
    # the camera rides with the boat (about 2 m/s): the sea in the lower right of the frame
    # moves under it, by more than the encoder's noise over every 0.4 s
    sea = frames[:, H // 2:, W // 2:]
    lagged = np.abs(sea[10:] - sea[:-10]).mean(axis=(1, 2, 3))
    assert lagged.min() > 1.0, lagged


def test_recording_leaves_the_trajectory_unchanged(follow_video):
    """Frames are drawn between physics sub-steps: the run is bit for bit the plain run."""
    _, recorded = follow_video
    env = suite.load("wille_yacht", "heading_hold", seed=3, time_limit=SECONDS)
    policy = sweep.make_controller("pid", env)
    policy.reset(3)
    timestep = env.reset()
    while not timestep.last():
        timestep = env.step(policy(timestep))
    assert env.physics.time() == recorded.physics.time()
    np.testing.assert_array_equal(env.physics.data.qpos, recorded.physics.data.qpos)
    np.testing.assert_array_equal(env.physics.data.qvel, recorded.physics.data.qvel)


def test_boat_translates_across_a_fixed_top_view(tmp_path):
    """Top camera, fixed over the start, north up: the boat's pixels move as the boat does."""
    envs = []

    def factory(env):
        envs.append(env)
        return sweep.make_controller("pid", env)

    extent = 9.0  # m, half-height of the view on the water
    rec = video.record("wille_yacht", "heading_hold", factory, tmp_path / "top.mp4",
                       seconds=SECONDS, fps=FPS, width=W, height=H, camera="top", overlay=False,
                       forces=False, seed=1, top_center=(0.0, 2.0), top_extent=extent,
                       desired_heading_deg=0.0, wind_from_deg=90.0)
    frames = read_frames(rec.path)
    first, last = boat_pixels(frames[0]), boat_pixels(frames[-1])
    assert len(first) > 20 and len(last) > 20
    shift = last.mean(axis=0) - first.mean(axis=0)  # (rows, cols)
    # where the simulation says the boat went between frame 0 and the last frame (t = 1.96 s)
    env = suite.load("wille_yacht", "heading_hold", seed=1, time_limit=SECONDS,
                     desired_heading_deg=0.0, wind_from_deg=90.0)
    policy = sweep.make_controller("pid", env)
    policy.reset(1)
    timestep = env.reset()
    start = env.physics.position()
    while env.physics.time() < (len(frames) - 1) / FPS - 1e-9:
        timestep = env.step(policy(timestep))
    moved = env.physics.position() - start  # m, (east, north); the last step ends at 2.0 s
    assert moved[1] > 1.0  # sailing north
    pixels_per_metre = (H / 2) / extent
    expected_rows = -moved[1] * pixels_per_metre  # north is up
    assert shift[0] == pytest.approx(expected_rows, rel=0.35, abs=2.0)
    assert abs(shift[1] - moved[0] * pixels_per_metre) < 3.0


def test_paper_world_frames_hold_the_control_step_state(tmp_path):
    rec = video.record("wille_yacht", "heading_hold", "pid", tmp_path / "paper.mp4", seconds=1.0,
                       world="paper", fps=20, width=W, height=H, camera="side", seed=0)
    frames = read_frames(rec.path)
    assert abs(len(frames) - 20) <= 1
    # 10 Hz control, 20 Hz video: frames 2k-1 and 2k (t = 0.1 k - 0.05 and 0.1 k) both show
    # the state after control step k; the next pair shows the next step
    frames = frames.astype(float)
    same = np.abs(frames[1:19:2] - frames[2:20:2]).mean(axis=(1, 2, 3))
    moved = np.abs(frames[2:18:2] - frames[3:19:2]).mean(axis=(1, 2, 3))
    assert same.max() < 0.5 < moved.min(), (same, moved)


def test_cli_writes_video_and_still(tmp_path, capsys):
    out, still = tmp_path / "cli.mp4", tmp_path / "still.png"
    code = video_main(["saoud_robot", "heading_hold", "--controller", "saoud", "--seconds", "0.4",
                       "--out", str(out), "--fps", "10", "--width", "64", "--height", "48",
                       "--camera", "side", "--still", str(still), "--no-progress",
                       "--set", "wind_speed=5.0"])
    assert code == 0
    assert out.stat().st_size > 0 and imageio.imread(still).shape == (48, 64, 3)
    assert "4 frames" in capsys.readouterr().out
    assert not list(tmp_path.glob(".*partial*"))


def test_cli_records_the_run_as_an_mcap_log_beside_the_video(tmp_path, capsys):
    from rosbags.rosbag2 import Reader

    out, log = tmp_path / "cli.mp4", tmp_path / "run.mcap"
    code = video_main(["saoud_robot", "heading_hold", "--controller", "saoud", "--seconds", "0.4",
                       "--out", str(out), "--fps", "10", "--width", "64", "--height", "48",
                       "--camera", "side", "--record", str(log), "--no-progress", "--set", "wind_speed=5.0"])
    assert code == 0 and f"wrote {log}" in capsys.readouterr().out
    with Reader(log) as reader:
        clocks = [stamp for connection, stamp, _ in reader.messages() if connection.topic == "/clock"]
    # the reset and the 4 control steps of 0.4 s at 10 Hz, stamped with the simulation's time
    assert clocks == [0, 100_000_000, 200_000_000, 300_000_000, 400_000_000]


def test_cli_makes_the_missing_folders_of_out(tmp_path, capsys):
    out = tmp_path / "not" / "yet" / "run.mp4"
    code = video_main(["saoud_robot", "heading_hold", "--controller", "pid", "--seconds", "0.2",
                       "--out", str(out), "--fps", "10", "--width", "32", "--height", "24",
                       "--camera", "side"])
    assert code == 0 and out.stat().st_size > 0
    captured = capsys.readouterr()
    assert f"wrote {out}: 2 frames" in captured.out
    # progress into a captured (non-terminal) stream: plain lines, no carriage-return bar
    assert "\r" not in captured.err
    assert captured.err.splitlines()[-1].startswith("video: 2/2 (100 %)")


@pytest.mark.parametrize("argument, message", [
    (["--distance", "-3"], "--distance) must be a number > 0 m"),
    (["--camera", "top", "--bearing", "nan"], "--bearing) must be a finite angle"),
    (["--set", "seed=3"], "--set seed=... is the option --seed"),
    (["--set", "time_limit=3"], "--set time_limit=... is the option --seconds"),
])
def test_cli_bad_camera_and_episode_arguments_are_one_line(tmp_path, capsys, argument, message):
    code = video_main(["saoud_robot", "heading_hold", "--controller", "pid", "--seconds", "0.2",
                       "--out", str(tmp_path / "x.mp4"), *argument])
    err = capsys.readouterr().err
    assert code == 2 and message in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "x.mp4").exists()


def test_study_scenario_goes_to_the_study_folder(tmp_path):
    rec = video.record_study_scenario(tmp_path, "saoud_robot", "heading_hold", "pid", seconds=0.3,
                                      fps=10, width=64, height=48, camera="top")
    assert rec.path == tmp_path / "saoud_robot_heading_hold_pid.mp4"
    assert len(read_frames(rec.path, 48, 64)) == 3


def test_bad_arguments_are_refused_before_rendering(tmp_path):
    with pytest.raises(ValueError, match="camera"):
        video.record("wille_yacht", "heading_hold", "pid", tmp_path / "x.mp4", camera="drone")
    with pytest.raises(ValueError, match="even"):
        video.record("wille_yacht", "heading_hold", "pid", tmp_path / "x.mp4", width=641)


def test_display_hull_is_closed_and_wound_outward():
    # a unit cube without its top face, wound inward
    v = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1],
                  [0, 1, 1]], float)
    outward = [(0, 2, 1), (0, 3, 2), (0, 1, 5), (0, 5, 4), (1, 2, 6), (1, 6, 5), (2, 3, 7),
               (2, 7, 6), (3, 0, 4), (3, 4, 7)]
    inward = np.array(outward)[:, ::-1]
    verts, faces = video.close_outward(v.ravel(), inward.ravel())
    verts, faces = verts.reshape(-1, 3), faces.reshape(-1, 3)
    volume = np.einsum("ij,ij->i", verts[faces[:, 0]], np.cross(verts[faces[:, 1]],
                                                                 verts[faces[:, 2]])).sum() / 6
    assert volume == pytest.approx(1.0)
    edges = {(f[a], f[b]) for f in faces for a, b in ((0, 1), (1, 2), (2, 0))}
    assert all((b, a) in edges for a, b in edges)  # closed and consistently wound
    again = video.close_outward(verts.ravel(), faces.ravel())
    np.testing.assert_array_equal(again[1], faces.ravel())  # closed and outward: unchanged


# ----------------------------------------------------------------------------- no GL platform
FIXES = ("MUJOCO_GL=egl", "libegl1", "apt-get install libosmesa6", "MUJOCO_GL=osmesa")

SCRIPT = textwrap.dedent("""
    from sailmujoco import video
    try:
        video.record("wille_yacht", "heading_hold", "pid", "never.mp4", seconds=0.2)
    except video.RenderingUnavailable as err:
        print(err)
        raise SystemExit(3)
""")


def _run_without_gl(backend: str, tmp_path) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY",
                                                           "PYOPENGL_PLATFORM")}
    env["MUJOCO_GL"] = backend
    return subprocess.run([sys.executable, "-c", SCRIPT], env=env, cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)


def test_unknown_gl_platform_names_the_fix(tmp_path):
    result = _run_without_gl("no-such-platform", tmp_path)
    assert result.returncode == 3, result.stderr
    for fix in FIXES:
        assert fix in result.stdout
    assert "MUJOCO_GL='no-such-platform'" in result.stdout
    assert not (tmp_path / "never.mp4").exists()


@pytest.mark.skipif(ctypes.util.find_library("OSMesa") is not None,
                    reason="libOSMesa is installed here, so MUJOCO_GL=osmesa loads")
def test_osmesa_without_libosmesa_names_the_fix(tmp_path):
    result = _run_without_gl("osmesa", tmp_path)
    assert result.returncode == 3, result.stderr
    for fix in FIXES:
        assert fix in result.stdout


def test_gl_context_failure_names_the_fix(monkeypatch):
    """A platform that imports but cannot make a context (e.g. EGL without a device)."""
    import mujoco

    def no_context(*args, **kwargs):
        raise RuntimeError("Cannot initialize a EGL device display.")

    monkeypatch.setattr(mujoco, "Renderer", no_context)
    with pytest.raises(video.RenderingUnavailable) as info:
        video.check_rendering()
    for fix in FIXES:
        assert fix in str(info.value)
    assert "EGL device" in str(info.value)


def test_a_video_with_instruments_draws_the_true_boat_and_the_fixes_beside_it(tmp_path):
    """In a paper world the boat is drawn where it is, not where the GNSS says: under the same
    commands the frames of a run with typical sensors show the same boat as the run with perfect
    ones (instruments move no physics), while the panel differs by the fixes and the readings."""
    def fixed(env):
        return lambda timestep: np.array([0.02, 0.4])  # reads nothing: the same commands in both

    frames = {}
    for sensors in ("perfect", "typical"):
        rec = video.record("wille_yacht", "heading_hold", fixed, tmp_path / f"{sensors}.mp4", seconds=2.0,
                           world="paper", fps=10, width=W, height=H, camera="side", seed=0, sensors=sensors,
                           overlay=True)
        frames[sensors] = read_frames(rec.path).astype(float)
    scene = W - video.panel.panel_width(W)
    a, b = frames["perfect"][:, :, :scene - 16], frames["typical"][:, :, :scene - 16]  # clear of the
    assert np.abs(a - b).mean() < 0.2  # codec's blocks that straddle the panel's edge: the same boat
    assert np.abs(frames["perfect"][:, :, scene:] - frames["typical"][:, :, scene:]).mean() > 0.5
