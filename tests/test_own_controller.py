"""A controller of one's own, in one file outside the package, named by its import path or
registered at run time: it runs in Python, in a sweep on worker processes, in a polar, in a
video and in the viewer (from Python and the command line), with its options checked (names
and kinds) before anything runs."""

import math
import os
import re
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from test_view import xvfb  # noqa: F401  (the fixture: a virtual X server, skipped as there)

from sailmujoco import suite, sweep
from sailmujoco.cli.main import main
from sailmujoco.design import polar
from sailmujoco.sweep import SweepError

LAW = textwrap.dedent('''
    """A proportional rudder on the heading error and the sail at half the apparent wind angle."""
    import math

    import numpy as np


    class HeadingP:
        def __init__(self, gain, max_rudder):
            self.gain, self.max_rudder = gain, max_rudder

        def reset(self, seed=None):
            pass

        def __call__(self, timestep):
            o = timestep.observation
            error = (o["heading"] - o["desired_heading"] + math.pi) % (2 * math.pi) - math.pi
            rudder = float(np.clip(self.gain * error, -self.max_rudder, self.max_rudder))
            return np.array([rudder, 0.5 * float(o["apparent_wind_angle"])])


    def make(env, gain: float = 1.0, max_rudder_deg: float = 30.0):
        return HeadingP(gain, math.radians(max_rudder_deg))
''')


@pytest.fixture
def law_file(tmp_path):
    path = tmp_path / "my_law.py"
    path.write_text(LAW)
    return path


def _spec(controller: str) -> dict:
    return {"name": "own", "boat": "saoud_robot", "task": "heading_hold", "controller": controller,
            "duration": 20.0, "seeds": [0, 1], "metrics": ["mean_surge", "heading_error_rms"],
            "grid": {"controller.gain": [0.5, 1.5]}}


def test_a_file_controller_holds_the_heading(law_file):
    """By its file path, no package and no install: the P rudder holds north within 15° after
    30 s and the robot makes headway."""
    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=40)
    log = suite.rollout(env, sweep.make_controller(f"{law_file}:make", env, gain=1.0))
    last = log[log["t"] >= 30.0]
    assert np.max(np.abs(np.angle(np.exp(1j * last["heading"])))) < math.radians(15.0)
    assert last["u"].mean() > 0.3


def test_a_file_controller_runs_in_a_sweep_on_two_workers(law_file, tmp_path):
    """The workers import the file themselves: every run of the grid finishes, and each equals the
    same run in this process (the same seed and gain, the same numbers)."""
    table = sweep.run(_spec(f"{law_file}:make"), tmp_path / "out", workers=2, progress=False)
    assert len(table) == 4 and set(table["status"]) == {"ok"}
    serial = sweep.run(_spec(f"{law_file}:make"), tmp_path / "serial", scheduler="serial",
                       progress=False)
    key = ["seed", "controller.gain"]
    np.testing.assert_array_equal(table.sort_values(key)["mean_surge"].to_numpy(),
                                  serial.sort_values(key)["mean_surge"].to_numpy())


def test_a_registered_controller_is_found_by_name_and_by_workers(law_file, tmp_path):
    """register_controller at run time: found by its name in Python, and a sweep sends the
    workers the factory's file instead of a name they never saw."""
    module = {}
    exec(compile(LAW, str(law_file), "exec"), module)
    factory = module["make"]
    factory.__module__ = "__main__"  # as a function of the user's script
    sweep.register_controller("my_heading_p", factory)
    try:
        env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=5)
        assert callable(sweep.make_controller("my_heading_p", env))
        spec = sweep.validate(_spec("my_heading_p"))
        assert spec["controller"] == f"{law_file.resolve()}:make"
        table = sweep.run(_spec("my_heading_p"), tmp_path / "out", workers=2, progress=False)
        assert set(table["status"]) == {"ok"}
        with pytest.raises(SweepError, match="'pid' is a built-in controller"):
            sweep.register_controller("pid", factory)
    finally:
        sweep.controllers._REGISTERED.pop("my_heading_p", None)


def test_a_file_controller_draws_a_polar(law_file, tmp_path):
    """polar takes an import path: its files are named after the factory."""
    frame = polar.compute("saoud_robot", f"{law_file}:make", tmp_path, tws=[4.0], twa=[90.0],
                          duration=20.0, scheduler="serial", progress=False)
    assert len(frame) == 1 and frame["speed"].iloc[0] > 0.2
    assert (tmp_path / "sweep-make").is_dir()


