"""The command line: help, the health check, bad input exits 2."""

import subprocess
import sys

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
