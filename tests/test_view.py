"""`sailmujoco view`: MuJoCo's interactive viewer, run for real in a virtual X server (Xvfb).

Without Xvfb the window test is skipped on a workstation and fails on CI (CI set): .ci/run
installs Debian's xvfb and Mesa's GL, and a CI run that cannot open a window must say so.
"""

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from sailmujoco.viewer.view import KEY_RIGHT, KEY_SPACE, Keys

VIEW = [sys.executable, "-m", "sailmujoco", "view", "wille_yacht", "heading_hold", "--controller", "pid"]
RESULT = re.compile(r"viewed (?P<sim>[\d.]+) s simulated in (?P<wall>[\d.]+) s "
                    r"\(real-time factor (?P<rtf>[\d.]+)\); the boat moved (?P<distance>[\d.]+) m")


@pytest.fixture(scope="module")
def xvfb():
    """DISPLAY of a fresh Xvfb (1280 x 720, 24 bit) that it picks itself (-displayfd)."""
    if shutil.which("Xvfb") is None:
        message = ("Xvfb is not installed (Debian: apt-get install xvfb libgl1 libglx-mesa0 "
                   "libgl1-mesa-dri; .ci/run does this)")
        if os.environ.get("CI"):
            pytest.fail(message + ": on CI the viewer must be tested")
        pytest.skip(message)
    read, write = os.pipe()
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", "1280x720x24",
                               "-nolisten", "tcp"], pass_fds=(write,),
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    os.close(write)
    with os.fdopen(read) as pipe:
        number = pipe.readline().strip()  # written once the server accepts connections
    if not number:
        server.kill()
        pytest.fail(f"Xvfb did not start: {server.stderr.read().decode(errors='replace')[-500:]}")
    yield f":{number}"
    server.terminate()
    server.wait(10)


def _env(**changes):
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env.update(changes)
    return env


def test_view_sails_the_boat_at_real_time_and_saves_the_window(xvfb, tmp_path):
    shot = tmp_path / "view.png"
    out = subprocess.run(VIEW + ["--seconds", "2", "--screenshot", str(shot)], env=_env(DISPLAY=xvfb),
                         cwd=tmp_path,  # the installed package, not a source tree in the working folder
                         capture_output=True, text=True, timeout=180)
    assert out.returncode == 0, out.stderr[-2000:]
    found = RESULT.search(out.stdout)
    assert found, out.stdout
    assert float(found["sim"]) == pytest.approx(2.0, abs=1e-6)
    # heading_hold starts the yacht at 1 m/s in a 6 m/s wind: over 2 s it can neither stop (a
    # tonnes-heavy hull coasts) nor outrun the wind
    assert 1.0 < float(found["distance"]) < 2.0 * 6.0
    # paced by the wall clock: never faster than real time (slower only where a step costs more)
    assert float(found["rtf"]) < 1.1
    assert f"wrote {shot}: the state at t = 2.00 s from the window's camera" in out.stdout

    from PIL import Image

    image = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    assert image.shape[0] >= 240 and image.shape[1] >= 320  # the window, not a 16 px probe
    r, g, b = image[..., 0], image[..., 1], image[..., 2]
    assert image.mean(axis=2).std() > 10.0  # not blank
    assert ((b > r + 40) & (b > g)).mean() > 0.3  # mostly the sea (blue)
    assert ((g > 200) & (b > 200) & (r < 170)).sum() > 50  # the cyan wind arrow
    assert ((r > 180) & (g < 90) & (b < 90)).sum() > 50  # the red sail-force arrow


def _scene_at(times, width, height, camera):
    """Offscreen renders (the scene part) of heading_hold under pid, seed 0, at ``times`` (s),
    simulated here without a window, drawn with ``camera``."""
    from sailmujoco import suite, sweep, video

    env = suite.load("wille_yacht", "heading_hold", seed=0, time_limit=max(times))
    policy = sweep.make_controller("pid", env)
    policy.reset(0)
    timestep = env.reset()
    snaps, first_wind = {}, float(np.hypot(*env.physics.true_wind()[:2]))
    while not timestep.last():
        timestep = env.step(policy(timestep))
        for t in times:
            if abs(env.physics.time() - t) < 1e-9:
                snaps[t] = video.snapshot_physics(env.physics, env.task.references(env.physics))
    frames = {}
    with video.SceneRenderer(env.physics.params, width, height, overlay=True) as renderer:
        renderer.scale_forces(first_wind)  # as the window: scaled to the wind of its first state
        for t, snap in snaps.items():
            frames[t] = renderer.render(snap, camera=camera)[:, :width - renderer.panel].astype(float)
    return frames, width - renderer.panel


