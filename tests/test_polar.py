"""Polar diagrams: the CLI writes the figure and the CSV; the brute-force polar bounds the others."""

import pandas as pd
import pytest

from sailmujoco.cli.main import main
from sailmujoco.design import polar, polar_compare


def test_best_vmg_picks_the_right_angles():
    frame = pd.DataFrame({"tws": [4.0] * 4, "twa": [45.0, 60.0, 135.0, 165.0],
                          "speed": [1.0, 1.2, 1.4, 1.3]})
    best = polar.best_vmg(frame)[4.0]
    assert best["upwind"][0] == 45.0  # 1.0 cos 45 = 0.71 > 1.2 cos 60 = 0.6
    assert best["downwind"][0] == 165.0  # 1.3 cos 15 = 1.26 > 1.4 cos 45 = 0.99
    assert best["upwind"][1] == pytest.approx(1.0 * 2**-0.5)


def test_comparison_summary_by_twa_band():
    """Two winds x four angles, one per band; the ratios are chosen so that each band's min and
    max are known by hand. briere misses one point (NaN): it is left out, not counted as 0."""
    twa = [45.0, 60.0, 120.0, 180.0]
    frames = {
        "best": pd.DataFrame({"tws": [2.0] * 4 + [4.0] * 4, "twa": twa * 2,
                              "speed": [0.50, 0.80, 1.00, 0.40, 0.60, 1.00, 1.20, 0.50]}),
        "saoud": pd.DataFrame({"tws": [2.0] * 4 + [4.0] * 4, "twa": twa * 2,
                               "speed": [0.45, 0.82, 0.90, 0.40, 0.30, 0.95, 1.20, 0.55]}),
        "briere": pd.DataFrame({"tws": [2.0] * 3 + [4.0] * 4, "twa": twa[:3] + twa,
                                "speed": [0.25, 0.40, 0.50, 0.60, 0.50, 0.60, 0.25]}),
    }
    table = polar_compare.comparison_table(frames)
    assert len(table) == 8 and table["briere"].isna().sum() == 1
    summary = polar_compare.ratio_summary(table).set_index(["controller", "band"])
    s = summary.loc[("saoud", "close-hauled")]  # 0.45/0.50 = 0.9 at 2 m/s, 0.30/0.60 = 0.5 at 4 m/s
    assert (s["ratio_min"], s["ratio_max"]) == pytest.approx((0.5, 0.9))
    assert (s["min_tws"], s["min_twa"], s["min_speed"], s["min_best"]) == (4.0, 45.0, 0.30, 0.60)
    s = summary.loc[("saoud", "close reach")]  # 0.82/0.80 = 1.025 (faster than best), 0.95/1.00
    assert (s["ratio_min"], s["ratio_max"]) == pytest.approx((0.95, 1.025))
    s = summary.loc[("saoud", "beam to broad reach")]  # 0.90/1.00, 1.20/1.20
    assert (s["ratio_min"], s["ratio_max"]) == pytest.approx((0.9, 1.0))
    s = summary.loc[("saoud", "running")]  # 0.40/0.40, 0.55/0.50
    assert (s["ratio_min"], s["ratio_max"]) == pytest.approx((1.0, 1.1))
    s = summary.loc[("briere", "running")]  # only 4 m/s: 0.25/0.50
    assert (s["ratio_min"], s["ratio_max"], s["min_tws"]) == pytest.approx((0.5, 0.5, 4.0))
    assert summary.loc[("briere", "close-hauled"), "ratio_min"] == pytest.approx(0.5)  # 0.25/0.5
    text = polar_compare.comparison_markdown(table, polar_compare.ratio_summary(table), "sailmujoco polar x")
    assert "| saoud | close-hauled | 45-45 | 0.50 (4 m/s, 45°: 0.30 / 0.60 m/s) | 0.90 (2 m/s, 45°" in text
    assert "| 2 | 180 | 0.40 | 0.40 | — | 1.00 | — |" in text  # the point briere did not finish
    assert polar_compare.ratio_summary(polar_compare.comparison_table({"saoud": frames["saoud"]})).empty


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
    compare = pd.read_csv(tmp_path / "compare.csv")
    assert compare["saoud/best"].to_numpy() == pytest.approx(merged["speed_saoud"] / merged["speed_best"])
    text = (tmp_path / "compare.md").read_text()
    assert "--compare best" in text and "| saoud | close reach | 60-60 |" in text


def test_polar_unknown_boat_exits_2(capsys):
    assert main(["polar", "catamaran"]) == 2
    assert "unknown boat 'catamaran'" in capsys.readouterr().err


def test_polar_over_seeds_keeps_each_seed_and_pairs_the_ratio_by_seed(tmp_path):
    """Two seeds (two start headings): each seed's row kept; a point's speed is the mean of its
    two runs with the t-interval mean ± t(0.975, 1) |a - b| / 2, t(0.975, 1) = 12.7062; the
    ratio to the best sail is the mean of the two per-seed ratios."""
    code = main(["polar", "saoud_robot", "--controller", "saoud", "--compare", "best", "--tws", "4",
                 "--twa", "90", "--duration", "12", "--seeds", "2", "--scheduler", "serial",
                 "--out", str(tmp_path), "--no-progress"])
    assert code == 0
    seeds = pd.read_csv(tmp_path / "polar_saoud_seeds.csv")
    assert list(seeds["seed"]) == [0, 1] and seeds["speed"].nunique() == 2  # the start differs
    point = pd.read_csv(tmp_path / "polar_saoud.csv").iloc[0]
    a, b = seeds["speed"]
    assert point["n"] == 2 and point["speed"] == pytest.approx((a + b) / 2, rel=1e-12)
    assert (point["speed_low"], point["speed_high"]) == pytest.approx(
        ((a + b) / 2 - 12.7062 * abs(a - b) / 2, (a + b) / 2 + 12.7062 * abs(a - b) / 2), rel=1e-5)
    best = pd.read_csv(tmp_path / "polar_best_seeds.csv")
    compare = pd.read_csv(tmp_path / "compare.csv").iloc[0]
    assert compare["saoud/best"] == pytest.approx(float((seeds["speed"] / best["speed"]).mean()), rel=1e-12)
    assert "saoud/best" in (tmp_path / "compare.md").read_text()
