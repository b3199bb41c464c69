"""The assumption study's fitted arms: the change's arithmetic, the switches that make one
instrument or servo perfect, the rule that traces a change to one of them, and the perfect arm
being the papers' loop itself."""

import math

import numpy as np
import pandas as pd
import pytest
from sailmujoco.studies.assumptions.fitted import (
    ACTUATOR_SWITCHES,
    SCENARIOS,
    SENSOR_SWITCHES,
    attribution_jobs,
    fitted_jobs,
    fitted_run,
    relative,
)
from sailmujoco.studies.assumptions.fitted_analysis import FittedAnalysis, _effects, flagged, traced_to

from sailmujoco import suite
from sailmujoco.boat.fitted import ACTUATOR_PRESETS as ACTUATORS
from sailmujoco.boat.fitted import SENSOR_PRESETS as SENSORS
from sailmujoco.boat.fitted import actuator_options, sensor_options


def test_the_change_is_relative_to_the_perfect_arm_or_to_the_floor():
    assert relative(1.1, 1.0, 0.3) == pytest.approx(0.10, rel=1e-12)
    assert relative(0.9, -1.0, 0.3) == pytest.approx(1.9, rel=1e-12)  # of |perfect|
    assert relative(0.2, 0.1, 0.3) == pytest.approx(1.0 / 3.0, rel=1e-12)  # of the floor, not of ~0


def test_each_switch_makes_its_own_instrument_perfect_and_leaves_the_others_typical():
    jobs = attribution_jobs([("viel", "sensors"), ("saoud", "actuators")], smoke=True, seeds=(0, 1))
    assert len(jobs) == 2 * (len(SENSOR_SWITCHES) + len(ACTUATOR_SWITCHES))
    typical_s, typical_a = SENSORS["typical"], ACTUATORS["typical"]
    for job in jobs:
        switch = (SENSOR_SWITCHES | ACTUATOR_SWITCHES)[job["switch"]]
        sensors, actuators = sensor_options(job["sensors"]), actuator_options(job["actuators"])
        fitted, other = (sensors, actuators) if job["arm"] == "sensors" else (actuators, sensors)
        typical = typical_s if job["arm"] == "sensors" else typical_a
        assert other.perfect and not fitted.perfect
        for name in fitted.__dataclass_fields__:
            expected = switch.get(name, getattr(typical, name))
            assert getattr(fitted, name) == expected, (job["switch"], name)
    # a switch is only figures that act: each one is 0 but the GNSS's rate (a fix every step)
    for switch in (SENSOR_SWITCHES | ACTUATOR_SWITCHES).values():
        assert all(v == 0.0 for k, v in switch.items() if k != "gnss_rate_hz")


def test_a_gnss_made_perfect_reads_the_true_position_every_step():
    fitted = {"preset": "typical", **SENSOR_SWITCHES["gnss"]}
    env = suite.load("saoud_robot", "heading_hold", seed=2, sensors=fitted, time_limit=5.0)
    truth = suite.load("saoud_robot", "heading_hold", seed=2, time_limit=5.0)
    a, b = env.reset(), truth.reset()
    while not a.last():
        np.testing.assert_array_equal(a.observation["position"], b.observation["position"])
        np.testing.assert_array_equal(a.observation["velocity"], b.observation["velocity"])
        a, b = env.step(np.array([0.05, 0.4])), truth.step(np.array([0.05, 0.4]))
    assert a.observation["heading"] != b.observation["heading"]  # the compass still errs


def test_the_perfect_arm_is_the_papers_loop_bit_for_bit():
    job = next(j for j in fitted_jobs(True, (1,)) if j["scenario"] == "saoud" and j["arm"] == "perfect")
    s = SCENARIOS["saoud"]
    env = suite.load(s["boat"], s["task"], seed=1, time_limit=s["seconds"][0], **s["options"])
    from sailmujoco import sweep

    suite.rollout(env, sweep.make_controller(s["controller"], env))
    assert fitted_run(job)["value"] == env.task.metrics()["steady_speed"]


def _analysis(values: dict) -> FittedAnalysis:
    """A FittedAnalysis of synthetic runs: (scenario, arm, switch) -> one value per seed."""
    rows = [{"scenario": sc, "arm": arm, "switch": sw, "seed": seed, "value": v, "stopped": None}
            for (sc, arm, sw), vs in values.items() for seed, v in enumerate(vs)]
    runs = pd.DataFrame(rows)
    return FittedAnalysis(runs, _effects(runs), (0, 1, 2))


def test_a_change_is_traced_to_the_switch_that_brings_it_back_within_ten_percent():
    f = _analysis({("viel", "perfect", ""): [10.0, 12.0, 11.0],
                   ("viel", "sensors", ""): [13.0, 15.6, 14.3],  # +30 % on every seed
                   ("viel", "sensors", "gnss"): [10.2, 12.1, 11.3],  # +1.8 % left: the GNSS
                   ("viel", "sensors", "compass"): [13.0, 15.6, 14.3]})
    change = f.change("viel", "sensors")
    assert change.mean == pytest.approx(0.30, rel=1e-12) and change.low == pytest.approx(0.30, rel=1e-9)
    assert flagged(f.effects) == [("viel", "sensors")]
    text = traced_to(f, "viel", "sensors")
    assert text.startswith("the gnss (") and "compass +30 %" in text
    g = _analysis({("viel", "perfect", ""): [10.0, 12.0, 11.0],
                   ("viel", "sensors", ""): [13.0, 15.6, 14.3],
                   ("viel", "sensors", "gnss"): [12.0, 14.4, 13.2],  # +20 %: neither removes it
                   ("viel", "sensors", "compass"): [12.0, 14.4, 13.2]})
    assert traced_to(g, "viel", "sensors").startswith("no single switch")
    assert math.isclose(g.change("viel", "sensors", "gnss").mean, 0.2, rel_tol=1e-12)
