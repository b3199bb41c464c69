"""Intervals over seeds against published values and first principles (sailmujoco.stats)."""

import math

import numpy as np
import pytest

from sailmujoco import stats

# Student (1908), "The probable error of a mean", Table II (Cushny and Peebles): extra hours of
# sleep of ten patients under two drugs; the same patients in both arms, so the arms are paired.
# Published 95 % intervals (R's documented `t.test(extra ~ group, data = sleep)` output):
# paired: mean difference -1.58, [-2.4598858, -0.7001142] (t = -4.0621, df = 9);
# Welch: [-3.3654832, 0.2054832] (t = -1.8608, df = 17.776).
DRUG_1 = [0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0]
DRUG_2 = [1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4]


def test_t_interval_of_students_sleep_data():
    diff = np.subtract(DRUG_1, DRUG_2)
    got = stats.mean_interval(diff)
    assert got.mean == pytest.approx(-1.58)
    assert (got.low, got.high) == pytest.approx((-2.4598858, -0.7001142), abs=1e-6)
    assert got.n == 10 and got.method == "t"


def test_t_interval_from_the_textbook_formula():
    # mean ± t(0.975, n-1) s / sqrt(n), t(0.975, 4) = 2.776 (any t table)
    x = [4.0, 6.0, 5.0, 7.0, 3.0]
    got = stats.mean_interval(x)
    half = 2.776445 * math.sqrt(2.5) / math.sqrt(5)
    assert (got.low, got.high) == pytest.approx((5.0 - half, 5.0 + half), abs=1e-5)


def test_wilson_interval_against_published_values():
    # Newcombe (1998), Stat. Med. 17:857, Table II, example (d): 0 of 20, Wilson score 0 to 0.1611
    zero = stats.pass_rate(0, 20)
    assert zero.mean == 0.0 and zero.low == 0.0 and zero.high == pytest.approx(0.1611, abs=5e-5)
    # 7 of 10 from Wilson's (1927) closed form, z = 1.959964:
    # (p + z²/2n ± z sqrt(p(1-p)/n + z²/4n²)) / (1 + z²/n) = 0.3968 ... 0.8922
    z, p, n = 1.959964, 0.7, 10
    centre, half = p + z * z / (2 * n), z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n))
    seven = stats.pass_rate(7, 10)
    assert (seven.low, seven.high) == pytest.approx(((centre - half) / (1 + z * z / n),
                                                     (centre + half) / (1 + z * z / n)), abs=1e-6)
    assert (seven.low, seven.high) == pytest.approx((0.3968, 0.8922), abs=5e-5)


def test_wilson_refuses_a_count_outside_the_runs():
    with pytest.raises(ValueError, match="passed must be within 0..n"):
        stats.pass_rate(11, 10)


@pytest.mark.parametrize("draw", ["normal", "exponential"])
def test_bootstrap_interval_covers_the_true_mean_about_95_percent(draw):
    # 400 samples of 40 values: the fraction of BCa intervals that contain the true mean (0 for
    # the normal, 1 for the skewed exponential) is 95 % within a few per cent (the binomial
    # standard error of 400 draws is 1.1 %)
    rng = np.random.default_rng(7)
    true_mean = 0.0 if draw == "normal" else 1.0
    hits = 0
    for _ in range(400):
        x = rng.normal(0.0, 1.0, 40) if draw == "normal" else rng.exponential(1.0, 40)
        hits += stats.mean_interval(x, method="bootstrap").contains(true_mean)
    assert abs(hits / 400 - 0.95) < 0.035


def test_bootstrap_is_a_pure_function_of_its_values():
    x = np.random.default_rng(3).normal(size=12)
    assert stats.mean_interval(x, method="bootstrap") == stats.mean_interval(x, method="bootstrap")


def test_paired_difference_is_the_interval_of_the_per_seed_differences_and_narrower():
    paired = stats.paired_difference(DRUG_1, DRUG_2)
    per_seed = stats.mean_interval(np.subtract(DRUG_1, DRUG_2))
    assert paired == per_seed
    welch = stats.unpaired_difference(DRUG_1, DRUG_2)
    assert (welch.low, welch.high) == pytest.approx((-3.3654832, 0.2054832), abs=1e-6)
    assert paired.width < 0.5 * welch.width  # the shared patient cancels in each difference


def test_paired_difference_on_correlated_arms():
    # two arms sharing a large per-seed "weather" term: the paired interval sees only the small
    # arm-specific noise, the unpaired one the weather as well
    rng = np.random.default_rng(11)
    weather = rng.normal(0.0, 5.0, 20)
    a = 10.0 + weather + rng.normal(0.0, 0.2, 20)
    b = 9.0 + weather + rng.normal(0.0, 0.2, 20)
    paired, unpaired = stats.paired_difference(a, b), stats.unpaired_difference(a, b)
    assert paired.width < 0.1 * unpaired.width
    assert paired.contains(1.0) and paired.low > 0.5


def test_paired_ratio_is_the_interval_of_per_seed_ratios():
    a, b = np.array([2.0, 3.0, 4.5, 5.0]), np.array([1.0, 1.5, 2.0, 2.5])
    assert stats.paired_ratio(a, b) == stats.mean_interval(a / b)


def test_paired_arms_need_the_same_seeds():
    with pytest.raises(ValueError, match="one value per seed"):
        stats.paired_difference([1.0, 2.0], [1.0])


def test_equal_values_have_a_zero_width_interval_and_one_value_none():
    assert stats.mean_interval([2.5, 2.5, 2.5]) == stats.Interval(2.5, 2.5, 2.5, 3, "exact")
    one = stats.mean_interval([2.5])
    assert not one.decided and one.text() == "2.5 (N=1)"
    assert stats.mean_interval([1.0, float("nan"), 3.0]).n == 2


@pytest.mark.parametrize("low, high, sense, expected", [
    (1.0, 2.0, "below", "holds"),       # wholly under the bound 3
    (3.5, 4.0, "below", "breaks"),      # wholly over it
    (2.0, 4.0, "below", "undecided at 5 seeds"),  # straddles it
    (3.5, 4.0, "above", "holds"),
    (1.0, 2.0, "above", "breaks"),
    (2.0, 4.0, "above", "undecided at 5 seeds"),
    (2.8, 3.2, "within", "holds"),      # inside the band 3 ± 0.3
    (3.4, 3.9, "within", "breaks"),     # wholly outside it
    (2.5, 3.1, "within", "undecided at 5 seeds"),
])
def test_verdict_rule_on_synthetic_intervals(low, high, sense, expected):
    interval = stats.Interval((low + high) / 2, low, high, 5)
    assert stats.verdict(interval, 3.0, sense, band=0.3 if sense == "within" else None) == expected


def test_verdict_without_an_interval_is_undecided():
    assert stats.verdict(stats.mean_interval([1.0]), 3.0, "below") == "undecided at 1 seed"


def test_interval_text():
    got = stats.Interval(1.234, 1.0, 1.5, 8)
    assert got.text() == "1.23 [1, 1.5]"
    assert got.text(n=True, unit="m") == "1.23 [1, 1.5, N=8] m"
    assert got.fixed(2, "m/s") == "1.23 [1.00, 1.50] m/s"
