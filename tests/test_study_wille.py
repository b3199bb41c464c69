"""The Wille studies (2016a Table 2, 2016b Table 1) in smoke mode: they run, write their report
and figures, and their headline numbers say what the papers say in kind.

Smoke mode is short (30 s close-hauled, 60 s beam reach, a 2 x 2 Fig. 8 grid): the assertions
are on properties that already hold then, not on the paper's numbers (the full studies compare
those in their reports).
"""

import math

import pandas as pd
import pytest
from sailmujoco.studies import wille_course_table2, wille_roll_table1
from sailmujoco.studies.kit.wille import table1_numbers, table1_simulate
from test_reports import layout_problems

from sailmujoco import sweep
from sailmujoco.study import run_study


def _smoke(study, out):
    with sweep.Engine("serial") as engine:  # in this process
        return out, run_study(study, out, engine, smoke=True, progress=False)


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    return _smoke(wille_course_table2.STUDY, tmp_path_factory.mktemp("wille_course_table2"))


@pytest.fixture(scope="module")
def roll(tmp_path_factory):
    return _smoke(wille_roll_table1.STUDY, tmp_path_factory.mktemp("wille_roll_table1"))


def test_course_study_writes_report_and_figures(course):
    out, _ = course
    report = (out / "report.md").read_text()
    assert layout_problems(report) == []  # title, summary, main table
    assert "Table 2" in report
    assert "| quantity | world | paper | ours | difference | cause |" in report
    for name in ("fig4_position.png", "fig5_course.png"):
        assert (out / name).stat().st_size > 10_000, name
    table = pd.read_csv(out / "table2.csv")
    assert len(table) == 4  # two controllers in two worlds
    assert set(table["law"]) == {"heading", "course"}


@pytest.mark.parametrize("world", ["paper", "mujoco"])
def test_course_controller_cuts_the_drift(course, world):
    _, h = course
    # the heading controller drifts to leeward (east: the wind comes from 310 deg) by degrees
    assert h[f"{world}_heading_east"] > 0.0
    assert 1.0 < h[f"{world}_heading_error_deg"] < 6.0
    # both sail north, close-hauled
    assert h[f"{world}_heading_north"] > 20.0 and h[f"{world}_course_north"] > 20.0
    # Wille §4: the correction term cuts the drift error (by 93 % in the paper's 200 s run). One
    # 30 s run (seed 0) is a single draw of the gusts, and a change in the last bit of a force
    # moves a run about as much as another gust realisation does, so each bound sits well
    # outside the spread of this smoke run over seeds 0-11 (measured, 30 s, 50 Hz):
    # - paper world: reduction 0.69-0.94 (seed 0: 0.92; seeds 0-7): the correction removes most
    #   of the error, more than 60 %;
    # - MuJoCo world: reduction 0.21-0.83 (seed 0: 0.63), the rudder limit-cycles: only "less
    #   drift than the heading controller" holds for every realisation.
    least = {"paper": 0.6, "mujoco": 0.0}[world]
    assert h[f"{world}_error_reduction"] > least
    assert h[f"{world}_course_error_deg"] < (1.0 - least) * h[f"{world}_heading_error_deg"]


def test_course_study_paper_world_is_quiet_at_50_hz(course):
    _, h = course
    assert h["paper_heading_rudder_rms_deg"] < 3.0  # no rudder limit cycle at the headline rate
    assert h["wall_time_s"] < 60.0


def test_roll_study_writes_report_and_figures(roll):
    out, _ = roll
    report = (out / "report.md").read_text()
    assert layout_problems(report) == []  # title, summary, main table
    for heading in ("Table 1", "Fig. 3", "Fig. 8"):
        assert heading in report
    pngs = sorted(p.name for p in out.glob("*.png"))
    assert len(pngs) == 5, pngs  # Figs. 3, 5, 6, 7, 8
    for name in pngs:
        assert (out / name).stat().st_size > 10_000, name
    for world in ("paper", "mujoco"):  # the sweep engine's store
        assert (out / f"fig8_sweep_{world}" / "results.parquet").exists()
    header = "| quantity | world | paper | ours | difference | cause |"
    table1 = report.split(header, 1)[1].split("\n\n", 1)[0]
    flagged = [line for line in table1.splitlines() if "⚠" in line]
    assert flagged and all(line.rstrip(" |").endswith("not checked in smoke mode (below the table)")
                           for line in flagged)  # a flagged row says why it names no cause
    assert "Smoke mode names no causes" in report


