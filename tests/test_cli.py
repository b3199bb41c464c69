
"""The command line: help, the health check, bad input exits 2."""

import os
import subprocess
import sys
import time

import pytest

from sailmujoco.cli.main import main


def test_help_runs(tmp_path):
    out = subprocess.run([sys.executable, "-m", "sailmujoco", "--help"], capture_output=True,
                         text=True, check=True, cwd=tmp_path)
    assert "check" in out.stdout


def test_check_reports_health(capsys, tmp_path):
    code = main(["check", "--seconds", "3", "--plots", str(tmp_path)])
    out = capsys.readouterr().out
    assert code == 0
    assert "health: OK" in out
    assert out.count(" ok ") == 8  # four boats x two hydrostatic modes
    assert (tmp_path / "righting_curve_wille_yacht.png").stat().st_size > 10_000


def test_check_unknown_boat_exits_2(capsys):
    assert main(["check", "--boat", "dinghy"]) == 2
    assert "unknown boat 'dinghy'" in capsys.readouterr().err


FOUR_PER_CORE = 4 * (os.cpu_count() or 1)  # local worker processes beyond this only queue


@pytest.mark.parametrize("argv,message", [
    (["check", "--seconds", "-1"], "argument --seconds: must be a number > 0 s, got '-1'"),
    (["check", "--seconds", "nan"], "argument --seconds: must be a number > 0 s, got 'nan'"),
    (["check", "--wind", "-3"], "argument --wind: must be a number >= 0 m/s, got '-3'"),
    (["sweep", "x.toml", "--workers", "-1"],
     f"argument --workers: must be an integer >= 0 and <= {FOUR_PER_CORE} (0: all cores), got '-1'"),
    (["study", "all", "--workers", "two"],
     f"argument --workers: must be an integer >= 0 and <= {FOUR_PER_CORE} (0: all cores), got 'two'"),
    (["sweep", "x.toml", "--workers", "100000"],  # beyond the bound: 100000 processes would only queue
     f"argument --workers: must be an integer >= 0 and <= {FOUR_PER_CORE} (0: all cores), "
     "got '100000'"),
])
def test_bad_numbers_exit_2_with_one_line(argv, message, capsys):
    from sailmujoco.cli import main as cli

    with pytest.raises(SystemExit) as err:
        cli.main(argv)
    assert err.value.code == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert lines[-1].endswith(message)
    assert not any("Traceback" in line for line in lines)


def _one_line(capsys) -> str:
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "Traceback" not in err, err
    return err


def _tiny_sweep(tmp_path):
    path = tmp_path / "tiny.toml"
    path.write_text('boat = "saoud_robot"\ntask = "heading_hold"\nworld = "mujoco"\n'
                    'controller = "pid"\nduration = 1.0\n')
    return path


@pytest.mark.parametrize("address,why", [("tcp://127.0.0.1:1", "Timed out trying to connect"),
                                         ("nonsense", "missing port number")])
def test_sweep_on_an_unreachable_scheduler_fails_fast_in_one_line(tmp_path, capsys, address, why):
    assert main(["sweep", str(_tiny_sweep(tmp_path)), "--out", str(tmp_path / "o"), "--no-progress",
                 "--scheduler", address]) == 2
    err = _one_line(capsys)
    assert f"cannot reach the Dask scheduler at {address!r} within 3 s" in err and why in err


def test_sweep_given_a_folder_or_a_missing_file_exits_2(tmp_path, capsys):
    assert main(["sweep", str(tmp_path)]) == 2
    assert f"sweep file {str(tmp_path)!r} is a folder, not a TOML file" in _one_line(capsys)
    assert main(["sweep", str(tmp_path / "nope.toml")]) == 2
    assert f"sweep file {str(tmp_path / 'nope.toml')!r} does not exist" in _one_line(capsys)


@pytest.mark.parametrize("command", [["sweep", "SWEEP"], ["polar", "saoud_robot"],
                                     ["study", "saoud_fig6"]])
def test_out_at_a_file_exits_2_in_one_line(tmp_path, capsys, command):
    a_file = tmp_path / "taken"
    a_file.write_text("not a folder")
    argv = [str(_tiny_sweep(tmp_path)) if a == "SWEEP" else a for a in command]
    assert main([*argv, "--out", str(a_file), "--no-progress"]) == 2
    err = _one_line(capsys)
    assert str(a_file) in err and "file" in err
    assert a_file.read_text() == "not a folder"


def test_video_out_at_a_folder_exits_2_in_one_line(tmp_path, capsys):
    assert main(["video", "saoud_robot", "heading_hold", "--controller", "pid",
                 "--out", str(tmp_path)]) == 2
    assert f"--out {str(tmp_path)!r} is a folder; give a file name" in _one_line(capsys)


@pytest.mark.parametrize("option", ["--out", "--still"])
def test_video_file_under_a_file_exits_2_in_one_line(tmp_path, capsys, option):
    a_file = tmp_path / "notes.txt"
    a_file.write_text("x")
    files = {"--out": str(tmp_path / "v.mp4"), "--still": None}
    files[option] = str(a_file / "x.png")
    argv = ["video", "saoud_robot", "heading_hold", "--controller", "pid", "--seconds", "0.2",
            "--out", files["--out"]] + (["--still", files["--still"]] if files["--still"] else [])
    assert main(argv) == 2
    assert f"{option} {str(a_file / 'x.png')!r}: {str(a_file)!r} is (or lies under) a file" in \
        _one_line(capsys)
    assert not (tmp_path / "v.mp4").exists()


@pytest.mark.parametrize("argv", [["check"], ["video", "saoud_robot", "heading_hold", "--controller",
                                              "pid", "--out", "v.mp4"],
                                  ["view", "saoud_robot", "heading_hold", "--controller", "pid"]])
def test_a_negative_seed_exits_2_naming_the_option(argv, capsys):
    with pytest.raises(SystemExit) as err:
        main([*argv, "--seed", "-1"])
    assert err.value.code == 2
    lines = capsys.readouterr().err.strip().splitlines()
    assert lines[-1].endswith("error: argument --seed: must be an integer >= 0, got '-1'")
    assert not any("Traceback" in line for line in lines)


@pytest.mark.parametrize("argv", [["check", "--boat", "saoud_robot", "--plots", "OUT"],
                                  ["study", "saoud_fig6", "--smoke", "--out", "OUT"],
                                  ["sweep", "SWEEP", "--out", "OUT", "--scheduler", "serial"]])
def test_an_out_folder_that_cannot_be_made_exits_2_in_one_line(argv, tmp_path, capsys):
    out = "/proc/sailmujoco_cannot_be_made"  # /proc takes no new folders, even for root
    argv = [out if a == "OUT" else str(_tiny_sweep(tmp_path)) if a == "SWEEP" else a for a in argv]
    start = time.perf_counter()
    assert main(argv) == 2
    assert time.perf_counter() - start < 10  # refused before any run
    err = _one_line(capsys)
    assert f"cannot make the {'results ' if argv[0] == 'sweep' else ''}folder {out!r}: " in err
    assert "No such file or directory" in err
