"""A controller that raises, or gives a bad action, in `video`, `view` and `polar`: one line on
stderr that names the controller and the simulated time, exit status 2, and what was made up to
then kept (the video cut at that state, the polar's finished points).

The controllers are a file of the user's in tmp_path, named ``file.py:factory``. They fail at the
first control step after FAIL_AFTER s: saoud_robot's control step is 0.1 s, so at t = 1.10 s.
"""

from __future__ import annotations

import math
import textwrap

import numpy as np
import pandas as pd
import pytest

from sailmujoco import suite
from sailmujoco.cli.main import build_parser, main
from sailmujoco.errors import ControllerFailed, act

imageio = pytest.importorskip("imageio.v3")
pytest.importorskip("imageio_ffmpeg")

FAIL_AFTER = 1.05  # s
FAILS_AT = 1.1  # s, the first control step (0.1 s) after FAIL_AFTER
FPS = 10
CONTROLLER = f"""
import numpy as np

FAIL_AFTER = {FAIL_AFTER}


class Sails:
    def __init__(self, env, bad):
        self.env, self.bad = env, bad

    def reset(self, seed):
        pass

    def __call__(self, timestep):
        if self.env.physics.time() > FAIL_AFTER:
            if self.bad == "raise":
                raise ValueError("boom")
            return np.array([np.nan, 0.3]) if self.bad == "nan" else np.zeros(3)
        return np.array([0.0, 0.3])


def make(env):
    return Sails(env, "raise")


def make_nan(env):
    return Sails(env, "nan")


def make_three(env):
    return Sails(env, "three")


def make_broken(env):
    raise RuntimeError("no wind vane on this boat")
"""


@pytest.fixture(scope="module")
def controller_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("own") / "my_ctrl.py"
    path.write_text(textwrap.dedent(CONTROLLER))
    env = suite.load("saoud_robot", "heading_hold")  # the kernels compiled before any command runs
    env.reset()
    env.step([0.0, 0.3])
    assert env.control_timestep() == pytest.approx(0.1)
    return path


def _frames_until_failure(fps: float) -> int:
    """Frames of a video cut at FAILS_AT: frame k shows t = k / fps, up to the state the
    controller was given; that frame is then held for 1 s."""
    return math.floor(FAILS_AT * fps + 1e-9) + 1 + round(fps)


def _red_on_top(frame: np.ndarray) -> int:
    top = frame[:8].astype(int)
    return int(((top[..., 0] > 150) & (top[..., 1] < 120)).sum())


