"""Fitted actuators in the loop: ``perfect`` passes the command to the world bit for bit;
``typical`` lets the sail winch go from one end of its range to the other in 1.3 s, in equal
steps, whatever the command."""

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