@pytest.mark.parametrize("name, message", [
    ("no_such_file.py:make", "no file"),
    ("sailmujoco.no_such_module:make", "cannot import 'sailmujoco.no_such_module'"),
    ("{law}:mkae", "unknown factory 'mkae' in controller .*; did you mean 'make'"),
    ("pdi", "unknown controller 'pdi' .*did you mean 'pid'"),
])
def test_a_bad_controller_name_is_one_line(law_file, name, message):
    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=5)
    with pytest.raises(SweepError, match=message) as err:
        sweep.make_controller(name.format(law=law_file), env)
    assert "\n" not in str(err.value)


def test_an_option_of_the_wrong_kind_is_one_line(law_file):
    """kp="two" would fail at the first step deep inside the PID; it is refused at construction,
    naming the option and the kind its default has. The same in a sweep file."""
    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=5)
    with pytest.raises(SweepError, match=r"controller.kp = 'two': must be a finite number"):
        sweep.make_controller("pid", env, kp="two")
    with pytest.raises(SweepError, match=r"controller.gain = 'high': must be a finite number"):
        sweep.make_controller(f"{law_file}:make", env, gain="high")
    with pytest.raises(SweepError, match=r"controller.gain = 'high': must be a finite number"):
        sweep.validate({**_spec(f"{law_file}:make"), "grid": {"controller.gain": ["high"]}})


def test_rollout_says_what_a_law_needs():
    """A rudder law alone (observation -> angle) is not a controller: rollout says in one line
    what it takes, and a Composite of the law with a sail law runs."""
    from sailmujoco.controllers.base import Composite
    from sailmujoco.controllers.pid import PIDHeading
    from sailmujoco.controllers.sail_laws import LeewardSail

    env = suite.load("saoud_robot", "heading_hold", seed=0, time_limit=3)
    rudder = PIDHeading()
    with pytest.raises(TypeError, match=r"takes the dm_env TimeStep .*Composite\(rudder, sail\)") as err:
        suite.rollout(env, rudder)
    assert "\n" not in str(err.value)
    with pytest.raises(TypeError, match="must be callable"):
        suite.rollout(env, (rudder, LeewardSail()))
    with pytest.raises(ValueError,
                       match=r"returned 0.1; the action is \[rudder, sail\] \[rad\], shape \(2,\)"):
        suite.rollout(env, lambda timestep: 0.1)
    log = suite.rollout(env, Composite(rudder, LeewardSail()))
    assert log["t"].iloc[-1] == pytest.approx(3.0)


# ---- the command line: a file controller that notes every call ------------------------------
CONSTANT = textwrap.dedent('''
    """A constant rudder and sail; each call appends the time and the rudder angle it sees."""
    import math

    import numpy as np


    class Constant:
        def __init__(self, action, marker):
            self.action, self.marker = action, marker

        def reset(self, seed=None):
            pass

        def __call__(self, timestep):
            state = timestep.observation["true_state"]
            with open(self.marker, "a") as f:
                f.write(f"{state['time']:.6f} {math.degrees(state['rudder']):.6f}\\n")
            return self.action


    def make(env, rudder_deg: float = 0.0, sail_deg: float = 30.0, marker: str = "calls.txt"):
        """A constant rudder and sail (degrees)."""
        return Constant(np.radians([rudder_deg, sail_deg]), marker)
''')
CONTROL_TIMESTEP = 0.1  # s, suite.load's default: the controller is called at 10 Hz


@pytest.fixture
def constant_file(tmp_path, monkeypatch):
    path = tmp_path / "constant.py"
    path.write_text(CONSTANT)
    monkeypatch.chdir(tmp_path)  # the default marker, calls.txt, lands here
    return path


def _display_env(**changes) -> dict:
    """This process's environment without its display, with ``changes``."""
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env.update(changes)
    return env


def _calls(marker) -> np.ndarray:
    """(time s, rudder deg) of every call the controller noted."""
    return np.loadtxt(marker, ndmin=2)


def _check_calls(marker, seconds: float, rudder_deg: float) -> None:
    """Called once per control step from t = 0, and the rudder it commands reaches the boat: a
    servo settles on a constant command within a second."""
    calls = _calls(marker)
    steps = round(seconds / CONTROL_TIMESTEP)
    np.testing.assert_allclose(calls[:, 0], CONTROL_TIMESTEP * np.arange(steps), atol=1e-6)
    assert calls[0, 1] == pytest.approx(0.0, abs=1e-9)  # the task starts with the rudder amidships
    assert calls[-1, 1] == pytest.approx(rudder_deg, abs=0.5)