def _one_line(err: str, command: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith(f"sailmujoco {command}: controller ")
    return lines[0]


def test_act_names_the_controller_the_time_and_the_error():
    def raises(timestep):
        raise KeyError("gain")

    expected = r"^controller mine raised at t = 3\.20 s: KeyError: 'gain'$"
    with pytest.raises(ControllerFailed, match=expected) as caught:
        act(raises, None, controller="mine", time=3.2)
    assert isinstance(caught.value.__cause__, KeyError) and caught.value.time == 3.2
    for action, shown in (([np.inf, 0.0], r"\[inf 0\.\]"), ([0.1, 0.2, 0.3], r"\[0\.1 0\.2 0\.3\]"),
                          ("left", "'left'"), (None, "nan")):
        with pytest.raises(ControllerFailed, match=rf"^controller mine gave a bad action at t = 0\.50 s: "
                                                   rf"{shown} \(2 finite numbers expected\)$"):
            act(lambda timestep, a=action: a, None, controller="mine", time=0.5)
    action = [0.1, 0.2]
    assert act(lambda timestep: action, None, controller="mine", time=0.0) is action
    text = "line one\n   line two " + "x" * 400
    with pytest.raises(ControllerFailed) as caught:
        act(lambda timestep: (_ for _ in ()).throw(RuntimeError(text)), None, controller="c", time=0.0)
    assert "\n" not in str(caught.value) and len(caught.value.detail) == 200


@pytest.mark.parametrize("factory, error", [
    ("make", "raised at t = 1.10 s: ValueError: boom"),
    ("make_nan", r"gave a bad action at t = 1.10 s: [nan 0.3] (2 finite numbers expected)"),
])
def test_video_says_when_the_controller_failed_and_keeps_the_video_cut_there(controller_file, tmp_path,
                                                                             capsys, factory, error):
    out, still = tmp_path / "video" / "mine.mp4", tmp_path / "mine.png"
    name = f"{controller_file}:{factory}"
    code = main(["video", "saoud_robot", "heading_hold", "--controller", name, "--seconds", "3",
                 "--fps", str(FPS), "--width", "64", "--height", "48", "--camera", "side", "--no-overlay",
                 "--out", str(out), "--still", str(still), "--no-progress"])
    captured = capsys.readouterr()
    assert code == 2
    line = _one_line(captured.err, "video")
    assert line == (f"sailmujoco video: controller {name} {error}; the video stops there: {out} and "
                    f"{still} ({FAILS_AT:.1f} s of 3 s)")
    assert "wrote" not in captured.out
    frames = imageio.imread(out, plugin="FFMPEG", index=None)
    assert len(frames) == _frames_until_failure(FPS) < 3 * FPS
    assert frames.shape[1:] == (48, 64, 3)
    held = frames[-FPS:].astype(float)
    assert np.abs(held - held[0]).mean() < 2.0  # the last frame, held
    # the note, red on a dark band across the top, on the held frame, not on the same state before
    marked, plain = (_red_on_top(frames[i]) for i in (-1, -FPS - 1))
    assert marked > plain + 5, (marked, plain)
    assert imageio.imread(still).shape == (48, 64, 3)
    assert not list(out.parent.glob(".*partial*"))


def test_video_refuses_an_action_of_the_wrong_shape_in_one_line(controller_file, tmp_path, capsys):
    out = tmp_path / "three.mp4"
    code = main(["video", "saoud_robot", "heading_hold", "--controller", f"{controller_file}:make_three",
                 "--seconds", "3", "--fps", "5", "--width", "32", "--height", "24", "--camera", "side",
                 "--out", str(out), "--no-progress"])
    assert code == 2
    line = _one_line(capsys.readouterr().err, "video")
    assert "gave a bad action at t = 1.10 s: [0. 0. 0.] (2 finite numbers expected)" in line
    assert len(imageio.imread(out, plugin="FFMPEG", index=None)) == _frames_until_failure(5) < 3 * 5


@pytest.mark.parametrize("command", ["video", "polar"])
def test_a_factory_that_raises_is_one_line_and_nothing_runs(command, controller_file, tmp_path, capsys):
    name = f"{controller_file}:make_broken"
    video = ["video", "saoud_robot", "heading_hold", "--out", str(tmp_path / "never.mp4")]
    polar = ["polar", "saoud_robot", "--tws", "4", "--twa", "60", "--scheduler", "serial",
             "--out", str(tmp_path)]
    args = video if command == "video" else polar
    code = main([*args, "--controller", name, "--seconds", "1", "--no-progress"])
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1, err
    assert f"{name} could not be built" in err and "RuntimeError: no wind vane on this boat" in err
    assert not list(tmp_path.glob("*.mp4")) and not list(tmp_path.glob("*.csv"))


def test_polar_names_the_failed_point_and_keeps_the_finished_ones(controller_file, tmp_path, capsys):
    name = f"{controller_file}:make"
    code = main(["polar", "saoud_robot", "--controller", "saoud", "--compare", name, "--tws", "4",
                 "--twa", "60,120", "--seconds", "3", "--scheduler", "serial", "--out", str(tmp_path),
                 "--no-progress"])
    captured = capsys.readouterr()
    assert code == 2
    line = _one_line(captured.err, "polar")
    assert line == (f"sailmujoco polar: controller {name} raised at t = 1.10 s: ValueError: boom "
                    f"(TWS 4 m/s, TWA 60 deg); 2 of 2 runs failed; kept what finished: "
                    f"{tmp_path / 'polar_saoud.csv'} (2 points), {tmp_path / 'polar_make.csv'} "
                    f"(0 points)")
    saoud = pd.read_csv(tmp_path / "polar_saoud.csv")
    assert list(saoud["twa"]) == [60.0, 120.0] and (saoud["speed"] > 0).all()
    assert pd.read_csv(tmp_path / "polar_make.csv").empty
    assert not (tmp_path / "polar_saoud.png").exists()  # no figure is drawn from a polar that failed


def test_polar_seconds_is_the_option_and_duration_its_hidden_alias(capsys):
    parser = build_parser()
    assert parser.parse_args(["polar", "saoud_robot"]).seconds == 60.0
    assert parser.parse_args(["polar", "saoud_robot", "--seconds", "25"]).seconds == 25.0
    assert parser.parse_args(["polar", "saoud_robot", "--duration", "25"]).seconds == 25.0
    with pytest.raises(SystemExit):
        parser.parse_args(["polar", "--help"])
    polar_help = capsys.readouterr().out
    assert "--seconds SECONDS" in polar_help and "--duration" not in polar_help


class _Viewer:
    def __init__(self):
        self.running = True

    def is_running(self):
        return self.running


class _Window:
    """MuJoCo's viewer as sailmujoco.viewer.view drives it (tests/test_view.py runs the real one in Xvfb)."""

    opened = []

    def __init__(self, scene, snap, key_callback, *, forces, overlay):
        self.viewer, self.shown, self.closed = _Viewer(), [], False
        _Window.opened.append(self)

    def show(self, snap, note=None):
        self.shown.append((float(snap.time), note))

    def save(self, path, snap):
        return f"the state at t = {snap.time:.2f} s"

    def close(self):
        self.viewer.running, self.closed = False, True


def test_view_says_when_the_controller_failed(controller_file, monkeypatch, capsys):
    from sailmujoco.viewer import view

    monkeypatch.setattr(view, "open_display", lambda: None)
    monkeypatch.setattr(view, "Window", _Window)
    name = f"{controller_file}:make"
    code = main(["view", "saoud_robot", "heading_hold", "--controller", name, "--seconds", "3",
                 "--fps", "10", "--screenshot", "unused.png"])
    captured = capsys.readouterr()
    assert code == 2
    line = _one_line(captured.err, "view")
    assert line == (f"sailmujoco view: controller {name} raised at t = 1.10 s: ValueError: boom; the run "
                    f"stops there; wrote unused.png: the state at t = 1.10 s")
    assert "viewed" not in captured.out
    window = _Window.opened[-1]
    assert window.closed
    time, note = window.shown[-1]  # the state the controller was given, marked
    assert time == pytest.approx(FAILS_AT) and note == "controller raised at t = 1.10 s: ValueError: boom"
    assert max(t for t, _ in window.shown) == pytest.approx(FAILS_AT)  # nothing after it
