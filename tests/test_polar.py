"""Polar diagrams: the CLI writes the figure and the CSV; the brute-force polar bounds the others."""

import pandas as pd
import pytest

from sailmujoco import polar
from sailmujoco.cli import main


def test_best_vmg_picks_the_right_angles():
    frame = pd.DataFrame({"tws": [4.0] * 4, "twa": [45.0, 60.0, 135.0, 165.0],
                          "speed": [1.0, 1.2, 1.4, 1.3]})
    best = polar.best_vmg(frame)[4.0]
    assert best["upwind"][0] == 45.0  # 1.0 cos 45 = 0.71 > 1.2 cos 60 = 0.6
    assert best["downwind"][0] == 165.0  # 1.3 cos 15 = 1.26 > 1.4 cos 45 = 0.99
    assert best["upwind"][1] == pytest.approx(1.0 * 2**-0.5)


def test_polar_command_writes_figure_and_csv(tmp_path, capsys):
    code = main(["polar", "saoud_robot", "--controller", "saoud", "--compare", "best",
                 "--tws", "4", "--twa", "60,120", "--duration", "25", "--scheduler", "serial",
                 "--out", str(tmp_path), "--no-progress"])
    assert code == 0
    assert (tmp_path / "polar_saoud.png").stat().st_size > 20_000
    assert (tmp_path / "compare.png").stat().st_size > 20_000
    saoud = pd.read_csv(tmp_path / "polar_saoud.csv")
    best = pd.read_csv(tmp_path / "polar_best.csv")
    assert list(saoud["twa"]) == [60.0, 120.0]
    assert (saoud["speed"] > 0.3).all()  # 4 m/s of wind moves the robot
    merged = saoud.merge(best, on=["tws", "twa"], suffixes=("_saoud", "_best"))
    # the brute-force best fixed sail is at least as fast as the optimiser, to 5 %
    assert (merged["speed_best"] >= 0.95 * merged["speed_saoud"]).all()
    assert "best VMG upwind" in capsys.readouterr().out


def test_polar_unknown_boat_exits_2(capsys):
    assert main(["polar", "catamaran"]) == 2
    assert "unknown boat 'catamaran'" in capsys.readouterr().err
