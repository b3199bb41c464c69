"""A misspelt metric, an option value of the wrong kind and an unknown option: each one line
naming it and what is accepted, the same from Python and from a sweep file, before any run
starts (no run is written)."""

import re

import pytest

from sailmujoco import sweep
from sailmujoco.cli.main import main
from sailmujoco.sweep import SweepError

BASE = {"name": "bad", "boat": "saoud_robot", "task": "heading_hold", "controller": "pid",
        "duration": 2.0, "seeds": [0]}

CASES = {
    "misspelt metric": (
        {"metrics": ["mean_surge", "mean_sped"]},
        r"unknown metric 'mean_sped' in 'metrics' of {source}; did you mean 'mean_surge'\? "
        r"\(accepted: duration, heading_error_rms, heel_amplitude, mean_surge, steady_heel, "
        r"steady_speed, stopped\)$"),
    "controller option of the wrong kind": (
        {"grid": {"controller.kp": [1.0, "two"]}},
        r"controller.kp = 'two': must be a finite number, in {source}$"),
    "task option of the wrong kind": (
        {"options": {"task.gusts": "no"}},
        r"task.gusts = 'no': must be true or false, in {source}$"),
    "env option of the wrong kind": (
        {"options": {"env.control_timestep": "fast"}},
        r"env.control_timestep = 'fast': must be a finite number, in {source}$"),
    "unknown controller option": (
        {"options": {"controller.kpp": 2.0}},
        r"unknown controller option 'kpp' in \[options\] key 'controller.kpp' of {source}; "
        r"did you mean 'kp'\? \(accepted: fraction, kd, ki, kp\)$"),
    "the run's length given as an env option": (
        {"options": {"env.time_limit": 5.0}},
        r"\[options\] key 'env.time_limit' of {source}: not an env option; give the top-level "
        r"key 'duration'$"),
}


def _toml(value) -> str:
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return repr(value)


def _sweep_file(spec: dict) -> str:
    lines = [f"{key} = {_toml(value)}" for key, value in spec.items() if not isinstance(value, dict)]
    for table, values in spec.items():
        if isinstance(values, dict):
            lines += [f"[{table}]"] + [f'"{key}" = {_toml(value)}' for key, value in values.items()]
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("case", CASES)
def test_in_python_one_line_before_any_run(case, tmp_path):
    change, message = CASES[case]
    out = tmp_path / "out"
    with pytest.raises(SweepError, match=message.format(source="the sweep description")) as err:
        sweep.run({**BASE, **change}, out, scheduler="serial", progress=False)
    assert "\n" not in str(err.value)
    assert not (out / "runs").exists()


@pytest.mark.parametrize("case", CASES)
def test_in_a_sweep_file_one_line_and_exit_2_before_any_run(case, tmp_path, capsys):
    change, message = CASES[case]
    path = tmp_path / "bad.toml"
    path.write_text(_sweep_file({**BASE, **change}))
    out = tmp_path / "out"
    assert main(["sweep", str(path), "--out", str(out), "--scheduler", "serial"]) == 2
    captured = capsys.readouterr()
    lines = captured.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("sailmujoco: error: ")
    source = re.escape(f"sweep file '{path}'")
    assert re.search(message.format(source=source), lines[0]), lines[0]
    assert captured.out == "" and not out.exists()


def test_a_metric_of_the_task_with_diagnostics_is_accepted():
    """Metrics can depend on the task's options: the diagnostics' metrics are known where a run
    of the sweep turns them on."""
    spec = {**BASE, "metrics": ["mean_surge", "ct_cn_ratio"],
            "grid": {"task.diagnostics": [False, True]}}
    assert sweep.validate(spec)["metrics"] == ["mean_surge", "ct_cn_ratio"]
    with pytest.raises(SweepError, match="unknown metric 'ct_cn_ratio'"):
        sweep.validate({**spec, "grid": {"task.diagnostics": [False]}})
