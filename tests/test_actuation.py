"""Actuators as fitted, exact on step and reversal commands: rate limit, deadband, backlash,
quantisation, and a winch that cannot haul in against a load beyond its stall torque."""

import math

import pytest

from sailmujoco.actuation.servo import Backlash, Deadband, FittedServo, RateLimit, quantise
from sailmujoco.actuation.winch import SheetWinch


def test_rate_limit_turns_a_step_into_a_ramp_at_the_rated_speed():
    rate = math.radians(60.0) / 0.2  # an RC servo: 60 deg in 0.2 s
    limit = RateLimit(rate, dt=0.01)
    limit.step(0.0)
    path = [limit.step(math.radians(30.0)) for _ in range(15)]
    assert path[:9] == pytest.approx([rate * 0.01 * (k + 1) for k in range(9)], rel=1e-12)
    assert path[9:] == [math.radians(30.0)] * 6  # 30 deg reached after 0.1 s, then held exactly


def test_deadband_ignores_small_changes_and_follows_large_ones():
    band = Deadband(0.02)
    assert band.step(0.10) == 0.10
    assert band.step(0.115) == 0.10  # 0.015 inside the band
    assert band.step(0.085) == 0.10
    assert band.step(0.125) == 0.125  # 0.025 beyond it


def test_backlash_holds_the_output_on_reversal_until_the_play_is_taken_up():
    play = Backlash(0.1)
    play.step(0.0)
    assert play.step(0.3) == pytest.approx(0.25)  # pushed: lags the input by half the play
    assert play.step(0.25) == pytest.approx(0.25)  # reversal: the output stays ...
    assert play.step(0.20) == pytest.approx(0.25)  # ... while the input crosses the whole play of 0.1
    assert play.step(0.15) == pytest.approx(0.20)  # then it is pulled back, half the play ahead


def test_quantisation_rounds_to_the_resolution():
    assert quantise(0.123, 0.05) == pytest.approx(0.10)
    assert quantise(0.126, 0.05) == pytest.approx(0.15)
    assert quantise(0.123, 0.0) == 0.123


def test_an_ideal_fitted_servo_passes_the_command_bit_for_bit():
    servo = FittedServo(0.1)
    commands = [0.1, -0.3, 0.123456789, 1e-17, -2.0]
    assert [servo.step(c) for c in commands] == commands


def test_a_winch_cannot_haul_in_against_a_load_beyond_its_stall_torque():
    winch = SheetWinch(free_speed=0.5, stall_torque=2.0, drum_radius=0.02, dt=0.1)  # stall pull 100 N
    winch.step(1.0, load=0.0)
    assert winch.step(0.5, load=150.0) == 1.0  # cannot pull in
    assert winch.step(0.5, load=50.0) == pytest.approx(1.0 - 0.25 * 0.1)  # half the stall pull: half speed
    assert winch.step(1.5, load=150.0) == pytest.approx(0.975 + 0.05)  # eases out at the no-load speed


def test_bad_actuator_values_are_refused_in_one_line():
    with pytest.raises(ValueError, match="rate_limit must be a finite number >= 0"):
        RateLimit(-1.0, 0.1)
    with pytest.raises(ValueError, match="winch stall_torque must be a finite number > 0"):
        SheetWinch(0.5, 0.0, 0.02, 0.1)
