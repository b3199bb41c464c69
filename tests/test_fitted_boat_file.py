"""A boat file's [sensors] and [actuators] sections: written with units and sources, read back
exactly, carried wherever the file goes (a task, a sweep, the command line), overridden by a
task's own figures, and refused in one line naming the file, the section and the figure."""

import math
import tomllib

import numpy as np
import pytest

from sailmujoco import suite, sweep
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.boat.file import boat_toml, write_boat
from sailmujoco.boat.fitted import ACTUATOR_PRESETS, SENSOR_PRESETS
from sailmujoco.boat.fitted_file import FITTED
from sailmujoco.cli.main import main

HEAD = boat_toml(get_boat("saoud_robot").with_(name="fitted_robot")).split("\n[sensors]")[0]


def _file(tmp_path, sections: str, name="fitted.toml"):
    """The robot as a boat file (perfect sections dropped) with ``sections`` appended."""
    path = tmp_path / name
    path.write_text(f"{HEAD}\n{sections}")
    return path


def test_every_figure_has_a_unit_meaning_and_typical_source():
    for section, (_, table, presets, _) in FITTED.items():
        names = [f for f in presets["perfect"].__dataclass_fields__]
        assert list(table) == names, section  # the table follows the dataclass, in order
        for name, (unit, meaning, source) in table.items():
            assert unit and meaning, name
            assert name == "perfect" or source, f"{section}.{name} has no source for its typical value"


def test_a_fitted_export_reads_back_equal_with_units_and_sources(tmp_path):
    boat = get_boat("saoud_robot").with_(name="fitted_robot", sensors="typical",
                                         actuators={"preset": "typical", "rudder_60deg_s": 0.2})
    path = write_boat(boat, tmp_path / "fitted.toml")
    text = path.read_text()
    data = tomllib.loads(text)
    assert data["sensors"]["gnss_cep"] == 2.5 and data["actuators"]["rudder_60deg_s"] == 0.2
    lines = dict(line.split(" = ", 1) for line in text.splitlines() if " = " in line and line[0] != "#")
    assert lines["gnss_cep"] == "2.5  # [m] u-blox M8 class: 2.5 m CEP"
    assert lines["vane_filter_hz"] == "0.5  # [Hz] ArduPilot's vane filter, WNDVN_DIR_FILT"
    assert lines["rudder_60deg_s"] == "0.2  # [s]"  # not the preset's: no source claimed for it
    read = get_boat(path)
    assert read == boat
    assert boat_toml(read) == text  # written again from what was read: the same text


def test_a_file_without_the_sections_is_perfect(tmp_path):
    read = get_boat(_file(tmp_path, ""))
    assert read.sensors == SENSOR_PRESETS["perfect"] and read.actuators == ACTUATOR_PRESETS["perfect"]


def test_the_files_figures_reach_the_task_and_its_instruments(tmp_path):
    path = _file(tmp_path, '[sensors]\npreset = "typical"\ncompass_noise_deg = 4.0\n'
                           '[actuators]\npreset = "typical"\n')
    env = suite.load(str(path), "heading_hold", seed=3, time_limit=60)
    assert env.task.sensors.compass_noise_deg == 4.0
    assert env.task.sensors.gnss_cep == 2.5  # the rest: the preset's
    assert env.task.actuators == ACTUATOR_PRESETS["typical"]
    truth = suite.load(str(path), "heading_hold", seed=3, time_limit=60, sensors="perfect")
    timestep, true_step = env.reset(), truth.reset()
    errors = []
    while not timestep.last():  # the same commands: the same true boat (instruments change no physics)
        errors.append(math.remainder(float(timestep.observation["heading"])
                                     - float(true_step.observation["heading"]), 2 * math.pi))
        timestep, true_step = env.step(np.array([0.0, 0.5])), truth.step(np.array([0.0, 0.5]))
    # a tilt-compensated compass: its white noise (4 deg) and, through its inclinometer's
    # 0.5 deg, a tilt error far smaller at these heels; 600 samples give sigma within +-6 %
    assert np.degrees(np.std(errors)) == pytest.approx(4.0, rel=0.08)
    assert abs(np.degrees(np.mean(errors))) < 0.5  # no deviation given: no bias


def test_a_tasks_own_figures_override_the_files_and_a_dict_is_over_them(tmp_path):
    path = _file(tmp_path, '[sensors]\npreset = "typical"\ncompass_noise_deg = 4.0\n')
    assert suite.load(str(path), "heading_hold", sensors="perfect").task.sensors.perfect
    over = suite.load(str(path), "heading_hold", sensors={"gnss_cep": 5.0}).task.sensors
    assert (over.gnss_cep, over.compass_noise_deg, over.vane_filter_hz) == (5.0, 4.0, 0.5)
    fresh = suite.load(str(path), "heading_hold",
                       sensors={"preset": "perfect", "gnss_cep": 5.0}).task.sensors
    assert (fresh.gnss_cep, fresh.compass_noise_deg, fresh.perfect) == (5.0, 0.0, False)


WHERE = r"fitted.toml: \[(sensors|actuators)\] "


@pytest.mark.parametrize("section, expected", [
    ("[sensors]\ngnss_cep = -2.5\n", "sensors.gnss_cep must be a finite number >= 0, got -2.5"),
    ("[sensors]\ngnss_cpe = 2.5\n", "sensors.gnss_cpe is not a sensor figure; choose from"),
    ('[actuators]\npreset = "fast"\n', r"actuators must be one of \['perfect', 'typical'\]"),
    ("[actuators]\nsail_deadband = true\n", "actuators.sail_deadband must be a finite number >= 0"),
    ("sensors = 3\n", "must be a table"),
])
def test_a_bad_figure_is_one_line_naming_the_file_section_and_figure(tmp_path, section, expected):
    if section.startswith("sensors ="):  # a key, not a section: it must come before any table
        path = tmp_path / "fitted.toml"
        path.write_text(section + HEAD)
    else:
        path = _file(tmp_path, section)
    with pytest.raises(ValueError, match=WHERE + expected) as err:
        get_boat(path)
    assert "\n" not in str(err.value)


def test_a_fitted_file_in_a_sweep_and_on_the_command_line(tmp_path, capsys):
    path = tmp_path / "fitted.toml"
    assert main(["boat", "export", "saoud_robot", "--sensors", "typical", "--actuators", "typical",
                 "--out", str(path)]) == 0
    read = get_boat(path)
    assert read.sensors == SENSOR_PRESETS["typical"] and read.actuators == ACTUATOR_PRESETS["typical"]
    (tmp_path / "s.toml").write_text(
        'boat = "fitted.toml"\ntask = "heading_hold"\ncontroller = "pid"\nduration = 3.0\n'
        'metrics = ["mean_surge"]\n[grid]\n"sensors.compass_noise_deg" = [1.0, 4.0]\n')
    table = sweep.run(tmp_path / "s.toml", tmp_path / "out", scheduler="serial", progress=False)
    assert set(table["status"]) == {"ok"} and len(table) == 2
    # the sweep's figure is over the file's (typical) figures, not over perfect ones
    env = suite.load(str(path), "heading_hold", sensors={"compass_noise_deg": 1.0})
    assert env.task.sensors.gnss_cep == 2.5
    capsys.readouterr()
    assert main(["boat", "check", str(path), "--out", str(tmp_path / "check")]) == 0
    out = capsys.readouterr().out
    assert "sensors       gnss_cep 2.5 m, gnss_tau 60 s" in out
    assert "actuators     rudder_60deg_s 0.15 s" in out