def test_a_file_controller_records_a_video_with_its_options(constant_file, tmp_path, capsys):
    pytest.importorskip("imageio_ffmpeg")
    marker, out = tmp_path / "video_calls.txt", tmp_path / "run.mp4"
    code = main(["video", "saoud_robot", "heading_hold", "--controller", f"{constant_file}:make",
                 "--option", "rudder_deg=20", "--option", f"marker={marker}", "--seconds", "2",
                 "--width", "160", "--height", "120", "--fps", "10", "--out", str(out),
                 "--no-progress"])
    assert code == 0, capsys.readouterr().err
    assert "wrote" in capsys.readouterr().out and out.stat().st_size > 1000
    _check_calls(marker, 2.0, 20.0)


def test_a_file_controller_runs_in_the_viewer(constant_file, tmp_path, xvfb):  # noqa: F811
    """In a real window (a virtual X server), through ``python -m sailmujoco``."""
    marker = tmp_path / "view_calls.txt"
    out = subprocess.run([sys.executable, "-m", "sailmujoco", "view", "saoud_robot", "heading_hold",
                          "--controller", f"{constant_file}:make", "--option", "rudder_deg=-15",
                          "--option", f"marker={marker}", "--seconds", "1.5"],
                         env=_display_env(DISPLAY=xvfb), cwd=tmp_path, capture_output=True,
                         text=True, timeout=180)
    assert out.returncode == 0, out.stderr[-2000:]
    assert "viewed 1.50 s simulated" in out.stdout
    _check_calls(marker, 1.5, -15.0)


def test_a_file_controller_draws_a_polar_from_the_command_line(constant_file, tmp_path, capsys):
    out = tmp_path / "polar"
    assert main(["polar", "saoud_robot", "--controller", "constant.py:make", "--option",
                 "rudder_deg=12", "--tws", "4", "--twa", "90", "--duration", "3", "--scheduler",
                 "serial", "--out", str(out), "--no-progress"]) == 0
    assert (out / "polar_make.csv").is_file() and (out / "polar_make.png").is_file()
    _check_calls(tmp_path / "calls.txt", 3.0, 12.0)


def test_a_file_controller_runs_in_a_sweep_file_on_two_workers(constant_file, tmp_path, capsys):
    """Named by a path relative to the sweep file (as a boat file is), with an option; two
    worker processes, run from another folder."""
    marker = tmp_path / "sweep_calls.txt"
    (tmp_path / "sweeps").mkdir()
    (tmp_path / "sweeps" / "own.toml").write_text(textwrap.dedent(f"""
        boat = "saoud_robot"
        task = "heading_hold"
        controller = "../constant.py:make"
        duration = 2.0
        seeds = [0, 1]
        [options]
        "controller.marker" = "{marker}"
        [grid]
        "controller.rudder_deg" = [-10.0, 10.0]
    """))
    assert main(["sweep", "sweeps/own.toml", "--workers", "2", "--out", "out", "--no-progress"]) == 0
    assert "status: ok 4, stopped 0, failed 0" in capsys.readouterr().out
    calls = _calls(marker)
    assert len(calls) == 4 * round(2.0 / CONTROL_TIMESTEP)
    assert sorted(np.round(calls[calls[:, 0] > 1.85, 1]).tolist()) == [-10.0, -10.0, 10.0, 10.0]


@pytest.mark.parametrize("option, message", [
    ("rudder_dge=20", r"unknown option 'rudder_dge' in controller '.*constant.py:make'; "
                      r"did you mean 'rudder_deg'\? \(accepted: marker, rudder_deg, sail_deg\)"),
    ("rudder_deg=hard", r"controller.rudder_deg = 'hard': must be a finite number"),
])
@pytest.mark.parametrize("command", ["video", "view"])
def test_a_bad_option_is_one_line_before_anything_runs(constant_file, tmp_path, command, option,
                                                       message, capsys, monkeypatch):
    """Named in one line and exit 2, with no display (view) and before any frame (video)."""
    monkeypatch.delenv("DISPLAY", raising=False)
    out = ["--out", str(tmp_path / "x.mp4")] if command == "video" else []
    assert main([command, "saoud_robot", "heading_hold", "--controller", f"{constant_file}:make",
                 "--option", option, *out]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and re.search(message, err[0]), err
    assert not (tmp_path / "calls.txt").exists() and not (tmp_path / "x.mp4").exists()
