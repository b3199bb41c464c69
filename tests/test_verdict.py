"""The one function set that writes every report's difference, range and verdict
(studies/kit/verdict.py), on constructed cases whose answer is known by hand."""

import math

import numpy as np
import pytest
from sailmujoco.studies.kit import Report, verdict


def test_relative_difference_is_the_change_in_size_for_same_signed_numbers():
    # -0.54 m against the paper's -2.15 m: a quarter of the paper's drift, not "+75 %"
    d = verdict.difference(-0.54, -2.15, unit="m")
    assert d.relative and d.value == pytest.approx((0.54 - 2.15) / 2.15)
    assert d.text() == "-75 %"
    # positive numbers: the ordinary (ours - paper) / paper
    assert verdict.difference(3.73, 4.38).value == pytest.approx(3.73 / 4.38 - 1.0)
    assert verdict.difference(-8.31, -2.15).text() == "+287 %"  # ours nearly four times the size


def test_opposite_signs_give_the_absolute_difference_with_its_unit():
    d = verdict.difference(1.2, -2.0, unit="m")
    assert not d.relative and d.value == pytest.approx(3.2)
    assert d.text() == "+3.2 m (signs differ)"


def test_reference_within_the_floor_gives_the_absolute_difference():
    d = verdict.difference(0.091, 0.12, floor=0.3, unit="m/s")  # a stalled boat: 0.12 m/s
    assert not d.relative and d.value == pytest.approx(-0.029)
    assert d.text() == "-0.029 m/s (reference ≈ 0)"
    # judged against the tolerance times the floor, not against ~0: 0.029 > 0.05 * 0.3
    assert d.beyond(0.05) and not verdict.difference(0.11, 0.12, floor=0.3).beyond(0.05)
    assert not verdict.difference(0.0, 0.0).relative  # a zero reference is never divided by


def test_not_a_number_gives_no_difference_and_counts_beyond():
    for ours, ref in ((float("nan"), 1.0), (1.0, "≤ 45"), (1.0, None)):
        d = verdict.difference(ours, ref)
        assert not d.finite and d.text() == "—" and d.beyond()


def test_value_range_is_min_to_max_of_every_finite_value():
    values = [0.05, -0.29, float("nan"), 0.012]
    assert verdict.value_range(values, 100, "{:+.1f}") == "-29.0 … +5.0"
    assert verdict.value_range([float("nan")]) == "—"


def test_range_of_differences_keeps_the_points_below_the_floor():
    """The C_T-off defect: the stalled point (-23 %) was dropped from the range. Now it is
    reported in m/s beside the relative range, with the counts."""
    built = np.array([0.12, 0.68, 3.28])
    off = np.array([0.0915, 0.660, 3.45])
    diffs = verdict.differences(off, built, floor=0.3, unit="m/s")
    text = verdict.range_of(diffs)
    assert text.startswith(f"{100 * (0.660 / 0.68 - 1):+.1f} … {100 * (3.45 / 3.28 - 1):+.1f} % (2 points)")
    assert text.endswith("; -0.0285 m/s where the reference is below 0.3 m/s (1 point)")


def test_holds_only_when_every_value_is_within():
    assert verdict.judge([0.01, 0.02, 0.09], below=0.1).text() == "holds (3 of 3 points)"
    # -24 ... +724 %: one value far beyond is enough to break, and is counted
    j = verdict.judge([-0.24, 0.01, 7.24], below=0.05, magnitude=True)
    assert not j.holds and j.beyond == 2 and j.text() == "breaks at 2 of 3 points"
    assert verdict.judge([-0.04, -0.06], above=-0.05).beyond == 1
    assert verdict.judge([0.1], below=0.1).beyond == 1  # the threshold itself is not within


def test_a_missing_value_cannot_hold():
    j = verdict.judge([0.01, float("nan")], below=0.1)
    assert not j.holds and j.text() == "breaks at 1 of 2 points, 1 without a value"
    assert verdict.judge([], below=1.0).text() == "no data" and not verdict.judge([], below=1.0).holds


def test_judge_differences_uses_the_same_tolerance_per_kind():
    diffs = verdict.differences([1.04, 0.2, 0.5], [1.0, 0.21, 0.3], floor=0.3)
    # +4 % (within 5 %), -0.01 m/s against 0.05 * 0.3 (within), +67 % (beyond)
    j = verdict.judge_differences(diffs, 0.05)
    assert (j.n, j.beyond) == (3, 1)


@pytest.mark.parametrize(("value", "state"), [
    (30.0, "does not bind"),  # the defect: 30° under a 45° limit
    (44.6, "binds"), (45.0, "binds"), (-45.0, "binds"), (45.4, "binds"),
    (46.0, "exceeded"), (float("nan"), "no value")])
def test_limit_binds_only_at_the_limit(value, state):
    assert verdict.limit_state(value, 45.0, 0.5) == state


def test_comparison_table_takes_its_difference_from_the_function():
    report = Report("t")
    report.comparison([
        {"quantity": "x", "world": "w", "paper": -2.15, "ours": -0.54, "unit": "m", "cause": ""},
        {"quantity": "y", "world": "w", "paper": 1.0, "ours": 1.05, "cause": ""},
        {"quantity": "z", "world": "w", "paper": "≤ 45", "ours": 30.0, "cause": ""},
        {"quantity": "s", "world": "w", "paper": -1.0, "ours": 2.0, "unit": "m", "cause": ""}])
    lines = report.parts[0].splitlines()
    assert "| -75 % ⚠ |" in lines[2]
    assert "| +5 % |" in lines[3] and "⚠" not in lines[3]
    assert "| — |" in lines[4]
    assert "| +3 m (signs differ) ⚠ |" in lines[5]
    assert not math.isnan(verdict.difference(2.0, -1.0).value)
    assert report.parts[1].strip() == verdict.DIFFERENCE_NOTE  # the table says how it is computed


def test_combined_holds_only_when_every_criterion_holds():
    """The heave+pitch defect: pitch within 2° everywhere but the speed moved up to 724 % was
    reported "holds"."""
    pitch = verdict.judge([0.5, 1.0], below=2.0)
    speed = verdict.judge_differences(verdict.differences([0.76, 8.24], [1.0, 1.0]), 0.05)
    assert verdict.combined({"pitch": pitch}) == "holds (pitch: holds (2 of 2 points))"
    assert verdict.combined({"pitch": pitch, "speed": speed}) == (
        "breaks (pitch: holds (2 of 2 points); speed: breaks at 2 of 2 points)")


def test_saoud_fig4_report_says_binds_only_where_the_limit_is_reached(tmp_path):
    from sailmujoco.studies import saoud_fig3_fig4

    from sailmujoco import sweep
    from sailmujoco.study import run_study

    headline = run_study(saoud_fig3_fig4.STUDY, tmp_path, sweep.Engine("serial"), smoke=True, progress=False)
    lines = (tmp_path / "report.md").read_text().splitlines()
    for limit in (45, 20, 10):
        (row,) = [line for line in lines if f"with φ_max = {limit}° (deg)" in line]
        reached = abs(headline[f"max_phi_limit_{limit}"]) >= limit - 0.5
        assert ("the limit binds" in row) == reached, row
        assert ("does not bind" in row) == (not reached), row
