"""A controller of one's own, in one file outside the package, named by its import path or
registered at run time: it runs in Python, in a sweep on worker processes and in a polar, with
its options checked (names and kinds) before anything runs."""

import math
import textwrap

import numpy as np
import pytest

from sailmujoco import polar, suite, sweep
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
    with pytest.raises(ValueError, match=r"returned 0.1; the action is \[rudder, sail\] \[rad\], shape \(2,\)"):
        suite.rollout(env, lambda timestep: 0.1)
    log = suite.rollout(env, Composite(rudder, LeewardSail()))
    assert log["t"].iloc[-1] == pytest.approx(3.0)
