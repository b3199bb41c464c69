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
    assert "| quantity | world | paper | ours: mean [95 % interval] | difference of the mean | verdict |" \
        in report
    for name in ("fig4_position.png", "fig5_course.png"):
        assert (out / name).stat().st_size > 10_000, name
    table = pd.read_csv(out / "table2.csv")
    assert len(table) == 8  # two controllers in two worlds, on each of the smoke pass's two seeds
    assert set(table["law"]) == {"heading", "course"}
    assert sorted(table["seed"].unique()) == [0, 1]
    assert (out / "table2_intervals.png").stat().st_size > 10_000
    assert "**Method.** N = 2" in report  # the seeds and the verdict rule, stated once


@pytest.mark.parametrize("world", ["paper", "mujoco"])
def test_course_controller_cuts_the_drift(course, world):
    from sailmujoco import stats

    out, h = course
    runs = pd.read_csv(out / "table2.csv")
    main = runs[(runs["case"] == "main") & (runs["world"] == world)]
    heading = main[main["law"] == "heading"].sort_values("seed")
    course_ = main[main["law"] == "course"].sort_values("seed")
    # the heading controller drifts to leeward (east: the wind comes from 310 deg) by the leeway
    # angle of a keel boat close-hauled, a few degrees, on every seed
    assert (heading["east"] > 0.0).all()
    assert ((heading["error_deg"] > 1.0) & (heading["error_deg"] < 6.0)).all()
    # both sail north, close-hauled
    assert (main["north"] > 20.0).all()
    # Wille §4: the correction term cuts the drift error. Decided seed by seed (both laws sail the
    # same gusts and start): the interval of course error - heading error lies below zero
    cut = stats.paired_difference(course_["error_deg"], heading["error_deg"])
    assert cut.n == 2 and cut.decided
    assert stats.verdict(cut, 0.0, "below") == "holds"
    # the headline's reduction is the mean of the per-seed reductions, with a finite interval
    reduction = 1.0 - course_["error_deg"].to_numpy() / heading["error_deg"].to_numpy()
    assert h[f"{world}_error_reduction"] == pytest.approx(reduction.mean())
    low, high = h[f"{world}_error_reduction_low"], h[f"{world}_error_reduction_high"]
    assert math.isfinite(low) and math.isfinite(high)
    assert low <= h[f"{world}_error_reduction"] <= high
    # in the paper world the correction removes most of the error (more than 60 % on each seed of
    # the 30 s smoke run; seeds 0-11 ranged 0.69-0.94); in 6-DOF the rudder limit-cycles and only
    # "less drift than the heading controller" holds
    if world == "paper":
        assert (reduction > 0.6).all()
    for key in ("error_reduction_verdict", "heading_error_deg_verdict", "course_error_deg_verdict"):
        assert h[f"{world}_{key}"] in ("holds", "breaks", "undecided at 2 seeds")


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
    assert len(pngs) == 6, pngs  # Figs. 3, 5, 6, 7, 8 and Table 1 with its intervals
    for name in pngs:
        assert (out / name).stat().st_size > 10_000, name
    for world in ("paper", "mujoco"):  # the sweep engine's store
        assert (out / f"fig8_sweep_{world}" / "results.parquet").exists()
    header = ("| quantity | world | paper | ours: mean [95 % interval] | difference of the mean | "
              "verdict (±10 %) | cause |")
    table1 = report.split(header, 1)[1].split("\n\n", 1)[0]
    rows = table1.splitlines()[2:]
    assert len(rows) == 30  # 5 simulations x 3 numbers x 2 worlds
    verdicts = [row.split(" | ")[-2] for row in rows]
    assert set(verdicts) <= {"holds", "breaks", "undecided at 2 seeds"}
    not_held = [row for row, said in zip(rows, verdicts, strict=True) if said != "holds"]
    assert not_held and all(row.rstrip(" |").endswith("not checked in smoke mode (below the table)")
                            for row in not_held)  # a row that does not hold says why it names no cause
    assert "Smoke mode names no causes" in report
    assert "**Method.** N = 2 (seeds 0-1)" in report  # the rule and N, stated once
    # every seed's row is kept, and the table's numbers over seeds
    runs = pd.read_csv(out / "runs.csv")
    main = runs[runs["case"] == "main"]
    assert sorted(set(main["seed"])) == [0, 1] and len(main) == 2 * 5 * 2
    table = pd.read_csv(out / "table1.csv")
    assert len(table) == 10 and (table["n"] == 2).all()
    assert (table["roll_amplitude_low"] <= table["roll_amplitude"]).all()
    assert (table["roll_amplitude"] <= table["roll_amplitude_high"]).all()


@pytest.mark.parametrize("world", ["paper", "mujoco"])
def test_roll_study_table1_numbers(roll, world):
    _, h = roll
    assert h["seeds"] == 2  # a smoke pass: two gust realisations
    for sim in ("sim1", "sim1_mean", "sim2", "sim2_mean", "sim3"):
        assert 0.1 < h[f"{world}_{sim}_roll_amplitude"] < 15.0
        assert 0.1 < h[f"{world}_{sim}_max_roll_rate"] < 20.0
        assert 4.0 < h[f"{world}_{sim}_mean_surge"] < 10.0  # beam reach in 10 m/s
        # the mean over the two realisations has a finite interval around it
        low, high = h[f"{world}_{sim}_roll_amplitude_low"], h[f"{world}_{sim}_roll_amplitude_high"]
        assert math.isfinite(low) and math.isfinite(high)
        assert low <= h[f"{world}_{sim}_roll_amplitude"] <= high
    # the reductions are paired by seed (law on against off on the same gusts): the interval of
    # the per-seed reductions exists, each verdict is one of the rule's three words
    for base, sim in (("sim1", "sim2"), ("sim1", "sim3"), ("sim1_mean", "sim3")):
        key = f"{world}_reduction_{base}_{sim}"
        assert math.isfinite(h[f"{key}_low"]) and h[f"{key}_low"] <= h[key] <= h[f"{key}_high"]
        assert h[f"{key}_verdict"] in ("holds", "breaks", "undecided at 2 seeds")
        assert h[f"{world}_roll_cut_{base}_{sim}_deg"] > 0.0  # the law takes roll away on average
    if world == "paper":
        # Table 1: with the law holding 10 deg both controlled runs sail at the paper's 6.59 m/s;
        # the paper world's speed is the paper's model, so its interval does not miss the 10 % band
        assert h["paper_sim3_mean_surge_verdict"] != "breaks"
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
    assert h["wall_time_s"] < 120.0  # two seeds of 60 s runs
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
