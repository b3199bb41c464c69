"""Fitted actuators in the loop: ``perfect`` passes the command to the world bit for bit;
``typical`` lets the sail winch go from one end of its range to the other in 1.3 s, in equal
steps, whatever the command; a sheeted sail's winch hauls in as fast as its torque allows
against the sheet's load."""

import math

import numpy as np
import pytest

from sailmujoco import suite


def _controls(actuators, commands, world="mujoco"):
    env = suite.load("saoud_robot", "heading_hold", world, seed=1, gusts=False, wander=False,
                     **({} if actuators is None else {"actuators": actuators}))
    env.reset()
    sent = []
    for command in commands:
        env.step(np.asarray(command, dtype=float))
        sent.append(np.array(env.physics.data.ctrl, dtype=float).copy() if world == "mujoco" else None)
    return env, sent


def test_perfect_actuators_pass_the_command_bit_for_bit():
    commands = [(0.1 * math.sin(k), 0.3 + 0.2 * math.cos(k)) for k in range(20)]
    _, plain = _controls(None, commands)
    env, perfect = _controls("perfect", commands)
    assert env.task._servos is None
    assert all(a.tobytes() == b.tobytes() for a, b in zip(plain, perfect, strict=True))
    assert all(np.array_equal(s, c) for s, c in zip(perfect, commands, strict=True))


def test_typical_sail_actuator_crosses_its_range_in_1_3_seconds():
    env, _ = _controls("typical", [])
    low, high = env.physics.action_bounds()
    span = high[1] - low[1]
    _, sent = _controls("typical", [(0.0, low[1])] + [(0.0, high[1])] * 20)
    sail = np.array([c[1] for c in sent])
    steps = np.diff(sail[:14])
    # 0.1 s a step at span / 1.3 s, the backlash (1 % of the span) taken up in the first step
    assert steps[1:12] == pytest.approx(np.full(11, span * 0.1 / 1.3), rel=1e-9)
    assert sail[-1] == pytest.approx(high[1] - 0.005 * span, rel=1e-9)  # half the play short of the end


def test_a_bad_actuator_option_is_one_line():
    with pytest.raises(ValueError, match="actuators must be one of"):
        suite.load("saoud_robot", "heading_hold", actuators="fast")
    with pytest.raises(ValueError, match="actuators.rudder_60deg_s must be a finite number >= 0"):
        suite.load("saoud_robot", "heading_hold", actuators={"rudder_60deg_s": -0.1})


def _winch_run(stall_pull):
    """The robot's sheeted sail in 8 m/s on a beam reach: the sheet let out for 3 s, then
    ordered full in; (the length sent each step, the sheet's tension before it, free speed)."""
    figures = {"sail_full_range_s": 1.3, "winch_stall_pull": stall_pull}
    env = suite.load("saoud_robot", "heading_hold", seed=0, sail_mode="sheeted", gusts=False, wander=False,
                     wind_speed=8.0, wind_from_deg=90.0, actuators=figures)
    env.reset()
    low, high = env.physics.action_bounds()
    sent, tension = [], []
    for k in range(60):
        tension.append(env.physics.sheet_tension())
        env.step(np.array([0.0, high[1] if k < 30 else low[1]]))
        sent.append(float(env.physics.data.ctrl[1]))
    return np.array(sent), np.array(tension), (high[1] - low[1]) / 1.3


@pytest.mark.parametrize("stall_pull", [1e6, 15.0])
def test_a_winch_hauls_in_as_fast_as_its_torque_allows_against_the_sheets_load(stall_pull):
    """Hauling in, each 0.1 s step shortens the sheet by v_free (1 - T / F_stall) dt, T the
    sheet's tension felt (the load on the drum), to zero once T reaches the stall pull; easing
    out, the load helps and it pays out at v_free."""
    sent, tension, free = _winch_run(stall_pull)
    haul = -np.diff(sent[29:])  # the steps ordered full in (the first from the eased sheet)
    expected = free * np.clip(1.0 - tension[30:] / stall_pull, 0.0, 1.0) * 0.1
    np.testing.assert_allclose(haul, np.minimum(expected, sent[29:-1] - sent.min()), rtol=1e-12, atol=1e-12)
    assert tension[30:].max() > 0.0  # the sheet took the sail's load


def test_the_weaker_the_winch_the_further_out_its_sheet_stays():
    """Three winches under the same orders: the runs are the same until a sheet's load lies
    between two winches' stall pulls; there the weaker one stops and the stronger hauls on, so
    at the step where two runs part the weaker winch's sheet is the longer. (Their ends are
    not compared: once the sheets differ the sail and the boat do, and a sail that luffs late
    may let a weak winch haul in further than a stronger one did earlier.)"""
    strong, loads, _ = _winch_run(1e6)
    middle, middle_loads, _ = _winch_run(15.0)
    weak, _, _ = _winch_run(5.0)
    assert strong[-1] == pytest.approx(strong.min())  # the strong one hauls all the way in,
    assert loads[-10:].mean() > 15.0  # N: against a load the weaker two cannot hold
    for weaker, stronger, low, high, felt in ((weak, middle, 5.0, 15.0, middle_loads),
                                              (middle, strong, 15.0, 1e6, loads)):
        k = int(np.flatnonzero(weaker != stronger)[0])  # the first step the two sheets differ
        assert k > 30  # while easing out they paid out alike
        assert weaker[k] > stronger[k]  # m: the weaker stopped, the stronger hauled in
        assert weaker[k] == weaker[k - 1]  # the weaker one did not move at all
        assert low <= felt[k] < high  # N: because the load lay between their stall pulls