@pytest.mark.parametrize("world", ["paper", "mujoco"])
def test_roll_study_table1_numbers(roll, world):
    _, h = roll
    for sim in ("sim1", "sim1_mean", "sim2", "sim2_mean", "sim3"):
        assert 0.1 < h[f"{world}_{sim}_roll_amplitude"] < 15.0
        assert 0.1 < h[f"{world}_{sim}_max_roll_rate"] < 20.0
        assert 4.0 < h[f"{world}_{sim}_mean_surge"] < 10.0  # beam reach in 10 m/s
    # the roll control with the true wind rolls less than lambda_100 alone (either baseline)
    assert h[f"{world}_sim3_roll_amplitude"] < h[f"{world}_sim1_roll_amplitude"]
    assert h[f"{world}_sim3_roll_amplitude"] < h[f"{world}_sim1_mean_roll_amplitude"]
    # sim 2 as read (the apparent direction measured, the mean speed) rolls less than with the
    # mean direction as well: near luffing the moment follows the direction, not the speed
    assert h[f"{world}_sim2_roll_amplitude"] < h[f"{world}_sim2_mean_roll_amplitude"]
    # and never heels more on average than lambda_100 (it can only take moment away)
    assert h[f"{world}_sim3_mean_heel"] <= h[f"{world}_sim1_mean_heel"] + 0.2


@pytest.mark.parametrize("world", ["paper", "mujoco"])
def test_roll_study_moment_shares(roll, world):
    _, h = roll
    shares = [h[f"{world}_share_{k}"] for k in ("sail_restoring", "keel", "rudder_damping")]
    assert sum(shares) == pytest.approx(1.0, abs=1e-9)
    # §3: sail and restoring dominate (paper 91 %), the keel is next (8 %), the rest small (1 %)
    assert shares[0] > 0.85
    assert shares[1] > shares[2]
    assert shares[2] < 0.05


def test_roll_study_fig8_grid(roll):
    _, h = roll
    for world in ("paper", "mujoco"):
        for wind in (13, 16):
            assert h[f"{world}_fig8_optimum_deg_{wind}"] in (10.0, 30.0)  # a grid point in smoke mode
    assert h["wall_time_s"] < 60.0
    assert math.isfinite(h["simulation_wall_time_s"])


def test_roll_sim3_residual_is_the_sail_actuators_lag():
    """Wille (2016b) §5: with perfect wind "the remaining error is likely caused by the delay in
    the sail actuator". Where the law is on all the time (U10 = 13 m/s, the boat would heel far
    past 10 deg), halving T_lambda (0.5 s, Appendix A) halves sim 3's roll amplitude, and the
    mean heel stays at phi_d."""
    runs = {}
    for lag in (0.5, 0.25):
        job = dict(world="paper", sim="sim3", seed=0, duration=100.0, wind_speed=13.0, sail_time_constant=lag)
        runs[lag] = table1_numbers(table1_simulate(job))
    for n in runs.values():
        assert n["on"] == 1.0
        assert abs(n["mean_heel"] - 10.0) < 0.3
    # measured 0.71 deg and 0.54; over seeds 0-3: 0.71-0.79 deg and 0.51-0.54, mean heel within
    # 0.06 deg of phi_d, the law on all the window: the bounds are far outside that spread
    assert 0.5 < runs[0.5]["roll_amplitude"] < 1.0
    assert 0.4 < runs[0.25]["roll_amplitude"] / runs[0.5]["roll_amplitude"] < 0.65
