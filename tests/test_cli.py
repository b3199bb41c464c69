"""The command line: help, the health check, bad input exits 2."""

import subprocess
import sys

import pytest

from sailmujoco.cli import main


def test_help_runs(tmp_path):
    out = subprocess.run([sys.executable, "-m", "sailmujoco.cli", "--help"], capture_output=True,
                         text=True, check=True, cwd=tmp_path)
    assert "check" in out.stdout


def test_check_reports_health(capsys, tmp_path):
    code = main(["check", "--seconds", "3", "--plots", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 0
    assert "health: OK" in out
    assert out.count(" ok ") == 6  # three boats x two hydrostatic modes
    assert (tmp_path / "righting_curve_wille_yacht.png").stat().st_size > 10_000


def test_check_unknown_boat_exits_2(capsys):
    assert main(["check", "--boat", "dinghy"]) == 2
    assert "unknown boat 'dinghy'" in capsys.readouterr().err


@pytest.mark.parametrize("argv,message", [
    (["check", "--seconds", "-1"], "argument --seconds: must be a number > 0 s, got '-1'"),
    (["check", "--seconds", "nan"], "argument --seconds: must be a number > 0 s, got 'nan'"),
    (["check", "--wind", "-3"], "argument --wind: must be a number >= 0 m/s, got '-3'"),
    (["sweep", "x.toml", "--workers", "-1"],
     "argument --workers: must be an integer >= 0 (0: all cores), got '-1'"),
    (["study", "all", "--workers", "two"],
     "argument --workers: must be an integer >= 0 (0: all cores), got 'two'"),
])
def test_bad_numbers_exit_2_with_one_line(argv, message, capsys):
    from sailmujoco import cli

    with pytest.raises(SystemExit) as err:
        cli.main(argv)
    assert err.value.code == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert lines[-1].endswith(message)
    assert not any("Traceback" in line for line in lines)