def test_view_screenshot_is_the_state_it_names_under_load(xvfb, tmp_path):
    """Two busy processes load the cores while the viewer runs: the screenshot still shows the
    state at the end (t = 2 s), as a render of that state, simulated here without a window,
    from the camera the PNG names; a state 0.6 s earlier looks different."""
    from PIL import Image

    from sailmujoco.viewer.screenshot import read_stamp

    shot = tmp_path / "loaded.png"
    load = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(2)]
    try:
        out = subprocess.run(VIEW + ["--seconds", "2", "--screenshot", str(shot)], env=_env(DISPLAY=xvfb),
                             cwd=tmp_path, capture_output=True, text=True, timeout=300)
    finally:
        for process in load:
            process.kill()
            process.wait()
    assert out.returncode == 0, out.stderr[-2000:]
    time, camera = read_stamp(shot)
    assert time == pytest.approx(2.0, abs=1e-9)
    image = np.asarray(Image.open(shot).convert("RGB")).astype(float)
    frames, scene_width = _scene_at((1.4, 2.0), image.shape[1], image.shape[0], camera)
    now = np.abs(image[:, :scene_width] - frames[2.0]).mean()
    earlier = np.abs(image[:, :scene_width] - frames[1.4]).mean()
    assert now < 1.0, (now, earlier)  # the same state, the same camera: the same pixels
    assert earlier > 5.0 * max(now, 0.2), (now, earlier)


@pytest.mark.parametrize("display", [None, ":987"], ids=["no DISPLAY", "display not served"])
def test_without_a_display_one_line_points_to_video(display, tmp_path):
    if display is not None and Path(f"/tmp/.X11-unix/X{display[1:]}").exists():
        pytest.fail(f"display {display} is served here: pick another for this test")
    env = _env(**({"DISPLAY": display} if display else {}))
    out = subprocess.run(VIEW + ["--seconds", "2"], env=env, capture_output=True, text=True, cwd=tmp_path,
                         timeout=120)
    assert out.returncode == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1, out.stderr
    assert "cannot open a window" in lines[0]
    assert "sailmujoco video wille_yacht heading_hold --controller pid" in lines[0]
    assert "Traceback" not in out.stderr and out.stdout == ""


def test_without_a_display_a_bad_name_is_named_not_passed_on_to_video(capsys):
    """The video command suggested without a display must be one that runs: names first."""
    from sailmujoco.cli.main import main

    assert main(["view", "wille_yacht", "heading_hold", "--controller", "nope"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "unknown controller 'nope'" in err[0] and "pid" in err[0]
    assert "sailmujoco video" not in err[0]


def test_space_pauses_and_right_arrow_steps_once_per_press():
    keys = Keys()
    assert keys.may_step() and keys.may_step()  # running: every step
    keys.press(KEY_RIGHT)  # ignored while running
    keys.press(KEY_SPACE)
    assert keys.paused and not keys.may_step()
    keys.press(KEY_RIGHT)
    keys.press(KEY_RIGHT)
    assert [keys.may_step() for _ in range(3)] == [True, True, False]
    keys.press(KEY_SPACE)
    assert not keys.paused and keys.may_step()
    keys.press(ord("A"))  # other keys (MuJoCo's own) change nothing
    assert not keys.paused


@pytest.mark.parametrize("setting, option", [("seed=3", "--seed"), ("time_limit=5", "--seconds")])
def test_episode_seed_and_length_are_options_not_settings(setting, option, capsys):
    from sailmujoco.cli.main import main

    assert main(["view", "wille_yacht", "heading_hold", "--controller", "pid", "--set", setting]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"sailmujoco: error: --set {setting.split('=')[0]}=... is the option {option}"]


def test_view_takes_the_videos_sea_and_names_a_bad_one_before_the_display(tmp_path, capsys):
    """--waves as in `sailmujoco video`: a bad value is one line (exit 2) whatever the display;
    without a display the video command suggested sails in the same sea."""
    from sailmujoco.cli.main import main

    assert main(["view", "wille_yacht", "beam_reach_roll", "--controller", "wille_roll",
                 "--waves", "tp=-6"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--waves tp must be > 0 s" in err[0]
    out = subprocess.run(VIEW + ["--seconds", "2", "--waves", "hs=1.5", "--waves", "tp=6"], env=_env(),
                         capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert out.returncode == 2 and "cannot open a window" in out.stderr
    assert "--waves hs=1.5 --waves tp=6" in out.stderr
