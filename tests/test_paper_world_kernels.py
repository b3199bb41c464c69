"""The compiled paper worlds' pieces: CPython's hypot, one numba signature per control-step
kernel, the Python RK4 on the compiled right-hand sides, and how a state that runs away stops."""

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

from sailmujoco.forces.wind import WindConfig, WindField
from sailmujoco.physics import SimulationStopped
from sailmujoco.reference import viel_model, wille_model
from sailmujoco.reference.hypot import hypot
from sailmujoco.reference.integrators import integrate
from sailmujoco.reference.viel import VielParams, VielWorld
from sailmujoco.reference.wille import RK4_MAX_STEP, Wille4DOF

GUSTY = WindConfig(speed=9.0, direction_from=1.2, seed=7, current_east=0.1)


def same_bits(a: float, b: float) -> bool:
    return a.hex() == b.hex() or (math.isnan(a) and math.isnan(b))


def test_hypot_is_cpythons_to_the_last_bit():
    """numba's math.hypot is the C library's, which differs from CPython's in the last bit for
    about one pair in 500; Viel's model takes |wind| and |apparent wind| with math.hypot."""
    rng = np.random.default_rng(1)
    n = 50_000
    xs = rng.normal(size=n) * 10.0 ** rng.integers(-30, 30, n)
    ys = rng.normal(size=n) * 10.0 ** rng.integers(-30, 30, n)
    ys[::2] = xs[::2] * rng.uniform(0.3, 3.0, n // 2)  # similar sizes, where the last bit is hard
    pairs = list(zip(xs.tolist(), ys.tolist(), strict=True))
    special = [0.0, -0.0, 5e-324, 1e-310, 2.2250738585072014e-308, 1e-300, 1.0, 3.0, 4.0, 1e300,
               1.7e308, math.inf, -math.inf, math.nan]
    pairs += [(x, y) for x in special for y in special]
    bad = [(x, y) for x, y in pairs if not same_bits(hypot(x, y), math.hypot(x, y))]
    assert not bad, bad[:5]
    assert sum(math.hypot(x, y) != math.sqrt(x * x + y * y) for x, y in pairs[:n]) > 1000  # not trivial


SIGNATURES = """
import json, math
import numpy as np
from sailmujoco.forces.wind import WindConfig
from sailmujoco.boat.catalogue import get_boat
from sailmujoco.reference import viel_model, wille_model
from sailmujoco.reference.viel import VielParams, VielWorld
from sailmujoco.reference.wille import Wille4DOF
wind = WindConfig(speed=8, direction_from=1, seed=1)  # an int speed, as a user may write it
for boat in ("wille_yacht", "saoud_robot"):
    for model in ("paper", "rigid"):
        world = Wille4DOF(params=get_boat(boat), wind=wind, model=model, timestep=0.005)
        world.set_control([0.1, 0.5])
        world.step(20)
        world.step(1)
for law in ("linear", "printed"):
    world = VielWorld(params=VielParams(rudder_law=law), wind=wind, wind_height=10)
    world.reset([0, 0, 1, 1, 0, 0], time=3)
    world.step([0.1, 0.5], 0.01)
    world.step(np.array([0, 1]), 1)
print(json.dumps([len(wille_model.advance.signatures), len(viel_model.advance.signatures)]))
"""


def test_the_control_step_kernels_have_one_signature_each():
    """An int where a float was would give a kernel a second numba signature and send every
    control step through numba's type dispatch; the worlds convert at the boundary."""
    out = subprocess.run([sys.executable, "-c", SIGNATURES], capture_output=True, text=True, timeout=600,
                         env={k: v for k, v in os.environ.items() if k != "NUMBA_DISABLE_JIT"})
    assert out.returncode == 0, out.stderr[-2000:]
    assert json.loads(out.stdout.strip().splitlines()[-1]) == [1, 1]


@pytest.mark.parametrize("model", ["paper", "rigid"])
def test_wille_compiled_rk4_equals_the_python_rk4_on_the_compiled_rhs(model):
    """integrators.rk4 (numpy) stepping the compiled right-hand side gives the compiled RK4's
    control step bit for bit: rk4_stage and rk4_update keep numpy's order."""
    world = Wille4DOF(wind=GUSTY, model=model)
    world.set_state_ours(u=2.5, heel=0.15, r=0.03, sail=0.7)
    world.set_control([0.3, 0.9])
    world.step(20)
    start, t0 = world.state.copy(), world.time()
    expected, message = integrate(world._rhs, t0, start, 0.1, "rk4", RK4_MAX_STEP, 1e-6, 1e-8)
    world.step(20)
    assert message == ""
    assert world.state.tobytes() == expected.tobytes()


class ShiftedWind(WindField):
    """A wind whose velocity is not WindField's kernel: the world integrates it stage by stage."""

    def velocity(self, t, z):
        return super().velocity(t, z) + np.array([0.5, -0.25, 0.0])


def test_viel_wind_of_its_own_takes_the_python_rk4_with_the_same_numbers():
    config = WindConfig(speed=10.0, direction_from=2.0, seed=3)
    shifted, plain = VielWorld(wind=ShiftedWind(config)), VielWorld(wind=WindField(config))
    for world in (shifted, plain):
        world.reset([0.0, 0.0, 0.4, 1.0, 0.0, 0.05])
        for k in range(20):
            world.step([0.3 * math.sin(k), 0.8], 0.05)
    assert not np.allclose(shifted.state, plain.state, rtol=0, atol=1e-6)  # it did take its own wind

    class SameWind(WindField):
        def velocity(self, t, z):
            return super().velocity(t, z)

    same = VielWorld(wind=SameWind(config))  # Python RK4 + compiled RHS against the compiled RK4
    same.reset([0.0, 0.0, 0.4, 1.0, 0.0, 0.05])
    for k in range(20):
        same.step([0.3 * math.sin(k), 0.8], 0.05)
    assert same.state.tobytes() == plain.state.tobytes()


@pytest.mark.parametrize("model", ["paper", "rigid"])
@pytest.mark.parametrize("index,value,message", [
    (2, math.inf, "the state ran away: math domain error"),  # heel: math.cos(inf) in Python
    (9, math.inf, "the state ran away: math domain error"),  # sail angle
    (8, math.inf, "the state ran away: math domain error"),  # rudder angle
    (2, math.nan, "non-finite state"),  # math.cos(nan) is nan: no error, a lost state
    (5, 1e308, "non-finite state"),  # sway that overflows in the damping
])
def test_wille_state_that_runs_away_stops_as_the_python_model_did(model, index, value, message):
    world = Wille4DOF(wind=GUSTY, model=model)
    world.set_state_ours(u=2.0, sail=0.5)
    world.state[index] = value
    before = world.state.copy()
    with pytest.raises(SimulationStopped, match=f"integration failed: {message}"):
        world.step(20)
    assert world.time() == 0.0 and world.state.tobytes() == before.tobytes()
    if value == math.inf:
        with pytest.raises(ValueError, match="math domain error"):
            world.forces(0.0, world.state)


def test_viel_theta_infinite_is_a_runaway_and_forces_raise():
    world = VielWorld(wind=GUSTY)
    world.reset([0.0, 0.0, 0.0, 1.0, 0.0, 0.0])
    world._state[5] = 1e308  # omega: theta overflows within the first step
    with pytest.raises(FloatingPointError, match=r"the state ran away: math domain error"):
        world.step([0.0, 0.0], 0.1)
    with pytest.raises(ValueError, match="math domain error"):
        viel_model.model_rates(VielParams(), [0, 0, math.inf, 1, 0, 0], 0.1, 0.2, 5.0, 1.0)


def test_packed_parameters_follow_a_new_boat_or_switch():
    """The packed parameters are cached; replacing params, switches or model repacks them."""
    world = Wille4DOF(wind=GUSTY)
    first = world._packed()
    assert world._packed() is first
    world.model = "rigid"
    assert world._packed()[wille_model.RIGID] == 1.0
    w = VielWorld()
    w.params = VielParams(p5=1000.0)
    assert w._packed()[viel_model.P5] == 1000.0
